// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/BoundaryCondition.hpp"

namespace mpm {

/// `type: roller`: a smooth wall the material can neither enter nor leave, v·n ← 0 whatever its
/// sign (bilateral), the tangential velocity free: a symmetry plane, or a wall the material is
/// pressed against. Unlike `slip` (which releases a node moving away from the wall), it
/// never separates.
template <int dim> class Roller final : public NodeRuleCondition<dim, Roller<dim>> {
public:
    explicit Roller(const Dictionary&) {}
    auto rule(const FaceNormal& n, double) const {
        return [n](Vec<dim>& v) { v[n.axis] = 0; };
    }
};

} // namespace mpm
