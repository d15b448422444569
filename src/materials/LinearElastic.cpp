// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/LinearElastic.hpp"

namespace mpm {

template class ElastoPlastic<2, HypoelasticLaw, NoPlasticity>;
template class ElastoPlastic<3, HypoelasticLaw, NoPlasticity>;

MPM_REGISTER(MaterialRegistry<2>, LinearElastic<2>, "linearElastic");
MPM_REGISTER(MaterialRegistry<3>, LinearElastic<3>, "linearElastic");

} // namespace mpm
