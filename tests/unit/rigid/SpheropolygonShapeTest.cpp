// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/SpheropolygonShape.hpp"
#include "core/Constants.hpp"
#include "rigid/BoxShape.hpp"
#include "rigid/RigidBody.hpp"
#include "rigid/SphereShape.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>

namespace mpm {
namespace {

std::unique_ptr<Shape<2>> make2(const std::string& yaml) {
    return Shape<2>::create(Dictionary::fromString(yaml, "rigidBodies"));
}

std::string errorOf2(const std::string& yaml) {
    try {
        make2(yaml);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

/// Brute-force signed distance to polygon ⊕ disk(a) (vertices counter-clockwise, n ≥ 3):
/// smallest distance to the edges, negative inside (all edges see x on their left).
double bruteDistance(const std::vector<Vec<2>>& v, double a, const Vec<2>& x) {
    double d = 1e300;
    bool inside = true;
    const int n = static_cast<int>(v.size());
    for (int k = 0; k < n; ++k) {
        const Vec<2> p = v[k], q = v[(k + 1) % n];
        const Vec<2> e = q - p;
        const double s = std::clamp((x - p).dot(e) / e.squaredNorm(), 0.0, 1.0);
        d = std::min(d, (x - p - s * e).norm());
        if (e[0] * (x - p)[1] - e[1] * (x - p)[0] < 0) inside = false;
    }
    return (inside ? -d : d) - a;
}

/// Area, centroid and polar moment about the centroid of {φ < 0} by midpoint quadrature on an
/// N × N grid over [lo, hi]².
void quadrature(const std::function<double(const Vec<2>&)>& phi, double lo, double hi, int N,
                double& area, Vec<2>& centroid, double& polar) {
    const double h = (hi - lo) / N;
    double A = 0, J0 = 0;
    Vec<2> S = Vec<2>::Zero();
    for (int i = 0; i < N; ++i)
        for (int j = 0; j < N; ++j) {
            const Vec<2> x(lo + (i + 0.5) * h, lo + (j + 0.5) * h);
            if (phi(x) >= 0) continue;
            A += h * h;
            S += h * h * x;
            J0 += h * h * x.squaredNorm();
        }
    area = A;
    centroid = S / A;
    polar = J0 - A * centroid.squaredNorm();
}

TEST(SpheropolygonShapeTest, RoundedSquareHasAnalyticAreaCentroidAndPolarMoment) {
    const double s = 2.0, a = 0.3;
    const auto shape = make2("{type: spheropolygon, radius: 0.3, "
                             "vertices: [[4, 0], [6, 0], [6, 2], [4, 2]]}");
    EXPECT_NEAR(shape->volume(), s * s + 4 * s * a + pi * a * a, 1e-13);
    // I_x = ∫x² dA: central band (s + 2a) wide and s high, two strips s × a, four quarter disks
    // (∫(s/2 + u)² over u, v ≥ 0, |u| < a); J = 2 I_x by symmetry.
    const double w = s + 2 * a;
    const double ix = s * w * w * w / 12 + 2 * a * s * s * s / 12 +
                      (pi * a * a * s * s / 4 + 4 * s * a * a * a / 3 + pi * a * a * a * a / 4);
    EXPECT_NEAR(shape->unitInertia()[2], 2 * ix, 1e-12 * ix);
    Vec<2> c;
    Mat<2> R;
    ASSERT_TRUE(shape->meshPose(c, R));
    EXPECT_LT((c - Vec<2>(5, 1)).norm(), 1e-14);
    EXPECT_TRUE(R.isIdentity());
    EXPECT_NEAR(shape->boundingRadius(), std::sqrt(2.0) + a, 1e-14);
}

TEST(SpheropolygonShapeTest, OneVertexIsADisk) {
    const auto shape = make2("{type: spheropolygon, radius: 0.5, vertices: [[0.3, -0.2]]}");
    const double a = 0.5;
    EXPECT_NEAR(shape->volume(), pi * a * a, 1e-15);
    EXPECT_NEAR(shape->unitInertia()[2], pi * a * a * a * a / 2, 1e-15);
    Vec<2> c;
    Mat<2> R;
    shape->meshPose(c, R);
    EXPECT_LT((c - Vec<2>(0.3, -0.2)).norm(), 1e-15);
    Vec<2> n;
    EXPECT_NEAR(shape->distance(Vec<2>(0.6, 0.8), n), 1.0 - a, 1e-15); // body frame
    EXPECT_LT((n - Vec<2>(0.6, 0.8)).norm(), 1e-15);
    EXPECT_EQ(shape->spheroPolygon()->edgeCount(), 1);
}

TEST(SpheropolygonShapeTest, TwoVerticesAreACapsule) {
    const double L = 1.5, a = 0.2;
    const auto shape = make2("{type: spheropolygon, radius: 0.2, vertices: [[0, 1], [1.5, 1]]}");
    EXPECT_NEAR(shape->volume(), 2 * a * L + pi * a * a, 1e-14);
    // Rectangle L × 2a plus two half disks (centroid 4a/3π beyond each end vertex).
    const double J = a * L * (L * L + 4 * a * a) / 6 + pi * a * a * a * a / 2 +
                     pi * a * a * L * L / 4 + 4 * a * a * a * L / 3;
    EXPECT_NEAR(shape->unitInertia()[2], J, 1e-14);
    Vec<2> c;
    Mat<2> R;
    shape->meshPose(c, R);
    EXPECT_LT((c - Vec<2>(0.75, 1)).norm(), 1e-15);
    Vec<2> n;
    EXPECT_NEAR(shape->distance(Vec<2>(0.1, 0.5), n), 0.5 - a, 1e-15);
    EXPECT_LT((n - Vec<2>(0, 1)).norm(), 1e-15);
    EXPECT_NEAR(shape->distance(Vec<2>(3, 0), n), 3 - L / 2 - a, 1e-15);
    EXPECT_EQ(shape->spheroPolygon()->edgeCount(), 1);
    EXPECT_NEAR(shape->boundingRadius(), L / 2 + a, 1e-15);
}

TEST(SpheropolygonShapeTest, OffCentreTriangleMatchesQuadratureAndBruteForceDistance) {
    const std::vector<Vec<2>> v = {Vec<2>(1.0, 0.5), Vec<2>(2.2, 0.8), Vec<2>(1.3, 1.9)};
    const double a = 0.15;
    const auto shape = make2("{type: spheropolygon, radius: 0.15, "
                             "vertices: [[1.0, 0.5], [2.2, 0.8], [1.3, 1.9]]}");
    double perimeter = 0;
    for (int k = 0; k < 3; ++k)
        perimeter += (v[(k + 1) % 3] - v[k]).norm();
    const Vec<2> e1 = v[1] - v[0], e2 = v[2] - v[0];
    const double core = 0.5 * (e1[0] * e2[1] - e1[1] * e2[0]);
    EXPECT_NEAR(shape->volume(), core + a * perimeter + pi * a * a, 1e-14);
    double A, J;
    Vec<2> c;
    quadrature([&](const Vec<2>& x) { return bruteDistance(v, a, x); }, 0.0, 2.5, 2500, A, c, J);
    Vec<2> cs;
    Mat<2> R;
    shape->meshPose(cs, R);
    // Midpoint quadrature of the indicator converges erratically, ~1e-4 at h = 1e-3.
    EXPECT_NEAR(A / shape->volume(), 1.0, 2e-4);
    EXPECT_LT((c - cs).norm(), 1e-4);
    EXPECT_NEAR(J / shape->unitInertia()[2], 1.0, 3e-4);

    // distance() in the body frame (origin at the centroid) against brute force, and its normal
    // against central differences away from the kinks.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(0.0, 3.0);
    for (int k = 0; k < 2000; ++k) {
        const Vec<2> x(u(rng), u(rng));
        Vec<2> n, unused;
        const double phi = shape->distance(x - cs, n);
        EXPECT_NEAR(phi, bruteDistance(v, a, x), 1e-13) << x.transpose();
        const double h = 1e-6;
        const Vec<2> g((shape->distance(x - cs + Vec<2>(h, 0), unused) -
                        shape->distance(x - cs - Vec<2>(h, 0), unused)) /
                           (2 * h),
                       (shape->distance(x - cs + Vec<2>(0, h), unused) -
                        shape->distance(x - cs - Vec<2>(0, h), unused)) /
                           (2 * h));
        if (std::fabs(g.norm() - 1) < 1e-6) {
            EXPECT_LT((g - n).norm(), 1e-6) << x.transpose();
        }
        EXPECT_NEAR(n.norm(), 1.0, 1e-14);
    }
}

TEST(SpheropolygonShapeTest, OutlineIsCounterClockwiseAndEnclosesNearlyTheArea) {
    for (const std::string& yaml :
         {std::string("{type: spheropolygon, radius: 0.3, vertices: [[0, 0], [2, 0], [1, 1]]}"),
          std::string("{type: spheropolygon, radius: 0.3, vertices: [[0, 0], [2, 0]]}"),
          std::string("{type: spheropolygon, radius: 0.3, vertices: [[0, 0]]}"),
          std::string("{type: spheropolygon, radius: 0, vertices: [[0, 0], [2, 0], [1, 1]]}")}) {
        const auto shape = make2(yaml);
        std::vector<Vec3> p;
        std::vector<std::vector<int>> cells;
        shape->surface(p, cells);
        double area = 0;
        for (const auto& c : cells)
            area += 0.5 * (p[c[0]][0] * p[c[1]][1] - p[c[1]][0] * p[c[0]][1]);
        EXPECT_GT(area, 0.99 * shape->volume()) << yaml;
        EXPECT_LE(area, shape->volume() * (1 + 1e-14)) << yaml;
        for (const auto& x : p) { // every outline point lies on φ = 0
            Vec<2> n;
            EXPECT_NEAR(shape->distance(x.head<2>(), n), 0.0, 1e-14) << yaml;
        }
        std::vector<Vec<2>> probes;
        std::vector<double> radii;
        shape->contactProbes(probes, radii);
        EXPECT_EQ(probes.size(), shape->spheroPolygon()->vertices.size());
        EXPECT_EQ(radii[0], shape->spheroPolygon()->radius);
    }
}

TEST(SpheropolygonShapeTest, BoxAndDiskAreSpheropolygonsIn2D) {
    const auto box = make2("{type: box, halfExtents: [0.5, 0.25]}");
    ASSERT_NE(box->spheroPolygon(), nullptr);
    EXPECT_EQ(box->spheroPolygon()->vertices.size(), 4u);
    EXPECT_EQ(box->spheroPolygon()->radius, 0.0);
    // Same mass properties as the spheropolygon of its corners.
    SpheropolygonShape same(box->spheroPolygon()->vertices, 0.0);
    EXPECT_NEAR(same.volume(), box->volume(), 1e-15);
    EXPECT_NEAR(same.unitInertia()[2], box->unitInertia()[2], 1e-15);
    const auto disk = make2("{type: disk, radius: 0.4}");
    ASSERT_NE(disk->spheroPolygon(), nullptr);
    EXPECT_EQ(disk->spheroPolygon()->vertices.size(), 1u);
    EXPECT_EQ(disk->spheroPolygon()->radius, 0.4);
    EXPECT_EQ(BoxShape<3>(Vec3(1, 1, 1)).spheroPolygon(), nullptr);
    EXPECT_EQ(SphereShape<3>(1.0).spheroPolygon(), nullptr);
}

TEST(SpheropolygonShapeTest, BodyWithoutPositionSitsWhereItsVerticesSay) {
    const RigidBody<2> body(Dictionary::fromString("{shape: {type: spheropolygon, radius: 0.1, "
                                                   "vertices: [[2, 3], [4, 3], [4, 5], [2, 5]]}, "
                                                   "density: 10}",
                                                   "rigidBodies"),
                            "block");
    EXPECT_LT((body.position() - Vec<2>(3, 4)).norm(), 1e-14);
    const RigidBody<2> moved(Dictionary::fromString("{shape: {type: spheropolygon, radius: 0.1, "
                                                    "vertices: [[2, 3], [4, 3], [4, 5], [2, 5]]}, "
                                                    "density: 10, position: [0, 0]}",
                                                    "rigidBodies"),
                             "block");
    EXPECT_LT(moved.position().norm(), 1e-14);
}

TEST(SpheropolygonShapeTest, BadInputIsAClearError) {
    const auto expectError = [](const std::string& yaml, const std::string& what) {
        const std::string e = errorOf2(yaml);
        EXPECT_NE(e.find(what), std::string::npos) << yaml << " -> '" << e << "'";
        EXPECT_NE(e.find("rigidBodies"), std::string::npos) << e; // names the file
    };
    const std::string t = "{type: spheropolygon, ";
    expectError(t + "radius: 0.1, vertices: [[0, 0], [2, 0], [1, 0.2], [1, 2]]}", "not convex");
    expectError(t + "radius: 0.1, vertices: [[0, 0], [1, 2], [2, 0]]}", "clockwise");
    expectError(t + "radius: 0.1, vertices: [[0, 0], [2, 0], [2, 0], [1, 2]]}", "coincide");
    expectError(t + "radius: 0.1, vertices: [[0, 0], [1, 0], [2, 0], [1, 2]]}", "collinear");
    expectError(t + "radius: 0, vertices: [[0, 0], [1, 0], [2, 0]]}", "collinear");
    expectError(t + "radius: 0, vertices: [[0, 0], [1, 0]]}", "radius > 0");
    expectError(t + "radius: 0, vertices: [[0, 0]]}", "radius > 0");
    expectError(t + "radius: -0.1, vertices: [[0, 0], [1, 0], [0, 1]]}", "radius");
    expectError(t + "radius: 0.1, vertices: []}", "at least one vertex");
    expectError(t + "radius: 0.1, vertices: [[0, 0, 1]]}", "vertices");
    expectError(t + "vertices: [[0, 0], [1, 0], [0, 1]]}", "radius");
    expectError(t + "radius: 0.1, vertices: [[0, 0], [1, 0], [0, 1]], size: 2}", "size");
    // A pentagram turns twice: every turn is to the left but it is not convex.
    expectError(t + "radius: 0, vertices: [[1, 0], [-0.809, 0.588], [0.309, -0.951], "
                    "[0.309, 0.951], [-0.809, -0.588]]}",
                "not convex");
    try {
        Shape<3>::create(Dictionary::fromString(
            "{type: spheropolygon, radius: 0.1, vertices: [[0, 0]]}", "rigidBodies"));
        ADD_FAILURE() << "3D spheropolygon accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("2D"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace mpm
