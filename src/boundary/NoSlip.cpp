// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/NoSlip.hpp"

namespace mpm {

MPM_REGISTER(BoundaryConditionRegistry<2>, NoSlip<2>, "noSlip");
MPM_REGISTER(BoundaryConditionRegistry<3>, NoSlip<3>, "noSlip");
MPM_SCHEMA("boundaryConditions", "noSlip", {"fixed rough wall: v = 0", {}, "{type: noSlip}"});

} // namespace mpm
