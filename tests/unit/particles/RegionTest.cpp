// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/Region.hpp"
#include "core/Constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mpm {
namespace {

template <int dim> std::unique_ptr<Region<dim>> makeRegion(const std::string& yaml) {
    return Region<dim>::create(Dictionary::fromString(yaml, "test"));
}

TEST(RegionTest, Box2D) {
    const auto r = makeRegion<2>("type: box\nmin: [0, -1]\nmax: [2, 1]\n");
    EXPECT_TRUE(r->contains(Vec<2>(1.0, 0.0)));
    EXPECT_TRUE(r->contains(Vec<2>(2.0, 1.0))); // boundary
    EXPECT_FALSE(r->contains(Vec<2>(2.01, 0.0)));
    EXPECT_FALSE(r->contains(Vec<2>(1.0, -1.5)));
    EXPECT_DOUBLE_EQ(r->volume(), 4.0);
    EXPECT_TRUE(r->bounds().min().isApprox(Vec<2>(0.0, -1.0)));
    EXPECT_TRUE(r->bounds().max().isApprox(Vec<2>(2.0, 1.0)));
}

TEST(RegionTest, Box3D) {
    const auto r = makeRegion<3>("type: box\nmin: [0, 0, 0]\nmax: [1, 2, 3]\n");
    EXPECT_TRUE(r->contains(Vec<3>(0.5, 1.5, 2.5)));
    EXPECT_FALSE(r->contains(Vec<3>(0.5, 1.5, 3.5)));
    EXPECT_DOUBLE_EQ(r->volume(), 6.0);
}

TEST(RegionTest, Disk2D) {
    const auto r = makeRegion<2>("type: disk\ncentre: [1, 1]\nradius: 0.5\n");
    EXPECT_TRUE(r->contains(Vec<2>(1.0, 1.4)));
    EXPECT_TRUE(r->contains(Vec<2>(1.5, 1.0)));
    EXPECT_FALSE(r->contains(Vec<2>(1.36, 1.36)));
    EXPECT_NEAR(r->volume(), pi * 0.25, 1e-14);
    EXPECT_TRUE(r->bounds().min().isApprox(Vec<2>(0.5, 0.5)));
    EXPECT_TRUE(r->bounds().max().isApprox(Vec<2>(1.5, 1.5)));
}

TEST(RegionTest, Sphere3D) {
    const auto r = makeRegion<3>("type: sphere\ncentre: [0, 0, 0]\nradius: 2\n");
    EXPECT_TRUE(r->contains(Vec<3>(1.0, 1.0, 1.0)));
    EXPECT_FALSE(r->contains(Vec<3>(1.2, 1.2, 1.2)));
    EXPECT_NEAR(r->volume(), 4.0 / 3.0 * pi * 8.0, 1e-12);
    EXPECT_TRUE(r->bounds().max().isApprox(Vec<3>(2.0, 2.0, 2.0)));
}

TEST(RegionTest, Cylinder3D) {
    const auto r = makeRegion<3>("type: cylinder\np1: [0, 0, 0]\np2: [0, 0, 2]\nradius: 1\n");
    EXPECT_TRUE(r->contains(Vec<3>(0.5, 0.5, 1.0)));
    EXPECT_TRUE(r->contains(Vec<3>(0.0, 0.0, 0.0)));
    EXPECT_FALSE(r->contains(Vec<3>(0.8, 0.8, 1.0)));
    EXPECT_FALSE(r->contains(Vec<3>(0.0, 0.0, 2.1)));
    EXPECT_FALSE(r->contains(Vec<3>(0.0, 0.0, -0.1)));
    EXPECT_NEAR(r->volume(), 2.0 * pi, 1e-14);
    EXPECT_TRUE(r->bounds().min().isApprox(Vec<3>(-1.0, -1.0, 0.0)));
    EXPECT_TRUE(r->bounds().max().isApprox(Vec<3>(1.0, 1.0, 2.0)));
}

TEST(RegionTest, ObliqueCylinderBoundsHoldItsPoints) {
    const auto r = makeRegion<3>("type: cylinder\np1: [0, 0, 0]\np2: [1, 2, 3]\nradius: 0.5\n");
    EXPECT_NEAR(r->volume(), pi * 0.25 * std::sqrt(14.0), 1e-12);
    const auto box = r->bounds();
    // Sample the bounds: every contained point lies inside, and points near each face exist.
    const int n = 40;
    Vec<3> lo = Vec<3>::Constant(1e9);
    Vec<3> hi = Vec<3>::Constant(-1e9);
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            for (int k = 0; k <= n; ++k) {
                const Vec<3> t(double(i) / n, double(j) / n, double(k) / n);
                const Vec<3> x = box.min() + t.cwiseProduct(box.sizes());
                if (r->contains(x)) {
                    lo = lo.cwiseMin(x);
                    hi = hi.cwiseMax(x);
                }
            }
        }
    }
    const Vec<3> cell = box.sizes() / n;
    EXPECT_TRUE(((lo - box.min()).array() <= 1.01 * cell.array()).all());
    EXPECT_TRUE(((box.max() - hi).array() <= 1.01 * cell.array()).all());
}

TEST(RegionTest, PolygonConvex) {
    const auto r = makeRegion<2>("type: polygon\nvertices: [[0, 0], [2, 0], [0, 2]]\n");
    EXPECT_TRUE(r->contains(Vec<2>(0.5, 0.5)));
    EXPECT_FALSE(r->contains(Vec<2>(1.5, 1.5)));
    EXPECT_DOUBLE_EQ(r->volume(), 2.0);
    EXPECT_TRUE(r->bounds().max().isApprox(Vec<2>(2.0, 2.0)));
}

TEST(RegionTest, PolygonConcaveEitherOrientation) {
    // An L shape: [0,2]x[0,1] plus [0,1]x[1,2], area 3.
    const std::string ccw = "[[0, 0], [2, 0], [2, 1], [1, 1], [1, 2], [0, 2]]";
    const std::string cw = "[[0, 2], [1, 2], [1, 1], [2, 1], [2, 0], [0, 0]]";
    for (const std::string& v : {ccw, cw}) {
        const auto r = makeRegion<2>("type: polygon\nvertices: " + v + "\n");
        EXPECT_DOUBLE_EQ(r->volume(), 3.0);
        EXPECT_TRUE(r->contains(Vec<2>(1.5, 0.5)));
        EXPECT_TRUE(r->contains(Vec<2>(0.5, 1.5)));
        EXPECT_TRUE(r->contains(Vec<2>(0.5, 0.5)));
        EXPECT_FALSE(r->contains(Vec<2>(1.5, 1.5))); // the notch
        EXPECT_FALSE(r->contains(Vec<2>(-0.5, 0.5)));
        EXPECT_FALSE(r->contains(Vec<2>(2.5, 0.5)));
        EXPECT_TRUE(r->bounds().min().isApprox(Vec<2>(0.0, 0.0)));
        EXPECT_TRUE(r->bounds().max().isApprox(Vec<2>(2.0, 2.0)));
    }
}

TEST(RegionTest, PolygonAreaMatchesSampling) {
    // A star-like concave polygon: the fraction of a fine lattice inside approximates the area.
    const auto r = makeRegion<2>("type: polygon\nvertices: [[0, 0], [3, 1], [6, 0], [5, 3], [6, "
                                 "6], [3, 4], [0, 6], [1, 3]]\n");
    const int n = 600;
    const double h = 6.0 / n;
    int inside = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j)
            inside += r->contains(Vec<2>((i + 0.5) * h, (j + 0.5) * h));
    }
    EXPECT_NEAR(inside * h * h, r->volume(), 0.01 * r->volume());
    EXPECT_DOUBLE_EQ(r->volume(), 21.0);
}

TEST(RegionTest, PrismIsThePolygonExtrudedAlongItsAxis) {
    // Triangle (0,0), (2,0), (0,1) in the x–z plane, extruded over y ∈ [1, 4]: V = 1 × 3.
    const auto r = makeRegion<3>("type: polygon\nvertices: [[0, 0], [2, 0], [0, 1]]\n"
                                 "extrude: {axis: y, min: 1, max: 4}\n");
    EXPECT_DOUBLE_EQ(r->volume(), 3.0);
    EXPECT_TRUE(r->bounds().min().isApprox(Vec3(0, 1, 0)));
    EXPECT_TRUE(r->bounds().max().isApprox(Vec3(2, 4, 1)));
    EXPECT_TRUE(r->contains(Vec3(0.5, 2.0, 0.25)));
    EXPECT_FALSE(r->contains(Vec3(0.5, 0.5, 0.25))); // below min along y
    EXPECT_FALSE(r->contains(Vec3(0.5, 4.5, 0.25))); // above max
    EXPECT_FALSE(r->contains(Vec3(1.5, 2.0, 0.5)));  // beyond the hypotenuse x/2 + z = 1
    // Axis x: the vertices are (y, z).
    const auto q = makeRegion<3>("type: polygon\nvertices: [[0, 0], [2, 0], [0, 1]]\n"
                                 "extrude: {axis: x, min: 0, max: 1}\n");
    EXPECT_TRUE(q->contains(Vec3(0.5, 1.0, 0.25)));
    EXPECT_FALSE(q->contains(Vec3(0.5, 0.25, 1.0)));
    // Lattice count approximates the volume.
    int inside = 0;
    const int n = 60;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                inside += r->contains(
                    Vec3(2.0 * (i + 0.5) / n, 1.0 + 3.0 * (j + 0.5) / n, (k + 0.5) / n));
    EXPECT_NEAR(inside * 6.0 / (n * n * n), 3.0, 0.03);
}

TEST(RegionTest, Errors) {
    // Names valid only in the other dimension say what to use instead.
    try {
        makeRegion<2>("type: sphere\ncentre: [0, 0]\nradius: 1\n");
        FAIL() << "2D sphere accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("disk"), std::string::npos) << e.what();
    }
    try {
        makeRegion<3>("type: disk\ncentre: [0, 0, 0]\nradius: 1\n");
        FAIL() << "3D disk accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("sphere"), std::string::npos) << e.what();
    }
    try {
        makeRegion<2>("type: cylinder\np1: [0, 0]\np2: [1, 0]\nradius: 1\n");
        FAIL() << "2D cylinder accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("box"), std::string::npos) << e.what();
    }
    try { // a 3D polygon needs its extrusion
        makeRegion<3>("type: polygon\nvertices: [[0, 0], [1, 0], [0, 1]]\n");
        FAIL() << "3D polygon without extrude accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("extrude"), std::string::npos) << e.what();
    }
    EXPECT_THROW(makeRegion<3>("type: polygon\nvertices: [[0, 0], [1, 0], [0, 1]]\n"
                               "extrude: {axis: w, min: 0, max: 1}\n"),
                 InputError);
    EXPECT_THROW(makeRegion<3>("type: polygon\nvertices: [[0, 0], [1, 0], [0, 1]]\n"
                               "extrude: {axis: y, min: 1, max: 1}\n"),
                 InputError);

    EXPECT_THROW(makeRegion<3>("type: sphere\ncentre: [0, 0, 0]\nradius: -1\n"), InputError);
    EXPECT_THROW(makeRegion<2>("type: disk\ncentre: [0, 0]\nradius: 0\n"), InputError);
    EXPECT_THROW(makeRegion<3>("type: cylinder\np1: [0, 0, 0]\np2: [0, 0, 1]\nradius: -2\n"),
                 InputError);
    EXPECT_THROW(makeRegion<3>("type: cylinder\np1: [1, 1, 1]\np2: [1, 1, 1]\nradius: 1\n"),
                 InputError);
    EXPECT_THROW(makeRegion<2>("type: box\nmin: [0, 0]\nmax: [1, 0]\n"), InputError);
    EXPECT_THROW(makeRegion<3>("type: box\nmin: [0, 0, 0]\nmax: [1, 1, -1]\n"), InputError);
    EXPECT_THROW(makeRegion<2>("type: box\nmin: [0, 0, 0]\nmax: [1, 1, 1]\n"), InputError);
    EXPECT_THROW(makeRegion<2>("type: polygon\nvertices: [[0, 0], [1, 0]]\n"), InputError);
    EXPECT_THROW(makeRegion<2>("type: polygon\nvertices: [[0, 0], [1, 1], [2, 2]]\n"), InputError);
    EXPECT_THROW(makeRegion<2>("type: box\nmin: [0, 0]\nmax: [1, 1]\nmax_: [2, 2]\n"),
                 InputError); // unknown key
    EXPECT_THROW(makeRegion<2>("type: ball\ncentre: [0, 0]\nradius: 1\n"), InputError);
}

} // namespace
} // namespace mpm
