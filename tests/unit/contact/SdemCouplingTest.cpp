// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/SdemCoupling.hpp"
#include "contact/Coupling.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

namespace mpm {
namespace {

constexpr double H = 0.003;  // grid spacing [m]
constexpr double Rp = 0.001; // coupling radius [m]
constexpr double Mp = 5e-4;  // point mass [kg/m]
constexpr double Kn = 6e9;   // k_n [N/m per m]
constexpr double Kt = 3e8;   // k_t [N/m per m]
constexpr double Mu = 0.1;

std::unique_ptr<CouplingLaw<2>> make(const std::string& yaml) {
    return CouplingLaw<2>::create(Dictionary::fromString(yaml, "test"), H);
}

/// A point at signed distance phi above a horizontal surface (n = +y, t = −x).
Contact<2> contact(double phi, const Vec<2>& vRel = Vec<2>::Zero()) {
    return {0, phi, Vec<2>(0, 1), vRel, Rp, Mp, 100.0};
}

} // namespace

TEST(SdemCoupling, NormalForceIsKnTimesTheOverlapAlongTheNormal) {
    const auto law = make("{type: sdem, kn: 6e9, kt: 3e8, friction: 0.1}");
    std::vector<double> slip(1, 0.0);
    std::vector<Vec<2>> f(1);
    for (double phi : {0.9 * Rp, 0.5 * Rp, 0.0, -0.3 * Rp}) {
        law->forces({contact(phi)}, 1e-6, slip, f);
        EXPECT_NEAR(f[0][1], Kn * (Rp - phi), 1e-9 * Kn * Rp) << "phi = " << phi;
        EXPECT_EQ(f[0][0], 0.0);
    }
    // Along any normal.
    const Vec<2> n = Vec<2>(3, -4) / 5;
    law->forces({{0, 0.25 * Rp, n, Vec<2>::Zero(), Rp, Mp, 100.0}}, 1e-6, slip, f);
    EXPECT_LE((f[0] - Kn * 0.75 * Rp * n).norm(), 1e-12 * Kn * Rp);
    EXPECT_FALSE(law->nonPenetrating());
    // Δt ≤ 2π √(m_p / k_n) [000 Eq. 24].
    EXPECT_NEAR(law->stableDeltaT(Mp, 100.0), 2 * M_PI * std::sqrt(Mp / Kn), 1e-18);
}

TEST(SdemCoupling, TangentialSpringSticksThenSlidesAtTheCoulombCapWithHistory) {
    const auto law = make("{type: sdem, kn: 6e9, kt: 3e8, friction: 0.1}");
    const double phi = 0.5 * Rp, fn = Kn * (Rp - phi), dt = 1e-4;
    const Vec<2> t = SdemCoupling<2>::tangent(Vec<2>(0, 1));
    ASSERT_LE((t - Vec<2>(-1, 0)).norm(), 0.0);
    std::vector<double> slip(1, 0.0);
    std::vector<Vec<2>> f(1);
    const double v = 0.01; // sliding along +x = −t
    // Stick: δ_t = −v Δt k, F_t = −k_t δ_t t opposes the motion (points along −x).
    law->forces({contact(phi, Vec<2>(v, 0))}, dt, slip, f);
    EXPECT_NEAR(slip[0], -v * dt, 1e-20);
    EXPECT_NEAR(f[0][0], -Kt * v * dt, 1e-9 * Kt * v * dt);
    law->forces({contact(phi, Vec<2>(v, 0))}, dt, slip, f);
    EXPECT_NEAR(f[0][0], -Kt * 2 * v * dt, 1e-9 * Kt * v * dt); // history accumulates
    // Keep going until the cap μ k_n ξ: then the force stays there, δ_t scaled back.
    const double capSlip = Mu * fn / Kt;
    int steps = 2;
    while (std::fabs(slip[0]) < capSlip * (1 - 1e-12) && steps < 100000) {
        law->forces({contact(phi, Vec<2>(v, 0))}, dt, slip, f);
        ++steps;
        EXPECT_LE(std::fabs(f[0][0]), Mu * fn * (1 + 1e-12));
    }
    EXPECT_NEAR(steps, capSlip / (v * dt), 1.5);
    for (int k = 0; k < 10; ++k) {
        law->forces({contact(phi, Vec<2>(v, 0))}, dt, slip, f);
        EXPECT_NEAR(f[0][0], -Mu * fn, 1e-12 * Mu * fn);
        EXPECT_NEAR(slip[0], -capSlip, 1e-15 * capSlip);
    }
    // Reversal: the spring unloads elastically from the cap (stick again), then slides back.
    law->forces({contact(phi, Vec<2>(-v, 0))}, dt, slip, f);
    EXPECT_NEAR(f[0][0], -Mu * fn + Kt * v * dt, 1e-9 * Mu * fn);
    // At rest the stored spring keeps its force (static friction).
    law->forces({contact(phi)}, dt, slip, f);
    EXPECT_NEAR(f[0][0], -Mu * fn + Kt * v * dt, 1e-9 * Mu * fn);
    // A lower normal force lowers the cap: δ_t is scaled back to it at once.
    law->forces({contact(0.9 * Rp)}, dt, slip, f);
    EXPECT_NEAR(std::fabs(f[0][0]), Mu * Kn * 0.1 * Rp, 1e-9 * Mu * fn);
    // Frictionless or without k_t: no tangential force, no history.
    for (const char* yaml :
         {"{type: sdem, kn: 6e9, kt: 3e8}", "{type: sdem, kn: 6e9, friction: 0.5}"}) {
        const auto frictionless = make(yaml);
        std::vector<double> s(1, 0.0);
        frictionless->forces({contact(phi, Vec<2>(v, 0))}, dt, s, f);
        EXPECT_EQ(f[0][0], 0.0) << yaml;
        EXPECT_EQ(s[0], 0.0) << yaml;
    }
}

TEST(SdemCoupling, RadiusAndContactPointAreTheOverlapMiddle) {
    const auto law = make("{type: sdem, kn: 1e6, radius: 0.002, verletDistance: 0.004}");
    EXPECT_EQ(law->contactRadius(0.001), 0.002);
    EXPECT_EQ(law->searchBand(), 0.004);
    EXPECT_TRUE(law->resetsAllSlip());
    const auto byVolume = make("{type: sdem, kn: 1e6}");
    EXPECT_EQ(byVolume->contactRadius(0.001), 0.001);
    EXPECT_EQ(byVolume->searchBand(), 0.0);
    // p = x − (r_p − ξ/2) n, ξ = r_p − φ: the middle of [x − r_p n, x − φ n].
    const Contact<2> c{0, 0.0015, Vec<2>(0.6, 0.8), Vec<2>::Zero(), 0.002, Mp, 100.0};
    const Vec<2> x(1, 2);
    const Vec<2> expected = x - (0.002 - 0.5 * (0.002 - 0.0015)) * c.normal;
    EXPECT_LE((law->contactPoint(x, c) - expected).norm(), 1e-15);
    // The existing laws keep x_p as the lever arm and their radius.
    const auto spring = make("{type: linearSpring, stiffness: 1}");
    EXPECT_EQ(spring->contactPoint(x, c), x);
    EXPECT_EQ(spring->contactRadius(0.001), 0.001);
    EXPECT_FALSE(spring->resetsAllSlip());
}

TEST(SdemCoupling, BadInputIsAnError) {
    EXPECT_THROW(make("{type: sdem}"), InputError);                   // kn required
    EXPECT_THROW(make("{type: sdem, kn: 0}"), InputError);            // kn > 0
    EXPECT_THROW(make("{type: sdem, kn: 1, kt: -1}"), InputError);    // kt ≥ 0
    EXPECT_THROW(make("{type: sdem, kn: 1, radius: 0}"), InputError); // radius > 0
    EXPECT_THROW(make("{type: sdem, kn: 1, verletDistance: -1}"), InputError);
    EXPECT_THROW(make("{type: sdem, kn: 1, slipThreshold: 0.1}"), InputError);
    EXPECT_THROW(make("{type: sdem, kn: 1, stiffness: 1}"), InputError); // linearSpring's key
    EXPECT_THROW(CouplingLaw<3>::create(Dictionary::fromString("{type: sdem, kn: 1}", "t"), H),
                 InputError); // 2D only
}

/// A disk body and a ring of points around it, some sliding, some inside: the force on the body
/// is −Σ f_p and its torque Σ (p − c) × (−f_p) with p the overlap middle.
TEST(SdemCoupling, BodyGetsMinusTheSumOfPointForcesAndTheirTorqueAtTheContactPoint) {
    const Grid<2> grid(Dictionary::fromString(
        "bounds: {min: [0, 0], max: [0.1, 0.1]}\ncellSize: 0.0025\n", "constant/grid"));
    std::vector<std::unique_ptr<RigidBody<2>>> bodies;
    bodies.push_back(std::make_unique<RigidBody<2>>(
        Dictionary::fromString("shape: {type: box, size: [0.03, 0.02]}\ndensity: 2000\n"
                               "position: [0.05, 0.05]\norientation: 20\n"
                               "velocity: [0.1, -0.2]\nangularVelocity: 3\n",
                               "test"),
        "block"));
    const RigidBody<2>& body = *bodies[0];
    Particles<2> p;
    const int n = 400;
    p.resize(n);
    for (int i = 0; i < n; ++i) {
        const double a = 2 * M_PI * i / n, r = 0.012 + 0.006 * ((i * 37) % 11) / 10.0;
        p.x[i] = body.position() + r * Vec<2>(std::cos(a), std::sin(a));
        p.v[i] = Vec<2>(0.3 * std::sin(3 * a), -0.2 * std::cos(a));
        p.C[i] = p.L[i] = Mat<2>::Zero();
        p.F[i] = Mat<2>::Identity();
        p.be[i] = Mat3::Identity();
        p.stress[i] = Mat3::Zero();
        p.volume0[i] = p.volume[i] = 1e-6;
        p.mass[i] = 2000 * p.volume[i];
        p.plasticStrain[i] = 0;
        p.id[i] = i;
        p.material[i] = 0;
    }
    const Index far = n - 1; // far from the body: a stale slip there must be cleared
    p.x[far] = body.position() + Vec<2>(0.04, 0.04);
    std::vector<std::unique_ptr<CouplingLaw<2>>> laws;
    laws.push_back(CouplingLaw<2>::create(
        Dictionary::fromString("{type: sdem, kn: 1e6, kt: 5e5, friction: 0.3, radius: 0.0015, "
                               "verletDistance: 0.002}",
                               "test"),
        grid.h()));
    Coupling<2> coupling(std::move(laws));
    coupling.setParticles(p);
    BlockSort<2> sort;
    ASSERT_EQ(sort.update(p, grid), -1);
    coupling.declareState(p, bodies);
    std::vector<double>& slip = p.scalar(p.addScalar({"contactSlip"}, 0.0));
    for (int step = 0; step < 3; ++step) {
        bodies[0]->clearForces();
        coupling.computeForces(p, bodies, {100.0}, nullptr, sort, grid, 1e-4);
        ASSERT_GT(coupling.numContacts(), 20);
        Vec<2> sum = Vec<2>::Zero();
        double torque = 0, scale = 0;
        int sliding = 0;
        for (std::size_t k = 0; k < coupling.gridPoints().size(); ++k) {
            const Index i = coupling.gridPoints()[k];
            const Vec<2>& f = coupling.gridForces()[k];
            Vec<2> nrm;
            const double phi = body.distance(p.x[i], nrm);
            const double rp = 0.0015;
            ASSERT_LT(phi, rp);
            EXPECT_NEAR(f.dot(nrm), 1e6 * (rp - phi), 1e-9 * 1e6 * rp);
            const Vec<2> at = p.x[i] - (rp - 0.5 * (rp - phi)) * nrm;
            const Vec<2> r = at - body.position();
            sum += f;
            torque += r[0] * (-f[1]) - r[1] * (-f[0]);
            scale += f.norm();
            sliding +=
                std::fabs(f.dot(SdemCoupling<2>::tangent(nrm))) >= 0.3 * f.dot(nrm) * (1 - 1e-12);
        }
        EXPECT_LE((body.force() + sum).norm(), 1e-13 * scale); // Σ f_p + F_body = 0
        EXPECT_NEAR(body.torque()[2], torque, 1e-13 * scale * 0.03);
        if (step == 2) {
            EXPECT_GT(sliding, 0);
        }
        // Out of contact: no history, even far away.
        for (int i = 0; i < n; ++i) {
            Vec<2> nrm;
            if (body.distance(p.x[i], nrm) >= 0.0015) {
                EXPECT_EQ(slip[i], 0.0) << i;
            }
        }
        slip[far] = 1.0; // a stale value on a point out of reach is cleared at the next step
    }
    EXPECT_EQ(slip[far], 1.0);
}

} // namespace mpm
