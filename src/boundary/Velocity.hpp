// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/BoundaryCondition.hpp"

#include <vector>

namespace mpm {

/// `type: velocity`: a wall moving with a prescribed velocity w(t) — a constant
/// `value: [wx, wy(, wz)]`, or a `table: [[t, wx, wy(, wz)], …]` linear in t between rows and
/// held at the first and last rows beyond the ends [m/s]. The nodes stay where they are: the
/// condition prescribes velocity, not a moving face position (a shear lid, a conveyor, an
/// inflow, a small normal motion).
///
/// - `slip: no` (default), a rough moving wall: v_i ← w on every node (the material sticks,
///   also when it would separate; with w = 0 this is noSlip exactly).
/// - `slip: yes`, a smooth moving wall: only the normal component, and only when the material
///   moves into the wall relative to it: (v − w)·n > 0 ⇒ v·n ← w·n; the tangential velocity is
///   free (with w = 0 this is slip exactly).
template <int dim> class Velocity final : public NodeRuleCondition<dim, Velocity<dim>> {
public:
    explicit Velocity(const Dictionary& dict);

    /// w(t) [m/s].
    Vec<dim> wallVelocity(double t) const;
    /// The smooth wall (`slip: yes`) releases nodes that leave it.
    bool unilateral() const override { return slip_; }
    double wallNormalVelocity(const FaceNormal& n, double t) const override {
        return wallVelocity(t)[n.axis];
    }

    auto rule(const FaceNormal& n, double t) const {
        const Vec<dim> w = wallVelocity(t);
        return [n, w, slip = slip_](Vec<dim>& v) {
            if (!slip)
                v = w;
            else if (n.sign * (v[n.axis] - w[n.axis]) > 0)
                v[n.axis] = w[n.axis];
        };
    }

private:
    std::vector<double> times_;  ///< table times, strictly increasing [s]
    std::vector<Vec<dim>> rows_; ///< w at times_ [m/s] (one row for a constant value)
    bool slip_ = false;
};

} // namespace mpm
