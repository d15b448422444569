// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/Shape.hpp"
#include "core/Constants.hpp"
#include "rigid/BoxShape.hpp"
#include "rigid/SphereShape.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mpm {
namespace {

template <int dim> std::unique_ptr<Shape<dim>> makeShape(const std::string& yaml) {
    return Shape<dim>::create(Dictionary::fromString(yaml, "test"));
}

/// φ and n at x against the expected values.
template <int dim>
void expectDistance(const Shape<dim>& s, const Vec<dim>& x, double phi, const Vec<dim>& n) {
    Vec<dim> normal;
    EXPECT_NEAR(s.distance(x, normal), phi, 1e-14) << "at " << x.transpose();
    EXPECT_LT((normal - n).norm(), 1e-14) << "at " << x.transpose() << ": " << normal.transpose();
}

/// The returned normal is the gradient of φ (central differences, away from kinks).
template <int dim> void expectGradient(const Shape<dim>& s, const Vec<dim>& x) {
    Vec<dim> normal;
    Vec<dim> unused;
    s.distance(x, normal);
    const double h = 1e-6;
    for (int d = 0; d < dim; ++d) {
        Vec<dim> e = Vec<dim>::Zero();
        e[d] = h;
        const double g = (s.distance(x + e, unused) - s.distance(x - e, unused)) / (2.0 * h);
        EXPECT_NEAR(normal[d], g, 1e-7) << "at " << x.transpose() << ", component " << d;
    }
    EXPECT_NEAR(normal.norm(), 1.0, 1e-14);
}

/// Error message of building `yaml` (empty if it builds).
template <int dim> std::string errorOf(const std::string& yaml) {
    try {
        makeShape<dim>(yaml);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

/// Closed-surface checks: 3D triangles with outward normals enclose the volume
/// V = Σ p0·(p1 × p2)/6 (divergence theorem); 2D counter-clockwise segments enclose
/// A = Σ (x0 y1 − x1 y0)/2.
template <int dim> double enclosedVolume(const Shape<dim>& s, bool& outward) {
    std::vector<Vec3> p;
    std::vector<std::vector<int>> cells;
    s.surface(p, cells);
    double v = 0.0;
    outward = true;
    for (const auto& c : cells) {
        if constexpr (dim == 3) {
            EXPECT_EQ(c.size(), 3u);
            const Vec3 n = (p[c[1]] - p[c[0]]).cross(p[c[2]] - p[c[0]]);
            if (!(n.dot(p[c[0]] + p[c[1]] + p[c[2]]) > 0.0)) outward = false;
            v += p[c[0]].dot(p[c[1]].cross(p[c[2]])) / 6.0;
        } else {
            EXPECT_EQ(c.size(), 2u);
            const double cross = p[c[0]].x() * p[c[1]].y() - p[c[1]].x() * p[c[0]].y();
            if (!(cross > 0.0)) outward = false;
            v += 0.5 * cross;
        }
    }
    return v;
}

TEST(ShapeTest, Sphere) {
    const auto s = makeShape<3>("type: sphere\nradius: 2\n");
    expectDistance<3>(*s, Vec3(3, 0, 0), 1.0, Vec3(1, 0, 0));
    expectDistance<3>(*s, Vec3(0, -0.5, 0), -1.5, Vec3(0, -1, 0));
    expectDistance<3>(*s, Vec3(0, 0, -2), 0.0, Vec3(0, 0, -1));
    expectDistance<3>(*s, Vec3(2, 3, 6), 5.0, Vec3(2, 3, 6) / 7.0);
    Vec3 n;
    EXPECT_EQ(s->distance(Vec3::Zero(), n), -2.0);
    EXPECT_NEAR(n.norm(), 1.0, 1e-15);
    expectGradient<3>(*s, Vec3(0.3, -1.1, 0.7));
    expectGradient<3>(*s, Vec3(2.5, 1.0, -3.0));
    EXPECT_NEAR(s->volume(), 4.0 / 3.0 * pi * 8.0, 1e-13);
    const double inertia = 0.4 * s->volume() * 4.0; // 2/5 V r²
    EXPECT_NEAR(s->unitInertia()[0], inertia, 1e-12);
    EXPECT_NEAR(s->unitInertia()[1], inertia, 1e-12);
    EXPECT_NEAR(s->unitInertia()[2], 8.0 / 15.0 * pi * 32.0, 1e-12);
    EXPECT_EQ(s->boundingRadius(), 2.0);

    std::vector<Vec3> p;
    std::vector<std::vector<int>> cells;
    s->surface(p, cells);
    EXPECT_EQ(cells.size(), 2u * 24u * 11u);
    for (const Vec3& x : p)
        EXPECT_NEAR(x.norm(), 2.0, 1e-14);
    bool outward = false;
    const double v = enclosedVolume<3>(*s, outward);
    EXPECT_TRUE(outward);
    EXPECT_GT(v, 0.95 * s->volume());
    EXPECT_LT(v, s->volume());
}

TEST(ShapeTest, Disk) {
    const auto s = makeShape<2>("type: disk\nradius: 0.5\n");
    expectDistance<2>(*s, Vec<2>(0, 1), 0.5, Vec<2>(0, 1));
    expectDistance<2>(*s, Vec<2>(-0.3, 0), -0.2, Vec<2>(-1, 0));
    expectDistance<2>(*s, Vec<2>(0.3, -0.4), 0.0, Vec<2>(0.6, -0.8));
    expectGradient<2>(*s, Vec<2>(0.1, 0.2));
    EXPECT_NEAR(s->volume(), pi * 0.25, 1e-15);
    EXPECT_NEAR(s->unitInertia()[2], pi * std::pow(0.5, 4) / 2.0, 1e-15);
    EXPECT_EQ(s->boundingRadius(), 0.5);
    bool outward = false;
    const double a = enclosedVolume<2>(*s, outward);
    EXPECT_TRUE(outward);
    EXPECT_NEAR(a, 0.5 * 64 * 0.25 * std::sin(2.0 * pi / 64), 1e-14); // inscribed 64-gon

    std::vector<Vec3> p;
    std::vector<std::vector<int>> cells;
    s->surface(p, cells);
    EXPECT_EQ(cells.size(), 64u);
    for (const Vec3& x : p)
        EXPECT_EQ(x.z(), 0.0);
}

TEST(ShapeTest, Box3D) {
    const auto s = makeShape<3>("type: box\nhalfExtents: [0.5, 1, 1.5]\n");
    // Outside: face, edge and corner regions.
    expectDistance<3>(*s, Vec3(1, 0, 0), 0.5, Vec3(1, 0, 0));
    expectDistance<3>(*s, Vec3(0.2, 0.3, -2.5), 1.0, Vec3(0, 0, -1));
    expectDistance<3>(*s, Vec3(1, 2, 0), std::sqrt(1.25), Vec3(0.5, 1, 0) / std::sqrt(1.25));
    expectDistance<3>(*s, Vec3(-1, -2, 2), std::sqrt(1.5), Vec3(-0.5, -1, 0.5) / std::sqrt(1.5));
    // Inside: minus the distance to the nearest face, that face's normal.
    expectDistance<3>(*s, Vec3(0.4, 0, 0), -0.1, Vec3(1, 0, 0));
    expectDistance<3>(*s, Vec3(0, -0.9, 0.5), -0.1, Vec3(0, -1, 0));
    expectDistance<3>(*s, Vec3(0.1, 0.2, -1.3), -0.2, Vec3(0, 0, -1));
    expectDistance<3>(*s, Vec3(0, 0, 0), -0.5, Vec3(1, 0, 0));
    // On the surface.
    expectDistance<3>(*s, Vec3(-0.5, 0.2, 0.3), 0.0, Vec3(-1, 0, 0));
    expectDistance<3>(*s, Vec3(0.1, 1, 1.2), 0.0, Vec3(0, 1, 0));
    for (const Vec3& x : {Vec3(0.7, 0.2, 0.1), Vec3(0.8, 1.3, -0.2), Vec3(-0.9, 1.4, 1.9),
                          Vec3(0.1, -0.5, 1.2), Vec3(-0.3, 0.1, 0.05)}) {
        expectGradient<3>(*s, x);
    }
    EXPECT_NEAR(s->volume(), 6.0, 1e-15);
    // I_x = V (b² + c²)/12 for edges a, b, c = 1, 2, 3.
    EXPECT_NEAR(s->unitInertia()[0], 6.0 * (4.0 + 9.0) / 12.0, 1e-14);
    EXPECT_NEAR(s->unitInertia()[1], 6.0 * (9.0 + 1.0) / 12.0, 1e-14);
    EXPECT_NEAR(s->unitInertia()[2], 6.0 * (1.0 + 4.0) / 12.0, 1e-14);
    EXPECT_NEAR(s->boundingRadius(), std::sqrt(0.25 + 1.0 + 2.25), 1e-15);

    std::vector<Vec3> p;
    std::vector<std::vector<int>> cells;
    s->surface(p, cells);
    EXPECT_EQ(p.size(), 8u);
    EXPECT_EQ(cells.size(), 12u);
    bool outward = false;
    EXPECT_NEAR(enclosedVolume<3>(*s, outward), 6.0, 1e-14);
    EXPECT_TRUE(outward);

    // size = full edge lengths.
    const auto t = makeShape<3>("type: box\nsize: [1, 2, 3]\n");
    EXPECT_EQ(t->volume(), s->volume());
    EXPECT_EQ(t->unitInertia(), s->unitInertia());
}

TEST(ShapeTest, Box2D) {
    const auto s = makeShape<2>("type: box\nsize: [2, 1]\n");
    expectDistance<2>(*s, Vec<2>(2, 0), 1.0, Vec<2>(1, 0));
    expectDistance<2>(*s, Vec<2>(4, 4.5), 5.0, Vec<2>(0.6, 0.8));
    expectDistance<2>(*s, Vec<2>(0.5, -0.4), -0.1, Vec<2>(0, -1));
    expectDistance<2>(*s, Vec<2>(-0.95, 0.1), -0.05, Vec<2>(-1, 0));
    expectDistance<2>(*s, Vec<2>(0.3, 0.5), 0.0, Vec<2>(0, 1));
    expectGradient<2>(*s, Vec<2>(1.3, 0.9));
    expectGradient<2>(*s, Vec<2>(0.2, -0.1));
    EXPECT_NEAR(s->volume(), 2.0, 1e-15);
    EXPECT_NEAR(s->unitInertia()[2], 2.0 * (4.0 + 1.0) / 12.0, 1e-15); // A (a² + b²)/12
    bool outward = false;
    EXPECT_NEAR(enclosedVolume<2>(*s, outward), 2.0, 1e-15);
    EXPECT_TRUE(outward);
}

TEST(ShapeTest, Errors) {
    EXPECT_NE(errorOf<2>("type: sphere\nradius: 1\n").find("use 'disk' in 2D"), std::string::npos);
    EXPECT_NE(errorOf<3>("type: disk\nradius: 1\n").find("use 'sphere' in 3D"), std::string::npos);
    EXPECT_NE(errorOf<3>("type: sphere\nradius: 1\nradus: 2\n").find("radus"), std::string::npos);
    EXPECT_NE(errorOf<3>("type: box\nsize: [1, 1, 1]\ncentre: [0, 0, 0]\n").find("centre"),
              std::string::npos);
    EXPECT_NE(errorOf<3>("type: cone\nradius: 1\n").find("unknown type"), std::string::npos);
    EXPECT_FALSE(errorOf<3>("type: sphere\nradius: 0\n").empty());
    EXPECT_FALSE(errorOf<3>("type: box\nhalfExtents: [1, 1]\n").empty());
    EXPECT_FALSE(errorOf<2>("type: box\nhalfExtents: [1, -1]\n").empty());
    EXPECT_FALSE(errorOf<2>("type: box\n").empty());
    EXPECT_NE(errorOf<2>("type: box\nsize: [1, 1]\nhalfExtents: [1, 1]\n").find("exactly one"),
              std::string::npos);
}

} // namespace
} // namespace mpm
