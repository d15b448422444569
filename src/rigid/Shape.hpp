// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "case/Registry.hpp"
#include "core/Types.hpp"

#include <array>
#include <memory>
#include <vector>

namespace mpm {

struct SpheroPolygon;

/// Geometry of a rigid body in its own frame: origin at the centroid, axes along the
/// principal axes of inertia ([004 §4.2]). The coupling asks only for the signed
/// distance and normal, so a level-set grid (next issue) is one more Shape.
template <int dim> class Shape {
public:
    virtual ~Shape() = default;

    /// Signed distance φ [m] of body-frame point x (negative inside) and the outward unit
    /// normal n = ∇φ/|∇φ| there.
    virtual double distance(const Vec<dim>& x, Vec<dim>& normal) const = 0;
    /// Volume [m³] (area [m²] in 2D).
    virtual double volume() const = 0;
    /// Principal moments of inertia per unit density about the centroid, along the body axes
    /// [m⁵] (in 2D only component 2, the polar moment about z, [m⁴], is used).
    virtual Vec3 unitInertia() const = 0;
    /// Radius of a circle/sphere about the origin that encloses the shape [m] (broad phase).
    virtual double boundingRadius() const = 0;
    /// Surface for output, in the body frame: points (z = 0 in 2D) and cells (triangles in 3D,
    /// line segments in 2D) as point-index lists.
    virtual void surface(std::vector<Vec3>& points, std::vector<std::vector<int>>& cells) const = 0;
    /// Where the body frame sat in the shape's source (a mesh): x_source = centroid + R x_body.
    /// False (the default) for shapes without a source frame; a body of such a shape must give
    /// its position.
    virtual bool meshPose(Vec<dim>& /*centroid*/, Mat<dim>& /*rotation*/) const { return false; }
    /// What body–body contact needs of the shape: probes in the body frame, each a point and a
    /// radius, such that the shape is the union of the balls B(point, radius) near its surface.
    /// The default is its output surface's vertices with radius 0 (a polyhedron's corners, a
    /// level set's marching-tetrahedra vertices); a ball answers its centre and its radius.
    virtual void contactProbes(std::vector<Vec<dim>>& points, std::vector<double>& radii) const {
        std::vector<Vec3> pts;
        std::vector<std::vector<int>> cells;
        surface(pts, cells);
        points.resize(pts.size());
        radii.assign(pts.size(), 0.0);
        for (std::size_t k = 0; k < pts.size(); ++k)
            points[k] = pts[k].template head<dim>();
    }
    /// The shape as a spheropolygon (2D: polygon ⊕ disk [001 Eq. 37]) for the SDEM body–body
    /// law, in the body frame; nullptr (the default) for a shape that is not one. 2D
    /// `spheropolygon`, `box` (4 vertices, a = 0) and `disk` (1 vertex, a = R) answer it.
    virtual const SpheroPolygon* spheroPolygon() const { return nullptr; }
    /// Spacing of the sampled field behind distance() [m]; 0 for an exact (analytic) shape.
    virtual double samplingSpacing() const { return 0.0; }

    /// Build the shape named by `type:` (sphere, disk, box, …).
    static std::unique_ptr<Shape> create(const Dictionary& dict);
};

template <int dim> using ShapeRegistry = Registry<Shape<dim>>;

} // namespace mpm
