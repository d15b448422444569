// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/RigidBody.hpp"
#include "core/Constants.hpp"
#include "rigid/RigidBodyOutput.hpp"

#include "TestSupport.hpp"

#include <gtest/gtest.h>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

namespace mpm {
namespace {

namespace fs = std::filesystem;

template <int dim>
std::unique_ptr<RigidBody<dim>> makeBody(const std::string& yaml, const std::string& name = "b") {
    return std::make_unique<RigidBody<dim>>(Dictionary::fromString(yaml, "test"), name);
}

template <int dim> std::string errorOf(const std::string& yaml) {
    try {
        makeBody<dim>(yaml);
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

Mat3 rotZ(double a) {
    return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix();
}

template <int dim> std::string stateOf(const RigidBody<dim>& b) {
    std::ostringstream os;
    b.writeState(os);
    return os.str();
}

/// Convention: the `velocity` read from the case is v^{-½}; after n steps of Δt under a constant
/// acceleration a, v^{n-½} = v0 + a t and x^n = x0 + v0 t + ½ a t (t + Δt), t = nΔt — the exact
/// x(t) of a body whose velocity at t = 0 is v0 + ½ a Δt.
TEST(RigidBodyTest, FreeFall) {
    auto b = makeBody<3>("shape: {type: sphere, radius: 0.1}\ndensity: 1000\n"
                         "position: [0, 0, 1]\nvelocity: [1, 0, 2]\n");
    const Vec3 g(0, 0, -9.81);
    const double dt = 1e-3;
    const int n = 1000;
    for (int i = 0; i < n; ++i) {
        b->clearForces();
        b->advance(dt, i * dt, g);
    }
    const double t = n * dt;
    const Vec3 x = Vec3(0, 0, 1) + Vec3(1, 0, 2) * t + 0.5 * g * t * (t + dt);
    EXPECT_LT((b->position() - x).norm(), 1e-12);
    EXPECT_LT((b->velocity() - (Vec3(1, 0, 2) + g * t)).norm(), 1e-12);
    EXPECT_EQ(b->rotation(), Mat3::Identity());
}

TEST(RigidBodyTest, ConstantForce2D) {
    auto b = makeBody<2>("shape: {type: box, size: [2, 1]}\nmass: 4\nposition: [1, 2]\n");
    const double dt = 0.01;
    for (int i = 0; i < 100; ++i) {
        b->clearForces();
        b->addForce(Vec<2>(8, 0), b->position()); // through the centroid: no torque
        b->advance(dt, i * dt, Vec<2>(0, -1));
    }
    const double t = 1.0;
    const Vec<2> a(2, -1);
    EXPECT_LT((b->position() - (Vec<2>(1, 2) + 0.5 * a * t * (t + dt))).norm(), 1e-12);
    EXPECT_EQ(b->torque()[2], 0.0);
    EXPECT_EQ(b->angularVelocity(), Vec3::Zero());
}

TEST(RigidBodyTest, Fixed) {
    auto b = makeBody<3>("shape: {type: box, halfExtents: [1, 1, 1]}\ndensity: 1\n"
                         "position: [1, 2, 3]\norientation: {axis: [0, 0, 1], angle: 30}\n"
                         "motion: fixed\n");
    const Mat3 r0 = b->rotation();
    EXPECT_LT((r0 - rotZ(pi / 6)).norm(), 1e-15);
    for (int i = 0; i < 10; ++i) {
        b->clearForces();
        b->addForce(Vec3(1, 2, 3), Vec3(2, 2, 2));
        b->advance(0.1, 0.1 * i, Vec3(0, 0, -9.81));
    }
    EXPECT_EQ(b->motion(), Motion::Fixed);
    EXPECT_EQ(b->position(), Vec3(1, 2, 3));
    EXPECT_EQ(b->rotation(), r0);
    EXPECT_EQ(b->velocity(), Vec3::Zero());
    EXPECT_EQ(b->angularVelocity(), Vec3::Zero());
    EXPECT_EQ(b->velocityAt(Vec3(5, 5, 5)), Vec3::Zero());
    EXPECT_EQ(b->kineticEnergy(), 0.0);
    EXPECT_NE(errorOf<3>("shape: {type: sphere, radius: 1}\ndensity: 1\nposition: [0, 0, 0]\n"
                         "motion: fixed\nvelocity: [1, 0, 0]\n")
                  .find("fixed"),
              std::string::npos);
}

TEST(RigidBodyTest, PrescribedConstant) {
    auto b = makeBody<3>("shape: {type: sphere, radius: 1}\ndensity: 1\nposition: [0, 0, 0]\n"
                         "motion: {type: prescribed, velocity: [1, 2, 0], "
                         "angularVelocity: [0, 0, 0.5]}\n");
    EXPECT_EQ(b->motion(), Motion::Prescribed);
    EXPECT_EQ(b->velocity(), Vec3(1, 2, 0));
    const double dt = 0.01;
    for (int i = 0; i < 200; ++i) {
        b->clearForces();
        b->addForce(Vec3(100, 0, 0), Vec3(0, 1, 0)); // ignored
        b->advance(dt, i * dt, Vec3(0, 0, -9.81));
    }
    EXPECT_LT((b->position() - Vec3(2, 4, 0)).norm(), 1e-13);
    EXPECT_LT((b->rotation() - rotZ(1.0)).norm(), 1e-13);
    EXPECT_LT((b->angularVelocity() - Vec3(0, 0, 0.5)).norm(), 1e-15);
    EXPECT_LT((b->velocityAt(b->position() + Vec3(1, 0, 0)) - Vec3(1, 2.5, 0)).norm(), 1e-15);
}

/// v(t) = t on [0, 1], then held at 1: the midpoint rule integrates the piecewise-linear
/// velocity exactly when a step boundary falls on the knot.
TEST(RigidBodyTest, PrescribedTable) {
    auto b = makeBody<3>("shape: {type: sphere, radius: 1}\nmass: 2\nposition: [0, 0, 0]\n"
                         "motion:\n  type: prescribed\n"
                         "  table: [[0, 0, 0, 0, 0, 0, 0], [1, 1, 0, -2, 0, 0, 1]]\n");
    const double dt = 0.01;
    for (int i = 0; i < 100; ++i)
        b->advance(dt, i * dt, Vec3::Zero());
    EXPECT_LT((b->position() - Vec3(0.5, 0, -1.0)).norm(), 1e-13);
    EXPECT_LT((b->rotation() - rotZ(0.5)).norm(), 1e-13);
    for (int i = 100; i < 200; ++i)
        b->advance(dt, i * dt, Vec3::Zero());
    EXPECT_LT((b->position() - Vec3(1.5, 0, -3.0)).norm(), 1e-13);
    EXPECT_LT((b->rotation() - rotZ(1.5)).norm(), 1e-13);
    EXPECT_LT((b->velocity() - Vec3(1, 0, -2)).norm(), 1e-15);

    // 2D, with the first row after t = 0 (held constant before it).
    auto c = makeBody<2>("shape: {type: disk, radius: 1}\ndensity: 1\nposition: [0, 0]\n"
                         "motion: {type: prescribed, table: [[0.5, 2, 0, 1], [1.5, 0, 0, 3]]}\n");
    for (int i = 0; i < 200; ++i)
        c->advance(dt, i * dt, Vec<2>(0, -9.81));
    // ∫ v: 0.5·2 + 2·½ + 0.5·0 = 2; ∫ ω: 0.5·1 + 2·1 + 0.5·3 = 4.
    EXPECT_NEAR(c->position().x(), 2.0, 1e-13);
    EXPECT_EQ(c->position().y(), 0.0);
    EXPECT_LT((c->rotation() - rotZ(4.0).topLeftCorner<2, 2>()).norm(), 1e-13);

    EXPECT_NE(errorOf<2>("shape: {type: disk, radius: 1}\ndensity: 1\nposition: [0, 0]\n"
                         "motion: {type: prescribed, table: [[1, 0, 0, 0], [1, 1, 0, 0]]}\n")
                  .find("increasing"),
              std::string::npos);
    EXPECT_FALSE(errorOf<2>("shape: {type: disk, radius: 1}\ndensity: 1\nposition: [0, 0]\n"
                            "motion: {type: prescribed, table: [[0, 0, 0]]}\n")
                     .empty());
    EXPECT_FALSE(errorOf<2>("shape: {type: disk, radius: 1}\ndensity: 1\nposition: [0, 0]\n"
                            "motion: prescribed\n")
                     .empty());
    EXPECT_FALSE(errorOf<2>("shape: {type: disk, radius: 1}\ndensity: 1\nposition: [0, 0]\n"
                            "motion: {type: prescribed, velocity: [1, 0], table: [[0, 0, 0, 0]]}\n")
                     .empty());
}

/// Driven: ω from the motion (constant or a table), translation free under gravity and the
/// coupling force, which does not turn it; an impulse changes v only.
TEST(RigidBodyTest, DrivenRotatesAsToldAndTranslatesFreely) {
    auto b = makeBody<3>("shape: {type: sphere, radius: 1}\nmass: 2\nposition: [0, 0, 0]\n"
                         "velocity: [1, 0, 0]\n"
                         "motion: {type: driven, angularVelocity: [0, 0, 0.5]}\n");
    EXPECT_EQ(b->motion(), Motion::Driven);
    const double dt = 0.01;
    for (int i = 0; i < 200; ++i) {
        b->clearForces();
        b->addForce(Vec3(4, 0, 0), Vec3(0, 1, 0)); // a = 2 m/s², its torque is ignored
        b->advance(dt, i * dt, Vec3(0, 0, -1));
    }
    // x = v0 t + ½ a t (t + Δt) per axis (see FreeFall), t = 2 s.
    EXPECT_NEAR(b->position().x(), 2.0 + 0.5 * 2.0 * 2.0 * 2.01, 1e-12);
    EXPECT_NEAR(b->position().z(), -0.5 * 2.0 * 2.01, 1e-12);
    EXPECT_LT((b->rotation() - rotZ(1.0)).norm(), 1e-13);
    b->applyImpulse(Vec3(0, 2, 0), b->position() + Vec3(1, 0, 0));
    EXPECT_NEAR(b->velocity().y(), 1.0, 1e-15);
    EXPECT_LT((b->angularVelocity() - Vec3(0, 0, 0.5)).norm(), 1e-15);

    // 2D table (t, ω): ω = 2 t on [0, 1].
    auto c = makeBody<2>("shape: {type: disk, radius: 1}\ndensity: 1\nposition: [0, 0]\n"
                         "motion: {type: driven, table: [[0, 0], [1, 2]]}\n");
    for (int i = 0; i < 100; ++i)
        c->advance(dt, i * dt, Vec<2>(0, -2));
    EXPECT_LT((c->rotation() - rotZ(1.0).topLeftCorner<2, 2>()).norm(), 1e-13);
    EXPECT_NEAR(c->position().y(), -0.5 * 2 * 1.01, 1e-12);

    // Errors: ω is required, the table has (t, ω…) columns, angularVelocity belongs in motion.
    EXPECT_FALSE(errorOf<3>("shape: {type: sphere, radius: 1}\ndensity: 1\nposition: [0, 0, 0]\n"
                            "motion: {type: driven}\n")
                     .empty());
    EXPECT_FALSE(errorOf<3>("shape: {type: sphere, radius: 1}\ndensity: 1\nposition: [0, 0, 0]\n"
                            "motion: {type: driven, table: [[0, 0, 0, 0, 1, 0, 0]]}\n")
                     .empty());
    EXPECT_FALSE(errorOf<3>("shape: {type: sphere, radius: 1}\ndensity: 1\nposition: [0, 0, 0]\n"
                            "angularVelocity: [0, 0, 1]\n"
                            "motion: {type: driven, angularVelocity: [0, 0, 1]}\n")
                     .empty());
    EXPECT_FALSE(errorOf<3>("shape: {type: sphere, radius: 1}\ndensity: 1\nposition: [0, 0, 0]\n"
                            "motion: driven\n")
                     .empty());
}

/// Torque-free box 1 × 2 × 3 spinning about a non-principal axis: Walton–Braun conserves
/// the kinetic energy and the world angular momentum L = R I ω only approximately. ω is stored
/// at half steps and R at whole steps, so L^n = R^n I (ω^{n-½} + ω^{n+½})/2 is compared; the
/// mixed R^{n+1} I ω^{n+½} carries an O(Δt|ω|) offset that oscillates with the precession.
TEST(RigidBodyTest, TorqueFreeAsymmetric) {
    auto b = makeBody<3>("shape: {type: box, size: [1, 2, 3]}\ndensity: 7\nposition: [0, 0, 0]\n"
                         "orientation: {axis: [1, 1, 0], angle: 20}\n"
                         "angularVelocity: [0.6, 2.0, 0.9]\n");
    const Vec3 w0(0.6, 2.0, 0.9);
    const double dt = 0.01 / w0.norm();
    const auto omegaBody = [&] { return Vec3(b->rotation().transpose() * b->angularVelocity()); };
    const auto mixed = [&] { return Vec3(b->rotation() * b->inertia().cwiseProduct(omegaBody())); };
    const double e0 = b->kineticEnergy();
    const Vec3 mixed0 = mixed();
    Vec3 l0 = Vec3::Zero();
    double maxE = 0.0;
    double maxL = 0.0;
    double maxMixed = 0.0;
    for (int i = 0; i < 1000; ++i) {
        const Mat3 r = b->rotation();
        const Vec3 before = omegaBody();
        b->clearForces();
        b->advance(dt, i * dt, Vec3::Zero());
        const Vec3 l = r * b->inertia().cwiseProduct(0.5 * (before + omegaBody()));
        if (i == 0) l0 = l;
        maxE = std::max(maxE, std::abs(b->kineticEnergy() - e0) / e0);
        maxL = std::max(maxL, (l - l0).norm() / l0.norm());
        maxMixed = std::max(maxMixed, (mixed() - mixed0).norm() / mixed0.norm());
        ASSERT_LT((b->rotation() * b->rotation().transpose() - Mat3::Identity()).norm(), 1e-14);
        ASSERT_NEAR(b->rotation().determinant(), 1.0, 1e-14);
    }
    std::printf("[ drift    ] torque-free box, 1000 steps of dt|w| = 0.01: max relative "
                "|dE| = %.3e, |dL| = %.3e (mixed-time R I w: %.3e)\n",
                maxE, maxL, maxMixed);
    EXPECT_LT(maxE, 1e-3);
    EXPECT_LT(maxL, 1e-3);
    // The spin has moved off its initial direction (a real precession, not a frozen ω).
    EXPECT_GT((b->angularVelocity().normalized() - w0.normalized()).norm(), 1e-2);
    EXPECT_EQ(b->position(), Vec3::Zero());
}

/// Spin about a principal axis stays about that axis; the rotation is Rz(4n atan(Δtω/4)) from
/// the Cayley update [004 Eq. 30–31], within (Δtω)³/48 per step of Rz(ωt).
TEST(RigidBodyTest, SpinAboutPrincipalAxis) {
    auto b = makeBody<3>("shape: {type: box, size: [1, 2, 3]}\ndensity: 1\nposition: [0, 0, 0]\n"
                         "angularVelocity: [0, 0, 2]\n");
    const double w = 2.0;
    const double dt = 0.005;
    const int n = 300;
    for (int i = 0; i < n; ++i)
        b->advance(dt, i * dt, Vec3::Zero());
    EXPECT_EQ(b->angularVelocity(), Vec3(0, 0, 2));
    EXPECT_LT((b->rotation() - rotZ(4.0 * n * std::atan(0.25 * dt * w))).norm(), 1e-12);
    EXPECT_LT((b->rotation() - rotZ(w * n * dt)).norm(), 1e-5);
    EXPECT_NEAR(b->rotation()(2, 2), 1.0, 1e-15);

    // About body x with an initial orientation: ω stays along body x, i.e. along R e_x.
    auto c = makeBody<3>("shape: {type: box, size: [1, 2, 3]}\ndensity: 1\nposition: [0, 0, 0]\n"
                         "orientation: [0.9, 0.1, -0.3, 0.2]\n");
    auto d = makeBody<3>("shape: {type: box, size: [1, 2, 3]}\ndensity: 1\nposition: [0, 0, 0]\n"
                         "orientation: [0.9, 0.1, -0.3, 0.2]\n" +
                         [&] {
                             const Vec3 a = 1.5 * c->rotation().col(0);
                             char s[200];
                             std::snprintf(s, sizeof(s), "angularVelocity: [%.17g, %.17g, %.17g]\n",
                                           a[0], a[1], a[2]);
                             return std::string(s);
                         }());
    const Vec3 axis = d->rotation().col(0);
    for (int i = 0; i < 500; ++i)
        d->advance(0.01, i * 0.01, Vec3::Zero());
    EXPECT_LT((d->angularVelocity() - 1.5 * axis).norm(), 1e-13);
    EXPECT_LT((d->rotation().col(0) - axis).norm(), 1e-13);
}

/// A body spinning about world z by ω for time t is rotated by Rz(ωt) (sign convention), for any
/// initial orientation (isotropic inertia: ω is constant).
TEST(RigidBodyTest, SpinAboutWorldZ) {
    auto b = makeBody<3>("shape: {type: sphere, radius: 1}\ndensity: 1\nposition: [0, 0, 0]\n"
                         "orientation: {axis: [1, 2, 3], angle: 50}\n"
                         "angularVelocity: [0, 0, 0.8]\n");
    const Mat3 r0 = b->rotation();
    const double dt = 1e-3;
    const int n = 1000;
    for (int i = 0; i < n; ++i)
        b->advance(dt, i * dt, Vec3::Zero());
    EXPECT_LT((b->rotation() - rotZ(0.8) * r0).norm(), 1e-7);
    EXPECT_LT((b->rotation() - rotZ(4.0 * n * std::atan(0.25 * dt * 0.8)) * r0).norm(), 1e-12);
    EXPECT_LT((b->angularVelocity() - Vec3(0, 0, 0.8)).norm(), 1e-14);
    // Rigid velocity: ω × r.
    EXPECT_LT((b->velocityAt(Vec3(1, 0, 0)) - Vec3(0, 0.8, 0)).norm(), 1e-14);
}

/// One step of our update equals the paper's q^{n+1} = B⁻¹ Bᵀ q^n [004 Eq. 30–31] with
/// (q1, q2, q3, q4) = (−y, x, z, w) of Eigen's quaternion, and A of Eq. 32 is Rᵀ.
TEST(RigidBodyTest, PaperQuaternionConvention) {
    const Eigen::Quaterniond q0 = Eigen::Quaterniond(0.8, -0.2, 0.5, 0.3).normalized();
    auto b = makeBody<3>("shape: {type: sphere, radius: 1}\ndensity: 1\nposition: [0, 0, 0]\n"
                         "orientation: [0.8, -0.2, 0.5, 0.3]\n"
                         "angularVelocity: [1.3, -0.4, 2.1]\n");
    const Vec3 wBody = q0.toRotationMatrix().transpose() * Vec3(1.3, -0.4, 2.1);
    const double dt = 0.2;
    b->advance(dt, 0.0, Vec3::Zero());

    const Vec3 beta = 0.25 * dt * wBody;
    Eigen::Matrix4d bm;
    bm << 1, -beta[2], beta[0], beta[1], beta[2], 1, beta[1], -beta[0], -beta[0], -beta[1], 1,
        -beta[2], -beta[1], beta[0], beta[2], 1;
    const Eigen::Vector4d p0(-q0.y(), q0.x(), q0.z(), q0.w());
    const Eigen::Vector4d p = bm.lu().solve(bm.transpose() * p0);
    const double q1 = p[0], q2 = p[1], q3 = p[2], q4 = p[3];
    Mat3 a;
    a << -q1 * q1 + q2 * q2 - q3 * q3 + q4 * q4, -2 * (q1 * q2 - q3 * q4), 2 * (q2 * q3 + q1 * q4),
        -2 * (q1 * q2 + q3 * q4), q1 * q1 - q2 * q2 - q3 * q3 + q4 * q4, -2 * (q1 * q3 - q2 * q4),
        2 * (q2 * q3 - q1 * q4), -2 * (q1 * q3 + q2 * q4), -q1 * q1 - q2 * q2 + q3 * q3 + q4 * q4;
    EXPECT_LT((a - b->rotation().transpose()).norm(), 1e-14);
}

TEST(RigidBodyTest, TorqueAndForce3D) {
    auto b = makeBody<3>("shape: {type: sphere, radius: 0.5}\nmass: 3\nposition: [1, 1, 1]\n"
                         "velocity: [1, 0, 0]\nangularVelocity: [0, 0, 2]\n");
    b->clearForces();
    b->addForce(Vec3(0, 2, 0), Vec3(2, 1, 1));
    b->addForceAndTorque(Vec3(1, 0, 0), Vec3(0, 0.5, 0));
    EXPECT_EQ(b->force(), Vec3(1, 2, 0));
    EXPECT_EQ(b->torque(), Vec3(0, 0.5, 2));
    const double i = 0.4 * 3 * 0.25;
    EXPECT_NEAR(b->inertia()[0], i, 1e-15);
    EXPECT_NEAR(b->kineticEnergy(), 0.5 * 3 * 1 + 0.5 * i * 4, 1e-15);
    EXPECT_LT((b->velocityAt(Vec3(2, 1, 1)) - Vec3(1, 2, 0)).norm(), 1e-15);
    b->clearForces();
    EXPECT_EQ(b->force(), Vec3::Zero());
    EXPECT_EQ(b->torque(), Vec3::Zero());
}

TEST(RigidBodyTest, DiskRotation2D) {
    auto b = makeBody<2>("shape: {type: disk, radius: 0.5}\ndensity: 2\nposition: [0, 0]\n"
                         "orientation: 90\nangularVelocity: 1\n");
    const double inertia = 2 * pi * std::pow(0.5, 4) / 2;
    EXPECT_NEAR(b->inertia()[2], inertia, 1e-15);
    EXPECT_LT((b->rotation() - rotZ(pi / 2).topLeftCorner<2, 2>()).norm(), 1e-15);
    // Torque r × f = 0.5 · 3 about z from a force at the rim; the force also pushes the centre.
    const double dt = 1e-3;
    const int n = 1000;
    double theta = pi / 2;
    double w = 1.0;
    for (int i = 0; i < n; ++i) {
        b->clearForces();
        b->addForce(Vec<2>(0, 3), b->position() + Vec<2>(0.5, 0));
        EXPECT_NEAR(b->torque()[2], 1.5, 1e-15);
        b->advance(dt, i * dt, Vec<2>::Zero());
        w += dt * 1.5 / inertia;
        theta += dt * w;
    }
    EXPECT_NEAR(b->angularVelocity()[2], 1.0 + 1.5 / inertia, 1e-11);
    EXPECT_LT((b->rotation() - rotZ(theta).topLeftCorner<2, 2>()).norm(), 1e-12);
    // Exact: θ = θ0 + ω0 t + ½ α t (t + Δt).
    const double t = n * dt;
    EXPECT_NEAR(theta, pi / 2 + t + 0.5 * 1.5 / inertia * t * (t + dt), 1e-11);
    const Vec<2> r(0, 0.5);
    const Vec<2> v = b->velocity() + b->angularVelocity()[2] * Vec<2>(-r[1], r[0]);
    EXPECT_LT((b->velocityAt(b->position() + r) - v).norm(), 1e-15);
    EXPECT_NEAR(b->kineticEnergy(),
                0.5 * b->mass() * b->velocity().squaredNorm() +
                    0.5 * inertia * std::pow(b->angularVelocity()[2], 2),
                1e-13);
}

TEST(RigidBodyTest, DensityOrMass) {
    auto a =
        makeBody<3>("shape: {type: box, size: [1, 2, 3]}\ndensity: 500\nposition: [0, 0, 0]\n");
    auto b = makeBody<3>("shape: {type: box, size: [1, 2, 3]}\nmass: 3000\nposition: [0, 0, 0]\n");
    EXPECT_EQ(a->mass(), 3000.0);
    EXPECT_EQ(b->mass(), 3000.0);
    EXPECT_LT((a->inertia() - b->inertia()).norm(), 1e-12);
    EXPECT_NEAR(a->inertia()[0], 3000.0 * 13.0 / 12.0, 1e-10);
    EXPECT_NE(errorOf<3>("shape: {type: box, size: [1, 2, 3]}\nposition: [0, 0, 0]\n")
                  .find("exactly one"),
              std::string::npos);
    EXPECT_NE(errorOf<3>("shape: {type: box, size: [1, 2, 3]}\nmass: 1\ndensity: 1\n"
                         "position: [0, 0, 0]\n")
                  .find("exactly one"),
              std::string::npos);
    EXPECT_FALSE(
        errorOf<3>("shape: {type: box, size: [1, 2, 3]}\nmass: 0\nposition: [0, 0, 0]\n").empty());
    EXPECT_FALSE(errorOf<3>("shape: {type: box, size: [1, 2, 3]}\nmass: 1\n").empty());
    EXPECT_NE(errorOf<3>("shape: {type: box, size: [1, 2, 3]}\nmass: 1\nposition: [0, 0, 0]\n"
                         "velocty: [1, 0, 0]\n")
                  .find("velocty"),
              std::string::npos);
    EXPECT_FALSE(errorOf<3>("shape: {type: box, size: [1, 2, 3]}\nmass: 1\nposition: [0, 0, 0]\n"
                            "orientation: [0, 0, 0, 0]\n")
                     .empty());
}

/// writeState → readState restores the state bit for bit: both bodies then evolve identically.
TEST(RigidBodyTest, StateRoundTrip) {
    const std::string yaml = "shape: {type: box, size: [1, 2, 3]}\ndensity: 3\n"
                             "position: [0.1, 0.2, 0.3]\nvelocity: [0.3, -0.1, 0.7]\n"
                             "angularVelocity: [0.6, 2.0, 0.9]\n";
    auto a = makeBody<3>(yaml);
    for (int i = 0; i < 37; ++i) {
        a->clearForces();
        a->addForce(Vec3(0.1, 0.2, -0.3), a->position() + Vec3(1.0 / 3.0, 0.1, 0.2));
        a->advance(1.0 / 300.0, i / 300.0, Vec3(0, 0, -9.81));
    }
    auto b = makeBody<3>(yaml);
    b->readState(Dictionary::fromString(stateOf(*a), "state"));
    EXPECT_EQ(stateOf(*a), stateOf(*b));
    for (auto* body : {a.get(), b.get()}) {
        body->clearForces();
        body->addForce(Vec3(0.1, 0.2, -0.3), body->position() + Vec3(0.2, 0.1, 0.2));
        body->advance(1.0 / 300.0, 0.1, Vec3(0, 0, -9.81));
    }
    EXPECT_EQ(stateOf(*a), stateOf(*b));
    EXPECT_EQ(a->rotation(), b->rotation());
    EXPECT_EQ(a->position(), b->position());

    auto c = makeBody<2>("shape: {type: disk, radius: 1}\ndensity: 1\nposition: [0, 0]\n"
                         "angularVelocity: 0.3\nvelocity: [1, 1]\n");
    for (int i = 0; i < 7; ++i)
        c->advance(0.1, 0.1 * i, Vec<2>(0, -9.81));
    auto d = makeBody<2>("shape: {type: disk, radius: 1}\ndensity: 1\nposition: [5, 5]\n");
    d->readState(Dictionary::fromString(stateOf(*c), "state"));
    EXPECT_EQ(stateOf(*c), stateOf(*d));
    EXPECT_EQ(c->rotation(), d->rotation());
}

/// The last step's force and torque are part of the written state (mpmFoam -postProcess reports
/// them); a state written without them (older files) reads them as zero.
TEST(RigidBodyTest, StateKeepsTheLastForce) {
    const std::string yaml = "shape: {type: box, size: [1, 2, 3]}\ndensity: 3\n"
                             "position: [0.1, 0.2, 0.3]\n";
    auto a = makeBody<3>(yaml);
    a->addForce(Vec3(0.1, 0.2, -0.3), a->position() + Vec3(1.0 / 3.0, 0.1, 0.2));
    auto b = makeBody<3>(yaml);
    b->readState(Dictionary::fromString(stateOf(*a), "state"));
    EXPECT_EQ(b->force(), a->force());
    EXPECT_EQ(b->torque(), a->torque());
    EXPECT_NE(b->torque(), Vec3::Zero());

    std::string old = stateOf(*a);
    old = old.substr(0, old.find("force:"));
    b->readState(Dictionary::fromString(old, "state"));
    EXPECT_EQ(b->force(), Vec3::Zero());
    EXPECT_EQ(b->torque(), Vec3::Zero());
}

using RigidBodyFileTest = test::TempDirTest;

TEST_F(RigidBodyFileTest, StateFile) {
    std::vector<std::unique_ptr<RigidBody<3>>> bodies;
    bodies.push_back(makeBody<3>("shape: {type: sphere, radius: 1}\ndensity: 1\n"
                                 "position: [0, 0, 0]\nangularVelocity: [0, 1, 0]\n",
                                 "ball"));
    bodies.push_back(makeBody<3>("shape: {type: box, size: [1, 1, 1]}\ndensity: 1\n"
                                 "position: [3, 0, 0]\nvelocity: [0, 1, 0]\n",
                                 "cube"));
    for (auto& b : bodies)
        b->advance(0.1, 0.0, Vec3(0, 0, -9.81));
    const fs::path file = dir_ / "0.1" / "uniform" / "rigidBodies";
    writeRigidBodyState<3>(file, bodies);

    std::vector<std::unique_ptr<RigidBody<3>>> restored;
    restored.push_back(makeBody<3>("shape: {type: sphere, radius: 1}\ndensity: 1\n"
                                   "position: [0, 0, 0]\n",
                                   "ball"));
    restored.push_back(makeBody<3>("shape: {type: box, size: [1, 1, 1]}\ndensity: 1\n"
                                   "position: [0, 0, 0]\n",
                                   "cube"));
    readRigidBodyState<3>(Dictionary::fromFile(file, "uniform/rigidBodies"), restored);
    for (int i = 0; i < 2; ++i)
        EXPECT_EQ(stateOf(*bodies[i]), stateOf(*restored[i]));

    restored.push_back(makeBody<3>("shape: {type: sphere, radius: 1}\ndensity: 1\n"
                                   "position: [0, 0, 0]\n",
                                   "extra"));
    try {
        readRigidBodyState<3>(Dictionary::fromFile(file, "uniform/rigidBodies"), restored);
        ADD_FAILURE() << "a missing body must be an InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("extra"), std::string::npos) << e.what();
    }
}

TEST_F(RigidBodyFileTest, Surfaces) {
    std::vector<std::unique_ptr<RigidBody<3>>> bodies;
    bodies.push_back(makeBody<3>("shape: {type: box, size: [1, 2, 3]}\ndensity: 1\n"
                                 "position: [1, 0, 0]\norientation: {axis: [0, 0, 1], angle: 90}\n"
                                 "angularVelocity: [0, 0, 1]\n"));
    bodies.push_back(makeBody<3>("shape: {type: sphere, radius: 1}\ndensity: 1\n"
                                 "position: [5, 0, 0]\nvelocity: [0, 0, 2]\n"));
    const fs::path file = dir_ / "bodies.vtp";
    writeRigidBodies<3>(file, bodies);
    EXPECT_FALSE(fs::exists(dir_ / "bodies.vtp.tmp"));

    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(file.string().c_str());
    reader->Update();
    vtkPolyData* poly = reader->GetOutput();
    ASSERT_EQ(poly->GetNumberOfPolys(), 12 + 528);
    ASSERT_EQ(poly->GetNumberOfPoints(), 8 + 2 + 11 * 24);
    vtkDataArray* body = poly->GetCellData()->GetArray("body");
    vtkDataArray* velocity = poly->GetPointData()->GetArray("velocity");
    ASSERT_NE(body, nullptr);
    ASSERT_NE(velocity, nullptr);
    EXPECT_EQ(body->GetTuple1(0), 0.0);
    EXPECT_EQ(body->GetTuple1(12), 1.0);
    EXPECT_EQ(velocity->GetNumberOfComponents(), 3);
    // Box corner 0 = (−0.5, −1, −1.5) rotated by 90° about z: (1, −0.5, −1.5) + (1, 0, 0);
    // rigid velocity ω × r = (0, 0, 1) × (1, −0.5, −1.5) = (0.5, 1, 0).
    double x[3];
    poly->GetPoint(0, x);
    EXPECT_LT((Vec3(x[0], x[1], x[2]) - Vec3(2, -0.5, -1.5)).norm(), 1e-15);
    double v[3];
    velocity->GetTuple(0, v);
    EXPECT_LT((Vec3(v[0], v[1], v[2]) - Vec3(0.5, 1, 0)).norm(), 1e-15);
    velocity->GetTuple(8, v);
    EXPECT_LT((Vec3(v[0], v[1], v[2]) - Vec3(0, 0, 2)).norm(), 1e-15);

    std::vector<std::unique_ptr<RigidBody<2>>> flat;
    flat.push_back(makeBody<2>("shape: {type: box, size: [2, 1]}\ndensity: 1\n"
                               "position: [1, 1]\norientation: 90\n"));
    flat.push_back(makeBody<2>("shape: {type: disk, radius: 1}\ndensity: 1\nposition: [5, 0]\n"));
    writeRigidBodies<2>(dir_ / "flat.vtp", flat);
    vtkNew<vtkXMLPolyDataReader> reader2;
    reader2->SetFileName((dir_ / "flat.vtp").string().c_str());
    reader2->Update();
    EXPECT_EQ(reader2->GetOutput()->GetNumberOfLines(), 4 + 64);
    EXPECT_EQ(reader2->GetOutput()->GetNumberOfPolys(), 0);
    reader2->GetOutput()->GetPoint(0, x); // (−1, −0.5) rotated by 90°: (0.5, −1)
    EXPECT_LT((Vec3(x[0], x[1], x[2]) - Vec3(1.5, 0, 0)).norm(), 1e-15);
}

} // namespace
} // namespace mpm
