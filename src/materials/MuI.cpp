// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/MuI.hpp"

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

template class ElastoPlastic<2, HenckyLaw, MuIPlasticity>;
template class ElastoPlastic<3, HenckyLaw, MuIPlasticity>;
template class ElastoPlastic<2, HypoelasticLaw, MuIPlasticity>;
template class ElastoPlastic<3, HypoelasticLaw, MuIPlasticity>;

static const MaterialRegistry<2>::Add registerMuI2("muI", createElastoPlastic<2, MuIPlasticity>);
static const MaterialRegistry<3>::Add registerMuI3("muI", createElastoPlastic<3, MuIPlasticity>);

} // namespace mpm
