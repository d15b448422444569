// SPDX-License-Identifier: GPL-3.0-or-later
// Elastic constants, Hencky hyperelasticity, Jaumann linear elasticity and material selection.
#include "materials/HenckyElastic.hpp"
#include "TestSupport.hpp"
#include "core/Constants.hpp"
#include "materials/LinearElastic.hpp"
#include "materials/Material.hpp"

#include "core/SymmetricEigen.hpp"

#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace mpm {
namespace {

Dictionary parse(const std::string& text) {
    return Dictionary::fromString(text, "constant/materials");
}

using test::catchInputError;

Mat3 randomMatrix(std::mt19937_64& rng, double scale) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Mat3 a;
    for (int i = 0; i < 9; ++i)
        a(i) = scale * u(rng);
    return a;
}

Mat3 randomSymmetric(std::mt19937_64& rng, double scale) {
    const Mat3 a = randomMatrix(rng, scale);
    return 0.5 * (a + a.transpose());
}

/// Sorted eigenvalues of a symmetric matrix.
Vec3 sortedEigenvalues(const Mat3& a) {
    Vec3 lam;
    Mat3 Q;
    symmetricEigen3(0.5 * (a + a.transpose()), lam, Q);
    std::sort(lam.data(), lam.data() + 3);
    return lam;
}

// ---------------------------------------------------------------------------------------------
// ElasticConstants

TEST(ElasticConstants, FromYoungsModulusAndPoissonRatio) {
    const double E = 2.5e7, nu = 0.3;
    const ElasticConstants c(E, nu);
    EXPECT_DOUBLE_EQ(c.E, E);
    EXPECT_DOUBLE_EQ(c.nu, nu);
    EXPECT_NEAR(c.G, E / (2 * (1 + nu)), 1e-9 * E);
    EXPECT_NEAR(c.K, E / (3 * (1 - 2 * nu)), 1e-9 * E);
    EXPECT_NEAR(c.lambda, E * nu / ((1 + nu) * (1 - 2 * nu)), 1e-9 * E);
    EXPECT_NEAR(c.M, E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)), 1e-9 * E);
    // Consistency of the usual identities.
    EXPECT_NEAR(c.lambda, c.K - 2.0 * c.G / 3.0, 1e-9 * E);
    EXPECT_NEAR(c.M, c.lambda + 2.0 * c.G, 1e-9 * E);
    EXPECT_NEAR(9 * c.K * c.G / (3 * c.K + c.G), E, 1e-9 * E);
    EXPECT_NEAR((3 * c.K - 2 * c.G) / (2 * (3 * c.K + c.G)), nu, 1e-12);
}

TEST(ElasticConstants, FromDictionary) {
    const ElasticConstants c(parse("E: 1e6\nnu: 0.25\n"));
    EXPECT_DOUBLE_EQ(c.E, 1e6);
    EXPECT_NEAR(c.G, 4e5, 1e-6);
    EXPECT_NEAR(c.lambda, 4e5, 1e-6); // ν = 1/4: λ = G
}

TEST(ElasticConstants, IncompressibleAndOutOfRangeRejected) {
    for (const char* text : {"E: 1e6\nnu: 0.5\n", "E: 1e6\nnu: 0.6\n", "E: 1e6\nnu: -1\n",
                             "E: 0\nnu: 0.3\n", "E: -1e6\nnu: 0.3\n"}) {
        SCOPED_TRACE(text);
        EXPECT_THROW(ElasticConstants c(parse(text)), InputError);
    }
    const InputError e = catchInputError([] {
        Material<3>::create(parse("type: henckyElastic\ndensity: 2000\nE: 1e7\nnu: 0.5\n"), "m");
    });
    EXPECT_EQ(e.key(), "nu") << e.what();
}

// ---------------------------------------------------------------------------------------------
// Material selection

TEST(Material, UnknownTypeListsValidTypes) {
    const InputError e = catchInputError(
        [] { Material<2>::create(parse("type: rubber\ndensity: 1000\nE: 1e6\nnu: 0.3\n"), "m"); });
    const std::string msg = e.what();
    EXPECT_EQ(e.key(), "type") << msg;
    EXPECT_NE(msg.find("rubber"), std::string::npos) << msg;
    EXPECT_NE(msg.find("henckyElastic"), std::string::npos) << msg;
    EXPECT_NE(msg.find("linearElastic"), std::string::npos) << msg;
}

TEST(Material, CreateReadsDensityAndRejectsUnknownKeys) {
    const auto m = Material<3>::create(
        parse("type: linearElastic\ndensity: 2000\nE: 1.8e7\nnu: 0.3\n"), "soil");
    EXPECT_EQ(m->name(), "soil");
    EXPECT_DOUBLE_EQ(m->density(), 2000.0);
    const ElasticConstants c(1.8e7, 0.3);
    EXPECT_NEAR(m->waveSpeed(), std::sqrt(c.M / 2000.0), 1e-12 * m->waveSpeed());
    EXPECT_NEAR(m->defaultK0(), 0.3 / 0.7, 1e-15);
    EXPECT_THROW(Material<3>::create(
                     parse("type: henckyElastic\ndensity: 2000\nE: 1e7\nnu: 0.3\nEE: 1\n"), "m"),
                 InputError);
}

// ---------------------------------------------------------------------------------------------
// Hencky

/// τ = ∂ψ/∂F Fᵀ with ψ(F) = ψ(F Fᵀ), by central differences.
Mat3 kirchhoffByFiniteDifference(const ElasticConstants& c, const Mat3& F, double delta) {
    Mat3 P;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            Mat3 Fp = F, Fm = F;
            Fp(i, j) += delta;
            Fm(i, j) -= delta;
            P(i, j) = (HenckyLaw::energyDensity(c, Fp * Fp.transpose()) -
                       HenckyLaw::energyDensity(c, Fm * Fm.transpose())) /
                      (2 * delta);
        }
    return P * F.transpose();
}

void checkKirchhoffIsEnergyDerivative(double strain, unsigned seed) {
    const ElasticConstants c(1.0e7, 0.3);
    std::mt19937_64 rng(seed);
    for (int trial = 0; trial < 50; ++trial) {
        const Mat3 F = Mat3::Identity() + randomMatrix(rng, strain);
        ASSERT_GT(F.determinant(), 0.0);
        const Mat3 be = F * F.transpose();
        const Mat3 tau = HenckyLaw::kirchhoff(c, be);
        const Mat3 fd = kirchhoffByFiniteDifference(c, F, 1e-6);
        EXPECT_LE((tau - fd).norm(), 1e-6 * tau.norm()) << "F =\n"
                                                        << F << "\nτ =\n"
                                                        << tau << "\nFD =\n"
                                                        << fd;
    }
}

TEST(HenckyElastic, KirchhoffIsEnergyDerivativeNearIdentity) {
    checkKirchhoffIsEnergyDerivative(0.01, 1);
}

TEST(HenckyElastic, KirchhoffIsEnergyDerivativeAtLargeStrain) {
    checkKirchhoffIsEnergyDerivative(0.3, 2);
}

TEST(HenckyElastic, ZeroStressAndEnergyAtIdentity) {
    const ElasticConstants c(1.0e7, 0.3);
    EXPECT_EQ(HenckyLaw::kirchhoff(c, Mat3::Identity()).cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(HenckyLaw::energyDensity(c, Mat3::Identity()), 0.0);
}

TEST(HenckyElastic, KirchhoffOfKnownStrain) {
    // bᵉ = diag(e^{2a}, e^{2b}, e^{2c}): ε = diag(a, b, c), τ = λ tr ε 1 + 2G ε.
    const ElasticConstants c(1.0e7, 0.25);
    const Vec3 eps(-0.02, 0.01, 0.005);
    const Mat3 be = (2.0 * eps).array().exp().matrix().asDiagonal();
    const Mat3 tau = HenckyLaw::kirchhoff(c, be);
    const Mat3 expected =
        c.lambda * eps.sum() * Mat3::Identity() + 2.0 * c.G * Mat3(eps.asDiagonal());
    EXPECT_LE((tau - expected).norm(), 1e-10 * expected.norm());
    const double psi = 0.5 * c.lambda * eps.sum() * eps.sum() + c.G * eps.squaredNorm();
    EXPECT_NEAR(HenckyLaw::energyDensity(c, be), psi, 1e-12 * psi);
}

TEST(HenckyElastic, LeftCauchyGreenFromStressInvertsKirchhoff) {
    const ElasticConstants c(5.0e6, 0.35);
    std::mt19937_64 rng(3);
    for (int trial = 0; trial < 200; ++trial) {
        // bᵉ = exp(2ε) for a random symmetric ε.
        const Mat3 eps = randomSymmetric(rng, trial % 2 ? 0.3 : 1e-3);
        Vec3 lam;
        Mat3 Q;
        symmetricEigen3(eps, lam, Q);
        const Mat3 be = fromEigen(Q, (2.0 * lam).array().exp().matrix());
        const Mat3 tau = HenckyLaw::kirchhoff(c, be);
        const Mat3 back = HenckyLaw::leftCauchyGreenFromStress(c, tau);
        EXPECT_LE((back - be).norm(), 1e-12 * be.norm()) << "bᵉ =\n" << be;
        // And the other way round, from a prescribed stress.
        const Mat3 tau0 = randomSymmetric(rng, 1e5);
        const Mat3 tau1 = HenckyLaw::kirchhoff(c, HenckyLaw::leftCauchyGreenFromStress(c, tau0));
        EXPECT_LE((tau1 - tau0).norm(), 1e-9 * tau0.norm());
    }
}

TEST(HenckyElastic, InitialiseFromStress) {
    const auto m =
        Material<3>::create(parse("type: henckyElastic\ndensity: 2000\nE: 1e7\nnu: 0.3\n"), "m");
    Particles<3> p;
    p.resize(2);
    Mat3 sigma0 = Mat3::Zero();
    sigma0.diagonal() << -3e4, -3e4, -7e4;
    m->initialise(p, 0, sigma0);
    m->initialise(p, 1, Mat3::Zero());
    EXPECT_EQ(p.be[1], Mat3::Identity());
    EXPECT_EQ(p.stress[0], sigma0);
    EXPECT_LE((HenckyLaw::kirchhoff(ElasticConstants(1e7, 0.3), p.be[0]) - sigma0).norm(),
              1e-9 * sigma0.norm());
}

/// updateStress (batched, vectorised) against the scalar formulas: bᵉ ← f bᵉ fᵀ with
/// f = 1 + Δt L, σ = τ(bᵉ) / J with J = V / V⁰, for particle counts that are not multiples of
/// the batch width and ids in any order. `strain`: the size of Fᵉ − 1 (0.2: most batches hold
/// a stretch beyond the series' range and are decomposed; 0.01: the series of ½ ln bᵉ).
template <int dim> void checkHenckyUpdate(int n, unsigned seed, double strain = 0.2) {
    const ElasticConstants c(2e7, 0.3);
    const auto m =
        Material<dim>::create(parse("type: henckyElastic\ndensity: 2000\nE: 2e7\nnu: 0.3\n"), "m");
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.8, 1.2);
    Particles<dim> p;
    p.resize(n + 3);
    std::vector<Index> ids;
    for (int i = 0; i < n + 3; ++i) {
        const Mat3 F = Mat3::Identity() + randomMatrix(rng, strain);
        p.be[i] = F * F.transpose();
        p.L[i] = randomMatrix(rng, 10.0).template topLeftCorner<dim, dim>();
        p.F[i] = Mat<dim>::Identity();
        p.volume0[i] = 1e-3;
        p.volume[i] = 1e-3 * u(rng);
        p.stress[i] = Mat3::Zero();
        if (i % 7 != 3) ids.push_back(i); // some particles belong to another material
    }
    std::shuffle(ids.begin(), ids.end(), rng);
    const Particles<dim> before = p;
    const double dt = 1e-3;
    ASSERT_EQ(m->updateStress(p, ids, dt), -1);
    std::vector<bool> updated(p.size(), false);
    for (Index i : ids)
        updated[i] = true;
    for (std::size_t i = 0; i < p.size(); ++i) {
        SCOPED_TRACE(i);
        if (!updated[i]) {
            EXPECT_EQ(p.be[i], before.be[i]);
            EXPECT_EQ(p.stress[i], before.stress[i]);
            continue;
        }
        const Mat3 f = Mat3::Identity() + dt * embed3<dim>(before.L[i]);
        const Mat3 be = f * before.be[i] * f.transpose();
        EXPECT_LE((p.be[i] - be).norm(), 1e-14 * be.norm());
        const Mat3 sigma = HenckyLaw::kirchhoff(c, be) * (before.volume0[i] / before.volume[i]);
        EXPECT_LE((p.stress[i] - sigma).norm(), 1e-11 * sigma.norm()) << p.stress[i] << "\n"
                                                                      << sigma;
        EXPECT_LE((p.stress[i] - p.stress[i].transpose()).norm(), 1e-12 * sigma.norm());
    }
    EXPECT_EQ(m->updateStress(p, {}, dt), -1);
}

TEST(HenckyElastic, UpdateStressMatchesScalarFormulas3D) {
    for (int n : {1, 7, 8, 9, 30})
        checkHenckyUpdate<3>(n, 40 + n);
}

TEST(HenckyElastic, UpdateStressMatchesScalarFormulas2D) {
    for (int n : {1, 5, 16, 21})
        checkHenckyUpdate<2>(n, 50 + n);
}

TEST(HenckyElastic, UpdateStressBySeriesMatchesScalarFormulas) {
    for (int n : {1, 9, 30}) {
        checkHenckyUpdate<3>(n, 60 + n, 0.01);
        checkHenckyUpdate<2>(n, 70 + n, 0.01);
    }
}

TEST(HenckyElastic, UpdateStressReportsNonFiniteParticle) {
    const auto m =
        Material<3>::create(parse("type: henckyElastic\ndensity: 2000\nE: 1e7\nnu: 0.3\n"), "m");
    Particles<3> p;
    p.resize(12);
    for (int i = 0; i < 12; ++i) {
        m->initialise(p, i, Mat3::Zero());
        p.L[i] = Mat3::Zero();
        p.F[i] = Mat3::Identity();
        p.volume[i] = p.volume0[i] = 1.0;
    }
    p.L[9](0, 1) = std::nan("");
    EXPECT_EQ(m->updateStress(p, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}, 1e-3), 9);
    EXPECT_EQ(m->updateStress(p, {11, 10, 9}, 1e-3), 9);
}

TEST(HenckyElastic, BatchedStrainEnergiesMatchOnePointAtATime) {
    // 19 points (two full batches and a short one), in a scrambled order and a subset:
    // undeformed (ψ = 0 exactly), repeated stretches, small and large strains, rotated axes.
    const auto m =
        Material<3>::create(parse("type: henckyElastic\ndensity: 2000\nE: 1e7\nnu: 0.3\n"), "m");
    Particles<3> p;
    p.resize(21);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const ElasticConstants c(1e7, 0.3);
    double exact[21]; // ψ V⁰ from the strains the points were built with
    for (int i = 0; i < 21; ++i) {
        const double scale = i % 3 == 0 ? 1e-4 : (i % 3 == 1 ? 1e-2 : 0.3);
        Vec3 eps(scale * u(rng), scale * u(rng), scale * u(rng));
        if (i == 4) eps = Vec3::Constant(0.01);
        const Mat3 Q = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().matrix();
        p.be[i] = Q * (2.0 * eps).array().exp().matrix().asDiagonal() * Q.transpose();
        p.volume0[i] = 1.0 + 0.1 * i;
        exact[i] =
            (0.5 * c.lambda * eps.sum() * eps.sum() + c.G * eps.squaredNorm()) * p.volume0[i];
    }
    p.be[7] = Mat3::Identity();
    std::vector<Index> ids;
    for (Index i = 20; i >= 2; --i)
        ids.push_back(i);
    std::vector<double> out(21, -1.0);
    m->strainEnergies(p, ids, out);
    EXPECT_EQ(out[0], -1.0); // not in ids: untouched
    EXPECT_EQ(out[1], -1.0);
    EXPECT_EQ(out[7], 0.0);
    // ψ of a small strain is ill-conditioned in bᵉ (δψ/ψ ≈ 2 δλ/ε: a few ulps of λ are 1e-11 at
    // ε = 1e-4), for either path; a wrong lane or volume would be off by O(1).
    for (Index i : ids) {
        if (i == 7) continue;
        EXPECT_NEAR(out[i], m->strainEnergy(p, i), 1e-10 * exact[i]) << "point " << i;
        EXPECT_NEAR(out[i], exact[i], 1e-10 * exact[i]) << "point " << i;
    }
}

TEST(HenckyElastic, StrainEnergyUsesReferenceVolume) {
    const auto m =
        Material<3>::create(parse("type: henckyElastic\ndensity: 2000\nE: 1e7\nnu: 0.3\n"), "m");
    Particles<3> p;
    p.resize(1);
    const Vec3 eps(0.01, -0.02, 0.005);
    p.be[0] = (2.0 * eps).array().exp().matrix().asDiagonal();
    p.volume0[0] = 2.0;
    p.volume[0] = 3.0;
    const ElasticConstants c(1e7, 0.3);
    EXPECT_NEAR(m->strainEnergy(p, 0), 2.0 * HenckyLaw::energyDensity(c, p.be[0]),
                1e-12 * m->strainEnergy(p, 0));
}

// ---------------------------------------------------------------------------------------------
// Linear elastic (Jaumann rate)

std::unique_ptr<Material<3>> linearElastic(double E, double nu) {
    return Material<3>::create(parse("type: linearElastic\ndensity: 2000\nE: " + std::to_string(E) +
                                     "\nnu: " + std::to_string(nu) + "\n"),
                               "m");
}

TEST(LinearElastic, SpinLeavesStressInvariantsUnchanged) {
    // Rotate a prestressed state through 90° about z by a pure spin (L skew) in small steps:
    // the Jaumann rate is objective, so the eigenvalues stay and σ_xx, σ_yy swap.
    // 10⁴ calls for one particle: one thread, so that the test does not time the OpenMP
    // fork/join of a loaded machine.
    struct OneThread {
        int saved = omp_get_max_threads();
        OneThread() { omp_set_num_threads(1); }
        ~OneThread() { omp_set_num_threads(saved); }
    } oneThread;
    const auto m = linearElastic(1e7, 0.3);
    Particles<3> p;
    p.resize(1);
    Mat3 sigma0 = Mat3::Zero();
    sigma0.diagonal() << -1e5, -2e5, -3e5;
    sigma0(0, 2) = sigma0(2, 0) = 2e4;
    m->initialise(p, 0, sigma0);
    const double omega = 1.0;
    const int steps = 10000;
    const double dt = 0.5 * pi / omega / steps;
    p.L[0] << 0.0, -omega, 0.0, omega, 0.0, 0.0, 0.0, 0.0, 0.0;
    p.F[0] = Mat3::Identity();
    p.volume[0] = p.volume0[0] = 1.0;
    const std::vector<Index> ids{0};
    const Vec3 lam0 = sortedEigenvalues(sigma0);
    for (int s = 0; s < steps; ++s) {
        ASSERT_EQ(m->updateStress(p, ids, dt), -1);
        if (s % 1000 == 999) {
            const Vec3 lam = sortedEigenvalues(p.stress[0]);
            ASSERT_LE((lam - lam0).cwiseAbs().maxCoeff(), 1e-3 * lam0.cwiseAbs().maxCoeff())
                << "step " << s << ": " << lam.transpose();
        }
    }
    // R = rotation by 90° about z: σ = R σ₀ Rᵀ.
    Mat3 R;
    R << 0, -1, 0, 1, 0, 0, 0, 0, 1;
    const Mat3 expected = R * sigma0 * R.transpose();
    EXPECT_LE((p.stress[0] - expected).norm(), 1e-3 * sigma0.norm()) << p.stress[0];
    EXPECT_LE((p.stress[0] - p.stress[0].transpose()).norm(), 1e-12 * sigma0.norm());
}

TEST(LinearElastic, UniaxialStrainIncrement) {
    const double E = 1e7, nu = 0.3;
    const auto m = linearElastic(E, nu);
    const ElasticConstants c(E, nu);
    Particles<3> p;
    p.resize(1);
    m->initialise(p, 0, Mat3::Zero());
    p.F[0] = Mat3::Identity();
    p.volume[0] = p.volume0[0] = 1.0;
    const double dt = 1e-3, rate = -0.5; // ε_xx = -5e-4
    p.L[0] = Mat3::Zero();
    p.L[0](0, 0) = rate;
    ASSERT_EQ(m->updateStress(p, {0}, dt), -1);
    const double eps = rate * dt;
    EXPECT_NEAR(p.stress[0](0, 0), c.M * eps, 1e-9 * std::fabs(c.M * eps));
    EXPECT_NEAR(p.stress[0](1, 1), c.lambda * eps, 1e-9 * std::fabs(c.lambda * eps));
    EXPECT_NEAR(p.stress[0](2, 2), c.lambda * eps, 1e-9 * std::fabs(c.lambda * eps));
    EXPECT_EQ(p.stress[0](0, 1), 0.0);
}

TEST(LinearElastic, StressIncrementIsStiffnessTimesStrain) {
    // From zero stress the spin term vanishes: Δσ = λ tr(Δε) 1 + 2G Δε for any L.
    const double E = 3e7, nu = 0.2;
    const auto m = linearElastic(E, nu);
    const ElasticConstants c(E, nu);
    std::mt19937_64 rng(9);
    Particles<3> p;
    p.resize(1);
    p.F[0] = Mat3::Identity();
    p.volume[0] = p.volume0[0] = 1.0;
    for (int trial = 0; trial < 20; ++trial) {
        m->initialise(p, 0, Mat3::Zero());
        p.L[0] = randomMatrix(rng, 1.0);
        const double dt = 1e-4;
        ASSERT_EQ(m->updateStress(p, {0}, dt), -1);
        const Mat3 deps = 0.5 * dt * (p.L[0] + p.L[0].transpose());
        const Mat3 expected = c.lambda * deps.trace() * Mat3::Identity() + 2.0 * c.G * deps;
        EXPECT_LE((p.stress[0] - expected).norm(), 1e-12 * expected.norm());
    }
}

TEST(LinearElastic, StrainEnergyIsComplementaryEnergy) {
    const double E = 1e7, nu = 0.3;
    const auto m = linearElastic(E, nu);
    const ElasticConstants c(E, nu);
    Particles<3> p;
    p.resize(1);
    Mat3 eps;
    eps << 1e-3, 2e-4, 0, 2e-4, -5e-4, 1e-4, 0, 1e-4, 3e-4;
    const Mat3 sigma = c.lambda * eps.trace() * Mat3::Identity() + 2.0 * c.G * eps;
    m->initialise(p, 0, sigma);
    p.volume[0] = p.volume0[0] = 2.0;
    const double expected = 0.5 * (sigma.array() * eps.array()).sum() * 2.0;
    EXPECT_NEAR(m->strainEnergy(p, 0), expected, 1e-10 * expected);
}

} // namespace
} // namespace mpm
