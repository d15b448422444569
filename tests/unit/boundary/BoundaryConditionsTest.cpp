// SPDX-License-Identifier: GPL-3.0-or-later
// Boundary conditions on grid nodes: each condition's velocities and reactions, patches with
// boxes and time windows, input errors, outflow, and bit-identity with the face conditions of
// the grid's legacy syntax.
#include "boundary/BoundaryConditions.hpp"
#include "TestSupport.hpp"
#include "boundary/Velocity.hpp"
#include "core/KeySchema.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace mpm {
namespace {

using test::catchInputError;

Dictionary parse(const std::string& text) {
    return Dictionary::fromString(text, "constant/grid");
}

/// The grid of a box (no boundary entry) and the boundary conditions read with `boundary`.
template <int dim> struct Scene {
    Grid<dim> grid;
    BoundaryConditions<dim> bc;
    Scene(const std::string& box, const std::string& boundary)
        : grid(parse(box)), bc(parse(box + boundary), grid) {
        test::activateAll(grid); // the conditions act on every face node
        bc.selectActive(grid);
    }
};

const std::string box2D = "bounds: {min: [-0.1, 0], max: [0.1, 0.2]}\ncellSize: 0.025\n";

template <int dim> IVec<dim> coordOf(const Grid<dim>& g, Index k) {
    return g.nodeCoord(k);
}

/// Index of the node nearest to x.
template <int dim> Index nodeAt(const Grid<dim>& g, const Vec<dim>& x) {
    IVec<dim> c;
    for (int d = 0; d < dim; ++d)
        c[d] = static_cast<int>(std::lround((x[d] - g.origin()[d]) / g.h()));
    return g.nodeIndex(c);
}

template <int dim> void clearNodes(Grid<dim>& g) {
    std::fill(g.mass.begin(), g.mass.end(), 0.0);
    for (auto* f : {&g.momentum, &g.force, &g.vOld, &g.v})
        std::fill(f->begin(), f->end(), Vec<dim>::Zero());
}

// ---------------------------------------------------------------------------------------------
// One node, every condition

struct NodeCase {
    std::string boundary;
    Vec<2> v;        ///< expected velocity after the condition
    Vec<2> reaction; ///< expected reaction of face yMin
    /// Expected P2G velocity if not v: slip and friction only zero the normal velocity of a
    /// node the update pressed against the wall (here (1.1, −2.9) → (1.1, 0)).
    std::optional<Vec<2>> p2g = std::nullopt;
};

/// One loaded node in the middle of yMin (m = 2 kg, v⁰ = (1, −2), f = (4, 0), g = (0, −10),
/// Δt = 0.1: undamped update (1.2, −3); the velocity handed over is a damped (1.1, −2.9)).
TEST(BoundaryConditions, EveryConditionOnOneNode) {
    const double m = 2, dt = 0.1;
    const Vec<2> before(1.2, -3.0), damped(1.1, -2.9);
    const std::vector<NodeCase> cases{
        {"{yMin: noSlip}", Vec<2>(0, 0), m * before / dt},
        {"{yMin: slip}", Vec<2>(1.1, 0), m * (before - Vec<2>(1.1, 0)) / dt},
        {"{yMin: roller}", Vec<2>(1.1, 0), m * (before - Vec<2>(1.1, 0)) / dt},
        // v_n = 2.9, v_t = 1.1: μ = 0.2 takes 0.58 off v_t, μ = 0.5 all of it.
        {"{yMin: {type: friction, friction: 0.2}}", Vec<2>(1.1 - 0.58, 0),
         m * (before - Vec<2>(0.52, 0)) / dt, Vec<2>(1.1, 0)},
        {"{yMin: {type: friction, friction: 0.5}}", Vec<2>(0, 0), m * before / dt, Vec<2>(1.1, 0)},
        {"{yMin: open}", damped, Vec<2>(0, 0)},
        {"{yMin: {type: velocity, value: [0.5, 0.2]}}", Vec<2>(0.5, 0.2),
         m * (before - Vec<2>(0.5, 0.2)) / dt},
        // Smooth moving wall: (v − w)·n = 2.9 − 1 > 0, so v_y ← w_y; v_x is free.
        {"{yMin: {type: velocity, value: [0.5, -1], slip: yes}}", Vec<2>(1.1, -1),
         m * (before - Vec<2>(1.1, -1)) / dt},
        // … and separating from it (w_y = −3 is faster downwards): untouched.
        {"{yMin: {type: velocity, value: [0.5, -3], slip: yes}}", damped,
         m * (before - damped) / dt},
    };
    for (const NodeCase& c : cases) {
        SCOPED_TRACE(c.boundary);
        Scene<2> s(box2D, "boundary: " + c.boundary + "\n");
        Grid<2>& g = s.grid;
        clearNodes(g);
        const Index i = nodeAt(g, Vec<2>(0.0, -0.025)); // one ghost layer below yMin
        g.mass[i] = m;
        g.vOld[i] = Vec<2>(1, -2);
        g.force[i] = Vec<2>(4, 0);
        g.v[i] = damped;
        BoundaryConditions<2>::Reactions r;
        s.bc.constrainUpdate(g, Vec<2>(0, -10), 0.0, dt, r);
        EXPECT_NEAR((g.v[i] - c.v).norm(), 0, 1e-12) << g.v[i].transpose();
        EXPECT_NEAR((r[2] - c.reaction).norm(), 0, 1e-9) << r[2].transpose();
        for (int f : {0, 1, 3})
            EXPECT_EQ(r[f], Vec<2>::Zero()) << Grid<2>::faceName(f);
        // The P2G velocity: the same rule (unilateral walls: the contact just found), no reaction.
        g.vOld[i] = damped;
        s.bc.constrain(g, g.vOld, 0.0);
        EXPECT_NEAR((g.vOld[i] - c.p2g.value_or(c.v)).norm(), 0, 1e-12);
    }
}

/// Every registered condition (from its schema's example) on yMin of a box periodic along x:
/// the reaction is the momentum the condition took out of the owner nodes, Σ m (v⁻ − v⁺)/Δt
/// with v⁻ the undamped update, and a periodic image, given its owner's state, is constrained
/// as its owner but not counted. A new condition is tested without writing a test.
TEST(BoundaryConditions, EveryRegisteredConditionBooksTheMomentumItTakesOut) {
    const auto* family = ModelCatalogue::find("boundaryConditions");
    ASSERT_NE(family, nullptr);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    const double dt = 0.01;
    const Vec<2> gravity(0.3, -9.81);
    int tested = 0;
    for (const auto& [type, schema] : family->schemas) {
        if (type == "periodic") continue; // a face kind: the x faces here
        SCOPED_TRACE(schema.example);
        Scene<2> s(box2D,
                   "boundary: {xMin: periodic, xMax: periodic, yMin: " + schema.example + "}\n");
        Grid<2>& g = s.grid;
        clearNodes(g);
        const PeriodicLattice<2>& lattice = s.bc.lattice();
        // The owner of every node of yMin's layers, and each owner's state (images copy it).
        std::vector<std::pair<Index, Index>> imageOf; // (image, owner)
        std::vector<Index> owners;
        for (Index k : g.faceNodes(2)) {
            IVec<2> c = g.nodeCoord(k);
            const IVec<2> oc(lattice.ownerCoord(0, c[0]), c[1]);
            const Index o = g.nodeIndex(oc);
            if (o == k)
                owners.push_back(k);
            else
                imageOf.emplace_back(k, o);
        }
        ASSERT_FALSE(owners.empty());
        ASSERT_FALSE(imageOf.empty()) << "no periodic image on yMin";
        for (Index k : owners) {
            g.mass[k] = 1.0 + 0.5 * (u(rng) + 2.0);
            g.vOld[k] = Vec<2>(u(rng), u(rng));
            g.force[k] = Vec<2>(u(rng), u(rng));
            g.v[k] = g.vOld[k] + dt * (g.force[k] / g.mass[k] + gravity) + Vec<2>(0.01, -0.02);
        }
        for (const auto& [k, o] : imageOf) {
            g.mass[k] = g.mass[o];
            g.vOld[k] = g.vOld[o];
            g.force[k] = g.force[o];
            g.v[k] = g.v[o];
        }
        BoundaryConditions<2>::Reactions r;
        s.bc.constrainUpdate(g, gravity, 0.5, dt, r);
        // v⁻ is the undamped update, not the damped velocity handed over (+(0.01, −0.02)).
        Vec<2> expected = Vec<2>::Zero();
        for (Index k : owners)
            expected +=
                g.mass[k] * (g.vOld[k] + dt * (g.force[k] / g.mass[k] + gravity) - g.v[k]) / dt;
        if (type == "open") expected.setZero(); // no condition, no reaction
        EXPECT_LT((r[2] - expected).norm(), 1e-9 * (1.0 + expected.norm()))
            << type << ": " << r[2].transpose() << " against " << expected.transpose();
        for (const auto& [k, o] : imageOf)
            EXPECT_EQ(g.v[k], g.v[o]) << type << ": image " << k << " of " << o;
        for (int f : {0, 1, 3})
            EXPECT_EQ(r[f], Vec<2>::Zero()) << type << " " << Grid<2>::faceName(f);
        ++tested;
    }
    EXPECT_GE(tested, 6);
}

TEST(BoundaryConditions, UnilateralP2GVelocityFollowsTheContactOfTheLastUpdate) {
    // A node on yMin whose P2G velocity enters the wall: slip, friction and a smooth moving wall
    // (w = (0.5, 0.2)) set its normal part to the wall's only if the last update pressed it
    // against the wall, and never touch the tangential part; roller applies its rule whatever
    // the history.
    for (const std::string boundary :
         {"{yMin: slip}", "{yMin: {type: friction, friction: 0.4}}", "{yMin: roller}",
          "{yMin: {type: velocity, value: [0.5, 0.2], slip: yes}}"}) {
        SCOPED_TRACE(boundary);
        const bool unilateral = boundary != "{yMin: roller}";
        const double wallY = boundary.find("velocity") != std::string::npos ? 0.2 : 0.0;
        Scene<2> s(box2D, "boundary: " + boundary + "\n");
        Grid<2>& g = s.grid;
        clearNodes(g);
        const Index i = nodeAt(g, Vec<2>(0.0, -0.025));
        g.mass[i] = 1;
        BoundaryConditions<2>::Reactions r;
        const Vec<2> entering(0.7, -0.4), leaving(0.7, 0.4);
        for (const Vec<2>& updated : {leaving, entering, leaving}) {
            g.v[i] = updated; // the update: contact where it enters the wall
            s.bc.constrainUpdate(g, Vec<2>::Zero(), 0.0, 1e-3, r);
            g.vOld[i] = entering; // the next P2G velocity enters the wall
            s.bc.constrain(g, g.vOld, 0.0);
            const bool pressed = updated == entering;
            EXPECT_EQ(g.vOld[i], unilateral && !pressed ? entering : Vec<2>(0.7, wallY))
                << "after an update " << (pressed ? "into" : "away from") << " the wall";
        }
    }
}

TEST(BoundaryConditions, RollerHoldsANodeLeavingTheWallWhereSlipReleasesIt) {
    // A node on yMin moving away from the wall (v_y > 0) and along it: slip leaves it alone
    // (the material separates), roller removes the normal part (a symmetry plane).
    for (const auto& [boundary, expected] :
         {std::pair<std::string, Vec<2>>{"{yMin: slip}", Vec<2>(0.7, 0.4)},
          std::pair<std::string, Vec<2>>{"{yMin: roller}", Vec<2>(0.7, 0.0)}}) {
        SCOPED_TRACE(boundary);
        Scene<2> s(box2D, "boundary: " + boundary + "\n");
        clearNodes(s.grid);
        const Index i = nodeAt(s.grid, Vec<2>(0.0, -0.025));
        s.grid.mass[i] = 1;
        s.grid.v[i] = Vec<2>(0.7, 0.4);
        s.bc.constrain(s.grid, s.grid.v, 0.0);
        EXPECT_EQ(s.grid.v[i], expected);
    }
}

TEST(BoundaryConditions, VelocityTableIsLinearAndHeldBeyondTheEnds) {
    const Velocity<3> w(
        Dictionary::fromString("{type: velocity, table: [[1, 0, 0, 0], [3, 2, -4, 1], "
                               "[4, 2, 0, 1]]}",
                               "constant/grid"));
    EXPECT_EQ(w.wallVelocity(-5), Vec<3>(0, 0, 0));
    EXPECT_EQ(w.wallVelocity(1), Vec<3>(0, 0, 0));
    EXPECT_NEAR((w.wallVelocity(1.5) - Vec<3>(0.5, -1, 0.25)).norm(), 0, 1e-15);
    EXPECT_NEAR((w.wallVelocity(3.5) - Vec<3>(2, -2, 1)).norm(), 0, 1e-15);
    EXPECT_EQ(w.wallVelocity(4), Vec<3>(2, 0, 1));
    EXPECT_EQ(w.wallVelocity(100), Vec<3>(2, 0, 1));

    // On the nodes: the condition evaluates w at the time it is given.
    Scene<2> s(box2D, "boundary: {yMax: {type: velocity, table: [[0, 0, 0], [1, 2, 0]]}}\n");
    clearNodes(s.grid);
    const Index i = nodeAt(s.grid, Vec<2>(0.05, 0.2));
    s.grid.mass[i] = 1;
    s.bc.constrain(s.grid, s.grid.v, 0.25);
    EXPECT_NEAR((s.grid.v[i] - Vec<2>(0.5, 0)).norm(), 0, 1e-15);
    s.bc.constrain(s.grid, s.grid.v, 7);
    EXPECT_EQ(s.grid.v[i], Vec<2>(2, 0));
}

/// A corner node: the first face acting measures from the undamped update, the next from
/// what is left (here nothing).
TEST(BoundaryConditions, CornerNodeReactionGoesToTheFirstFaceActing) {
    Scene<2> s(box2D, "boundary: {xMin: noSlip, yMin: slip}\n");
    Grid<2>& g = s.grid;
    clearNodes(g);
    const Index i = nodeAt(g, Vec<2>(-0.1, 0.0));
    g.mass[i] = 3;
    g.vOld[i] = Vec<2>(-1, -1);
    g.v[i] = Vec<2>(-1, -1);
    BoundaryConditions<2>::Reactions r;
    s.bc.constrainUpdate(g, Vec<2>::Zero(), 0.0, 0.5, r);
    EXPECT_EQ(g.v[i], Vec<2>::Zero());
    EXPECT_EQ(r[0], Vec<2>(-6, -6));
    EXPECT_EQ(r[2], Vec<2>::Zero());
    // Open on xMin: yMin acts first.
    Scene<2> o(box2D, "boundary: {xMin: open, yMin: slip}\n");
    clearNodes(o.grid);
    o.grid.mass[i] = 3;
    o.grid.vOld[i] = o.grid.v[i] = Vec<2>(-1, -1);
    o.bc.constrainUpdate(o.grid, Vec<2>::Zero(), 0.0, 0.5, r);
    EXPECT_EQ(o.grid.v[i], Vec<2>(-1, 0));
    EXPECT_EQ(r[0], Vec<2>::Zero());
    EXPECT_EQ(r[2], Vec<2>(0, -6));
}

// ---------------------------------------------------------------------------------------------
// The legacy syntax is bit-identical to the grid's face conditions

/// The grid's former per-face condition (one per face, before patches).
struct FaceCondition {
    enum class Kind { NoSlip, Slip, Friction, Open };
    Kind kind = Kind::Slip;
    double friction = 0.0;
};
using Kind = FaceCondition::Kind;

/// The solver's former applyBoundaryConditions on the former face conditions, verbatim but for
/// one change since: on the P2G velocity (recordReactions false) slip and friction zero the
/// normal velocity of the nodes the last update pushed out of the wall (`contact`, bit = axis),
/// instead of applying their rule again.
template <int dim>
void legacyApply(Grid<dim>& grid, const std::vector<FaceCondition>& faces, bool recordReactions,
                 double dt, const Vec<dim>& gravity, std::array<Vec<dim>, 2 * dim>& reactions,
                 std::vector<unsigned char>& contact) {
    NodeArray<Vec<dim>>& vel = recordReactions ? grid.v : grid.vOld;
    std::vector<char> touched(grid.numNodes(), 0);
    for (int f = 0; f < Grid<dim>::NumFaces; ++f) {
        const FaceCondition& fc = faces[f];
        Vec<dim> reaction = Vec<dim>::Zero();
        if (fc.kind != FaceCondition::Kind::Open) {
            const int axis = f / 2;
            const double sign = f % 2 == 0 ? -1.0 : 1.0;
            for (Index i : grid.faceNodes(f)) {
                const double m = grid.mass[i];
                if (m == 0) continue;
                Vec<dim>& v = vel[i];
                Vec<dim> before = v;
                if (recordReactions && !touched[i]) {
                    before = grid.vOld[i] + dt * (grid.force[i] / m + gravity);
                    touched[i] = 1;
                }
                const double vn = sign * v[axis];
                const bool unilateral = fc.kind != FaceCondition::Kind::NoSlip;
                if (unilateral && !recordReactions) {
                    if (contact[i] & (1u << axis)) v[axis] = 0;
                    continue;
                }
                if (unilateral) {
                    if (vn > 0)
                        contact[i] |= 1u << axis;
                    else
                        contact[i] &= ~(1u << axis);
                }
                switch (fc.kind) {
                case FaceCondition::Kind::NoSlip:
                    v.setZero();
                    break;
                case FaceCondition::Kind::Slip:
                    if (vn > 0) v[axis] = 0;
                    break;
                case FaceCondition::Kind::Friction:
                    if (vn > 0) {
                        v[axis] = 0;
                        const double vt = v.norm();
                        const double drop = fc.friction * vn;
                        v *= vt > drop ? (1.0 - drop / vt) : 0.0;
                    }
                    break;
                case FaceCondition::Kind::Open:
                    break;
                }
                if (recordReactions) reaction += m * (before - v) / dt;
            }
        }
        if (recordReactions) reactions[f] = reaction;
    }
}

template <int dim> void randomNodes(Grid<dim>& g, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (Index k = 0; k < g.numNodes(); ++k) {
        g.mass[k] = k % 5 == 0 ? 0.0 : 1.0 + u(rng) * 0.4;
        for (int d = 0; d < dim; ++d) {
            g.vOld[k][d] = u(rng);
            g.v[k][d] = u(rng);
            g.force[k][d] = 10 * u(rng);
        }
    }
}

template <int dim>
void checkLegacy(const std::string& text, const std::vector<FaceCondition>& faces) {
    SCOPED_TRACE(text);
    Grid<dim> a(parse(text)), b(parse(text));
    BoundaryConditions<dim> bc(parse(text), a);
    test::activateAll(b);
    bc.selectActive(b);
    const BoundaryConditions<dim>& bcConst = bc;
    std::vector<unsigned char> contact(a.numNodes(), 0);
    Vec<dim> gravity = Vec<dim>::Zero();
    gravity[dim - 1] = -9.81;
    for (unsigned seed : {1u, 2u}) {
        randomNodes(a, seed);
        randomNodes(b, seed);
        std::array<Vec<dim>, 2 * dim> ra, rb;
        legacyApply(a, faces, true, 1e-3, gravity, ra, contact);
        bc.constrainUpdate(b, gravity, 0.3, 1e-3, rb);
        legacyApply(a, faces, false, 0.0, gravity, ra, contact);
        bcConst.constrain(b, b.vOld, 0.3);
        for (Index k = 0; k < a.numNodes(); ++k) {
            ASSERT_EQ(a.vOld[k], b.vOld[k]) << k;
            ASSERT_EQ(a.v[k], b.v[k]) << k;
        }
        // Velocities bit for bit; the reactions sum the same terms block by block (the walls'
        // work follows the active blocks), so they agree to rounding.
        for (int f = 0; f < 2 * dim; ++f) {
            EXPECT_LE((ra[f] - rb[f]).norm(), 1e-13 * ra[f].norm()) << Grid<dim>::faceName(f);
            EXPECT_EQ(rb[f], bc.patchReaction(f, 0));
        }
        EXPECT_NE(rb[2], Vec<dim>::Zero());
    }
}

TEST(BoundaryConditions, LegacySyntaxIsBitIdenticalToFaceConditions) {
    checkLegacy<2>("bounds: {min: [0, 0], max: [0.4, 0.3]}\ncellSize: 0.05\n"
                   "boundary: {yMin: noSlip, xMax: {type: friction, friction: 0.3}, "
                   "xMin: open}\n",
                   {{Kind::Open}, {Kind::Friction, 0.3}, {Kind::NoSlip}, {Kind::Slip}});
    checkLegacy<2>("bounds: {min: [0, 0], max: [0.4, 0.3]}\ncellSize: 0.05\n",
                   std::vector<FaceCondition>(4));
    checkLegacy<3>("bounds: {min: [0, 0, 0], max: [0.3, 0.2, 0.4]}\ncellSize: 0.05\n"
                   "boundary: {xMin: noSlip, yMin: {type: friction, friction: 0.5}, "
                   "zMin: {type: noSlip}, zMax: open, yMax: slip}\n",
                   {{Kind::NoSlip},
                    {Kind::Slip},
                    {Kind::Friction, 0.5},
                    {Kind::Slip},
                    {Kind::NoSlip},
                    {Kind::Open}});
}

// ---------------------------------------------------------------------------------------------
// Patches: box, windows, fallback

const std::string orifice =
    "boundary:\n"
    "  yMin:\n"
    "    wall: {type: noSlip}\n"
    "    orifice: {type: open, box: {min: [-0.05, 0], max: [0.05, 0]}, from: 0.5}\n";

TEST(BoundaryConditions, BoxSelectsTheNodesWhoseTangentialCoordinatesLieInIt) {
    Scene<2> s(box2D, orifice);
    const Grid<2>& g = s.grid;
    ASSERT_EQ(s.bc.numPatches(2), 2);
    EXPECT_EQ(s.bc.patchName(2, 0), "wall");
    EXPECT_EQ(s.bc.patchName(2, 1), "orifice");
    std::set<Index> expected, rest;
    for (Index k : g.faceNodes(2)) {
        const double x = g.nodePosition(coordOf(g, k))[0];
        (std::fabs(x) <= 0.05 + 1e-12 ? expected : rest).insert(k);
    }
    const auto& in = s.bc.patchNodes(2, 1);
    const auto& out = s.bc.patchNodes(2, 0);
    EXPECT_EQ(std::set<Index>(in.begin(), in.end()), expected);
    EXPECT_EQ(std::set<Index>(out.begin(), out.end()), rest);
    // 5 node columns (x = -0.05 … 0.05) × the face and its Pad ghost layers.
    EXPECT_EQ(in.size(), 5u * (Grid<2>::Pad + 1));
    EXPECT_EQ(in.size() + out.size(), g.faceNodes(2).size());
}

TEST(BoundaryConditions, WindowSwitchesAtFromAndUntil) {
    // The orifice is no-slip (the face's box-less patch) before t = 0.5 and open from then on.
    Scene<2> s(box2D, orifice);
    Grid<2>& g = s.grid;
    const Index hole = nodeAt(g, Vec<2>(0.025, 0.0));
    const Index wall = nodeAt(g, Vec<2>(-0.075, 0.0));
    const Vec<2> v(0.3, -1.0);
    BoundaryConditions<2>::Reactions r;
    for (double t : {0.0, 0.4999, 0.5, 3.0}) {
        SCOPED_TRACE(t);
        clearNodes(g);
        for (Index i : {hole, wall}) {
            g.mass[i] = 1;
            g.vOld[i] = g.v[i] = v;
        }
        s.bc.constrainUpdate(g, Vec<2>::Zero(), t, 1.0, r);
        const bool open = t >= 0.5;
        EXPECT_EQ(s.bc.active(2, 1, t), open);
        EXPECT_EQ(g.v[hole], open ? v : Vec<2>::Zero());
        EXPECT_EQ(g.v[wall], Vec<2>::Zero());
        EXPECT_EQ(s.bc.patchReaction(2, 0), v);
        EXPECT_EQ(s.bc.patchReaction(2, 1), open ? Vec<2>::Zero() : v);
        EXPECT_EQ(r[2], open ? v : Vec<2>(2 * v));
    }

    // `until`, and slip as the fallback when the face has no box-less patch.
    Scene<2> u(box2D, "boundary:\n  yMin:\n"
                      "    gate: {type: noSlip, box: {min: [-0.05, 0], max: [0.05, 0]}, "
                      "from: 1, until: 2}\n");
    ASSERT_EQ(u.bc.numPatches(2), 2);
    EXPECT_EQ(u.bc.patchName(2, 0), "yMin"); // the implicit slip rest
    for (double t : {0.5, 1.0, 1.5, 2.0}) {
        SCOPED_TRACE(t);
        clearNodes(u.grid);
        u.grid.mass[hole] = 1;
        u.grid.vOld[hole] = u.grid.v[hole] = v;
        u.bc.constrainUpdate(u.grid, Vec<2>::Zero(), t, 1.0, r);
        EXPECT_EQ(u.grid.v[hole], t >= 1 && t < 2 ? Vec<2>::Zero() : Vec<2>(0.3, 0));
    }
}

TEST(BoundaryConditions, WholeFacePatchWithWindowFallsBackToSlip) {
    Scene<2> s(box2D, "boundary: {yMin: {type: noSlip, until: 1}}\n");
    Grid<2>& g = s.grid;
    const Index i = nodeAt(g, Vec<2>(0.0, 0.0));
    BoundaryConditions<2>::Reactions r;
    for (double t : {0.0, 1.0}) {
        clearNodes(g);
        g.mass[i] = 1;
        g.vOld[i] = g.v[i] = Vec<2>(1, -1);
        s.bc.constrainUpdate(g, Vec<2>::Zero(), t, 1.0, r);
        EXPECT_EQ(g.v[i], t < 1 ? Vec<2>::Zero() : Vec<2>(1, 0));
    }
}

// ---------------------------------------------------------------------------------------------
// Outflow

template <int dim> Particles<dim> particlesAt(const std::vector<Vec<dim>>& xs) {
    Particles<dim> p;
    p.resize(xs.size());
    for (std::size_t i = 0; i < xs.size(); ++i) {
        p.x[i] = xs[i];
        p.id[i] = static_cast<Index>(i);
        p.mass[i] = 1;
    }
    return p;
}

TEST(BoundaryConditions, OpenPatchRemovesParticlesOnlyWhileActive) {
    Scene<2> s(box2D, orifice);
    EXPECT_TRUE(s.bc.hasOpen());
    const double h = 0.025;
    // 0: inside; 1: under the orifice, more than a cell out; 2: under it, less than a cell out;
    // 3: under the wall, far out; 4: under the orifice's edge node + a bit less than a cell.
    const std::vector<Vec<2>> xs{
        Vec<2>(0, 0.1),        Vec<2>(0.01, -1.01 * h),          Vec<2>(0.01, -0.99 * h),
        Vec<2>(-0.09, -2 * h), Vec<2>(0.05 + 0.9 * h, -1.5 * h), Vec<2>(0.02, -2.5 * h)};
    Particles<2> before = particlesAt<2>(xs);
    Particles<2> p = before;
    EXPECT_EQ(s.bc.removeOutflow(p, 0.49), 0);
    EXPECT_EQ(p.size(), xs.size());
    EXPECT_EQ(s.bc.removeOutflow(p, 0.5), 3);
    ASSERT_EQ(p.size(), 3u);
    EXPECT_EQ(p.id, (std::vector<Index>{0, 2, 3})); // the others keep their order
    EXPECT_EQ(p.x[2], xs[3]);

    // Legacy open face: everything more than one cell beyond it.
    Scene<2> o(box2D, "boundary: {yMin: open}\n");
    p = before;
    EXPECT_EQ(o.bc.removeOutflow(p, 0.0), 4);
    EXPECT_EQ(p.id, (std::vector<Index>{0, 2}));

    // No open face: nothing to do; every particle leaving is an error.
    Scene<2> w(box2D, "boundary: {yMin: noSlip}\n");
    EXPECT_FALSE(w.bc.hasOpen());
    p = before;
    EXPECT_EQ(w.bc.removeOutflow(p, 0.0), 0);
    Particles<2> gone = particlesAt<2>({Vec<2>(0, -1)});
    EXPECT_THROW(o.bc.removeOutflow(gone, 0.0), RunError);
}

TEST(BoundaryConditions, OpenQueryForBodies) {
    Scene<2> s(box2D, orifice);
    EXPECT_FALSE(s.bc.open(2, Vec<2>(0, -0.1), 0.0));
    EXPECT_TRUE(s.bc.open(2, Vec<2>(0, -0.1), 1.0));
    EXPECT_FALSE(s.bc.open(2, Vec<2>(-0.09, -0.1), 1.0));
    EXPECT_FALSE(s.bc.open(3, Vec<2>(0, 0.3), 1.0));
}

// ---------------------------------------------------------------------------------------------
// Input errors

InputError boundaryError(const std::string& boundary) {
    return catchInputError([&] { Scene<2> s(box2D, boundary); });
}

void expectMessage(const InputError& e, const std::vector<std::string>& parts) {
    for (const auto& p : parts)
        EXPECT_NE(std::string(e.what()).find(p), std::string::npos) << e.what();
}

TEST(BoundaryConditions, OverlappingBoxesAreAnErrorNamingBoth) {
    const InputError e = boundaryError(
        "boundary:\n  yMin:\n    a: {type: open, box: {min: [-0.05, 0], max: [0, 0]}}\n"
        "    b: {type: noSlip, box: {min: [0, 0], max: [0.05, 0]}}\n");
    expectMessage(e, {"'a'", "'b'", "overlap", "yMin"});
    EXPECT_EQ(e.line(), 6);
    // Touching boxes without a common node are fine.
    Scene<2> s(box2D, "boundary:\n  yMin:\n    a: {type: open, box: {min: [-0.05, 0], max: "
                      "[-0.01, 0]}}\n    b: {type: noSlip, box: {min: [0.01, 0], max: [0.05, "
                      "0]}}\n");
    EXPECT_EQ(s.bc.numPatches(2), 3);
}

TEST(BoundaryConditions, PeriodicPairingErrors) {
    expectMessage(boundaryError("boundary: {xMin: periodic, xMax: slip}\n"),
                  {"xMin is periodic but xMax is not", "pairs"});
    expectMessage(boundaryError("boundary: {yMax: periodic}\n"),
                  {"yMax is periodic but yMin is not"});
    expectMessage(boundaryError("boundary: {xMin: {type: periodic, from: 1}, xMax: periodic}\n"),
                  {"whole face"});
    expectMessage(boundaryError("boundary: {xMin: {p: {type: periodic}}, xMax: periodic}\n"),
                  {"whole face"});
    expectMessage(boundaryError("boundary: {xMin: {p: {type: periodic, box: {min: [0, 0], max: "
                                "[0, 0.1]}}}, xMax: periodic}\n"),
                  {"whole face"});
}

TEST(BoundaryConditions, UnknownTypeListsTheValidOnes) {
    for (const char* b :
         {"boundary: {xMin: sticky}\n", "boundary: {xMin: {type: sticky}}\n",
          "boundary: {xMin: {w: {type: sticky}}}\n", "boundary: {xMin: {w: sticky}}\n"}) {
        SCOPED_TRACE(b);
        expectMessage(boundaryError(b),
                      {"unknown type 'sticky'", "friction, noSlip, open, periodic, roller, slip, "
                                                "velocity (mpmFoam -list boundaryConditions"});
    }
}

TEST(BoundaryConditions, OpenAndPeriodicAreFaceKindsOfTheSetNotConditions) {
    // The registry holds only the conditions that constrain nodes; the set reads the face kinds
    // open and periodic itself, and the user sees all of them as types of the family.
    for (const std::string kind : {"open", "periodic"}) {
        SCOPED_TRACE(kind);
        EXPECT_EQ(BoundaryConditionRegistry<2>::table().count(kind), 0u);
        EXPECT_EQ(BoundaryConditionRegistry<3>::table().count(kind), 0u);
        EXPECT_NE(faceKind(kind), FaceKind::constrained);
        const auto names = BoundaryConditions<3>::typeNames();
        EXPECT_NE(std::find(names.begin(), names.end(), kind), names.end());
        std::ostringstream list;
        ModelCatalogue::list(list, "boundaryConditions");
        EXPECT_NE(list.str().find("\n  " + kind + " (2D, 3D): "), std::string::npos) << list.str();
    }
    EXPECT_EQ(faceKind("slip"), FaceKind::constrained);
    // A face kind's map takes only the patch keys; an unknown one names them.
    expectMessage(boundaryError("boundary: {yMin: {type: open, friction: 0.3}}\n"),
                  {"friction", "The keys of open are: type, box, from, until"});
    // Open and periodic faces constrain nothing and take no reaction.
    Scene<2> s(box2D, "boundary: {xMin: periodic, xMax: periodic, yMin: open, yMax: open}\n");
    Grid<2>& g = s.grid;
    clearNodes(g);
    for (Index i = 0; i < g.numNodes(); ++i) {
        g.mass[i] = 1;
        g.vOld[i] = g.v[i] = Vec<2>(0.3, -0.7);
    }
    BoundaryConditions<2>::Reactions r;
    s.bc.constrainUpdate(g, Vec<2>::Zero(), 0.0, 0.01, r);
    s.bc.constrain(g, g.vOld, 0.0);
    for (Index i = 0; i < g.numNodes(); ++i) {
        EXPECT_EQ(g.v[i], Vec<2>(0.3, -0.7));
        EXPECT_EQ(g.vOld[i], Vec<2>(0.3, -0.7));
    }
    for (int f = 0; f < 4; ++f)
        EXPECT_EQ(r[f], Vec<2>::Zero()) << Grid<2>::faceName(f);
    EXPECT_TRUE(s.bc.hasOpen());
    EXPECT_TRUE(s.bc.periodic(0));
    EXPECT_FALSE(s.bc.periodic(1));
}

TEST(BoundaryConditions, OtherInputErrors) {
    const std::vector<std::pair<std::string, std::string>> cases{
        {"boundary: {xMin: friction}\n", "needs parameters"},
        {"boundary: {xMin: velocity}\n", "needs parameters"},
        {"boundary: {xMin: {type: friction}}\n", "friction"},
        {"boundary: {xMin: {type: friction, friction: -1}}\n", "friction"},
        {"boundary: {xMin: {type: velocity}}\n", "exactly one of"},
        {"boundary: {xMin: {type: velocity, value: [1, 0], table: [[0, 1, 0]]}}\n",
         "exactly one of"},
        {"boundary: {xMin: {type: velocity, table: [[1, 0, 0], [1, 1, 0]]}}\n", "increase"},
        {"boundary: {xMin: {type: velocity, value: [1, 0, 0]}}\n", "value"},
        {"boundary: {xMin: {type: noSlip, box: {min: [0, 0], max: [0, 0.1]}}}\n", "whole face"},
        {"boundary: {xMin: {type: noSlip, from: 2, until: 1}}\n", "until must exceed from"},
        {"boundary: {xMin: {a: noSlip, b: slip}}\n", "both have no box"},
        {"boundary: {xMin: {}}\n", "no condition"},
        {"boundary: {xMin: {a: {type: open, box: {min: [0, 0.5], max: [0, 0.6]}}}}\n",
         "holds no node"},
        {"boundary: {xMin: {a: {type: open, box: {min: [0, 0.1], max: [0, 0.05]}}}}\n",
         "below its min"},
        {"boundary: {xMin: {a: {type: open, box: {min: [0, 0.1], max: [0, 0.2], mid: 1}}}}\n",
         "unknown key"},
        {"boundary: {xMin: {type: slip, friction: 0.3}}\n", "unknown key"},
        {"boundary: {zMin: slip}\n", "unknown key"},
    };
    for (const auto& [b, what] : cases) {
        SCOPED_TRACE(b);
        expectMessage(boundaryError(b), {what});
    }
}

} // namespace
} // namespace mpm
