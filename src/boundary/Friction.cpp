// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Friction.hpp"

namespace mpm {

MPM_REGISTER(BoundaryConditionRegistry<2>, Friction<2>, "friction");
MPM_REGISTER(BoundaryConditionRegistry<3>, Friction<3>, "friction");

} // namespace mpm
