// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Open.hpp"

namespace mpm {

MPM_REGISTER(BoundaryConditionRegistry<2>, Open<2>, "open");
MPM_REGISTER(BoundaryConditionRegistry<3>, Open<3>, "open");
MPM_SCHEMA("boundaryConditions", "open",
           {"no condition; points more than a cell beyond it are removed", {}, "{type: open}"});

} // namespace mpm
