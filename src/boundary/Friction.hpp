// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/BoundaryCondition.hpp"

namespace mpm {

/// `type: friction, friction: μ`: a fixed Coulomb wall. When the velocity points into the
/// wall (v_n = v·n > 0) the normal component is removed and the tangential velocity v_t is
/// reduced by μ v_n, down to zero: v_t ← v_t max(0, 1 − μ v_n/|v_t|) (the impulse bound
/// |Δv_t| ≤ μ |Δv_n| of Coulomb friction). Material may separate freely.
template <int dim> class Friction final : public NodeRuleCondition<dim, Friction<dim>> {
public:
    explicit Friction(const Dictionary& dict)
        : mu_(dict.getScalar("friction", Bounds::nonNegative())) {}
    bool unilateral() const override { return true; }
    auto rule(const FaceNormal& n, double) const {
        return [n, mu = mu_](Vec<dim>& v) {
            const double vn = n.sign * v[n.axis];
            if (vn > 0) {
                v[n.axis] = 0;
                const double vt = v.norm();
                const double drop = mu * vn;
                v *= vt > drop ? (1.0 - drop / vt) : 0.0;
            }
        };
    }
    double coefficient() const { return mu_; }

private:
    double mu_; ///< Coulomb coefficient μ [-]
};

} // namespace mpm
