// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "rigid/Shape.hpp"
#include "rigid/SpheroPolygon.hpp"

namespace mpm {

/// Box |x_d| ≤ h_d centred on the origin (`type: box`). Keys: halfExtents h (dim numbers > 0)
/// or size = 2h (full edge lengths), exactly one of them.
///
/// Exact signed distance with q = |x| − h (componentwise): φ = |max(q, 0)| outside and
/// φ = max_d q_d (minus the distance to the nearest face) inside; the normal is ∇φ outside and
/// the nearest face's normal inside or on the surface. Volume Π 2h_d; inertia per unit density
/// I_x = V (h_y² + h_z²)/3 and cyclic (2D: polar moment V (h_x² + h_y²)/3).
template <int dim> class BoxShape : public Shape<dim> {
public:
    explicit BoxShape(const Dictionary& dict);
    explicit BoxShape(const Vec<dim>& halfExtents);

    const Vec<dim>& halfExtents() const { return h_; }

    double distance(const Vec<dim>& x, Vec<dim>& normal) const override;
    double volume() const override;
    Vec3 unitInertia() const override;
    double boundingRadius() const override { return h_.norm(); }
    /// 3D: 8 corners, 12 triangles with outward normals; 2D: 4 corners, 4 segments.
    void surface(std::vector<Vec3>& points, std::vector<std::vector<int>>& cells) const override;
    /// 2D: the 4 corners counter-clockwise with a = 0 (SDEM contact); 3D: none.
    const SpheroPolygon* spheroPolygon() const override { return dim == 2 ? &sp_ : nullptr; }

private:
    Vec<dim> h_ = Vec<dim>::Zero();
    SpheroPolygon sp_; ///< 2D only

    void setCorners();
};

} // namespace mpm
