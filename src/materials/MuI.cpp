// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/MuI.hpp"

#include <cmath>

namespace mpm {

template <int dim>
MuI<dim>::MuI(const Dictionary& dict, const std::string& name)
    : HenckyGranular<dim>(dict, name),
      mu2_(frictionCoefficient(dict.getScalar("frictionAngle2", {this->phi_, 90.0, false, false}))),
      I0_(dict.getScalarOr("I0", 0.278, Bounds::positive())),
      grainDiameter_(dict.getScalar("grainDiameter", Bounds::positive())),
      grainDensity_(dict.getScalar("grainDensity", Bounds::positive())) {}

template <int dim> MuIFlow MuI<dim>::flow(double dt) const {
    return MuIFlow{this->muS_, mu2_ - this->muS_, I0_, this->c_.G,
                   grainDiameter_ * std::sqrt(grainDensity_) / dt};
}

template <int dim>
Index MuI<dim>::updateStress(Particles<dim>& p, const std::vector<Index>& ids, double dt) const {
    return henckyReturnMapUpdate(p, ids, dt, this->c_, this->rhoC_, flow(dt));
}

template class MuI<2>;
template class MuI<3>;

MPM_REGISTER(MaterialRegistry<2>, MuI<2>, "muI");
MPM_REGISTER(MaterialRegistry<3>, MuI<3>, "muI");

} // namespace mpm
