// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "boundary/PeriodicLattice.hpp"
#include "case/Dictionary.hpp"
#include "case/Registry.hpp"
#include "rigid/RigidBody.hpp"

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace mpm {

/// Tangential spring displacement of every touching contact [m] — the history a frictional
/// contact keeps between steps and across a restart. Key: linearSpring (prober body, target
/// body, probe, 0); sdem (vertex body, edge body, vertex, edge).
template <int dim> using ContactHistory = std::map<std::array<int, 4>, Vec<dim>>;

/// Contact between rigid bodies (constant/bodyContact, `type:`): the body–body phase of the step,
/// which seed 001's spheropolygon DEM fills with its own geometry.
///
/// Narrow phase through the shapes' contact probes (Shape::contactProbes): of a pair, the body
/// with fewer probes probes the other's signed distance φ. A probe (x, r) touches when
/// δ = r − φ(x) > 0; the normal n = ∇φ points out of the target, the contact point is
/// c = x − (r − δ/2) n. A ball probes with its centre and radius, so contact with a ball is
/// exact. Pairs are found by bounding spheres (O(N²): the DEM issue brings neighbour lists).
/// With periodic faces (setPeriodic) a pair meets through its minimum image: the prober's
/// image nearest the target (PeriodicLattice::separation of the centres), if R_a + R_b < L/2
/// along every periodic axis (otherwise, e.g. with a terrain spanning the box, where they lie).
template <int dim> class BodyContactLaw {
public:
    using BodyList = std::vector<std::unique_ptr<RigidBody<dim>>>;

    virtual ~BodyContactLaw() = default;

    /// Add the contact forces and torques of every touching pair to the bodies over a step dt,
    /// advancing `history` (entries of probes that separated are dropped).
    virtual void addForces(BodyList& bodies, ContactHistory<dim>& history, double dt) = 0;
    /// The stable step of this law for these bodies [s].
    virtual double stableDeltaT(const BodyList& bodies) const = 0;

    /// Pairs meet through their minimum image across the periodic faces of `lattice` (kept by
    /// reference; no effect without a periodic axis).
    void setPeriodic(const PeriodicLattice<dim>& lattice) {
        periodic_ = lattice.any() ? &lattice : nullptr;
    }

    /// Build the law named by `type:` (linearSpring, sdem).
    static std::unique_ptr<BodyContactLaw> create(const Dictionary& dict);

protected:
    const PeriodicLattice<dim>* periodic_ = nullptr; ///< null without periodic faces
};

template <int dim> using BodyContactRegistry = Registry<BodyContactLaw<dim>>;

/// One probe–target contact of a step (world frame).
template <int dim> struct ProbeContact {
    int prober, target, probe;
    double overlap;       ///< δ > 0 [m]
    Vec<dim> normal;      ///< out of the target
    Vec<dim> point;       ///< c (at the target)
    Vec<dim> proberPoint; ///< c on the prober's side of a periodic seam (c itself without one)
};

/// The contact probes (Shape::contactProbes) of each body, in its body frame: fixed for a rigid
/// shape, so computed once (a level set's surface is not extracted every sub-step).
template <int dim> struct ContactProbes {
    std::vector<std::vector<Vec<dim>>> points;
    std::vector<std::vector<double>> radii;
    /// Fill for `bodies` unless already filled for that many.
    void update(const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies);
};

/// The pairs i < j (ascending) of `bodies` whose bounding spheres, inflated by `margin`, may
/// overlap, fixed–fixed pairs left out: a superset of the pairs with
/// |x_i − x_j| < R_i + R_j + margin, in O(N log N), not O(N²). The bodies are binned in cells
/// of 2 R + margin (R: the largest bounding radius of the bodies no larger than 4 × the median);
/// a body meets those of its own and the 3^dim neighbouring cells, and the few larger ones (a
/// floor, a silo wall) meet every body. Without a grid (periodic faces, or two bodies at most)
/// every pair is listed. The caller tests each pair's distance.
template <int dim>
std::vector<std::array<int, 2>>
candidatePairs(const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies, double margin,
               bool periodic);

/// Every touching probe of every pair i < j of `bodies` (fixed pairs skipped), in a fixed order;
/// with `periodic`, through the minimum image of each pair (BodyContactLaw).
template <int dim>
void findProbeContacts(const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies,
                       const ContactProbes<dim>& probes, std::vector<ProbeContact<dim>>& contacts,
                       const PeriodicLattice<dim>* periodic = nullptr);

} // namespace mpm
