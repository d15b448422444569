// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/ViscoelasticMuI.hpp"

#include "core/Constants.hpp"
#include "materials/MaterialKeys.hpp"

#include <cmath>
#include <sstream>

namespace mpm {

TanMuIPlasticity::TanMuIPlasticity(const Dictionary& dict, const ElasticConstants& /*c*/,
                                   ElasticLaw /*law*/, int /*dim*/) {
    flow_.muS = std::tan(dict.getScalar("frictionAngle", {0.0, 90.0, false, false}) * degree);
    flow_.mu2 = std::tan(
        dict.getScalar("frictionAngle2", {std::atan(flow_.muS) / degree, 90.0, false, false}) *
        degree);
    flow_.I0 = dict.getScalarOr("I0", 0.278, Bounds::positive());
    flow_.grainDiameter = dict.getScalar("grainDiameter", Bounds::positive());
    flow_.grainDensity = dict.getScalar("grainDensity", Bounds::positive());
}

std::string TanMuIPlasticity::describe() const {
    std::ostringstream os;
    os << "    mu(I) of [002]: mu_s = tan(phi_s) = " << flow_.muS << ", mu_2 = " << flow_.mu2
       << ", I0 = " << flow_.I0 << ", grain diameter " << flow_.grainDiameter
       << " m, grain density " << flow_.grainDensity << " kg/m3\n";
    return os.str();
}

double TanMuIPlasticity::defaultK0(const ElasticConstants& /*c*/) const {
    return 1.0 - std::sin(std::atan(flow_.muS));
}

MPM_REGISTER_COMPOSITION(HypoelasticLaw, TanMuIPlasticity, KelvinVoigtViscosity, "viscoelasticMuI");

MPM_SCHEMA("materials", "viscoelasticMuI",
           {"viscoelastic μ(I) of [002], damped through the grains' coefficient of restitution",
            elasticKeys() +
                KeyList{{"frictionAngle", "scalar", "deg", "required",
                         "φ_s: μ_s = tan φ_s, in (0, 90)"},
                        {"frictionAngle2", "scalar", "deg", "required",
                         "φ₂: μ₂ = tan φ₂, in (frictionAngle, 90)"},
                        {"I0", "scalar", "-", "0.278", "I₀ of μ(I) (> 0)"},
                        {"grainDiameter", "scalar", "m", "required", "grain size d (> 0)"},
                        {"grainDensity", "scalar", "kg/m³", "required",
                         "grain density ρ_s (> 0; φ₀ = density/ρ_s)"},
                        {"restitution", "scalar", "-", "none",
                         "e in (0, 1]: ϑ and η from [002 Eq. 40, 42]; not with bulkViscosity"},
                        {"bulkViscosity", "scalar", "Pa·s", "0",
                         "ϑ (≥ 0) directly (not with restitution)"},
                        {"shearViscosity", "scalar", "Pa·s", "(G/K) ϑ",
                         "η (≥ 0) directly (not with restitution)"},
                        {"criticalDensity", "scalar", "kg/m³", "density",
                         "ρ_c (≥ 0): a point with ρ ≤ ρ_c carries no stress"}},
            "{type: viscoelasticMuI, density: 1500, E: 1.0e6, nu: 0.3, frictionAngle: 20.9, "
            "frictionAngle2: 32.8, grainDiameter: 0.001, grainDensity: 2500, restitution: 0.5}"});

} // namespace mpm
