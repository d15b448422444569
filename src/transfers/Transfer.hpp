// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "grid/Grid.hpp"
#include "particles/BlockSort.hpp"
#include "particles/Particles.hpp"

#include <memory>
#include <string>

namespace mpm {

/// What G2P saw: the largest particle speed, the largest speed a particle moved with (the grid
/// velocity, [000 Eq. 16]: its displacement over Δt) and that particle (the first of equals; -1
/// if none moved), the kinetic energy, and the first particle whose velocity is not finite (-1 if
/// none).
struct GatherStats {
    double maxSpeed = 0;
    double maxMoveSpeed = 0;
    Index fastestMoving = -1;
    double kineticEnergy = 0;
    Index firstNonFinite = -1;
};

/// Particle ↔ grid transfers for one kernel and one velocity scheme, chosen once at set-up
/// (system/mpmSchemes `kernel`, `transfer`); each call is one phase over all particles.
template <int dim> class Transfer {
public:
    virtual ~Transfer() = default;

    /// Kernel weights and gradients of every particle at its present position, for all
    /// transfers of the step (p and g must outlive them, and x must not change before the
    /// first of them). Evaluated once, where first needed: the step's first scatter evaluates
    /// each point's stencil in its own pass over the point.
    virtual void computeWeights(const Particles<dim>& p, const Grid<dim>& g) = 0;

    /// P2G of mass and momentum [000 Eq. 13] (APIC adds the affine term m_p C_p (x_i - x_p))
    /// into the grid's active blocks, which must hold every stencil (Grid::activate); the sums
    /// are added to the node fields.
    /// With `withStress` the internal force f_i = -Σ V_p σ_p ∇w_ip is scattered in the same
    /// pass (USL); otherwise it is left for scatterForce (USF).
    virtual void scatter(const Particles<dim>& p, Grid<dim>& g, const BlockSort<dim>& s,
                         bool withStress) = 0;
    /// P2G of the internal force alone (USF's second scatter).
    virtual void scatterForce(const Particles<dim>& p, Grid<dim>& g, const BlockSort<dim>& s) = 0;

    /// Add external point forces f_k at particles ids[k] to the grid force: f_i += Σ w_ip f_p
    /// (the coupling forces [000 Eq. 19–20]); serial, in list order (deterministic).
    virtual void scatterPointForces(const std::vector<Index>& ids, const std::vector<Vec<dim>>& f,
                                    Grid<dim>& g) const = 0;

    /// out_i += Σ_p w_ip q_p for a particle scalar q with this step's weights; `out` (a node
    /// field) must be zero on the active blocks (Grid::activeBlocks) on entry. Race-free and
    /// deterministic (blocks by colour).
    virtual void scatterScalar(const std::vector<double>& q, NodeArray<double>& out,
                               const BlockSort<dim>& s) const = 0;
    /// out_p = Σ_i w_ip q_i for a nodal scalar q with this step's weights.
    virtual void gatherScalar(const NodeArray<double>& q, std::vector<double>& out) const = 0;

    /// L_p = Σ_i v_i ⊗ ∇w_ip from the P2G velocity g.vOld (USF) [002 Eq. 75].
    virtual void velocityGradient(Particles<dim>& p, const Grid<dim>& g) = 0;

    /// G2P: velocity by the FLIP/PIC blend [000 Eq. 15] or APIC [000 Eq. 17], position
    /// [000 Eq. 16], and (with `withGradient`, USL) L_p from the updated velocity. Reads the
    /// grid's velocities through its scratch lines (Grid::lines), which it overwrites.
    virtual GatherStats gather(Particles<dim>& p, Grid<dim>& g, double dt, bool withGradient) = 0;

    /// Bytes of kernel data kept per particle between computeWeights and the last transfer of
    /// the step (the stencil: first node, weights, gradients; APIC adds the offset).
    virtual std::size_t stencilBytes() const = 0;

    /// Build the transfer selected in system/mpmSchemes; `particleHalfWidth` is GIMP's l_p / h.
    static std::unique_ptr<Transfer> create(const Dictionary& schemes, double particleHalfWidth);
};

} // namespace mpm
