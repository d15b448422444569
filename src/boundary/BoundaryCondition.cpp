// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/BoundaryCondition.hpp"

namespace mpm {

template <int dim>
std::unique_ptr<BoundaryCondition<dim>> BoundaryCondition<dim>::create(const Dictionary& dict) {
    return BoundaryConditionRegistry<dim>::createReadingMore(dict); // and the patch keys
}

template class BoundaryCondition<2>;
template class BoundaryCondition<3>;

// The family (boundaryConditions) joins in FaceKind.cpp, with the face kinds.

} // namespace mpm
