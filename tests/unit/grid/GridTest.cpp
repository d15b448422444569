// SPDX-License-Identifier: GPL-3.0-or-later
// Grid layout, face node lists, input errors, and the block colouring of P2G.
#include "grid/Grid.hpp"
#include "TestSupport.hpp"
#include "particles/BlockSort.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <omp.h>
#include <random>
#include <set>
#include <string>
#include <sys/mman.h>
#include <unistd.h>
#include <vector>

namespace mpm {
namespace {

Dictionary parse(const std::string& text) {
    return Dictionary::fromString(text, "constant/grid");
}

using test::catchInputError;

/// Pages of [p, p + bytes) wholly inside the range that are resident in memory (mincore).
Index residentPages(const void* p, std::size_t bytes) {
    const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    const auto begin = reinterpret_cast<std::uintptr_t>(p);
    const std::uintptr_t first = (begin + page - 1) / page * page,
                         last = (begin + bytes) / page * page;
    if (first >= last) return 0;
    std::vector<unsigned char> in((last - first) / page);
    EXPECT_EQ(mincore(reinterpret_cast<void*>(first), last - first, in.data()), 0);
    Index n = 0;
    for (unsigned char c : in)
        n += c & 1;
    return n;
}

template <int dim> IVec<dim> nodeCoord(const Grid<dim>& g, Index k) {
    return g.nodeCoord(k);
}

using test::boxNodes;

/// The numbering: block by block, a sum of per-axis offsets, file numbers x fastest.
template <int dim> void checkNumbering(const Grid<dim>& g) {
    for (Index k = 0; k < g.numNodes(); ++k) {
        const IVec<dim> c = g.nodeCoord(k);
        ASSERT_EQ(g.nodeIndex(c), k);
        Index b = 0;
        for (int d = dim - 1; d >= 0; --d)
            b = b * g.blocks()[d] + c[d] / Grid<dim>::BlockSize;
        ASSERT_EQ(k / Grid<dim>::NodesPerBlock, b) << "node " << k << " lies in its block";
    }
    Index f = 0;
    for (Index k : boxNodes(g)) {
        ASSERT_GE(k, 0);
        ASSERT_EQ(g.fileIndex(k), f++);
        const IVec<dim> c = g.nodeCoord(k);
        for (int d = 0; d < dim; ++d)
            ASSERT_LT(c[d], g.nodes()[d]);
    }
    EXPECT_EQ(g.nodeOfFileIndex(g.numFileNodes()), -1);
}

TEST(Grid, NodeCountsAndOriginWithPadding2D) {
    const Grid<2> g(parse("bounds: {min: [0, -1], max: [1, 1]}\ncellSize: 0.25\n"));
    constexpr int P = Grid<2>::Pad;
    EXPECT_DOUBLE_EQ(g.h(), 0.25);
    EXPECT_DOUBLE_EQ(g.invH(), 4.0);
    EXPECT_EQ(g.nodes()[0], 4 + 1 + 2 * P);
    EXPECT_EQ(g.nodes()[1], 8 + 1 + 2 * P);
    EXPECT_EQ(g.numFileNodes(), Index(g.nodes()[0]) * g.nodes()[1]);
    EXPECT_DOUBLE_EQ(g.origin()[0], -P * 0.25);
    EXPECT_DOUBLE_EQ(g.origin()[1], -1.0 - P * 0.25);
    EXPECT_DOUBLE_EQ(g.hi()[0], 1.0);
    EXPECT_DOUBLE_EQ(g.hi()[1], 1.0);
    // Box corners are nodes Pad and n - 1 - Pad.
    EXPECT_TRUE(g.nodePosition(IVec<2>(P, P)).isApprox(g.lo()));
    EXPECT_TRUE(
        g.nodePosition(IVec<2>(g.nodes()[0] - 1 - P, g.nodes()[1] - 1 - P)).isApprox(g.hi()));
    EXPECT_EQ(g.blocks()[0], (g.nodes()[0] + 3) / 4);
    EXPECT_EQ(g.blocks()[1], (g.nodes()[1] + 3) / 4);
    EXPECT_EQ(g.numBlocks(), Index(g.blocks()[0]) * g.blocks()[1]);
    EXPECT_EQ(g.numNodes(), g.numBlocks() * 16);
    EXPECT_EQ(g.mass.size(), g.numNodes());
    EXPECT_EQ(g.v.size(), g.numNodes());
    checkNumbering(g);
}

TEST(Grid, NodeCountsAndOriginWithPadding3D) {
    const Grid<3> g(parse("bounds: {min: [0, 0, 0], max: [0.5, 1, 1.5]}\ncellSize: 0.1\n"));
    constexpr int P = Grid<3>::Pad;
    EXPECT_EQ(g.nodes()[0], 5 + 1 + 2 * P);
    EXPECT_EQ(g.nodes()[1], 10 + 1 + 2 * P);
    EXPECT_EQ(g.nodes()[2], 15 + 1 + 2 * P);
    EXPECT_EQ(g.numNodes(), g.numBlocks() * 64);
    for (int d = 0; d < 3; ++d)
        EXPECT_NEAR(g.origin()[d], -P * 0.1, 1e-15);
    EXPECT_NEAR(g.hi()[2], 1.5, 1e-15);
    checkNumbering(g);
}

TEST(Grid, BlockOfAndBlockCoordAgree) {
    const Grid<3> g(parse("bounds: {min: [0, 0, 0], max: [1, 1, 1]}\ncellSize: 0.125\n"));
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> u(1.0, g.nodes()[0] - 3.0);
    for (int t = 0; t < 1000; ++t) {
        const Vec<3> xh(u(rng), u(rng), u(rng));
        const IVec<3> c = g.blockCoord(g.blockOf(xh));
        for (int d = 0; d < 3; ++d)
            ASSERT_EQ(c[d], static_cast<int>(std::floor(xh[d])) / Grid<3>::BlockSize);
    }
}

TEST(Grid, InsideArrays) {
    const Grid<2> g(parse("bounds: {min: [0, 0], max: [1, 1]}\ncellSize: 0.25\n"));
    const double n = g.nodes()[0];
    EXPECT_TRUE(g.insideArrays(Vec<2>(1.0, 1.0)));
    EXPECT_FALSE(g.insideArrays(Vec<2>(0.999, 2.0)));
    EXPECT_FALSE(g.insideArrays(Vec<2>(2.0, n - 3.0)));
    EXPECT_TRUE(g.insideArrays(Vec<2>(2.0, std::nextafter(n - 3.0, 0.0))));
    // Every point of the box (with a cell of margin) is inside.
    const Vec<2> lo = (g.lo() - g.origin()) * g.invH();
    const Vec<2> hi = (g.hi() - g.origin()) * g.invH();
    EXPECT_TRUE(g.insideArrays(lo - Vec<2>::Constant(1.0)));
    EXPECT_TRUE(g.insideArrays(hi + Vec<2>::Constant(0.999)));
}

TEST(Grid, FaceNodeLists) {
    const Grid<3> g(parse("bounds: {min: [0, 0, 0], max: [1, 0.5, 0.75]}\ncellSize: 0.25\n"));
    constexpr int P = Grid<3>::Pad;
    for (int f = 0; f < Grid<3>::NumFaces; ++f) {
        SCOPED_TRACE(Grid<3>::faceName(f));
        const int axis = f / 2;
        const auto& list = g.faceNodes(f);
        Index expected = (P + 1);
        for (int d = 0; d < 3; ++d)
            if (d != axis) expected *= g.nodes()[d];
        EXPECT_EQ(static_cast<Index>(list.size()), expected);
        std::set<Index> unique(list.begin(), list.end());
        EXPECT_EQ(unique.size(), list.size());
        const double faceCoord = f % 2 == 0 ? g.lo()[axis] : g.hi()[axis];
        for (Index k : list) {
            const Vec<3> x = g.nodePosition(nodeCoord(g, k));
            if (f % 2 == 0)
                ASSERT_LE(x[axis], faceCoord + 1e-12);
            else
                ASSERT_GE(x[axis], faceCoord - 1e-12);
        }
        // And no node on or beyond the face is missing.
        Index onOrBeyond = 0;
        for (Index k : boxNodes(g)) {
            const double x = g.nodePosition(nodeCoord(g, k))[axis];
            if (f % 2 == 0 ? x <= faceCoord + 1e-12 : x >= faceCoord - 1e-12) ++onOrBeyond;
        }
        EXPECT_EQ(onOrBeyond, expected);
    }
    EXPECT_EQ(Grid<3>::faceName(0), "xMin");
    EXPECT_EQ(Grid<3>::faceName(5), "zMax");
}

TEST(Grid, ForEachNodeVisitsTheBoxNodesOfTheBlocks) {
    const Grid<3> g(parse("bounds: {min: [0, 0, 0], max: [1, 0.5, 0.75]}\ncellSize: 0.125\n"));
    std::vector<Index> all(static_cast<std::size_t>(g.numBlocks()));
    for (Index b = 0; b < g.numBlocks(); ++b)
        all[b] = b;
    std::vector<int> seen(g.numNodes(), 0);
    g.forEachNode(all, [&](Index k) { ++seen[k]; });
    std::vector<int> expected(g.numNodes(), 0);
    for (Index k : boxNodes(g))
        expected[k] = 1;
    EXPECT_EQ(seen, expected);
}

TEST(Grid, ActivateZeroesTheLastBlocksAndReleasesThoseLeft) {
    Grid<3> g(parse("bounds: {min: [0, 0, 0], max: [4, 1, 1]}\ncellSize: 0.0625\n"));
    constexpr Index B = Grid<3>::NodesPerBlock;
    std::vector<Index> first(32), second{40, 41};
    for (Index b = 0; b < 32; ++b)
        first[b] = b;
    g.activate(std::vector<Index>(first));
    for (Index b : first)
        for (Index k = b * B; k < (b + 1) * B; ++k) {
            g.mass[k] = 1.0;
            g.v[k] = Vec<3>(1, 2, 3);
        }
    g.activate(std::vector<Index>(second));
    EXPECT_EQ(g.activeBlocks(), second);
    // The pages wholly inside the blocks left are given back (not resident; a read would map
    // the zero page), and every node of them reads zero.
    EXPECT_EQ(residentPages(g.mass.data(), 32 * B * sizeof(double)), 0);
    EXPECT_EQ(residentPages(g.v.data(), 32 * B * sizeof(Vec<3>)), 0);
    for (Index k = 0; k < 42 * B; ++k) {
        ASSERT_EQ(g.mass[k], 0.0) << k;
        ASSERT_EQ(g.v[k], Vec<3>::Zero()) << k;
    }
}

TEST(Grid, CellSizeNotDividingBoxIsAnError) {
    const InputError e = catchInputError(
        [] { Grid<2> g(parse("bounds: {min: [0, 0], max: [1, 1]}\ncellSize: 0.3\n")); });
    EXPECT_EQ(e.key(), "cellSize") << e.what();
    EXPECT_NE(std::string(e.what()).find("whole number of cells"), std::string::npos) << e.what();
}

TEST(Grid, MaxNotAboveMinIsAnError) {
    for (const char* text : {"bounds: {min: [0, 0], max: [1, 0]}\ncellSize: 0.25\n",
                             "bounds: {min: [0, 0], max: [-1, 1]}\ncellSize: 0.25\n"}) {
        const InputError e = catchInputError([text] { Grid<2> g(parse(text)); });
        EXPECT_NE(std::string(e.what()).find("max must exceed min"), std::string::npos) << e.what();
    }
}

TEST(Grid, OtherInputErrors) {
    // Non-positive cell size, wrong vector length (boundary keys: BoundaryConditionsTest).
    for (const char* text : {"bounds: {min: [0, 0], max: [1, 1]}\ncellSize: 0\n",
                             "bounds: {min: [0, 0, 0], max: [1, 1]}\ncellSize: 0.25\n"}) {
        SCOPED_TRACE(text);
        EXPECT_THROW(Grid<2> g(parse(text)), InputError);
    }
}

// ---------------------------------------------------------------------------------------------
// BlockSort colouring

template <int dim> Particles<dim> randomParticles(const Grid<dim>& g, int n, unsigned seed) {
    Particles<dim> p;
    p.resize(n);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (int i = 0; i < n; ++i)
        for (int d = 0; d < dim; ++d)
            p.x[i][d] = g.lo()[d] + u(rng) * (g.hi()[d] - g.lo()[d]);
    return p;
}

/// Nodes any kernel's stencil can touch from xh: [floor(xh) - 1, floor(xh) + 2] per axis.
template <int dim> void stencilNodes(const Grid<dim>& g, const Vec<dim>& xh, std::set<Index>& out) {
    IVec<dim> f;
    for (int d = 0; d < dim; ++d)
        f[d] = static_cast<int>(std::floor(xh[d])) - 1;
    const int S = dim == 2 ? 16 : 64;
    for (int s = 0; s < S; ++s) {
        IVec<dim> c;
        int r = s;
        for (int d = 0; d < dim; ++d) {
            c[d] = f[d] + r % 4;
            r /= 4;
        }
        out.insert(g.nodeIndex(c));
    }
}

template <int dim> void checkColouring(const Grid<dim>& g, int n, unsigned seed) {
    const Particles<dim> p = randomParticles(g, n, seed);
    BlockSort<dim> sort;
    ASSERT_EQ(sort.update(p, g), -1);

    // order() is a permutation, grouped by block, stable within a block.
    const auto& order = sort.order();
    ASSERT_EQ(order.size(), p.size());
    std::vector<int> seen(p.size(), 0);
    for (Index b = 0; b < g.numBlocks(); ++b) {
        const auto r = sort.particlesOf(b);
        for (Index j = r.begin; j < r.end; ++j) {
            const Index i = order[j];
            ++seen[i];
            ASSERT_EQ(g.blockOf((p.x[i] - g.origin()) * g.invH()), b);
            if (j > r.begin) {
                ASSERT_LT(order[j - 1], i);
            }
        }
    }
    for (int s : seen)
        ASSERT_EQ(s, 1);

    // Every non-empty block is in exactly one colour list, that of its coordinate parity.
    std::vector<int> listed(g.numBlocks(), 0);
    for (int c = 0; c < BlockSort<dim>::NumColours; ++c)
        for (Index b : sort.blocksOfColour(c)) {
            ++listed[b];
            const IVec<dim> bc = g.blockCoord(b);
            int colour = 0;
            for (int d = 0; d < dim; ++d)
                colour |= (bc[d] & 1) << d;
            EXPECT_EQ(colour, c);
        }
    for (Index b = 0; b < g.numBlocks(); ++b)
        EXPECT_EQ(listed[b], sort.particlesOf(b).end > sort.particlesOf(b).begin ? 1 : 0)
            << "block " << b;

    // Brute force: within one colour, no two blocks' particles share a stencil node — neither
    // with the particles present nor for any point the block could hold.
    std::set<Index> active(sort.activeNodeBlocks().begin(), sort.activeNodeBlocks().end());
    for (int c = 0; c < BlockSort<dim>::NumColours; ++c) {
        const auto& blocks = sort.blocksOfColour(c);
        std::vector<std::set<Index>> nodes(blocks.size()), worst(blocks.size());
        for (std::size_t bi = 0; bi < blocks.size(); ++bi) {
            const Index b = blocks[bi];
            for (Index j = sort.particlesOf(b).begin; j < sort.particlesOf(b).end; ++j) {
                const Vec<dim> xh = (p.x[order[j]] - g.origin()) * g.invH();
                stencilNodes(g, xh, nodes[bi]);
            }
            // Worst case: the block's 4^dim cells, each stencil clipped to the arrays.
            const IVec<dim> bc = g.blockCoord(b);
            const int cells = dim == 2 ? 16 : 64;
            for (int s = 0; s < cells; ++s) {
                Vec<dim> xh;
                int r = s;
                bool ok = true;
                for (int d = 0; d < dim; ++d) {
                    xh[d] = Grid<dim>::BlockSize * bc[d] + r % 4 + 0.5;
                    r /= 4;
                    if (xh[d] < 1.0 || xh[d] + 2.0 >= g.nodes()[d]) ok = false;
                }
                if (ok) stencilNodes(g, xh, worst[bi]);
            }
            // Nodes that can receive mass lie in active node blocks.
            for (Index k : nodes[bi]) {
                const IVec<dim> nc = nodeCoord(g, k);
                Index nb = 0;
                for (int d = dim - 1; d >= 0; --d)
                    nb = nb * g.blocks()[d] + nc[d] / Grid<dim>::BlockSize;
                ASSERT_TRUE(active.count(nb)) << "node " << k << " of block " << b;
            }
        }
        for (std::size_t a = 0; a < blocks.size(); ++a)
            for (std::size_t b = a + 1; b < blocks.size(); ++b) {
                for (Index k : nodes[a])
                    ASSERT_FALSE(nodes[b].count(k)) << "colour " << c << ": blocks " << blocks[a]
                                                    << " and " << blocks[b] << " share node " << k;
                for (Index k : worst[a])
                    ASSERT_FALSE(worst[b].count(k))
                        << "colour " << c << ": blocks " << blocks[a] << " and " << blocks[b]
                        << " could share node " << k;
            }
    }
}

TEST(BlockSort, SameColourBlocksShareNoStencilNode2D) {
    const Grid<2> g(parse("bounds: {min: [0, 0], max: [1, 1.5]}\ncellSize: 0.0625\n"));
    checkColouring(g, 3000, 1);
}

TEST(BlockSort, SameColourBlocksShareNoStencilNode3D) {
    const Grid<3> g(parse("bounds: {min: [0, 0, 0], max: [1, 0.75, 1.25]}\ncellSize: 0.125\n"));
    checkColouring(g, 3000, 2);
}

/// The sort's range of every block holds the particles of byBlock[block] (each list in storage
/// order), the blocks one after the other in ascending order.
template <int dim>
void expectBlockRanges(const BlockSort<dim>& sort, const std::vector<std::vector<Index>>& byBlock) {
    Index pos = 0;
    for (Index blk = 0; blk < static_cast<Index>(byBlock.size()); ++blk) {
        const auto r = sort.particlesOf(blk);
        ASSERT_EQ(r.end - r.begin, static_cast<Index>(byBlock[blk].size())) << blk;
        if (byBlock[blk].empty()) continue;
        ASSERT_EQ(r.begin, pos) << blk;
        for (Index j = r.begin; j < r.end; ++j)
            ASSERT_EQ(sort.order()[j], byBlock[blk][j - r.begin]);
        pos = r.end;
    }
    EXPECT_EQ(pos, static_cast<Index>(sort.order().size()));
}

TEST(BlockSort, ReusedSortEqualsAFreshOneAndCountingSort) {
    // 5832 blocks: one radix pass, whose digit counts give the block ranges. A sort updated
    // first with other particles (the per-block index forgotten entry by entry) gives what a
    // fresh sort and a counting sort over every block give.
    const Grid<3> g(parse("bounds: {min: [0, 0, 0], max: [1, 1, 1]}\ncellSize: 0.015625\n"));
    ASSERT_GT(g.numBlocks(), 2048);
    const Particles<3> a = randomParticles(g, 4000, 5);
    Particles<3> b = randomParticles(g, 3000, 6);
    for (auto& x : b.x)
        x = 0.3 * x; // a corner of the box: most of a's blocks empty now
    BlockSort<3> reused, fresh;
    ASSERT_EQ(reused.update(a, g), -1);
    ASSERT_EQ(reused.update(b, g), -1);
    ASSERT_EQ(fresh.update(b, g), -1);
    EXPECT_EQ(reused.order(), fresh.order());
    EXPECT_EQ(reused.occupiedBlocks(), fresh.occupiedBlocks());
    EXPECT_EQ(reused.activeNodeBlocks(), fresh.activeNodeBlocks());
    for (int c = 0; c < BlockSort<3>::NumColours; ++c)
        EXPECT_EQ(reused.blocksOfColour(c), fresh.blocksOfColour(c));
    std::vector<std::vector<Index>> byBlock(g.numBlocks());
    for (Index i = 0; i < static_cast<Index>(b.size()); ++i)
        byBlock[g.blockOf((b.x[i] - g.origin()) * g.invH())].push_back(i);
    expectBlockRanges(reused, byBlock);
}

TEST(BlockSort, SortIsTheStableCountingSortForAnyThreadCount) {
    // 262 144 blocks: two radix passes; 20 000 particles: the slices of a thread team.
    const Grid<3> g(parse("bounds: {min: [0, 0, 0], max: [1, 1, 1]}\ncellSize: 0.00390625\n"));
    ASSERT_GT(g.numBlocks(), 65536);
    const Particles<3> p = randomParticles(g, 20000, 8);
    std::vector<std::vector<Index>> byBlock(g.numBlocks());
    for (Index i = 0; i < static_cast<Index>(p.size()); ++i)
        byBlock[g.blockOf((p.x[i] - g.origin()) * g.invH())].push_back(i);
    std::vector<Index> expected;
    for (const auto& b : byBlock)
        expected.insert(expected.end(), b.begin(), b.end());
    const int threads = omp_get_max_threads();
    for (int t : {1, 2, 3}) {
        omp_set_num_threads(t);
        BlockSort<3> sort;
        ASSERT_EQ(sort.update(p, g), -1);
        EXPECT_EQ(sort.order(), expected) << t << " threads";
        expectBlockRanges(sort, byBlock); // the two-pass sort's, found from the sorted keys
    }
    omp_set_num_threads(threads);
}

TEST(BlockSort, ThreadSharesPartitionEachColourAndVisitOrderFollowsThem) {
    // Each colour's blocks are split into contiguous shares, one per thread, that cover every
    // block once and hold 1/team of the colour's particles to within one block's; visitOrder lists
    // the particles in exactly the order forEachBlockByColour visits them, on any team.
    const Grid<3> g(parse("bounds: {min: [0, 0, 0], max: [1, 1, 1]}\ncellSize: 0.03125\n"));
    const Particles<3> p = randomParticles(g, 20000, 9);
    BlockSort<3> sort;
    ASSERT_EQ(sort.update(p, g), -1);
    const auto& order = sort.order();
    std::vector<Index> visit;
    sort.visitOrder(visit);
    ASSERT_EQ(visit.size(), p.size());
    std::vector<Index> sorted = visit;
    std::sort(sorted.begin(), sorted.end());
    for (Index i = 0; i < static_cast<Index>(sorted.size()); ++i)
        ASSERT_EQ(sorted[i], i);
    for (int team : {1, 2, 3, 7}) {
        std::vector<Index> walked;
        for (int c = 0; c < BlockSort<3>::NumColours; ++c) {
            const auto& blocks = sort.blocksOfColour(c);
            Index next = 0, total = 0, biggestBlock = 0;
            std::vector<Index> counts;
            for (int t = 0; t < team; ++t) {
                const auto share = sort.shareOf(c, t, team);
                ASSERT_EQ(share.begin, next) << "colour " << c << ", thread " << t;
                ASSERT_LE(share.begin, share.end);
                next = share.end;
                Index count = 0;
                for (Index k = share.begin; k < share.end; ++k) {
                    const auto r = sort.particlesOf(blocks[k]);
                    count += r.end - r.begin;
                    biggestBlock = std::max(biggestBlock, r.end - r.begin);
                    walked.insert(walked.end(), order.begin() + r.begin, order.begin() + r.end);
                }
                counts.push_back(count);
                total += count;
            }
            EXPECT_EQ(next, static_cast<Index>(blocks.size())) << "colour " << c;
            for (Index count : counts)
                EXPECT_LE(std::abs(static_cast<double>(count) - static_cast<double>(total) / team),
                          biggestBlock + 1.0)
                    << "colour " << c << ", team " << team;
        }
        EXPECT_EQ(walked, visit) << team << " threads";
    }
}

TEST(BlockSort, ReportsFirstParticleOutsideArrays) {
    const Grid<2> g(parse("bounds: {min: [0, 0], max: [1, 1]}\ncellSize: 0.25\n"));
    Particles<2> p = randomParticles(g, 10, 3);
    BlockSort<2> sort;
    EXPECT_EQ(sort.update(p, g), -1);
    p.x[7] = Vec<2>(0.5, 10.0);
    p.x[4] = Vec<2>(-2.0, 0.5);
    EXPECT_EQ(sort.update(p, g), 4);
    // A point one cell outside the box is still inside the arrays.
    p.x[4] = Vec<2>(-0.24, 0.5);
    p.x[7] = Vec<2>(1.24, 1.24);
    EXPECT_EQ(sort.update(p, g), -1);
}

} // namespace
} // namespace mpm
