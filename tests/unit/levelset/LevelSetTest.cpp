// SPDX-License-Identifier: GPL-3.0-or-later
#include "TestMeshes.hpp"
#include "TestSupport.hpp"
#include "core/Constants.hpp"

#include "levelset/LevelSetFile.hpp"
#include "levelset/MassProperties.hpp"
#include "levelset/SignedDistance.hpp"
#include "levelset/TriangleMesh.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace {

using namespace mpm;
using namespace mpm::levelset;
using namespace mpm::levelset::test;
namespace fs = std::filesystem;

/// Uniform random points in the shell r0 ≤ |x| ≤ r1 (fixed seed).
std::vector<Vec3> shellPoints(double r0, double r1, int n, unsigned seed) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> u(r0, r1);
    std::vector<Vec3> p;
    for (int i = 0; i < n; ++i)
        p.push_back(Vec3(g(rng), g(rng), g(rng)).normalized() * u(rng));
    return p;
}

TEST(SignedDistance, sphereInsideAndOutside) {
    const double r = 0.7;
    const TriangleMesh mesh = icosphere(r, 4);
    const double sag = sagitta(mesh, r);
    ASSERT_LT(sag, 5e-3);
    const SignedDistance sdf(mesh);
    EXPECT_NEAR(sdf.windingNumberExact(Vec3::Zero()), 1.0, 1e-9);
    for (const Vec3& x : shellPoints(0.0, 2.0 * r, 400, 1)) {
        const double exact = x.norm() - r;
        // The polyhedron lies between the spheres of radii r − sag and r.
        EXPECT_LE(sdf.signedDistance(x), exact + sag + 1e-12) << x.transpose();
        EXPECT_GE(sdf.signedDistance(x), exact - 1e-12) << x.transpose();
    }
}

TEST(SignedDistance, boxMatchesExactSdf) {
    const Vec3 h(0.5, 0.3, 0.2);
    const SignedDistance sdf(box(h));
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 1000; ++i) {
        const Vec3 x(u(rng), u(rng), u(rng));
        EXPECT_NEAR(sdf.signedDistance(x), boxSdf(x, h), 1e-12) << x.transpose();
    }
}

TEST(SignedDistance, hierarchicalWindingNumberIsClose) {
    const SignedDistance sdf(icosphere(1.0, 3));
    for (const Vec3& x : shellPoints(0.0, 3.0, 300, 3)) {
        // First-order far field with β = 2: a few per cent, far from the ½ threshold.
        EXPECT_NEAR(sdf.windingNumber(x), sdf.windingNumberExact(x), 0.06) << x.transpose();
    }
}

TEST(SignedDistance, signWithHoleAndFlippedTriangles) {
    const double r = 1.0;
    TriangleMesh holed = icosphere(r, 3);
    holed.triangles.erase(holed.triangles.begin() + 17);
    EXPECT_GT(diagnose(holed).boundaryEdges, 0U);
    TriangleMesh flipped = icosphere(r, 3);
    for (std::size_t t = 0; t < flipped.triangles.size(); t += 7) {
        std::swap(flipped.triangles[t][1], flipped.triangles[t][2]);
    }
    for (const TriangleMesh* mesh : {&holed, &flipped}) {
        const SignedDistance sdf(*mesh);
        for (const Vec3& x : shellPoints(0.0, 0.85 * r, 200, 4)) {
            EXPECT_LT(sdf.signedDistance(x), 0.0) << x.transpose();
        }
        for (const Vec3& x : shellPoints(1.1 * r, 2.0 * r, 200, 5)) {
            EXPECT_GT(sdf.signedDistance(x), 0.0) << x.transpose();
        }
    }
}

TEST(SignedDistance, gridMatchesPointwiseEvaluation) {
    const TriangleMesh mesh = icosphere(1.0, 3);
    const SignedDistance sdf(mesh);
    RegularGrid grid;
    grid.origin = Vec3(-1.3, -1.25, -1.2);
    grid.spacing = 0.1;
    grid.dims = {27, 26, 25};
    sdf.evaluate(grid);
    ASSERT_EQ(grid.values.size(), grid.numPoints());
    for (int k = 0; k < grid.dims[2]; ++k) {
        for (int j = 0; j < grid.dims[1]; ++j) {
            for (int i = 0; i < grid.dims[0]; ++i) {
                const Vec3 x = grid.point(i, j, k);
                const double d = sdf.unsignedDistance(x);
                const double w = sdf.windingNumberExact(x);
                EXPECT_NEAR(grid.values[grid.index(i, j, k)], std::abs(w) > 0.5 ? -d : d, 1e-12);
            }
        }
    }
}

/// A non-convex, star-shaped body: icosphere vertices at radius 1 + 0.25 sin(3x) cos(2y).
TriangleMesh bumpySphere() {
    TriangleMesh mesh = icosphere(1.0, 3);
    for (Vec3& v : mesh.vertices)
        v *= 1.0 + 0.25 * std::sin(3.0 * v.x()) * std::cos(2.0 * v.y());
    return mesh;
}

/// Exact signed distance: BVH distance and exact winding number at every node.
std::vector<double> bruteForce(const SignedDistance& sdf, const RegularGrid& grid) {
    std::vector<double> v(grid.numPoints());
    for (int k = 0; k < grid.dims[2]; ++k)
        for (int j = 0; j < grid.dims[1]; ++j)
            for (int i = 0; i < grid.dims[0]; ++i) {
                const Vec3 x = grid.point(i, j, k);
                const double d = sdf.unsignedDistance(x);
                v[grid.index(i, j, k)] = std::abs(sdf.windingNumberExact(x)) > 0.5 ? -d : d;
            }
    return v;
}

TEST(SignedDistance, fastGridMatchesBruteForce) {
    const TriangleMesh mesh = bumpySphere();
    const SignedDistance sdf(mesh);
    RegularGrid grid;
    grid.origin = Vec3(-1.45, -1.4, -1.35);
    grid.spacing = 0.05;
    grid.dims = {58, 57, 55};
    sdf.evaluate(grid);
    const std::vector<double> ref = bruteForce(sdf, grid);
    const double band = SignedDistance::bandWidth * grid.spacing;
    double maxBand = 0.0, maxFar = 0.0;
    std::size_t nBand = 0, nFar = 0, nInexact = 0;
    for (std::size_t n = 0; n < ref.size(); ++n) {
        const double err = std::abs(grid.values[n] - ref[n]);
        ASSERT_EQ(grid.values[n] < 0.0, ref[n] < 0.0) << n; // sign everywhere
        // Outside the band the propagated distance is an upper bound.
        EXPECT_GE(std::abs(grid.values[n]), std::abs(ref[n])) << n;
        if (std::abs(ref[n]) <= band) {
            maxBand = std::max(maxBand, err);
            ++nBand;
        } else {
            maxFar = std::max(maxFar, err / std::abs(ref[n]));
            ++nFar;
            nInexact += err > 0.0 ? 1 : 0;
        }
    }
    EXPECT_GT(nBand, 10000U);
    EXPECT_GT(nFar, 10000U);
    EXPECT_LE(maxBand, 1e-12);
    EXPECT_LE(maxFar, 1e-2); // relative, outside the band
    std::cout << "band nodes " << nBand << " max error " << maxBand << "; far nodes " << nFar
              << " inexact " << nInexact << " max relative error " << maxFar << '\n';
}

/// Faces exactly halfway between grid nodes (the case a helper found: a 0.4 m cube on a grid
/// with h = 8 mm starting at −0.284 m): d_i + d_{i+1} = h there, and the sign must still flip.
TEST(SignedDistance, facesHalfwayBetweenNodes) {
    const Vec3 half(0.2, 0.2, 0.2);
    const SignedDistance sdf(box(half));
    RegularGrid grid;
    grid.origin = Vec3::Constant(-0.284);
    grid.spacing = 0.008;
    grid.dims = {72, 72, 72};
    for (int exact = 0; exact < 2; ++exact) {
        exact ? sdf.evaluateExact(grid) : sdf.evaluate(grid);
        std::size_t wrong = 0;
        for (int k = 0; k < 72; ++k)
            for (int j = 0; j < 72; ++j)
                for (int i = 0; i < 72; ++i)
                    wrong += (grid.values[grid.index(i, j, k)] < 0.0) !=
                             (boxSdf(grid.point(i, j, k), half) < 0.0);
        EXPECT_EQ(wrong, 0U) << (exact ? "evaluateExact" : "evaluate");
    }
}

TEST(SignedDistance, fastGridIsIndependentOfThreads) {
#ifdef _OPENMP
    const SignedDistance sdf(bumpySphere());
    RegularGrid g1, g2;
    g1.origin = g2.origin = Vec3(-1.5, -1.4, -1.3);
    g1.spacing = g2.spacing = 0.04;
    g1.dims = g2.dims = {75, 70, 66};
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    sdf.evaluate(g1);
    omp_set_num_threads(2);
    sdf.evaluate(g2);
    omp_set_num_threads(threads);
    ASSERT_EQ(g1.values.size(), g2.values.size());
    EXPECT_EQ(std::memcmp(g1.values.data(), g2.values.data(), g1.values.size() * sizeof(double)),
              0);
#else
    GTEST_SKIP() << "built without OpenMP";
#endif
}

TEST(SignedDistance, fastGridFarFromTheSurface) {
    // The grid does not meet the band of any triangle: exact distance everywhere.
    const Vec3 h(0.5, 0.3, 0.2);
    const SignedDistance sdf(box(h));
    RegularGrid grid;
    grid.origin = Vec3(2.0, -1.0, 0.5);
    grid.spacing = 0.1;
    grid.dims = {10, 12, 9};
    sdf.evaluate(grid);
    for (int k = 0; k < grid.dims[2]; ++k)
        for (int j = 0; j < grid.dims[1]; ++j)
            for (int i = 0; i < grid.dims[0]; ++i)
                EXPECT_NEAR(grid.values[grid.index(i, j, k)], boxSdf(grid.point(i, j, k), h),
                            1e-12);
}

TEST(MassProperties, rotatedBox) {
    const double a = 2.0, b = 1.0, c = 0.5;
    TriangleMesh mesh = box(Vec3(a / 2, b / 2, c / 2));
    const Mat3 R = Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    const Vec3 shift(10.0, -3.0, 2.0);
    for (Vec3& v : mesh.vertices)
        v = R * v + shift;
    const MassProperties mp = computeMassProperties(mesh);
    const double m = a * b * c;
    EXPECT_NEAR(mp.volume, m, 1e-12);
    EXPECT_NEAR((mp.centroid - shift).norm(), 0.0, 1e-12);
    const Mat3 body =
        Vec3(m / 12 * (b * b + c * c), m / 12 * (a * a + c * c), m / 12 * (a * a + b * b))
            .asDiagonal();
    EXPECT_NEAR((mp.inertia - R * body * R.transpose()).norm(), 0.0, 1e-12);
    EXPECT_NEAR(mp.principalMoments[0], m / 12 * (b * b + c * c), 1e-12);
    EXPECT_NEAR(mp.principalMoments[1], m / 12 * (a * a + c * c), 1e-12);
    EXPECT_NEAR(mp.principalMoments[2], m / 12 * (a * a + b * b), 1e-12);
    EXPECT_NEAR(mp.rotation.determinant(), 1.0, 1e-12);
    const Mat3 D = mp.rotation.transpose() * mp.inertia * mp.rotation;
    EXPECT_NEAR((D - Mat3(mp.principalMoments.asDiagonal())).norm(), 0.0, 1e-12);
    // Principal axis of the smallest moment is the box's long edge.
    EXPECT_NEAR(std::abs(mp.rotation.col(0).dot(R.col(0))), 1.0, 1e-12);

    // Inside-out winding gives the same result.
    for (auto& t : mesh.triangles)
        std::swap(t[1], t[2]);
    EXPECT_NEAR(computeMassProperties(mesh).volume, m, 1e-12);
}

TEST(MassProperties, icosphere) {
    const double r = 0.3;
    const TriangleMesh mesh = icosphere(r, 5);
    const double rel = sagitta(mesh, r) / r; // volume error ≈ 3 sag/r
    const MassProperties mp = computeMassProperties(mesh);
    const double v = 4.0 / 3.0 * pi * r * r * r;
    EXPECT_NEAR(mp.volume / v, 1.0, 3.0 * rel);
    EXPECT_LT(mp.volume, v);
    EXPECT_NEAR(mp.centroid.norm(), 0.0, 1e-12);
    for (int d = 0; d < 3; ++d) {
        EXPECT_NEAR(mp.principalMoments[d] / (0.4 * v * r * r), 1.0, 5.0 * rel);
    }
}

TEST(MassProperties, flatSurfaceThrows) {
    TriangleMesh mesh;
    mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
    mesh.triangles = {{0, 1, 2}};
    EXPECT_THROW(computeMassProperties(mesh), std::runtime_error);
}

/// A fresh folder per test, removed afterwards.
using LevelSetFiles = mpm::test::TempDirTest;

TEST_F(LevelSetFiles, vtiRoundTrip) {
    LevelSet ls;
    ls.grid.origin = Vec3(-0.1, 0.2, -0.3);
    ls.grid.spacing = 0.05;
    ls.grid.dims = {4, 3, 5};
    for (std::size_t i = 0; i < ls.grid.numPoints(); ++i) {
        ls.grid.values.push_back(0.1 * std::sin(static_cast<double>(i)));
    }
    ls.volume = 1.25;
    ls.centroid = Vec3(1, 2, 3);
    ls.principalMoments = Vec3(0.1, 0.2, 0.3);
    ls.rotation = Eigen::AngleAxisd(0.3, Vec3(0, 1, 1).normalized()).toRotationMatrix();
    for (const bool dbl : {true, false}) {
        const fs::path file = dir_ / (dbl ? "d.vti" : "f.vti");
        writeVti(file, ls, dbl);
        const LevelSet in = readVti(file);
        EXPECT_EQ(in.grid.dims, ls.grid.dims);
        EXPECT_NEAR((in.grid.origin - ls.grid.origin).norm(), 0.0, 1e-15);
        EXPECT_DOUBLE_EQ(in.grid.spacing, ls.grid.spacing);
        ASSERT_EQ(in.grid.values.size(), ls.grid.values.size());
        for (std::size_t i = 0; i < in.grid.values.size(); ++i) {
            EXPECT_NEAR(in.grid.values[i], ls.grid.values[i], dbl ? 0.0 : 1e-8);
        }
        EXPECT_EQ(in.volume, ls.volume);
        EXPECT_EQ(in.centroid, ls.centroid);
        EXPECT_EQ(in.principalMoments, ls.principalMoments);
        EXPECT_EQ(in.rotation, ls.rotation);
    }
    EXPECT_THROW(readVti(dir_ / "missing.vti"), std::runtime_error);
    std::ofstream(dir_ / "bad.vti") << "not xml";
    EXPECT_THROW(readVti(dir_ / "bad.vti"), std::runtime_error);
}

TEST_F(LevelSetFiles, readStlAndObj) {
    {
        std::ofstream stl(dir_ / "box.stl");
        const TriangleMesh b = box(Vec3(1, 2, 3));
        stl << "solid box\n";
        for (std::size_t t = 0; t < b.numTriangles(); ++t) {
            stl << "facet normal 0 0 0\nouter loop\n";
            for (int k = 0; k < 3; ++k) {
                const Vec3 v = b.vertex(t, k);
                stl << "vertex " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
            }
            stl << "endloop\nendfacet\n";
        }
        stl << "endsolid box\n";
        std::ofstream obj(dir_ / "box.obj");
        for (const Vec3& v : b.vertices)
            obj << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
        for (std::size_t t = 0; t + 1 < b.numTriangles(); ++t) { // one triangle missing
            obj << "f " << b.triangles[t][0] + 1 << ' ' << b.triangles[t][1] + 1 << ' '
                << b.triangles[t][2] + 1 << '\n';
        }
    }
    const TriangleMesh stl = readTriangleMesh(dir_ / "box.stl", 0.5);
    EXPECT_EQ(stl.numTriangles(), 12U);
    EXPECT_EQ(stl.vertices.size(), 8U);
    EXPECT_TRUE(diagnose(stl).clean());
    EXPECT_NEAR(computeMassProperties(stl).volume, 6.0, 1e-12); // (1·2·3 · 8) · 0.5³
    const TriangleMesh obj = readTriangleMesh(dir_ / "box.obj");
    EXPECT_EQ(obj.numTriangles(), 11U);
    EXPECT_EQ(diagnose(obj).boundaryEdges, 3U);

    std::ofstream(dir_ / "empty.stl").flush();
    EXPECT_THROW(readTriangleMesh(dir_ / "empty.stl"), std::runtime_error);
    EXPECT_THROW(readTriangleMesh(dir_ / "missing.stl"), std::runtime_error);
}

/// Triangles wound against their neighbours (and a whole mesh wound inward) are found and
/// turned outward: the mass properties then equal those of the clean mesh.
TEST(TriangleMesh, orientOutward) {
    const TriangleMesh clean = icosphere(1.0, 2);
    TriangleMesh mixed = clean;
    for (std::size_t t = 0; t < mixed.triangles.size(); t += 5)
        std::swap(mixed.triangles[t][1], mixed.triangles[t][2]);
    EXPECT_GT(diagnose(mixed).inconsistentEdges, 0U);
    EXPECT_EQ(orientOutward(mixed), (clean.triangles.size() + 4) / 5);
    EXPECT_EQ(diagnose(mixed).inconsistentEdges, 0U);
    EXPECT_EQ(mixed.triangles, clean.triangles);

    TriangleMesh inward = clean;
    for (auto& tri : inward.triangles)
        std::swap(tri[1], tri[2]);
    EXPECT_EQ(diagnose(inward).inconsistentEdges, 0U); // consistent, but inward
    EXPECT_EQ(orientOutward(inward), clean.triangles.size());
    EXPECT_NEAR(computeMassProperties(inward).volume, computeMassProperties(clean).volume, 1e-12);
    TriangleMesh same = clean;
    EXPECT_EQ(orientOutward(same), 0U);
}

TEST(TriangleMesh, diagnostics) {
    TriangleMesh m = box(Vec3(1, 1, 1));
    EXPECT_TRUE(diagnose(m).clean());
    m.triangles.push_back({0, 1, 2}); // third triangle on edge 0–1 and 1–2: non-manifold
    m.vertices.push_back(Vec3(2, 2, 2));
    m.triangles.push_back({7, 8, 8}); // degenerate
    const MeshDiagnostics d = diagnose(m);
    EXPECT_GE(d.nonManifoldEdges, 2U);
    EXPECT_EQ(d.degenerateTriangles, 1U);
}

} // namespace
