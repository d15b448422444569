// SPDX-License-Identifier: GPL-3.0-or-later
#include "forces/RampAcceleration.hpp"

#include "case/DictionaryVectors.hpp"
#include "core/Constants.hpp"

#include <algorithm>
#include <cmath>

namespace mpm {

template <int dim>
RampAcceleration<dim>::RampAcceleration(const Dictionary& dict)
    : initial_(dict.has("initial") ? readVec<dim>(dict, "initial") : Vec<dim>::Zero()),
      value_(readVec<dim>(dict, "value")), start_(dict.getScalarOr("start", 0.0)),
      duration_(dict.getScalar("duration", Bounds::positive())),
      cosine_(dict.getWordOr("profile", "cosine", {"cosine", "smoothstep"}) == "cosine") {
    magnitudeA_ = initial_.norm();
    magnitudeB_ = value_.norm();
    from_.setZero();
    towards_.setZero();
    if (magnitudeA_ > 0)
        from_ = initial_ / magnitudeA_;
    else if (magnitudeB_ > 0)
        from_ = value_ / magnitudeB_;
    if (magnitudeA_ > 0 && magnitudeB_ > 0) {
        // b̂ = cos θ â + sin θ ê with ê ⊥ â; atan2 keeps θ accurate near 0 and π.
        const Vec<dim> b = value_ / magnitudeB_;
        const double c = from_.dot(b);
        const Vec<dim> perpendicular = b - c * from_;
        const double s = perpendicular.norm();
        angle_ = std::atan2(s, c);
        if (s > 0) towards_ = perpendicular / s;
        if (angle_ > pi * (1.0 - 1e-9))
            dict.error("value", "'initial' and 'value' point in opposite directions, so the "
                                "plane to turn g in is not defined; give a table instead");
    }
}

template <int dim> double RampAcceleration<dim>::profile(double s) const {
    return cosine_ ? 0.5 * (1.0 - std::cos(pi * s)) : s * s * (3.0 - 2.0 * s);
}

template <int dim> Vec<dim> RampAcceleration<dim>::at(double t) const {
    const double s = (t - start_) / duration_;
    if (s <= 0) return initial_;
    if (s >= 1) return value_;
    const double S = profile(s);
    const double magnitude = magnitudeA_ + S * (magnitudeB_ - magnitudeA_);
    const double phi = S * angle_;
    return magnitude * (std::cos(phi) * from_ + std::sin(phi) * towards_);
}

template <int dim> double RampAcceleration<dim>::maxMagnitude() const {
    return std::max(magnitudeA_, magnitudeB_);
}

template <int dim> double RampAcceleration<dim>::totalVariation() const {
    return std::fabs(magnitudeB_ - magnitudeA_) + std::max(magnitudeA_, magnitudeB_) * angle_;
}

template class RampAcceleration<2>;
template class RampAcceleration<3>;

MPM_REGISTER_DIMS(BodyAccelerationRegistry, RampAcceleration, "ramp");
MPM_SCHEMA("bodyAccelerations", "ramp",
           {"g turned smoothly from a to b over [t₀, t₀ + T]",
            {{"value", "vector", "m/s²", "required", "b, g after the ramp"},
             {"initial", "vector", "m/s²", "zero", "a, g before the ramp"},
             {"start", "scalar", "s", "0", "t₀"},
             {"duration", "scalar", "s", "required", "T (> 0)"},
             {"profile", "word", "-", "cosine", "cosine or smoothstep"}},
            "{type: ramp, value: [0, -9.81], duration: 0.1}"});

} // namespace mpm
