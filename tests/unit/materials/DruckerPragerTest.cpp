// SPDX-License-Identifier: GPL-3.0-or-later
// Drucker–Prager on Hencky elasticity: return map in principal logarithmic strain, apex,
// trans-phase gasification, input checks.
#include "materials/DruckerPrager.hpp"
#include "TestSupport.hpp"
#include "core/Constants.hpp"
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
const std::string sand = "type: druckerPrager\ndensity: 1600\nE: 1e7\nnu: 0.3\nfrictionAngle: "
                         "30\nconeFit: compression\n";

template <int dim> std::unique_ptr<Material<dim>> create(const std::string& extra = "") {
    return Material<dim>::create(parse(sand + extra), "sand");
}

/// bᵉ = R exp(2ε) Rᵀ for principal Hencky strains ε with volumetric part ev and a deviatoric part
/// of norm dev in a random direction, in random axes R (plane strain: R about z).
template <int dim> Mat3 randomElasticState(std::mt19937_64& rng, double ev, double dev) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Vec3 d(u(rng), u(rng), u(rng));
    d.array() -= d.mean();
    d *= dev / d.norm();
    const Vec3 eps = d + Vec3::Constant(ev / 3.0);
    Mat3 R = randomRotation(rng);
    if (dim == 2) {
        const double a = pi * u(rng);
        R << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    }
    return fromEigen(R, (2.0 * eps).array().exp().matrix());
}

/// n particles at rest (L = 0, so that the trial bᵉ is the stored one), V⁰ = 1e-3,
/// V = J V⁰, m = ρ₀ V⁰.
template <int dim> Particles<dim> makeParticles(int n, double rho0 = 1600.0) {
    Particles<dim> p;
    p.resize(n);
    for (int i = 0; i < n; ++i) {
        p.L[i].setZero();
        p.F[i].setIdentity();
        p.be[i].setIdentity();
        p.stress[i].setZero();
        p.volume0[i] = 1e-3;
        p.volume[i] = 1e-3;
        p.mass[i] = rho0 * 1e-3;
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

// ---------------------------------------------------------------------------------------------
// Helpers

TEST(DruckerPrager, FrictionCoefficientEq8) {
    // φ = 30°: μ = 2√3 · ½ / (3 − ½) = 2√3/5.
    EXPECT_NEAR(frictionCoefficient(30.0), 2.0 * std::sqrt(3.0) / 5.0, 1e-15);
    EXPECT_EQ(frictionCoefficient(0.0), 0.0);
    EXPECT_NEAR(frictionCoefficient(90.0), std::sqrt(3.0), 1e-15);
}

// ---------------------------------------------------------------------------------------------
// Input

TEST(DruckerPrager, CreateAndDefaults) {
    const auto m = create<3>();
    const auto& dp = dynamic_cast<const DruckerPrager<3>&>(*m).plasticity();
    EXPECT_EQ(m->name(), "sand");
    EXPECT_DOUBLE_EQ(m->density(), 1600.0);
    EXPECT_DOUBLE_EQ(m->criticalDensity(), 1600.0); // ρ_c = initial density [000 §3.1]
    EXPECT_EQ(dp.dilationAngle(), 0.0);
    EXPECT_EQ(dp.dilatancy(), 0.0);
    EXPECT_NEAR(dp.staticFriction(), 2.0 * std::sqrt(3.0) / 5.0, 1e-15);
    EXPECT_NEAR(m->defaultK0(), 0.5, 1e-15); // Jaky: 1 − sin 30°
    const ElasticConstants c(1e7, 0.3);
    EXPECT_NEAR(m->waveSpeed(), std::sqrt(c.M / 1600.0), 1e-12 * m->waveSpeed());
    EXPECT_DOUBLE_EQ(create<2>("criticalDensity: 1500\n")->criticalDensity(), 1500.0);
    EXPECT_EQ(create<2>("transPhase: false\n")->criticalDensity(), 0.0);
    EXPECT_EQ(create<2>("transPhase: no\ncriticalDensity: 1500\n")->criticalDensity(), 0.0);
    const auto dil = create<3>("dilationAngle: 10\n");
    EXPECT_NEAR(dynamic_cast<const DruckerPrager<3>&>(*dil).plasticity().dilatancy(),
                frictionCoefficient(10), 1e-15);
    // Hencky elastic materials never gasify.
    EXPECT_EQ(Material<3>::create(parse("type: henckyElastic\ndensity: 1\nE: 1\nnu: 0\n"), "m")
                  ->criticalDensity(),
              0.0);
}

TEST(DruckerPrager, BadInputIsInputError) {
    const std::string base = "type: druckerPrager\ndensity: 1600\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"E: 1e7\nnu: 0.3\nfrictionAngle: 0\n", "frictionAngle"},
        {"E: 1e7\nnu: 0.3\nfrictionAngle: -5\n", "frictionAngle"},
        {"E: 1e7\nnu: 0.3\nfrictionAngle: 90\n", "frictionAngle"},
        {"E: 1e7\nnu: 0.3\n", "frictionAngle"},
        {"E: 1e7\nnu: 0.3\nfrictionAngle: 30\ndilationAngle: 31\n", "dilationAngle"},
        {"E: 1e7\nnu: 0.3\nfrictionAngle: 30\ndilationAngle: -1\n", "dilationAngle"},
        {"E: 1e7\nnu: 0.5\nfrictionAngle: 30\n", "nu"},
        {"E: 1e7\nnu: 0.7\nfrictionAngle: 30\n", "nu"},
        {"E: 0\nnu: 0.3\nfrictionAngle: 30\n", "E"},
        {"E: 1e7\nnu: 0.3\nfrictionAngle: 30\ncriticalDensity: -1\n", "criticalDensity"},
        {"E: 1e7\nnu: 0.3\nfrictionAngle: 30\ntransPhase: maybe\n", "transPhase"},
        {"E: 1e7\nnu: 0.3\nfrictionAngle: 30\nfrictionAngel: 30\n", "frictionAngel"},
    };
    for (const auto& [text, key] : cases) {
        SCOPED_TRACE(text);
        const InputError e =
            catchInputError([&, t = text] { Material<3>::create(parse(base + t), "sand"); });
        EXPECT_EQ(e.key(), key) << e.what();
    }
    // ψ = φ (associated flow) is allowed.
    EXPECT_NO_THROW(create<3>("dilationAngle: 30\n"));
}

TEST(DruckerPrager, ConeFitIsPlaneStrainByDefaultAndCompressionIn2DIsWarned) {
    // The default fit keeps φ in plane strain (simple shear) in 2D and 3D.
    const std::string base = "type: druckerPrager\ndensity: 1600\nE: 1e7\nnu: 0.3\n"
                             "frictionAngle: 30\n";
    using DP2 = DruckerPrager<2, HenckyLaw>;
    using DP3 = DruckerPrager<3, HenckyLaw>;
    const auto m2 = Material<2>::create(parse(base), "sand");
    const auto m3 = Material<3>::create(parse(base), "sand");
    const auto& p2 = dynamic_cast<const DP2&>(*m2).plasticity();
    const auto& p3 = dynamic_cast<const DP3&>(*m3).plasticity();
    EXPECT_EQ(p2.coneFit(), ConeFit::planeStrain);
    EXPECT_EQ(p3.coneFit(), ConeFit::planeStrain);
    EXPECT_NEAR(planeStrainAngle(p2.staticFriction()), 30.0, 1e-12);
    EXPECT_NEAR(planeStrainAngle(p3.staticFriction()), 30.0, 1e-12);
    const auto c3 = Material<3>::create(parse(base + "coneFit: compression\n"), "sand");
    EXPECT_NEAR(compressionAngle(dynamic_cast<const DP3&>(*c3).plasticity().staticFriction()), 30.0,
                1e-12);
    // The measurement: the compression fit of 30° is 49.1° in plane strain, and the
    // plane-strain fit of 30° is 21.4° in triaxial compression.
    EXPECT_NEAR(planeStrainAngle(frictionCoefficient(30.0)), 49.1, 0.05);
    EXPECT_NEAR(compressionAngle(planeStrainFrictionCoefficient(30.0)), 21.4, 0.05);
    EXPECT_EQ(planeStrainAngle(0.9), 90.0); // 12 μ² ≥ 9: beyond any plane-strain angle
    // The compression fit in 2D is warned about, with the angle it amounts to.
    testing::internal::CaptureStderr();
    Material<2>::create(parse(base + "coneFit: compression\n"), "sand");
    const std::string w2 = testing::internal::GetCapturedStderr();
    EXPECT_NE(w2.find("coneFit: compression in a 2D run"), std::string::npos) << w2;
    EXPECT_NE(w2.find("acts as φ = 49.1°"), std::string::npos) << w2;
    EXPECT_NE(w2.find("constant/materials:6"), std::string::npos) << w2; // file:line of the key
    testing::internal::CaptureStderr();
    Material<2>::create(parse(base + "coneFit: planeStrain\n"), "sand");
    Material<3>::create(parse(base), "sand");
    Material<3>::create(parse(base + "coneFit: compression\n"), "sand");
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
}

TEST(DruckerPrager, DescribeStatesTheDerivedConstants) {
    const auto m = Material<2>::create(
        parse("type: druckerPrager\ndensity: 1500\nE: 1e6\nnu: 0.3\nfrictionAngle: 30\n"), "s");
    const std::string d = m->describe();
    EXPECT_NE(d.find("density 1500 kg/m3"), std::string::npos) << d;
    EXPECT_NE(d.find("cone fit planeStrain: mu = 0.4804 (φ = 30° in plane strain, 21.4° in "
                     "triaxial compression)"),
              std::string::npos)
        << d;
    EXPECT_NE(d.find("K0 of a geostatic initial stress (1 - sin phi) = 0.5"), std::string::npos)
        << d;
    EXPECT_NE(d.find("trans-phase: critical density 1500 kg/m3"), std::string::npos) << d;
    const auto off = Material<2>::create(parse("type: druckerPrager\ndensity: 1500\nE: 1e6\n"
                                               "nu: 0.3\nfrictionAngle: 30\ntransPhase: false\n"),
                                         "s");
    EXPECT_NE(off->describe().find("trans-phase: off"), std::string::npos);
}

TEST(DruckerPrager, UnknownTypeListsGranularTypes) {
    const InputError e =
        catchInputError([] { Material<3>::create(parse("type: sandy\ndensity: 1600\n"), "m"); });
    const std::string msg = e.what();
    EXPECT_EQ(e.key(), "type") << msg;
    EXPECT_NE(msg.find("druckerPrager"), std::string::npos) << msg;
    EXPECT_NE(msg.find("muI"), std::string::npos) << msg;
    EXPECT_NE(msg.find("henckyElastic"), std::string::npos) << msg;
}

// ---------------------------------------------------------------------------------------------
// Return map

/// Random plastic trial states (compressive, q_tr/p_tr up to 6 μ) in one call: the returned
/// stress lies on F = q − μ p = 0, Δγ = F_tr/(G + μKβ), ε_v changes by −β Δγ, σ = τ(bᵉ)/J,
/// and the deviatoric direction is kept.
template <int dim> void checkReturn(double psi, unsigned seed) {
    const auto m = create<dim>("dilationAngle: " + std::to_string(psi) + "\n");
    const ElasticConstants c(1e7, 0.3);
    const double mu = frictionCoefficient(30.0), beta = frictionCoefficient(psi);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 203;
    Particles<dim> p = makeParticles<dim>(n);
    for (int i = 0; i < n; ++i) {
        // ε_v from −1e-5 to −0.1; |ε̂| so that q_tr/(μ p_tr) ∈ (1, 6).
        const double ev = -std::pow(10.0, -5.0 + 4.0 * u(rng));
        const double ratio = 1.0 + 1e-6 + 5.0 * u(rng);
        const double dev = ratio * mu * c.K * (-ev) / (sqrt2 * c.G);
        p.be[i] = randomElasticState<dim>(rng, ev, dev);
        p.volume[i] = p.volume0[i] * (0.9 + 0.09 * u(rng)); // denser than ρ₀: not gasified
        p.plasticStrain[i] = u(rng);
    }
    const Particles<dim> before = p;
    ASSERT_EQ(m->updateStress(p, allIds(n), 1e-4), -1);
    for (int i = 0; i < n; ++i) {
        SCOPED_TRACE(i);
        const double jInv = p.volume0[i] / p.volume[i];
        double pt, qt, pn, qn;
        invariants(HenckyLaw::kirchhoff(c, before.be[i]), pt, qt);
        invariants(p.stress[i], pn, qn);
        ASSERT_GT(qt, mu * pt);
        EXPECT_NEAR(qn, mu * pn, 1e-10 * mu * pn);
        const double dGamma = (qt - mu * pt) / (c.G + mu * c.K * beta);
        EXPECT_NEAR(p.plasticStrain[i] - before.plasticStrain[i], dGamma, 1e-9 * dGamma);
        // (Hencky strain conditioning: ε from ln λ carries ~1e-16 |ε| absolute errors.)
        EXPECT_NEAR(pn / jInv, pt + c.K * beta * dGamma, 1e-10 * (pt + qt));
        // ln det bᵉ = 2 ε_v.
        const double evOld = 0.5 * std::log(before.be[i].determinant());
        const double evNew = 0.5 * std::log(p.be[i].determinant());
        EXPECT_NEAR(evNew - evOld, -beta * dGamma, 1e-10 * std::fabs(evOld) + 1e-14);
        if (psi == 0) {
            EXPECT_NEAR(p.be[i].determinant(), before.be[i].determinant(), 1e-13);
        }
        // The stored bᵉ gives the stored stress.
        const Mat3 sigma = HenckyLaw::kirchhoff(c, p.be[i]) * jInv;
        EXPECT_LE((sigma - p.stress[i]).norm(), 1e-9 * p.stress[i].norm());
        // Coaxial return: the deviator keeps its direction.
        const Mat3 tauTrial = HenckyLaw::kirchhoff(c, before.be[i]);
        const Mat3 sOld = tauTrial + pt * Mat3::Identity();
        const Mat3 sNew = p.stress[i] + pn * Mat3::Identity();
        EXPECT_LE((sNew / sNew.norm() - sOld / sOld.norm()).norm(), 1e-9);
        EXPECT_LE((p.stress[i] - p.stress[i].transpose()).norm(), 1e-12 * p.stress[i].norm());
        if (dim == 2) {
            EXPECT_EQ(p.stress[i](0, 2), 0.0);
            EXPECT_EQ(p.be[i](1, 2), 0.0);
        }
    }
}

TEST(DruckerPrager, ReturnLiesOnYieldSurfaceIsochoric3D) {
    checkReturn<3>(0.0, 11);
}
TEST(DruckerPrager, ReturnLiesOnYieldSurfaceIsochoric2D) {
    checkReturn<2>(0.0, 12);
}
TEST(DruckerPrager, ReturnLiesOnYieldSurfaceDilatant3D) {
    checkReturn<3>(10.0, 13);
}
TEST(DruckerPrager, ReturnLiesOnYieldSurfaceAssociated2D) {
    checkReturn<2>(30.0, 14);
}

TEST(DruckerPrager, DilationRaisesPressureAndLowersElasticVolume) {
    const auto iso = create<3>();
    const auto dil = create<3>("dilationAngle: 15\n");
    Particles<3> a = makeParticles<3>(1);
    std::mt19937_64 rng(5);
    a.be[0] = randomElasticState<3>(rng, -0.01, 0.05);
    a.volume[0] = 0.95e-3;
    Particles<3> b = a;
    ASSERT_EQ(iso->updateStress(a, {0}, 1e-4), -1);
    ASSERT_EQ(dil->updateStress(b, {0}, 1e-4), -1);
    double pa, qa, pb, qb;
    invariants(a.stress[0], pa, qa);
    invariants(b.stress[0], pb, qb);
    EXPECT_GT(pb, pa);                                       // dilatancy: p rises
    EXPECT_LT(b.be[0].determinant(), a.be[0].determinant()); // elastic volume falls
    EXPECT_GT(qb, qa);
    EXPECT_LT(b.plasticStrain[0], a.plasticStrain[0]);
}

/// Points inside the yield surface: bᵉ exactly as HenckyElastic, stress to round-off, no
/// plastic strain; with L ≠ 0, in any order, for sizes around the batch width.
template <int dim> void checkElastic(int n, unsigned seed) {
    const auto m = create<dim>();
    const auto hencky =
        Material<dim>::create(parse("type: henckyElastic\ndensity: 1600\nE: 1e7\nnu: 0.3\n"), "h");
    const ElasticConstants c(1e7, 0.3);
    const double mu = frictionCoefficient(30.0);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0), s(-1.0, 1.0);
    Particles<dim> p = makeParticles<dim>(n + 2);
    std::vector<Index> ids;
    for (int i = 0; i < n + 2; ++i) {
        const double ev = -0.001 - 0.02 * u(rng);
        const double dev = 0.5 * u(rng) * mu * c.K * (-ev) / (sqrt2 * c.G);
        p.be[i] = randomElasticState<dim>(rng, ev, dev);
        for (int a = 0; a < dim; ++a)
            for (int b = 0; b < dim; ++b)
                p.L[i](a, b) = 1e-2 * s(rng);
        p.volume[i] = p.volume0[i] * (0.95 + 0.04 * u(rng));
        if (i % 5 != 2) ids.push_back(i);
    }
    std::shuffle(ids.begin(), ids.end(), rng);
    Particles<dim> q = p;
    const Particles<dim> before = p;
    ASSERT_EQ(m->updateStress(p, ids, 1e-3), -1);
    ASSERT_EQ(hencky->updateStress(q, ids, 1e-3), -1);
    for (int i = 0; i < n + 2; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(p.be[i], q.be[i]);
        EXPECT_LE((p.stress[i] - q.stress[i]).norm(), 1e-14 * q.stress[i].norm());
        EXPECT_EQ(p.plasticStrain[i], before.plasticStrain[i]);
    }
}

TEST(DruckerPrager, ElasticStatesMatchHencky3D) {
    for (int n : {1, 7, 8, 9, 30})
        checkElastic<3>(n, 20 + n);
}

TEST(DruckerPrager, ElasticStatesMatchHencky2D) {
    for (int n : {1, 8, 13})
        checkElastic<2>(n, 30 + n);
}

TEST(DruckerPrager, TensionGoesToApex) {
    const auto m = create<3>();
    std::mt19937_64 rng(7);
    Particles<3> p = makeParticles<3>(10);
    std::vector<double> dev(10);
    for (int i = 0; i < 10; ++i) {
        dev[i] = i % 3 == 0 ? 0.0 : 0.01 * (i + 1);
        p.be[i] = randomElasticState<3>(rng, 1e-4 * (i + 1), dev[i]);
        p.volume[i] = 0.99e-3; // dense: the apex is reached by tension, not by gasification
        p.plasticStrain[i] = 0.25;
    }
    ASSERT_EQ(m->updateStress(p, allIds(10), 1e-4), -1);
    for (int i = 0; i < 10; ++i) {
        SCOPED_TRACE(i);
        EXPECT_EQ(p.stress[i], Mat3::Zero());
        EXPECT_EQ(p.be[i], Mat3::Identity());
        // Plastic shear strain += √2 |ε̂_tr| (engineering measure).
        EXPECT_NEAR(p.plasticStrain[i], 0.25 + sqrt2 * dev[i], 1e-12);
    }
}

/// ψ > 0: the apex region is bounded by the potential's normal through the apex, not by the
/// hydrostatic axis. A tensile trial (ε_v > 0) with enough shear (ε_v < √2 β |ε̂|, i.e.
/// q_tr/G > −p_tr/(K β)) returns onto the cone with p > 0 and Δγ from consistency; a trial
/// beyond the normal line goes to the apex.
TEST(DruckerPrager, DilatantTensileTrialWithShearReturnsOntoCone) {
    const double psi = 5.0;
    const auto m = create<3>("dilationAngle: 5\n");
    const ElasticConstants c(1e7, 0.3);
    const double mu = frictionCoefficient(30.0), beta = frictionCoefficient(psi);
    std::mt19937_64 rng(17);
    Particles<3> p = makeParticles<3>(2);
    p.be[0] = randomElasticState<3>(rng, 1e-4, 0.01); // √2 β |ε̂| ≈ 1.5e-3 > ε_v: cone side
    p.be[1] = randomElasticState<3>(rng, 1e-4, 1e-4); // √2 β |ε̂| ≈ 1.5e-5 < ε_v: apex side
    for (int i = 0; i < 2; ++i) {
        p.volume[i] = 0.99e-3; // dense: not gasified
        p.plasticStrain[i] = 0.25;
    }
    const Particles<3> before = p;
    ASSERT_EQ(m->updateStress(p, allIds(2), 1e-4), -1);

    const double jInv = 1e-3 / 0.99e-3;
    double pt, qt, pn, qn;
    invariants(HenckyLaw::kirchhoff(c, before.be[0]), pt, qt);
    ASSERT_LT(pt, 0.0); // tensile trial
    invariants(p.stress[0], pn, qn);
    const double dGamma = (qt - mu * pt) / (c.G + mu * c.K * beta);
    EXPECT_GT(pn, 0.0);
    EXPECT_NEAR(qn, mu * pn, 1e-9 * qt);
    EXPECT_NEAR(p.plasticStrain[0] - 0.25, dGamma, 1e-9 * dGamma);
    // p = (G p_tr + K β q_tr)/(G + μ K β) (Kirchhoff), σ = τ/J.
    EXPECT_NEAR(pn / jInv, (c.G * pt + c.K * beta * qt) / (c.G + mu * c.K * beta), 1e-9 * qt);
    EXPECT_LE((HenckyLaw::kirchhoff(c, p.be[0]) * jInv - p.stress[0]).norm(), 1e-9 * qt);

    EXPECT_EQ(p.stress[1], Mat3::Zero());
    EXPECT_EQ(p.be[1], Mat3::Identity());
    EXPECT_NEAR(p.plasticStrain[1], 0.25 + sqrt2 * 1e-4, 1e-12);

    // Isochoric flow (ψ = 0) sends the first trial to the apex: its apex region is ε_v ≥ 0.
    Particles<3> r = before;
    ASSERT_EQ(create<3>()->updateStress(r, {0}, 1e-4), -1);
    EXPECT_EQ(r.stress[0], Mat3::Zero());
}

/// Random tensile trials at ψ = 5° and ψ = φ: the apex exactly beyond the normal line
/// ε_v ≥ √2 β |ε̂|, else a return onto the cone with p ≥ 0 whose pressure vanishes as the trial
/// approaches the line (continuity of the map across the region boundary).
template <int dim> void checkTensileRegions(double psi, unsigned seed) {
    const auto m = create<dim>("dilationAngle: " + std::to_string(psi) + "\n");
    const ElasticConstants c(1e7, 0.3);
    const double mu = frictionCoefficient(30.0), beta = frictionCoefficient(psi);
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 400;
    Particles<dim> p = makeParticles<dim>(n);
    for (int i = 0; i < n; ++i) {
        const double dev = 0.02 * u(rng);
        const double ev = 2.0 * sqrt2 * beta * dev * u(rng); // both sides of the line
        p.be[i] = randomElasticState<dim>(rng, ev, dev);
        p.volume[i] = 0.99e-3;
    }
    const Particles<dim> before = p;
    ASSERT_EQ(m->updateStress(p, allIds(n), 1e-4), -1);
    int cone = 0, apex = 0;
    for (int i = 0; i < n; ++i) {
        SCOPED_TRACE(i);
        double pt, qt, pn, qn;
        invariants(HenckyLaw::kirchhoff(c, before.be[i]), pt, qt);
        invariants(p.stress[i], pn, qn);
        // Distance of the trial from the normal line in Kirchhoff stress (G p + K β q = 0).
        const double side = (c.G * pt + c.K * beta * qt) / (c.G + mu * c.K * beta);
        if (side > 1e-9 * qt) {
            ++cone;
            EXPECT_NEAR(pn / (1e-3 / 0.99e-3), side, 1e-9 * qt);
            EXPECT_NEAR(qn, mu * pn, 1e-9 * qt);
        } else if (side < -1e-9 * qt) {
            ++apex;
            EXPECT_EQ(p.stress[i], Mat3::Zero());
        }
    }
    EXPECT_GT(cone, n / 4);
    EXPECT_GT(apex, n / 4);
}

TEST(DruckerPrager, DilatantTensileRegions3D) {
    checkTensileRegions<3>(5.0, 61);
    checkTensileRegions<3>(30.0, 62);
}
TEST(DruckerPrager, DilatantTensileRegions2D) {
    checkTensileRegions<2>(5.0, 63);
}

TEST(DruckerPrager, GasifiedPointsCarryNoStress) {
    std::mt19937_64 rng(8);
    Particles<3> p = makeParticles<3>(12);
    for (int i = 0; i < 12; ++i) {
        p.be[i] = randomElasticState<3>(rng, -0.01, 0.002 * (i % 4));        // elastic or plastic
        p.volume[i] = p.volume0[i] * (i < 6 ? 1.0 + 1e-3 * (i + 1) : 0.999); // ρ < ρ₀ for i < 6
        p.plasticStrain[i] = 0.5;
    }
    const Particles<3> before = p;
    const auto m = create<3>();
    ASSERT_EQ(m->updateStress(p, allIds(12), 1e-4), -1);
    for (int i = 0; i < 12; ++i) {
        SCOPED_TRACE(i);
        if (i < 6) {
            EXPECT_EQ(p.stress[i], Mat3::Zero());
            EXPECT_EQ(p.be[i], Mat3::Identity());
            EXPECT_EQ(p.plasticStrain[i], 0.5);
        } else {
            EXPECT_GT(p.stress[i].norm(), 1e3);
        }
    }
    // transPhase: false keeps the stress of the same loose points.
    Particles<3> r = before;
    ASSERT_EQ(create<3>("transPhase: false\n")->updateStress(r, allIds(12), 1e-4), -1);
    for (int i = 0; i < 12; ++i)
        EXPECT_GT(r.stress[i].norm(), 1e3) << i;
    // A lower ρ_c keeps points above it.
    Particles<3> s = before;
    ASSERT_EQ(create<3>("criticalDensity: 1590\n")->updateStress(s, allIds(12), 1e-4), -1);
    for (int i = 0; i < 12; ++i)
        EXPECT_GT(s.stress[i].norm(), 1e3) << i;
    // A gasified point re-compacted above ρ_c starts from zero stress.
    p.volume[0] = 0.9999e-3;
    p.L[0].setZero();
    ASSERT_EQ(m->updateStress(p, {0}, 1e-4), -1);
    EXPECT_EQ(p.be[0], Mat3::Identity());
    EXPECT_EQ(p.stress[0], Mat3::Zero());
}

TEST(DruckerPrager, GasVolumeTakesTheNeighbourhoodsDensityAwayFromBodies) {
    // ρ_c = 1600. Points 0, 1, 4 are gasified (ρ̄_p, the `phaseDensity` field, below ρ_c),
    // 2 and 3 dense. Own densities m_p/V_p: 0 and 4 looser than their neighbourhood, 1 denser;
    // 4 next to a body.
    const double rhoBar[5] = {1590.0, 1400.0, 1600.0, 1700.0, 1590.0};
    const double rhoOwn[5] = {1500.0, 1595.0, 1550.0, 1650.0, 1500.0};
    const auto run = [&](const std::string& extra) {
        Particles<3> p = makeParticles<3>(5);
        const auto m = create<3>(extra);
        m->declareState(p);
        const TransPhaseFields f = transPhaseFields(p);
        const std::size_t near = p.addFlag(FieldInfo{"nearBody", false, false});
        p.flag(near)[4] = 1; // next to a body (contact/Coupling.cpp)
        for (int i = 0; i < 5; ++i) {
            p.scalar(f.density)[i] = rhoBar[i];
            p.volume[i] = p.mass[i] / rhoOwn[i];
            p.F[i] = std::cbrt(p.volume[i] / p.volume0[i]) * Mat<3>::Identity();
        }
        EXPECT_EQ(m->updateStress(p, allIds(5), 1e-4), -1);
        for (int i = 0; i < 5; ++i)
            EXPECT_EQ(p.flag(f.gasified)[i], rhoBar[i] < 1600.0 ? 1 : 0) << i;
        return p;
    };
    const auto own = [&](const Particles<3>& p, int i) { return p.mass[i] / rhoOwn[i]; };
    const Particles<3> n = run(""); // the default, `neighbourhood`
    for (int i : {0, 1}) { // gas, looser or denser than ρ̄: V = m/ρ̄, V = det F V⁰, no stress
        EXPECT_NEAR(n.volume[i], n.mass[i] / rhoBar[i], 1e-15) << i;
        EXPECT_NEAR(n.F[i].determinant() * n.volume0[i], n.volume[i], 1e-15) << i;
        EXPECT_EQ(n.stress[i], Mat3::Zero()) << i;
    }
    for (int i : {2, 3, 4}) // dense, or gas next to a body: kept
        EXPECT_EQ(n.volume[i], own(n, i)) << i;
    const Particles<3> o = run("gasVolume: point\n"); // every volume kept
    for (int i = 0; i < 5; ++i)
        EXPECT_EQ(o.volume[i], own(o, i)) << i;
    EXPECT_NE(create<3>("")->describe().find("from the neighbourhood's density"),
              std::string::npos);
    EXPECT_NE(create<3>("gasVolume: point\n")->describe().find("kept by each point"),
              std::string::npos);
    EXPECT_EQ(catchInputError([] { create<3>("gasVolume: grains\n"); }).key(), "gasVolume");
    // Without the trans-phase relation there is no gasified point to act on: the default is
    // `point`, and `neighbourhood` an error, not a key that silently does nothing.
    EXPECT_NE(create<3>("transPhase: false\n")->describe().find("trans-phase: off"),
              std::string::npos);
    EXPECT_EQ(
        catchInputError([] { create<3>("gasVolume: neighbourhood\ntransPhase: false\n"); }).key(),
        "gasVolume");
}

TEST(DruckerPrager, BatchResultsDoNotDependOnNeighbours) {
    // Elastic, plastic, tensile and gasified points mixed in batches give what each gives alone.
    const auto m = create<3>("dilationAngle: 5\n");
    std::mt19937_64 rng(9);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 29;
    Particles<3> p = makeParticles<3>(n);
    for (int i = 0; i < n; ++i) {
        const int kind = i % 4;
        const double ev = kind == 2 ? 0.002 : -0.005;
        p.be[i] = randomElasticState<3>(rng, ev, kind == 0 ? 1e-4 : 0.01 * u(rng));
        p.volume[i] = p.volume0[i] * (kind == 3 ? 1.01 : 0.98);
        for (int k = 0; k < 9; ++k)
            p.L[i](k) = 0.2 * u(rng) - 0.1;
    }
    Particles<3> q = p;
    ASSERT_EQ(m->updateStress(p, allIds(n), 1e-3), -1);
    for (int i = 0; i < n; ++i) {
        ASSERT_EQ(m->updateStress(q, {i}, 1e-3), -1);
        EXPECT_LE((p.stress[i] - q.stress[i]).norm(), 1e-12 * (1 + q.stress[i].norm())) << i;
        EXPECT_LE((p.be[i] - q.be[i]).norm(), 1e-14) << i;
        EXPECT_NEAR(p.plasticStrain[i], q.plasticStrain[i], 1e-14) << i;
    }
}

TEST(DruckerPrager, SimpleShearReachesYieldRatio) {
    // Confined isochoric simple shear over many steps: q/p rises elastically to μ_s and stays
    // there while the plastic shear strain grows at the imposed rate.
    const auto m = create<3>();
    const ElasticConstants c(1e7, 0.3);
    const double mu = frictionCoefficient(30.0);
    Particles<3> p = makeParticles<3>(1);
    m->initialise(p, 0, -1e4 * Mat3::Identity());
    p.L[0].setZero();
    p.L[0](0, 1) = 1.0; // γ̇ = 1/s
    const double dt = 1e-4;
    for (int s = 0; s < 2000; ++s)
        ASSERT_EQ(m->updateStress(p, {0}, dt), -1);
    double pr, q;
    invariants(p.stress[0], pr, q);
    EXPECT_NEAR(q / pr, mu, 1e-10);
    // γ = 0.2 in all, of which q/G ≈ 2e-3 elastic.
    EXPECT_GT(p.plasticStrain[0], 0.19);
    EXPECT_LT(p.plasticStrain[0], 0.2);
    EXPECT_NEAR(p.be[0].determinant(), std::exp(-2e4 / c.K), 1e-12); // isochoric
}

TEST(DruckerPrager, ReportsNonFiniteParticleAlsoWhenGasified) {
    const auto m = create<3>();
    Particles<3> p = makeParticles<3>(12);
    p.L[9](0, 1) = std::nan("");
    p.L[4](1, 1) = std::nan("");
    p.volume[4] = 2e-3; // gasified
    EXPECT_EQ(m->updateStress(p, allIds(12), 1e-3), 4);
    EXPECT_EQ(m->updateStress(p, {11, 10, 9}, 1e-3), 9);
}

TEST(DruckerPrager, InitialiseAndStrainEnergy) {
    const auto m = create<3>();
    const ElasticConstants c(1e7, 0.3);
    Particles<3> p = makeParticles<3>(2);
    Mat3 sigma0 = Mat3::Zero();
    sigma0.diagonal() << -5e3, -5e3, -1e4; // K0 = 0.5
    m->initialise(p, 0, sigma0);
    m->initialise(p, 1, Mat3::Zero());
    EXPECT_EQ(p.stress[0], sigma0);
    EXPECT_EQ(p.be[1], Mat3::Identity());
    EXPECT_LE((HenckyLaw::kirchhoff(c, p.be[0]) - sigma0).norm(), 1e-9 * sigma0.norm());
    EXPECT_NEAR(m->strainEnergy(p, 0), HenckyLaw::energyDensity(c, p.be[0]) * 1e-3, 1e-15);
    EXPECT_EQ(m->strainEnergy(p, 1), 0.0);
}

} // namespace
} // namespace mpm
