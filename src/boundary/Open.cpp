// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Open.hpp"

namespace mpm {

MPM_REGISTER_DIMS(BoundaryConditionRegistry, Open, "open");
MPM_SCHEMA("boundaryConditions", "open",
           {"no condition; points more than a cell beyond it are removed", {}, "{type: open}"});

} // namespace mpm
