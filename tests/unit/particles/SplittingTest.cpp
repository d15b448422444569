// SPDX-License-Identifier: GPL-3.0-or-later
// Particle splitting: a point stretched beyond maxStretch becomes two halves along the stretch,
// keeping mass, momentum, volume, stress and the centre of mass; a rotation or a stretch below
// the limit splits nothing; the halves are not split again until they are stretched again.
#include "particles/Splitting.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <vector>

namespace mpm {
namespace {

/// One point of side a = 0.01 m (V⁰ = a^dim), density 1500, at x0, with F and a stress.
template <int dim> Particles<dim> onePoint(const Mat<dim>& F, Index id = 7) {
    Particles<dim> p;
    p.resize(1);
    p.x[0] = Vec<dim>::Constant(0.5);
    p.v[0] = Vec<dim>::LinSpaced(1.0, 2.0);
    p.C[0].setZero();
    p.L[0].setZero();
    p.F[0] = F;
    p.be[0] = 1.01 * Mat3::Identity();
    p.stress[0] = -1000.0 * Mat3::Identity();
    p.volume0[0] = std::pow(0.01, dim);
    p.volume[0] = F.determinant() * p.volume0[0];
    p.mass[0] = 1500.0 * p.volume0[0];
    p.plasticStrain[0] = 0.3;
    p.id[0] = id;
    p.material[0] = 0;
    return p;
}

/// `splitting` in system/mpmSchemes: a map sets maxStretch, `off` disables, and absent the
/// splitting is on (maxStretch 4) exactly when the scene has a granular material.
TEST(Splitting, SchemesSelectTheSplittingAndGranularScenesSplitByDefault) {
    const auto make = [](const std::string& text, bool granular) {
        Particles<2> p = onePoint<2>(Mat<2>::Identity());
        return ParticleSplitting<2>::create(Dictionary::fromString(text, "system/mpmSchemes"),
                                            granular, p);
    };
    const auto byDefault = make("kernel: linear", true);
    ASSERT_NE(byDefault, nullptr);
    EXPECT_EQ(byDefault->maxStretch(), 4.0);
    EXPECT_TRUE(byDefault->byDefault());
    EXPECT_EQ(make("kernel: linear", false), nullptr);
    EXPECT_EQ(make("splitting: off", true), nullptr);
    EXPECT_EQ(make("splitting: false", true), nullptr);
    const auto given = make("splitting: {maxStretch: 2.5}", false);
    ASSERT_NE(given, nullptr);
    EXPECT_EQ(given->maxStretch(), 2.5);
    EXPECT_FALSE(given->byDefault());

    const std::string on = test::catchInputError([&] { make("splitting: on", true); }).what();
    EXPECT_NE(on.find("expected off or a map"), std::string::npos) << on;
    const std::string one =
        test::catchInputError([&] { make("splitting: {maxStretch: 1}", true); }).what();
    EXPECT_NE(one.find("maxStretch"), std::string::npos) << one;
    const std::string typo =
        test::catchInputError([&] { make("splitting: {maxStrech: 4}", true); }).what();
    EXPECT_NE(typo.find("maxStre"), std::string::npos) << typo;
}

TEST(Splitting, StretchedPointBecomesTwoHalvesAlongTheStretch) {
    Mat<2> F;
    F << 3.0, 0.0, 0.0, 1.0 / 3.0; // isochoric stretch 3 along x
    Particles<2> p = onePoint<2>(F);
    ParticleSplitting<2> split(2.0, p);
    const Comm comm;
    ASSERT_EQ(split.apply(p, comm, 1.0), 1);
    ASSERT_EQ(p.size(), 2u);
    // Halves at x0 ± σ a / 4 along the stretch (σ = 3, a = 0.01).
    EXPECT_NEAR(std::fabs(p.x[0].x() - 0.5), 0.0075, 1e-15);
    EXPECT_NEAR(p.x[0].x() + p.x[1].x(), 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(p.x[0].y(), 0.5);
    EXPECT_DOUBLE_EQ(p.x[1].y(), 0.5);
    for (int c = 0; c < 2; ++c) {
        EXPECT_DOUBLE_EQ(p.mass[c], 0.5 * 1500.0 * 1e-4);
        EXPECT_DOUBLE_EQ(p.volume0[c], 0.5e-4);
        EXPECT_DOUBLE_EQ(p.volume[c], 0.5e-4); // det F = 1
        EXPECT_EQ(p.v[c], Vec<2>(1.0, 2.0));
        EXPECT_EQ(p.F[c], F);
        EXPECT_EQ(p.stress[c], -1000.0 * Mat3::Identity());
        EXPECT_EQ(p.be[c], 1.01 * Mat3::Identity());
        EXPECT_DOUBLE_EQ(p.plasticStrain[c], 0.3);
        EXPECT_EQ(split.levels(p)[c], 1);
    }
    EXPECT_EQ(p.id[0], 7); // the parent keeps its id, the child takes the next free one
    EXPECT_EQ(p.id[1], 8);
    // Each half's domain is stretched 1.5: not split again.
    EXPECT_EQ(split.apply(p, comm, 1.0), 0);
    EXPECT_EQ(p.size(), 2u);
}

/// Left whole: a point marked near a body, and a needle whose halves would land more than a
/// cell away (σ a / 4 > h).
TEST(Splitting, PointsNearBodiesAndNeedlesStayWhole) {
    Mat<2> F;
    F << 8.5, 0.0, 0.0, 1.0 / 8.5; // σ a / 4 = 0.02125 m with a = 0.01 m
    const Comm comm;
    Particles<2> p = onePoint<2>(F);
    ParticleSplitting<2> split(4.0, p);
    EXPECT_EQ(split.apply(p, comm, 0.02), 0);
    EXPECT_EQ(p.size(), 1u);
    EXPECT_EQ(split.apply(p, comm, 0.022), 1);
    EXPECT_EQ(p.size(), 2u);

    Particles<2> q = onePoint<2>(F);
    ParticleSplitting<2> split2(4.0, q);
    const int near[] = {1};
    EXPECT_EQ(split2.apply(q, comm, 1.0, near), 0);
    const int far[] = {0};
    EXPECT_EQ(split2.apply(q, comm, 1.0, far), 1);
}

TEST(Splitting, RotationAndSmallStretchSplitNothing) {
    const Mat<3> R = Eigen::AngleAxisd(0.9, Vec<3>(1, 2, 3).normalized()).toRotationMatrix();
    Particles<3> p = onePoint<3>(R);
    ParticleSplitting<3> split(1.5, p);
    const Comm comm;
    EXPECT_EQ(split.apply(p, comm, 1.0), 0);
    Particles<3> q = onePoint<3>(R * Vec<3>(1.4, 1.0, 1.0 / 1.4).asDiagonal());
    ParticleSplitting<3> split2(1.5, q);
    EXPECT_EQ(split2.apply(q, comm, 1.0), 0);
    EXPECT_EQ(q.size(), 1u);
}

TEST(Splitting, RotatedStretchSplitsAlongTheCurrentStretchDirection) {
    // F = R diag(1, 2.5, 0.4): the reference y axis, stretched 2.5, now points along R e_y.
    const Mat<3> R = Eigen::AngleAxisd(0.7, Vec<3>(0, 0, 1)).toRotationMatrix();
    const Mat<3> F = R * Vec<3>(1.0, 2.5, 0.4).asDiagonal();
    Particles<3> p = onePoint<3>(F, 0);
    ParticleSplitting<3> split(2.0, p);
    const Comm comm;
    ASSERT_EQ(split.apply(p, comm, 1.0), 1);
    const Vec<3> d = p.x[1] - p.x[0];
    // 2 × σ a / 4 = 0.0125 along R e_y; the centre of mass stays.
    EXPECT_NEAR(d.norm(), 0.0125, 1e-15);
    EXPECT_NEAR(std::fabs(d.normalized().dot(R.col(1))), 1.0, 1e-12);
    EXPECT_TRUE((0.5 * (p.x[0] + p.x[1]) - Vec<3>::Constant(0.5)).norm() < 1e-15);
    EXPECT_DOUBLE_EQ(p.mass[0] + p.mass[1], 1500.0 * 1e-6);
    EXPECT_DOUBLE_EQ(p.volume[0] + p.volume[1], F.determinant() * 1e-6);
    EXPECT_EQ(p.id[1], 1);
    // Stretched twice as far as the limit asks: the halves split once more, to four quarters
    // whose positions stay on the line through the seed along R e_y.
    Particles<3> q = onePoint<3>(R * Vec<3>(1.0, 8.5, 1.0 / 8.5).asDiagonal(), 0);
    ParticleSplitting<3> split2(2.0, q);
    EXPECT_EQ(split2.apply(q, comm, 1.0), 1);
    EXPECT_EQ(split2.apply(q, comm, 1.0), 2);
    EXPECT_EQ(split2.apply(q, comm, 1.0), 4); // 8.5 / 4 = 2.1 > 2
    EXPECT_EQ(split2.apply(q, comm, 1.0), 0);
    ASSERT_EQ(q.size(), 8u);
    double mass = 0.0;
    Vec<3> centre = Vec<3>::Zero();
    for (std::size_t i = 0; i < q.size(); ++i) {
        mass += q.mass[i];
        centre += q.mass[i] * q.x[i];
        EXPECT_EQ(split2.levels(q)[i], 3);
        EXPECT_NEAR((q.x[i] - Vec<3>::Constant(0.5)).cross(R.col(1)).norm(), 0.0, 1e-15);
    }
    EXPECT_DOUBLE_EQ(mass, 1500.0 * 1e-6);
    EXPECT_TRUE((centre / mass - Vec<3>::Constant(0.5)).norm() < 1e-15);
    // Eight points spaced evenly: σ a / 8 apart (the seed's extent 8.5 a in eight slices).
    std::vector<double> along;
    for (std::size_t i = 0; i < q.size(); ++i)
        along.push_back((q.x[i] - Vec<3>::Constant(0.5)).dot(R.col(1)));
    std::sort(along.begin(), along.end());
    for (std::size_t i = 1; i < along.size(); ++i)
        EXPECT_NEAR(along[i] - along[i - 1], 8.5 * 0.01 / 8.0, 1e-14);
}

} // namespace
} // namespace mpm
