// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/PeriodicLattice.hpp"
#include "contact/CouplingLaw.hpp"
#include "grid/Grid.hpp"
#include "parallel/Comm.hpp"
#include "particles/BlockSort.hpp"
#include "particles/Particles.hpp"
#include "rigid/RigidBody.hpp"

#include <cmath>
#include <memory>
#include <optional>
#include <vector>

namespace mpm {

/// Particle–rigid-body coupling of all bodies (docs/architecture.md, [000 §3], [004 §4]).
///
/// Per step: (1) broad phase — only particles in grid blocks overlapping a body's bounding
/// sphere grown by r_p (plus the law's search band) are tested, every step; (2) narrow phase —
/// the body's signed distance in its own frame [004 §4.2]; (3) the body's law gives the force
/// on each point; the body receives −f at the law's contact point p (x_p; `sdem`: the middle of
/// the overlap) and the torque (p − x_b) × (−f) [004 Eq. 41–42], [001 Eq. 49–50]. Forces of
/// dense points go to the grid in P2G
/// [000 Eq. 19–20]; a gasified point (ρ_p < ρ_c) keeps its force locally (its velocity changes
/// by Δt f/m_p after G2P) and transfers nothing to the grid. After the bodies move, points of
/// non-penetrating (barrier) bodies closer than ξ_min are projected back to ξ_min and lose
/// their approaching normal velocity, so no point ever ends a step inside such a body.
///
/// Periodic faces: a body meets each point through the body's image nearest the point, i.e. at
/// the point's image x' = PeriodicLattice::imageNear(x, x_b): φ(x'), v_b + ω × (x' − x_b), and
/// force and torque with the lever arm x' − x_b. The broad phase searches around each image of
/// the body that is the nearest image of some point of the box (a point near xMax meets a body
/// whose centre is just past xMin). This needs R + r_p < L/2 along each periodic axis (one
/// image can touch a point); a moving body that is larger is an error, a larger fixed body (a
/// terrain spanning the box) is coupled where it lies, without images. Without periodic faces
/// none of this runs.
template <int dim> class Coupling {
public:
    /// `laws[b]` is body b's law (nullptr: not coupled); `lattice` the periodic faces (none:
    /// nullptr, or a lattice with no periodic axis).
    explicit Coupling(std::vector<std::unique_ptr<CouplingLaw<dim>>> laws,
                      const PeriodicLattice<dim>* lattice = nullptr);

    bool empty() const { return laws_.empty(); }

    /// Declare each coupled body's per-point contact slip u_T [004 Eq. 37] in `p`: `contactSlip`
    /// when one body is coupled, `contactSlip_<body>` for each when several are (a point touching
    /// two bodies keeps one history with each).
    void declareState(Particles<dim>& p,
                      const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies);
    /// Keep the `nearBody` flag (declared in `p` if not yet) when a body is coupled: the
    /// particle splitting leaves the flagged points whole.
    void keepNearBodyFlag(Particles<dim>& p);

    /// Record the largest coupling radius of the particles (call after seeding or restart;
    /// V⁰ never changes, removal only lowers it); over all ranks of `comm`.
    void setParticles(const Particles<dim>& p, const Comm& comm = serialComm());

    /// Coupling radius r_p = (V_p⁰)^(1/dim) [000 §3.2] [m].
    static double radius(double v0) { return dim == 3 ? std::cbrt(v0) : std::sqrt(v0); }

    /// Find contacts and their forces, and add −f and torques to the bodies (after their
    /// clearForces()). `wave[m]` is per material; `gasified` the points' trans-phase
    /// state (PhaseDensity.hpp: 1 for a gasified point), null without trans-phase.
    void computeForces(Particles<dim>& p,
                       const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies,
                       const std::vector<double>& wave, const std::vector<int>* gasified,
                       const BlockSort<dim>& sort, const Grid<dim>& grid, double dt);

    /// Points (dense) and their coupling forces to scatter into the grid this step.
    const std::vector<Index>& gridPoints() const { return gridPoints_; }
    const std::vector<Vec<dim>>& gridForces() const { return gridForces_; }

    /// Apply the forces of gasified points to their own velocity (after G2P) [000 Eq. 19].
    /// Positions move with the grid velocity [000 Eq. 16], which does not see this force, so a
    /// gasified point resting on a body stores the kicks of many steps in its FLIP velocity,
    /// up to η/(1 − η) Δt f/m_p, without moving (docs/granularImpact.md, limitations).
    void applyLocalForces(Particles<dim>& p, double dt) const;

    /// Project points closer than ξ_min to a non-penetrating body back out (after the bodies
    /// advanced). Returns the number of points moved. It reuses this step's broad phase and
    /// distances from computeForces (same sort): a point whose distance then, less
    /// `maxDisplacement` (the largest point displacement of the step, |v|max Δt) and the body's
    /// own displacement (|v_b| + |ω| R) Δt, still exceeds ξ_min cannot be inside and is skipped;
    /// only the others are evaluated again.
    Index enforceGap(Particles<dim>& p, std::vector<std::unique_ptr<RigidBody<dim>>>& bodies,
                     double maxDisplacement, double dt) const;

    /// Smallest gap ξ of any point near a coupled body after the last enforceGap [m] (a lower
    /// bound: points skipped there count with their bound); +inf when no point is near a body.
    double minimumGapSeen() const { return minGap_; }
    /// Smallest gap ξ of any point near a coupled body in the last enforceGap, before it projected
    /// points out [m] (same lower bound for skipped points; +inf when no point is near a body):
    /// what the force law alone achieved. Negative: a point ended the step inside a body. With
    /// a non-penetrating law it is the barrier's result, minimumGapSeen() that of the safety net;
    /// without projection (linear spring) both are equal.
    double minimumGapBeforeProjection() const { return minGapBefore_; }

    /// The contact limit on Δt over all laws for the lightest point [000 Eq. 24].
    double stableDeltaT(double lightestMass, double maxWave) const;

    /// Number of points in contact in the last step.
    Index numContacts() const { return numContacts_; }

private:
    /// Visit the particles that may be within `reach` of the body's surface, right after the
    /// sort: those of the blocks that overlap its bounding ball grown by `reach`, less the
    /// blocks, and then the half-blocks (2 cells a side), whose centre is farther from the
    /// surface than their half-diagonal + h + reach (φ is a distance: no point there can be
    /// within reach; h is a margin for a sampled field). The narrow phase then costs per point
    /// near the surface, not per point inside the bounding ball (a terrain's ball holds them all).
    /// `shift`: search around the body's periodic image x_b + shift (zero: the body itself).
    template <class Fn>
    void forParticlesNear(const RigidBody<dim>& body, const Vec<dim>& shift,
                          const Particles<dim>& p, double reach, const BlockSort<dim>& sort,
                          const Grid<dim>& grid, Fn&& fn) const;

    /// The points the broad phase keeps for `body` (near_, in block order; with `images`, image
    /// by image) with their signed distance phi_ and normal normals_, evaluated in parallel.
    void nearPoints(const RigidBody<dim>& body, const PeriodicLattice<dim>* images,
                    const Particles<dim>& p, double reach, const BlockSort<dim>& sort,
                    const Grid<dim>& grid);

    /// How far from a body's surface `law` must find points: its largest coupling radius plus
    /// its search band [m] (the barrier and linear spring: r_p,max).
    double searchReach(const CouplingLaw<dim>& law) const {
        return law.contactRadius(maxRadius_) + law.searchBand();
    }

    /// The lattice whose images `body` meets points through, or nullptr (no periodic face, or a
    /// fixed body too large for one image); throws RunError for a moving body with
    /// 2 (R + reach) ≥ L along a periodic axis (`reach`: searchReach of its law).
    const PeriodicLattice<dim>* imagesFor(const RigidBody<dim>& body, double reach) const;
    /// The image of point x nearest the body's centre (x itself when `images` is null).
    static Vec<dim> imageOf(const PeriodicLattice<dim>* images, const Vec<dim>& x,
                            const RigidBody<dim>& body) {
        return images ? images->imageNear(x, body.position()) : x;
    }

    std::vector<std::unique_ptr<CouplingLaw<dim>>> laws_;
    const PeriodicLattice<dim>* lattice_; ///< null without periodic faces
    /// Handle of the `nearBody` flag (points within nearBodyCells cells of a body, for the
    /// trans-phase relation and the splitting: transfers/PhaseDensity.hpp), if kept.
    std::optional<std::size_t> nearBody_;
    std::vector<std::size_t> slip_; ///< per body: handle of its slip field in the particles
    std::vector<Index> near_;
    std::vector<double> phi_;
    std::vector<Vec<dim>> normals_;
    mutable std::vector<Vec<dim>> impulses_; ///< enforceGap's impulses, applied in point order
    /// Per body: this step's broad-phase points and their distances at x^n (for enforceGap).
    std::vector<std::vector<Index>> nearOf_;
    std::vector<std::vector<double>> phiOf_;
    std::vector<Contact<dim>> contacts_;
    std::vector<Vec<dim>> forces_;
    std::vector<double> kept_; ///< the contacts' slip while the others are reset
    std::vector<Index> gridPoints_, localPoints_;
    std::vector<Vec<dim>> gridForces_, localForces_;
    mutable double minGap_ = 1e300;
    mutable double minGapBefore_ = 1e300;
    double maxRadius_ = 0;
    Index numContacts_ = 0;
};

} // namespace mpm
