// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/BodyContact.hpp"
#include "grid/Grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace {

using namespace mpm;

template <int dim> using Bodies = std::vector<std::unique_ptr<RigidBody<dim>>>;

template <int dim> std::unique_ptr<RigidBody<dim>> body(const std::string& yaml) {
    return std::make_unique<RigidBody<dim>>(Dictionary::fromString(yaml, "test"), "b");
}

template <int dim> std::unique_ptr<BodyContactLaw<dim>> law(const std::string& yaml) {
    return BodyContactLaw<dim>::create(Dictionary::fromString(yaml, "test"));
}

/// One step of the body phase: forces from contact only, then every body advances.
template <int dim>
void stepBodies(Bodies<dim>& b, BodyContactLaw<dim>& l, ContactHistory<dim>& h, double dt,
                double t) {
    for (auto& x : b)
        x->clearForces();
    l.addForces(b, h, dt);
    for (auto& x : b)
        x->advance(dt, t, Vec<dim>::Zero());
}

template <int dim> double kinetic(const Bodies<dim>& b) {
    double e = 0;
    for (const auto& x : b)
        e += x->kineticEnergy();
    return e;
}

/// Energy lost by a frictionless elastic head-on collision of two balls with step dt.
double collisionEnergyError(double dt) {
    Bodies<3> b;
    b.push_back(body<3>("{shape: {type: sphere, radius: 0.1}, density: 1000, position: [0, 0, 0], "
                        "velocity: [1, 0, 0]}"));
    b.push_back(body<3>("{shape: {type: sphere, radius: 0.05}, density: 1000, "
                        "position: [0.16, 0.01, 0], velocity: [-1, 0, 0]}"));
    auto l = law<3>("{type: linearSpring, normalStiffness: 1e5}");
    ContactHistory<3> h;
    const double e0 = kinetic(b);
    const Vec<3> p0 = b[0]->mass() * b[0]->velocity() + b[1]->mass() * b[1]->velocity();
    for (int k = 0; k * dt < 0.1; ++k) {
        stepBodies(b, *l, h, dt, k * dt);
        const Vec<3> p = b[0]->mass() * b[0]->velocity() + b[1]->mass() * b[1]->velocity();
        EXPECT_LT((p - p0).norm(), 1e-12 * p0.norm()) << "momentum at step " << k;
    }
    EXPECT_TRUE(h.empty()); // separated: no history left
    return std::fabs(kinetic(b) - e0) / e0;
}

TEST(BodyContactTest, FrictionlessElasticCollisionKeepsMomentumAndEnergyToSecondOrder) {
    const double coarse = collisionEnergyError(2e-4);
    const double fine = collisionEnergyError(1e-4);
    EXPECT_LT(coarse, 1e-2);
    EXPECT_GT(coarse / std::max(fine, 1e-300), 3.0) << coarse << " " << fine; // O(Δt²)
}

TEST(BodyContactTest, ActionEqualsReactionForcesAndTorques) {
    Bodies<3> b;
    b.push_back(body<3>("{shape: {type: box, halfExtents: [0.1, 0.05, 0.08]}, density: 2000, "
                        "position: [0, 0, 0], orientation: {axis: [1, 2, 3], angle: 25}}"));
    b.push_back(body<3>("{shape: {type: sphere, radius: 0.05}, density: 1000, "
                        "position: [0.02, 0.09, 0.01], velocity: [0.3, -0.2, 0.1]}"));
    auto l = law<3>("{type: linearSpring, normalStiffness: 1e5, friction: 0.5}");
    ContactHistory<3> h;
    for (auto& x : b)
        x->clearForces();
    l->addForces(b, h, 1e-4);
    l->addForces(b, h, 1e-4); // a second pass with history
    ASSERT_FALSE(h.empty());
    const Vec<3> f = b[0]->force() + b[1]->force();
    EXPECT_LT(f.norm(), 1e-12 * b[0]->force().norm());
    // Angular momentum about the origin: Σ x_b × F_b + τ_b = 0.
    Vec<3> L = Vec<3>::Zero();
    for (const auto& x : b)
        L += x->position().cross(x->force()) + x->torque();
    EXPECT_LT(L.norm(), 1e-12 * b[0]->force().norm());
}

TEST(BodyContactTest, SlidingFrictionIsMuTimesNormalForceAgainstTheMotion) {
    Bodies<2> b;
    b.push_back(body<2>("{shape: {type: box, halfExtents: [1, 0.1]}, mass: 1, motion: fixed, "
                        "position: [0, 0]}"));
    b.push_back(body<2>("{shape: {type: disk, radius: 0.05}, density: 1000, "
                        "position: [0, 0.149], velocity: [2, 0]}"));
    auto l = law<2>("{type: linearSpring, normalStiffness: 1e4, friction: 0.3}");
    ContactHistory<2> h;
    for (int k = 0; k < 3; ++k) {
        for (auto& x : b)
            x->clearForces();
        l->addForces(b, h, 1e-3);
    }
    const Vec<2> f = b[1]->force();
    EXPECT_NEAR(f[1], 1e4 * 0.001, 1e-9);  // k_n δ
    EXPECT_NEAR(f[0], -0.3 * f[1], 1e-12); // μ f_n, against +x
    EXPECT_EQ(h.size(), 1u);
}

/// Relative separation speed over approach speed of a frictionless head-on collision of two
/// balls (disks in 2D) of unequal mass.
template <int dim> double headOnRestitution(const std::string& keys) {
    const std::string shape = dim == 2 ? "disk" : "sphere", zero = dim == 2 ? "" : ", 0";
    Bodies<dim> b;
    b.push_back(body<dim>("{shape: {type: " + shape +
                          ", radius: 0.1}, density: 1000, position: [0, 0" + zero +
                          "], velocity: [1, 0" + zero + "]}"));
    b.push_back(body<dim>("{shape: {type: " + shape + ", radius: 0.05}, density: 3000, " +
                          "position: [0.151, 0" + zero + "], velocity: [-0.5, 0" + zero + "]}"));
    auto l = law<dim>("{type: linearSpring, normalStiffness: 1e5" + keys + "}");
    ContactHistory<dim> h;
    const double approach = b[0]->velocity()[0] - b[1]->velocity()[0];
    const double dt = 1e-5;
    for (int k = 0; k * dt < 0.08; ++k)
        stepBodies(b, *l, h, dt, k * dt);
    EXPECT_TRUE(h.empty()); // apart
    return (b[1]->velocity()[0] - b[0]->velocity()[0]) / approach;
}

TEST(BodyContactTest, HeadOnCollisionLeavesAtTheRestitutionAsked) {
    EXPECT_NEAR(headOnRestitution<2>(""), 1.0, 2e-3);
    EXPECT_NEAR(headOnRestitution<3>(""), 1.0, 2e-3);
    for (const double e : {0.9, 0.5, 0.3, 0.2, 0.14}) { // 0.2 and below: the ζ > 1/√2 branch
        EXPECT_NEAR(headOnRestitution<2>(", restitution: " + std::to_string(e)), e, 3e-3) << e;
        EXPECT_NEAR(headOnRestitution<3>(", restitution: " + std::to_string(e)), e, 3e-3) << e;
    }
}

TEST(BodyContactTest, RestitutionBelowTheUnderdampedLimitIsAnInputError) {
    EXPECT_THROW(law<2>("{type: linearSpring, normalStiffness: 1e5, restitution: 0.1}"),
                 InputError);
}

TEST(BodyContactTest, UnknownTypeListsTheValidOnes) {
    try {
        law<2>("{type: hertz}");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("linearSpring"), std::string::npos);
    }
}

/// Forces and torques after two passes (with friction history) of two bodies, one of them a
/// box so that the lever arm matters; pairs meet through the minimum image of `lattice`.
template <int dim>
std::vector<std::pair<Vec<dim>, Vec3>> pairForces(const std::string& a, const std::string& b,
                                                  const PeriodicLattice<dim>* lattice) {
    Bodies<dim> bodies;
    bodies.push_back(body<dim>(a));
    bodies.push_back(body<dim>(b));
    auto l = law<dim>("{type: linearSpring, normalStiffness: 1e5, friction: 0.5}");
    if (lattice) l->setPeriodic(*lattice);
    ContactHistory<dim> h;
    for (int k = 0; k < 2; ++k) {
        for (auto& x : bodies)
            x->clearForces();
        l->addForces(bodies, h, 1e-4);
    }
    EXPECT_FALSE(h.empty());
    return {{bodies[0]->force(), bodies[0]->torque()}, {bodies[1]->force(), bodies[1]->torque()}};
}

TEST(BodyContactTest, PeriodicPairMeetsThroughTheMinimumImage) {
    const Grid<2> grid(Dictionary::fromString(
        "bounds: {min: [0, 0], max: [1, 1]}\ncellSize: 0.05\n", "constant/grid"));
    const PeriodicLattice<2> lattice(grid, {true, false});
    const std::string box = "{shape: {type: box, halfExtents: [0.1, 0.05]}, density: 2000, "
                            "orientation: 25, velocity: [0.3, 0.1], angularVelocity: 2, ";
    const std::string disk = "{shape: {type: disk, radius: 0.05}, density: 1000, "
                             "velocity: [-0.2, 0], ";
    // Reference: side by side in mid-box, no seam.
    const auto ref =
        pairForces<2>(box + "position: [0.45, 0.5]}", disk + "position: [0.58, 0.53]}", nullptr);
    ASSERT_GT(ref[0].first.norm(), 0);
    // The same pair across the seam: box centre at 0.95, disk centre at 1.08 - 1 = 0.08.
    const auto per =
        pairForces<2>(box + "position: [0.95, 0.5]}", disk + "position: [0.08, 0.53]}", &lattice);
    for (int b = 0; b < 2; ++b) {
        EXPECT_LE((per[b].first - ref[b].first).norm(), 1e-9 * ref[b].first.norm()) << b;
        EXPECT_LE((per[b].second - ref[b].second).norm(), 1e-9 * ref[0].second.norm()) << b;
    }
    // Without the lattice they do not touch.
    Bodies<2> apart;
    apart.push_back(body<2>(box + "position: [0.95, 0.5]}"));
    apart.push_back(body<2>(disk + "position: [0.08, 0.53]}"));
    ContactProbes<2> probes;
    probes.update(apart);
    std::vector<ProbeContact<2>> contacts;
    findProbeContacts(apart, probes, contacts);
    EXPECT_TRUE(contacts.empty());
    findProbeContacts(apart, probes, contacts, &lattice);
    EXPECT_FALSE(contacts.empty());
}

} // namespace
