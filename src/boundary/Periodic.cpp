// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Periodic.hpp"

namespace mpm {

MPM_REGISTER(BoundaryConditionRegistry<2>, Periodic<2>, "periodic");
MPM_REGISTER(BoundaryConditionRegistry<3>, Periodic<3>, "periodic");

} // namespace mpm
