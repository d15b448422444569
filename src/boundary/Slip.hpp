// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/BoundaryCondition.hpp"

namespace mpm {

/// `type: slip`: a fixed smooth wall. The normal velocity is removed when it points into the
/// wall, v_n = v·n > 0 ⇒ v·n ← 0; material may separate and slides freely along it. The
/// default of every face.
template <int dim> class Slip final : public NodeRuleCondition<dim, Slip<dim>> {
public:
    explicit Slip(const Dictionary&) {}
    bool unilateral() const override { return true; }
    auto rule(const FaceNormal& n, double) const {
        return [n](Vec<dim>& v) {
            if (n.sign * v[n.axis] > 0) v[n.axis] = 0;
        };
    }
};

} // namespace mpm
