// SPDX-License-Identifier: GPL-3.0-or-later
// Body accelerations of constant/g: values against closed forms, smoothness, bounds, errors.
#include "forces/BodyAcceleration.hpp"
#include "core/Constants.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <functional>
#include <string>

namespace mpm {
namespace {

using test::catchInputError;

/// A number as YAML reads it back exactly (17 significant digits).
std::string num(double value) {
    char buffer[64];
    const auto result =
        std::to_chars(buffer, buffer + sizeof(buffer), value, std::chars_format::general, 17);
    return std::string(buffer, result.ptr);
}

template <int dim> std::unique_ptr<BodyAcceleration<dim>> make(const std::string& yaml) {
    return BodyAcceleration<dim>::create(Dictionary::fromString(yaml, "constant/g"));
}

template <int dim> std::string errorOf(const std::string& yaml) {
    return catchInputError([&] { make<dim>(yaml); }).what();
}

/// Kinetic energy gained by a unit mass on a segment [0, L] with elastic walls under the
/// x-component of g(t), from rest at x = 0, after time T (velocity Verlet; the walls do no
/// work, so the gain is the work of the field).
double largestGain(const BodyAcceleration<2>& g, double length, double duration, double dt) {
    double x = 0, v = 0, gained = 0;
    for (double t = 0; t < duration; t += dt) {
        v += 0.5 * dt * g.at(t)[0];
        x += dt * v;
        if (x < 0) x = -x, v = -v;
        if (x > length) x = 2 * length - x, v = -v;
        v += 0.5 * dt * g.at(t + dt)[0];
        gained = std::max(gained, 0.5 * v * v);
    }
    return gained;
}

TEST(BodyAccelerationTest, ValueWithoutTypeIsConstant) {
    for (const char* yaml : {"value: [0, -9.81]\n", "type: constant\nvalue: [0, -9.81]\n"}) {
        const auto g = make<2>(yaml);
        for (double t : {-1.0, 0.0, 0.37, 1e6})
            EXPECT_EQ(g->at(t), Vec<2>(0, -9.81));
        EXPECT_TRUE(g->isConstant());
        EXPECT_DOUBLE_EQ(g->maxMagnitude(), 9.81);
        EXPECT_EQ(g->totalVariation(), 0.0);
        // m |g| extent: the largest drop in potential.
        EXPECT_DOUBLE_EQ(g->energySupply(2.0, 3.0), 2.0 * 3.0 * 9.81);
    }
    const auto g3 = make<3>("value: [1, 2, -9.81]\n");
    EXPECT_EQ(g3->at(5.0), Vec3(1, 2, -9.81));
    EXPECT_EQ(BodyAcceleration<3>::constant(Vec3(0, 0, -1))->at(2.0), Vec3(0, 0, -1));
    EXPECT_EQ(BodyAcceleration<2>::constant(Vec<2>::Zero())->maxMagnitude(), 0.0);
}

TEST(BodyAccelerationTest, ConstantErrors) {
    EXPECT_NE(errorOf<2>("value: [0, -9.81, 0]\n").find("expected a sequence of 2 numbers"),
              std::string::npos);
    EXPECT_NE(errorOf<3>("value: [0, -9.81]\n").find("3"), std::string::npos);
    EXPECT_NE(errorOf<2>("vale: [0, -9.81]\n").find("value"), std::string::npos);
    EXPECT_NE(errorOf<2>("value: [0, -9.81]\nphase: 3\n").find("unknown key"), std::string::npos);
    const std::string unknown = errorOf<2>("type: vibrating\nvalue: [0, -9.81]\n");
    EXPECT_NE(unknown.find("unknown type 'vibrating'; valid types are: constant, ramp, "
                           "sinusoidal, table"),
              std::string::npos)
        << unknown;
    const InputError e = catchInputError([] { make<2>("type: constant\nvalue: [0, x]\n"); });
    EXPECT_EQ(e.file(), "constant/g");
    EXPECT_EQ(e.line(), 2);
}

TEST(BodyAccelerationTest, SinusoidalAgainstClosedForm) {
    // The vibrated layer of [002 §4.5] with Γ = A ω²/g = 3, f = 15.49 Hz, here tilted and
    // phase shifted: g = g₀ + A ω² sin(ωt + φ) d.
    const double f = 15.49, omega = 2 * pi * f, amplitude = 3 * 9.81 / (omega * omega);
    const double phase = 30.0 * pi / 180.0;
    const Vec3 d = Vec3(1, 0, 2).normalized(), g0(0, 0, -9.81);
    const std::string common =
        "type: sinusoidal\nvalue: [0, 0, -9.81]\namplitude: " + num(amplitude) +
        "\ndirection: [1, 0, 2]\nphase: 30\n";
    const auto byF = make<3>(common + "frequency: 15.49\n");
    const auto byOmega = make<3>(common + "angularFrequency: " + num(omega) + "\n");
    for (double t : {0.0, 0.0123, 0.05, 0.5, 7.3}) {
        const Vec3 expected = g0 + amplitude * omega * omega * std::sin(omega * t + phase) * d;
        EXPECT_LT((byF->at(t) - expected).norm(), 1e-12 * expected.norm()) << t;
        EXPECT_LT((byOmega->at(t) - expected).norm(), 1e-12 * expected.norm()) << t;
    }
    EXPECT_FALSE(byF->isConstant());
    EXPECT_TRUE(std::isinf(byF->totalVariation()));
}

TEST(BodyAccelerationTest, SinusoidalIsThePlateFrame) {
    // Plate displacement u(t) = A sin(ωt + φ) d: in the plate frame the material feels
    // g₀ − ü. Lift-off (g·d = 0 with g₀ = −g d) at ωt = arcsin(1/Γ) [002 §4.5 notes].
    const double omega = 2 * pi * 15.0, amplitude = 3 * 9.81 / (omega * omega);
    const auto g =
        make<2>("type: sinusoidal\nvalue: [0, -9.81]\namplitude: " + num(amplitude) +
                "\nangularFrequency: " + num(omega) + "\ndirection: [0, 0.5]\nphase: 0\n");
    const double a = amplitude, w = omega;
    const auto plate = [&](double t) { return a * std::sin(w * t); };
    const double h = 1e-5;
    for (double t : {0.001, 0.01, 0.02, 0.031}) {
        const double plateAcceleration = (plate(t + h) - 2 * plate(t) + plate(t - h)) / (h * h);
        EXPECT_NEAR(g->at(t)[1], -9.81 - plateAcceleration, 1e-4 * 9.81) << t;
        EXPECT_EQ(g->at(t)[0], 0.0);
    }
    const double gamma = a * w * w / 9.81;
    EXPECT_NEAR(g->at(std::asin(1.0 / gamma) / w)[1], 0.0, 1e-12);
    EXPECT_LT(g->at(0.5 * std::asin(1.0 / gamma) / w)[1], 0.0); // still pressed on the plate
    EXPECT_GT(g->at(1.5 * std::asin(1.0 / gamma) / w)[1], 0.0); // pulled off it
}

TEST(BodyAccelerationTest, SinusoidalBounds) {
    const auto g = make<2>("type: sinusoidal\nvalue: [1, -9.81]\namplitude: 0.002\n"
                           "frequency: 20\ndirection: [1, 3]\nphase: 10\n");
    // |g|max against a dense sampling of one period.
    const double omega = 2 * pi * 20;
    double sampled = 0;
    for (int k = 0; k <= 100000; ++k)
        sampled = std::max(sampled, g->at(k * 2 * pi / omega / 100000).norm());
    EXPECT_GE(g->maxMagnitude(), sampled);
    EXPECT_LT(g->maxMagnitude(), sampled * (1 + 1e-8));
    // m extent |g|max + 8 · ½ m (A ω)².
    const double speed = 0.002 * omega;
    EXPECT_NEAR(g->energySupply(3.0, 0.5),
                3.0 * 0.5 * g->maxMagnitude() + 8 * 0.5 * 3.0 * speed * speed, 1e-12);
    const auto still = make<2>("type: sinusoidal\nvalue: [0, -9.81]\namplitude: 0\n"
                               "frequency: 20\ndirection: [0, 1]\n");
    EXPECT_TRUE(still->isConstant());
    EXPECT_EQ(still->at(0.0123), Vec<2>(0, -9.81));
}

TEST(BodyAccelerationTest, SinusoidalBouncingLayer) {
    // A point on the vibrated plate, integrated in the plate frame (1D along d = up) with
    // Γ = 3, f = 15.49 Hz as in [002 §4.5]: it rests on the plate while g·d < 0, flies when
    // the plate pulls away and lands with restitution e.
    const double omega = 2 * pi * 15.49, amplitude = 3 * 9.81 / (omega * omega);
    const auto g = make<2>("type: sinusoidal\nvalue: [0, -9.81]\namplitude: " + num(amplitude) +
                           "\nangularFrequency: " + num(omega) + "\ndirection: [0, 1]\n");
    // Lab frame, independently: the plate is at A sin ωt; the point leaves it at
    // ωt₀ = arcsin(1/Γ) with the plate's velocity and flies under −g; its largest height
    // above the plate before landing (≈ 7.4 mm, the inelastic rise of the notes on [002]).
    const double t0 = std::asin(1.0 / 3.0) / omega;
    const double z0 = amplitude * std::sin(omega * t0),
                 v0 = amplitude * omega * std::cos(omega * t0);
    double rise = 0;
    for (double t = t0; t < t0 + 2 * pi / omega; t += 1e-7) {
        const double above =
            z0 + v0 * (t - t0) - 4.905 * (t - t0) * (t - t0) - amplitude * std::sin(omega * t);
        if (above < 0) break;
        rise = std::max(rise, above);
    }
    EXPECT_NEAR(rise, 7.4e-3, 0.1e-3);
    for (double e : {0.0, 0.3, 0.7}) {
        double z = 0, v = 0, top = 0, kinetic = 0;
        const double dt = 1e-6;
        for (double t = 0; t < 50 * 2 * pi / omega; t += dt) {
            v += dt * g->at(t + 0.5 * dt)[1];
            z += dt * v;
            if (z <= 0) {
                z = 0;
                v = v < 0 ? -e * v : v;
            }
            top = std::max(top, z);
            kinetic = std::max(kinetic, 0.5 * v * v);
        }
        if (e == 0.0) {
            EXPECT_NEAR(top, rise, 1e-3 * rise); // the same flight, seen from the plate
        }
        // The kinetic energy relative to the plate stays below energySupply, with extent =
        // the height reached.
        EXPECT_LT(kinetic, g->energySupply(1.0, top)) << e;
    }
}

TEST(BodyAccelerationTest, SinusoidalErrors) {
    const std::string base = "type: sinusoidal\nvalue: [0, -9.81]\namplitude: 0.001\n";
    EXPECT_NE(errorOf<2>(base + "direction: [0, 1]\n").find("exactly one of 'frequency'"),
              std::string::npos);
    const InputError both = catchInputError(
        [&] { make<2>(base + "direction: [0, 1]\nfrequency: 10\nangularFrequency: 62.8\n"); });
    EXPECT_NE(std::string(both.what()).find("exactly one"), std::string::npos);
    EXPECT_EQ(both.key(), "angularFrequency");
    EXPECT_NE(errorOf<2>(base + "direction: [0, 0]\nfrequency: 10\n").find("must not be zero"),
              std::string::npos);
    EXPECT_NE(errorOf<2>(base + "frequency: 10\n").find("direction"), std::string::npos);
    EXPECT_NE(errorOf<2>(base + "direction: [0, 1]\nfrequency: 0\n").find("frequency"),
              std::string::npos);
    EXPECT_NE(errorOf<2>("type: sinusoidal\nvalue: [0, -9.81]\namplitude: -0.001\n"
                         "direction: [0, 1]\nfrequency: 10\n")
                  .find("amplitude"),
              std::string::npos);
    EXPECT_NE(errorOf<3>(base + "direction: [0, 1]\nfrequency: 10\n").find("3"), std::string::npos);
}

TEST(BodyAccelerationTest, RampProfiles) {
    // [002 §4.2]: gravity 9.81 rotated by Θ = 25°, ramped up from zero over 0.1 s.
    const double theta = 25 * pi / 180;
    const Vec<2> b(9.81 * std::sin(theta), -9.81 * std::cos(theta));
    const std::string value = "value: [" + num(b[0]) + ", " + num(b[1]) + "]\nduration: 0.1\n";
    const auto cosine = make<2>("type: ramp\n" + value);
    const auto smooth = make<2>("type: ramp\nprofile: smoothstep\nstart: 0.2\n" + value);
    const Vec<2> written = cosine->at(1.0); // the value as read from the file
    EXPECT_LT((written - b).norm(), 1e-6);
    for (double s : {0.1, 0.25, 0.5, 0.8, 0.99}) {
        const Vec<2> c = 0.5 * (1 - std::cos(pi * s)) * written;
        EXPECT_LT((cosine->at(0.1 * s) - c).norm(), 1e-13) << s;
        const Vec<2> p = (3 * s * s - 2 * s * s * s) * written;
        EXPECT_LT((smooth->at(0.2 + 0.1 * s) - p).norm(), 1e-13) << s;
    }
    // Constant outside the ramp, exactly.
    for (double t : {-1.0, 0.0})
        EXPECT_EQ(cosine->at(t), Vec<2>::Zero());
    for (double t : {0.1, 0.1000001, 3.0})
        EXPECT_EQ(cosine->at(t), written);
    EXPECT_EQ(smooth->at(0.15), Vec<2>::Zero());
    EXPECT_EQ(smooth->at(0.31), written);
    EXPECT_FALSE(cosine->isConstant());
    EXPECT_DOUBLE_EQ(cosine->maxMagnitude(), written.norm());
    EXPECT_DOUBLE_EQ(cosine->totalVariation(), written.norm());
}

TEST(BodyAccelerationTest, RampIsSmooth) {
    // C¹: zero slope at both ends (the change over ε grows like ε², not ε), and the one-sided
    // slopes agree inside; |g| rises monotonically.
    for (const char* profile : {"cosine", "smoothstep"}) {
        const auto g = make<2>(std::string("type: ramp\nprofile: ") + profile +
                               "\nstart: 1\nduration: 0.5\nvalue: [3, -9]\n");
        const double eps = 1e-5, scale = Vec<2>(3, -9).norm() / 0.5; // mean slope
        EXPECT_LT((g->at(1 + eps) - g->at(1)).norm(), 1e-3 * scale * eps) << profile;
        EXPECT_LT((g->at(1.5) - g->at(1.5 - eps)).norm(), 1e-3 * scale * eps) << profile;
        double last = 0;
        for (double t = 1.001; t < 1.5; t += 0.01) {
            const Vec<2> left = (g->at(t) - g->at(t - eps)) / eps;
            const Vec<2> right = (g->at(t + eps) - g->at(t)) / eps;
            EXPECT_LT((left - right).norm(), 1e-3 * scale) << profile << " t = " << t;
            EXPECT_GE(g->at(t).norm(), last);
            last = g->at(t).norm();
        }
    }
}

TEST(BodyAccelerationTest, RampRotatesAndKeepsLength) {
    // Tilting 9.81 by 30°: the length stays 9.81 and the angle follows S(s) · 30°.
    const auto g = make<2>("type: ramp\ninitial: [0, -9.81]\nvalue: [4.905, -8.49571]\n"
                           "duration: 2\n");
    const double angle = std::atan2(4.905, 8.49571), length = Vec<2>(4.905, -8.49571).norm();
    for (double s : {0.1, 0.3, 0.5, 0.77}) {
        const Vec<2> v = g->at(2 * s);
        const double S = 0.5 * (1 - std::cos(pi * s));
        EXPECT_NEAR(v.norm(), 9.81 + S * (length - 9.81), 1e-12);
        EXPECT_NEAR(std::atan2(v[0], -v[1]), S * angle, 1e-12);
    }
    EXPECT_NEAR(g->maxMagnitude(), 9.81, 1e-4);
    EXPECT_NEAR(g->totalVariation(), 9.81 * angle, 1e-4);
    // 3D: from −z to +x through the xz plane; the y component stays zero.
    const auto g3 = make<3>("type: ramp\ninitial: [0, 0, -2]\nvalue: [2, 0, 0]\nduration: 1\n"
                            "profile: smoothstep\n");
    const Vec3 mid = g3->at(0.5);
    EXPECT_NEAR(mid.norm(), 2.0, 1e-14);
    EXPECT_NEAR(mid[0], std::sqrt(2.0), 1e-14);
    EXPECT_NEAR(mid[2], -std::sqrt(2.0), 1e-14);
    EXPECT_EQ(mid[1], 0.0);
    // Parallel ends: the magnitude is interpolated along the common direction.
    const auto grow = make<2>("type: ramp\ninitial: [0, -5]\nvalue: [0, -10]\nduration: 1\n");
    EXPECT_LT((grow->at(0.5) - Vec<2>(0, -7.5)).norm(), 1e-14);
    EXPECT_DOUBLE_EQ(grow->totalVariation(), 5.0);
    EXPECT_TRUE(
        make<2>("type: ramp\ninitial: [0, -5]\nvalue: [0, -5]\nduration: 1\n")->isConstant());
}

TEST(BodyAccelerationTest, RampErrors) {
    EXPECT_NE(errorOf<2>("type: ramp\nvalue: [0, -9.81]\nduration: -0.1\n").find("duration"),
              std::string::npos);
    EXPECT_NE(errorOf<2>("type: ramp\nvalue: [0, -9.81]\nduration: 0\n").find("duration"),
              std::string::npos);
    EXPECT_NE(errorOf<2>("type: ramp\nvalue: [0, -9.81]\n").find("missing"), std::string::npos);
    EXPECT_NE(errorOf<2>("type: ramp\ninitial: [0, 9.81]\nvalue: [0, -9.81]\nduration: 1\n")
                  .find("opposite directions"),
              std::string::npos);
    EXPECT_NE(
        errorOf<2>("type: ramp\nvalue: [0, -9.81]\nduration: 1\nprofile: linear\n").find("cosine"),
        std::string::npos);
    EXPECT_NE(errorOf<3>("type: ramp\ninitial: [0, -1]\nvalue: [0, 0, -9.81]\nduration: 1\n")
                  .find("initial"),
              std::string::npos);
}

TEST(BodyAccelerationTest, TableInterpolates) {
    const auto g = make<2>("type: table\ntable: [[0, 0, 0], [1, 0, -9.81], [2, 3, -9.81]]\n");
    EXPECT_EQ(g->at(-1.0), Vec<2>(0, 0));
    EXPECT_EQ(g->at(0.0), Vec<2>(0, 0));
    EXPECT_LT((g->at(0.5) - Vec<2>(0, -4.905)).norm(), 1e-15);
    EXPECT_EQ(g->at(1.0), Vec<2>(0, -9.81));
    EXPECT_LT((g->at(1.25) - Vec<2>(0.75, -9.81)).norm(), 1e-15);
    EXPECT_EQ(g->at(2.0), Vec<2>(3, -9.81));
    EXPECT_EQ(g->at(50.0), Vec<2>(3, -9.81));
    EXPECT_FALSE(g->isConstant());
    EXPECT_DOUBLE_EQ(g->maxMagnitude(), Vec<2>(3, -9.81).norm());
    EXPECT_DOUBLE_EQ(g->totalVariation(), 9.81 + 3.0);
    EXPECT_DOUBLE_EQ(g->energySupply(2.0, 0.5), 2.0 * 0.5 * (Vec<2>(3, -9.81).norm() + 12.81));

    const auto g3 = make<3>("type: table\ntable: [[0.5, 1, 2, 3], [1.5, 3, 2, 1]]\n");
    EXPECT_LT((g3->at(1.0) - Vec3(2, 2, 2)).norm(), 1e-15);
    EXPECT_TRUE(make<2>("type: table\ntable: [[0, 1, 2]]\n")->isConstant());
    EXPECT_TRUE(make<2>("type: table\ntable: [[0, 1, 2], [1, 1, 2]]\n")->isConstant());
}

TEST(BodyAccelerationTest, TableErrors) {
    const InputError equal =
        catchInputError([] { make<2>("type: table\ntable:\n  - [0, 0, -1]\n  - [0, 0, -2]\n"); });
    EXPECT_NE(std::string(equal.what()).find("strictly increasing time; row 1 (t = 0)"),
              std::string::npos)
        << equal.what();
    EXPECT_EQ(equal.key(), "table");
    EXPECT_NE(errorOf<2>("type: table\ntable: [[1, 0, -1], [0.5, 0, -2]]\n").find("row 1"),
              std::string::npos);
    const InputError shortRow =
        catchInputError([] { make<3>("type: table\ntable:\n  - [0, 0, -1]\n"); });
    EXPECT_NE(std::string(shortRow.what()).find("expected a sequence of 4 numbers, got 3"),
              std::string::npos);
    EXPECT_EQ(shortRow.line(), 3);
    EXPECT_NE(errorOf<2>("type: table\ntable: []\n").find("at least one row"), std::string::npos);
    EXPECT_NE(errorOf<2>("type: table\nvalue: [0, -9.81]\n").find("table"), std::string::npos);
}

TEST(BodyAccelerationTest, SupplyBoundsPumpedWork) {
    // A field that flips sign each time the point hits a wall pumps energy: after n
    // traversals E_k = n G L, far more than the constant-field bound G L. Flip times from
    // rest: t_k = √(2 k L / G). energySupply (|g|max + total variation) bounds it.
    const double G = 2.0, L = 1.0, width = 1e-6;
    std::string rows = "type: table\ntable:\n  - [0, 2, 0]\n";
    const int n = 6;
    for (int k = 1; k < n; ++k) {
        const double tk = std::sqrt(2.0 * k * L / G);
        const double before = k % 2 == 1 ? G : -G;
        rows += "  - [" + num(tk) + ", " + num(before) + ", 0]\n";
        rows += "  - [" + num(tk + width) + ", " + num(-before) + ", 0]\n";
    }
    const auto g = make<2>(rows);
    const double gained = largestGain(*g, L, std::sqrt(2.0 * n * L / G), 1e-5);
    EXPECT_GT(gained, 0.9 * n * G * L);
    EXPECT_LE(gained, g->energySupply(1.0, L));
    // The same for a ramp that turns g around by 179°.
    const auto ramp = make<2>("type: ramp\ninitial: [2, 0]\nvalue: [-1.99969541, 0.03490481]\n"
                              "start: 1\nduration: 0.5\n");
    EXPECT_LE(largestGain(*ramp, L, 10.0, 1e-5), ramp->energySupply(1.0, L));
}

} // namespace
} // namespace mpm
