// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/PointBins.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <vector>

using mpm::PointBins;
using mpm::Vec;

namespace {

template <int dim> std::vector<Vec<dim>> randomPoints(std::size_t n, double side, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, side);
    std::vector<Vec<dim>> x(n);
    for (auto& p : x)
        for (int d = 0; d < dim; ++d)
            p[d] = u(rng);
    return x;
}

/// Every point within ring · cellSize() of each query is in its block, and no index twice;
/// the queries reach a cell beyond the box on every side.
template <int dim>
void expectBlocksComplete(const std::vector<Vec<dim>>& x, const PointBins<dim>& bins, int ring,
                          double side) {
    const double reach = ring * bins.cellSize();
    for (const auto& q : randomPoints<dim>(300, side + 2.0 * reach, 11)) {
        const Vec<dim> y = q - Vec<dim>::Constant(reach);
        std::multiset<std::size_t> seen;
        bins.forEachNear(y, ring, [&](std::size_t j) { seen.insert(j); });
        for (std::size_t j = 0; j < x.size(); ++j) {
            EXPECT_LE(seen.count(j), 1U);
            if ((x[j] - y).norm() <= reach) {
                EXPECT_EQ(seen.count(j), 1U) << "point " << j;
            }
        }
    }
}

} // namespace

TEST(PointBins, BlocksHoldEveryPointWithinRingCells2D) {
    const auto x = randomPoints<2>(400, 1.0, 1);
    const PointBins<2> bins(x, 0.07);
    EXPECT_EQ(bins.cellSize(), 0.07);
    expectBlocksComplete<2>(x, bins, 1, 1.0);
    expectBlocksComplete<2>(x, bins, 2, 1.0);
}

TEST(PointBins, BlocksHoldEveryPointWithinRingCells3D) {
    const auto x = randomPoints<3>(500, 1.0, 2);
    const PointBins<3> bins(x, 0.15);
    expectBlocksComplete<3>(x, bins, 1, 1.0);
}

TEST(PointBins, AGivenBoxLargerThanThePointsKeepsBlocksComplete) {
    const auto x = randomPoints<2>(200, 0.5, 3);
    const Eigen::AlignedBox<double, 2> box(Vec<2>(-1.0, -1.0), Vec<2>(2.0, 2.0));
    const PointBins<2> bins(x, 0.1, box);
    expectBlocksComplete<2>(x, bins, 1, 0.5);
}

TEST(PointBins, BlockVisitsCellsInOrderAndIndicesAscendingWithinACell) {
    // Three points in one cell, one in the next along x: the cell's first, then the next.
    const std::vector<Vec<2>> x = {{1.5, 0.5}, {0.5, 0.5}, {0.2, 0.1}, {0.9, 0.9}, {5.0, 5.0}};
    const PointBins<2> bins(x, 1.0);
    std::vector<std::size_t> order;
    bins.forEachNear(Vec<2>(0.5, 0.5), 1, [&](std::size_t j) { order.push_back(j); });
    EXPECT_EQ(order, (std::vector<std::size_t>{1, 2, 3, 0}));
}

TEST(PointBins, AnyNearStopsAtTheFirstMatch) {
    const std::vector<Vec<2>> x = {{0.1, 0.1}, {0.2, 0.2}, {0.3, 0.3}};
    const PointBins<2> bins(x, 1.0);
    int calls = 0;
    EXPECT_TRUE(bins.anyNear(Vec<2>(0.0, 0.0), 1, [&](std::size_t j) {
        ++calls;
        return j == 1;
    }));
    EXPECT_EQ(calls, 2);
    EXPECT_FALSE(bins.anyNear(Vec<2>(0.0, 0.0), 1, [](std::size_t) { return false; }));
}

TEST(PointBins, ATinyCellOverAWideSpreadGrowsAndStaysComplete) {
    // 1e-9 m cells over a 1 m spread would be 1e18 cells; the bins take ~8 a point instead.
    auto x = randomPoints<3>(100, 1.0, 4);
    const PointBins<3> bins(x, 1e-9);
    EXPECT_GT(bins.cellSize(), 1e-9);
    EXPECT_LE(std::pow(1.0 / bins.cellSize(), 3), 8.0 * 100 * 8.0);
    expectBlocksComplete<3>(x, bins, 1, 1.0);
}

TEST(PointBins, NoPointsAndBadCellSizes) {
    const std::vector<Vec<2>> none;
    const PointBins<2> empty(none, 0.1);
    int calls = 0;
    empty.forEachNear(Vec<2>(0.0, 0.0), 2, [&](std::size_t) { ++calls; });
    EXPECT_EQ(calls, 0);
    const std::vector<Vec<2>> one = {{0.0, 0.0}};
    EXPECT_THROW(PointBins<2>(one, 0.0), std::invalid_argument);
    EXPECT_THROW(PointBins<2>(one, -1.0), std::invalid_argument);
    EXPECT_THROW(PointBins<2>(one, std::nan("")), std::invalid_argument);
}
