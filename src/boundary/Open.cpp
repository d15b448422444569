// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Open.hpp"

namespace mpm {

MPM_REGISTER(BoundaryConditionRegistry<2>, Open<2>, "open");
MPM_REGISTER(BoundaryConditionRegistry<3>, Open<3>, "open");

} // namespace mpm
