// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/BoxShape.hpp"

#include <cmath>
#include <vector>

namespace mpm {

template <int dim> BoxShape<dim>::BoxShape(const Dictionary& dict) {
    const bool hasHalf = dict.has("halfExtents");
    const bool hasSize = dict.has("size");
    if (hasHalf == hasSize) {
        dict.error(hasHalf ? "size" : "halfExtents",
                   "give exactly one of halfExtents (half edge lengths) or size (full edge "
                   "lengths)");
    }
    const std::string key = hasHalf ? "halfExtents" : "size";
    const std::vector<double> v = dict.getVector(key, dim);
    for (int d = 0; d < dim; ++d) {
        if (!(v[d] > 0.0)) dict.error(key, "every component must be > 0");
        h_[d] = hasHalf ? v[d] : 0.5 * v[d];
    }
    dict.checkUnknownKeys();
    setCorners();
}

template <int dim> BoxShape<dim>::BoxShape(const Vec<dim>& halfExtents) : h_(halfExtents) {
    setCorners();
}

template <int dim> void BoxShape<dim>::setCorners() {
    if constexpr (dim == 2) {
        const double a = h_[0];
        const double b = h_[1];
        sp_.vertices = {Vec<2>(-a, -b), Vec<2>(a, -b), Vec<2>(a, b), Vec<2>(-a, b)};
    }
}

template <int dim> double BoxShape<dim>::distance(const Vec<dim>& x, Vec<dim>& normal) const {
    const Vec<dim> q = x.cwiseAbs() - h_;
    const Vec<dim> outside = q.cwiseMax(0.0);
    const double outsideNorm = outside.norm();
    if (outsideNorm > 0.0) {
        // Nearest point is on a face, edge or corner: n = ∇φ = sign(x) max(q, 0) / |max(q, 0)|.
        for (int d = 0; d < dim; ++d) {
            normal[d] = (x[d] < 0.0 ? -outside[d] : outside[d]) / outsideNorm;
        }
        return outsideNorm;
    }
    // Inside or on the surface: the nearest face is the one with the largest q_d.
    int k = 0;
    for (int d = 1; d < dim; ++d) {
        if (q[d] > q[k]) k = d;
    }
    normal.setZero();
    normal[k] = x[k] < 0.0 ? -1.0 : 1.0;
    return q[k];
}

template <int dim> double BoxShape<dim>::volume() const {
    return (2.0 * h_).prod();
}

template <int dim> Vec3 BoxShape<dim>::unitInertia() const {
    const double v = volume();
    if constexpr (dim == 3) {
        const Vec3 s = h_.cwiseProduct(h_);
        return v / 3.0 * Vec3(s[1] + s[2], s[2] + s[0], s[0] + s[1]);
    } else {
        const double sx = h_[0] * h_[0];
        const double sy = h_[1] * h_[1];
        return v / 3.0 * Vec3(sy, sx, sx + sy);
    }
}

template <int dim>
void BoxShape<dim>::surface(std::vector<Vec3>& points, std::vector<std::vector<int>>& cells) const {
    points.clear();
    cells.clear();
    if constexpr (dim == 2) {
        const double a = h_[0];
        const double b = h_[1];
        points = {Vec3(-a, -b, 0.0), Vec3(a, -b, 0.0), Vec3(a, b, 0.0), Vec3(-a, b, 0.0)};
        cells = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
    } else {
        // Corner i has coordinate sign (−1)^(bit d of i + 1) along axis d.
        for (int i = 0; i < 8; ++i) {
            points.emplace_back((i & 1) ? h_[0] : -h_[0], (i & 2) ? h_[1] : -h_[1],
                                (i & 4) ? h_[2] : -h_[2]);
        }
        // Two triangles per face, counter-clockwise seen from outside.
        cells = {{0, 2, 3}, {0, 3, 1},  // z = −h
                 {4, 5, 7}, {4, 7, 6},  // z = +h
                 {0, 1, 5}, {0, 5, 4},  // y = −h
                 {2, 6, 7}, {2, 7, 3},  // y = +h
                 {0, 4, 6}, {0, 6, 2},  // x = −h
                 {1, 3, 7}, {1, 7, 5}}; // x = +h
    }
}

template class BoxShape<2>;
template class BoxShape<3>;

MPM_REGISTER_DIMS(ShapeRegistry, BoxShape, "box");
MPM_SCHEMA("shapes", "box",
           {"a box (a rectangle in 2D)",
            {{"halfExtents", "vector", "m", "none",
              "half edge lengths h > 0 (give halfExtents or size)"},
             {"size", "vector", "m", "none", "edge lengths 2h > 0"}},
            "{type: box, size: [0.1, 0.05]}"});

} // namespace mpm
