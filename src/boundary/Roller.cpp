// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Roller.hpp"

namespace mpm {

MPM_REGISTER_DIMS(BoundaryConditionRegistry, Roller, "roller");
MPM_SCHEMA("boundaryConditions", "roller",
           {"fixed smooth wall the material can neither enter nor leave (a symmetry plane)",
            {},
            "{type: roller}"});

} // namespace mpm
