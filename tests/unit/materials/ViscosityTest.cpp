// SPDX-License-Identifier: GPL-3.0-or-later
// The viscosity policies of ElastoPlastic (materials/Viscosity.hpp): the Kelvin–Voigt stress
// [002 Eq. 13] and the restitution viscosity [002 Eq. 40, 42] against hand-computed answers, and
// NoViscosity as the compile-time default of every inviscid material.
#include "materials/Viscosity.hpp"
#include "materials/DruckerPrager.hpp"
#include "materials/MuI.hpp"
#include "materials/ViscoelasticMuI.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <type_traits>

namespace mpm {
namespace {

KelvinVoigtViscosity kelvinVoigt(const std::string& keys, double density = 1475.0) {
    const Dictionary dict =
        Dictionary::fromString("E: 2e7\nnu: 0.3\n" + keys, "constant/materials");
    return KelvinVoigtViscosity(dict, ElasticConstants(dict), density);
}

TEST(Viscosity, KelvinVoigtStressOfAGivenRate) {
    // ϑ = 100, η = 7 Pa·s; D with tr D = 2 1/s: σᵛ = 200 1 + 14 (D − ⅔ 1) [Pa] [002 Eq. 13].
    const KelvinVoigtViscosity v = kelvinVoigt("bulkViscosity: 100\nshearViscosity: 7\n");
    Mat3 D;
    D << 1.0, 2.0, 0.0, 2.0, -3.0, 0.5, 0.0, 0.5, 4.0;
    const Mat3 s = v.stress(D);
    Mat3 expected;
    expected << 200.0 + 14.0 / 3.0, 28.0, 0.0, 28.0, 200.0 - 14.0 * 11.0 / 3.0, 7.0, 0.0, 7.0,
        200.0 + 14.0 * 10.0 / 3.0;
    EXPECT_NEAR((s - expected).norm(), 0.0, 1e-12);
    EXPECT_DOUBLE_EQ(v.pWaveViscosity(), 100.0 + 4.0 * 7.0 / 3.0);
    // A shear rate alone: no mean stress; an isotropic rate alone: ϑ tr D on the diagonal.
    Mat3 shear = Mat3::Zero();
    shear(0, 1) = shear(1, 0) = 3.0;
    EXPECT_DOUBLE_EQ(v.stress(shear).trace(), 0.0);
    EXPECT_DOUBLE_EQ(v.stress(shear)(0, 1), 42.0);
    EXPECT_NEAR((v.stress(Mat3::Identity()) - 300.0 * Mat3::Identity()).norm(), 0.0, 1e-12);
}

TEST(Viscosity, RestitutionViscosityIsEquation40) {
    // ϑ = 0.237 d √(M ρ) |ln e|^(π/2): d = 2 mm, M = 10⁸ Pa, ρ = 1600 kg/m³, e = 0.5 gives
    // 0.237 · 2e-3 · 4e5 · 0.693147^1.5708 = 106.6124 Pa·s.
    EXPECT_NEAR(restitutionViscosity(0.5, 2e-3, 1e8, 1600.0), 106.61235871754397, 1e-9);
    EXPECT_EQ(restitutionViscosity(1.0, 2e-3, 1e8, 1600.0), 0.0); // elastic collisions: no damping
    // Through the keys (E = 20 MPa, ν = 0.3: M = 26.92 MPa; ρ₀ = 1475, d = 1 mm, e = 0.2):
    // ϑ = 99.7355, η = (G/K) ϑ = 46.0318 [002 Eq. 42], ϑ + 4η/3 = 161.1112 Pa·s.
    const KelvinVoigtViscosity v = kelvinVoigt("restitution: 0.2\ngrainDiameter: 1e-3\n");
    EXPECT_NEAR(v.bulkViscosity(), 99.73551155858513, 1e-9);
    EXPECT_NEAR(v.shearViscosity(), 46.03177456550083, 1e-9);
    EXPECT_NEAR(v.pWaveViscosity(), 161.11121097925292, 1e-9);
    // bulkViscosity alone: η = (G/K) ϑ; neither: undamped.
    EXPECT_NEAR(kelvinVoigt("bulkViscosity: 30\n").shearViscosity(), 30.0 * 0.46153846153846156,
                1e-12);
    EXPECT_EQ(kelvinVoigt("").pWaveViscosity(), 0.0);
}

// The default policy is NoViscosity: the inviscid types are the compositions they were, with no
// viscosity to read, state to carry or step limit to take.
static_assert(!NoViscosity::viscous && KelvinVoigtViscosity::viscous);
static_assert(std::is_same_v<MuI<2, HypoelasticLaw>,
                             ElastoPlastic<2, HypoelasticLaw, MuIPlasticity, NoViscosity>>);
static_assert(
    std::is_same_v<ViscoelasticMuI<3>,
                   ElastoPlastic<3, HypoelasticLaw, TanMuIPlasticity, KelvinVoigtViscosity>>);

TEST(Viscosity, InviscidMaterialsTakeNoViscousStepLimitAndReadF) {
    const auto m = Material<2>::create(
        Dictionary::fromString("{type: muI, density: 1530, E: 1.0e6, nu: 0.3, frictionAngle: "
                               "20.9, frictionAngle2: 32.8, grainDiameter: 0.0007, "
                               "grainDensity: 2600, elasticity: hypoelastic}",
                               "constant/materials"),
        "m");
    EXPECT_EQ(m->pWaveViscosity(), 0.0);
    EXPECT_EQ(m->viscousStepFactor(1e-3), 1.0);
    EXPECT_FALSE(m->volumeFromRate());
    const auto v = Material<2>::create(
        Dictionary::fromString("{type: viscoelasticMuI, density: 1475, E: 2e7, nu: 0.3, "
                               "frictionAngle: 21, frictionAngle2: 33, grainDiameter: 1e-3, "
                               "grainDensity: 2500, restitution: 0.2}",
                               "constant/materials"),
        "v");
    EXPECT_NEAR(v->pWaveViscosity(), 161.11121097925292, 1e-9);
    EXPECT_TRUE(v->volumeFromRate());
}

} // namespace
} // namespace mpm
