// SPDX-License-Identifier: GPL-3.0-or-later
// Hypoelastic Drucker–Prager with tension cut-off [001 Eq. 31b–36] (druckerPrager with
// elasticity: hypoelastic), hypoelastic μ(I), and the composition factory (ElastoPlastic).
#include "materials/HypoelasticReturnMap.hpp"
#include "TestSupport.hpp"
#include "core/Constants.hpp"
#include "materials/DruckerPrager.hpp"
#include "materials/HenckyElastic.hpp"
#include "materials/LinearElastic.hpp"
#include "materials/Material.hpp"
#include "materials/MuI.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

namespace mpm {
namespace {

using test::catchInputError;
using test::invariants;
using test::randomRotation;

Dictionary parse(const std::string& text) {
    return Dictionary::fromString(text, "constant/materials");
}

const std::string sandBase = "type: druckerPrager\nelasticity: hypoelastic\ndensity: 1600\n"
                             "E: 1e7\nnu: 0.3\nfrictionAngle: 30\n";

/// The sand of [001] with its plane-strain fit [001 Eq. 35], stated (3D's default is the
/// compression fit) unless `extra` gives one.
template <int dim> std::unique_ptr<Material<dim>> create(const std::string& extra = "") {
    const bool fit = extra.find("coneFit") != std::string::npos;
    return Material<dim>::create(parse(sandBase + (fit ? "" : "coneFit: planeStrain\n") + extra),
                                 "sand");
}

const double sqrt2 = std::sqrt(2.0);

template <class T, class M> bool isA(const M& m) {
    return dynamic_cast<const T*>(&m) != nullptr;
}

template <int dim> const DruckerPragerPlasticity& plasticityOf(const Material<dim>& m) {
    return dynamic_cast<const DruckerPrager<dim, HypoelasticLaw>&>(m).plasticity();
}

/// σ = σ_m 1 + s with √(½ s : s) = τ in random axes (plane strain: s_xz = s_yz = 0).
template <int dim> Mat3 randomStress(std::mt19937_64& rng, double sm, double tau) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Mat3 a;
    for (int k = 0; k < 9; ++k)
        a(k) = u(rng);
    Mat3 s = 0.5 * (a + a.transpose());
    if (dim == 2) s(0, 2) = s(2, 0) = s(1, 2) = s(2, 1) = 0.0;
    s -= (s.trace() / 3.0) * Mat3::Identity();
    s *= tau / std::sqrt(0.5 * s.squaredNorm());
    return sm * Mat3::Identity() + s;
}

/// Particles at rest (L = 0: the trial stress is the stored one), V = V⁰ = 1e-3, ρ = ρ₀.
template <int dim> Particles<dim> makeParticles(int n) {
    Particles<dim> p;
    p.resize(n);
    for (int i = 0; i < n; ++i) {
        p.L[i].setZero();
        p.F[i].setIdentity();
        p.be[i].setIdentity();
        p.stress[i].setZero();
        p.volume0[i] = 1e-3;
        p.volume[i] = 0.99e-3; // dense: not gasified
        p.mass[i] = 1.6;
        p.plasticStrain[i] = 0.0;
    }
    return p;
}

std::vector<Index> allIds(int n) {
    std::vector<Index> ids(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i)
        ids[static_cast<std::size_t>(i)] = i;
    return ids;
}

// ---------------------------------------------------------------------------------------------
// Input and composition

TEST(HypoelasticDruckerPrager, CoefficientsAndDefaults) {
    // [001 Eq. 35], q_φ = 3 tan φ/√(9 + 12 tan² φ), at φ = 35° ([001 Table 3]), 22° ([001 §6])
    // and 25°.
    EXPECT_NEAR(planeStrainFrictionCoefficient(35.0), 0.5445, 5e-5);
    EXPECT_NEAR(planeStrainFrictionCoefficient(22.0), 0.3661, 5e-5);
    EXPECT_NEAR(planeStrainFrictionCoefficient(25.0), 0.4106, 5e-5);
    EXPECT_EQ(planeStrainFrictionCoefficient(0.0), 0.0);
    // Both fits put the apex at σ_m = c/tan φ.
    for (double phi : {10.0, 30.0, 45.0}) {
        const double apex = 1e3 / std::tan(phi * pi / 180.0);
        EXPECT_NEAR(planeStrainCohesionCoefficient(1e3, phi) / planeStrainFrictionCoefficient(phi),
                    apex, 1e-12 * apex);
        EXPECT_NEAR(cohesionCoefficient(1e3, phi) / frictionCoefficient(phi), apex, 1e-12 * apex);
    }

    const auto m = create<3>();
    const auto& dp = plasticityOf(*m);
    EXPECT_EQ(dp.coneFit(), ConeFit::planeStrain); // as stated by create()
    EXPECT_EQ(dp.staticFriction(), planeStrainFrictionCoefficient(30.0));
    EXPECT_EQ(dp.dilatancy(), 0.0);
    EXPECT_EQ(dp.cohesion(), 0.0);
    EXPECT_EQ(dp.tensionStrength(), 0.0);
    EXPECT_EQ(m->criticalDensity(), 1600.0);
    EXPECT_NEAR(m->defaultK0(), 0.5, 1e-15);
    const ElasticConstants c(1e7, 0.3);
    EXPECT_NEAR(m->waveSpeed(), std::sqrt(c.M / 1600.0), 1e-12 * m->waveSpeed());

    const auto coh = create<3>("cohesion: 2000\ndilationAngle: 10\n");
    const auto& dc = plasticityOf(*coh);
    EXPECT_EQ(dc.dilatancy(), planeStrainFrictionCoefficient(10.0));
    EXPECT_EQ(dc.cohesionCoefficient(), planeStrainCohesionCoefficient(2000.0, 30.0));
    EXPECT_NEAR(dc.tensionStrength(), 2000.0 / std::tan(pi / 6.0), 1e-9); // apex by default
    EXPECT_EQ(dc.cutoff().tauC, 0.0);
    const auto cut = create<3>("cohesion: 2000\ntensionStrength: 1000\n");
    EXPECT_EQ(plasticityOf(*cut).tensionStrength(), 1000.0);
    EXPECT_NEAR(plasticityOf(*cut).cutoff().tauC,
                planeStrainCohesionCoefficient(2000.0, 30.0) -
                    planeStrainFrictionCoefficient(30.0) * 1000.0,
                1e-9);
    const auto fit = create<3>("coneFit: compression\ndilationAngle: 5\n");
    EXPECT_EQ(plasticityOf(*fit).staticFriction(), frictionCoefficient(30.0));
    EXPECT_EQ(plasticityOf(*fit).dilatancy(), frictionCoefficient(5.0));
    EXPECT_EQ(create<3>("transPhase: false\n")->criticalDensity(), 0.0);
}

TEST(ElastoPlastic, FactoryPicksTheElasticLaw) {
    const std::string dp = "type: druckerPrager\ndensity: 1600\nE: 1e7\nnu: 0.3\n"
                           "frictionAngle: 30\n";
    const std::string mui = "type: muI\ndensity: 1600\nE: 1e7\nnu: 0.3\nfrictionAngle: 30\n"
                            "frictionAngle2: 40\ngrainDiameter: 1e-3\ngrainDensity: 2650\n";
    const auto byDefault = Material<2>::create(parse(dp), "a");
    const auto hencky = Material<2>::create(parse(dp + "elasticity: hencky\n"), "b");
    const auto hypo = Material<2>::create(parse(dp + "elasticity: hypoelastic\n"), "c");
    using HenckyDP = DruckerPrager<2, HenckyLaw>;
    using HypoDP = DruckerPrager<2, HypoelasticLaw>;
    EXPECT_TRUE(isA<HenckyDP>(*byDefault));
    EXPECT_TRUE(isA<HenckyDP>(*hencky));
    EXPECT_TRUE(isA<HypoDP>(*hypo));
    // The cone fit is plane strain by default, whatever the elastic law and dimension.
    EXPECT_EQ(dynamic_cast<const HenckyDP&>(*byDefault).plasticity().coneFit(),
              ConeFit::planeStrain);
    EXPECT_EQ(dynamic_cast<const HypoDP&>(*hypo).plasticity().coneFit(), ConeFit::planeStrain);
    using HenckyDP3 = DruckerPrager<3, HenckyLaw>;
    using HypoDP3 = DruckerPrager<3, HypoelasticLaw>;
    const auto hencky3 = Material<3>::create(parse(dp), "h");
    const auto hypo3 = Material<3>::create(parse(dp + "elasticity: hypoelastic\n"), "i");
    EXPECT_EQ(dynamic_cast<const HenckyDP3&>(*hencky3).plasticity().coneFit(),
              ConeFit::planeStrain);
    EXPECT_EQ(dynamic_cast<const HypoDP3&>(*hypo3).plasticity().coneFit(), ConeFit::planeStrain);
    using HypoMuI = MuI<3, HypoelasticLaw>;
    using HenckyMuI = MuI<3, HenckyLaw>;
    EXPECT_TRUE(isA<HypoMuI>(*Material<3>::create(parse(mui + "elasticity: hypoelastic\n"), "d")));
    EXPECT_TRUE(isA<HenckyMuI>(*Material<3>::create(parse(mui), "e")));
    EXPECT_TRUE(isA<LinearElastic<3>>(
        *Material<3>::create(parse("type: linearElastic\ndensity: 1\nE: 1\nnu: 0\n"), "f")));
    EXPECT_TRUE(isA<HenckyElastic<3>>(
        *Material<3>::create(parse("type: henckyElastic\ndensity: 1\nE: 1\nnu: 0\n"), "g")));
}

TEST(ElastoPlastic, InvalidCombinationsAreInputErrors) {
    const std::string dp = "type: druckerPrager\ndensity: 1600\nE: 1e7\nnu: 0.3\n"
                           "frictionAngle: 30\n";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {dp + "elasticity: hypo\n", "elasticity"},
        {dp + "elasticity: hypoelastic\nconeFit: triaxial\n", "coneFit"},
        {dp + "cohesion: 1000\n", "cohesion"}, // Hencky is cohesionless
        {dp + "elasticity: hencky\ncohesion: 1\n", "cohesion"},
        {dp + "elasticity: hypoelastic\ncohesion: -1\n", "cohesion"},
        {dp + "elasticity: hypoelastic\ntensionStrength: 1\n", "tensionStrength"}, // c = 0
        {dp + "elasticity: hypoelastic\ncohesion: 1000\ntensionStrength: 1733\n",
         "tensionStrength"}, // above the apex 1732.05
        {dp + "elasticity: hypoelastic\ncohesion: 1000\ntensionStrength: -1\n", "tensionStrength"},
        {dp + "elasticity: hypoelastic\ndilationAngle: 31\n", "dilationAngle"},
        {dp + "elasticity: hypoelastic\ncohesoin: 1000\n", "cohesoin"},
        {"type: linearElastic\ndensity: 1\nE: 1\nnu: 0\nelasticity: hencky\n", "elasticity"},
        {"type: henckyElastic\ndensity: 1\nE: 1\nnu: 0\nfrictionAngle: 30\n", "frictionAngle"},
        {"type: muI\ndensity: 1600\nE: 1e7\nnu: 0.3\nfrictionAngle: 30\nfrictionAngle2: 40\n"
         "grainDiameter: 1e-3\ngrainDensity: 2650\nelasticity: hypoelastic\ncohesion: 1\n",
         "cohesion"},
    };
    for (const auto& [text, key] : cases) {
        SCOPED_TRACE(text);
        const InputError e =
            catchInputError([&, t = text] { Material<3>::create(parse(t), "sand"); });
        EXPECT_EQ(e.key(), key) << e.what();
    }
    const InputError e =
        catchInputError([&] { Material<2>::create(parse(dp + "elasticity: linear\n"), "sand"); });
    const std::string msg = e.what();
    EXPECT_NE(msg.find("hencky"), std::string::npos) << msg;
    EXPECT_NE(msg.find("hypoelastic"), std::string::npos) << msg;
    // The largest cut-off, the apex itself, is allowed.
    EXPECT_NO_THROW(create<3>("cohesion: 1000\ntensionStrength: 1732\n"));
}

// ---------------------------------------------------------------------------------------------
// Return map

struct Sand {
    double psi, cohesion, tensionFraction; // σ_t as a fraction of the apex c/tan φ
};

/// Random trial states all around the (σ_m, τ) plane: the result is admissible (f_s ≤ 0,
/// σ_m ≤ σ_t), an admissible trial is unchanged, a returned one lies on the shear surface or the
/// cut-off, the plastic strain Δεᵖ = C⁻¹ : (σ_tr − σ) follows the potentials (shear: deviator
/// along s, tr Δεᵖ = β √2 |Δε̂ᵖ|; tension: purely volumetric; corner: a non-negative tension
/// part on top of shear), and plasticStrain grows by √2 |Δε̂ᵖ|.
template <int dim> void checkReturn(const Sand& sand, unsigned seed) {
    const ElasticConstants c(1e7, 0.3);
    const double mu = planeStrainFrictionCoefficient(30.0);
    const double beta = planeStrainFrictionCoefficient(sand.psi);
    const double k = planeStrainCohesionCoefficient(sand.cohesion, 30.0);
    const double apex = sand.cohesion / std::tan(pi / 6.0);
    std::string keys = "dilationAngle: " + std::to_string(sand.psi) +
                       "\ncohesion: " + std::to_string(sand.cohesion) + "\n";
    if (sand.cohesion > 0 && sand.tensionFraction < 1.0)
        keys += "tensionStrength: " + std::to_string(sand.tensionFraction * apex) + "\n";
    const auto m = create<dim>(keys);
    const double sigmaT = plasticityOf<dim>(*m).tensionStrength();
    if (sand.tensionFraction == 1.0) {
        EXPECT_NEAR(sigmaT, apex, 1e-12 * apex);
    }
    const double tauC = k - mu * sigmaT;

    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    const int n = 4000;
    const double scale = 2e4; // Pa
    Particles<dim> p = makeParticles<dim>(n);
    for (int i = 0; i < n; ++i) {
        p.stress[i] = randomStress<dim>(rng, scale * (3.0 * u(rng) - 2.0), 1.5 * scale * u(rng));
        p.plasticStrain[i] = u(rng);
    }
    const Particles<dim> before = p;
    ASSERT_EQ(m->updateStress(p, allIds(n), 1e-4), -1);
    const double tol = 1e-9 * scale;
    int counts[4] = {0, 0, 0, 0}; // elastic, shear, tension, corner
    for (int i = 0; i < n; ++i) {
        SCOPED_TRACE(i);
        const Mat3& tr = before.stress[i];
        const Mat3& s = p.stress[i];
        const double smTr = tr.trace() / 3.0, sm = s.trace() / 3.0;
        const double tauTr = std::sqrt(0.5 * (tr - smTr * Mat3::Identity()).squaredNorm());
        const double tau = std::sqrt(0.5 * (s - sm * Mat3::Identity()).squaredNorm());
        const double fs = tau + mu * sm - k, ft = sm - sigmaT;
        // Admissible.
        ASSERT_LE(fs, tol);
        ASSERT_LE(ft, tol);
        EXPECT_LE((s - s.transpose()).norm(), 1e-12 * scale);
        if (dim == 2) {
            EXPECT_EQ(s(0, 2), 0.0);
            EXPECT_EQ(s(1, 2), 0.0);
        }
        const double dps = p.plasticStrain[i] - before.plasticStrain[i];
        if (tauTr + mu * smTr - k <= 0.0 && smTr <= sigmaT) {
            ++counts[0];
            EXPECT_EQ(s, tr);
            EXPECT_EQ(dps, 0.0);
            continue;
        }
        // On the shear surface or on the cut-off.
        EXPECT_TRUE(std::fabs(fs) <= tol || std::fabs(ft) <= tol) << fs << " " << ft;
        // Plastic strain from the stress drop.
        const Mat3 ds = tr - s;
        const double dsm = ds.trace() / 3.0;
        const Mat3 dev = (ds - dsm * Mat3::Identity()) / (2.0 * c.G);
        const double vol = dsm / c.K; // tr Δεᵖ = tr Δσ/(3K)
        const double shear = sqrt2 * dev.norm();
        EXPECT_NEAR(dps, shear, 1e-9);
        if (shear > 1e-12) {
            // The deviatoric flow is along s_tr (coaxial return).
            const Mat3 sTr = tr - smTr * Mat3::Identity();
            EXPECT_LE((dev / dev.norm() - sTr / sTr.norm()).norm(), 1e-6);
        }
        if (std::fabs(fs) <= tol && ft < -tol) { // shear surface only
            ++counts[1];
            EXPECT_NEAR(vol, beta * shear, 1e-9 * (1.0 + shear));
            EXPECT_NEAR(dps, (tauTr + mu * smTr - k) / (c.G + mu * c.K * beta), 1e-9);
        } else if (std::fabs(ft) <= tol && fs < -tol) { // tension cut-off only
            ++counts[2];
            EXPECT_NEAR(tau, tauTr, 1e-9 * scale);
            EXPECT_EQ(dps, 0.0);
            EXPECT_GT(vol, 0.0);
        } else { // the corner: τ = τ_C, σ_m = σ_t, tension part tr Δεᵖ − β Δγ ≥ 0
            ++counts[3];
            EXPECT_NEAR(sm, sigmaT, tol);
            EXPECT_NEAR(tau, tauC, tol);
            EXPECT_GE(vol - beta * shear, -1e-9);
            EXPECT_NEAR(dps, (tauTr - tauC) / c.G, 1e-9);
        }
    }
    EXPECT_GT(counts[0], n / 20);
    EXPECT_GT(counts[1], n / 20);
    if (sand.cohesion > 0 && sand.tensionFraction < 1.0) {
        EXPECT_GT(counts[2], n / 100);
    }
    EXPECT_GT(counts[3], n / 50);
}

TEST(HypoelasticDruckerPrager, ReturnIsAdmissibleAndFollowsPotential3D) {
    checkReturn<3>({0.0, 0.0, 0.0}, 1);
    checkReturn<3>({10.0, 5e3, 0.5}, 2);
    checkReturn<3>({25.0, 5e3, 1.0}, 3);
    checkReturn<3>({30.0, 2e3, 0.0}, 4); // associated, zero tension strength with cohesion
}

TEST(HypoelasticDruckerPrager, ReturnIsAdmissibleAndFollowsPotential2D) {
    checkReturn<2>({5.0, 0.0, 0.0}, 5);
    checkReturn<2>({20.0, 1e4, 0.3}, 6);
}

TEST(HypoelasticDruckerPrager, CohesionlessTensionGoesToApex) {
    // c = 0, σ_t = 0: a tensile trial beyond the normal line through the apex returns to zero
    // stress, with plastic strain τ_tr/G; at ψ = 0 that is every trial with σ_m ≥ 0.
    const ElasticConstants c(1e7, 0.3);
    for (double psi : {0.0, 10.0}) {
        SCOPED_TRACE(psi);
        const auto m = create<3>("dilationAngle: " + std::to_string(psi) + "\n");
        const double beta = planeStrainFrictionCoefficient(psi);
        std::mt19937_64 rng(9);
        const int n = 20;
        Particles<3> p = makeParticles<3>(n);
        for (int i = 0; i < n; ++i) {
            const double sm = 1e2 * (i + 1);
            // G σ_m − K β τ > 0 (beyond the line); τ = 0 for some.
            const double tau = i % 4 == 0 ? 0.0 : 0.9 * c.G * sm / (c.K * beta + 1e-300);
            p.stress[i] = randomStress<3>(rng, sm, std::min(tau, 5e4));
            p.plasticStrain[i] = 0.5;
        }
        const Particles<3> before = p;
        ASSERT_EQ(m->updateStress(p, allIds(n), 1e-4), -1);
        for (int i = 0; i < n; ++i) {
            SCOPED_TRACE(i);
            EXPECT_EQ(p.stress[i], Mat3::Zero());
            double pt, qt;
            invariants(before.stress[i], pt, qt);
            EXPECT_NEAR(p.plasticStrain[i], 0.5 + qt / c.G, 1e-12);
        }
    }
}

TEST(HypoelasticDruckerPrager, DilatantTensileTrialWithShearReturnsOntoCone) {
    // ψ = 10°, c = 0: small tension and large shear lie on the cone side of the normal line
    // (G σ_m − K β τ < 0) and return onto the cone with p > 0.
    const ElasticConstants c(1e7, 0.3);
    const double mu = planeStrainFrictionCoefficient(30.0);
    const double beta = planeStrainFrictionCoefficient(10.0);
    const auto m = create<3>("dilationAngle: 10\n");
    std::mt19937_64 rng(10);
    Particles<3> p = makeParticles<3>(1);
    p.stress[0] = randomStress<3>(rng, 1e3, 2e4);
    ASSERT_LT(c.G * 1e3 - c.K * beta * 2e4, 0.0);
    ASSERT_EQ(m->updateStress(p, {0}, 1e-4), -1);
    double pn, qn;
    invariants(p.stress[0], pn, qn);
    const double dl = (2e4 + mu * 1e3) / (c.G + mu * c.K * beta);
    EXPECT_NEAR(pn, -1e3 + c.K * beta * dl, 1e-9 * 2e4);
    EXPECT_GT(pn, 0.0);
    EXPECT_NEAR(qn, mu * pn, 1e-9 * 2e4);
    EXPECT_NEAR(p.plasticStrain[0], dl, 1e-15);
}

TEST(HypoelasticDruckerPrager, ElasticTrialMatchesLinearElastic) {
    // Inside the surfaces the update is exactly linearElastic's, with L ≠ 0, in 2D and 3D.
    const auto lin2 =
        Material<2>::create(parse("type: linearElastic\ndensity: 1600\nE: 1e7\nnu: 0.3\n"), "l");
    const auto lin3 =
        Material<3>::create(parse("type: linearElastic\ndensity: 1600\nE: 1e7\nnu: 0.3\n"), "l");
    const auto dp2 = create<2>("cohesion: 1e3\ndilationAngle: 5\n");
    const auto dp3 = create<3>("cohesion: 1e3\ndilationAngle: 5\n");
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int n = 50;
    Particles<2> a = makeParticles<2>(n);
    Particles<3> b = makeParticles<3>(n);
    for (int i = 0; i < n; ++i) {
        a.stress[i] = randomStress<2>(rng, -2e4, 2e3 * (1.0 + u(rng)));
        b.stress[i] = randomStress<3>(rng, -2e4, 2e3 * (1.0 + u(rng)));
        for (int k = 0; k < 4; ++k)
            a.L[i](k) = 1e-2 * u(rng);
        for (int k = 0; k < 9; ++k)
            b.L[i](k) = 1e-2 * u(rng);
    }
    Particles<2> a2 = a;
    Particles<3> b2 = b;
    ASSERT_EQ(dp2->updateStress(a, allIds(n), 1e-3), -1);
    ASSERT_EQ(lin2->updateStress(a2, allIds(n), 1e-3), -1);
    ASSERT_EQ(dp3->updateStress(b, allIds(n), 1e-3), -1);
    ASSERT_EQ(lin3->updateStress(b2, allIds(n), 1e-3), -1);
    for (int i = 0; i < n; ++i) {
        EXPECT_EQ(a.stress[i], a2.stress[i]) << i;
        EXPECT_EQ(b.stress[i], b2.stress[i]) << i;
        EXPECT_EQ(a.plasticStrain[i], 0.0);
        EXPECT_EQ(b.plasticStrain[i], 0.0);
    }
}

TEST(HypoelasticDruckerPrager, Objectivity) {
    // (a) Frame indifference of the update: rotating the stress and L by R rotates the result,
    // elastic and plastic points alike. (b) A rigid spin rotates the stress: after a quarter
    // turn σ = R σ₀ Rᵀ up to the forward-Euler error, invariants and plastic strain kept.
    const auto m = create<3>("cohesion: 2e3\ntensionStrength: 1e3\ndilationAngle: 10\n");
    std::mt19937_64 rng(12);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const int n = 200;
    Particles<3> p = makeParticles<3>(n);
    for (int i = 0; i < n; ++i) {
        p.stress[i] = randomStress<3>(rng, 2e4 * u(rng) - 1e4, 2e4 * (1.0 + u(rng)));
        for (int k = 0; k < 9; ++k)
            p.L[i](k) = 1e-1 * u(rng);
    }
    Particles<3> q = p;
    const Mat3 R = randomRotation(rng);
    for (int i = 0; i < n; ++i) {
        q.stress[i] = R * p.stress[i] * R.transpose();
        q.L[i] = R * p.L[i] * R.transpose();
    }
    ASSERT_EQ(m->updateStress(p, allIds(n), 1e-3), -1);
    ASSERT_EQ(m->updateStress(q, allIds(n), 1e-3), -1);
    for (int i = 0; i < n; ++i) {
        EXPECT_LE((q.stress[i] - R * p.stress[i] * R.transpose()).norm(), 1e-9 * 2e4) << i;
        EXPECT_NEAR(q.plasticStrain[i], p.plasticStrain[i], 1e-12) << i;
    }

    Particles<2> s = makeParticles<2>(1);
    const Mat3 sigma0 = randomStress<2>(rng, -1e4, 2e3);
    s.stress[0] = sigma0;
    const double omega = 2.0, dt = 1e-5; // rad/s
    s.L[0] << 0.0, -omega, omega, 0.0;   // v = ω × x: a rigid spin about z
    const auto m2 = create<2>("cohesion: 2e3\ndilationAngle: 10\n");
    const int steps = static_cast<int>(std::lround(0.5 * pi / omega / dt));
    for (int k = 0; k < steps; ++k)
        ASSERT_EQ(m2->updateStress(s, {0}, dt), -1);
    const double a = omega * dt * steps;
    Mat3 Rz;
    Rz << std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1;
    // Forward Euler: |σ̂| grows by (1 + 4 ω² Δt²)^(N/2) ≈ 1 + 6e-5.
    EXPECT_LE((s.stress[0] - Rz * sigma0 * Rz.transpose()).norm(), 2e-4 * sigma0.norm());
    double p0, q0, p1, q1;
    invariants(sigma0, p0, q0);
    invariants(s.stress[0], p1, q1);
    EXPECT_NEAR(p1, p0, 1e-12 * p0);
    EXPECT_NEAR(q1, q0, 2e-4 * q0);
    EXPECT_EQ(s.plasticStrain[0], 0.0);
}

TEST(HypoelasticDruckerPrager, GasifiedPointsCarryNoStress) {
    std::mt19937_64 rng(13);
    Particles<3> p = makeParticles<3>(6);
    for (int i = 0; i < 6; ++i) {
        p.stress[i] = randomStress<3>(rng, -1e4, 5e2 * i); // elastic
        p.volume[i] = i < 3 ? 1.01e-3 : 0.99e-3;           // ρ < ρ₀ = ρ_c for i < 3
        p.plasticStrain[i] = 0.5;
        p.F[i] << 1.0, 3.0e4, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.01; // sheared: det F = 1.01
    }
    const Particles<3> before = p;
    ASSERT_EQ(create<3>()->updateStress(p, allIds(6), 1e-4), -1);
    for (int i = 0; i < 6; ++i) {
        SCOPED_TRACE(i);
        if (i < 3) {
            EXPECT_EQ(p.stress[i], Mat3::Zero());
            // A gas point keeps its volume only: F isotropic with J = V/V⁰.
            EXPECT_LT((p.F[i] - std::cbrt(1.01) * Mat<3>::Identity()).norm(), 1e-15);
        } else {
            EXPECT_EQ(p.stress[i], before.stress[i]);
            EXPECT_EQ(p.F[i], before.F[i]);
        }
        EXPECT_EQ(p.plasticStrain[i], 0.5);
    }
    Particles<3> r = before;
    ASSERT_EQ(create<3>("transPhase: false\n")->updateStress(r, allIds(6), 1e-4), -1);
    for (int i = 0; i < 6; ++i)
        EXPECT_EQ(r.stress[i], before.stress[i]) << i;
}

TEST(HypoelasticDruckerPrager, ReportsNonFiniteParticle) {
    const auto m = create<3>();
    Particles<3> p = makeParticles<3>(5);
    for (int i = 0; i < 5; ++i)
        p.stress[i] = -1e4 * Mat3::Identity();
    p.L[3](0, 1) = std::nan("");
    EXPECT_EQ(m->updateStress(p, allIds(5), 1e-3), 3);
}

TEST(HypoelasticDruckerPrager, InitialiseAndStrainEnergy) {
    const auto m = create<3>();
    const ElasticConstants c(1e7, 0.3);
    Particles<3> p = makeParticles<3>(1);
    Mat3 sigma0 = Mat3::Zero();
    sigma0.diagonal() << -5e3, -5e3, -1e4;
    m->initialise(p, 0, sigma0);
    EXPECT_EQ(p.stress[0], sigma0);
    EXPECT_EQ(p.be[0], Mat3::Identity());
    // (p²/(2K) + s:s/(4G)) V.
    const double pr = 2e4 / 3.0;
    const Mat3 dev = sigma0 + pr * Mat3::Identity();
    EXPECT_NEAR(m->strainEnergy(p, 0),
                (pr * pr / (2.0 * c.K) + dev.squaredNorm() / (4.0 * c.G)) * p.volume[0], 1e-15);
}

TEST(HypoelasticMuI, ReturnKeepsPressureAndMeetsRateDependentFriction) {
    // μ(I) on hypoelasticity: isochoric return τ = τ_tr − G Δγ at fixed σ_m with
    // τ = μ(I) p, I = Δγ/Δt √(d² ρ_s/p); tension goes to the apex.
    const auto m = Material<3>::create(
        parse("type: muI\nelasticity: hypoelastic\ndensity: 1600\nE: 1e7\nnu: 0.3\n"
              "frictionAngle: 20\nfrictionAngle2: 35\ngrainDiameter: 1e-2\ngrainDensity: 2650\n"
              "coneFit: planeStrain\n"),
        "m");
    const ElasticConstants c(1e7, 0.3);
    const double muS = planeStrainFrictionCoefficient(20.0);
    const double mu2 = planeStrainFrictionCoefficient(35.0);
    std::mt19937_64 rng(14);
    Particles<3> p = makeParticles<3>(3);
    p.stress[0] = randomStress<3>(rng, -1e4, 2e4);
    p.stress[1] = randomStress<3>(rng, -1e4, 1e3); // elastic
    p.stress[2] = randomStress<3>(rng, 1e2, 1e3);  // tension
    const Particles<3> before = p;
    const double dt = 1e-4;
    ASSERT_EQ(m->updateStress(p, allIds(3), dt), -1);
    double pt, qt, pn, qn;
    invariants(before.stress[0], pt, qt);
    invariants(p.stress[0], pn, qn);
    EXPECT_NEAR(pn, pt, 1e-9 * pt);
    const double dg = p.plasticStrain[0];
    EXPECT_NEAR(qn, qt - c.G * dg, 1e-9 * qt);
    const double I = dg / dt * std::sqrt(1e-4 * 2650.0 / pn);
    const double muI = muS + (mu2 - muS) * I / (0.278 + I);
    EXPECT_NEAR(qn, muI * pn, 1e-9 * qt);
    EXPECT_GT(qn, muS * pn * (1.0 + 1e-6)); // rate dependence shows
    EXPECT_EQ(p.stress[1], before.stress[1]);
    EXPECT_EQ(p.stress[2], Mat3::Zero());
}

} // namespace
} // namespace mpm
