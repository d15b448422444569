// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/Shape.hpp"

namespace mpm {

template <int dim> std::unique_ptr<Shape<dim>> Shape<dim>::create(const Dictionary& dict) {
    return ShapeRegistry<dim>::create(dict);
}

template class Shape<2>;
template class Shape<3>;

} // namespace mpm
