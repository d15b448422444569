// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Periodic.hpp"

namespace mpm {

MPM_REGISTER_DIMS(BoundaryConditionRegistry, Periodic, "periodic");
MPM_SCHEMA("boundaryConditions", "periodic",
           {"the face and its opposite face are one periodic pair (whole faces only)",
            {},
            "{type: periodic}"});

} // namespace mpm
