// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/SphereShape.hpp"

#include "core/Constants.hpp"

#include <cmath>
#include <string>

namespace mpm {

namespace {
constexpr int nLongitude = 24; ///< segments around the z axis (3D) / the circle has 64
constexpr int nLatitude = 12;  ///< bands from pole to pole
constexpr int nCircle = 64;
} // namespace

template <int dim> SphereShape<dim>::SphereShape(const Dictionary& dict) {
    radius_ = dict.getScalar("radius", Bounds::positive());
    dict.checkUnknownKeys();
    sp_.radius = radius_;
}

template <int dim> SphereShape<dim>::SphereShape(double radius) : radius_(radius) {
    sp_.radius = radius_;
}

template <int dim> double SphereShape<dim>::distance(const Vec<dim>& x, Vec<dim>& normal) const {
    const double r = x.norm();
    if (r > 0.0) {
        normal = x / r;
    } else {
        normal = Vec<dim>::UnitX(); // the centre: every direction is nearest
    }
    return r - radius_;
}

template <int dim> double SphereShape<dim>::volume() const {
    const double r = radius_;
    return dim == 2 ? pi * r * r : 4.0 / 3.0 * pi * r * r * r;
}

/// 3D: I = 2/5 (4/3 π r³) r² = 8/15 π r⁵ per unit density about every axis.
/// 2D: polar moment ∫ |x|² dA = π r⁴/2 (component 2); in-plane axes π r⁴/4 (components 0, 1).
template <int dim> Vec3 SphereShape<dim>::unitInertia() const {
    const double r2 = radius_ * radius_;
    if constexpr (dim == 3) {
        return Vec3::Constant(8.0 / 15.0 * pi * r2 * r2 * radius_);
    } else {
        return Vec3(pi * r2 * r2 / 4.0, pi * r2 * r2 / 4.0, pi * r2 * r2 / 2.0);
    }
}

template <int dim>
void SphereShape<dim>::surface(std::vector<Vec3>& points,
                               std::vector<std::vector<int>>& cells) const {
    points.clear();
    cells.clear();
    const double r = radius_;
    if constexpr (dim == 2) {
        for (int i = 0; i < nCircle; ++i) {
            const double a = 2.0 * pi * i / nCircle;
            points.emplace_back(r * std::cos(a), r * std::sin(a), 0.0);
            cells.push_back({i, (i + 1) % nCircle});
        }
    } else {
        // Point 0: north pole; rings 1 .. nLatitude-1 of nLongitude points; last: south pole.
        points.emplace_back(0.0, 0.0, r);
        for (int j = 1; j < nLatitude; ++j) {
            const double polar = pi * j / nLatitude;
            for (int i = 0; i < nLongitude; ++i) {
                const double az = 2.0 * pi * i / nLongitude;
                points.emplace_back(r * std::sin(polar) * std::cos(az),
                                    r * std::sin(polar) * std::sin(az), r * std::cos(polar));
            }
        }
        points.emplace_back(0.0, 0.0, -r);
        const int south = static_cast<int>(points.size()) - 1;
        const auto ring = [](int j, int i) { return 1 + (j - 1) * nLongitude + i % nLongitude; };
        // Counter-clockwise seen from outside (outward normals).
        for (int i = 0; i < nLongitude; ++i)
            cells.push_back({0, ring(1, i), ring(1, i + 1)});
        for (int j = 1; j < nLatitude - 1; ++j) {
            for (int i = 0; i < nLongitude; ++i) {
                cells.push_back({ring(j, i), ring(j + 1, i), ring(j + 1, i + 1)});
                cells.push_back({ring(j, i), ring(j + 1, i + 1), ring(j, i + 1)});
            }
        }
        for (int i = 0; i < nLongitude; ++i) {
            cells.push_back({south, ring(nLatitude - 1, i + 1), ring(nLatitude - 1, i)});
        }
    }
}

template class SphereShape<2>;
template class SphereShape<3>;

MPM_REGISTER_ONLY(2, ShapeRegistry, SphereShape<2>, "disk");
MPM_REGISTER_ONLY(3, ShapeRegistry, SphereShape<3>, "sphere");
MPM_SCHEMA("shapes", "sphere",
           {"a sphere",
            {{"radius", "scalar", "m", "required", "radius (> 0)"}},
            "{type: sphere, radius: 0.019}",
            "use 'disk' in 2D"});
MPM_SCHEMA("shapes", "disk",
           {"a disk",
            {{"radius", "scalar", "m", "required", "radius (> 0)"}},
            "{type: disk, radius: 0.019}",
            "use 'sphere' in 3D"});

} // namespace mpm
