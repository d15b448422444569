// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/DruckerPrager.hpp"

#include "core/Log.hpp"
#include "materials/MaterialKeys.hpp"

#include <algorithm>
#include <iomanip>
#include <sstream>
#include <string>

namespace mpm {

ConeFit readConeFit(const Dictionary& dict) {
    return dict.getWordOr("coneFit", "planeStrain", {"planeStrain", "compression"}) == "compression"
               ? ConeFit::compression
               : ConeFit::planeStrain;
}

const char* coneFitName(ConeFit fit) {
    return fit == ConeFit::compression ? "compression" : "planeStrain";
}

std::string describeCone(const std::string& symbol, double mu) {
    std::ostringstream os;
    os << std::setprecision(4) << symbol << " = " << mu << std::setprecision(3)
       << " (φ = " << planeStrainAngle(mu) << "° in plane strain, " << compressionAngle(mu)
       << "° in triaxial compression)";
    return os.str();
}

void warnConeFit(const Dictionary& dict, ConeFit fit, int dim, double angleDegrees) {
    if (dim != 2 || fit != ConeFit::compression) return;
    const double mu = coneFriction(fit, angleDegrees);
    warning() << dict.fileName() << ':' << dict.line("coneFit")
              << ": coneFit: compression in a 2D run: φ = " << angleDegrees
              << "° gives μ = " << std::setprecision(4) << mu
              << ", which acts as φ = " << std::setprecision(3) << planeStrainAngle(mu)
              << "° in plane strain; the default 'planeStrain' keeps φ (docs/settingsGuide.md)\n";
}

double coneFriction(ConeFit fit, double angleDegrees) {
    return fit == ConeFit::compression ? frictionCoefficient(angleDegrees)
                                       : planeStrainFrictionCoefficient(angleDegrees);
}

DruckerPragerPlasticity::DruckerPragerPlasticity(const Dictionary& dict, const ElasticConstants& c,
                                                 ElasticLaw law, int dim)
    : phi_(dict.getScalar("frictionAngle", {0.0, 90.0, false, false})), fit_(readConeFit(dict)),
      psi_(dict.getScalarOr("dilationAngle", 0.0, Bounds::closed(0.0, phi_))),
      cohesion_(dict.getScalarOr("cohesion", 0.0, Bounds::nonNegative())),
      flow_{coneFriction(fit_, phi_), coneFriction(fit_, psi_), c.G, c.K} {
    if (law == ElasticLaw::hencky && cohesion_ > 0.0)
        dict.error("cohesion", "cohesion > 0 needs 'elasticity: hypoelastic' (the Hencky return "
                               "map is cohesionless)");
    flow_.k = fit_ == ConeFit::compression ? mpm::cohesionCoefficient(cohesion_, phi_)
                                           : planeStrainCohesionCoefficient(cohesion_, phi_);
    // The apex of the shear cone, σ_m = k/μ = c/tan φ: the largest meaningful cut-off.
    const double apex = flow_.k / flow_.mu;
    cutoff_.sigmaT = dict.getScalarOr("tensionStrength", apex, Bounds::nonNegative());
    if (cutoff_.sigmaT > apex) {
        std::ostringstream msg;
        msg << "expected at most the apex of the shear cone, c/tan φ = " << apex
            << " Pa (0 without cohesion), got " << cutoff_.sigmaT;
        dict.error("tensionStrength", msg.str());
    }
    cutoff_.tauC =
        cutoff_.sigmaT == apex ? 0.0 : std::max(0.0, flow_.k - flow_.mu * cutoff_.sigmaT);
    warnConeFit(dict, fit_, dim, phi_);
}

std::string DruckerPragerPlasticity::describe() const {
    std::ostringstream os;
    os << "    Drucker-Prager, cone fit " << coneFitName(fit_) << ": "
       << describeCone("mu", flow_.mu) << "\n    dilatancy " << describeCone("beta", flow_.beta)
       << '\n';
    if (cohesion_ > 0.0)
        os << "    cohesion " << cohesion_ << " Pa: k = " << flow_.k << " Pa, tension cut-off "
           << cutoff_.sigmaT << " Pa\n";
    return os.str();
}

MPM_REGISTER_PLASTICITY(DruckerPragerPlasticity, "druckerPrager");
MPM_SCHEMA("materials", "druckerPrager",
           {"Drucker-Prager plasticity; cohesion, tension cut-off and dilation with elasticity: "
            "hypoelastic [000], [001 Eq. 31b-36]",
            elasticKeys() + granularKeys() +
                KeyList{{"dilationAngle", "scalar", "deg", "0",
                         "dilation angle ψ, in [0, frictionAngle]: 0 isochoric, = φ associated"},
                        {"cohesion", "scalar", "Pa", "0",
                         "cohesion c (≥ 0); > 0 only with elasticity: hypoelastic"},
                        {"tensionStrength", "scalar", "Pa", "c/tan φ",
                         "tension cut-off σ_t, in [0, c/tan φ] (the apex of the cone)"}},
            "{type: druckerPrager, density: 1530, E: 1.0e6, nu: 0.3, frictionAngle: 35}"});

} // namespace mpm
