// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/LevelSetShape.hpp"
#include "core/Constants.hpp"

#include "core/Error.hpp"
#include "levelset/LevelSetFile.hpp"
#include "rigid/RigidBody.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

namespace mpm {
namespace {

constexpr double radius = 0.3;

namespace fs = std::filesystem;

using test::TempDir;

/// Signed distance of a sphere of `radius` about the origin on the grid [−half, half]³ with
/// spacing h, with the sphere's mass properties.
levelset::LevelSet sphereLevelSet(double h, double half = 0.5) {
    levelset::LevelSet ls;
    const int n = static_cast<int>(std::lround(2.0 * half / h)) + 1;
    ls.grid.origin = Vec3::Constant(-half);
    ls.grid.spacing = h;
    ls.grid.dims = {n, n, n};
    ls.grid.values.resize(ls.grid.numPoints());
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                ls.grid.values[ls.grid.index(i, j, k)] = ls.grid.point(i, j, k).norm() - radius;
    ls.volume = 4.0 / 3.0 * pi * std::pow(radius, 3);
    ls.principalMoments = Vec3::Constant(8.0 / 15.0 * pi * std::pow(radius, 5));
    return ls;
}

std::unique_ptr<Shape<3>> shapeFromFile(const fs::path& file) {
    return Shape<3>::create(
        Dictionary::fromString("{type: levelSet, file: " + file.string() + "}", "test"));
}

/// Largest errors of φ and n against the exact sphere at points with 2h ≤ |x| ≤ 0.45.
std::pair<double, double> sphereErrors(const Shape<3>& s) {
    double ePhi = 0.0, eN = 0.0;
    for (int a = 0; a < 400; ++a) {
        // Deterministic scatter over directions and radii 0.12 … 0.45.
        const double u = std::fmod(a * 0.618033988749895, 1.0);
        const double v = std::fmod(a * 0.414213562373095, 1.0);
        const double r = 0.12 + 0.33 * std::fmod(a * 0.7320508075688772, 1.0);
        const double z = 2.0 * u - 1.0, az = 2.0 * pi * v;
        const Vec3 dir(std::sqrt(1 - z * z) * std::cos(az), std::sqrt(1 - z * z) * std::sin(az), z);
        Vec3 n;
        const double phi = s.distance(r * dir, n);
        ePhi = std::max(ePhi, std::abs(phi - (r - radius)));
        eN = std::max(eN, (n - dir).norm());
    }
    return {ePhi, eN};
}

TEST(LevelSetShape, SphereDistanceAndNormalSecondOrder) {
    TempDir tmp;
    double prevPhi = 0.0, prevN = 0.0;
    for (const double h : {0.04, 0.02}) {
        const fs::path file = tmp / ("sphere" + std::to_string(h) + ".vti");
        levelset::writeVti(file, sphereLevelSet(h), true);
        const auto shape = shapeFromFile(file);
        const auto [ePhi, eN] = sphereErrors(*shape);
        // Smoothing by the quadratic B-spline: φ error ≈ h²/8 ∇²φ = h²/(4|x|) ≤ h²/0.48.
        EXPECT_LT(ePhi, h * h / 0.12) << "h = " << h;
        EXPECT_LT(eN, 10.0 * h * h) << "h = " << h; // measured ≈ 5 h²
        if (prevPhi > 0.0) {
            EXPECT_LT(ePhi, 0.35 * prevPhi) << "φ error should fall ~4× when h halves";
            EXPECT_LT(eN, 0.35 * prevN) << "n error should fall ~4× when h halves";
        }
        prevPhi = ePhi;
        prevN = eN;
    }
}

TEST(LevelSetShape, NormalIsGradient) {
    LevelSetShape s(sphereLevelSet(0.05));
    for (const Vec3& x : {Vec3(0.21, -0.13, 0.05), Vec3(0.01, 0.33, -0.2), Vec3(-0.49, 0.4, 0.1)}) {
        Vec3 n, unused;
        s.distance(x, n);
        Vec3 g;
        const double e = 1e-6;
        for (int d = 0; d < 3; ++d) {
            const Vec3 dx = e * Vec3::Unit(d);
            g[d] = (s.distance(x + dx, unused) - s.distance(x - dx, unused)) / (2 * e);
        }
        EXPECT_LT((n - g.normalized()).norm(), 1e-6) << "at " << x.transpose();
    }
}

TEST(LevelSetShape, LinearFieldExactUpToTheGridBoundary) {
    // φ = a·x − c is reproduced exactly by the B-spline with the linearly extrapolated ghosts.
    levelset::LevelSet ls = sphereLevelSet(0.1);
    const Vec3 a = Vec3(1.0, 2.0, -2.0) / 3.0;
    auto& g = ls.grid;
    for (int k = 0; k < g.dims[2]; ++k)
        for (int j = 0; j < g.dims[1]; ++j)
            for (int i = 0; i < g.dims[0]; ++i)
                g.values[g.index(i, j, k)] = a.dot(g.point(i, j, k)) - 0.1;
    LevelSetShape s(ls);
    for (const Vec3& x : {Vec3(0.5, 0.5, 0.5), Vec3(-0.5, 0.47, -0.03), Vec3(0.03, -0.2, 0.44),
                          Vec3(-0.46, -0.5, 0.5)}) {
        Vec3 n;
        EXPECT_NEAR(s.distance(x, n), a.dot(x) - 0.1, 1e-12) << "at " << x.transpose();
        EXPECT_LT((n - a).norm(), 1e-12) << "at " << x.transpose();
    }
}

TEST(LevelSetShape, OutsideTheGridIsConservative) {
    LevelSetShape s(sphereLevelSet(0.05));
    EXPECT_DOUBLE_EQ(s.gridMax()[0], 0.5);
    for (const Vec3& x :
         {Vec3(2.0, 0.0, 0.0), Vec3(0.6, 0.7, -0.8), Vec3(0.51, 0.1, 0.2), Vec3(-30.0, 4.0, 2.0)}) {
        Vec3 n;
        const double phi = s.distance(x, n);
        EXPECT_GT(phi, 0.0) << "at " << x.transpose();
        // Never below the exact distance (minus the interpolation error at the boundary).
        EXPECT_GT(phi, x.norm() - radius - 1e-3) << "at " << x.transpose();
        EXPECT_NEAR(n.norm(), 1.0, 1e-12);
    }
    // On the x axis the continuation is exact up to the boundary error, with n = e_x.
    Vec3 n;
    EXPECT_NEAR(s.distance(Vec3(2.0, 0.0, 0.0), n), 2.0 - radius, 2e-3);
    EXPECT_LT((n - Vec3::UnitX()).norm(), 1e-12);
    // Continuous across the box face.
    Vec3 unused;
    EXPECT_NEAR(s.distance(Vec3(0.5 + 1e-9, 0.1, 0.2), unused),
                s.distance(Vec3(0.5 - 1e-9, 0.1, 0.2), unused), 1e-8);
}

TEST(LevelSetShape, MassPropertiesAndBoundingRadiusFromTheFile) {
    TempDir tmp;
    const fs::path file = tmp / "sphere.vti";
    levelset::writeVti(file, sphereLevelSet(0.05));
    const auto s = shapeFromFile(file);
    EXPECT_NEAR(s->volume(), 4.0 / 3.0 * pi * std::pow(radius, 3), 1e-6);
    const Vec3 I = s->unitInertia();
    for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(I[d], 8.0 / 15.0 * pi * std::pow(radius, 5), 1e-7);
    EXPECT_NEAR(s->boundingRadius(), 0.5 * std::sqrt(3.0), 1e-6);
}

TEST(LevelSetShape, SurfaceOnTheSphereAndOutward) {
    const double h = 0.05;
    LevelSetShape s(sphereLevelSet(h));
    std::vector<Vec3> points;
    std::vector<std::vector<int>> cells;
    s.surface(points, cells);
    ASSERT_GT(cells.size(), 100u);
    for (const Vec3& p : points)
        EXPECT_LT(std::abs(p.norm() - radius), 0.5 * h) << "at " << p.transpose();
    // Enclosed volume by the divergence theorem: positive (outward) and close to the sphere's.
    double vol = 0.0;
    for (const auto& c : cells) {
        ASSERT_EQ(c.size(), 3u);
        vol += points[c[0]].dot(points[c[1]].cross(points[c[2]])) / 6.0;
    }
    EXPECT_NEAR(vol, 4.0 / 3.0 * pi * std::pow(radius, 3), 0.03 * vol);
    // Closed: every edge is shared by exactly two triangles.
    std::map<std::pair<int, int>, int> edges;
    for (const auto& c : cells)
        for (int e = 0; e < 3; ++e)
            ++edges[std::minmax(c[e], c[(e + 1) % 3])];
    for (const auto& [e, count] : edges)
        EXPECT_EQ(count, 2) << "edge " << e.first << "-" << e.second;
}

TEST(LevelSetShape, Errors) {
    TempDir tmp;
    // Missing file: an InputError at key 'file'.
    try {
        shapeFromFile(tmp / "missing.vti");
        FAIL() << "expected an InputError";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "file");
        EXPECT_NE(std::string(e.what()).find("missing.vti"), std::string::npos) << e.what();
    }
    // Relative path not found from the working directory.
    EXPECT_THROW(Shape<3>::create(Dictionary::fromString(
                     "{type: levelSet, file: constant/levelSets/noSuchBody.vti}", "test")),
                 InputError);
    // A relative path is taken from the current working directory.
    levelset::writeVti(tmp / "rel.vti", sphereLevelSet(0.1));
    {
        const fs::path cwd = fs::current_path();
        fs::current_path(tmp.path());
        EXPECT_NO_THROW(
            Shape<3>::create(Dictionary::fromString("{type: levelSet, file: rel.vti}", "test")));
        fs::current_path(cwd);
    }
    // Unknown key.
    const fs::path file = tmp / "sphere.vti";
    levelset::writeVti(file, sphereLevelSet(0.1));
    EXPECT_THROW(Shape<3>::create(Dictionary::fromString(
                     "{type: levelSet, file: " + file.string() + ", scale: 2}", "test")),
                 InputError);
    // Not a .vti: an InputError at 'file'.
    const fs::path junk = tmp / "junk.vti";
    { std::ofstream(junk) << "not xml"; }
    EXPECT_THROW(shapeFromFile(junk), InputError);
    // 2D: the type is 3D only.
    EXPECT_THROW(Shape<2>::create(Dictionary::fromString(
                     "{type: levelSet, file: " + file.string() + "}", "test")),
                 InputError);
}

/// A levelSet body without `position` sits where its mesh was: centroid at the file's
/// centroid and rotation R = the file's rotation (body → mesh), so a body-frame point maps to
/// the mesh point it came from; `orientation` turns the mesh about its centroid and `position`
/// moves the centroid.
TEST(LevelSetShape, BodyPoseDefaultsToTheMeshPose) {
    TempDir tmp;
    const fs::path file = tmp / "tilted.vti";
    levelset::LevelSet ls = sphereLevelSet(0.1);
    ls.centroid = Vec3(1.0, 2.0, 3.0);
    ls.rotation = Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
    levelset::writeVti(file, ls);
    const std::string shape = "shape: {type: levelSet, file: " + file.string() + "}\ndensity: 1\n";

    const RigidBody<3> atMesh(Dictionary::fromString(shape, "test"), "b");
    EXPECT_LT((atMesh.position() - ls.centroid).norm(), 1e-12);
    EXPECT_LT((atMesh.rotation() - ls.rotation).norm(), 1e-6); // the file stores %.9g

    const RigidBody<3> moved(
        Dictionary::fromString(shape + "position: [0, 0, 1]\n"
                                       "orientation: {axis: [0, 0, 1], angle: 90}\n",
                               "test"),
        "b");
    const Mat3 quarter = Eigen::AngleAxisd(pi / 2, Vec3::UnitZ()).toRotationMatrix();
    EXPECT_EQ(moved.position(), Vec3(0, 0, 1));
    EXPECT_LT((moved.rotation() - quarter * ls.rotation).norm(), 1e-6);
}

} // namespace
} // namespace mpm
