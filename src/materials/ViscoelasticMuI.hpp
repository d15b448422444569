// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "materials/ElastoPlastic.hpp"
#include "materials/Viscosity.hpp"

#include <string>

namespace mpm {

/// The μ(I) plasticity of the viscoelastic model [002 §2–3] (TanMuIFlow): τ = μ(I) p
/// [Eq. 43–44] with μ_s = tan φ_s, μ₂ = tan φ₂ in τ = √J₂ [002 §4], I = γ̇ᵖ d √(ρ_s/p),
/// isochoric flow, no tension. Its return is the viscous return map of the hypoelastic law
/// (ViscoelasticReturnMap.hpp), which also applies the separation rule [Eq. 46–47].
/// Keys: frictionAngle φ_s and frictionAngle2 φ₂ [deg]; I0 (default 0.278); grainDiameter d [m];
/// grainDensity ρ_s [kg/m³].
class TanMuIPlasticity {
public:
    static constexpr bool plastic = true;

    TanMuIPlasticity(const Dictionary& dict, const ElasticConstants& c, ElasticLaw law, int dim);
    /// The constants, for the log (Material::describe).
    std::string describe() const;
    /// The flow functor (the same for every dt).
    TanMuIFlow flow(double /*dt*/) const { return flow_; }
    TensionCutoff cutoff() const { return {}; }
    /// Jaky's K0 = 1 − sin φ_s.
    double defaultK0(const ElasticConstants& c) const;

private:
    TanMuIFlow flow_;
};

/// Viscoelastic μ(I) with restitution-derived damping (`type: viscoelasticMuI`) [002 §2–3]:
/// the hypoelastic law (rotationally neutralised update [002 Eq. 52]) × the μ(I) flow of [002]
/// (TanMuIPlasticity, separation below ρ_c or at p_tr ≤ 0) × Kelvin–Voigt viscosity
/// σᵛ = ϑ tr Dᵛᵉ 1 + 2η Dᵛᵉ_dev (KelvinVoigtViscosity), σ = σᵉ + σᵛ; the step is
/// ViscoelasticReturnMap.hpp.
/// Keys: density ρ₀ = φ₀ ρ_s [kg/m³]; E [Pa]; nu; the plasticity's keys; the damping as
/// `restitution: e` in (0, 1] [Eq. 40, 42], or `bulkViscosity: ϑ` [Pa·s] with optional
/// `shearViscosity: η` (default (G/K) ϑ [Eq. 42]), or neither (undamped); criticalDensity ρ_c
/// (default ρ₀) [kg/m³].
/// State: elasticStress σᵉ (restarted), plasticStrainRate γ̇ᵖ [1/s], flowState
/// (ViscoelasticState); plasticStrain accumulates ∫ γ̇ᵖ dt (the deviatoric plastic strain of
/// [002 Fig. 16] is plasticStrain/√3).
template <int dim>
using ViscoelasticMuI = ElastoPlastic<dim, HypoelasticLaw, TanMuIPlasticity, KelvinVoigtViscosity>;

} // namespace mpm
