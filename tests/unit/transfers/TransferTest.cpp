// SPDX-License-Identifier: GPL-3.0-or-later
// Conservation, reproduction and determinism of the particle ↔ grid transfers.
#include "transfers/Transfer.hpp"
#include "TestSupport.hpp"
#include "core/Parallel.hpp"

#include "kernels/Kernels.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <string>
#include <vector>

namespace mpm {
namespace {

struct Scheme {
    std::string kernel;
    std::string transfer;
    std::string backend = "cpu";
    std::string name() const { return backend + ": " + kernel + " " + transfer; }
};

/// Every registered compute backend (system/mpmSchemes `backend`): each test below runs on all.
std::vector<std::string> backends() {
    std::vector<std::string> names;
    for (const auto& entry : BackendRegistry<3>::table())
        names.push_back(entry.first);
    return names;
}

/// Every valid backend × kernel × transfer combination.
std::vector<Scheme> allSchemes() {
    std::vector<Scheme> s;
    for (const std::string& b : backends())
        for (const std::string& k : kernelNames())
            for (const char* t : {"pic", "flip", "apic"}) {
                if (std::string(t) == "apic" && k != "quadraticBSpline" && k != "cubicBSpline")
                    continue;
                s.push_back({k, t, b});
            }
    return s;
}

double inertiaFactor(const std::string& kernel) {
    return kernel == "quadraticBSpline" ? QuadraticBSplineKernel::InertiaFactor
                                        : CubicBSplineKernel::InertiaFactor;
}

template <int dim> Dictionary gridDict() {
    // A box away from the coordinate origin, so that angular momentum about it is not trivial.
    const std::string text =
        dim == 2 ? "bounds: {min: [-0.5, 0.25], max: [0.5, 1.25]}\ncellSize: 0.0625\n"
                   "boundary: {xMin: noSlip, yMin: slip}\n"
                 : "bounds: {min: [-0.5, 0.25, 0], max: [0.5, 1.25, 0.5]}\ncellSize: 0.125\n"
                   "boundary: {xMin: noSlip, zMax: open}\n";
    return Dictionary::fromString(text, "constant/grid");
}

template <int dim> std::unique_ptr<Transfer<dim>> makeTransfer(const Scheme& s) {
    return Transfer<dim>::create(Dictionary::fromString("kernel: " + s.kernel +
                                                            "\ntransfer: " + s.transfer +
                                                            "\nbackend: " + s.backend + "\n",
                                                        "system/mpmSchemes"),
                                 0.25);
}

template <int dim>
Particles<dim> randomParticles(const Grid<dim>& g, int n, unsigned seed, bool affine) {
    Particles<dim> p;
    p.resize(n);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    for (int i = 0; i < n; ++i) {
        for (int d = 0; d < dim; ++d) {
            p.x[i][d] = g.lo()[d] + u(rng) * (g.hi()[d] - g.lo()[d]);
            p.v[i][d] = s(rng);
        }
        p.C[i] = Mat<dim>::Zero();
        if (affine)
            for (int k = 0; k < dim * dim; ++k)
                p.C[i](k) = 5.0 * s(rng);
        p.L[i] = Mat<dim>::Zero();
        p.F[i] = Mat<dim>::Identity();
        p.be[i] = Mat3::Identity();
        Mat3 sig;
        for (int k = 0; k < 9; ++k)
            sig(k) = 1e3 * s(rng);
        p.stress[i] = 0.5 * (sig + sig.transpose());
        p.mass[i] = 0.5 + 1.5 * u(rng);
        p.volume0[i] = p.volume[i] = 1e-3 * (0.5 + u(rng));
        p.plasticStrain[i] = 0.0;
        p.id[i] = i;
        p.material[i] = 0;
    }
    return p;
}

/// Zero the node fields, every block active (the transfers act on the active blocks).
template <int dim> void clearGrid(Grid<dim>& g) {
    test::activateAll(g);
    std::fill(g.mass.begin(), g.mass.end(), 0.0);
    std::fill(g.momentum.begin(), g.momentum.end(), Vec<dim>::Zero());
    std::fill(g.force.begin(), g.force.end(), Vec<dim>::Zero());
}

/// Sort, weigh and scatter mass and momentum into a cleared grid.
template <int dim>
void p2g(Transfer<dim>& t, const Particles<dim>& p, Grid<dim>& g, BlockSort<dim>& sort,
         bool withStress = false) {
    clearGrid(g);
    ASSERT_EQ(sort.update(p, g), -1);
    t.computeWeights(p, g);
    t.scatter(p, g, sort, withStress);
}

/// v = vOld = momentum / mass (zero where there is no mass).
template <int dim> void gridVelocityFromMomentum(Grid<dim>& g) {
    for (Index k = 0; k < g.numNodes(); ++k) {
        g.v[k] = g.mass[k] > 0 ? Vec<dim>(g.momentum[k] / g.mass[k]) : Vec<dim>::Zero();
        g.vOld[k] = g.v[k];
    }
}

template <int dim> Vec<dim> nodePos(const Grid<dim>& g, Index k) {
    return g.nodePosition(g.nodeCoord(k));
}

template <int dim> Vec3 to3(const Vec<dim>& a) {
    Vec3 r = Vec3::Zero();
    r.template head<dim>() = a;
    return r;
}

/// ε : Bᵀ, the angular momentum carried by the affine part B = C D of an APIC particle
/// (Jiang et al. 2015): (ε:Bᵀ)_α = ε_αβγ B_γβ.
template <int dim> Vec3 affineSpin(const Mat<dim>& B) {
    Mat3 b = Mat3::Zero();
    b.template topLeftCorner<dim, dim>() = B;
    return Vec3(b(2, 1) - b(1, 2), b(0, 2) - b(2, 0), b(1, 0) - b(0, 1));
}

struct Totals {
    double mass = 0;
    Vec3 momentum = Vec3::Zero();
    Vec3 angular = Vec3::Zero();
    double scale = 0; ///< Σ m (|x||v| + |B|): the size of the sums, for relative tolerances
};

/// Particle totals; with APIC (inertia > 0) the affine angular momentum m ε:(C D)ᵀ is added.
template <int dim> Totals particleTotals(const Particles<dim>& p, double inertia, double h) {
    Totals t;
    for (std::size_t i = 0; i < p.size(); ++i) {
        const double m = p.mass[i];
        t.mass += m;
        t.momentum += to3<dim>(m * p.v[i]);
        t.angular += to3<dim>(p.x[i]).cross(to3<dim>(m * p.v[i]));
        Mat<dim> B = Mat<dim>::Zero();
        if (inertia > 0) {
            B = p.C[i] * (inertia * h * h);
            t.angular += m * affineSpin<dim>(B);
        }
        t.scale += m * (p.x[i].norm() * p.v[i].norm() + B.norm() + p.v[i].norm());
    }
    return t;
}

/// Grid totals from mass and momentum.
template <int dim> Totals gridTotals(const Grid<dim>& g) {
    Totals t;
    for (Index k = 0; k < g.numNodes(); ++k) {
        t.mass += g.mass[k];
        t.momentum += to3<dim>(g.momentum[k]);
        t.angular += to3<dim>(nodePos(g, k)).cross(to3<dim>(g.momentum[k]));
    }
    return t;
}

/// Grid totals from mass and velocity: Σ m_i v_i, Σ x_i × m_i v_i.
template <int dim> Totals gridVelocityTotals(const Grid<dim>& g) {
    Totals t;
    for (Index k = 0; k < g.numNodes(); ++k) {
        t.mass += g.mass[k];
        const Vec<dim> mv = g.mass[k] * g.v[k];
        t.momentum += to3<dim>(mv);
        t.angular += to3<dim>(nodePos(g, k)).cross(to3<dim>(mv));
    }
    return t;
}

void expectSame(const Totals& a, const Totals& b, double scale, bool angular, const char* what) {
    SCOPED_TRACE(what);
    EXPECT_NEAR(a.mass, b.mass, 1e-12 * a.mass);
    EXPECT_LE((a.momentum - b.momentum).norm(), 1e-12 * scale)
        << a.momentum.transpose() << " vs " << b.momentum.transpose();
    if (angular) {
        EXPECT_LE((a.angular - b.angular).norm(), 1e-12 * scale)
            << a.angular.transpose() << " vs " << b.angular.transpose();
    }
}

// ---------------------------------------------------------------------------------------------

template <int dim> void checkScatterConservesMassAndMomentum(int n) {
    for (const Scheme& s : allSchemes()) {
        SCOPED_TRACE(s.name());
        Grid<dim> g(gridDict<dim>());
        const bool apic = s.transfer == "apic";
        const Particles<dim> p = randomParticles(g, n, 17, apic);
        auto t = makeTransfer<dim>(s);
        BlockSort<dim> sort;
        p2g(*t, p, g, sort);
        const double inertia = apic ? inertiaFactor(s.kernel) : 0.0;
        const Totals pt = particleTotals(p, inertia, g.h());
        const Totals gt = gridTotals(g);
        // Angular momentum is conserved by APIC only.
        expectSame(pt, gt, pt.scale, apic, "P2G");
        for (Index k = 0; k < g.numNodes(); ++k)
            ASSERT_GE(g.mass[k], 0.0);
    }
}

TEST(Transfer, ScatterConservesMassAndMomentum2D) {
    checkScatterConservesMassAndMomentum<2>(2000);
}

TEST(Transfer, ScatterConservesMassAndMomentum3D) {
    checkScatterConservesMassAndMomentum<3>(800);
}

/// P2G, grid velocity from momentum, G2P with dt = 0, P2G again: mass, linear momentum (all
/// schemes) and angular momentum (APIC) are the same at every stage [Jiang et al. 2015].
template <int dim> void checkRoundTrip(int n) {
    for (const Scheme& s : allSchemes()) {
        SCOPED_TRACE(s.name());
        Grid<dim> g(gridDict<dim>());
        const bool apic = s.transfer == "apic";
        const double inertia = apic ? inertiaFactor(s.kernel) : 0.0;
        Particles<dim> p = randomParticles(g, n, 23, apic);
        const std::vector<Vec<dim>> x0 = p.x;
        auto t = makeTransfer<dim>(s);
        BlockSort<dim> sort;
        p2g(*t, p, g, sort);
        gridVelocityFromMomentum(g);
        const Totals grid1 = gridVelocityTotals(g);
        const double scale = particleTotals(p, inertia, g.h()).scale;
        expectSame(gridTotals(g), grid1, scale, true, "momentum / mass");

        t->gather(p, g, 0.0, false);
        EXPECT_EQ(p.x, x0); // dt = 0: nothing moves
        const Totals part2 = particleTotals(p, inertia, g.h());
        expectSame(grid1, part2, scale, apic, "G2P");

        p2g(*t, p, g, sort);
        const Totals grid3 = gridTotals(g);
        expectSame(part2, grid3, scale, apic, "second P2G");
        expectSame(grid1, grid3, scale, apic, "round trip");
    }
}

TEST(Transfer, RoundTripConservesMomentum2D) {
    checkRoundTrip<2>(1500);
}

TEST(Transfer, RoundTripConservesMomentum3D) {
    checkRoundTrip<3>(600);
}

/// Grid velocity set to the affine field a + A x on every node (every block active).
template <int dim> void setAffineGridVelocity(Grid<dim>& g, const Vec<dim>& a, const Mat<dim>& A) {
    test::activateAll(g);
    for (Index k = 0; k < g.numNodes(); ++k) {
        g.v[k] = a + A * nodePos(g, k);
        g.vOld[k] = g.v[k];
        g.mass[k] = 1.0;
    }
}

template <int dim> Mat<dim> rotationRate(double omega) {
    Mat<dim> W = Mat<dim>::Zero();
    if constexpr (dim == 2) {
        W(0, 1) = -omega;
        W(1, 0) = omega;
    } else {
        // ω = omega · (1, -2, 3)/√14: W x = ω × x.
        const Vec3 w = omega * Vec3(1.0, -2.0, 3.0).normalized();
        W << 0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0;
    }
    return W;
}

template <int dim> void checkRigidRotationReproducedByApic() {
    for (const std::string& backend : backends())
        for (const char* kernel : {"quadraticBSpline", "cubicBSpline"}) {
            const Scheme s{kernel, "apic", backend};
            SCOPED_TRACE(s.name());
            Grid<dim> g(gridDict<dim>());
            Particles<dim> p = randomParticles(g, 300, 5, false);
            auto t = makeTransfer<dim>(s);
            t->computeWeights(p, g);
            const Mat<dim> W = rotationRate<dim>(2.0);
            setAffineGridVelocity<dim>(g, Vec<dim>::Zero(), W);
            t->gather(p, g, 0.0, true);
            for (std::size_t i = 0; i < p.size(); ++i) {
                ASSERT_LE((p.v[i] - W * p.x[i]).norm(), 1e-13) << "particle " << i;
                ASSERT_LE((p.C[i] - W).norm(), 1e-12) << "particle " << i << "\n" << p.C[i];
                ASSERT_LE((p.L[i] - W).norm(), 1e-12) << "particle " << i;
            }
        }
}

TEST(Transfer, ApicReproducesRigidRotation2D) {
    checkRigidRotationReproducedByApic<2>();
}

TEST(Transfer, ApicReproducesRigidRotation3D) {
    checkRigidRotationReproducedByApic<3>();
}

/// Every scheme interpolates an affine grid field exactly (PIC/APIC velocity, L everywhere).
template <int dim> void checkAffineFieldInterpolation() {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Vec<dim> a;
    Mat<dim> A;
    for (int d = 0; d < dim; ++d)
        a[d] = u(rng);
    for (int k = 0; k < dim * dim; ++k)
        A(k) = u(rng);
    for (const Scheme& s : allSchemes()) {
        if (s.transfer == "flip") continue; // FLIP keeps the particle's own velocity
        SCOPED_TRACE(s.name());
        Grid<dim> g(gridDict<dim>());
        Particles<dim> p = randomParticles(g, 300, 6, false);
        auto t = makeTransfer<dim>(s);
        t->computeWeights(p, g);
        setAffineGridVelocity<dim>(g, a, A);
        t->gather(p, g, 0.0, true);
        Particles<dim> q = p;
        t->velocityGradient(q, g);
        for (std::size_t i = 0; i < p.size(); ++i) {
            ASSERT_LE((p.v[i] - (a + A * p.x[i])).norm(), 1e-13) << "particle " << i;
            ASSERT_LE((p.L[i] - A).norm(), 1e-12) << "particle " << i;
            ASSERT_LE((q.L[i] - A).norm(), 1e-12) << "particle " << i;
            if (s.transfer == "apic") {
                ASSERT_LE((p.C[i] - A).norm(), 1e-12) << "particle " << i;
            }
        }
    }
}

TEST(Transfer, AffineFieldInterpolatedExactly2D) {
    checkAffineFieldInterpolation<2>();
}

TEST(Transfer, AffineFieldInterpolatedExactly3D) {
    checkAffineFieldInterpolation<3>();
}

template <int dim> void checkUniformVelocityPreserved() {
    Vec<dim> u0;
    for (int d = 0; d < dim; ++d)
        u0[d] = 0.3 - 0.7 * d;
    for (const Scheme& s : allSchemes()) {
        SCOPED_TRACE(s.name());
        Grid<dim> g(gridDict<dim>());
        Particles<dim> p = randomParticles(g, 500, 9, false);
        for (auto& v : p.v)
            v = u0;
        auto t = makeTransfer<dim>(s);
        BlockSort<dim> sort;
        for (int cycle = 0; cycle < 2; ++cycle) {
            p2g(*t, p, g, sort);
            gridVelocityFromMomentum(g);
            t->gather(p, g, 0.0, true);
            for (std::size_t i = 0; i < p.size(); ++i) {
                ASSERT_LE((p.v[i] - u0).norm(), 1e-14) << "particle " << i;
                ASSERT_LE(p.L[i].norm(), 1e-12) << "particle " << i;
                if (s.transfer == "apic") {
                    ASSERT_LE(p.C[i].norm(), 1e-12) << "particle " << i;
                }
            }
        }
    }
}

TEST(Transfer, UniformVelocityPreservedByRoundTrip2D) {
    checkUniformVelocityPreserved<2>();
}

TEST(Transfer, UniformVelocityPreservedByRoundTrip3D) {
    checkUniformVelocityPreserved<3>();
}

TEST(Transfer, GatherMovesParticlesWithPicVelocity) {
    for (const std::string& backend : backends()) {
        SCOPED_TRACE(backend);
        Grid<2> g(gridDict<2>());
        Particles<2> p = randomParticles(g, 100, 4, false);
        const std::vector<Vec<2>> x0 = p.x;
        auto t = makeTransfer<2>({"cubicBSpline", "flip", backend});
        t->computeWeights(p, g);
        const Vec<2> a(0.5, -0.25);
        setAffineGridVelocity<2>(g, a, Mat<2>::Zero());
        for (auto& v : g.vOld)
            v = Vec<2>::Zero(); // FLIP increment a; PIC velocity a
        const double dt = 1e-3;
        const GatherStats st = t->gather(p, g, dt, false);
        EXPECT_EQ(st.firstNonFinite, -1);
        double ke = 0.0, vmax = 0.0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            EXPECT_LE((p.x[i] - (x0[i] + dt * a)).norm(), 1e-15);
            ke += 0.5 * p.mass[i] * p.v[i].squaredNorm();
            vmax = std::max(vmax, p.v[i].norm());
        }
        EXPECT_NEAR(st.kineticEnergy, ke, 1e-12 * ke);
        EXPECT_NEAR(st.maxSpeed, vmax, 1e-14);
        EXPECT_NEAR(st.maxMoveSpeed, a.norm(), 1e-14);
    }
}

TEST(Transfer, ApicNeedsBSplineKernel) {
    for (const char* kernel : {"linear", "gimp"}) {
        EXPECT_THROW(makeTransfer<2>({kernel, "apic"}), InputError) << kernel;
        EXPECT_THROW(makeTransfer<3>({kernel, "apic"}), InputError) << kernel;
    }
    EXPECT_THROW(makeTransfer<2>({"quintic", "pic"}), InputError);
    EXPECT_THROW(makeTransfer<2>({"linear", "mls"}), InputError);
    EXPECT_THROW(makeTransfer<2>({"linear", "pic", "gpu"}), InputError); // unknown backend
    for (const std::string& backend : backends())
        EXPECT_THROW(makeTransfer<3>({"gimp", "apic", backend}), InputError) << backend;
    EXPECT_NO_THROW(Transfer<2>::create(
        Dictionary::fromString("kernel: gimp\ntransfer: {type: flip, ratio: 0.9}\n", "s"), 0.25));
}

/// Scatter (with stress) with 1 and with 2 threads: bit-identical grid arrays.
template <int dim> void checkScatterDeterministic(int n) {
    const int threads = omp_get_max_threads();
    for (const Scheme& s : allSchemes()) {
        if (s.transfer == "flip") continue; // scatters exactly as pic
        SCOPED_TRACE(s.name());
        Grid<dim> g1(gridDict<dim>()), g2(gridDict<dim>());
        const Particles<dim> p = randomParticles(g1, n, 31, s.transfer == "apic");
        auto t = makeTransfer<dim>(s);
        BlockSort<dim> sort;
        omp_set_num_threads(1);
        p2g(*t, p, g1, sort, true);
        omp_set_num_threads(2);
        p2g(*t, p, g2, sort, true);
        omp_set_num_threads(threads);
        const std::size_t nn = g1.mass.size();
        EXPECT_EQ(std::memcmp(g1.mass.data(), g2.mass.data(), nn * sizeof(double)), 0);
        EXPECT_EQ(std::memcmp(g1.momentum.data(), g2.momentum.data(), nn * sizeof(Vec<dim>)), 0);
        EXPECT_EQ(std::memcmp(g1.force.data(), g2.force.data(), nn * sizeof(Vec<dim>)), 0);
    }
}

TEST(Transfer, ScatterBitIdenticalForOneAndTwoThreads2D) {
    checkScatterDeterministic<2>(3 * ParallelThreshold); // above the threshold: really threaded
}

TEST(Transfer, ScatterBitIdenticalForOneAndTwoThreads3D) {
    checkScatterDeterministic<3>(2 * ParallelThreshold);
}

/// The stencils evaluated by the step's first scatter (in P2G's own pass) and those evaluated on
/// demand by a transfer that comes first: the same bits (gatherScalar of one nodal field).
template <int dim> void checkStencilsEvaluatedWhereFirstNeeded() {
    for (const Scheme& s : allSchemes()) {
        SCOPED_TRACE(s.name());
        Grid<dim> g(gridDict<dim>());
        const Particles<dim> p = randomParticles(g, 2 * ParallelThreshold, 17, false);
        NodeArray<double> q(g.numNodes());
        for (Index k = 0; k < g.numNodes(); ++k)
            q[k] = std::sin(0.37 * k) + 0.01 * k;
        auto t1 = makeTransfer<dim>(s), t2 = makeTransfer<dim>(s);
        BlockSort<dim> sort;
        p2g(*t1, p, g, sort, true); // the scatter evaluates
        std::vector<double> a, b;
        t1->gatherScalar(q, a);
        t2->computeWeights(p, g); // gatherScalar evaluates
        t2->gatherScalar(q, b);
        ASSERT_EQ(a.size(), p.size());
        EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(double)), 0);
    }
}

TEST(Transfer, StencilsEvaluatedWhereFirstNeeded2D) {
    checkStencilsEvaluatedWhereFirstNeeded<2>();
}

TEST(Transfer, StencilsEvaluatedWhereFirstNeeded3D) {
    checkStencilsEvaluatedWhereFirstNeeded<3>();
}

TEST(Transfer, ScatterForceMatchesCombinedScatter) {
    // USF's separate force scatter adds the same force as USL's combined pass. The internal
    // force sums to zero (Σ ∇w = 0) and has no moment (Σ x_i ⊗ ∇w = 1 and σ is symmetric).
    for (const std::string& backend : backends()) {
        SCOPED_TRACE(backend);
        Grid<2> g1(gridDict<2>()), g2(gridDict<2>());
        const Particles<2> p = randomParticles(g1, 1000, 12, false);
        auto t = makeTransfer<2>({"quadraticBSpline", "pic", backend});
        BlockSort<2> sort;
        p2g(*t, p, g1, sort, true);
        p2g(*t, p, g2, sort, false);
        t->scatterForce(p, g2, sort);
        Vec<2> total = Vec<2>::Zero();
        double torque = 0.0, scale = 0.0;
        for (Index k = 0; k < g1.numNodes(); ++k) {
            ASSERT_LE((g1.force[k] - g2.force[k]).norm(), 1e-12 * (1.0 + g1.force[k].norm()));
            total += g1.force[k];
            const Vec<2> x = nodePos(g1, k);
            torque += x[0] * g1.force[k][1] - x[1] * g1.force[k][0];
            scale += g1.force[k].norm() * (1.0 + x.norm());
        }
        EXPECT_LE(total.norm(), 1e-12 * scale);
        EXPECT_LE(std::fabs(torque), 1e-12 * scale);
    }
}

// ---------------------------------------------------------------------------------------------
// Every backend against the reference backend (the transfers written straight from the
// equations, src/transfers/ReferenceTransfer.cpp), operation by operation, which checks the
// cpu backend's factored 3D loops and 2D stencil visitor term by term.

template <class V> double maxNorm(const NodeArray<V>& a) {
    double m = 0.0;
    for (Index i = 0; i < a.size(); ++i)
        m = std::max(m, std::sqrt(double(a[i].squaredNorm())));
    return m;
}

double maxNorm(const NodeArray<double>& a) {
    double m = 0.0;
    for (Index i = 0; i < a.size(); ++i)
        m = std::max(m, std::fabs(a[i]));
    return m;
}

template <class V> double maxDiff(const NodeArray<V>& a, const NodeArray<V>& b) {
    double m = 0.0;
    for (Index i = 0; i < a.size(); ++i)
        m = std::max(m, std::sqrt(double((a[i] - b[i]).squaredNorm())));
    return m;
}

double maxDiff(const NodeArray<double>& a, const NodeArray<double>& b) {
    double m = 0.0;
    for (Index i = 0; i < a.size(); ++i)
        m = std::max(m, std::fabs(a[i] - b[i]));
    return m;
}

/// Random node velocities v and vOld on every node.
template <int dim> void randomGridVelocities(Grid<dim>& g, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (Index k = 0; k < g.numNodes(); ++k)
        for (int d = 0; d < dim; ++d) {
            g.v[k][d] = u(rng);
            g.vOld[k][d] = u(rng);
        }
}

/// Run every operation of `backend` and of the reference on the same random points and grid.
template <int dim> void checkAgainstReference(const std::string& backend, int n) {
    for (const Scheme& s : allSchemes()) {
        if (s.backend != backend) continue;
        SCOPED_TRACE(s.name());
        const bool apic = s.transfer == "apic";
        struct Run {
            Grid<dim> g{gridDict<dim>()};
            Particles<dim> p, q;
            BlockSort<dim> sort;
            std::unique_ptr<Transfer<dim>> t;
            NodeArray<double> scalar;
            std::vector<double> gathered;
            GatherStats stats;
        };
        Run runs[2];
        for (int k = 0; k < 2; ++k) {
            Run& r = runs[k];
            r.p = randomParticles(r.g, n, 77, apic);
            r.t = makeTransfer<dim>({s.kernel, s.transfer, k == 0 ? backend : "reference"});
            // P2G with stress, a second force scatter, point forces on every third point.
            p2g(*r.t, r.p, r.g, r.sort, true);
            r.t->scatterForce(r.p, r.g, r.sort);
            std::vector<Index> ids;
            std::vector<Vec<dim>> f;
            for (Index i = 0; i < n; i += 3) {
                ids.push_back(i);
                f.push_back(Vec<dim>::Constant(0.1 * double(i)));
            }
            r.t->scatterPointForces(ids, f, r.g);
            r.scalar.reset(r.g.numNodes());
            r.t->scatterScalar(r.p.volume, r.scalar, r.sort);
            r.t->gatherScalar(r.g.mass, r.gathered);
            // The grid update with gravity and damping, then G2P from random velocities.
            r.t->updateVelocity(fieldsOf(r.g), r.g.activeBlocks(), Vec<dim>::Constant(-9.81), 0.1,
                                1e-3);
            Grid<dim> h(gridDict<dim>());
            test::activateAll(h);
            randomGridVelocities(h, 78);
            r.q = r.p;
            r.t->velocityGradient(r.q, h);
            r.stats = r.t->gather(r.p, h, 1e-3, true);
        }
        const Run &a = runs[0], &b = runs[1];
        EXPECT_LE(maxDiff(a.g.mass, b.g.mass), 1e-13 * maxNorm(b.g.mass));
        EXPECT_LE(maxDiff(a.g.momentum, b.g.momentum), 1e-13 * maxNorm(b.g.momentum));
        EXPECT_LE(maxDiff(a.g.force, b.g.force), 1e-13 * maxNorm(b.g.force));
        EXPECT_LE(maxDiff(a.g.v, b.g.v), 1e-12 * maxNorm(b.g.v));
        EXPECT_LE(maxDiff(a.g.vOld, b.g.vOld), 1e-12 * maxNorm(b.g.vOld));
        EXPECT_LE(maxDiff(a.scalar, b.scalar), 1e-13 * maxNorm(b.scalar));
        for (Index i = 0; i < n; ++i) {
            ASSERT_NEAR(a.gathered[i], b.gathered[i], 1e-13 * (1.0 + std::fabs(b.gathered[i])));
            ASSERT_LE((a.p.v[i] - b.p.v[i]).norm(), 1e-13) << "particle " << i;
            ASSERT_LE((a.p.x[i] - b.p.x[i]).norm(), 1e-15) << "particle " << i;
            ASSERT_LE((a.p.L[i] - b.p.L[i]).norm(), 1e-12 * (1.0 + b.p.L[i].norm())) << i;
            ASSERT_LE((a.q.L[i] - b.q.L[i]).norm(), 1e-12 * (1.0 + b.q.L[i].norm())) << i;
            if (apic) {
                ASSERT_LE((a.p.C[i] - b.p.C[i]).norm(), 1e-12 * (1.0 + b.p.C[i].norm())) << i;
            }
        }
        EXPECT_NEAR(a.stats.kineticEnergy, b.stats.kineticEnergy, 1e-12 * b.stats.kineticEnergy);
        EXPECT_NEAR(a.stats.maxSpeed, b.stats.maxSpeed, 1e-13 * b.stats.maxSpeed);
        EXPECT_NEAR(a.stats.maxMoveSpeed, b.stats.maxMoveSpeed, 1e-13 * b.stats.maxMoveSpeed);
        EXPECT_EQ(a.stats.firstNonFinite, b.stats.firstNonFinite);
    }
}

TEST(Transfer, EveryBackendMatchesReference2D) {
    for (const std::string& backend : backends())
        checkAgainstReference<2>(backend, 300);
}

TEST(Transfer, EveryBackendMatchesReference3D) {
    for (const std::string& backend : backends())
        checkAgainstReference<3>(backend, 150);
}

/// The grid update [000 Eq. 14] of one node against its closed form, on every backend: mass m,
/// momentum p, force f, gravity g, damping α: v_old = p/m, F = f + m g,
/// F_a ← F_a − α |F_a| sign(v_old,a), v = v_old + Δt F/m; a node without mass is left alone.
TEST(Transfer, GridUpdateMatchesClosedForm) {
    for (const std::string& backend : backends()) {
        SCOPED_TRACE(backend);
        Grid<2> g(gridDict<2>());
        test::activateAll(g);
        const Index k = g.nodeIndex(IVec<2>(5, 6)), empty = g.nodeIndex(IVec<2>(7, 6));
        g.mass[k] = 2.0;
        g.momentum[k] = Vec<2>(1.0, -4.0);
        g.force[k] = Vec<2>(3.0, 10.0);
        g.v[empty] = Vec<2>(7.0, 7.0);
        auto t = makeTransfer<2>({"linear", "pic", backend});
        const double dt = 0.01, alpha = 0.5;
        t->updateVelocity(fieldsOf(g), g.activeBlocks(), Vec<2>(0.0, -9.81), alpha, dt);
        // v_old = (0.5, −2); F = (3, 10 − 19.62) = (3, −9.62); damped: (3 − 1.5, −9.62 + 4.81).
        EXPECT_EQ(g.vOld[k], Vec<2>(0.5, -2.0));
        EXPECT_NEAR(g.v[k][0], 0.5 + dt * 1.5 / 2.0, 1e-15);
        EXPECT_NEAR(g.v[k][1], -2.0 + dt * (-4.81) / 2.0, 1e-15);
        EXPECT_EQ(g.v[empty], Vec<2>(7.0, 7.0));
        t->velocityFromMomentum(fieldsOf(g), g.activeBlocks());
        EXPECT_EQ(g.vOld[k], Vec<2>(0.5, -2.0));
        EXPECT_EQ(g.vOld[empty], Vec<2>::Zero());
    }
}

} // namespace
} // namespace mpm
