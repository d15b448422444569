// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "rigid/Shape.hpp"
#include "rigid/SpheroPolygon.hpp"

namespace mpm {

/// Spheropolygon `type: spheropolygon` (2D only) [001 §3.1, Eq. 37]: a convex polygon ⊕ a disk
/// of radius a. Keys: vertices [[x, y], …] in the case's frame (1: a disk, 2: a capsule, ≥ 3: a
/// convex polygon, counter-clockwise), radius a ≥ 0 [m] (> 0 with fewer than 3 vertices).
///
/// Mass properties are exact, summed over the pieces of the Minkowski sum: the core polygon
/// (shoelace), one rectangle L × a per edge (outward) and one circular sector of radius a per
/// vertex, of angle the exterior angle θ_k (Σθ_k = 2π): A = A_P + a P + π a². The body frame
/// has its origin at that centroid and the case's axes; meshPose() reports the centroid, so a
/// body may omit `position` and sit where its vertices say. φ(x) = ±d(x, P) − a (d: distance to
/// the core polygon, negative inside), n = ∇φ. In-plane inertia components (0, 1) are not used
/// in 2D and hold J/2.
class SpheropolygonShape : public Shape<2> {
public:
    explicit SpheropolygonShape(const Dictionary& dict);
    /// Vertices (counter-clockwise, convex, case frame) and sphero-radius, not checked.
    SpheropolygonShape(const std::vector<Vec<2>>& vertices, double radius);

    double distance(const Vec<2>& x, Vec<2>& normal) const override;
    double volume() const override { return area_; }
    Vec3 unitInertia() const override { return Vec3(0.5 * polar_, 0.5 * polar_, polar_); }
    double boundingRadius() const override { return boundingRadius_; }
    /// The rounded outline: each vertex arc in max(8, ⌈64 θ/2π⌉) segments (a disk: 64), joined
    /// by the straight offset edges; the bare polygon when a = 0.
    void surface(std::vector<Vec3>& points, std::vector<std::vector<int>>& cells) const override;
    bool meshPose(Vec<2>& centroid, Mat<2>& rotation) const override {
        centroid = centroid_;
        rotation.setIdentity();
        return true;
    }
    /// The vertices with radius a: linearSpring contact and the barrier coupling see the
    /// rounded shape as a union of disks along its core.
    void contactProbes(std::vector<Vec<2>>& points, std::vector<double>& radii) const override {
        points = sp_.vertices;
        radii.assign(points.size(), sp_.radius);
    }
    const SpheroPolygon* spheroPolygon() const override { return &sp_; }
    /// Centroid of the Minkowski sum in the case's frame [m].
    const Vec<2>& centroid() const { return centroid_; }

    /// Area, centroid and polar moment per unit density about the centroid of polygon ⊕ disk(a)
    /// for counter-clockwise convex `vertices` (case frame).
    static void massProperties(const std::vector<Vec<2>>& vertices, double a, double& area,
                               Vec<2>& centroid, double& polar);
    /// Signed distance to polygon ⊕ disk(a) and its gradient (body or any frame).
    static double signedDistance(const SpheroPolygon& sp, const Vec<2>& x, Vec<2>& normal);

private:
    SpheroPolygon sp_; ///< body frame
    Vec<2> centroid_ = Vec<2>::Zero();
    double area_ = 0, polar_ = 0, boundingRadius_ = 0;

    void build(const std::vector<Vec<2>>& vertices, double radius);
};

/// Exterior angle θ_k at vertex k of the closed loop of counter-clockwise `vertices` (the turn
/// from the incoming edge's outward normal to the outgoing one's): 2π for one vertex, π for two.
double exteriorAngle(const std::vector<Vec<2>>& vertices, int k);
/// Outward unit normal of edge k (V_k → V_{k+1}) of a counter-clockwise loop: (t_y, −t_x).
Vec<2> edgeNormal(const std::vector<Vec<2>>& vertices, int k);

} // namespace mpm
