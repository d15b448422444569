// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/BoundaryCondition.hpp"

namespace mpm {

/// `type: noSlip`: a fixed rough wall, v_i = 0 on every node of the patch (material sticks).
template <int dim> class NoSlip final : public NodeRuleCondition<dim, NoSlip<dim>> {
public:
    explicit NoSlip(const Dictionary&) {}
    auto rule(const FaceNormal&, double) const {
        return [](Vec<dim>& v) { v.setZero(); };
    }
};

} // namespace mpm
