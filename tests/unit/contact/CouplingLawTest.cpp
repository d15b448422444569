// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/CouplingLaw.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace mpm;

namespace {

constexpr double H = 0.004;    // grid spacing [m]
constexpr double Rp = 0.0025;  // coupling radius [m]
constexpr double Mp = 2.0e-5;  // point mass [kg]
constexpr double Wave = 29.46; // wave speed [m/s]

Contact<3> contact(double phi, const Vec<3>& vRel = Vec<3>::Zero()) {
    return {0, phi, Vec<3>(0, 0, 1), vRel, Rp, Mp, Wave};
}

double normalForce(const CouplingLaw<3>& law, double phi) {
    std::vector<double> slip(1, 0.0);
    std::vector<Vec<3>> f(1);
    law.forces({contact(phi)}, 1e-5, slip, f);
    return f[0][2];
}

std::unique_ptr<CouplingLaw<3>> make(const std::string& yaml) {
    return CouplingLaw<3>::create(Dictionary::fromString(yaml, "test"), H);
}

} // namespace

TEST(CouplingLaw, BarrierIsZeroOutsideRpAndGrowsWithoutBoundTowardsTheSurface) {
    const auto law = make("{type: barrier, minimumGap: 1e-6}");
    EXPECT_EQ(normalForce(*law, Rp), 0.0);
    EXPECT_EQ(normalForce(*law, 2 * Rp), 0.0);
    double previous = 0;
    for (double s : {0.9, 0.5, 0.2, 0.05, 0.01, 0.001}) {
        const double f = normalForce(*law, s * Rp);
        EXPECT_GT(f, previous) << "xi/rp = " << s;
        previous = f;
    }
    EXPECT_GT(previous, 1e2 * normalForce(*law, 0.5 * Rp));
    EXPECT_TRUE(law->nonPenetrating());
}

TEST(CouplingLaw, BarrierForceIsMinusTheDerivativeOfTheBarrierEnergy) {
    // B(ξ) = -κ (ξ - r_p)² ln(ξ/r_p) [000 Eq. 22]; recover κ from one force value, then
    // check f = -dB/dξ by central differences across the range.
    const auto law = make("{type: barrier, minimumGap: 1e-6}");
    const double x0 = 0.5 * Rp;
    const double g0 = (x0 - Rp) * (2 * std::log(x0 / Rp) - Rp / x0 + 1);
    const double kappa = normalForce(*law, x0) / g0;
    auto B = [&](double x) { return -kappa * (x - Rp) * (x - Rp) * std::log(x / Rp); };
    for (double s : {0.1, 0.3, 0.7, 0.95}) {
        const double x = s * Rp, e = 1e-7 * Rp;
        const double fd = -(B(x + e) - B(x - e)) / (2 * e);
        EXPECT_NEAR(normalForce(*law, x), fd, 1e-6 * std::fabs(fd)) << "xi/rp = " << s;
    }
}

TEST(CouplingLaw, BarrierStiffnessAtXiBarIsTheCriticalStiffness) {
    // κ from stability: k_N(ξ̄) = 4 m_p π² c² / h² [000 Eq. 25-27].
    const auto law = make("{type: barrier, xiBar: 0.2, minimumGap: 1e-6}");
    const double xb = 0.2 * Rp, e = 1e-6 * Rp;
    const double kN = -(normalForce(*law, xb + e) - normalForce(*law, xb - e)) / (2 * e);
    const double kCrit = 4 * Mp * M_PI * M_PI * Wave * Wave / (H * H);
    EXPECT_NEAR(kN, kCrit, 1e-5 * kCrit);
}

TEST(CouplingLaw, BarrierClampsAtTheMinimumGap) {
    const auto law = make("{type: barrier, minimumGap: 0.05}");
    EXPECT_DOUBLE_EQ(law->minimumGap(Rp), 0.05 * Rp);
    EXPECT_DOUBLE_EQ(normalForce(*law, -Rp), normalForce(*law, 0.05 * Rp));
    EXPECT_TRUE(std::isfinite(normalForce(*law, 0.0)));
}

TEST(CouplingLaw, LinearSpringIsHookeInTheOverlap) {
    const auto law = make("{type: linearSpring, stiffness: 1000}");
    EXPECT_EQ(normalForce(*law, Rp), 0.0);
    EXPECT_NEAR(normalForce(*law, 0.4 * Rp), 1000 * 0.6 * Rp, 1e-12);
    EXPECT_NEAR(normalForce(*law, -Rp), 1000 * 2 * Rp, 1e-12); // no limit: points sink in
    EXPECT_FALSE(law->nonPenetrating());
    // Δt ≤ 2π √(m_p / k_N) [000 Eq. 24].
    EXPECT_NEAR(law->stableDeltaT(Mp, Wave), 2 * M_PI * std::sqrt(Mp / 1000), 1e-15);
}

TEST(CouplingLaw, SmoothedCoulombFrictionOpposesSlipAndReachesMuFn) {
    const auto law = make("{type: barrier, friction: 0.4, slipThreshold: 0.01, minimumGap: 1e-6}");
    const double fn = normalForce(*law, 0.5 * Rp);
    std::vector<double> slip(1, 0.0);
    std::vector<Vec<3>> f(1);
    const Vec<3> vRel(0.1, 0, -0.05); // sliding along +x and approaching
    double previous = 0;
    for (int k = 0; k < 200; ++k) {
        law->forces({contact(0.5 * Rp, vRel)}, 1e-5, slip, f);
        EXPECT_LE(f[0][0], 0.0); // opposes the slip
        EXPECT_LE(-f[0][0], 0.4 * fn * (1 + 1e-12));
        EXPECT_GE(-f[0][0], previous - 1e-15); // the smoothing m(u_T) only grows [004 Eq. 36]
        previous = -f[0][0];
        EXPECT_NEAR(f[0][2], fn, 1e-12 * fn);
    }
    EXPECT_GT(slip[0], 0.01 * Rp);
    EXPECT_NEAR(-f[0][0], 0.4 * fn, 1e-12 * fn); // full Coulomb once u_T ≥ s_p
}

TEST(CouplingLaw, UnknownTypeAndBadKeysAreInputErrors) {
    EXPECT_THROW(make("{type: penalty}"), InputError);
    EXPECT_THROW(make("{type: barrier, xiBar: 1.5}"), InputError);
    EXPECT_THROW(make("{type: barrier, xiBar: 0.1, minimumGap: 0.2}"), InputError);
    EXPECT_THROW(make("{type: barrier, fricton: 0.2}"), InputError);
    EXPECT_THROW(make("{type: linearSpring, stiffness: -1}"), InputError);
}
