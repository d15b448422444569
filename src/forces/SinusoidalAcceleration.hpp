// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "forces/BodyAcceleration.hpp"

namespace mpm {

/// `type: sinusoidal`: the body acceleration in the frame of a plate vibrating with
/// displacement A sin(ωt + φ) d [002 §4.5],
///     g(t) = g₀ + A ω² sin(ωt + φ) d    [m/s²].
/// In the plate frame x = X − A sin(ωt + φ) d, so ẍ = Ẍ + A ω² sin(ωt + φ) d: the material
/// feels the plate's acceleration reversed. With d up and g₀ = −g d the layer is lifted off
/// the plate where A ω² sin(ωt + φ) > g, first at ωt + φ = arcsin(1/Γ), Γ = A ω²/g; at t = 0
/// (φ = 0) the plate passes its mid position moving up at A ω, so a layer at rest in the plate
/// frame moves with the plate. [002 §4.5] uses φ = 0, d = up: b = −g + ω² A sin ωt.
///
/// Keys: `value` g₀ [m/s²]; `amplitude` A [m] (≥ 0); exactly one of `frequency` f [Hz]
/// (ω = 2π f) and `angularFrequency` ω [rad/s]; `direction` d (normalised, not zero);
/// `phase` φ [deg] (default 0).
template <int dim> class SinusoidalAcceleration final : public BodyAcceleration<dim> {
public:
    explicit SinusoidalAcceleration(const Dictionary& dict);

    Vec<dim> at(double t) const override;
    bool isConstant() const override { return amplitude_ == 0.0; }
    /// max over s ∈ [−1, 1] of |g₀ + s A ω² d|, convex in s: at s = ±1.
    double maxMagnitude() const override;
    double totalVariation() const override;
    /// m extent |g|max + 8 · ½ m (A ω)², a bound for a dissipative layer on the plate.
    /// In the lab frame the plate moves at u, |u| ≤ A ω; a point leaves it with the plate's
    /// velocity, flies under g₀ and lands at a lab speed ≤ A ω + √(2|g₀|h) (h ≤ extent); the
    /// landing at most reverses its velocity relative to the plate (restitution ≤ 1), which is
    /// then ≤ 2 A ω + √(2|g₀|h). The kinetic energy relative to the plate, the one the solver
    /// sees, is therefore ≤ ½ m (2Aω + √(2|g₀|h))² ≤ 8 · ½ m (Aω)² + 2 m |g₀| h, and
    /// 2 |g₀| ≤ |g₀| + A ω² ≤ |g|max as soon as Γ ≥ 1 (below Γ = 1 the layer never lifts off).
    double energySupply(double mass, double extent) const override;

private:
    Vec<dim> g0_;
    Vec<dim> direction_;
    double amplitude_ = 0; ///< A [m]
    double omega_ = 0;     ///< ω [rad/s]
    double phase_ = 0;     ///< φ [rad]
};

} // namespace mpm
