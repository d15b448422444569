// SPDX-License-Identifier: GPL-3.0-or-later
#include "forces/BodyAcceleration.hpp"
#include "forces/ConstantAcceleration.hpp"

#include <vector>

namespace mpm {

template <int dim> double BodyAcceleration<dim>::energySupply(double mass, double extent) const {
    return mass * extent * (maxMagnitude() + totalVariation());
}

template <int dim>
std::unique_ptr<BodyAcceleration<dim>> BodyAcceleration<dim>::create(const Dictionary& dict) {
    // Cases written before `type:` existed have only `value:`: constant.
    if (dict.has("type")) return BodyAccelerationRegistry<dim>::create(dict);
    auto g = std::make_unique<ConstantAcceleration<dim>>(dict);
    dict.checkUnknownKeys();
    return g;
}

template <int dim>
std::unique_ptr<BodyAcceleration<dim>> BodyAcceleration<dim>::constant(const Vec<dim>& g) {
    return std::make_unique<ConstantAcceleration<dim>>(g);
}

template class BodyAcceleration<2>;
template class BodyAcceleration<3>;

MPM_FAMILY_INFO("bodyAccelerations", {"type in constant/g",
                                      "5. constant/g",
                                      {{"type", "word", "-", "constant", "how g varies in time"}}});
MPM_FAMILY_DIMS(BodyAccelerationRegistry, "bodyAccelerations");

} // namespace mpm
