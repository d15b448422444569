// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "forces/BodyAcceleration.hpp"
#include "grid/Grid.hpp"
#include "materials/Material.hpp"
#include "parallel/Comm.hpp"
#include "particles/Particles.hpp"
#include "rigid/BodySet.hpp"
#include "solver/Reduce.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <vector>

// Measures of the simulation state the step's checks use (CFL speed, blow-up budget, work of g).

namespace mpm {

/// Σ ψ V over the points [J]: each material's strainEnergies on its points (one call per
/// material), summed in fixed chunks (the same bits for any thread count).
template <int dim>
double totalStrainEnergy(const Particles<dim>& p,
                         const std::vector<std::unique_ptr<Material<dim>>>& materials) {
    const Index n = static_cast<Index>(p.size());
    std::vector<std::vector<Index>> ids(materials.size());
    for (Index i = 0; i < n; ++i)
        ids[p.material[i]].push_back(i);
    std::vector<double> energy(p.size(), 0.0);
    for (std::size_t m = 0; m < materials.size(); ++m)
        if (!ids[m].empty()) materials[m]->strainEnergies(p, ids[m], energy);
    return deterministicSum(n, [&](Index i) { return energy[i]; });
}

/// The largest point speed and body rim speed |v| + |ω| R [m/s] (bodies count for the CFL).
template <int dim> double maxSpeed(const Particles<dim>& p, const BodySet<dim>& bodies) {
    const Index n = static_cast<Index>(p.size());
    double speed = 0;
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(max : speed)
    for (Index i = 0; i < n; ++i)
        speed = std::max(speed, p.v[i].norm());
    return std::max(speed, bodies.maxRimSpeed());
}

/// The fastest point (the first of equals).
template <int dim> Index fastestParticle(const Particles<dim>& p) {
    Index worst = 0;
    for (Index i = 0; i < static_cast<Index>(p.size()); ++i)
        if (p.v[i].norm() > p.v[worst].norm()) worst = i;
    return worst;
}

/// Σ m_p x_p + Σ m_b x_b over the points (of every rank of `comm`) and the bodies that g moves
/// (free, driven) [kg m].
template <int dim>
Vec<dim> massMoment(const Particles<dim>& p, const BodySet<dim>& bodies, const Comm& comm) {
    const Index n = static_cast<Index>(p.size());
    Vec<dim> moment;
    for (int d = 0; d < dim; ++d)
        moment[d] = deterministicSum(n, [&](Index i) { return p.mass[i] * p.x[i][d]; });
    comm.sum(moment.data(), dim);
    for (const auto& b : bodies.bodies())
        if (b->motion() == Motion::Free || b->motion() == Motion::Driven)
            moment += b->mass() * b->position();
    return moment;
}

/// The blow-up budget [J]: 10 × what the initial state and the body acceleration can supply
/// (docs/caseFormat.md §11); unbounded (1e300) when prescribed or driven bodies can do unbounded
/// work, or g along a `periodic` axis (its first dim entries; a time-varying g with any
/// periodic axis). `g` is the acceleration at the start; the points are those of every rank.
template <int dim>
double energyBudget(const Particles<dim>& p,
                    const std::vector<std::unique_ptr<Material<dim>>>& materials,
                    const BodySet<dim>& bodies, const BodyAcceleration<dim>& acceleration,
                    const Vec<dim>& g, const Grid<dim>& grid, const std::array<bool, 3>& periodic,
                    const Comm& comm) {
    const Index n = static_cast<Index>(p.size());
    double sums[3] = {
        deterministicSum(n, [&](Index i) { return 0.5 * p.mass[i] * p.v[i].squaredNorm(); }),
        totalStrainEnergy(p, materials), deterministicSum(n, [&](Index i) { return p.mass[i]; })};
    comm.sum(sums, 3);
    const double kinetic = sums[0], strain = sums[1], mass = sums[2];
    double budget = 0;
    if (acceleration.isConstant()) {
        double extent = 0; // Σ |g_d| L_d: the largest drop in potential per unit mass
        for (int d = 0; d < dim; ++d)
            extent += std::fabs(g[d]) * (grid.hi()[d] - grid.lo()[d]);
        budget = 10.0 * (kinetic + strain + mass * extent + bodies.energyBudget(extent));
    } else { // the work a time-varying g can do (BodyAcceleration::energySupply)
        double bodyMass = 0;
        for (const auto& b : bodies.bodies())
            if (b->motion() == Motion::Free || b->motion() == Motion::Driven) bodyMass += b->mass();
        budget =
            10.0 * (kinetic + strain + bodies.energyBudget(0.0) +
                    acceleration.energySupply(mass + bodyMass, (grid.hi() - grid.lo()).norm()));
    }
    // Along a periodic axis g can do unbounded work (a flow down a periodic incline): no budget.
    bool unbounded = bodies.driven();
    for (int d = 0; d < dim; ++d)
        unbounded = unbounded || (periodic[d] && (!acceleration.isConstant() || g[d] != 0.0));
    return budget <= 0 || unbounded ? 1e300 : budget;
}

/// The debug invariant of the stress update: false when L = 0 on every point while the grid
/// velocity `v` it came from is not uniform — a stress-update order lost the phase that
/// computes L (USF did, unnoticed, until the scheme matrix).
template <int dim>
bool gradientSeen(const Particles<dim>& p, const Grid<dim>& grid, const NodeArray<Vec<dim>>& v) {
    for (const auto& L : p.L)
        if (L.squaredNorm() > 0) return true;
    bool first = true, uniform = true;
    Vec<dim> v0 = Vec<dim>::Zero();
    for (Index b : grid.activeBlocks())
        for (Index i = b * Grid<dim>::NodesPerBlock; i < (b + 1) * Grid<dim>::NodesPerBlock; ++i) {
            if (grid.mass[i] <= 0) continue;
            if (first) v0 = v[i], first = false;
            uniform = uniform && v[i] == v0;
        }
    return uniform;
}

} // namespace mpm
