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

/// The nodes one condition acts on in one call: `nodes[0 .. owners)` are owner nodes, whose
/// momentum change counts in the reaction; `nodes[owners ..)` are periodic images of owners
/// (ghost layers across a periodic seam), constrained alike but not counted twice.
struct PatchNodes {
    const std::vector<Index>* nodes = nullptr;
    Index owners = 0;
};

/// Grid node fields a condition reads after the grid update (the reaction's reference state).
template <int dim> struct NodeState {
    const NodeArray<double>& mass;
    const NodeArray<Vec<dim>>& vOld;  ///< velocity before the update v⁰ [m/s]
    const NodeArray<Vec<dim>>& force; ///< internal + coupling force f [N]
};

/// A boundary condition of a patch of a grid face (`constant/grid` boundary.<face>[.<patch>]
/// `type:`), chosen through the registry. The virtual calls are per patch, never per node: each
/// call runs over the patch's node list.
template <int dim> class BoundaryCondition {
public:
    virtual ~BoundaryCondition() = default;

    /// Constrain the velocities v_i of the nodes of `p` that carry mass, at time t [s]
    /// (the P2G velocity: no reaction is recorded).
    virtual void constrain(const PatchNodes& p, const FaceNormal& n, const NodeArray<double>& mass,
                           NodeArray<Vec<dim>>& v, double t) const = 0;

    /// Constrain the updated velocities v_i at time t and return the reaction, the force the
    /// material exerts on the patch, F = Σ m_i (v_i⁻ − v_i⁺)/Δt over the owner nodes [N]
    /// (per metre in 2D) [000 §4.2]. v⁻ is the undamped update v⁰ + Δt (f/m + g) for the first
    /// condition acting on a node in this step (`touched` is 0), otherwise the velocity the
    /// previous condition left (edges and corners).
    virtual Vec<dim> constrainUpdate(const PatchNodes& p, const FaceNormal& n,
                                     const NodeState<dim>& s, NodeArray<Vec<dim>>& v,
                                     const Vec<dim>& gravity, double t, double dt,
                                     NodeArray<char>& touched) const = 0;

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
    /// Material may leave through the patch (particles beyond it are removed).
    virtual bool open() const { return false; }
    /// The face is one side of a periodic pair (no constraint; the lattice is folded instead).
    virtual bool periodic() const { return false; }

    /// Build the condition named by `dict`'s `type:`; the caller reads the patch keys (box,
    /// from, until) of the same map and then checks its keys (BoundaryConditions::readPatch).
    static std::unique_ptr<BoundaryCondition> create(const Dictionary& dict);
    /// Names of the registered conditions, sorted.
    static std::vector<std::string> typeNames();
};

template <int dim> using BoundaryConditionRegistry = Registry<BoundaryCondition<dim>>;

/// The node loops of a condition that changes each node's velocity by a rule, written once:
/// `Derived::rule(n, t)` returns a small function object `r(Vec<dim>& v)` for the call (all
/// time-dependent values evaluated once per patch), which the loops below apply inline.
template <int dim, class Derived> class NodeRuleCondition : public BoundaryCondition<dim> {
public:
    void constrain(const PatchNodes& p, const FaceNormal& n, const NodeArray<double>& mass,
                   NodeArray<Vec<dim>>& v, double t) const override {
        const auto rule = static_cast<const Derived&>(*this).rule(n, t);
        for (Index i : *p.nodes)
            if (mass[i] != 0) rule(v[i]);
    }

    Vec<dim> constrainUpdate(const PatchNodes& p, const FaceNormal& n, const NodeState<dim>& s,
                             NodeArray<Vec<dim>>& v, const Vec<dim>& gravity, double t, double dt,
                             NodeArray<char>& touched) const override {
        const auto rule = static_cast<const Derived&>(*this).rule(n, t);
        const std::vector<Index>& nodes = *p.nodes;
        const Index count = static_cast<Index>(nodes.size());
        Vec<dim> reaction = Vec<dim>::Zero();
        for (Index k = 0; k < p.owners; ++k) {
            const Index i = nodes[k];
            const double m = s.mass[i];
            if (m == 0) continue;
            Vec<dim> before = v[i];
            if (!touched[i]) {
                before = s.vOld[i] + dt * (s.force[i] / m + gravity);
                touched[i] = 1;
            }
            rule(v[i]);
            reaction += m * (before - v[i]) / dt;
        }
        for (Index k = p.owners; k < count; ++k)
            if (s.mass[nodes[k]] != 0) rule(v[nodes[k]]);
        return reaction;
    }
};

} // namespace mpm
