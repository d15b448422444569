// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/HenckyElastic.hpp"
#include "materials/MaterialKeys.hpp"

namespace mpm {

template class ElastoPlastic<2, HenckyLaw, NoPlasticity>;
template class ElastoPlastic<3, HenckyLaw, NoPlasticity>;

MPM_REGISTER_DIMS(MaterialRegistry, HenckyElastic, "henckyElastic");
MPM_SCHEMA("materials", "henckyElastic",
           {"Hencky hyperelasticity in the elastic left Cauchy-Green tensor [000 Eq. 4-5]",
            elasticKeys(), "{type: henckyElastic, density: 1100, E: 2.0e5, nu: 0.45}"});

} // namespace mpm
