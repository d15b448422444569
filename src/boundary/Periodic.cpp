// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Periodic.hpp"

namespace mpm {

MPM_REGISTER(BoundaryConditionRegistry<2>, Periodic<2>, "periodic");
MPM_REGISTER(BoundaryConditionRegistry<3>, Periodic<3>, "periodic");
MPM_SCHEMA("boundaryConditions", "periodic",
           {"the face and its opposite face are one periodic pair (whole faces only)",
            {},
            "{type: periodic}"});

} // namespace mpm
