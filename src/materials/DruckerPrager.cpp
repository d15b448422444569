// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/DruckerPrager.hpp"

#include <algorithm>
#include <sstream>
#include <string>

namespace mpm {

ConeFit readConeFit(const Dictionary& dict, ElasticLaw law) {
    const std::string def = law == ElasticLaw::hencky ? "compression" : "planeStrain";
    return dict.getWordOr("coneFit", def, {"compression", "planeStrain"}) == "compression"
               ? ConeFit::compression
               : ConeFit::planeStrain;
}

double coneFriction(ConeFit fit, double angleDegrees) {
    return fit == ConeFit::compression ? frictionCoefficient(angleDegrees)
                                       : planeStrainFrictionCoefficient(angleDegrees);
}

DruckerPragerPlasticity::DruckerPragerPlasticity(const Dictionary& dict, const ElasticConstants& c,
                                                 ElasticLaw law)
    : phi_(dict.getScalar("frictionAngle", {0.0, 90.0, false, false})),
      fit_(readConeFit(dict, law)),
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
}

template class ElastoPlastic<2, HenckyLaw, DruckerPragerPlasticity>;
template class ElastoPlastic<3, HenckyLaw, DruckerPragerPlasticity>;
template class ElastoPlastic<2, HypoelasticLaw, DruckerPragerPlasticity>;
template class ElastoPlastic<3, HypoelasticLaw, DruckerPragerPlasticity>;

static const MaterialRegistry<2>::Add
    registerDruckerPrager2("druckerPrager", createElastoPlastic<2, DruckerPragerPlasticity>);
static const MaterialRegistry<3>::Add
    registerDruckerPrager3("druckerPrager", createElastoPlastic<3, DruckerPragerPlasticity>);

} // namespace mpm
