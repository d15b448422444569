// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/BoundaryCondition.hpp"

namespace mpm {

template <int dim>
std::unique_ptr<BoundaryCondition<dim>> BoundaryCondition<dim>::create(const Dictionary& dict) {
    return BoundaryConditionRegistry<dim>::create(dict);
}

template <int dim> std::vector<std::string> BoundaryCondition<dim>::typeNames() {
    std::vector<std::string> names;
    for (const auto& entry : BoundaryConditionRegistry<dim>::table())
        names.push_back(entry.first);
    return names;
}

template class BoundaryCondition<2>;
template class BoundaryCondition<3>;

} // namespace mpm
