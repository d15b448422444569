// SPDX-License-Identifier: GPL-3.0-or-later
// Domain decomposition over grid blocks: the methods against known answers, input errors, and
// the decomposition file's round trip.
#include "parallel/Decomposition.hpp"
#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace mpm {
namespace {

using test::catchInputError;

Dictionary parse(const std::string& text) {
    return Dictionary::fromString(text, "system/decomposeParDict");
}

template <int dim> Index count(const IVec<dim>& nb) {
    return static_cast<Index>(nb.prod());
}

/// Coordinates of block b (as Grid::blockCoord).
template <int dim> IVec<dim> coord(Index b, const IVec<dim>& nb) {
    IVec<dim> c;
    for (int d = 0; d < dim; ++d) {
        c[d] = static_cast<int>(b % nb[d]);
        b /= nb[d];
    }
    return c;
}

/// Load of `value` in every block with coordinates where `inside(c)` holds, zero elsewhere.
template <int dim, class Fn> std::vector<Index> loadWhere(const IVec<dim>& nb, Index value, Fn f) {
    std::vector<Index> load(static_cast<std::size_t>(count(nb)), 0);
    for (Index b = 0; b < count(nb); ++b)
        if (f(coord(b, nb))) load[static_cast<std::size_t>(b)] = value;
    return load;
}

template <int dim> std::vector<Index> uniform(const IVec<dim>& nb) {
    return std::vector<Index>(static_cast<std::size_t>(count(nb)), 1);
}

TEST(Decomposition, SerialOwnsEverythingByZero) {
    const Decomposition<3> dec(IVec<3>(3, 4, 5));
    EXPECT_EQ(dec.size(), 1);
    EXPECT_EQ(dec.method(), "none");
    ASSERT_EQ(dec.owners().size(), 60u);
    for (Index b = 0; b < 60; ++b)
        EXPECT_EQ(dec.owner(b), 0);
    EXPECT_EQ(dec.loads(uniform(IVec<3>(3, 4, 5))), std::vector<Index>{60});
    EXPECT_EQ(dec.emptySubdomains(), 0);
}

TEST(Decomposition, SimpleSlabsAlongX) {
    const IVec<3> nb(8, 2, 2);
    const auto dict =
        parse("numberOfSubdomains: 2\nmethod: simple\nsimpleCoeffs: {n: [2, 1, 1]}\n");
    const auto dec = Decomposition<3>::build(dict, nb, uniform(nb));
    dict.checkUnknownKeys();
    EXPECT_EQ(dec.size(), 2);
    EXPECT_EQ(dec.method(), "simple");
    for (Index b = 0; b < count(nb); ++b)
        EXPECT_EQ(dec.owner(b), coord(b, nb)[0] < 4 ? 0 : 1) << "block " << b;
    EXPECT_EQ(dec.loads(uniform(nb)), (std::vector<Index>{16, 16}));
}

TEST(Decomposition, SimpleNumbersXFastest) {
    // 2D, 5 x 7 blocks in 2 x 3 slabs: slab ⌊c n / nb⌋, owner sx + 2 sy.
    const IVec<2> nb(5, 7);
    const auto dict = parse("numberOfSubdomains: 6\nmethod: simple\nsimpleCoeffs: {n: [2, 3]}\n");
    const auto dec = Decomposition<2>::build(dict, nb, uniform(nb));
    for (Index b = 0; b < count(nb); ++b) {
        const IVec<2> c = coord(b, nb);
        EXPECT_EQ(dec.owner(b), c[0] * 2 / 5 + 2 * (c[1] * 3 / 7)) << "block " << b;
    }
    EXPECT_EQ(dec.blockCounts(), (std::vector<Index>{9, 6, 6, 4, 6, 4}));
}

TEST(Decomposition, InputErrorsNameTheKey) {
    const IVec<3> nb(8, 2, 2);
    const auto error = [&](const std::string& text) {
        return catchInputError([&] { Decomposition<3>::build(parse(text), nb, uniform(nb)); });
    };
    const auto expect = [&](const std::string& text, const std::string& key,
                            const std::string& words) {
        const InputError e = error(text);
        EXPECT_EQ(e.key(), key) << e.what();
        EXPECT_EQ(e.file(), "system/decomposeParDict") << e.what();
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    };
    expect("numberOfSubdomains: 0\nmethod: bisection\n", "numberOfSubdomains", "[1,");
    expect("numberOfSubdomains: 2\nmethod: scotch\n", "method", "bisection, hierarchical, simple");
    expect("numberOfSubdomains: 3\nmethod: simple\nsimpleCoeffs: {n: [2, 1, 1]}\n",
           "simpleCoeffs.n", "must multiply to numberOfSubdomains (3)");
    expect("numberOfSubdomains: 2\nmethod: simple\nsimpleCoeffs: {n: [2, 1]}\n", "simpleCoeffs.n",
           "3 numbers");
    expect("numberOfSubdomains: 3\nmethod: simple\nsimpleCoeffs: {n: [1, 3, 1]}\n",
           "simpleCoeffs.n", "only 2 blocks");
    expect("numberOfSubdomains: 2\nmethod: simple\nsimpleCoeffs: {n: [2.5, 0.8, 1]}\n",
           "simpleCoeffs.n", "positive integers");
    expect("numberOfSubdomains: 2\nmethod: simple\nhierarchicalCoeffs: {n: [2, 1, 1]}\n",
           "simpleCoeffs", "missing");
    expect("numberOfSubdomains: 2\nmethod: hierarchical\n", "hierarchicalCoeffs", "missing");
    expect("numberOfSubdomains: 2\nmethod: hierarchical\n"
           "hierarchicalCoeffs: {n: [2, 1, 1], order: xxz}\n",
           "hierarchicalCoeffs.order", "permutation of 'xyz'");
    expect("numberOfSubdomains: 2\nmethod: hierarchical\n"
           "hierarchicalCoeffs: {n: [2, 1, 1], order: xy}\n",
           "hierarchicalCoeffs.order", "permutation");
    expect("numberOfSubdomains: 2\nmethod: simple\nsimpleCoeffs: {n: [2, 1, 1], delta: 0.001}\n",
           "simpleCoeffs.delta", "unknown key");
}

TEST(Decomposition, OtherMethodsCoefficientsAreAllowed) {
    const IVec<2> nb(4, 4);
    const auto dict = parse("numberOfSubdomains: 2\nmethod: bisection\n"
                            "simpleCoeffs: {n: [2, 1]}\nhierarchicalCoeffs: {n: [1, 2]}\n");
    Decomposition<2>::build(dict, nb, uniform(nb));
    EXPECT_NO_THROW(dict.checkUnknownKeys());
    const auto typo = parse("numberOfSubdomains: 2\nmethod: bisection\nsimpleCoefs: {n: [2, 1]}\n");
    Decomposition<2>::build(typo, nb, uniform(nb));
    EXPECT_EQ(catchInputError([&] { typo.checkUnknownKeys(); }).key(), "simpleCoefs");
}

TEST(Decomposition, HierarchicalBalancesASkewedLoad) {
    // All the load in the first quarter along x: the cut lies inside that quarter.
    const IVec<3> nb(16, 2, 2);
    const auto load = loadWhere(nb, 3, [](const IVec<3>& c) { return c[0] < 4; });
    const auto dict =
        parse("numberOfSubdomains: 2\nmethod: hierarchical\nhierarchicalCoeffs: {n: [2, 1, 1]}\n");
    const auto dec = Decomposition<3>::build(dict, nb, load);
    for (Index b = 0; b < count(nb); ++b)
        EXPECT_EQ(dec.owner(b), coord(b, nb)[0] < 2 ? 0 : 1) << "block " << b;
    EXPECT_EQ(dec.loads(load), (std::vector<Index>{24, 24}));
}

TEST(Decomposition, HierarchicalSplitsEachSlabByItsOwnLoad) {
    // 8 x 8 blocks, order yx: the lower half (y < 4) has its load in x < 2, the upper half is
    // uniform, and both halves carry 32. The y cut is at 4; the lower slab is cut at x = 1,
    // the upper at x = 4; owners sx + 2 sy.
    const IVec<2> nb(8, 8);
    const auto load = loadWhere(nb, 1, [](const IVec<2>& c) { return c[1] >= 4 || c[0] < 2; });
    std::vector<Index> skewed = load;
    for (Index b = 0; b < count(nb); ++b)
        if (coord(b, nb)[1] < 4) skewed[static_cast<std::size_t>(b)] *= 4;
    const auto dict = parse("numberOfSubdomains: 4\nmethod: hierarchical\n"
                            "hierarchicalCoeffs: {n: [2, 2], order: yx}\n");
    const auto dec = Decomposition<2>::build(dict, nb, skewed);
    for (Index b = 0; b < count(nb); ++b) {
        const IVec<2> c = coord(b, nb);
        const int expected = c[1] < 4 ? (c[0] < 1 ? 0 : 1) : (c[0] < 4 ? 2 : 3);
        EXPECT_EQ(dec.owner(b), expected) << "block " << c.transpose();
    }
    EXPECT_EQ(dec.loads(skewed), (std::vector<Index>{16, 16, 16, 16}));
}

TEST(Decomposition, HierarchicalWithoutLoadIsGeometric) {
    const IVec<3> nb(8, 4, 6);
    const std::vector<Index> none(static_cast<std::size_t>(count(nb)), 0);
    const auto h =
        Decomposition<3>::build(parse("numberOfSubdomains: 12\nmethod: hierarchical\n"
                                      "hierarchicalCoeffs: {n: [2, 2, 3], order: zxy}\n"),
                                nb, none);
    const auto s = Decomposition<3>::build(
        parse("numberOfSubdomains: 12\nmethod: simple\nsimpleCoeffs: {n: [2, 2, 3]}\n"), nb, none);
    EXPECT_EQ(h.owners(), s.owners());
}

TEST(Decomposition, BisectionKnownAnswer) {
    // 8 x 4 blocks, 4 ranks, uniform: x cut at 4, then each 4 x 4 half across x (ties: the
    // lowest axis) at 2.
    const IVec<2> nb(8, 4);
    const auto dec = Decomposition<2>::build(parse("numberOfSubdomains: 4\nmethod: bisection\n"),
                                             nb, uniform(nb));
    for (Index b = 0; b < count(nb); ++b)
        EXPECT_EQ(dec.owner(b), coord(b, nb)[0] / 2) << "block " << b;
}

TEST(Decomposition, BisectionThirdsWithinOneSlice) {
    const IVec<3> nb(10, 7, 5);
    const auto load = uniform(nb);
    const auto dec =
        Decomposition<3>::build(parse("numberOfSubdomains: 3\nmethod: bisection\n"), nb, load);
    const std::vector<Index> loads = dec.loads(load);
    ASSERT_EQ(loads.size(), 3u);
    EXPECT_EQ(std::accumulate(loads.begin(), loads.end(), Index(0)), count(nb));
    const double third = count(nb) / 3.0, slice = 7 * 5; // the largest slice across an axis
    for (const Index l : loads)
        EXPECT_LE(std::abs(static_cast<double>(l) - third), slice) << l;
}

TEST(Decomposition, BisectionBalancesAnyCountAndIsDeterministic) {
    std::mt19937_64 rng(7);
    std::uniform_int_distribution<int> points(0, 200);
    const IVec<3> nb(13, 9, 6);
    std::vector<Index> load(static_cast<std::size_t>(count(nb)));
    for (Index& l : load)
        l = points(rng) < 60 ? 0 : points(rng); // patchy material
    const Index total = std::accumulate(load.begin(), load.end(), Index(0));
    for (int n : {1, 2, 3, 5, 7, 16, 37}) {
        const auto dict =
            parse("numberOfSubdomains: " + std::to_string(n) + "\nmethod: bisection\n");
        const auto a = Decomposition<3>::build(dict, nb, load);
        const auto b = Decomposition<3>::build(dict, nb, load);
        EXPECT_EQ(a, b);
        for (const std::int32_t r : a.owners())
            ASSERT_TRUE(r >= 0 && r < n) << r;
        EXPECT_EQ(a.emptySubdomains(), 0);
        const auto loads = a.loads(load);
        const Index worst = *std::max_element(loads.begin(), loads.end());
        EXPECT_LT(static_cast<double>(worst), 1.25 * total / n + 2 * 9 * 6 * 200) << n;
    }
}

TEST(Decomposition, BisectionWithMoreRanksThanBlocks) {
    const IVec<2> nb(2, 1);
    const auto dec = Decomposition<2>::build(parse("numberOfSubdomains: 5\nmethod: bisection\n"),
                                             nb, uniform(nb));
    EXPECT_EQ(dec.owner(0), 0);
    EXPECT_EQ(dec.owner(1), 2);
    EXPECT_EQ(dec.emptySubdomains(), 3);
}

class DecompositionFile : public test::TempDirTest {
protected:
    void SetUp() override {
        std::filesystem::create_directories(dir_ / "system");
        std::filesystem::create_directories(dir_ / "constant");
    }
    void writeText(const std::string& text) {
        std::ofstream(dir_ / "constant/decomposition", std::ios::binary) << text;
    }
};

TEST_F(DecompositionFile, WriteReadRoundTrips) {
    const Case cs(dir_);
    const IVec<3> nb(13, 9, 6);
    std::vector<Index> load(static_cast<std::size_t>(count(nb)));
    for (Index b = 0; b < count(nb); ++b)
        load[static_cast<std::size_t>(b)] = (b * 7919) % 13;
    for (const std::string& text :
         {std::string("numberOfSubdomains: 11\nmethod: bisection\n"),
          std::string("numberOfSubdomains: 6\nmethod: hierarchical\n"
                      "hierarchicalCoeffs: {n: [3, 2, 1], order: yzx}\n"),
          std::string("numberOfSubdomains: 4\nmethod: simple\nsimpleCoeffs: {n: [1, 2, 2]}\n")}) {
        const auto dec = Decomposition<3>::build(parse(text), nb, load);
        dec.write(dir_ / "constant/decomposition");
        const auto back = Decomposition<3>::read(cs, "constant/decomposition", nb);
        EXPECT_EQ(back, dec) << text;
    }
    const Decomposition<2> serial(IVec<2>(3, 3));
    serial.write(dir_ / "constant/decomposition");
    EXPECT_EQ(Decomposition<2>::read(cs, "constant/decomposition", IVec<2>(3, 3)), serial);
}

TEST_F(DecompositionFile, ReadErrorsNameTheFile) {
    const Case cs(dir_);
    const auto fails = [&](const IVec<2>& nb, const std::string& key, const std::string& words) {
        const InputError e =
            catchInputError([&] { Decomposition<2>::read(cs, "constant/decomposition", nb); });
        EXPECT_EQ(e.file(), "constant/decomposition") << e.what();
        EXPECT_EQ(e.key(), key) << e.what();
        EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    };
    fails(IVec<2>(4, 4), "", "missing");

    const IVec<2> nb(4, 4);
    Decomposition<2>::build(parse("numberOfSubdomains: 3\nmethod: bisection\n"), nb, uniform(nb))
        .write(dir_ / "constant/decomposition");
    fails(IVec<2>(4, 5), "blocks", "4 x 5");

    writeText("numberOfSubdomains: 2\nmethod: simple\nblocks: [2, 2]\nowner: [0, 2, 1]\n");
    fails(IVec<2>(2, 2), "owner", "pairs");
    writeText("numberOfSubdomains: 2\nmethod: simple\nblocks: [2, 2]\nowner: [0, 2, 2, 2]\n");
    fails(IVec<2>(2, 2), "owner", "[0, 1]");
    writeText("numberOfSubdomains: 2\nmethod: simple\nblocks: [2, 2]\nowner: [0, 2, 1, 1]\n");
    fails(IVec<2>(2, 2), "owner", "cover 3 blocks of 4");
    writeText("numberOfSubdomains: 2\nmethod: simple\nblocks: [2, 2]\nowner: [0, 2, 1, 3]\n");
    fails(IVec<2>(2, 2), "owner", "more than");
    writeText("numberOfSubdomains: 2\nmethod: simple\nblocks: [2, 2]\nowner: [0, 4]\nx: 1\n");
    fails(IVec<2>(2, 2), "x", "unknown key");
    writeText("numberOfSubdomains: 2\nmethod: simple\nblocks: [2, 2\n");
    fails(IVec<2>(2, 2), "", "");
}

} // namespace
} // namespace mpm
