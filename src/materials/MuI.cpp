// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/MuI.hpp"
#include "materials/MaterialKeys.hpp"

#include <cmath>
#include <sstream>

namespace mpm {

MuIPlasticity::MuIPlasticity(const Dictionary& dict, const ElasticConstants& c, ElasticLaw /*law*/,
                             int dim)
    : G_(c.G), phi_(dict.getScalar("frictionAngle", {0.0, 90.0, false, false})),
      fit_(readConeFit(dict)), muS_(coneFriction(fit_, phi_)),
      mu2_(coneFriction(fit_, dict.getScalar("frictionAngle2", {phi_, 90.0, false, false}))),
      I0_(dict.getScalarOr("I0", 0.278, Bounds::positive())),
      grainDiameter_(dict.getScalar("grainDiameter", Bounds::positive())),
      grainDensity_(dict.getScalar("grainDensity", Bounds::positive())) {
    warnConeFit(dict, fit_, dim, phi_);
}

std::string MuIPlasticity::describe() const {
    std::ostringstream os;
    os << "    mu(I), cone fit " << coneFitName(fit_) << ": " << describeCone("mu_s", muS_)
       << "\n    " << describeCone("mu_2", mu2_) << "\n    I0 = " << I0_ << ", grain diameter "
       << grainDiameter_ << " m, grain density " << grainDensity_ << " kg/m3\n";
    return os.str();
}

MuIFlow MuIPlasticity::flow(double dt) const {
    return MuIFlow{muS_, mu2_ - muS_, I0_, G_, grainDiameter_ * std::sqrt(grainDensity_) / dt};
}

MPM_REGISTER_PLASTICITY(MuIPlasticity, "muI");
MPM_SCHEMA("materials", "muI",
           {"μ(I) rheology [000 Eq. 9]",
            elasticKeys() + granularKeys() +
                KeyList{{"frictionAngle2", "scalar", "deg", "required",
                         "φ₂ of the limiting friction μ₂, in (frictionAngle, 90)"},
                        {"I0", "scalar", "-", "0.278", "I₀ of μ(I) (> 0)"},
                        {"grainDiameter", "scalar", "m", "required", "mean grain size d (> 0)"},
                        {"grainDensity", "scalar", "kg/m³", "required",
                         "grain (solid) density ρ_s (> 0)"}},
            "{type: muI, density: 1530, E: 1.0e6, nu: 0.3, frictionAngle: 20.9, frictionAngle2: "
            "32.8, grainDiameter: 0.0007, grainDensity: 2600}"});

} // namespace mpm
