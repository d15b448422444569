// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/Coupling.hpp"
#include "core/Constants.hpp"

#include "TestSupport.hpp"
#include "levelset/LevelSetFile.hpp"
#include "transfers/PhaseDensity.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace mpm {
namespace {

constexpr double H = 0.05; // MPM cell size [m]

template <int dim> Grid<dim> unitGrid() {
    const std::string text = dim == 2 ? "bounds: {min: [0, 0], max: [1, 1]}\ncellSize: 0.05\n"
                                      : "bounds: {min: [0, 0, 0], max: [1, 1, 1]}\n"
                                        "cellSize: 0.05\n";
    return Grid<dim>(Dictionary::fromString(text, "constant/grid"));
}

/// `n` points: half uniform over the grid, half in the body's bounding box grown by 2 r_p,max
/// (many near its surface), with volumes V⁰ ∈ [0.2, 1] (h/2)^dim, so r_p differs per point.
/// With `lattice`, the second half is drawn around the body without clipping and wrapped into
/// the box (points near the body's periodic images).
template <int dim>
Particles<dim> randomCloud(const Grid<dim>& g, const RigidBody<dim>& body, int n,
                           std::uint64_t seed, const PeriodicLattice<dim>* lattice = nullptr) {
    Particles<dim> p;
    p.resize(n);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double reach = body.shape().boundingRadius() + 2 * 0.5 * H;
    for (int i = 0; i < n; ++i) {
        for (int d = 0; d < dim; ++d) {
            const bool open = lattice && lattice->periodic(d);
            const double lo = i % 2 ? (open ? body.position()[d] - reach
                                            : std::max(g.lo()[d], body.position()[d] - reach))
                                    : g.lo()[d];
            const double hi = i % 2 ? (open ? body.position()[d] + reach
                                            : std::min(g.hi()[d], body.position()[d] + reach))
                                    : g.hi()[d];
            p.x[i][d] = lo + u(rng) * (hi - lo);
        }
        if (lattice) p.x[i] = lattice->wrapPosition(p.x[i]);
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

/// The bodies of a test: one, from its YAML.
template <int dim>
std::vector<std::unique_ptr<RigidBody<dim>>> oneBody(const std::string& yaml,
                                                     const std::string& name = "body") {
    std::vector<std::unique_ptr<RigidBody<dim>>> bodies;
    bodies.push_back(std::make_unique<RigidBody<dim>>(Dictionary::fromString(yaml, "test"), name));
    return bodies;
}

/// One coupling step of `bodies` with the law `lawYaml` on the points p (all of them gasified
/// by the trans-phase relation when `gasified`): the coupling after computeForces.
template <int dim>
std::unique_ptr<Coupling<dim>> coupleOnce(const std::string& lawYaml, Particles<dim>& p,
                                          std::vector<std::unique_ptr<RigidBody<dim>>>& bodies,
                                          const Grid<dim>& grid, const PeriodicLattice<dim>* images,
                                          bool gasified = false) {
    std::vector<std::unique_ptr<CouplingLaw<dim>>> laws;
    laws.push_back(CouplingLaw<dim>::create(Dictionary::fromString(lawYaml, "test"), H));
    auto coupling = std::make_unique<Coupling<dim>>(std::move(laws), images);
    coupling->setParticles(p);
    BlockSort<dim> sort;
    EXPECT_EQ(sort.update(p, grid), -1);
    coupling->declareState(p, bodies);
    bodies[0]->clearForces();
    const std::vector<int> gas(p.size(), 1);
    coupling->computeForces(p, bodies, {340.0}, gasified ? &gas : nullptr, sort, grid, 1e-4);
    return coupling;
}

/// Torque of force f at lever arm r (2D: component 2).
template <int dim> Vec3 torqueOf(const Vec<dim>& r, const Vec<dim>& f) {
    if constexpr (dim == 2)
        return Vec3(0, 0, r[0] * f[1] - r[1] * f[0]);
    else
        return r.cross(f);
}

/// Run the coupling of `body` with a unit linear spring (f = (r_p − φ) n: the force encodes φ)
/// and compare the points in contact, their forces and the body's force and torque with a
/// search over all points. `periodic`: the grid's periodic axes; the brute force then takes
/// every point at its image nearest the body's centre (the minimum image).
template <int dim>
void expectBruteForce(const std::string& bodyYaml, int n, std::uint64_t seed,
                      const std::array<bool, dim>& periodic = {}) {
    SCOPED_TRACE(bodyYaml);
    const Grid<dim> grid = unitGrid<dim>();
    const PeriodicLattice<dim> lattice(grid, periodic);
    const PeriodicLattice<dim>* images = lattice.any() ? &lattice : nullptr;
    auto bodies = oneBody<dim>(bodyYaml);
    const RigidBody<dim>& body = *bodies[0];
    Particles<dim> p = randomCloud(grid, body, n, seed, images);

    std::vector<std::unique_ptr<CouplingLaw<dim>>> laws;
    laws.push_back(CouplingLaw<dim>::create(
        Dictionary::fromString("{type: linearSpring, stiffness: 1}", "test"), H));
    Coupling<dim> coupling(std::move(laws), images);
    coupling.setParticles(p);
    BlockSort<dim> sort;
    ASSERT_EQ(sort.update(p, grid), -1);
    coupling.declareState(p, bodies);
    bodies[0]->clearForces();
    coupling.computeForces(p, bodies, {340.0}, nullptr, sort, grid, 1e-4);

    // Brute force: every point, φ < r_p.
    std::map<Index, Vec<dim>> expected;
    Vec<dim> total = Vec<dim>::Zero();
    Vec3 torque = Vec3::Zero();
    Index acrossSeam = 0;
    for (Index i = 0; i < static_cast<Index>(p.size()); ++i) {
        Vec<dim> normal;
        const Vec<dim> x = lattice.imageNear(p.x[i], body.position());
        const double phi = body.distance(x, normal);
        const double rp = Coupling<dim>::radius(p.volume0[i]);
        if (phi < rp) {
            expected[i] = (rp - phi) * normal;
            total -= expected[i];
            torque += torqueOf<dim>(x - body.position(), -expected[i]);
            acrossSeam += x != p.x[i];
        }
    }
    if (images) {
        EXPECT_GT(acrossSeam, 20) << "many points should touch the body through the seam";
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
    EXPECT_LE((body.torque() - torque).norm(), 1e-9 * (1 + torque.norm()));
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

TEST(Coupling, GasifiedPointsTakeTheirForceLocallyOrThroughTheGrid) {
    // Every point gasified: with `gasifiedPoints: local` ([000 Eq. 20]) no force goes to the
    // grid and each point's velocity gets Δt f/m; with `grid` (default) the same forces go to
    // the grid and the velocities are left alone.
    const Grid<2> grid = unitGrid<2>();
    for (const std::string& mode : {std::string(), std::string(", gasifiedPoints: local"),
                                    std::string(", gasifiedPoints: grid")}) {
        SCOPED_TRACE(mode);
        auto bodies = oneBody<2>("shape: {type: disk, radius: 0.17}\ndensity: 1\n"
                                 "position: [0.52, 0.47]\n");
        Particles<2> p = randomCloud<2>(grid, *bodies[0], 2000, 3, nullptr);
        const auto c = coupleOnce<2>("{type: linearSpring, stiffness: 1" + mode + "}", p, bodies,
                                     grid, nullptr, true);
        const Coupling<2>& coupling = *c;
        ASSERT_GT(coupling.numContacts(), 50);
        const std::vector<Vec<2>> v0 = p.v;
        coupling.applyLocalForces(p, 1e-4);
        Index moved = 0;
        for (std::size_t i = 0; i < p.size(); ++i)
            moved += p.v[i] != v0[i];
        if (mode.find("local") == std::string::npos) {
            EXPECT_EQ(static_cast<Index>(coupling.gridPoints().size()), coupling.numContacts());
            EXPECT_EQ(moved, 0);
        } else {
            EXPECT_TRUE(coupling.gridPoints().empty());
            EXPECT_EQ(moved, coupling.numContacts());
        }
    }
    const InputError e = test::catchInputError([] {
        CouplingLaw<2>::create(
            Dictionary::fromString("{type: barrier, gasifiedPoints: points}", "test"), H);
    });
    EXPECT_NE(std::string(e.what()).find("gasifiedPoints"), std::string::npos);
}

TEST(Coupling, MarksThePointsNearABodyForTheTransPhaseRelation) {
    // With the trans-phase fields declared, `nearBody` is 1 exactly where φ < r_p + b,
    // b = nearBodyCells h (a search over all points), in 2D and 3D, and absent without them.
    const auto check = [](auto dimTag, const std::string& bodyYaml) {
        constexpr int dim = decltype(dimTag)::value;
        SCOPED_TRACE(bodyYaml);
        const Grid<dim> grid = unitGrid<dim>();
        auto bodies = oneBody<dim>(bodyYaml);
        Particles<dim> p = randomCloud<dim>(grid, *bodies[0], 4000, 5, nullptr);
        const double band = nearBodyCells * H; // 0.3 m
        std::mt19937_64 rng(7);                // every point uniform over [0.05, 0.95]^dim
        std::uniform_real_distribution<double> u(0.05, 0.95);
        for (auto& x : p.x)
            for (int d = 0; d < dim; ++d)
                x[d] = u(rng);
        Particles<dim> none = p;
        transPhaseFields(p);
        const std::string law = "{type: barrier}";
        coupleOnce<dim>(law, p, bodies, grid, nullptr);
        const int* near = nearBodyFlag(p);
        ASSERT_NE(near, nullptr);
        std::vector<std::unique_ptr<CouplingLaw<dim>>> laws;
        laws.push_back(CouplingLaw<dim>::create(Dictionary::fromString(law, "test"), H));
        Index marked = 0, beyond = 0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            Vec<dim> n;
            const double phi = bodies[0]->distance(p.x[i], n);
            const double rp = laws[0]->contactRadius(std::pow(p.volume0[i], 1.0 / dim));
            const bool expected = phi < rp + band;
            EXPECT_EQ(near[i], expected ? 1 : 0) << i << " phi " << phi;
            marked += expected;
            beyond += phi >= rp + band && phi < rp + band + 2 * H;
        }
        EXPECT_GT(marked, 200);
        EXPECT_GT(beyond, 200);
        coupleOnce<dim>(law, none, bodies, grid, nullptr);
        EXPECT_EQ(nearBodyFlag(none), nullptr);
    };
    check(std::integral_constant<int, 2>(),
          "shape: {type: disk, radius: 0.05}\ndensity: 1\nposition: [0.52, 0.47]\n");
    check(std::integral_constant<int, 3>(),
          "shape: {type: sphere, radius: 0.05}\ndensity: 1\nposition: [0.52, 0.47, 0.5]\n");
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

// Periodic faces: a body near a seam meets the points beyond it through its image nearest them
// (the broad phase searches around every image that reaches the box; each point once).
TEST(CouplingBroadPhase, PeriodicImagesMatchBruteForce2D) {
    // Centre just past xMin: points near xMax touch it.
    expectBruteForce<2>("shape: {type: disk, radius: 0.17}\ndensity: 1\nposition: [0.03, 0.47]\n",
                        20000, 11, {true, false});
    // Centre just short of xMax, the other way.
    expectBruteForce<2>("shape: {type: disk, radius: 0.17}\ndensity: 1\nposition: [0.99, 0.5]\n",
                        20000, 12, {true, false});
    // A fixed body far outside the box (fixed bodies are not wrapped): its image at x = 0.7 is
    // two periods away.
    expectBruteForce<2>("shape: {type: disk, radius: 0.17}\ndensity: 1\nmotion: fixed\n"
                        "position: [-1.3, 0.5]\n",
                        20000, 16, {true, false});
    // A box in a corner, periodic both ways: four images.
    expectBruteForce<2>("shape: {type: box, size: [0.4, 0.2]}\ndensity: 1\n"
                        "position: [0.97, 0.04]\norientation: 33\n",
                        20000, 13, {true, true});
}

TEST(CouplingBroadPhase, PeriodicImagesMatchBruteForce3D) {
    expectBruteForce<3>("shape: {type: sphere, radius: 0.2}\ndensity: 1\n"
                        "position: [0.97, 0.02, 0.5]\n",
                        40000, 14, {true, true, true});
    test::TempDir tmp;
    const auto file = tmp / "torus.vti";
    levelset::writeVti(file, torusLevelSet(0.15, 0.05, 0.01));
    expectBruteForce<3>("shape: {type: levelSet, file: " + file.string() +
                            "}\ndensity: 1\nposition: [0.1, 0.5, 0.95]\n"
                            "orientation: {axis: [0, 1, 0], angle: 70}\n",
                        40000, 15, {true, false, true});
}

// Half-period invariance: the same body and cloud shifted by L/2 along the periodic axis give
// the same contacts, forces and torque (to round-off), one of them across the seam.
TEST(CouplingBroadPhase, PeriodicHalfPeriodShiftGivesTheSameForces) {
    const Grid<2> grid = unitGrid<2>();
    const PeriodicLattice<2> lattice(grid, {true, false});
    auto run = [&](double shift, Vec<2>& force, Vec3& torque, Index& contacts) {
        std::vector<std::unique_ptr<RigidBody<2>>> bodies;
        bodies.push_back(std::make_unique<RigidBody<2>>(
            Dictionary::fromString("shape: {type: box, size: [0.3, 0.1]}\ndensity: 1\n"
                                   "position: [0.52, 0.4]\norientation: 20\n"
                                   "angularVelocity: 3\nvelocity: [1, 0]\n",
                                   "test"),
            "body"));
        Particles<2> p = randomCloud(grid, *bodies[0], 20000, 21, &lattice);
        for (std::size_t i = 0; i < p.size(); ++i)
            p.x[i] = lattice.wrapPosition(p.x[i] + Vec<2>(shift, 0));
        bodies[0]->movePositionTo(bodies[0]->position() + Vec<2>(shift, 0));
        const auto coupling =
            coupleOnce<2>("{type: barrier, friction: 0.3}", p, bodies, grid, &lattice);
        force = bodies[0]->force();
        torque = bodies[0]->torque();
        contacts = coupling->numContacts();
    };
    Vec<2> f0, f1;
    Vec3 t0, t1;
    Index n0 = 0, n1 = 0;
    run(0.0, f0, t0, n0);
    run(0.5, f1, t1, n1); // centre at 1.02: beyond xMax, the box straddles the seam
    EXPECT_GT(n0, 50);
    EXPECT_EQ(n0, n1);
    EXPECT_LE((f1 - f0).norm(), 1e-9 * f0.norm());
    EXPECT_LE((t1 - t0).norm(), 1e-9 * t0.norm());
}

TEST(CouplingBroadPhase, PeriodicMovingBodyLargerThanHalfThePeriodIsAnError) {
    const Grid<2> grid = unitGrid<2>();
    const PeriodicLattice<2> lattice(grid, {true, false});
    auto bodies = oneBody<2>("shape: {type: disk, radius: 0.49}\ndensity: 1\n"
                             "position: [0.5, 0.5]\n",
                             "big");
    Particles<2> p = randomCloud(grid, *bodies[0], 200, 3);
    std::vector<std::unique_ptr<CouplingLaw<2>>> laws;
    laws.push_back(CouplingLaw<2>::create(Dictionary::fromString("{type: barrier}", "test"), H));
    Coupling<2> coupling(std::move(laws), &lattice);
    coupling.setParticles(p);
    BlockSort<2> sort;
    ASSERT_EQ(sort.update(p, grid), -1);
    coupling.declareState(p, bodies);
    try {
        coupling.computeForces(p, bodies, {340.0}, nullptr, sort, grid, 1e-4);
        ADD_FAILURE() << "no error";
    } catch (const RunError& e) {
        EXPECT_NE(std::string(e.what()).find("half the period"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace mpm
