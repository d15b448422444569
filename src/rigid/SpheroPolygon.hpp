// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"

#include <cmath>
#include <vector>

namespace mpm {

/// A spheropolygon [001 Eq. 37]: the Minkowski sum of a convex polygon with vertices V_k
/// (counter-clockwise, body frame) and a disk of radius a. One vertex is a disk of radius a,
/// two a capsule (rounded rod). What the SDEM body–body law needs of a 2D shape
/// (Shape<2>::spheroPolygon()).
struct SpheroPolygon {
    std::vector<Vec<2>> vertices; ///< V_k in the body frame [m]
    double radius = 0.0;          ///< sphero-radius a [m]

    /// Edges for vertex–edge contact [001 Eq. 38]: n for a polygon (n ≥ 3), one segment for a
    /// capsule, one degenerate edge (the single vertex) for a disk.
    int edgeCount() const {
        const int n = static_cast<int>(vertices.size());
        return n >= 3 ? n : 1;
    }
    /// End points of edge k: V_k and V_{k+1 mod n} (the same point for a disk).
    int edgeEnd(int k) const { return (k + 1) % static_cast<int>(vertices.size()); }
};

/// Closest point Y of segment [p, q] to x (p = q: the point) and its distance |x − Y| [m].
inline double closestOnSegment(const Vec<2>& x, const Vec<2>& p, const Vec<2>& q, Vec<2>& y) {
    const Vec<2> e = q - p;
    const double ee = e.squaredNorm();
    double s = ee > 0.0 ? (x - p).dot(e) / ee : 0.0;
    s = std::min(1.0, std::max(0.0, s));
    y = p + s * e;
    return (x - y).norm();
}

} // namespace mpm
