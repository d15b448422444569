// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "materials/HenckyReturnMap.hpp"

namespace mpm {

/// μ(I) rheology on Hencky elasticity [000 Eq. 3–9, 10]: F = q − μ(I) p ≤ 0,
/// μ(I) = μ_s + (μ₂ − μ_s)/(I₀/I + 1), I = γ̇ᵖ √(d² ρ_s / p) [000 Eq. 9], μ_s and μ₂ from
/// frictionAngle and frictionAngle2 by [000 Eq. 8]; isochoric flow, γ̇ᵖ = Δγ/Δt the engineering
/// plastic shear rate (MuIFlow); return map and trans-phase gasification as in
/// HenckyReturnMap.hpp. At I = 0 it is Drucker–Prager with μ_s and ψ = 0.
/// Keys: density, E, nu, frictionAngle [deg] (0, 90), frictionAngle2 [deg] (φ, 90),
/// I0 (default 0.278), grainDiameter [m], grainDensity [kg/m³], transPhase (default true),
/// criticalDensity [kg/m³] (default density).
template <int dim> class MuI : public HenckyGranular<dim> {
public:
    MuI(const Dictionary& dict, const std::string& name);

    Index updateStress(Particles<dim>& p, const std::vector<Index>& ids, double dt) const override;

    /// The flow functor for a step dt > 0 (μ(I), plastic multiplier).
    MuIFlow flow(double dt) const;

private:
    double mu2_;           ///< μ₂ [-]
    double I0_;            ///< I₀ [-]
    double grainDiameter_; ///< d [m]
    double grainDensity_;  ///< ρ_s [kg/m³]
};

} // namespace mpm
