// SPDX-License-Identifier: GPL-3.0-or-later
// The body set across periodic faces: a moving body wraps by whole periods (position only), a
// fixed one never; check() does not report a body beyond a periodic face but does beyond a wall;
// a moving body too large for one periodic image is an input error naming the body's shape.
#include "rigid/BodySet.hpp"

#include "TestSupport.hpp"
#include "boundary/BoundaryConditions.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

namespace mpm {
namespace {

const std::string Box = "dimension: 2\nbounds: {min: [0, 0], max: [0.4, 0.2]}\ncellSize: 0.01\n";

struct PeriodicScene {
    Grid<2> grid;
    BoundaryConditions<2> bc;
    explicit PeriodicScene(const std::string& boundary)
        : grid(Dictionary::fromString(Box, "constant/grid")),
          bc(Dictionary::fromString(Box + boundary, "constant/grid"), grid) {}
};

void writeBodies(const std::filesystem::path& dir, const std::string& text) {
    std::filesystem::create_directories(dir / "constant");
    std::filesystem::create_directories(dir / "system"); // a case directory
    std::ofstream(dir / "constant/rigidBodies") << text;
}

const std::string Bodies = "disk:\n"
                           "  shape: {type: disk, radius: 0.04}\n"
                           "  mass: 1\n"
                           "  position: [0.39, 0.1]\n"
                           "  orientation: 30\n"
                           "  velocity: [2, -1]\n"
                           "  angularVelocity: 3\n"
                           "post:\n"
                           "  shape: {type: box, size: [0.02, 0.02]}\n"
                           "  mass: 1\n"
                           "  motion: fixed\n"
                           "  position: [0.5, 0.1]\n";

TEST(BodySet, PeriodicWrapMovesThePositionOnly) {
    test::TempDir tmp;
    writeBodies(tmp.path(), Bodies);
    const PeriodicScene s("boundary: {xMin: periodic, xMax: periodic}\n");
    BodySet<2> set(Case(tmp.path()), s.grid, &s.bc.lattice());
    RigidBody<2>& disk = *set.bodies()[0];
    disk.movePositionTo(Vec<2>(0.43, 0.1));
    const Mat<2> rotation = disk.rotation();
    const Vec<2> velocity = disk.velocity();
    const Vec3 omega = disk.angularVelocity();
    set.wrap();
    EXPECT_NEAR(disk.position()[0], 0.03, 1e-15);
    EXPECT_EQ(disk.position()[1], 0.1);
    EXPECT_EQ(disk.rotation(), rotation);
    EXPECT_EQ(disk.velocity(), velocity);
    EXPECT_EQ(disk.angularVelocity(), omega);
    // A centre inside [lo, hi) is left bit for bit; a fixed body is never moved.
    disk.movePositionTo(Vec<2>(0.123456789, 0.1));
    set.wrap();
    EXPECT_EQ(disk.position(), Vec<2>(0.123456789, 0.1));
    EXPECT_EQ(set.bodies()[1]->position(), Vec<2>(0.5, 0.1));
}

TEST(BodySet, CheckIgnoresPeriodicFacesOnly) {
    test::TempDir tmp;
    writeBodies(tmp.path(), Bodies);
    auto open = [](int, const Vec<2>&) { return false; };
    const PeriodicScene periodic("boundary: {xMin: periodic, xMax: periodic}\n");
    BodySet<2> set(Case(tmp.path()), periodic.grid, &periodic.bc.lattice());
    set.bodies()[0]->movePositionTo(Vec<2>(0.5, 0.1)); // beyond xMax + R
    EXPECT_EQ(set.check(periodic.grid, open), "");
    set.bodies()[0]->movePositionTo(Vec<2>(0.2, -0.05)); // beyond the yMin wall
    EXPECT_NE(set.check(periodic.grid, open).find("yMin"), std::string::npos);
    // Without periodic faces the same body beyond xMax is reported.
    const PeriodicScene walls("");
    BodySet<2> closed(Case(tmp.path()), walls.grid, &walls.bc.lattice());
    closed.bodies()[0]->movePositionTo(Vec<2>(0.5, 0.1));
    EXPECT_NE(closed.check(walls.grid, open).find("xMax"), std::string::npos);
}

TEST(BodySet, MovingBodyLargerThanHalfThePeriodIsAnInputError) {
    test::TempDir tmp;
    writeBodies(tmp.path(), "big:\n  shape: {type: disk, radius: 0.095}\n  mass: 1\n"
                            "  position: [0.2, 0.1]\n");
    // Periodic along y (L = 0.2): R + h = 0.105 >= L/2.
    const PeriodicScene s("boundary: {yMin: periodic, yMax: periodic}\n");
    try {
        BodySet<2> set(Case(tmp.path()), s.grid, &s.bc.lattice());
        ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.key(), "big.shape") << e.what();
        EXPECT_NE(std::string(e.what()).find("half the period"), std::string::npos) << e.what();
    }
    // The same body fixed (a terrain) is accepted, as is the moving one without periodic faces.
    writeBodies(tmp.path(), "big:\n  shape: {type: disk, radius: 0.095}\n  mass: 1\n"
                            "  motion: fixed\n  position: [0.2, 0.1]\n");
    EXPECT_NO_THROW(BodySet<2>(Case(tmp.path()), s.grid, &s.bc.lattice()));
}

} // namespace
} // namespace mpm
