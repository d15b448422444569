// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/Coupling.hpp"

#include "TestSupport.hpp"
#include "levelset/LevelSetFile.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <vector>

namespace mpm {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double H = 0.05; // MPM cell size [m]

template <int dim> Grid<dim> unitGrid() {
    const std::string text = dim == 2 ? "bounds: {min: [0, 0], max: [1, 1]}\ncellSize: 0.05\n"
                                      : "bounds: {min: [0, 0, 0], max: [1, 1, 1]}\n"
                                        "cellSize: 0.05\n";
    return Grid<dim>(Dictionary::fromString(text, "constant/grid"));
}

/// `n` points: half uniform over the grid, half in the body's bounding box grown by 2 r_p,max
/// (many near its surface), with volumes V⁰ ∈ [0.2, 1] (h/2)^dim, so r_p differs per point.
template <int dim>
Particles<dim> randomCloud(const Grid<dim>& g, const RigidBody<dim>& body, int n,
                           std::uint64_t seed) {
    Particles<dim> p;
    p.resize(n);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double reach = body.shape().boundingRadius() + 2 * 0.5 * H;
    for (int i = 0; i < n; ++i) {
        for (int d = 0; d < dim; ++d) {
            const double lo = i % 2 ? std::max(g.lo()[d], body.position()[d] - reach) : g.lo()[d];
            const double hi = i % 2 ? std::min(g.hi()[d], body.position()[d] + reach) : g.hi()[d];
            p.x[i][d] = lo + u(rng) * (hi - lo);
        }
        p.v[i] = Vec<dim>::Zero();
        p.C[i] = p.L[i] = Mat<dim>::Zero();
        p.F[i] = Mat<dim>::Identity();
        p.be[i] = Mat3::Identity();
        p.stress[i] = Mat3::Zero();
        p.volume0[i] = p.volume[i] = (0.2 + 0.8 * u(rng)) * std::pow(0.5 * H, dim);
        p.mass[i] = 1000 * p.volume[i];
        p.plasticStrain[i] = 0;
        p.id[i] = i;
        p.material[i] = 0;
    }
    return p;
}

/// Run the coupling of `body` with a unit linear spring (f = (r_p − φ) n: the force encodes φ)
/// and compare the points in contact and their forces with a search over all points.
template <int dim> void expectBruteForce(const std::string& bodyYaml, int n, std::uint64_t seed) {
    SCOPED_TRACE(bodyYaml);
    const Grid<dim> grid = unitGrid<dim>();
    std::vector<std::unique_ptr<RigidBody<dim>>> bodies;
    bodies.push_back(
        std::make_unique<RigidBody<dim>>(Dictionary::fromString(bodyYaml, "test"), "body"));
    const RigidBody<dim>& body = *bodies[0];
    Particles<dim> p = randomCloud(grid, body, n, seed);

    std::vector<std::unique_ptr<CouplingLaw<dim>>> laws;
    laws.push_back(CouplingLaw<dim>::create(
        Dictionary::fromString("{type: linearSpring, stiffness: 1}", "test"), H));
    Coupling<dim> coupling(std::move(laws));
    coupling.setParticles(p);
    BlockSort<dim> sort;
    ASSERT_EQ(sort.update(p, grid), -1);
    coupling.declareState(p, bodies);
    bodies[0]->clearForces();
    coupling.computeForces(p, bodies, {340.0}, {0.0}, sort, grid, 1e-4);

    // Brute force: every point, φ < r_p.
    std::map<Index, Vec<dim>> expected;
    Vec<dim> total = Vec<dim>::Zero();
    for (Index i = 0; i < static_cast<Index>(p.size()); ++i) {
        Vec<dim> normal;
        const double phi = body.distance(p.x[i], normal);
        const double rp = Coupling<dim>::radius(p.volume0[i]);
        if (phi < rp) {
            expected[i] = (rp - phi) * normal;
            total -= expected[i];
        }
    }
    ASSERT_GT(expected.size(), 50u) << "the cloud should put many points in contact";
    ASSERT_LT(expected.size(), p.size() / 2) << "and many out of it";

    EXPECT_EQ(coupling.numContacts(), static_cast<Index>(expected.size()));
    ASSERT_EQ(coupling.gridPoints().size(), coupling.gridForces().size());
    std::map<Index, Vec<dim>> found;
    for (std::size_t k = 0; k < coupling.gridPoints().size(); ++k)
        EXPECT_TRUE(found.emplace(coupling.gridPoints()[k], coupling.gridForces()[k]).second)
            << "point " << coupling.gridPoints()[k] << " found twice";
    for (const auto& [i, f] : expected) {
        const auto it = found.find(i);
        if (it == found.end()) {
            Vec<dim> normal;
            ADD_FAILURE() << "point " << i << " at (" << p.x[i].transpose() << "), phi "
                          << body.distance(p.x[i], normal) << " < r_p "
                          << Coupling<dim>::radius(p.volume0[i]) << " missed by the broad phase";
            continue;
        }
        EXPECT_LE((it->second - f).norm(), 1e-12 * (1 + f.norm())) << "point " << i;
    }
    for (const auto& [i, f] : found)
        EXPECT_TRUE(expected.count(i)) << "point " << i << " is not within r_p";
    EXPECT_LE((body.force() - total).norm(), 1e-9 * (1 + total.norm()));
}

/// A torus of radii (ring, tube) about the z axis sampled on a grid of spacing `h`, with its
/// mass properties (density 1): non-convex, and its distance is a sampled field.
levelset::LevelSet torusLevelSet(double ring, double tube, double h) {
    levelset::LevelSet ls;
    const double half = ring + tube + 3 * h;
    const int m = static_cast<int>(std::lround(2 * half / h)) + 1;
    ls.grid.origin = Vec3::Constant(-half);
    ls.grid.spacing = h;
    ls.grid.dims = {m, m, m};
    ls.grid.values.resize(ls.grid.numPoints());
    for (int k = 0; k < m; ++k)
        for (int j = 0; j < m; ++j)
            for (int i = 0; i < m; ++i) {
                const Vec3 x = ls.grid.point(i, j, k);
                ls.grid.values[ls.grid.index(i, j, k)] =
                    std::hypot(std::hypot(x[0], x[1]) - ring, x[2]) - tube;
            }
    ls.volume = 2 * pi * pi * ring * tube * tube;
    ls.principalMoments =
        ls.volume * Vec3(ring * ring / 2 + 5 * tube * tube / 8,
                         ring * ring / 2 + 5 * tube * tube / 8, ring * ring + 3 * tube * tube / 4);
    return ls;
}

TEST(CouplingBroadPhase, SphereMatchesBruteForce2D) {
    expectBruteForce<2>("shape: {type: disk, radius: 0.17}\ndensity: 1\nposition: [0.52, 0.47]\n",
                        20000, 1);
    // Partly outside the grid: the visited blocks are clipped to it.
    expectBruteForce<2>("shape: {type: disk, radius: 0.2}\ndensity: 1\nposition: [0.03, 0.96]\n",
                        20000, 2);
}

TEST(CouplingBroadPhase, BoxMatchesBruteForce2D) {
    expectBruteForce<2>("shape: {type: box, size: [0.5, 0.12]}\ndensity: 1\n"
                        "position: [0.5, 0.41]\norientation: 27\n",
                        20000, 3);
    expectBruteForce<2>("shape: {type: box, size: [0.3, 0.3]}\ndensity: 1\n"
                        "position: [0.9, 0.1]\norientation: -40\n",
                        20000, 4);
}

TEST(CouplingBroadPhase, SphereMatchesBruteForce3D) {
    expectBruteForce<3>("shape: {type: sphere, radius: 0.16}\ndensity: 1\n"
                        "position: [0.48, 0.51, 0.55]\n",
                        40000, 5);
    expectBruteForce<3>("shape: {type: sphere, radius: 0.2}\ndensity: 1\n"
                        "position: [0.97, 0.02, 0.5]\n",
                        40000, 6);
}

TEST(CouplingBroadPhase, BoxMatchesBruteForce3D) {
    expectBruteForce<3>("shape: {type: box, size: [0.5, 0.1, 0.3]}\ndensity: 1\n"
                        "position: [0.5, 0.45, 0.52]\n"
                        "orientation: {axis: [1, 2, 3], angle: 35}\n",
                        40000, 7);
}

TEST(CouplingBroadPhase, LevelSetMatchesBruteForce3D) {
    test::TempDir tmp;
    const auto file = tmp / "torus.vti";
    levelset::writeVti(file, torusLevelSet(0.15, 0.05, 0.01));
    expectBruteForce<3>("shape: {type: levelSet, file: " + file.string() +
                            "}\ndensity: 1\nposition: [0.5, 0.47, 0.52]\n"
                            "orientation: {axis: [1, 1, 0], angle: 40}\n",
                        40000, 8);
    // Close to a grid corner: part of the level-set grid lies outside the MPM grid.
    expectBruteForce<3>("shape: {type: levelSet, file: " + file.string() +
                            "}\ndensity: 1\nposition: [0.1, 0.9, 0.08]\n"
                            "orientation: {axis: [0, 1, 0], angle: 70}\n",
                        40000, 9);
}

} // namespace
} // namespace mpm
