// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/SpheropolygonShape.hpp"

#include "core/Constants.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

namespace mpm {

namespace {
constexpr int nCircle = 64; ///< segments of a full circle in the output outline

double cross(const Vec<2>& u, const Vec<2>& v) {
    return u[0] * v[1] - u[1] * v[0];
}

std::string str(int k) {
    return std::to_string(k);
}
} // namespace

Vec<2> edgeNormal(const std::vector<Vec<2>>& vertices, int k) {
    const int n = static_cast<int>(vertices.size());
    const Vec<2> t = (vertices[(k + 1) % n] - vertices[k]).normalized();
    return Vec<2>(t[1], -t[0]);
}

double exteriorAngle(const std::vector<Vec<2>>& vertices, int k) {
    const int n = static_cast<int>(vertices.size());
    if (n == 1) return 2.0 * pi;
    if (n == 2) return pi;
    const Vec<2> in = edgeNormal(vertices, (k + n - 1) % n);
    const Vec<2> out = edgeNormal(vertices, k);
    return std::atan2(cross(in, out), in.dot(out));
}

SpheropolygonShape::SpheropolygonShape(const Dictionary& dict) {
    const std::vector<std::vector<double>> rows = dict.vectorList("vertices", 2);
    const double a = dict.getScalar("radius", Bounds::nonNegative());
    dict.checkUnknownKeys();
    const int n = static_cast<int>(rows.size());
    if (n == 0) dict.error("vertices", "expected at least one vertex [x, y]");
    std::vector<Vec<2>> v;
    for (const auto& r : rows)
        v.emplace_back(r[0], r[1]);
    if (n < 3 && !(a > 0.0))
        dict.error("radius", "a disk (1 vertex) or a capsule (2 vertices) needs radius > 0");
    // Length scale for the degeneracy tolerances.
    double scale = a;
    for (const auto& x : v)
        scale = std::max(scale, (x - v[0]).norm());
    const double tol = 1e-12 * scale;
    for (int k = 0; k < n && n > 1; ++k) {
        if ((v[(k + 1) % n] - v[k]).norm() <= tol)
            dict.error("vertices", "vertices " + str(k) + " and " + str((k + 1) % n) +
                                       " coincide (repeated vertex)");
    }
    if (n >= 3) {
        double area2 = 0.0, turning = 0.0;
        int left = 0, right = 0;
        for (int k = 0; k < n; ++k) {
            const Vec<2>& p = v[(k + n - 1) % n];
            const Vec<2>& q = v[k];
            const Vec<2>& r = v[(k + 1) % n];
            area2 += cross(q, r);
            const double c = cross(q - p, r - q);
            if (std::fabs(c) <= 1e-12 * (q - p).norm() * (r - q).norm())
                dict.error("vertices", "vertex " + str(k) +
                                           " lies on the line through its neighbours (collinear, "
                                           "degenerate: remove it)");
            (c > 0 ? left : right) += 1;
            turning += std::atan2(c, (q - p).dot(r - q));
        }
        if (right == n || (area2 < 0 && left == 0))
            dict.error("vertices", "the vertices run clockwise; list them counter-clockwise");
        if (right > 0 || std::fabs(turning - 2 * pi) > 1e-6)
            dict.error("vertices", "the polygon is not convex (or crosses itself); a "
                                   "spheropolygon needs a convex polygon, counter-clockwise");
    }
    build(v, a);
}

SpheropolygonShape::SpheropolygonShape(const std::vector<Vec<2>>& vertices, double radius) {
    build(vertices, radius);
}

void SpheropolygonShape::massProperties(const std::vector<Vec<2>>& v, double a, double& area,
                                        Vec<2>& centroid, double& polar) {
    const int n = static_cast<int>(v.size());
    // Σ over the pieces: area A, first moment S = ∫x dA and J₀ = ∫|x|² dA about the origin.
    double A = 0.0, J0 = 0.0;
    Vec<2> S = Vec<2>::Zero();
    // Core polygon (shoelace): A = ½Σc_k, S = ⅙Σ(P_k + P_k+1)c_k,
    // J₀ = 1/12 Σ c_k (|P_k|² + P_k·P_k+1 + |P_k+1|²), c_k = P_k × P_k+1.
    if (n >= 3)
        for (int k = 0; k < n; ++k) {
            const Vec<2>& p = v[k];
            const Vec<2>& q = v[(k + 1) % n];
            const double c = cross(p, q);
            A += 0.5 * c;
            S += (p + q) * c / 6.0;
            J0 += c * (p.squaredNorm() + p.dot(q) + q.squaredNorm()) / 12.0;
        }
    // One rectangle L × a per edge of the closed loop (a capsule: both sides of its segment),
    // centroid at the edge midpoint + a/2 m; own polar moment A (L² + a²)/12.
    if (n >= 2)
        for (int k = 0; k < n; ++k) {
            const Vec<2>& p = v[k];
            const Vec<2>& q = v[(k + 1) % n];
            const double L = (q - p).norm();
            const double ar = L * a;
            const Vec<2> c = 0.5 * (p + q) + 0.5 * a * edgeNormal(v, k);
            A += ar;
            S += ar * c;
            J0 += ar * (L * L + a * a) / 12.0 + ar * c.squaredNorm();
        }
    // One sector of radius a and angle θ per vertex, from the incoming edge's normal: area θa²/2,
    // centroid 4a sin(θ/2)/(3θ) along the bisector, polar moment θa⁴/4 about the vertex.
    for (int k = 0; k < n; ++k) {
        const double th = exteriorAngle(v, k);
        const double as = 0.5 * th * a * a;
        Vec<2> off = Vec<2>::Zero();
        if (n > 1) {
            const Vec<2> in = edgeNormal(v, (k + n - 1) % n);
            const double h = 0.5 * th;
            const Vec<2> bisector(std::cos(h) * in[0] - std::sin(h) * in[1],
                                  std::sin(h) * in[0] + std::cos(h) * in[1]);
            off = 4.0 * a * std::sin(h) / (3.0 * th) * bisector;
        }
        A += as;
        S += as * (v[k] + off);
        J0 += 0.25 * th * a * a * a * a + as * (v[k].squaredNorm() + 2.0 * v[k].dot(off));
    }
    area = A;
    centroid = S / A;
    polar = J0 - A * centroid.squaredNorm();
}

void SpheropolygonShape::build(const std::vector<Vec<2>>& vertices, double radius) {
    massProperties(vertices, radius, area_, centroid_, polar_);
    sp_.radius = radius;
    sp_.vertices.clear();
    boundingRadius_ = 0.0;
    for (const Vec<2>& x : vertices) {
        sp_.vertices.push_back(x - centroid_);
        boundingRadius_ = std::max(boundingRadius_, sp_.vertices.back().norm() + radius);
    }
}

double SpheropolygonShape::signedDistance(const SpheroPolygon& sp, const Vec<2>& x,
                                          Vec<2>& normal) {
    const std::vector<Vec<2>>& v = sp.vertices;
    const int n = static_cast<int>(v.size());
    double d = 1e300;
    Vec<2> y = v[0];
    int nearest = 0;
    bool inside = n >= 3;
    for (int k = 0; k < sp.edgeCount(); ++k) {
        Vec<2> yk;
        const Vec<2>& p = v[k];
        const Vec<2>& q = v[sp.edgeEnd(k)];
        const double dk = closestOnSegment(x, p, q, yk);
        if (dk < d) {
            d = dk;
            y = yk;
            nearest = k;
        }
        if (n >= 3 && cross(q - p, x - p) < 0) inside = false;
    }
    if (inside) {
        // −d is smallest along the nearest edge's outward normal.
        normal = edgeNormal(v, nearest);
        return -d - sp.radius;
    }
    if (d > 0) {
        normal = (x - y) / d;
    } else if (n >= 2) {
        normal = edgeNormal(v, nearest); // on the core's boundary
    } else {
        normal = Vec<2>::UnitX(); // the centre of a disk: every direction is nearest
    }
    return d - sp.radius;
}

double SpheropolygonShape::distance(const Vec<2>& x, Vec<2>& normal) const {
    return signedDistance(sp_, x, normal);
}

void SpheropolygonShape::surface(std::vector<Vec3>& points,
                                 std::vector<std::vector<int>>& cells) const {
    points.clear();
    cells.clear();
    const std::vector<Vec<2>>& v = sp_.vertices;
    const int n = static_cast<int>(v.size());
    const double a = sp_.radius;
    for (int k = 0; k < n; ++k) {
        if (!(a > 0.0)) {
            points.emplace_back(v[k][0], v[k][1], 0.0);
            continue;
        }
        if (n == 1) {
            for (int j = 0; j < nCircle; ++j) {
                const double t = 2.0 * pi * j / nCircle;
                points.emplace_back(v[0][0] + a * std::cos(t), v[0][1] + a * std::sin(t), 0.0);
            }
            break;
        }
        const double th = exteriorAngle(v, k);
        const Vec<2> in = edgeNormal(v, (k + n - 1) % n);
        const double t0 = std::atan2(in[1], in[0]);
        const int m = std::max(8, static_cast<int>(std::ceil(nCircle * th / (2.0 * pi))));
        for (int j = 0; j <= m; ++j) {
            const double t = t0 + th * j / m;
            points.emplace_back(v[k][0] + a * std::cos(t), v[k][1] + a * std::sin(t), 0.0);
        }
    }
    const int np = static_cast<int>(points.size());
    for (int i = 0; i < np; ++i)
        cells.push_back({i, (i + 1) % np});
}

MPM_REGISTER_ONLY(2, ShapeRegistry, SpheropolygonShape, "spheropolygon");
MPM_SCHEMA("shapes", "spheropolygon",
           {"a convex polygon rounded by a disk [001 Eq. 37]",
            {{"vertices", "list of [x, y]", "m", "required",
              "1: disk, 2: capsule, ≥ 3: convex polygon, counter-clockwise"},
             {"radius", "scalar", "m", "required",
              "sphero-radius a ≥ 0 (> 0 with fewer than 3 vertices)"}},
            "{type: spheropolygon, vertices: [[0, 0], [0.02, 0], [0, 0.02]], radius: 0.001}",
            "it is a polygon ⊕ disk; in 3D use 'box', 'sphere' or 'levelSet'"});

} // namespace mpm
