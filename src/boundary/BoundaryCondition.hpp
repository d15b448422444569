// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "case/Registry.hpp"
#include "core/Types.hpp"
#include "grid/NodeArray.hpp"

#include <memory>
#include <vector>

namespace mpm {

/// Outward unit normal of a grid face, n = sign · e_axis (sign -1 on xMin, +1 on xMax, …).
struct FaceNormal {
    int axis = 0;
    double sign = -1.0;
};

/// A boundary condition of a patch of a grid face (`constant/grid` boundary.<face>[.<patch>]
/// `type:`), chosen through the registry: a rule that constrains the patch's node velocities.
/// The face kinds that constrain no node, `open` and `periodic`, are not conditions but handled
/// by the set (FaceKind, BoundaryConditions). The virtual calls are per patch, never per node: each
/// call runs over the patch's node list.
template <int dim> class BoundaryCondition {
public:
    virtual ~BoundaryCondition() = default;

    /// Constrain the velocities v_i of the `nodes` that carry mass, at time t [s]: the P2G
    /// velocity, or the updated one (BoundaryConditions then books the reaction, the momentum
    /// the rule took out of its owner nodes).
    virtual void apply(const std::vector<Index>& nodes, const FaceNormal& n,
                       const NodeArray<double>& mass, NodeArray<Vec<dim>>& v, double t) const = 0;

    /// The condition releases a node whose updated velocity leaves the wall (slip, friction).
    /// Its P2G velocity is then not constrained by the rule but by the contact the last grid
    /// update found (BoundaryConditions::constrain): deciding contact twice per step, once on
    /// each velocity, lets the strain and the motion see different walls and pumps energy into
    /// pure FLIP under USF and MUSL.
    virtual bool unilateral() const { return false; }
    /// For a unilateral condition, the wall's velocity along the face axis at time t, w·e_axis
    /// [m/s]: a node pressed against the wall takes it as its normal velocity (0 for a fixed
    /// wall).
    virtual double wallNormalVelocity(const FaceNormal& /*n*/, double /*t*/) const { return 0.0; }

    /// Build the condition named by `dict`'s `type:`; the caller reads the patch keys (box,
    /// from, until) of the same map and then checks its keys (BoundaryConditions::readPatch).
    static std::unique_ptr<BoundaryCondition> create(const Dictionary& dict);
};

template <int dim> using BoundaryConditionRegistry = Registry<BoundaryCondition<dim>>;

/// The node loop of a condition that changes each node's velocity by a rule, written once:
/// `Derived::rule(n, t)` returns a small function object `r(Vec<dim>& v)` for the call (all
/// time-dependent values evaluated once per patch), which the loop applies inline.
template <int dim, class Derived> class NodeRuleCondition : public BoundaryCondition<dim> {
public:
    void apply(const std::vector<Index>& nodes, const FaceNormal& n, const NodeArray<double>& mass,
               NodeArray<Vec<dim>>& v, double t) const override {
        const auto rule = static_cast<const Derived&>(*this).rule(n, t);
        for (Index i : nodes)
            if (mass[i] != 0) rule(v[i]);
    }
};

} // namespace mpm
