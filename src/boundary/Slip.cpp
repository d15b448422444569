// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Slip.hpp"

namespace mpm {

MPM_REGISTER_DIMS(BoundaryConditionRegistry, Slip, "slip");
MPM_SCHEMA("boundaryConditions", "slip",
           {"fixed smooth wall: the velocity into the wall is removed; material may separate",
            {},
            "{type: slip}"});

} // namespace mpm
