// SPDX-License-Identifier: GPL-3.0-or-later
#include "particles/InitialVelocity.hpp"

#include "TestSupport.hpp"
#include "core/Constants.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace mpm {
namespace {

template <int dim> std::unique_ptr<InitialVelocity<dim>> velocityOf(const std::string& set) {
    return InitialVelocity<dim>::create(Dictionary::fromString(set, "constant/particles"));
}

TEST(InitialVelocity, VectorUniformAndAbsentGiveOneVelocity) {
    const Vec<2> x(0.3, 0.7);
    EXPECT_EQ(velocityOf<2>("material: sand")->at(x), Vec<2>::Zero());
    EXPECT_EQ(velocityOf<2>("velocity: [1, -2]")->at(x), Vec<2>(1, -2));
    EXPECT_EQ(velocityOf<3>("velocity: {type: uniform, value: [1, -2, 3]}")->at(Vec3::Ones()),
              Vec3(1, -2, 3));
}

/// v = A sin((2n − 1)π s / 2L) d: zero at the fixed end, A at the free end of mode 1, −A at the
/// free end of mode 2.
TEST(InitialVelocity, AxialModeIsTheBarsMode) {
    const auto m1 = velocityOf<2>("velocity: {type: axialMode, amplitude: 0.5, direction: [2, 0], "
                                  "length: 4, origin: [1, 0]}");
    EXPECT_NEAR(m1->at(Vec<2>(1, 0.3)).norm(), 0.0, 1e-15);
    EXPECT_NEAR(m1->at(Vec<2>(5, 0.3))[0], 0.5, 1e-15);
    EXPECT_NEAR(m1->at(Vec<2>(3, 0.3))[0], 0.5 * std::sin(pi / 4), 1e-15);
    EXPECT_EQ(m1->at(Vec<2>(3, 0.3))[1], 0.0);
    const auto m2 = velocityOf<2>(
        "velocity: {type: axialMode, amplitude: 0.5, direction: [1, 0], length: 4, mode: 2}");
    EXPECT_NEAR(m2->at(Vec<2>(4, 0))[0], -0.5, 1e-15);
}

/// v = A R(k r) r̂: R = J₁ with k = j₀,₁/a in 2D, j₁ with k = π/a in 3D; zero at the centre.
TEST(InitialVelocity, RadialModeIsTheBreathingMode) {
    const auto v2 =
        velocityOf<2>("velocity: {type: radialMode, amplitude: -2, centre: [1, 1], radius: 0.5}");
    EXPECT_EQ(v2->at(Vec<2>(1, 1)), Vec<2>::Zero());
    const Vec<2> at2 = v2->at(Vec<2>(1, 1.25));
    EXPECT_NEAR(at2[1], -2 * std::cyl_bessel_j(1.0, 2.404825557695773 * 0.5), 1e-14);
    EXPECT_EQ(at2[0], 0.0);
    const auto v3 =
        velocityOf<3>("velocity: {type: radialMode, amplitude: 3, centre: [0, 0, 0], radius: 2}");
    EXPECT_NEAR(v3->at(Vec3(1, 0, 0))[0], 3 * std::sph_bessel(1, pi / 2), 1e-14);
}

TEST(InitialVelocity, BadInputIsReported) {
    const std::string unknown =
        test::catchInputError([] { velocityOf<2>("velocity: {type: swirl}"); }).what();
    EXPECT_NE(unknown.find("valid types are: axialMode, radialMode, uniform"), std::string::npos)
        << unknown;
    const std::string zero = test::catchInputError([] {
                                 velocityOf<2>("velocity: {type: axialMode, amplitude: 1, "
                                               "direction: [0, 0], length: 1}");
                             }).what();
    EXPECT_NE(zero.find("direction must not be zero"), std::string::npos) << zero;
    const std::string typo = test::catchInputError([] {
                                 velocityOf<2>("velocity: {type: uniform, valeu: [1, 0]}");
                             }).what();
    EXPECT_NE(typo.find("valeu"), std::string::npos) << typo;
    const std::string size =
        test::catchInputError([] { velocityOf<3>("velocity: [1, 0]"); }).what();
    EXPECT_NE(size.find("velocity"), std::string::npos) << size;
}

} // namespace
} // namespace mpm
