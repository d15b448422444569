// SPDX-License-Identifier: GPL-3.0-or-later
// Seeding around rigid bodies: `outsideBodies: yes` leaves out the points closer to a body than
// half their spacing (fines in the voids of a skeleton), and asks for bodies.
#include "particles/ParticleSeeder.hpp"
#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace mpm {
namespace {

Dictionary parse(const std::string& text, const std::string& file) {
    return Dictionary::fromString(text, file);
}

struct Scene {
    Grid<2> grid{parse("bounds: {min: [0, 0], max: [1, 1]}\ncellSize: 0.05\n", "constant/grid")};
    std::vector<std::unique_ptr<Material<2>>> materials;
    Scene() {
        materials.push_back(Material<2>::create(
            parse("type: linearElastic\ndensity: 2000\nE: 1e6\nnu: 0.3\n", "constant/materials"),
            "sand"));
    }
    Particles<2> seed(const std::string& extra, bool withBody) {
        Particles<2> p;
        materials[0]->declareState(p);
        ParticleSeeder<2> seeder(grid, materials, Vec<2>(0, -9.81));
        if (withBody) // a disk of radius 0.2 at (0.5, 0.5)
            seeder.setBodyDistance(
                [](const Vec<2>& x) { return (x - Vec<2>(0.5, 0.5)).norm() - 0.2; });
        seeder.seed(parse("fines:\n  material: sand\n  region: {type: box, min: [0.1, 0.1], max: "
                          "[0.9, 0.9]}\n  seeding: {method: regular, perDirection: 2}\n" +
                              extra,
                          "constant/particles"),
                    p);
        return p;
    }
};

TEST(ParticleSeeder, OutsideBodiesLeavesOutThePointsInAndNextToTheBodies) {
    Scene s;
    const Particles<2> all = s.seed("", true);
    const Particles<2> fines = s.seed("  outsideBodies: yes\n", true);
    const double clearance = 0.5 * 0.025; // half the spacing h/2
    std::size_t near = 0;
    for (const Vec<2>& x : all.x)
        near += (x - Vec<2>(0.5, 0.5)).norm() - 0.2 < clearance;
    EXPECT_GT(near, 0u);
    EXPECT_EQ(fines.size(), all.size() - near);
    for (const Vec<2>& x : fines.x)
        EXPECT_GE((x - Vec<2>(0.5, 0.5)).norm() - 0.2, clearance);
    EXPECT_EQ(s.seed("  outsideBodies: no\n", true).size(), all.size());
}

TEST(ParticleSeeder, BodyClearanceSetsTheGapLeftAroundTheBodies) {
    Scene s;
    const Particles<2> all = s.seed("", true);
    for (double c : {0.01, 0.05, 0.1}) {
        const Particles<2> fines =
            s.seed("  outsideBodies: yes\n  bodyClearance: " + std::to_string(c) + "\n", true);
        std::size_t clear = 0;
        for (const Vec<2>& x : all.x)
            clear += (x - Vec<2>(0.5, 0.5)).norm() - 0.2 >= c;
        EXPECT_EQ(fines.size(), clear) << "c = " << c;
        for (const Vec<2>& x : fines.x)
            EXPECT_GE((x - Vec<2>(0.5, 0.5)).norm() - 0.2, c);
    }
}

TEST(ParticleSeeder, BodyClearanceWithoutOutsideBodiesOrNotPositiveIsAnInputError) {
    Scene s;
    InputError e = test::catchInputError([&] { s.seed("  bodyClearance: 0.01\n", true); });
    EXPECT_NE(std::string(e.what()).find("needs outsideBodies: yes"), std::string::npos);
    e = test::catchInputError([&] { s.seed("  outsideBodies: yes\n  bodyClearance: 0\n", true); });
    EXPECT_NE(std::string(e.what()).find("bodyClearance"), std::string::npos);
}

TEST(ParticleSeeder, MinimumClusterLeavesOutTheSpecksInClosedPockets) {
    // A ring body (|r − 0.25| < 0.05 about the centre) splits the points into the disk inside it
    // (r < 0.2 − c) and the rest (r > 0.3 + c); minimumCluster between the two counts drops the
    // inner disk only.
    Scene s;
    const Vec<2> o(0.5, 0.5);
    auto ring = [o](const Vec<2>& x) { return std::abs((x - o).norm() - 0.25) - 0.05; };
    const std::string fill = "  outsideBodies: yes\n";
    Particles<2> p;
    std::size_t inner = 0, outer = 0;
    {
        Particles<2> all = s.seed("", false);
        for (const Vec<2>& x : all.x) {
            if (ring(x) < 0.0125) continue; // within the default clearance (half the spacing)
            ((x - o).norm() < 0.25 ? inner : outer)++;
        }
    }
    ASSERT_GT(inner, 10u);
    ASSERT_GT(outer, inner);
    auto seed = [&](const std::string& extra) {
        Particles<2> q;
        s.materials[0]->declareState(q);
        ParticleSeeder<2> seeder(s.grid, s.materials, Vec<2>(0, -9.81));
        seeder.setBodyDistance(ring);
        seeder.seed(parse("fines:\n  material: sand\n  region: {type: box, min: [0.1, 0.1], "
                          "max: [0.9, 0.9]}\n" +
                              fill + extra,
                          "constant/particles"),
                    q);
        return q;
    };
    EXPECT_EQ(seed("").size(), inner + outer);
    EXPECT_EQ(seed("  minimumCluster: " + std::to_string(inner) + "\n").size(), inner + outer);
    const Particles<2> kept = seed("  minimumCluster: " + std::to_string(inner + 1) + "\n");
    EXPECT_EQ(kept.size(), outer);
    for (const Vec<2>& x : kept.x)
        EXPECT_GT((x - o).norm(), 0.3);
    const InputError e = test::catchInputError(
        [&] { seed("  minimumCluster: " + std::to_string(inner + outer + 1) + "\n"); });
    EXPECT_NE(std::string(e.what()).find("minimumCluster"), std::string::npos);
}

TEST(ParticleSeeder, OutsideBodiesWithoutBodiesIsAnInputError) {
    Scene s;
    const InputError e = test::catchInputError([&] { s.seed("  outsideBodies: yes\n", false); });
    EXPECT_NE(std::string(e.what()).find("outsideBodies"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("no rigid bodies"), std::string::npos);
}

/// Seeds the Scene's box [0.1, 0.9]² with Poisson-disk points and the given `volumes`.
Particles<2> seedPoisson(Scene& s, const std::string& seeding, bool withBody,
                         const std::string& extra = "") {
    Particles<2> p;
    s.materials[0]->declareState(p);
    ParticleSeeder<2> seeder(s.grid, s.materials, Vec<2>(0, -9.81));
    if (withBody)
        seeder.setBodyDistance([](const Vec<2>& x) { return (x - Vec<2>(0.5, 0.5)).norm() - 0.2; });
    seeder.seed(parse("fines:\n  material: sand\n  region: {type: box, min: [0.1, 0.1], max: "
                      "[0.9, 0.9]}\n  seeding: {method: poissonDisk, perCell: 4, seed: 3" +
                          seeding + "}\n" + extra,
                      "constant/particles"),
                p);
    return p;
}

TEST(ParticleSeeder, VoronoiVolumesGiveEachPointItsCellAndKeepTheMass) {
    Scene s;
    const Particles<2> equal = seedPoisson(s, "", false);
    const Particles<2> cells = seedPoisson(s, ", volumes: voronoi", false);
    ASSERT_EQ(equal.size(), cells.size());
    double sum = 0, lo = 1, hi = 0;
    for (std::size_t i = 0; i < cells.size(); ++i) {
        EXPECT_EQ(equal.x[i], cells.x[i]);
        EXPECT_EQ(cells.volume0[i], cells.volume[i]);
        EXPECT_DOUBLE_EQ(cells.mass[i], 2000 * cells.volume0[i]);
        sum += cells.volume0[i];
        lo = std::min(lo, cells.volume0[i] / equal.volume0[i]);
        hi = std::max(hi, cells.volume0[i] / equal.volume0[i]);
    }
    EXPECT_NEAR(sum, 0.64, 1e-12); // the box's area: the cells tile it
    EXPECT_LT(lo, 0.9);            // and differ from the equal shares
    EXPECT_GT(hi, 1.1);
}

TEST(ParticleSeeder, VoronoiVolumesAroundBodiesLeaveOutTheBodies) {
    Scene s;
    const Particles<2> p = seedPoisson(s, ", volumes: voronoi", true, "  outsideBodies: yes\n");
    double sum = 0;
    for (std::size_t i = 0; i < p.size(); ++i)
        sum += p.volume0[i];
    EXPECT_NEAR(sum, 0.64 - M_PI * 0.04, 1e-3);
}

TEST(ParticleSeeder, VolumesOtherThanEqualOrVoronoiOrWithRegularSeedingAreInputErrors) {
    Scene s;
    InputError e = test::catchInputError([&] { seedPoisson(s, ", volumes: lattice", false); });
    EXPECT_NE(std::string(e.what()).find("voronoi"), std::string::npos);
    e = test::catchInputError([&] {
        Particles<2> p;
        s.materials[0]->declareState(p);
        ParticleSeeder<2>(s.grid, s.materials, Vec<2>(0, -9.81))
            .seed(parse("fines:\n  material: sand\n  region: {type: box, min: [0.1, 0.1], "
                        "max: [0.9, 0.9]}\n  seeding: {method: regular, volumes: voronoi}\n",
                        "constant/particles"),
                  p);
    });
    EXPECT_NE(std::string(e.what()).find("only poissonDisk seeding takes `volumes`"),
              std::string::npos);
}

} // namespace
} // namespace mpm
