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
template <int dim> struct State {
    const Particles<dim>& particles;
    const Grid<dim>& grid;
    const std::vector<std::unique_ptr<Material<dim>>>& materials;
    const Vec<dim>& gravity; ///< g of the last step (acceleration at its midpoint)
    /// Force the material exerted on each grid face in the last step [N] (per metre in 2D).
    const std::array<Vec<dim>, 2 * dim>& reactions;
    const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies;
    /// Smallest signed distance ξ of any point to a coupled body at the end of the last step
    /// (+inf without bodies) [m]; negative means a point is inside a body.
    double minimumGap;
    /// Points in contact with a body in the last step.
    Index contacts;
    /// Current simulated time [s].
    double time;
    /// The body acceleration g(t) of constant/g.
    const BodyAcceleration<dim>& acceleration;
    /// Work of a time-varying g on the material and the free bodies since the start,
    /// ∫ Σ m g·v dt [J] (0 for a constant g, whose work is −Δ(−Σ m g·x)).
    double accelerationWork;
    /// minimumGap before the coupling projected points out (Coupling::enforceGap) [m]: what the
    /// force law alone achieved.
    double minimumGapBeforeProjection;
    /// The ranks of the run: a function object reduces what it sums over `particles` (this
    /// rank's only) with it; every other member is already the whole run's.
    const Comm& comm = serialComm();
};

} // namespace mpm
