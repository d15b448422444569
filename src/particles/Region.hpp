// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/Types.hpp"

#include <Eigen/Geometry>

#include <memory>

namespace mpm {

/// A closed geometric region of a dim-dimensional scene (where particles are seeded, what a
/// boundary or monitor selects).
///
/// Built from a dictionary by its `type:` key (one registry per dimension):
///
///     type: box       min: [x, y(, z)]   max: [x, y(, z)]          (every max > min)
///     type: disk      centre: [x, y]     radius: r                 (2D; `sphere` in 3D)
///     type: sphere    centre: [x, y, z]  radius: r                 (3D; `disk` in 2D)
///     type: cylinder  p1: [x, y, z]  p2: [x, y, z]  radius: r      (3D only; axis p1 -> p2)
///     type: polygon   vertices: [[x, y], [x, y], ...]              (>= 3 vertices; in 3D a
///                     extrude: {axis: y, min: a, max: b}          prism: vertices in the
///                                                                 plane of the other axes)
///
/// A name valid only in the other dimension is an InputError saying what to use instead.
template <int dim> class Region {
public:
    virtual ~Region() = default;

    /// True if `x` lies in the region (boundary included, except where a polygon's even-odd
    /// rule decides otherwise).
    virtual bool contains(const Vec<dim>& x) const = 0;
    /// Axis-aligned bounding box: every point with contains(x) lies in it.
    virtual Eigen::AlignedBox<double, dim> bounds() const = 0;
    /// Exact volume of the region (area in 2D).
    virtual double volume() const = 0;

    /// Build the region `dict` names by its `type:` entry (RegionRegistry).
    static std::unique_ptr<Region> create(const Dictionary& dict);
};

template <class Base, class... Args> class Registry; // case/Registry.hpp
template <int dim> using RegionRegistry = Registry<Region<dim>>;

extern template class Region<2>;
extern template class Region<3>;

} // namespace mpm
