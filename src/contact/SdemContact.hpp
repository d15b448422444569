// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "contact/BodyContact.hpp"
#include "contact/ContactForce.hpp"

#include <array>
#include <set>
#include <string>
#include <vector>

namespace mpm {

/// Spheropolygon DEM body–body contact `type: sdem` (2D) [001 §3.2, Eq. 38–43, §4.2, Eq. 51].
///
/// Every body is a spheropolygon (Shape<2>::spheroPolygon(): `spheropolygon`, `box` with a = 0,
/// `disk` with one vertex and a = R). For bodies i, j, every vertex V of i against every edge E of
/// j (a capsule has one edge, a disk one degenerate edge: its vertex) and vice versa, literally
/// (a vertex–vertex touch counts on both adjacent edges, as the paper's sums do):
///   ξ = a_i + a_j − d(V, E) > 0 [Eq. 38], n = (V − Y)/|V − Y| (Y: closest point of E),
///   p = V − (a_i − ξ/2) n [Eq. 41] (mid-overlap),
///   F = f_n n + F_t, f_n = max(k_n ξ − c v_n, 0), F_t = −k_t δ_t with |F_t| ≤ μ f_n [Eq. 43]:
/// δ_t is projected onto the current tangent line and advanced by (v_rel·t) t Δt,
/// v_rel = v_i(p) − v_j(p) (rigid velocities including ω × r); beyond the cap δ_t is scaled back
/// to it (sliding). +F acts on the vertex's body and −F on the edge's body, both at p (torques
/// about each centroid). History per (vertex body, edge body, vertex, edge), dropped when ξ = 0.
/// Two bodies with a = 0 (e.g. two boxes) never touch under this law: a warning says so.
/// A vertex farther than ρ_j + a_i + a_j from body j's centroid (ρ_j: the largest distance of
/// j's vertices from it) touches no edge of j and is not tested against them (same result).
///
/// Optional normal dashpot from a restitution e ∈ [0.14, 1]: c = 2 ζ √(m* k_n), m* = m_i m_j/(m_i +
/// m_j) (a fixed body's mass infinite), ζ the damping ratio with which one vertex–edge contact of a
/// head-on collision leaves at e times its impact speed (RestitutionDashpot, as linearSpring:
/// the cut dashpot's exact restitution, not the textbook −ln e/√(π² + ln² e), with which a pair
/// bounced higher than asked, e.g. 0.32 for 0.2); none by default, as the paper. The dashpot acts
/// per vertex–edge contact: a touch the literal sums count N times (a disk on a disk twice, the
/// corner of a square on a square's face four times) has N k_n and N c, damping ratio √N ζ, and
/// bounces lower than e.
///
/// Neighbour (Verlet) list [§4.2]: pairs whose bounding circles inflated by V_d overlap, fixed–
/// fixed pairs skipped, found by binning the bodies (candidatePairs: O(N log N)); rebuilt when a
/// body has moved more than V_d/2 since the last build (so no touching pair is missed: the gap
/// closes by < V_d). The list is not restart state: it is rebuilt on the first step, and contacts
/// are summed in pair order, so results do not depend on it. Periodic faces: pairs meet through
/// their minimum image as in findProbeContacts.
///
/// Keys: kn k_n [N/m] (> 0), kt k_t [N/m] (default k_n), friction μ (default 0), restitution e
/// ∈ [0.14, 1] (default 1: no dashpot), verletDistance V_d [m] (default 0.1 R_min, R_min the
/// smallest bounding radius: 5 % of the smallest body's size). In 2D forces and stiffnesses are per
/// metre.
class SdemContact final : public BodyContactLaw<2> {
public:
    using typename BodyContactLaw<2>::BodyList;

    explicit SdemContact(const Dictionary& dict);

    void addForces(BodyList& bodies, ContactHistory<2>& history, double dt) override;
    /// [001 Eq. 51]: κ₂ 2π √(m_min/k_n), κ₂ = 0.1, m_min over the bodies that are not fixed.
    double stableDeltaT(const BodyList& bodies) const override;

    /// The neighbour list for `bodies` now (rebuilt if the rule says so): pairs i < j.
    const std::vector<std::array<int, 2>>& neighbours(const BodyList& bodies);
    /// Pairs i < j whose inflated bounding circles overlap now, by brute force: the reference
    /// neighbours() (binned, candidatePairs) must equal after a build.
    std::vector<std::array<int, 2>> allNear(const BodyList& bodies) const;
    /// Verlet distance V_d in use [m] (0 before the first call with bodies).
    double verletDistance() const { return vd_; }
    /// How many times the list was built.
    int builds() const { return builds_; }
    /// The dashpot coefficient c [N s/m] for reduced mass m* (0 without restitution).
    double dashpot(double reducedMass) const;

private:
    double kn_, kt_, mu_;
    RestitutionDashpot dashpot_;
    double vdGiven_;
    double vd_ = 0;
    std::string file_;
    int line_ = 0;
    std::vector<std::array<int, 2>> pairs_;
    std::vector<Vec<2>> built_; ///< centroids at the last build
    int builds_ = 0;
    std::set<std::array<int, 2>> warned_;
    std::vector<Vec<2>> edgeEnds_; ///< vertexEdge's scratch: the edge body's vertices, world

    /// c_i − c_j through the minimum image where one image alone can touch (else direct).
    Vec<2> separation(const RigidBody<2>& a, const RigidBody<2>& b) const;
    void check(const BodyList& bodies);
    /// Contacts of vertices of body v against edges of body e; `shiftV`: the vertex body's
    /// centroid image minus its centroid (periodic), applied to its vertices.
    void vertexEdge(BodyList& bodies, int v, int e, const Vec<2>& shiftV,
                    const ContactHistory<2>& history, ContactHistory<2>& next, double dt);
};

} // namespace mpm
