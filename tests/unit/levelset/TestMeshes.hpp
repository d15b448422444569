// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "levelset/TriangleMesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <utility>

namespace mpm::levelset::test {

/// Icosphere of radius r: an icosahedron subdivided `levels` times (20·4^levels triangles),
/// vertices projected onto the sphere, counter-clockwise seen from outside.
inline TriangleMesh icosphere(double r, int levels) {
    TriangleMesh m;
    const double t = (1.0 + std::sqrt(5.0)) / 2.0;
    const double v[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                             {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                             {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
    for (const auto& p : v)
        m.vertices.push_back(Vec3(p[0], p[1], p[2]).normalized());
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<int, int>, int> mid;
        auto midpoint = [&](int a, int b) {
            const auto key = std::make_pair(std::min(a, b), std::max(a, b));
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            const Vec3 p =
                (m.vertices[static_cast<std::size_t>(a)] + m.vertices[static_cast<std::size_t>(b)])
                    .normalized();
            m.vertices.push_back(p);
            const int id = static_cast<int>(m.vertices.size()) - 1;
            mid.emplace(key, id);
            return id;
        };
        std::vector<std::array<int, 3>> next;
        next.reserve(4 * m.triangles.size());
        for (const auto& tri : m.triangles) {
            const int a = midpoint(tri[0], tri[1]), b = midpoint(tri[1], tri[2]),
                      c = midpoint(tri[2], tri[0]);
            next.push_back({tri[0], a, c});
            next.push_back({tri[1], b, a});
            next.push_back({tri[2], c, b});
            next.push_back({a, b, c});
        }
        m.triangles.swap(next);
    }
    for (Vec3& p : m.vertices)
        p *= r;
    return m;
}

/// Largest gap between the sphere of radius r and the planes of the icosphere's triangles.
inline double sagitta(const TriangleMesh& m, double r) {
    double s = 0.0;
    for (std::size_t t = 0; t < m.numTriangles(); ++t) {
        const Vec3 n = (m.vertex(t, 1) - m.vertex(t, 0)).cross(m.vertex(t, 2) - m.vertex(t, 0));
        s = std::max(s, r - n.normalized().dot(m.vertex(t, 0)));
    }
    return s;
}

/// Box [−h, h] (half-extents h), 12 triangles wound outward.
inline TriangleMesh box(const Vec3& h) {
    TriangleMesh m;
    for (int i = 0; i < 8; ++i) {
        m.vertices.emplace_back((i & 1) ? h.x() : -h.x(), (i & 2) ? h.y() : -h.y(),
                                (i & 4) ? h.z() : -h.z());
    }
    m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6},  // z−, z+
                   {0, 1, 4}, {1, 5, 4}, {2, 6, 3}, {3, 6, 7},  // y−, y+
                   {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}}; // x−, x+
    return m;
}

/// Exact signed distance to the box [−h, h].
inline double boxSdf(const Vec3& x, const Vec3& h) {
    const Vec3 q = x.cwiseAbs() - h;
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

} // namespace mpm::levelset::test
