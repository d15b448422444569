// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "materials/Material.hpp"

#include <string>

// Viscosity policies of ElastoPlastic (ElastoPlastic.hpp): the stress is σ = σᵉ + σᵛ [002 Eq. 10],
// σᵉ of the elastic law, σᵛ a viscous stress on the viscoelastic part of the rate. Chosen at
// compile time, as the law and the plasticity:
//  - NoViscosity (the default): σ = σᵉ, the inviscid kernels; no per-point branch on a zero
//    viscosity: an inviscid material has the per-point code it had before the policy existed.
//  - KelvinVoigtViscosity: σᵛ = ϑ tr D 1 + 2η D_dev (`viscoelasticMuI`).
// A viscous policy (viscous = true) makes ElastoPlastic carry σᵉ beside σ (the `elasticStress`
// field) and run the law's viscous return map (ViscoelasticReturnMap.hpp), which reads the policy
// through `volumetric`, `deviatoric` and `shearViscosity`.

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

/// No viscosity: σ = σᵉ. Reads no keys.
struct NoViscosity {
    static constexpr bool viscous = false;

    NoViscosity(const Dictionary& /*dict*/, const ElasticConstants& /*c*/, double /*density*/) {}
    std::string describe() const { return {}; }
    /// ϑ + 4η/3 = 0 [Pa·s].
    double pWaveViscosity() const { return 0.0; }
};

/// Kelvin–Voigt viscosity on the viscoelastic rate [002 Eq. 13]:
///   σᵛ = ϑ tr(Dᵛᵉ) 1 + 2η Dᵛᵉ_dev [Pa],
/// ϑ the bulk and η the shear viscosity [Pa·s], Dᵛᵉ = D − Dᵖ [1/s].
/// Keys: `restitution: e` in (0, 1]: ϑ from [002 Eq. 40] (with grainDiameter d [m], M and the
/// density ρ₀ = φ ρ_s) and η = (G/K) ϑ [002 Eq. 42]; or `bulkViscosity: ϑ` [Pa·s] with optional
/// `shearViscosity: η` (default (G/K) ϑ); or neither (ϑ = η = 0: the undamped model, same code).
class KelvinVoigtViscosity {
public:
    static constexpr bool viscous = true;

    KelvinVoigtViscosity(const Dictionary& dict, const ElasticConstants& c, double density);
    std::string describe() const;
    /// ϑ + 4η/3 [Pa·s]: the viscosity of a P wave, for the time-step limit [002 Eq. 79–80].
    double pWaveViscosity() const { return bulk_ + 4.0 * shear_ / 3.0; }
    double bulkViscosity() const { return bulk_; }   ///< ϑ [Pa·s]
    double shearViscosity() const { return shear_; } ///< η [Pa·s]

    /// ϑ tr D [Pa], added to each diagonal entry of σᵛ (tr D [1/s]).
    double volumetric(double trD) const { return bulk_ * trD; }
    /// 2η d [Pa] of an entry d of the deviatoric rate D_dev [1/s].
    double deviatoric(double dDev) const { return 2.0 * shear_ * dDev; }
    /// σᵛ = ϑ tr D 1 + 2η D_dev [Pa] of a symmetric rate D [1/s] [002 Eq. 13].
    Mat3 stress(const Mat3& D) const;

private:
    double bulk_;  ///< ϑ [Pa·s]
    double shear_; ///< η [Pa·s]
};

} // namespace mpm
