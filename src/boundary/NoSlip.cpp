// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/NoSlip.hpp"

namespace mpm {

MPM_REGISTER_DIMS(BoundaryConditionRegistry, NoSlip, "noSlip");
MPM_SCHEMA("boundaryConditions", "noSlip", {"fixed rough wall: v = 0", {}, "{type: noSlip}"});

} // namespace mpm
