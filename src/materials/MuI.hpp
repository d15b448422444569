// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Constants.hpp"
#include "materials/DruckerPrager.hpp"
#include "materials/ElastoPlastic.hpp"

namespace mpm {

/// μ(I) rheology (`type: muI`), the plasticity of ElastoPlastic [000 Eq. 9]: F = q − μ(I) p ≤ 0,
/// μ(I) = μ_s + (μ₂ − μ_s)/(I₀/I + 1), I = γ̇ᵖ √(d² ρ_s / p), μ_s and μ₂ from frictionAngle and
/// frictionAngle2 by the cone fit (readConeFit); isochoric flow, γ̇ᵖ = Δγ/Δt the engineering
/// plastic shear rate (MuIFlow). No cohesion, no tension. At I = 0 it is Drucker–Prager with
/// μ_s and ψ = 0.
/// Keys: frictionAngle [deg] (0, 90), frictionAngle2 [deg] (φ, 90), I0 (default 0.278),
/// grainDiameter [m], grainDensity [kg/m³], coneFit.
class MuIPlasticity {
public:
    static constexpr bool plastic = true;

    MuIPlasticity(const Dictionary& dict, const ElasticConstants& c, ElasticLaw law, int dim);
    /// The derived constants, for the log (Material::describe).
    std::string describe() const;

    /// The flow functor for a step dt > 0 (μ(I), plastic multiplier).
    MuIFlow flow(double dt) const;
    TensionCutoff cutoff() const { return {}; }
    /// Jaky's K0 = 1 − sin φ.
    double defaultK0(const ElasticConstants& /*c*/) const {
        return 1.0 - std::sin(phi_ * pi / 180.0);
    }

    /// Friction angle φ [deg].
    double frictionAngle() const { return phi_; }
    /// μ_s [-].
    double staticFriction() const { return muS_; }

private:
    double G_;             ///< shear modulus [Pa]
    double phi_;           ///< φ [deg]
    ConeFit fit_;          ///< cone fit of μ_s and μ₂
    double muS_;           ///< μ_s [-]
    double mu2_;           ///< μ₂ [-]
    double I0_;            ///< I₀ [-]
    double grainDiameter_; ///< d [m]
    double grainDensity_;  ///< ρ_s [kg/m³]
};

/// `muI` with the elastic law of `elasticity:` (default hencky).
template <int dim, class Law = HenckyLaw> using MuI = ElastoPlastic<dim, Law, MuIPlasticity>;

} // namespace mpm
