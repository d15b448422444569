// SPDX-License-Identifier: GPL-3.0-or-later
// Periodic faces: the folded lattice is seamless for every kernel, the fold conserves mass and
// momentum, the active blocks are closed under the image map, particles wrap across the seam,
// and conditions on the other faces follow the owners.
#include "TestSupport.hpp"
#include "boundary/BoundaryConditions.hpp"
#include "kernels/Kernels.hpp"
#include "transfers/Transfer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace mpm {
namespace {

Dictionary parse(const std::string& text) {
    return Dictionary::fromString(text, "constant/grid");
}

template <int dim> struct Scene {
    Grid<dim> grid;
    BoundaryConditions<dim> bc;
    Scene(const std::string& box, const std::string& boundary)
        : grid(parse(box)), bc(parse(box + boundary), grid) {
        test::activateAll(grid); // the conditions act on every face node
        bc.selectActive(grid);
    }
};

template <int dim> IVec<dim> coordOf(const Grid<dim>& g, Index k) {
    return g.nodeCoord(k);
}

using test::boxNodes;

template <int dim> Index blockOfNode(const Grid<dim>& g, Index k) {
    const IVec<dim> c = coordOf(g, k);
    Index b = 0;
    for (int d = dim - 1; d >= 0; --d)
        b = b * g.blocks()[d] + c[d] / Grid<dim>::BlockSize;
    return b;
}

template <int dim> void initParticle(Particles<dim>& p, std::size_t i) {
    p.C[i].setZero();
    p.L[i].setZero();
    p.F[i].setIdentity();
    p.be[i].setIdentity();
    p.stress[i].setZero();
    p.volume0[i] = p.volume[i] = 1e-3;
    p.plasticStrain[i] = 0;
    p.id[i] = static_cast<Index>(i);
    p.material[i] = 0;
}

/// 2 particles per direction per cell over the whole box, unit mass, velocity u.
template <int dim> Particles<dim> uniformParticles(const Grid<dim>& g, const Vec<dim>& u) {
    IVec<dim> cells;
    Index n = 1;
    for (int d = 0; d < dim; ++d) {
        cells[d] = 2 * static_cast<int>(std::lround((g.hi()[d] - g.lo()[d]) / g.h()));
        n *= cells[d];
    }
    Particles<dim> p;
    p.resize(n);
    for (Index i = 0; i < n; ++i) {
        Index r = i;
        for (int d = 0; d < dim; ++d) {
            p.x[i][d] = g.lo()[d] + (static_cast<double>(r % cells[d]) + 0.5) * 0.5 * g.h();
            r /= cells[d];
        }
        p.v[i] = u;
        p.mass[i] = 1.0;
        initParticle(p, i);
    }
    return p;
}

template <int dim>
Particles<dim> randomParticles(const Grid<dim>& g, int n, unsigned seed, bool affine) {
    Particles<dim> p;
    p.resize(n);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    for (int i = 0; i < n; ++i) {
        initParticle(p, i);
        for (int d = 0; d < dim; ++d) {
            p.x[i][d] = g.lo()[d] + u(rng) * (g.hi()[d] - g.lo()[d]);
            p.v[i][d] = s(rng);
        }
        if (affine)
            for (int k = 0; k < dim * dim; ++k)
                p.C[i](k) = 3.0 * s(rng);
        p.mass[i] = 0.5 + u(rng);
    }
    return p;
}

/// The solver's P2G with periodic faces: zero, close the active blocks, scatter, fold.
template <int dim>
std::vector<Index> scatterAndFold(const std::string& kernel, const std::string& transfer,
                                  const Particles<dim>& p, Scene<dim>& s) {
    Grid<dim>& g = s.grid;
    std::fill(g.mass.begin(), g.mass.end(), 0.0);
    std::fill(g.momentum.begin(), g.momentum.end(), Vec<dim>::Zero());
    std::fill(g.force.begin(), g.force.end(), Vec<dim>::Zero());
    auto t = Transfer<dim>::create(
        Dictionary::fromString("kernel: " + kernel + "\ntransfer: " + transfer + "\n",
                               "system/mpmSchemes"),
        0.25);
    BlockSort<dim> sort;
    EXPECT_EQ(sort.update(p, g), -1);
    std::vector<Index> blocks = sort.activeNodeBlocks();
    s.bc.closeActiveBlocks(blocks);
    t->computeWeights(p, g);
    t->scatter(p, g, sort, false);
    s.bc.fold(g, blocks, FoldAll);
    return blocks;
}

/// Every image equals its owner exactly (mass and momentum).
template <int dim> void expectImagesEqualOwners(const Scene<dim>& s) {
    const auto& L = s.bc.lattice();
    for (Index k : boxNodes(s.grid)) {
        const Index o = L.owner(k);
        ASSERT_EQ(s.grid.mass[k], s.grid.mass[o]) << k;
        ASSERT_EQ(s.grid.momentum[k], s.grid.momentum[o]) << k;
    }
}

const std::string periodic2D = "bounds: {min: [-0.5, 0], max: [0.5, 0.75]}\ncellSize: 0.0625\n";

TEST(PeriodicLattice, SeamlessForEveryKernel2D) {
    // Both axes periodic: every node of the folded lattice is an interior node, with the mass
    // of 2 × 2 unit particles and their momentum.
    const Vec<2> u(0.7, -0.3);
    for (const std::string& kernel : kernelNames()) {
        SCOPED_TRACE(kernel);
        Scene<2> s(periodic2D, "boundary: {xMin: periodic, xMax: periodic, yMin: periodic, "
                               "yMax: periodic}\n");
        const Particles<2> p = uniformParticles(s.grid, u);
        scatterAndFold<2>(kernel, "pic", p, s);
        const auto& L = s.bc.lattice();
        Index owners = 0;
        for (Index k : boxNodes(s.grid)) {
            if (!L.isOwner(k)) continue;
            ++owners;
            ASSERT_NEAR(s.grid.mass[k], 4.0, 1e-12) << k;
            ASSERT_NEAR((s.grid.momentum[k] - 4.0 * u).norm(), 0.0, 1e-12) << k;
        }
        EXPECT_EQ(owners, 16 * 12);
        expectImagesEqualOwners(s);
    }
}

TEST(PeriodicLattice, SeamlessForEveryKernel3D) {
    // x and z periodic, y walled: along the periodic axes every owner node has the mass of an
    // interior node of its y layer; 8 unit particles in the layers away from the walls.
    const std::string box = "bounds: {min: [0, 0, 0], max: [0.5, 0.5, 0.375]}\ncellSize: 0.125\n";
    for (const std::string& kernel : kernelNames()) {
        SCOPED_TRACE(kernel);
        Scene<3> s(box, "boundary: {xMin: periodic, xMax: periodic, zMin: periodic, "
                        "zMax: periodic, yMin: noSlip}\n");
        const Particles<3> p = uniformParticles(s.grid, Vec<3>(1, 2, 3));
        scatterAndFold<3>(kernel, "pic", p, s);
        const auto& L = s.bc.lattice();
        const auto& n = s.grid.nodes();
        for (int j = 0; j < n[1]; ++j) {
            const double layer =
                s.grid.mass[s.grid.nodeIndex(IVec<3>(Grid<3>::Pad, j, Grid<3>::Pad))];
            const double y = s.grid.nodePosition(IVec<3>(0, j, 0))[1];
            if (y > 0.2 && y < 0.3) {
                EXPECT_NEAR(layer, 8.0, 1e-12) << j;
            }
            for (Index k : boxNodes(s.grid)) {
                if (L.isOwner(k) && coordOf(s.grid, k)[1] == j) {
                    ASSERT_NEAR(s.grid.mass[k], layer, 1e-12) << k;
                }
            }
        }
        expectImagesEqualOwners(s);
    }
}

template <int dim> void checkFoldConserves(const std::string& box, const std::string& boundary) {
    for (const std::string& kernel : kernelNames())
        for (const char* transfer : {"pic", "apic"}) {
            if (std::string(transfer) == "apic" && kernel != "quadraticBSpline" &&
                kernel != "cubicBSpline")
                continue;
            SCOPED_TRACE(kernel + " " + transfer);
            Scene<dim> s(box, boundary);
            const Particles<dim> p =
                randomParticles(s.grid, 1500, 5, std::string(transfer) == "apic");
            const std::vector<Index> blocks = scatterAndFold<dim>(kernel, transfer, p, s);
            double mass = 0, scale = 0;
            Vec<dim> momentum = Vec<dim>::Zero();
            for (std::size_t i = 0; i < p.size(); ++i) {
                mass += p.mass[i];
                momentum += p.mass[i] * p.v[i];
                scale += p.mass[i] * p.v[i].norm();
            }
            double gm = 0;
            Vec<dim> gp = Vec<dim>::Zero();
            std::set<Index> closed(blocks.begin(), blocks.end());
            for (Index k : boxNodes(s.grid)) {
                if (s.grid.mass[k] != 0 || s.grid.momentum[k] != Vec<dim>::Zero()) {
                    ASSERT_TRUE(closed.count(blockOfNode(s.grid, k))) << "node " << k;
                }
                if (!s.bc.lattice().isOwner(k)) continue;
                gm += s.grid.mass[k];
                gp += s.grid.momentum[k];
            }
            EXPECT_NEAR(gm, mass, 1e-12 * mass);
            EXPECT_LE((gp - momentum).norm(), 1e-12 * scale);
            expectImagesEqualOwners(s);
        }
}

TEST(PeriodicLattice, FoldConservesMassAndMomentum2D) {
    checkFoldConserves<2>(periodic2D, "boundary: {xMin: periodic, xMax: periodic, yMin: noSlip}\n");
}

TEST(PeriodicLattice, FoldConservesMassAndMomentum3D) {
    checkFoldConserves<3>("bounds: {min: [0, 0, 0], max: [0.5, 0.375, 0.625]}\ncellSize: 0.125\n",
                          "boundary: {yMin: periodic, yMax: periodic, zMin: periodic, zMax: "
                          "periodic}\n");
}

TEST(PeriodicLattice, ClosedActiveBlocksHoldEveryImageAndOwner) {
    // Particles only near xMax: their stencils reach the ghost layers beyond it, whose owners
    // lie at xMin, in blocks that BlockSort does not mark.
    Scene<2> s(periodic2D, "boundary: {xMin: periodic, xMax: periodic}\n");
    const Grid<2>& g = s.grid;
    Particles<2> p = randomParticles(g, 200, 9, false);
    for (auto& x : p.x)
        x[0] = 0.5 - 0.1 * (x[0] + 0.5);
    BlockSort<2> sort;
    ASSERT_EQ(sort.update(p, g), -1);
    const std::vector<Index> open = sort.activeNodeBlocks();
    std::vector<Index> closed = open;
    s.bc.closeActiveBlocks(closed);
    EXPECT_TRUE(std::is_sorted(closed.begin(), closed.end()));
    EXPECT_EQ(std::set<Index>(closed.begin(), closed.end()).size(), closed.size());
    EXPECT_GT(closed.size(), open.size());
    const std::set<Index> a(open.begin(), open.end()), c(closed.begin(), closed.end());
    for (Index b : open)
        EXPECT_TRUE(c.count(b));
    // Every node of the same class as a node of an open block lies in a closed block.
    const auto& L = s.bc.lattice();
    const std::vector<Index> nodes = boxNodes(g);
    for (Index k : nodes)
        for (Index j : nodes) {
            if (L.owner(j) == L.owner(k) && a.count(blockOfNode(g, k))) {
                ASSERT_TRUE(c.count(blockOfNode(g, j))) << k << " ~ " << j;
            }
        }
    // Without periodic faces nothing changes.
    Scene<2> w(periodic2D, "");
    std::vector<Index> same = open;
    w.bc.closeActiveBlocks(same);
    EXPECT_EQ(same, open);
}

TEST(PeriodicLattice, ParticlesWrapAcrossTheSeam) {
    Scene<2> s(periodic2D, "boundary: {xMin: periodic, xMax: periodic}\n");
    Particles<2> p;
    p.resize(5);
    p.x = {Vec<2>(0.51, 0.3), Vec<2>(-0.52, 0.3), Vec<2>(0.5, 0.8), Vec<2>(0.1, -0.01),
           Vec<2>(-0.5, 0.1)};
    s.bc.wrap(p);
    EXPECT_NEAR(p.x[0][0], -0.49, 1e-15);
    EXPECT_NEAR(p.x[1][0], 0.48, 1e-15);
    EXPECT_EQ(p.x[2], Vec<2>(-0.5, 0.8)); // hi is lo; y is not periodic
    EXPECT_EQ(p.x[3], Vec<2>(0.1, -0.01));
    EXPECT_EQ(p.x[4], Vec<2>(-0.5, 0.1));
    EXPECT_EQ(p.x[0][1], 0.3);
    // Just below lo: x + L may round onto hi, the same node as lo; it lands on lo.
    Scene<2> unit("bounds: {min: [0, 0], max: [1, 1]}\ncellSize: 0.25\n",
                  "boundary: {xMin: periodic, xMax: periodic}\n");
    EXPECT_EQ(unit.bc.wrapPosition(Vec<2>(-1e-20, 0.5))[0], 0.0);
    EXPECT_EQ(s.bc.wrapPosition(Vec<2>(std::nextafter(-0.5, -1.0), 0.2))[0],
              std::nextafter(-0.5, -1.0) + 1.0);
    // Several periods away.
    EXPECT_NEAR(s.bc.wrapPosition(Vec<2>(2.75, 0))[0], -0.25, 1e-14);
}

TEST(PeriodicLattice, MinimumImageSeparation) {
    Scene<3> s("bounds: {min: [0, 0, 0], max: [1, 2, 1]}\ncellSize: 0.25\n",
               "boundary: {yMin: periodic, yMax: periodic}\n");
    const Vec<3> d = s.bc.separation(Vec<3>(0.1, 1.9, 0.5), Vec<3>(0.9, 0.1, 0.1));
    EXPECT_NEAR((d - Vec<3>(-0.8, -0.2, 0.4)).norm(), 0, 1e-14);
    EXPECT_NEAR(s.bc.separation(Vec<3>(0, 0.2, 0), Vec<3>(0, 1.9, 0))[1], 0.3, 1e-14);
    EXPECT_EQ(s.bc.lattice().period(), Vec<3>(0, 2, 0));
    EXPECT_TRUE(s.bc.periodic(1));
    EXPECT_FALSE(s.bc.periodic(0));
}

TEST(PeriodicLattice, ImageNearestACentre) {
    Scene<3> s("bounds: {min: [0, 0, 0], max: [1, 2, 1]}\ncellSize: 0.25\n",
               "boundary: {yMin: periodic, yMax: periodic}\n");
    const PeriodicLattice<3>& l = s.bc.lattice();
    // A point near yMax seen from a centre just past yMin: one period down along y only.
    const Vec<3> x(0.9, 1.95, 0.7), c(0.1, 0.05, 0.2);
    EXPECT_EQ(l.imageIndex(x, c), IVec<3>(0, 1, 0));
    EXPECT_NEAR((l.imageNear(x, c) - Vec<3>(0.9, -0.05, 0.7)).norm(), 0, 1e-15);
    // imageNear(x, c) − c is the minimum-image separation.
    EXPECT_NEAR((l.imageNear(x, c) - c - l.separation(x, c)).norm(), 0, 1e-15);
    // Several periods away, and the other way.
    EXPECT_EQ(l.imageIndex(Vec<3>(0, 6.3, 0), Vec<3>(0, 0.1, 0)), IVec<3>(0, 3, 0));
    EXPECT_EQ(l.imageIndex(Vec<3>(0, 0.1, 0), Vec<3>(0, 1.9, 0)), IVec<3>(0, -1, 0));
    EXPECT_NEAR(l.imageNear(Vec<3>(0, 0.1, 0), Vec<3>(0, 1.9, 0))[1], 2.1, 1e-15);
    // No shift: x itself, bit for bit (non-periodic x and z are never touched).
    const Vec<3> y(std::nextafter(0.3, 1.0), 1.2345678901234567, -7.0);
    EXPECT_EQ(l.imageNear(y, Vec<3>(5.0, 1.0, 3.0)), y);
    EXPECT_EQ(l.imageIndex(y, Vec<3>(5.0, 1.0, 3.0)), IVec<3>::Zero());
    // Without periodic faces: the identity.
    Scene<2> closed("bounds: {min: [0, 0], max: [1, 1]}\ncellSize: 0.25\n", "");
    EXPECT_EQ(closed.bc.lattice().imageNear(Vec<2>(0.99, 0.01), Vec<2>(0.01, 0.99)),
              Vec<2>(0.99, 0.01));
}

TEST(PeriodicLattice, ConditionsOnOtherFacesFollowTheOwners) {
    // x periodic, yMin no-slip with a boxed open patch at the seam's low side: images of
    // orifice nodes (beyond xMax) belong to the orifice, and only owners count in reactions.
    Scene<2> s(periodic2D, "boundary:\n  xMin: periodic\n  xMax: periodic\n  yMin:\n"
                           "    wall: noSlip\n"
                           "    hole: {type: open, box: {min: [-0.5, 0], max: [-0.375, 0]}}\n");
    Grid<2>& g = s.grid;
    const auto& L = s.bc.lattice();
    for (int k = 0; k < 2; ++k) {
        const auto& nodes = s.bc.patchNodes(2, k);
        for (Index i : nodes) {
            const double x = g.nodePosition(coordOf(g, L.owner(i)))[0];
            EXPECT_EQ(x <= -0.375 + 1e-12, k == 1) << i;
        }
    }
    // 3 owner columns x = -0.5, -0.4375, -0.375 and their images x = 0.5 (the duplicate node),
    // 0.5625, 0.625 (ghost layers beyond xMax).
    const auto& hole = s.bc.patchNodes(2, 1);
    EXPECT_EQ(hole.size(), std::size_t(6 * (Grid<2>::Pad + 1)));

    std::fill(g.mass.begin(), g.mass.end(), 0.0);
    for (Index i : g.faceNodes(2)) {
        g.mass[i] = 1.0;
        g.vOld[i] = g.v[i] = Vec<2>(0.5, -1.0);
    }
    BoundaryConditions<2>::Reactions r;
    s.bc.constrainUpdate(g, Vec<2>::Zero(), 0.0, 1.0, r);
    for (Index i : g.faceNodes(2))
        ASSERT_EQ(g.v[i], g.v[L.owner(i)]) << i;
    // The wall's owner columns: 16 − 3 = 13, each with Pad + 1 nodes.
    EXPECT_EQ(r[2], 13.0 * (Grid<2>::Pad + 1) * Vec<2>(0.5, -1.0));
    EXPECT_EQ(r[0], Vec<2>::Zero());
    EXPECT_EQ(r[1], Vec<2>::Zero());
}

} // namespace
} // namespace mpm
