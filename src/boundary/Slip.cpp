// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Slip.hpp"

namespace mpm {

MPM_REGISTER(BoundaryConditionRegistry<2>, Slip<2>, "slip");
MPM_REGISTER(BoundaryConditionRegistry<3>, Slip<3>, "slip");

} // namespace mpm
