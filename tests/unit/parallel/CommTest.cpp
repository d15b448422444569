// SPDX-License-Identifier: GPL-3.0-or-later
// The one-rank Comm of serial runs (every collective the identity, no MPI call), the byte
// messages, and the pieces of the parallel step that one rank can check: keeping a rank's
// points of a seeding, the owner rule, and a halo with nothing to exchange.
#include "parallel/Comm.hpp"
#include "parallel/GridHalo.hpp"
#include "parallel/Migration.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace mpm {
namespace {

TEST(Comm, SerialIsOneRankAndEveryCollectiveTheIdentity) {
    const Comm& c = serialComm();
    EXPECT_EQ(c.rank(), 0);
    EXPECT_EQ(c.size(), 1);
    EXPECT_TRUE(c.master());
    EXPECT_FALSE(c.parallel());
    double x[3] = {1.5, -2.0, 0.25};
    c.sum(x, 3);
    EXPECT_EQ(x[0], 1.5);
    EXPECT_EQ(x[2], 0.25);
    EXPECT_EQ(c.sum(Index(7)), 7);
    EXPECT_EQ(c.max(3.0), 3.0);
    EXPECT_EQ(c.min(Index(-4)), -4);
    EXPECT_TRUE(c.any(true));
    EXPECT_FALSE(c.any(false));
    EXPECT_EQ(c.gather(42.0), std::vector<double>{42.0});
    EXPECT_EQ(c.broadcast("0.05"), "0.05");
    const std::vector<std::vector<char>> sent{{'a', 'b'}};
    EXPECT_EQ(c.exchange(sent), sent); // to itself
}

TEST(Comm, BytesRoundTripInOrder) {
    std::vector<char> buffer;
    ByteWriter w(buffer);
    w.put(Index(3));
    const Vec3 v(1.0, -2.0, 3.5);
    w.put(&v, 1);
    const double d[2] = {0.1, 0.2};
    w.put(d, 2);
    ByteReader r(buffer);
    EXPECT_EQ(r.get<Index>(), 3);
    Vec3 u;
    r.get(&u, 1);
    EXPECT_EQ(u, v);
    double e[2];
    r.get(e, 2);
    EXPECT_EQ(e[0], 0.1);
    EXPECT_EQ(e[1], 0.2);
    EXPECT_TRUE(r.done());
}

Dictionary parse(const std::string& text, const std::string& name) {
    return Dictionary::fromString(text, name);
}

/// A 2D grid of 8 × 4 cells of 0.25 m (2 × 1 blocks of 4 × 4 cells inside the padding) split
/// by `simple` into two subdomains along x.
struct TwoSubdomains {
    Grid<2> grid{parse("bounds: {min: [0, 0], max: [2, 1]}\ncellSize: 0.25\n", "constant/grid")};
    Decomposition<2> dec = Decomposition<2>::build(
        parse("numberOfSubdomains: 2\nmethod: simple\nsimpleCoeffs: {n: [2, 1]}\n",
              "system/decomposeParDict"),
        grid.blocks(), std::vector<Index>(static_cast<std::size_t>(grid.numBlocks()), 0));
};

TEST(Migration, OwnerIsTheOwnerOfThePointsBlock) {
    const TwoSubdomains s;
    // The x extent of a block is 4 cells: the cut lies at the middle block boundary.
    const int nb = s.grid.blocks()[0];
    for (int i = 0; i < 40; ++i) {
        const Vec<2> x(-0.6 + 0.08 * i, 0.5);
        const Vec<2> xh = (x - s.grid.origin()) * s.grid.invH();
        if (!s.grid.insideArrays(xh)) {
            EXPECT_EQ(ownerOf(x, s.grid, s.dec), -1);
            continue;
        }
        const int bx = static_cast<int>(xh[0]) / Grid<2>::BlockSize;
        EXPECT_EQ(ownerOf(x, s.grid, s.dec), bx * 2 / nb) << "x = " << x[0];
    }
}

TEST(Migration, KeepOwnedKeepsThisRanksPointsInOrderWithAllFields) {
    const TwoSubdomains s;
    Particles<2> p;
    const std::size_t handle = p.addScalar(FieldInfo{"damage"});
    p.resize(20);
    for (std::size_t i = 0; i < 20; ++i) {
        p.x[i] = Vec<2>(0.05 + 0.1 * static_cast<double>(i), 0.5);
        p.id[i] = static_cast<Index>(i);
        p.mass[i] = 1.0 + static_cast<double>(i);
        p.scalar(handle)[i] = 10.0 * static_cast<double>(i);
    }
    for (int rank = 0; rank < 2; ++rank) {
        Particles<2> q = p;
        keepOwned(q, s.grid, s.dec, rank);
        ASSERT_FALSE(q.x.empty());
        for (std::size_t k = 0; k < q.size(); ++k) {
            EXPECT_EQ(ownerOf(q.x[k], s.grid, s.dec), rank);
            EXPECT_EQ(q.mass[k], 1.0 + static_cast<double>(q.id[k]));
            EXPECT_EQ(q.scalar(handle)[k], 10.0 * static_cast<double>(q.id[k]));
            if (k > 0) {
                EXPECT_LT(q.id[k - 1], q.id[k]); // order kept
            }
        }
    }
}

TEST(GridHalo, OneRankOwnsEveryReachedBlockAndExchangesNothing) {
    const TwoSubdomains s;
    const Decomposition<2> serial(s.grid.blocks());
    GridHalo<2> halo(serialComm(), serial);
    const std::vector<Index> reached{1, 2, 5};
    EXPECT_EQ(halo.exchangeBlocks(reached), reached);
    EXPECT_EQ(halo.owned(), reached);
    Grid<2> g(parse("bounds: {min: [0, 0], max: [2, 1]}\ncellSize: 0.25\n", "constant/grid"));
    g.mass[70] = 2.0;
    halo.sum(g.mass);
    halo.copy(g.mass);
    EXPECT_EQ(g.mass[70], 2.0);
    EXPECT_EQ(halo.bytesSent(), 0.0);
}

} // namespace
} // namespace mpm
