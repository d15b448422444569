// SPDX-License-Identifier: GPL-3.0-or-later
#include "materials/HenckyElastic.hpp"

namespace mpm {

template class ElastoPlastic<2, HenckyLaw, NoPlasticity>;
template class ElastoPlastic<3, HenckyLaw, NoPlasticity>;

MPM_REGISTER(MaterialRegistry<2>, HenckyElastic<2>, "henckyElastic");
MPM_REGISTER(MaterialRegistry<3>, HenckyElastic<3>, "henckyElastic");

} // namespace mpm
