// SPDX-License-Identifier: GPL-3.0-or-later
// μ(I) rheology on Hencky elasticity: rate-dependent return, Drucker–Prager limit, apex,
// trans-phase gasification, input checks.
#include "materials/MuI.hpp"
#include "TestSupport.hpp"
#include "materials/DruckerPrager.hpp"
#include "materials/HenckyElastic.hpp"
#include "materials/Material.hpp"

#include "core/SymmetricEigen.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

namespace mpm {
namespace {

const double sqrt2 = std::sqrt(2.0);

Dictionary parse(const std::string& text) {
    return Dictionary::fromString(text, "constant/materials");
}

using test::catchInputError;
using test::invariants;
using test::randomRotation;

// The expectations use the compression fit [000 Eq. 8] (frictionCoefficient), stated for 2D too.
const std::string elastic =
    "density: 1600\nE: 1e7\nnu: 0.3\nfrictionAngle: 30\nconeFit: compression\n";

template <int dim>
std::unique_ptr<Material<dim>> createMuI(double d = 1e-3, const std::string& extra = "") {
    return Material<dim>::create(parse("type: muI\n" + elastic + "frictionAngle2: 40\n" +
                                       "grainDiameter: " + std::to_string(d) +
                                       "\ngrainDensity: 2650\n" + extra),
                                 "sand");
}

/// createMuI with a grain diameter the decimal formatting of std::to_string would lose.
template <int dim> std::unique_ptr<Material<dim>> createMuITinyGrains() {
    return Material<dim>::create(parse("type: muI\n" + elastic +
                                       "frictionAngle2: 40\ngrainDiameter: 1e-300\n"
                                       "grainDensity: 2650\n"),
                                 "sand");
}

/// bᵉ = R exp(2ε) Rᵀ with tr ε = ev and |ε̂| = dev in random axes.
Mat3 randomElasticState(std::mt19937_64& rng, double ev, double dev) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Vec3 d(u(rng), u(rng), u(rng));
    d.array() -= d.mean();
    d *= dev / d.norm();
    const Vec3 eps = d + Vec3::Constant(ev / 3.0);
    return fromEigen(randomRotation(rng), (2.0 * eps).array().exp().matrix());
}

template <int dim> Particles<dim> makeParticles(int n) {
    Particles<dim> p;
    p.resize(n);
    for (int i = 0; i < n; ++i) {
        p.L[i].setZero();
        p.F[i].setIdentity();
        p.be[i].setIdentity();
        p.stress[i].setZero();
        p.volume0[i] = 1e-3;
        p.volume[i] = 0.98e-3; // denser than ρ₀ = ρ_c
        p.mass[i] = 1600.0 * 1e-3;
        p.plasticStrain[i] = 0.0;
    }
    return p;
}

std::vector<Index> allIds(std::size_t n) {
    std::vector<Index> ids(n);
    for (std::size_t i = 0; i < n; ++i)
        ids[i] = static_cast<Index>(i);
    return ids;
}

const double muS = frictionCoefficient(30.0), mu2 = frictionCoefficient(40.0), I0 = 0.278;

/// μ(I) [000 Eq. 9].
double muOfI(double I) {
    return I > 0 ? muS + (mu2 - muS) / (I0 / I + 1.0) : muS;
}

// ---------------------------------------------------------------------------------------------
// Input

TEST(MuI, CreateAndDefaults) {
    const auto m = createMuI<3>();
    EXPECT_DOUBLE_EQ(m->density(), 1600.0);
    EXPECT_DOUBLE_EQ(m->criticalDensity(), 1600.0);
    EXPECT_NEAR(m->defaultK0(), 0.5, 1e-15);
    const ElasticConstants c(1e7, 0.3);
    EXPECT_NEAR(m->waveSpeed(), std::sqrt(c.M / 1600.0), 1e-12 * m->waveSpeed());
    const auto& mi = dynamic_cast<const MuI<3>&>(*m).plasticity();
    const MuIFlow f = mi.flow(1e-4);
    EXPECT_NEAR(f.muS, muS, 1e-15);
    EXPECT_NEAR(f.muS + f.dMu, mu2, 1e-15);
    EXPECT_EQ(f.I0, 0.278);
    EXPECT_NEAR(f.rateScale, 1e-3 * std::sqrt(2650.0) / 1e-4, 1e-12);
    EXPECT_EQ(f.mu(0.0), f.muS);
    EXPECT_EQ(createMuI<2>(1e-3, "transPhase: off\n")->criticalDensity(), 0.0);
    EXPECT_DOUBLE_EQ(createMuI<2>(1e-3, "criticalDensity: 1400\n")->criticalDensity(), 1400.0);
    EXPECT_EQ(
        dynamic_cast<const MuI<2>&>(*createMuI<2>(1e-3, "I0: 0.5\n")).plasticity().flow(1.0).I0,
        0.5);
}

TEST(MuI, BadInputIsInputError) {
    const std::string base = "type: muI\ndensity: 1600\nE: 1e7\n";
    const std::string grains = "grainDiameter: 1e-3\ngrainDensity: 2650\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"nu: 0.3\nfrictionAngle: 30\nfrictionAngle2: 30\n" + grains, "frictionAngle2"},
        {"nu: 0.3\nfrictionAngle: 30\nfrictionAngle2: 25\n" + grains, "frictionAngle2"},
        {"nu: 0.3\nfrictionAngle: 30\nfrictionAngle2: 90\n" + grains, "frictionAngle2"},
        {"nu: 0.3\nfrictionAngle: 30\n" + grains, "frictionAngle2"},
        {"nu: 0.3\nfrictionAngle: 0\nfrictionAngle2: 40\n" + grains, "frictionAngle"},
        {"nu: 0.5\nfrictionAngle: 30\nfrictionAngle2: 40\n" + grains, "nu"},
        {"nu: 0.3\nfrictionAngle: 30\nfrictionAngle2: 40\ngrainDensity: 2650\n", "grainDiameter"},
        {"nu: 0.3\nfrictionAngle: 30\nfrictionAngle2: 40\ngrainDiameter: 0\ngrainDensity: 2650\n",
         "grainDiameter"},
        {"nu: 0.3\nfrictionAngle: 30\nfrictionAngle2: 40\ngrainDiameter: 1e-3\n", "grainDensity"},
        {"nu: 0.3\nfrictionAngle: 30\nfrictionAngle2: 40\nI0: 0\n" + grains, "I0"},
        // Isochoric flow: no dilation angle.
        {"nu: 0.3\nfrictionAngle: 30\nfrictionAngle2: 40\ndilationAngle: 5\n" + grains,
         "dilationAngle"},
    };
    for (const auto& [text, key] : cases) {
        SCOPED_TRACE(text);
        const InputError e =
            catchInputError([&, t = text] { Material<2>::create(parse(base + t), "sand"); });
        EXPECT_EQ(e.key(), key) << e.what();
    }
}

// ---------------------------------------------------------------------------------------------
// Plastic multiplier

TEST(MuI, MultiplierSolvesConsistencyOverWideRange) {
    // Residual h(Δγ) = q − G Δγ − μ(c Δγ) p, c = rateScale/√(p/J), in both branches of the
    // closed-form root (B > 0 and B ≤ 0) and against bisection.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const double G = 3.8e6;
    int negativeB = 0;
    for (int k = 0; k < 20000; ++k) {
        const MuIFlow f{muS, mu2 - muS, I0, G, std::pow(10.0, -8.0 + 14.0 * u(rng))};
        const double p = std::pow(10.0, -2.0 + 8.0 * u(rng));
        const double q = p * muS * (1.0 + std::pow(10.0, -6.0 + 8.0 * u(rng)));
        const double jInv = 0.8 + 0.4 * u(rng);
        const double x = f.multiplier(q, p, jInv);
        const double c = f.rateScale / std::sqrt(p * jInv);
        const double F = q - muS * p;
        negativeB += G * I0 + c * ((mu2 - muS) * p - F) <= 0;
        ASSERT_GT(x, 0.0);
        ASSERT_LE(x, F / G * (1 + 1e-15));
        const double h = q - G * x - f.mu(c * x) * p;
        ASSERT_LE(std::fabs(h), 1e-12 * q) << "q " << q << " p " << p << " c " << c;
        // Bisection on the monotone residual.
        double lo = 0, hi = F / G;
        for (int it = 0; it < 200; ++it) {
            const double mid = 0.5 * (lo + hi);
            (q - G * mid - f.mu(c * mid) * p > 0 ? lo : hi) = mid;
        }
        // The root is defined to the round-off of the residual, ~1e-16 q/G.
        ASSERT_NEAR(x, 0.5 * (lo + hi), 1e-11 * x + 1e-15 * q / G);
    }
    EXPECT_GT(negativeB, 100);
    // Elastic: zero.
    const MuIFlow f{muS, mu2 - muS, I0, G, 10.0};
    EXPECT_EQ(f.multiplier(0.5 * muS * 1e4, 1e4, 1.0), 0.0);
    EXPECT_EQ(f.multiplier(0.0, 1e4, 1.0), 0.0);
}

// ---------------------------------------------------------------------------------------------
// Return map

/// Random plastic trial states at several step sizes: σ on q = μ(I) p with I from the returned
/// Δγ and p, μ_s ≤ q/p ≤ μ₂, isochoric flow, σ = τ(bᵉ)/J.
template <int dim> void checkReturn(unsigned seed) {
    const auto m = createMuI<dim>();
    const ElasticConstants c(1e7, 0.3);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (double dt : {1e-7, 1e-5, 1e-3}) {
        SCOPED_TRACE(dt);
        const int n = 101;
        Particles<3> p3 = makeParticles<3>(n);
        Particles<dim> p = makeParticles<dim>(n);
        for (int i = 0; i < n; ++i) {
            const double ev = -std::pow(10.0, -5.0 + 3.0 * u(rng));
            const double ratio = 1.0 + 1e-6 + 5.0 * u(rng);
            const double dev = ratio * muS * c.K * (-ev) / (sqrt2 * c.G);
            p3.be[i] = randomElasticState(rng, ev, dev);
            if (dim == 2) {
                // Plane strain: bᵉ with axes in the plane (the trial of the 2D solver).
                Vec3 lam;
                Mat3 Q;
                symmetricEigen3(p3.be[i], lam, Q);
                const double a = 6.0 * u(rng);
                Mat3 R;
                R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
                p3.be[i] = fromEigen(R, lam);
            }
            p.be[i] = p3.be[i];
            p.volume[i] = p.volume0[i] * (0.9 + 0.09 * u(rng));
        }
        const Particles<dim> before = p;
        ASSERT_EQ(m->updateStress(p, allIds(n), dt), -1);
        for (int i = 0; i < n; ++i) {
            SCOPED_TRACE(i);
            const double jInv = p.volume0[i] / p.volume[i];
            double pt, qt, pn, qn;
            invariants(HenckyLaw::kirchhoff(c, before.be[i]), pt, qt);
            invariants(p.stress[i], pn, qn);
            const double dGamma = p.plasticStrain[i];
            ASSERT_GT(dGamma, 0.0);
            const double I = dGamma / dt * 1e-3 * std::sqrt(2650.0 / pn);
            EXPECT_NEAR(qn, muOfI(I) * pn, 1e-10 * muS * pn) << "I = " << I;
            EXPECT_GE(qn / pn, muS * (1 - 1e-12));
            EXPECT_LE(qn / pn, mu2);
            EXPECT_NEAR(qt - c.G * dGamma, muOfI(I) * pt, 1e-10 * qt);
            EXPECT_NEAR(pn / jInv, pt, 1e-10 * (pt + qt)); // isochoric: p unchanged
            EXPECT_NEAR(p.be[i].determinant(), before.be[i].determinant(), 1e-13);
            const Mat3 sigma = HenckyLaw::kirchhoff(c, p.be[i]) * jInv;
            EXPECT_LE((sigma - p.stress[i]).norm(), 1e-9 * p.stress[i].norm());
        }
    }
}

TEST(MuI, ReturnLiesOnRateDependentYieldSurface3D) {
    checkReturn<3>(41);
}
TEST(MuI, ReturnLiesOnRateDependentYieldSurface2D) {
    checkReturn<2>(42);
}

/// Same trial states through DruckerPrager (ψ = 0) and μ(I).
template <int dim>
void compareWithDruckerPrager(const Material<dim>& mui, double dt, double tol, unsigned seed) {
    const auto dp = Material<dim>::create(parse("type: druckerPrager\n" + elastic), "dp");
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const ElasticConstants c(1e7, 0.3);
    const int n = 50;
    Particles<dim> p = makeParticles<dim>(n);
    for (int i = 0; i < n; ++i) {
        const double ev = -std::pow(10.0, -4.0 + 2.0 * u(rng));
        const double dev = (0.5 + 3.0 * u(rng)) * muS * c.K * (-ev) / (sqrt2 * c.G);
        p.be[i] = randomElasticState(rng, ev, dev);
        if (dim == 2) p.be[i].template block<2, 1>(0, 2).setZero();
        if (dim == 2) p.be[i].template block<1, 2>(2, 0).setZero();
        if (dim == 2) p.L[i](0, 1) = 50.0;
    }
    Particles<dim> q = p;
    ASSERT_EQ(mui.updateStress(p, allIds(n), dt), -1);
    ASSERT_EQ(dp->updateStress(q, allIds(n), dt), -1);
    for (int i = 0; i < n; ++i) {
        EXPECT_LE((p.stress[i] - q.stress[i]).norm(), tol * q.stress[i].norm()) << i;
        EXPECT_LE((p.be[i] - q.be[i]).norm(), tol) << i;
        EXPECT_NEAR(p.plasticStrain[i], q.plasticStrain[i], tol * (1e-6 + q.plasticStrain[i])) << i;
    }
}

TEST(MuI, ZeroRateIsDruckerPrager) {
    // d → 0: I ≈ 0 at any rate.
    compareWithDruckerPrager<3>(*createMuITinyGrains<3>(), 1e-6, 1e-13, 51);
    compareWithDruckerPrager<2>(*createMuITinyGrains<2>(), 1e-6, 1e-13, 52);
    // Δt → ∞: γ̇ᵖ → 0.
    compareWithDruckerPrager<3>(*createMuI<3>(1e-3), 1e8, 1e-10, 53);
}

TEST(MuI, FrictionRisesWithShearRateUpToMu2) {
    // One trial state (q_tr/p_tr = 2 μ₂) returned with ever smaller Δt (higher γ̇ᵖ): q/p rises
    // monotonically from μ_s towards μ₂.
    const auto m = createMuI<3>();
    std::mt19937_64 rng(6);
    const ElasticConstants c(1e7, 0.3);
    const double ev = -1e-3;
    const Mat3 be = randomElasticState(rng, ev, 2.0 * mu2 * c.K * (-ev) / (sqrt2 * c.G));
    double last = 0;
    for (double dt : {1e6, 1.0, 1e-2, 1e-4, 1e-5, 1e-6, 1e-7, 1e-9, 1e-12}) {
        Particles<3> p = makeParticles<3>(1);
        p.be[0] = be;
        ASSERT_EQ(m->updateStress(p, {0}, dt), -1);
        double pr, q;
        invariants(p.stress[0], pr, q);
        SCOPED_TRACE(dt);
        EXPECT_GE(q / pr, muS * (1 - 1e-12));
        EXPECT_LT(q / pr, mu2);
        EXPECT_GT(q / pr, last);
        last = q / pr;
        if (dt == 1e6) {
            EXPECT_NEAR(q / pr, muS, 1e-9);
        }
    }
    EXPECT_GT(last, muS + 0.99 * (mu2 - muS));
}

TEST(MuI, ElasticStatesMatchHencky) {
    const auto m = createMuI<3>();
    const auto hencky =
        Material<3>::create(parse("type: henckyElastic\ndensity: 1600\nE: 1e7\nnu: 0.3\n"), "h");
    const ElasticConstants c(1e7, 0.3);
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    const int n = 19;
    Particles<3> p = makeParticles<3>(n);
    for (int i = 0; i < n; ++i) {
        const double ev = -0.001 - 0.02 * u(rng);
        p.be[i] = randomElasticState(rng, ev, 0.5 * u(rng) * muS * c.K * (-ev) / (sqrt2 * c.G));
        for (int k = 0; k < 9; ++k)
            p.L[i](k) = 1e-2 * s(rng);
    }
    Particles<3> q = p;
    ASSERT_EQ(m->updateStress(p, allIds(n), 1e-5), -1);
    ASSERT_EQ(hencky->updateStress(q, allIds(n), 1e-5), -1);
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(p.be[i], q.be[i]) << i;
        EXPECT_LE((p.stress[i] - q.stress[i]).norm(), 1e-14 * q.stress[i].norm()) << i;
        EXPECT_EQ(p.plasticStrain[i], 0.0);
    }
}

TEST(MuI, TensionApexAndGasification) {
    std::mt19937_64 rng(8);
    Particles<3> p = makeParticles<3>(9);
    for (int i = 0; i < 9; ++i) {
        const int kind = i % 3; // 0: tension, 1: gasified, 2: dense and compressed
        p.be[i] = randomElasticState(rng, kind == 0 ? 1e-3 : -1e-2, 0.01);
        p.volume[i] = kind == 1 ? 1.05e-3 : 0.98e-3;
    }
    const Particles<3> before = p;
    ASSERT_EQ(createMuI<3>()->updateStress(p, allIds(9), 1e-4), -1);
    for (int i = 0; i < 9; ++i) {
        SCOPED_TRACE(i);
        if (i % 3 == 2) {
            EXPECT_GT(p.stress[i].norm(), 1e3);
            continue;
        }
        EXPECT_EQ(p.stress[i], Mat3::Zero());
        EXPECT_EQ(p.be[i], Mat3::Identity());
        EXPECT_NEAR(p.plasticStrain[i], i % 3 == 0 ? sqrt2 * 0.01 : 0.0, 1e-12);
    }
    Particles<3> r = before;
    ASSERT_EQ(createMuI<3>(1e-3, "transPhase: false\n")->updateStress(r, allIds(9), 1e-4), -1);
    for (int i = 0; i < 9; ++i) {
        if (i % 3 != 0) {
            EXPECT_GT(r.stress[i].norm(), 1e3) << i;
        }
    }
}

} // namespace
} // namespace mpm
