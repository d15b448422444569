// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "materials/Material.hpp"

#include <string>
#include <vector>

namespace mpm {

/// Bulk viscosity from the coefficient of restitution of a grain collision [002 Eq. 40]:
/// ϑ = 0.237 d √(M φ ρ_s) |ln e|^(π/2) [Pa·s], with d the grain diameter [m], M = K + 4G/3 the
/// P-wave modulus [Pa] and φ ρ_s the bulk density [kg/m³]. e = 1 gives 0.
double restitutionViscosity(double restitution, double grainDiameter, double pWaveModulus,
                            double bulkDensity);

/// Continuum coefficient of restitution of a linear-viscoelastic body given an impulsive
/// dilatational mode of wavenumber k [002 Eq. 35–37], as a function of ζ = k ϑ / (2√(M ρ))
/// (ζ = π ϑ̃/2 for the sphere, ϑ̃ = ϑ/(a√(Mρ)) [002 Eq. 36]). Real-valued for every ζ ≥ 0
/// (the printed Eq. 37 is complex beyond ϑ̃ = 2/π):
///   ζ < 1: ℰ = exp(−ζ (π − 2 asin ζ)/√(1 − ζ²)),  ζ = 1: e⁻²,
///   ζ > 1: ℰ = exp(−(2ζ/√(ζ² − 1)) artanh(√(ζ² − 1)/ζ)).
double continuumRestitution(double zeta);

/// Which branch of the return map a point took in its last step (`flowState` in the VTU).
enum ViscoelasticState : int { elasticState = 0, flowingState = 1, separatedState = 2 };

/// Viscoelastic μ(I) with restitution-derived damping (`type: viscoelasticMuI`) [002 §2–3]:
///   σ = σᵉ + σᵛ [Eq. 10], σᵉ hypoelastic (Jaumann rate, rotationally neutralised update)
///   [Eq. 11–12], σᵛ = ϑ tr(Dᵛᵉ) 1 + 2η Dᵛᵉ_dev on the viscoelastic part Dᵛᵉ = D − Dᵖ of the rate
///   only [Eq. 13], μ(I) flow τ = μ(I) p [Eq. 43–44] with I = γ̇ᵖ d √(ρ_s/p), isochoric
///   Dᵖ = γ̇ᵖ σ_dev/(2τ) [Eq. 48–49], and no tension: σ = σᵉ = 0 when p_tr ≤ 0 or ρ ≤ ρ_c
///   [Eq. 46–47].
/// Per step and point ([002 §3.2], App. A), with ΔF = 1 + Δt L, D = sym L, W = skw L:
///   1. σᵉ_tr = Q σᵉ Qᵀ + ℂ : Δt D, Q = exp(Δt W) (exact for a rigid rotation, [Eq. 52]; the
///      increment in the end-of-step frame, docs/viscoelastic.md §5);
///   2. σ_tr = σᵉ_tr + ϑ tr D 1 + 2η D_dev [Eq. 51]; p_tr = −tr σ_tr/3, τ_tr = √(½ s_tr : s_tr);
///   3. separated if p_tr ≤ 0 or ρ ≤ ρ_c: σ = σᵉ = 0, γ̇ᵖ = 0;
///   4. elastic if τ_tr ≤ μ_s p_tr [Eq. 53]: σ = σ_tr, σᵉ = σᵉ_tr, γ̇ᵖ = 0;
///   5. flowing otherwise, with G̃ = G + η/Δt: α = I₀ G̃ Δt √p_tr/(d √ρ_s), S₀ = μ_s p_tr,
///      S₂ = μ₂ p_tr, B = S₂ + τ_tr + α, H = S₂ τ_tr + S₀ α, τ = 2H/(B + √(B² − 4H))
///      [Eq. 55–58] (the smaller root of τ = μ(I) p with I = I₀(τ_tr − τ)/α), p = p_tr [Eq. 56],
///      γ̇ᵖ = (τ_tr − τ)/(G̃ Δt) [Eq. 59], σ = (τ/τ_tr) s_tr − p 1 [Eq. 60];
///   6. σᵉ = σ − ϑ tr D 1 − 2η (D_dev − γ̇ᵖ N/√2), N = s_tr/|s_tr| [Eq. 61].
/// With ϑ = η = 0 (e = 1) it is the undamped hypoelastic μ(I) model: σ = σᵉ.
///
/// Keys: density ρ₀ = φ₀ ρ_s [kg/m³]; E [Pa]; nu; frictionAngle φ_s and frictionAngle2 φ₂ [deg]
/// (μ_s = tan φ_s, μ₂ = tan φ₂ in τ = √J₂ = μ p, as [002 §4]); I0 (default 0.278);
/// grainDiameter d [m]; grainDensity ρ_s [kg/m³]; the damping as `restitution: e` in (0, 1]
/// [Eq. 40, 42], or `bulkViscosity: ϑ` [Pa·s] with optional `shearViscosity: η` (default
/// (G/K) ϑ [Eq. 42]), or neither (undamped); criticalDensity ρ_c (default ρ₀) [kg/m³].
/// State: elasticStress σᵉ (restarted), plasticStrainRate γ̇ᵖ [1/s], flowState
/// (ViscoelasticState); plasticStrain accumulates ∫ γ̇ᵖ dt (the deviatoric plastic strain of
/// [002 Fig. 16] is plasticStrain/√3).
template <int dim> class ViscoelasticMuI final : public Material<dim> {
public:
    ViscoelasticMuI(const Dictionary& dict, const std::string& name);

    /// √(M/ρ₀) [m/s].
    double waveSpeed() const override;
    /// ϑ + 4η/3 [Pa·s]: the viscosity of a P wave, for the time-step limit [002 Eq. 79–80].
    double pWaveViscosity() const override { return bulkViscosity_ + 4.0 * shearViscosity_ / 3.0; }
    void declareState(Particles<dim>& p) override;
    void initialise(Particles<dim>& p, Index i, const Mat3& sigma0) const override;
    Index updateStress(Particles<dim>& p, const std::vector<Index>& ids, double dt) const override;
    /// Jaky's K0 = 1 − sin φ_s.
    double defaultK0() const override;
    /// Complementary energy of σᵉ, (p²/(2K) + s:s/(4G)) V [J].
    double strainEnergy(const Particles<dim>& p, Index i) const override;
    /// 0: the coupling sends every point's contact force through the grid [000 Eq. 19–20].
    /// Separation (ρ ≤ ρ_c or p_tr ≤ 0) is a state of this model's stress, reached and left
    /// every few steps by points at a wall or a body, not a gas with its own contact rule;
    /// under pure FLIP a force added to a separated point's own velocity is never taken back
    /// (the silo floor rang up to 48 m/s).
    double criticalDensity() const override { return 0.0; }
    bool volumeFromRate() const override { return true; } ///< [002 Eq. 76]
    /// ρ_c of the separation rule [002 Eq. 46–47] [kg/m³].
    double separationDensity() const { return rhoC_; }

    double bulkViscosity() const { return bulkViscosity_; }
    double shearViscosity() const { return shearViscosity_; }
    const ElasticConstants& elasticConstants() const { return c_; }

private:
    ElasticConstants c_;
    double muS_, mu2_;                                           ///< μ_s, μ₂ [-]
    double I0_;                                                  ///< I₀ [-]
    double grainDiameter_;                                       ///< d [m]
    double grainDensity_;                                        ///< ρ_s [kg/m³]
    double bulkViscosity_;                                       ///< ϑ [Pa·s]
    double shearViscosity_;                                      ///< η [Pa·s]
    double rhoC_;                                                ///< ρ_c [kg/m³]
    std::size_t elasticStress_ = 0, strainRate_ = 0, state_ = 0; ///< declared state handles
};

} // namespace mpm
