// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/DruckerPrager.hpp"

namespace mpm {

template <int dim>
DruckerPrager<dim>::DruckerPrager(const Dictionary& dict, const std::string& name)
    : HenckyGranular<dim>(dict, name),
      psi_(dict.getScalarOr("dilationAngle", 0.0, Bounds::closed(0.0, this->phi_))),
      beta_(frictionCoefficient(psi_)) {}

template <int dim>
Index DruckerPrager<dim>::updateStress(Particles<dim>& p, const std::vector<Index>& ids,
                                       double dt) const {
    const DruckerPragerFlow flow{this->muS_, beta_, this->c_.G, this->c_.K};
    return henckyReturnMapUpdate(p, ids, dt, this->c_, this->rhoC_, flow);
}

template class DruckerPrager<2>;
template class DruckerPrager<3>;

MPM_REGISTER(MaterialRegistry<2>, DruckerPrager<2>, "druckerPrager");
MPM_REGISTER(MaterialRegistry<3>, DruckerPrager<3>, "druckerPrager");

} // namespace mpm
