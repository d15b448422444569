// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Slip.hpp"

namespace mpm {

MPM_REGISTER(BoundaryConditionRegistry<2>, Slip<2>, "slip");
MPM_REGISTER(BoundaryConditionRegistry<3>, Slip<3>, "slip");
MPM_SCHEMA("boundaryConditions", "slip",
           {"fixed smooth wall: the velocity into the wall is removed; material may separate",
            {},
            "{type: slip}"});

} // namespace mpm
