// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/ContactForce.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace {

using namespace mpm;

/// e of the cut linear dashpot with damping ratio ζ, by integrating ẍ = −ω₀²x − 2ζω₀ẋ (ω₀ = 1)
/// from x = 0, ẋ = −1 while the force pushes (k x + c ẋ < 0 with x < 0 the overlap): the
/// outgoing speed over the incoming one.
double integratedRestitution(double zeta) {
    const double dt = 1e-5;
    double x = 0, v = -1;
    for (int k = 0; k < 10000000; ++k) {
        const auto accel = [&](double xs, double vs) { return -xs - 2.0 * zeta * vs; };
        if (k > 0 && (x >= 0 || accel(x, v) <= 0)) break; // apart, or the force would pull
        // RK4 step of (x, v).
        const double k1x = v, k1v = accel(x, v);
        const double k2x = v + 0.5 * dt * k1v, k2v = accel(x + 0.5 * dt * k1x, v + 0.5 * dt * k1v);
        const double k3x = v + 0.5 * dt * k2v, k3v = accel(x + 0.5 * dt * k2x, v + 0.5 * dt * k2v);
        const double k4x = v + dt * k3v, k4v = accel(x + dt * k3x, v + dt * k3v);
        x += dt / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
        v += dt / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    }
    return v;
}

TEST(ContactForceTest, DashpotGivesTheRestitutionAskedOfTheCutSpring) {
    for (const double e : {0.14, 0.2, 0.3, 0.5, 0.7, 0.9, 0.99}) {
        const RestitutionDashpot d(e);
        EXPECT_NEAR(RestitutionDashpot::restitution(d.dampingRatio()), e, 1e-12) << e;
        EXPECT_NEAR(integratedRestitution(d.dampingRatio()), e, 2e-4) << e;
        // The textbook ζ = −ln e/√(π² + ln² e) is that of the uncut dashpot: the cut one with it
        // bounces higher.
        const double l = std::log(e);
        EXPECT_GT(d.dampingRatio(), -l / std::sqrt(pi * pi + l * l)) << e;
    }
    EXPECT_EQ(RestitutionDashpot(1.0).dampingRatio(), 0.0);
    EXPECT_FALSE(RestitutionDashpot(1.0).any());
    EXPECT_NEAR(RestitutionDashpot::restitution(1.0 - 1e-12), std::exp(-2.0), 1e-5);
}

TEST(ContactForceTest, TangentialSpringSticksBelowTheCapAndSlidesAtIt) {
    const Vec<2> n(0, 1), vRel(1, -0.5);
    Vec<2> xi(0.0, 0.3); // the normal part is projected out
    const Vec<2> stick = tangentialSpring<2>(xi, n, vRel, vRel.dot(n), 100.0, 0.5, 10.0, 0.01);
    EXPECT_EQ(xi, Vec<2>(0.01, 0.0));
    EXPECT_EQ(stick, Vec<2>(-1.0, 0.0));
    Vec<2> far(0.2, 0.0);
    const Vec<2> slide = tangentialSpring<2>(far, n, vRel, vRel.dot(n), 100.0, 0.5, 10.0, 0.01);
    EXPECT_DOUBLE_EQ(slide[0], -5.0); // μ f_n against the spring's stretch
    EXPECT_DOUBLE_EQ(far[0], 0.05);   // ξ scaled back to the cap
}

} // namespace
