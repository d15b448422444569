// SPDX-License-Identifier: GPL-3.0-or-later
#include "forces/SinusoidalAcceleration.hpp"

#include "case/DictionaryVectors.hpp"
#include "core/Constants.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mpm {

namespace {}

template <int dim>
SinusoidalAcceleration<dim>::SinusoidalAcceleration(const Dictionary& dict)
    : g0_(readVec<dim>(dict, "value")), direction_(readVec<dim>(dict, "direction")),
      amplitude_(dict.getScalar("amplitude", Bounds::nonNegative())),
      phase_(dict.getScalarOr("phase", 0.0) * pi / 180.0) {
    const bool byFrequency = dict.has("frequency");
    const bool byAngular = dict.has("angularFrequency");
    if (byFrequency == byAngular)
        dict.error(byFrequency ? "angularFrequency" : "",
                   "give exactly one of 'frequency' [Hz] and 'angularFrequency' [rad/s]");
    omega_ = byFrequency ? 2.0 * pi * dict.getScalar("frequency", Bounds::positive())
                         : dict.getScalar("angularFrequency", Bounds::positive());
    const double n = direction_.norm();
    if (!(n > 0)) dict.error("direction", "the direction of the vibration must not be zero");
    direction_ /= n;
}

template <int dim> Vec<dim> SinusoidalAcceleration<dim>::at(double t) const {
    return g0_ + (amplitude_ * omega_ * omega_ * std::sin(omega_ * t + phase_)) * direction_;
}

template <int dim> double SinusoidalAcceleration<dim>::maxMagnitude() const {
    const Vec<dim> c = amplitude_ * omega_ * omega_ * direction_;
    return std::max((g0_ + c).norm(), (g0_ - c).norm());
}

template <int dim> double SinusoidalAcceleration<dim>::totalVariation() const {
    return amplitude_ == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

template <int dim>
double SinusoidalAcceleration<dim>::energySupply(double mass, double extent) const {
    const double speed = amplitude_ * omega_; // the plate's largest speed A ω [m/s]
    return mass * extent * maxMagnitude() + 8.0 * 0.5 * mass * speed * speed;
}

template class SinusoidalAcceleration<2>;
template class SinusoidalAcceleration<3>;

MPM_REGISTER_DIMS(BodyAccelerationRegistry, SinusoidalAcceleration, "sinusoidal");
MPM_SCHEMA(
    "bodyAccelerations", "sinusoidal",
    {"g₀ plus a sinusoidal vibration of amplitude A along d (a shaken container's frame)",
     {{"value", "vector", "m/s²", "required", "g₀, the acceleration without vibration"},
      {"amplitude", "scalar", "m", "required", "A (≥ 0)"},
      {"frequency", "scalar", "Hz", "none", "f > 0, ω = 2π f (give frequency or angularFrequency)"},
      {"angularFrequency", "scalar", "rad/s", "none", "ω > 0"},
      {"direction", "vector", "-", "required", "d (not zero; normalised)"},
      {"phase", "scalar", "deg", "0", "φ"}},
     "{type: sinusoidal, value: [0, -9.81], amplitude: 0.001, frequency: 50, direction: [0, 1]}"});

} // namespace mpm
