// SPDX-License-Identifier: GPL-3.0-or-later
#include "boundary/Friction.hpp"

namespace mpm {

MPM_REGISTER_DIMS(BoundaryConditionRegistry, Friction, "friction");
MPM_SCHEMA("boundaryConditions", "friction",
           {"as slip, with Coulomb friction on the tangential velocity",
            {{"friction", "scalar", "-", "required", "Coulomb coefficient μ (≥ 0)"}},
            "{type: friction, friction: 0.5}"});

} // namespace mpm
