// SPDX-License-Identifier: GPL-3.0-or-later
#include "forces/ConstantAcceleration.hpp"
#include "case/DictionaryVectors.hpp"

namespace mpm {

template <int dim>
ConstantAcceleration<dim>::ConstantAcceleration(const Dictionary& dict)
    : g_(readVec<dim>(dict, "value")) {}

template class ConstantAcceleration<2>;
template class ConstantAcceleration<3>;

MPM_REGISTER_DIMS(BodyAccelerationRegistry, ConstantAcceleration, "constant");
MPM_SCHEMA("bodyAccelerations", "constant",
           {"constant g",
            {{"value", "vector", "m/s²", "required", "gravitational acceleration g"}},
            "{type: constant, value: [0, -9.81]}"});

} // namespace mpm
