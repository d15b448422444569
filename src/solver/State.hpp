// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "forces/BodyAcceleration.hpp"
#include "grid/Grid.hpp"
#include "materials/Material.hpp"
#include "parallel/Comm.hpp"
#include "particles/Particles.hpp"
#include "rigid/RigidBody.hpp"

#include <array>
#include <memory>
#include <vector>

namespace mpm {

/// What function objects may read of a running simulation.
///
/// Built by naming what it holds: the constructor takes the references, each of a type of its
/// own (two swapped do not compile), and the figures are set by name (State is not an aggregate,
/// so no positional list of numbers, where a misordered one would compile, can build it).
template <int dim> struct State {
    State(const Particles<dim>& p, const Grid<dim>& g,
          const std::vector<std::unique_ptr<Material<dim>>>& m, const Vec<dim>& gNow,
          const std::array<Vec<dim>, 2 * dim>& faceForces,
          const std::vector<std::unique_ptr<RigidBody<dim>>>& b, const BodyAcceleration<dim>& gOfT,
          const Comm& ranks = serialComm())
        : particles(p), grid(g), materials(m), gravity(gNow), reactions(faceForces), bodies(b),
          acceleration(gOfT), comm(ranks) {}

    const Particles<dim>& particles;
    const Grid<dim>& grid;
    const std::vector<std::unique_ptr<Material<dim>>>& materials;
    const Vec<dim>& gravity; ///< g of the last step (acceleration at its midpoint)
    /// Force the material exerted on each grid face in the last step [N] (per metre in 2D).
    const std::array<Vec<dim>, 2 * dim>& reactions;
    const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies;
    /// The body acceleration g(t) of constant/g.
    const BodyAcceleration<dim>& acceleration;
    /// The ranks of the run: a function object reduces what it sums over `particles` (this
    /// rank's only) with it; every other member is already the whole run's.
    const Comm& comm;

    /// Smallest signed distance ξ of any point to a coupled body at the end of the last step
    /// (+inf without bodies) [m]; negative means a point is inside a body.
    double minimumGap = 1e300;
    /// Points in contact with a body in the last step.
    Index contacts = 0;
    /// Current simulated time [s].
    double time = 0;
    /// Work of a time-varying g on the material and the free bodies since the start,
    /// ∫ Σ m g·v dt [J] (0 for a constant g, whose work is −Δ(−Σ m g·x)).
    double accelerationWork = 0;
    /// minimumGap before the coupling projected points out (Coupling::enforceGap) [m]: what the
    /// force law alone achieved.
    double minimumGapBeforeProjection = 1e300;
};

} // namespace mpm
