// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/LinearElastic.hpp"
#include "materials/MaterialKeys.hpp"

namespace mpm {

template class ElastoPlastic<2, HypoelasticLaw, NoPlasticity>;
template class ElastoPlastic<3, HypoelasticLaw, NoPlasticity>;

MPM_REGISTER_DIMS(MaterialRegistry, LinearElastic, "linearElastic");
MPM_SCHEMA("materials", "linearElastic",
           {"linear elasticity, hypoelastic (Jaumann rate) [001 Eq. 25, 36]", elasticKeys(),
            "{type: linearElastic, density: 1000, E: 1.0e6, nu: 0.3}"});

} // namespace mpm
