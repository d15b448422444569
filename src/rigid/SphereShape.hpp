// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "rigid/Shape.hpp"
#include "rigid/SpheroPolygon.hpp"

namespace mpm {

/// Ball of radius r about the origin: `type: sphere` in 3D, `type: disk` in 2D (the other
/// name is an InputError saying which to use). Keys: radius [m] > 0.
///
/// φ(x) = |x| − r, n = x/|x|; volume 4/3 π r³ (area π r² in 2D); inertia per unit density
/// 2/5 V r² = 8/15 π r⁵ about every axis (2D: polar moment π r⁴/2).
template <int dim> class SphereShape : public Shape<dim> {
public:
    explicit SphereShape(const Dictionary& dict);
    explicit SphereShape(double radius);

    double radius() const { return radius_; }

    double distance(const Vec<dim>& x, Vec<dim>& normal) const override;
    double volume() const override;
    Vec3 unitInertia() const override;
    double boundingRadius() const override { return radius_; }
    /// 3D: UV sphere of 24 longitudes × 12 latitude bands (528 triangles); 2D: circle of 64
    /// segments. Points lie on the exact surface.
    void surface(std::vector<Vec3>& points, std::vector<std::vector<int>>& cells) const override;
    /// The centre with the radius: contact with a ball is exact.
    void contactProbes(std::vector<Vec<dim>>& points, std::vector<double>& radii) const override {
        points.assign(1, Vec<dim>::Zero());
        radii.assign(1, radius_);
    }
    /// 2D: one vertex at the centre with a = r (SDEM contact); 3D: none.
    const SpheroPolygon* spheroPolygon() const override { return dim == 2 ? &sp_ : nullptr; }

private:
    double radius_ = 0.0;
    SpheroPolygon sp_{{Vec<2>::Zero()}, 0.0};
};

} // namespace mpm
