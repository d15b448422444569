// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Constants.hpp"
#include "materials/ElastoPlastic.hpp"

#include <string>

namespace mpm {

/// The friction angle → cone coefficient fit of a Drucker–Prager cone (key `coneFit`).
enum class ConeFit {
    compression, ///< through Mohr–Coulomb's compression corners [000 Eq. 8]
    planeStrain  ///< Mohr–Coulomb in plane strain [001 Eq. 35]
};

/// Read `coneFit` (compression | planeStrain). The default is planeStrain in 2D and 3D: a
/// granular material fails and flows in shear, and in simple shear (plane strain at zero
/// dilatancy) this fit keeps φ; it is also μ(I)'s μ = |τ|/p. The compression fit [000 Eq. 8]
/// keeps φ in triaxial compression, where the plane-strain fit acts weaker (30° → 21.4°);
/// docs/settingsGuide.md has the measurements.
ConeFit readConeFit(const Dictionary& dict);
/// μ (or q_φ) of an angle [deg] by `fit`.
double coneFriction(ConeFit fit, double angleDegrees);
/// Warn when `coneFit: compression` is chosen in a 2D run, which is plane strain: a friction
/// angle φ [deg] then acts as a steeper one (φ = 30° acts as 49.1°).
void warnConeFit(const Dictionary& dict, ConeFit fit, int dim, double angleDegrees);
/// "μ = 0.4629 (φ = 30° in plane strain, 23.7° in triaxial compression)": a cone coefficient
/// and the Mohr–Coulomb angles it amounts to.
std::string describeCone(const std::string& symbol, double mu);
/// The word of a cone fit.
const char* coneFitName(ConeFit fit);

/// Rate-independent Drucker–Prager plasticity (`type: druckerPrager`), the plasticity of
/// ElastoPlastic: shear surface f = q − μ p − k ≤ 0 [000 Eq. 6–8], [001 Eq. 31b] with
/// p = −tr σ/3, q = √J₂, potential g = q − β p, and for the hypoelastic law the tension cut-off
/// −p ≤ σ_t [001 Eq. 32]. μ, β and k come from φ, ψ and c by the cone fit.
/// Keys: frictionAngle [deg] (0, 90), dilationAngle [deg] [0, φ] (default 0), coneFit,
/// cohesion c [Pa] (≥ 0, default 0; > 0 only with hypoelastic), tensionStrength σ_t [Pa]
/// ([0, c/tan φ], default c/tan φ, the apex).
class DruckerPragerPlasticity {
public:
    static constexpr bool plastic = true;

    DruckerPragerPlasticity(const Dictionary& dict, const ElasticConstants& c, ElasticLaw law,
                            int dim);
    /// The derived constants, for the log (Material::describe).
    std::string describe() const;

    DruckerPragerFlow flow(double /*dt*/) const { return flow_; }
    TensionCutoff cutoff() const { return cutoff_; }
    /// Jaky's K0 = 1 − sin φ.
    double defaultK0(const ElasticConstants& /*c*/) const {
        return 1.0 - std::sin(phi_ * pi / 180.0);
    }

    /// Friction angle φ [deg].
    double frictionAngle() const { return phi_; }
    /// Dilation angle ψ [deg].
    double dilationAngle() const { return psi_; }
    ConeFit coneFit() const { return fit_; }
    /// μ (q_φ) [-].
    double staticFriction() const { return flow_.mu; }
    /// β (q_ψ) [-].
    double dilatancy() const { return flow_.beta; }
    /// Cohesion c [Pa].
    double cohesion() const { return cohesion_; }
    /// Cohesion coefficient k (k_φ) [Pa].
    double cohesionCoefficient() const { return flow_.k; }
    /// Tension strength σ_t [Pa].
    double tensionStrength() const { return cutoff_.sigmaT; }

private:
    double phi_;
    ConeFit fit_;
    double psi_;
    double cohesion_;
    DruckerPragerFlow flow_;
    TensionCutoff cutoff_;
};

/// `druckerPrager` with the elastic law of `elasticity:` (default hencky).
template <int dim, class Law = HenckyLaw>
using DruckerPrager = ElastoPlastic<dim, Law, DruckerPragerPlasticity>;

} // namespace mpm
