// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/Particles.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

namespace {

using namespace mpm;

Particles<2> makeParticles(int n) {
    Particles<2> p;
    p.resize(n);
    for (int i = 0; i < n; ++i) {
        p.x[i] = Vec<2>(i, 0);
        p.id[i] = 100 + i;
        p.mass[i] = 1.0 + i;
    }
    return p;
}

TEST(ParticlesTest, TableNamesEveryStoredArrayOnce) {
    Particles<2> p = makeParticles(3);
    p.addScalar({"rate"});
    std::set<std::string> names;
    int arrays = 0;
    p.forEachField([&](const FieldInfo& info, const auto& a) {
        EXPECT_TRUE(names.insert(info.name).second) << info.name << " twice";
        EXPECT_EQ(a.size(), 3u) << info.name;
        ++arrays;
    });
    // 13 built-in arrays (x, v, C, L, F, be, stress, mass, V⁰, V, εp, id, material) + 1.
    EXPECT_EQ(arrays, 14);
    EXPECT_TRUE(names.count("rate"));
}

TEST(ParticlesTest, DeclaredStateIsResizedPermutedAndCompacted) {
    Particles<2> p = makeParticles(4);
    const std::size_t r = p.addScalar({"rate"}, 7.0);
    const std::size_t s = p.addTensor({"elasticStress"});
    const std::size_t f = p.addFlag({"state"}, 2);
    EXPECT_EQ(p.scalar(r), std::vector<double>(4, 7.0));
    EXPECT_EQ(p.flag(f), std::vector<int>(4, 2));
    for (int i = 0; i < 4; ++i) {
        p.scalar(r)[i] = 10.0 * i;
        p.tensor(s)[i] = Mat3::Identity() * i;
        p.flag(f)[i] = i;
    }
    PermuteBuffers<2> scratch;
    p.permute({3, 1, 0, 2}, scratch);
    EXPECT_EQ(p.id, (std::vector<Index>{103, 101, 100, 102}));
    EXPECT_EQ(p.scalar(r), (std::vector<double>{30, 10, 0, 20}));
    EXPECT_EQ(p.flag(f), (std::vector<int>{3, 1, 0, 2}));
    EXPECT_EQ(p.tensor(s)[0], Mat3::Identity() * 3);
    p.permute({2, 0}); // compaction: keeps old 2 and 0 in that order
    EXPECT_EQ(p.size(), 2u);
    EXPECT_EQ(p.id, (std::vector<Index>{100, 103}));
    EXPECT_EQ(p.scalar(r), (std::vector<double>{0, 30}));
    p.resize(5);
    EXPECT_EQ(p.scalar(r).size(), 5u);
    EXPECT_EQ(p.tensor(s).size(), 5u);
}

TEST(ParticlesTest, DeclaringAnExistingNameSharesIt) {
    Particles<3> p;
    const std::size_t a = p.addScalar({"rate"});
    const std::size_t b = p.addScalar({"rate"});
    EXPECT_EQ(a, b);
    EXPECT_EQ(p.scalars.size(), 1u);
}

TEST(ParticlesTest, EmptyLikeKeepsDeclarationsNotValues) {
    Particles<2> p = makeParticles(2);
    p.addScalar({"rate", true, false});
    const Particles<2> q = p.emptyLike();
    EXPECT_EQ(q.size(), 0u);
    ASSERT_EQ(q.scalars.size(), 1u);
    EXPECT_EQ(q.scalars[0].info.name, "rate");
    EXPECT_FALSE(q.scalars[0].info.written);
}

TEST(ParticlesTest, VolumeFromRateIsExactUnderRotationAndNeverInverts) {
    // Material 0: V = det F V⁰; material 1: V ← V exp(Δt tr L) [002 Eq. 76].
    Particles<2> p = makeParticles(2);
    p.material = {0, 1};
    for (int i = 0; i < 2; ++i) {
        p.F[i].setIdentity();
        p.volume0[i] = p.volume[i] = 2.0;
    }
    const std::vector<char> fromRate{0, 1};
    // A spin ω = 50 rad/s for 100 steps of 1 ms: det(1 + Δt W) = 1 + (Δt ω)² per step inflates
    // the det F volume; the rate form keeps it exactly.
    for (int i = 0; i < 2; ++i)
        p.L[i] << 0.0, -50.0, 50.0, 0.0;
    for (int n = 0; n < 100; ++n)
        ASSERT_EQ(p.updateDeformation(1e-3, fromRate), 2);
    EXPECT_NEAR(p.volume[0], 2.0 * std::pow(1.0 + 2.5e-3, 100), 1e-12);
    EXPECT_EQ(p.volume[1], 2.0);
    // A compression of Δt tr L = −1.5 along x in one step inverts F: det F ≤ 0 stops material 0,
    // while the rate form gives V e^−1.5 > 0 (its F is a diagnostic).
    for (int i = 0; i < 2; ++i) {
        p.F[i].setIdentity();
        p.volume[i] = 2.0;
        p.L[i] << -1500.0, 0.0, 0.0, 0.0;
    }
    EXPECT_EQ(p.updateDeformation(1e-3, fromRate), 0);
    EXPECT_NEAR(p.volume[1], 2.0 * std::exp(-1.5), 1e-15);
    // Only the rate-form point: no failure.
    p.material = {1, 1};
    p.volume = {2.0, 2.0};
    EXPECT_EQ(p.updateDeformation(1e-3, fromRate), 2);
}

} // namespace
