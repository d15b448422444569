// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "forces/BodyAcceleration.hpp"

namespace mpm {

/// `type: ramp`: g turns smoothly from `initial` a (default zero) into `value` b over
/// `duration` T [s] from `start` t₀ [s] (default 0), and is constant outside the ramp:
/// g = a for t ≤ t₀, g = b for t ≥ t₀ + T. With s = (t − t₀)/T and a profile S(s) rising
/// from 0 to 1 with zero slope at both ends (C¹),
///     `profile: cosine` (default)  S = (1 − cos πs)/2,
///     `profile: smoothstep`        S = 3s² − 2s³,
/// the magnitude is interpolated, |g| = |a| + S (|b| − |a|), and the direction turns from â
/// to b̂ in their common plane by S times the angle θ between them (one of a, b zero: the
/// other's direction). So ramping gravity up from zero (the incline of [002 §4.2]: "gravity
/// smoothly ramped up during the first tenth of a second", g rotated by Θ) grows
/// g = S b along a fixed direction, and tilting between two vectors of equal length keeps
/// the length. Opposite a and b (θ = π) have no unique plane and are an error.
template <int dim> class RampAcceleration final : public BodyAcceleration<dim> {
public:
    explicit RampAcceleration(const Dictionary& dict);

    Vec<dim> at(double t) const override;
    bool isConstant() const override { return initial_ == value_; }
    double maxMagnitude() const override;
    /// Bound of the path length: ||b| − |a|| + max(|a|, |b|) θ (exact when θ = 0).
    double totalVariation() const override;

    /// The profile S(s) for s in [0, 1].
    double profile(double s) const;

private:
    Vec<dim> initial_, value_;
    double start_ = 0, duration_ = 1;
    bool cosine_ = true;
    double magnitudeA_ = 0, magnitudeB_ = 0;
    double angle_ = 0; ///< θ between a and b [rad]
    /// Orthonormal pair spanning the rotation: the start direction and the one towards b̂.
    Vec<dim> from_, towards_;
};

} // namespace mpm
