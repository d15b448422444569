// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/Seeding.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace mpm {
namespace {

template <int dim> std::unique_ptr<Region<dim>> makeRegion(const std::string& yaml) {
    return Region<dim>::create(Dictionary::fromString(yaml, "test"));
}

/// Smallest pairwise distance (brute force).
template <int dim> double minPairDistance(const std::vector<Vec<dim>>& p) {
    double m2 = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < p.size(); ++i) {
        for (std::size_t j = i + 1; j < p.size(); ++j)
            m2 = std::min(m2, (p[i] - p[j]).squaredNorm());
    }
    return std::sqrt(m2);
}

TEST(SeedingTest, DropSmallClustersKeepsTheGroupsOfAtLeastMinCountInOrder) {
    // A 3 x 3 lattice (spacing 1), a pair 1 apart and a lone point, far from each other.
    std::vector<Vec<2>> p;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 3; ++i)
            p.emplace_back(i, j);
    p.insert(p.begin() + 4, Vec<2>(10, 0)); // the lone point, amid the lattice's order
    p.emplace_back(20, 0);
    p.emplace_back(20, 1);
    const std::vector<Vec<2>> all = p;
    EXPECT_EQ(dropSmallClusters(p, 1.5, 1), 0u);
    EXPECT_EQ(p, all);
    EXPECT_EQ(dropSmallClusters(p, 1.5, 2), 1u); // the lone point
    EXPECT_EQ(p.size(), 11u);
    EXPECT_EQ(dropSmallClusters(p, 1.5, 3), 2u); // the pair
    ASSERT_EQ(p.size(), 9u);
    for (int k = 0; k < 9; ++k)
        EXPECT_EQ(p[k], Vec<2>(k % 3, k / 3)) << k; // the lattice, in its order
    // A link shorter than the spacing leaves every point alone.
    EXPECT_EQ(dropSmallClusters(p, 0.9, 2), 9u);
    EXPECT_TRUE(p.empty());
    EXPECT_THROW(dropSmallClusters(p, 0.0, 2), std::invalid_argument);
}

TEST(SeedingTest, DropSmallClustersLinksDiagonalsIn3D) {
    std::vector<Vec<3>> p{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {5, 5, 5}};
    EXPECT_EQ(dropSmallClusters(p, std::sqrt(3.0) * 1.0001, 3), 1u);
    EXPECT_EQ(p.size(), 3u);
}

TEST(SeedingTest, RegularBoxAlignedToGrid2D) {
    const auto box = makeRegion<2>("type: box\nmin: [0.2, -0.3]\nmax: [1.2, 0.5]\n");
    const double h = 0.1;
    const auto p = seedRegular<2>(*box, Vec<2>(0.0, 0.1), h, 2);
    ASSERT_EQ(p.size(), std::size_t(10 * 8 * 4));
    // Sub-cell centres, first point in the lowest cell, x fastest within a cell.
    EXPECT_TRUE(p[0].isApprox(Vec<2>(0.225, -0.275)));
    EXPECT_TRUE(p[1].isApprox(Vec<2>(0.275, -0.275)));
    EXPECT_TRUE(p[2].isApprox(Vec<2>(0.225, -0.225)));
    EXPECT_TRUE(p[4].isApprox(Vec<2>(0.325, -0.275))); // next cell in x
    for (const auto& x : p)
        EXPECT_TRUE(box->contains(x));
    // Volume check: N (h / n)^2 = box volume.
    EXPECT_NEAR(p.size() * std::pow(h / 2, 2), box->volume(), 1e-12);
}

TEST(SeedingTest, RegularBoxAlignedToGrid3D) {
    const auto box = makeRegion<3>("type: box\nmin: [0, 0, 0]\nmax: [1, 0.5, 0.75]\n");
    const auto p = seedRegular<3>(*box, Vec<3>::Zero(), 0.25, 3);
    EXPECT_EQ(p.size(), std::size_t(4 * 2 * 3 * 27));
    const auto q = seedRegular<3>(*box, Vec<3>::Zero(), 0.25, 1);
    EXPECT_EQ(q.size(), std::size_t(4 * 2 * 3));
}

TEST(SeedingTest, RegularDiskVolume) {
    const auto disk = makeRegion<2>("type: disk\ncentre: [0.03, 0.01]\nradius: 1\n");
    const double h = 0.02;
    const auto p = seedRegular<2>(*disk, Vec<2>::Zero(), h, 2);
    EXPECT_NEAR(p.size() * std::pow(h / 2, 2), disk->volume(), 1e-3 * disk->volume());
    for (const auto& x : p)
        EXPECT_TRUE(disk->contains(x));
}

TEST(SeedingTest, RegularBadArguments) {
    const auto box = makeRegion<2>("type: box\nmin: [0, 0]\nmax: [1, 1]\n");
    EXPECT_THROW(seedRegular<2>(*box, Vec<2>::Zero(), 0.0, 2), std::invalid_argument);
    EXPECT_THROW(seedRegular<2>(*box, Vec<2>::Zero(), 0.1, 0), std::invalid_argument);
}

TEST(SeedingTest, PoissonDiskMinimumDistanceAndInside2D) {
    const auto poly = makeRegion<2>("type: polygon\nvertices: [[0, 0], [3, 1], [6, 0], [5, 3], [6, "
                                    "6], [3, 4], [0, 6], [1, 3]]\n");
    const double r = 0.1;
    const auto p = seedPoissonDisk<2>(*poly, r, 7);
    ASSERT_GT(p.size(), 1000u);
    for (const auto& x : p)
        EXPECT_TRUE(poly->contains(x));
    EXPECT_GE(minPairDistance<2>(p), r * (1.0 - 1e-12));
    // The concave arms are filled: density close to the bulk value (walls add a little).
    const double rho = p.size() * r * r / poly->volume();
    EXPECT_GT(rho, 0.60);
    EXPECT_LT(rho, 0.68);
}

TEST(SeedingTest, PoissonDiskMinimumDistanceAndInside3D) {
    const auto cyl = makeRegion<3>("type: cylinder\np1: [0, 0, 0]\np2: [1, 1, 1]\nradius: 0.4\n");
    const double r = 0.08;
    const auto p = seedPoissonDisk<3>(*cyl, r, 3);
    ASSERT_GT(p.size(), 500u);
    for (const auto& x : p)
        EXPECT_TRUE(cyl->contains(x));
    EXPECT_GE(minPairDistance<3>(p), r * (1.0 - 1e-12));
}

TEST(SeedingTest, PoissonDiskFillsDisconnectedParts) {
    // Two unit squares joined by a zero-width slit along y = 0.5 (even-odd rule: two separate
    // parts); the centre of the bounds lies outside, so both parts need seeds of their own.
    const auto twoSquares = makeRegion<2>(
        "type: polygon\nvertices: [[0, 0], [1, 0], [1, 0.5], [3, 0.5], [3, 0], [4, 0], [4, 1], "
        "[3, 1], [3, 0.5], [1, 0.5], [1, 1], [0, 1]]\n");
    ASSERT_DOUBLE_EQ(twoSquares->volume(), 2.0);
    ASSERT_FALSE(twoSquares->contains(Vec<2>(2.0, 0.5)));
    const double r = 0.05;
    const auto p = seedPoissonDisk<2>(*twoSquares, r, 11);
    int left = 0;
    int right = 0;
    for (const auto& x : p) {
        EXPECT_TRUE(twoSquares->contains(x));
        left += x.x() <= 1.0;
        right += x.x() >= 3.0;
    }
    EXPECT_EQ(left + right, int(p.size()));
    // Each square holds about its area times the bulk density 0.615 / r^2 (walls add a little).
    EXPECT_GT(left, 0.6 / (r * r));
    EXPECT_GT(right, 0.6 / (r * r));
}

TEST(SeedingTest, PoissonDiskCountMatchesParticlesPerCell) {
    {
        const double h = 0.025; // 40 x 40 cells
        const int ppc = 4;
        const auto box = makeRegion<2>("type: box\nmin: [0, 0]\nmax: [1, 1]\n");
        const auto p = seedPoissonDisk<2>(*box, poissonDiskSpacing(h, ppc, 2), 1);
        const double target = ppc * box->volume() / (h * h);
        EXPECT_NEAR(double(p.size()), target, 0.05 * target);
    }
    {
        const double h = 0.0625; // 16 x 16 x 16 cells
        const int ppc = 8;
        const auto box = makeRegion<3>("type: box\nmin: [0, 0, 0]\nmax: [1, 1, 1]\n");
        const auto p = seedPoissonDisk<3>(*box, poissonDiskSpacing(h, ppc, 3), 1);
        const double target = ppc * box->volume() / (h * h * h);
        EXPECT_NEAR(double(p.size()), target, 0.05 * target);
    }
}

TEST(SeedingTest, PoissonDiskDeterministicPerSeed) {
    const auto disk = makeRegion<2>("type: disk\ncentre: [0, 0]\nradius: 1\n");
    const auto a = seedPoissonDisk<2>(*disk, 0.05, 42);
    const auto b = seedPoissonDisk<2>(*disk, 0.05, 42);
    const auto c = seedPoissonDisk<2>(*disk, 0.05, 43);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i)
        EXPECT_EQ(a[i], b[i]);
    bool differ = a.size() != c.size();
    for (std::size_t i = 0; !differ && i < a.size(); ++i)
        differ = a[i] != c[i];
    EXPECT_TRUE(differ);
}

TEST(SeedingTest, PoissonDiskSortedByCell) {
    // Sorted by background-grid cell (size r / sqrt(2)), lexicographically, y slowest: the cell
    // row index never decreases.
    const auto box = makeRegion<2>("type: box\nmin: [0, 0]\nmax: [1, 1]\n");
    const double r = 0.05;
    const auto p = seedPoissonDisk<2>(*box, r, 5);
    const double h = r / std::sqrt(2.0);
    for (std::size_t i = 1; i < p.size(); ++i) {
        const int row0 = int(p[i - 1].y() / h);
        const int row1 = int(p[i].y() / h);
        ASSERT_LE(row0, row1);
        if (row0 == row1) {
            ASSERT_LT(p[i - 1].x(), p[i].x());
        }
    }
}

TEST(SeedingTest, VoronoiVolumesOfTwoPointsSplitAtTheBisector) {
    // Points at x = 0.25 and 1.25 in [0, 2] × [0, 1]: the bisector x = 0.75 falls between two
    // sample columns, so the cells are exactly 0.75 and 1.25.
    const auto box = makeRegion<2>("type: box\nmin: [0, 0]\nmax: [2, 1]\n");
    const std::vector<Vec<2>> p{{0.25, 0.5}, {1.25, 0.5}};
    const std::vector<double> v = voronoiVolumes<2>(*box, p, 1.0, 20);
    ASSERT_EQ(v.size(), 2u);
    EXPECT_NEAR(v[0], 0.75, 1e-12);
    EXPECT_NEAR(v[1], 1.25, 1e-12);
}

TEST(SeedingTest, VoronoiVolumesOfALatticeAreItsCells3D) {
    // The centres of a 4 × 4 × 4 lattice of the unit cube: every cell is 1/64.
    const auto cube = makeRegion<3>("type: box\nmin: [0, 0, 0]\nmax: [1, 1, 1]\n");
    std::vector<Vec<3>> p;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 4; ++i)
                p.emplace_back((i + 0.5) / 4, (j + 0.5) / 4, (k + 0.5) / 4);
    for (const double v : voronoiVolumes<3>(*cube, p, 0.25, 6))
        EXPECT_NEAR(v, 1.0 / 64, 1e-14);
}

TEST(SeedingTest, VoronoiVolumesOfPoissonDiskPointsFillTheRegionAndVary) {
    // A maximal Poisson-disk set: the cells tile the box (sum = its volume); away from the walls
    // (more than 2 r) their sizes spread by about ±10 % [002 §4.5] (here CV 0.125), and the
    // quadrature has converged (8 against 16 samples a spacing: 0.7 % rms a point).
    const auto box = makeRegion<3>("type: box\nmin: [0, 0, 0]\nmax: [1, 1, 0.4]\n");
    const double r = 0.06;
    const auto p = seedPoissonDisk<3>(*box, r, 5);
    const std::vector<double> v = voronoiVolumes<3>(*box, p, r, 8);
    const std::vector<double> fine = voronoiVolumes<3>(*box, p, r, 16);
    double sum = 0, bulk = 0, bulk2 = 0, err2 = 0;
    int nBulk = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        sum += v[i];
        err2 += std::pow(v[i] / fine[i] - 1, 2);
        if ((p[i].array() > 2 * r).all() &&
            (p[i].array() < Eigen::Array3d(1, 1, 0.4) - 2 * r).all()) {
            bulk += v[i];
            bulk2 += v[i] * v[i];
            ++nBulk;
        }
    }
    EXPECT_NEAR(sum, 0.4, 1e-12);
    EXPECT_LT(std::sqrt(err2 / p.size()), 0.015);
    ASSERT_GT(nBulk, 100);
    const double mean = bulk / nBulk;
    const double cv = std::sqrt(bulk2 / nBulk - mean * mean) / mean;
    EXPECT_GT(cv, 0.07);
    EXPECT_LT(cv, 0.20);
}

TEST(SeedingTest, VoronoiVolumesLeaveOutTheExcludedSpace) {
    // A disk of radius 0.2 excluded from the unit square: the cells share 1 − π 0.2².
    const auto square = makeRegion<2>("type: box\nmin: [0, 0]\nmax: [1, 1]\n");
    const double r = 0.02;
    const auto p = seedPoissonDisk<2>(*square, r, 2);
    const auto inDisk = [](const Vec<2>& x) { return (x - Vec<2>(0.5, 0.5)).norm() < 0.2; };
    const std::vector<double> v = voronoiVolumes<2>(*square, p, r, 12, inDisk);
    double sum = 0;
    for (const double vi : v)
        sum += vi;
    EXPECT_NEAR(sum, 1.0 - M_PI * 0.04, 3e-4);
}

TEST(SeedingTest, VoronoiVolumesAreTheSameOnAnyThreadCount) {
    const auto box = makeRegion<3>("type: box\nmin: [0, 0, 0]\nmax: [1, 1, 0.2]\n");
    const auto p = seedPoissonDisk<3>(*box, 0.05, 1);
    const int threads = omp_get_max_threads();
    omp_set_num_threads(1);
    const std::vector<double> one = voronoiVolumes<3>(*box, p, 0.05, 8);
    omp_set_num_threads(std::max(2, threads));
    const std::vector<double> many = voronoiVolumes<3>(*box, p, 0.05, 8);
    omp_set_num_threads(threads);
    EXPECT_EQ(one, many);
}

TEST(SeedingTest, VoronoiVolumesBadArguments) {
    const auto box = makeRegion<2>("type: box\nmin: [0, 0]\nmax: [1, 1]\n");
    const std::vector<Vec<2>> p{{0.5, 0.5}};
    EXPECT_THROW(voronoiVolumes<2>(*box, p, 0.0, 6), std::invalid_argument);
    EXPECT_THROW(voronoiVolumes<2>(*box, p, 0.1, 0), std::invalid_argument);
}

TEST(SeedingTest, PoissonDiskSpacing) {
    EXPECT_NEAR(poissonDiskSpacing(1.0, 4, 2), 0.785 / 2.0, 1e-12);
    EXPECT_NEAR(poissonDiskSpacing(2.0, 8, 3), 0.833, 1e-12);
    EXPECT_THROW(poissonDiskSpacing(1.0, 0, 2), std::invalid_argument);
    EXPECT_THROW(poissonDiskSpacing(1.0, 4, 1), std::invalid_argument);
}

} // namespace
} // namespace mpm
