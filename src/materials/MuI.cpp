// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/MuI.hpp"

#include <cmath>

namespace mpm {

MuIPlasticity::MuIPlasticity(const Dictionary& dict, const ElasticConstants& c, ElasticLaw law)
    : G_(c.G), phi_(dict.getScalar("frictionAngle", {0.0, 90.0, false, false})),
      fit_(readConeFit(dict, law)), muS_(coneFriction(fit_, phi_)),
      mu2_(coneFriction(fit_, dict.getScalar("frictionAngle2", {phi_, 90.0, false, false}))),
      I0_(dict.getScalarOr("I0", 0.278, Bounds::positive())),
      grainDiameter_(dict.getScalar("grainDiameter", Bounds::positive())),
      grainDensity_(dict.getScalar("grainDensity", Bounds::positive())) {}

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
