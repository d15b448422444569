// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"
#include "levelset/TriangleMesh.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace mpm::levelset {

/// Values at the nodes of a regular grid: node (i, j, k) sits at origin + spacing·(i, j, k) and
/// is stored at i + nx (j + ny k) (x fastest, as in vtkImageData).
struct RegularGrid {
    Vec3 origin = Vec3::Zero();
    double spacing = 1.0;
    std::array<int, 3> dims{0, 0, 0};
    std::vector<double> values;

    std::size_t numPoints() const {
        return static_cast<std::size_t>(dims[0]) * static_cast<std::size_t>(dims[1]) *
               static_cast<std::size_t>(dims[2]);
    }
    std::size_t index(int i, int j, int k) const {
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(dims[0]) *
                   (static_cast<std::size_t>(j) +
                    static_cast<std::size_t>(dims[1]) * static_cast<std::size_t>(k));
    }
    Vec3 point(int i, int j, int k) const { return origin + spacing * Vec3(i, j, k); }
};

/// Signed distance to a triangle mesh: φ(x) = ±min over triangles of |x − closest point|,
/// negative inside.
///
/// Distance: a bounding-volume hierarchy of axis-aligned boxes (median split along the longest
/// axis of the triangle centroids) with the exact closest point on a triangle (C. Ericson,
/// Real-Time Collision Detection, 2005, §5.1.5).
///
/// Sign: the generalized winding number w(x) = Σ Ω_t(x) / 4π (A. Jacobson et al., SIGGRAPH 2013),
/// inside if |w| > ½, which tolerates small holes and flipped triangles. The solid angle of a
/// triangle (a, b, c relative to x) is Van Oosterom & Strackee (IEEE TBME 30, 1983):
///   tan(Ω/2) = a·(b×c) / (|a||b||c| + (a·b)|c| + (b·c)|a| + (c·a)|b|).
/// Far clusters are replaced by their dipole, Ω ≈ N·(p − x)/|p − x|³ with N the sum of area
/// vectors and p the area-weighted centroid, when |p − x| > β r (r: cluster radius) — G. Barill
/// et al., "Fast winding numbers for soups and clouds", SIGGRAPH 2018, first order.
class SignedDistance {
public:
    /// `beta`: the far-field criterion of the winding number (larger: more exact, slower).
    explicit SignedDistance(const TriangleMesh& mesh, double beta = 2.0);

    /// Squared distance to the nearest triangle, searching only below `bound²` (if the
    /// surface is farther, returns bound² or more).
    double squaredDistance(const Vec3& x,
                           double boundSq = std::numeric_limits<double>::infinity()) const;
    double unsignedDistance(const Vec3& x) const { return std::sqrt(squaredDistance(x)); }
    /// Generalized winding number (hierarchical); exact if `beta` is infinite.
    double windingNumber(const Vec3& x) const;
    /// Exact winding number: the sum over all triangles (for tests).
    double windingNumberExact(const Vec3& x) const;
    double signedDistance(const Vec3& x) const;

    /// Fill `grid.values` (sized by grid.dims) with φ (OpenMP; the result is bit-identical for
    /// any thread count).
    /// (1) Narrow band: each triangle rasterises its bounding box grown by bandWidth·h and
    ///     computes the exact distance there; nodes with d ≤ bandWidth·h are exact (they equal
    ///     the brute-force minimum bit for bit).
    /// (2) Elsewhere the index of the nearest triangle is propagated from the neighbours along
    ///     x, y and z (both directions, propagationCycles times) and the exact distance to it
    ///     recomputed (vector propagation as in Bridson's SDFGen): an upper bound of d, very
    ///     close to it.
    ///     Then every node outside the band descends over the mesh to a nearer triangle
    ///     (across an edge, else sharing a vertex) while there is one: a local correction that
    ///     makes the propagated distance exact almost everywhere (it stays an upper bound).
    /// (3) Sign: along a row the sign is carried from the previous node when the distance balls
    ///     cover the segment (d_i + d_{i+1} > h), else taken from the winding number, so the
    ///     winding number is evaluated only near the surface (robust to holes and flips).
    void evaluate(RegularGrid& grid) const;
    /// The previous method: exact distance (BVH) at every node, sign as in evaluate(); slow.
    void evaluateExact(RegularGrid& grid) const;

    /// Narrow band half-width of evaluate(), in grid spacings.
    static constexpr double bandWidth = 3.0;
    /// Cycles of the six propagation passes of evaluate().
    static constexpr int propagationCycles = 2;

    std::size_t numTriangles() const { return a_.size(); }

private:
    struct Node {
        Vec3 lo, hi;       ///< bounds of the triangles
        Vec3 dipoleCentre; ///< area-weighted centroid
        Vec3 areaVector;   ///< Σ ½ (b − a) × (c − a)
        double radiusSq;   ///< squared radius of the ball around dipoleCentre holding the node
        int first, count;  ///< leaf: triangles [first, first+count); inner: count = 0
        int left, right;   ///< children (inner nodes)
    };
    int build(int first, int count, std::vector<int>& order, const std::vector<Vec3>& centres);
    static double boxDistanceSq(const Node& n, const Vec3& x);

    std::vector<Vec3> a_, b_, c_;             ///< triangle corners, in BVH order
    std::vector<std::array<int, 3>> corners_; ///< their vertex indices (for adjacency)
    int numVertices_ = 0;
    std::vector<Node> nodes_;
    double betaSq_;
};

} // namespace mpm::levelset
