// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/Region.hpp"

#include "case/DictionaryVectors.hpp"
#include "case/Registry.hpp"
#include "core/Constants.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace mpm {

template <int dim> std::unique_ptr<Region<dim>> Region<dim>::create(const Dictionary& dict) {
    return RegionRegistry<dim>::create(dict);
}

template class Region<2>;
template class Region<3>;

namespace {

/// Axis-aligned box [min, max]: volume = prod_d (max_d - min_d).
template <int dim> class BoxRegion : public Region<dim> {
public:
    explicit BoxRegion(const Dictionary& dict)
        : box_(readVec<dim>(dict, "min"), readVec<dim>(dict, "max")) {
        for (int d = 0; d < dim; ++d) {
            if (!(box_.max()[d] > box_.min()[d])) {
                dict.error("max", "every component of max must be greater than that of min");
            }
        }
        dict.checkUnknownKeys();
    }

    bool contains(const Vec<dim>& x) const override { return box_.contains(x); }
    Eigen::AlignedBox<double, dim> bounds() const override { return box_; }
    double volume() const override { return box_.volume(); }

private:
    Eigen::AlignedBox<double, dim> box_;
};

/// Ball |x - c| <= r: volume = pi r^2 (disk, 2D) or 4/3 pi r^3 (sphere, 3D); registered as
/// `disk` in 2D and `sphere` in 3D.
template <int dim> class BallRegion : public Region<dim> {
public:
    explicit BallRegion(const Dictionary& dict) {
        centre_ = readVec<dim>(dict, "centre");
        radius_ = dict.getScalar("radius", Bounds::positive());
        dict.checkUnknownKeys();
    }

    bool contains(const Vec<dim>& x) const override {
        return (x - centre_).squaredNorm() <= radius_ * radius_;
    }
    Eigen::AlignedBox<double, dim> bounds() const override {
        return {centre_.array() - radius_, centre_.array() + radius_};
    }
    double volume() const override {
        return dim == 2 ? pi * radius_ * radius_ : 4.0 / 3.0 * pi * radius_ * radius_ * radius_;
    }

private:
    Vec<dim> centre_;
    double radius_ = 0.0;
};

/// Solid circular cylinder of radius r around the segment p1 -> p2 (3D only), with flat end
/// caps: contains x iff t = (x - p1).a / |a|^2 in [0, 1] and |x - p1 - t a| <= r, a = p2 - p1.
/// Volume = pi r^2 |a|.
template <int dim> class CylinderRegion : public Region<dim> {
public:
    explicit CylinderRegion(const Dictionary& dict) {
        p1_ = readVec<dim>(dict, "p1");
        p2_ = readVec<dim>(dict, "p2");
        radius_ = dict.getScalar("radius", Bounds::positive());
        if (!((p2_ - p1_).squaredNorm() > 0.0)) dict.error("p2", "p2 must differ from p1");
        dict.checkUnknownKeys();
    }

    bool contains(const Vec<dim>& x) const override {
        const Vec<dim> a = p2_ - p1_;
        const Vec<dim> d = x - p1_;
        const double t = d.dot(a) / a.squaredNorm();
        return t >= 0.0 && t <= 1.0 && (d - t * a).squaredNorm() <= radius_ * radius_;
    }

    /// The end caps are disks normal to the unit axis n; a disk's half extent along axis d is
    /// r sqrt(1 - n_d^2).
    Eigen::AlignedBox<double, dim> bounds() const override {
        const Vec<dim> n = (p2_ - p1_).normalized();
        Vec<dim> e;
        for (int d = 0; d < dim; ++d)
            e[d] = radius_ * std::sqrt(std::max(0.0, 1.0 - n[d] * n[d]));
        return {p1_.cwiseMin(p2_) - e, p1_.cwiseMax(p2_) + e};
    }
    double volume() const override { return pi * radius_ * radius_ * (p2_ - p1_).norm(); }

private:
    Vec<dim> p1_;
    Vec<dim> p2_;
    double radius_ = 0.0;
};

/// Simple polygon with vertices v_0 .. v_{n-1} in either orientation; in 3D a prism, the
/// polygon drawn in the plane of the two other axes (in increasing axis order: x–z for
/// `extrude: {axis: y, ...}`) and extruded between `min` and `max` along `axis`.
/// contains: even-odd rule (a ray from x crosses the boundary an odd number of times).
/// Volume: the shoelace area A = |sum_i (x_i y_{i+1} - x_{i+1} y_i)| / 2, times max - min in 3D.
template <int dim> class PolygonRegion : public Region<dim> {
public:
    explicit PolygonRegion(const Dictionary& dict) {
        double length = 1.0;
        if constexpr (dim == 3) {
            if (!dict.has("extrude"))
                dict.error("extrude", "a 3D polygon is a prism: give extrude: {axis: x|y|z, "
                                      "min: a, max: b} (the vertices lie in the other two axes)");
            const Dictionary e = dict.subDict("extrude");
            const std::string a = e.getWord("axis", {"x", "y", "z"});
            axis_ = a[0] - 'x';
            along_[0] = e.getScalar("min");
            along_[1] = e.getScalar("max");
            e.checkUnknownKeys();
            if (!(along_[1] > along_[0])) e.error("max", "max must be greater than min");
            length = along_[1] - along_[0];
            int k = 0;
            for (int d = 0; d < 3; ++d)
                if (d != axis_) plane_[k++] = d;
        }
        const std::vector<std::vector<double>> list = dict.vectorList("vertices", 2);
        if (list.size() < 3) dict.error("vertices", "a polygon needs at least 3 vertices");
        for (const auto& v : list)
            vertices_.emplace_back(v[0], v[1]);

        Eigen::AlignedBox2d box;
        for (const auto& v : vertices_)
            box.extend(v);
        double twiceArea = 0.0;
        for (std::size_t i = 0, j = vertices_.size() - 1; i < vertices_.size(); j = i++) {
            twiceArea += vertices_[j].x() * vertices_[i].y() - vertices_[i].x() * vertices_[j].y();
        }
        area_ = 0.5 * std::abs(twiceArea);
        // Relative to the bounding box, so that rounding in collinear vertices still counts as 0.
        if (!(area_ > 1e-12 * box.sizes().prod())) {
            dict.error("vertices", "the polygon has zero area");
        }
        for (int d = 0; d < 2; ++d) {
            lo_[plane_[d]] = box.min()[d];
            hi_[plane_[d]] = box.max()[d];
        }
        if constexpr (dim == 3) {
            lo_[axis_] = along_[0];
            hi_[axis_] = along_[1];
        }
        volume_ = area_ * length;
        dict.checkUnknownKeys();
    }

    bool contains(const Vec<dim>& x) const override {
        if constexpr (dim == 3)
            if (!(x[axis_] >= along_[0] && x[axis_] <= along_[1])) return false;
        const double u = x[plane_[0]], w = x[plane_[1]];
        bool inside = false;
        for (std::size_t i = 0, j = vertices_.size() - 1; i < vertices_.size(); j = i++) {
            const Eigen::Vector2d& a = vertices_[i];
            const Eigen::Vector2d& b = vertices_[j];
            if ((a.y() > w) != (b.y() > w)) {
                const double uCross = a.x() + (w - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
                if (u < uCross) inside = !inside;
            }
        }
        return inside;
    }
    Eigen::AlignedBox<double, dim> bounds() const override { return {lo_, hi_}; }
    double volume() const override { return volume_; }

private:
    std::vector<Eigen::Vector2d> vertices_;
    int axis_ = 2;          ///< extrusion axis (3D)
    int plane_[2] = {0, 1}; ///< the axes of the vertices' coordinates
    double along_[2] = {0.0, 0.0};
    Vec<dim> lo_ = Vec<dim>::Zero();
    Vec<dim> hi_ = Vec<dim>::Zero();
    double area_ = 0.0, volume_ = 0.0;
};

MPM_FAMILY_INFO("regions", {"<set>.region.type in constant/particles",
                            "7. constant/particles",
                            {{"type", "word", "-", "required", "the region's shape"}}});
MPM_FAMILY_DIMS(RegionRegistry, "regions");

MPM_REGISTER_DIMS(RegionRegistry, BoxRegion, "box");
MPM_REGISTER_ONLY(3, RegionRegistry, BallRegion<3>, "sphere");
MPM_REGISTER_ONLY(2, RegionRegistry, BallRegion<2>, "disk");
MPM_REGISTER_ONLY(3, RegionRegistry, CylinderRegion<3>, "cylinder");
MPM_REGISTER_DIMS(RegionRegistry, PolygonRegion, "polygon");
MPM_SCHEMA("regions", "box",
           {"an axis-aligned box",
            {{"min", "vector", "m", "required", "lower corner"},
             {"max", "vector", "m", "required", "upper corner (> min)"}},
            "{type: box, min: [0, 0], max: [0.1, 0.1]}"});
MPM_SCHEMA("regions", "disk",
           {"a disk",
            {{"centre", "vector", "m", "required", "centre"},
             {"radius", "scalar", "m", "required", "radius (> 0)"}},
            "{type: disk, centre: [0.1, 0.1], radius: 0.05}",
            "use 'sphere' in 3D"});
MPM_SCHEMA("regions", "sphere",
           {"a ball",
            {{"centre", "vector", "m", "required", "centre"},
             {"radius", "scalar", "m", "required", "radius (> 0)"}},
            "{type: sphere, centre: [0.1, 0.1, 0.1], radius: 0.05}",
            "use 'disk' in 2D"});
MPM_SCHEMA("regions", "cylinder",
           {"a solid cylinder with flat caps",
            {{"p1", "vector", "m", "required", "one end of the axis"},
             {"p2", "vector", "m", "required", "the other end (≠ p1)"},
             {"radius", "scalar", "m", "required", "radius (> 0)"}},
            "{type: cylinder, p1: [0.1, 0.1, 0], p2: [0.1, 0.1, 0.2], radius: 0.05}",
            "use 'box' or 'polygon' in 2D"});
MPM_SCHEMA("regions", "polygon",
           {"a polygon (even-odd rule); in 3D a prism extruded along an axis",
            {{"vertices", "list of [x, y]", "m", "required",
              "≥ 3 vertices; in 3D in the two axes other than extrude.axis"},
             {"extrude", "map {axis, min, max}", "m", "none (3D: required)",
              "3D: the prism's axis x, y or z and its extent [min, max]"}},
            "{type: polygon, vertices: [[0, 0], [0.1, 0], [0, 0.1]]}"});

} // namespace
} // namespace mpm
