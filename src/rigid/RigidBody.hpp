// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/Types.hpp"
#include "rigid/BodyMotion.hpp"
#include "rigid/Shape.hpp"

#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace mpm {

/// A rigid body [004 §3]: shape, mass properties, pose and twist, and the integrators.
///
/// Translation by central difference [004 Eq. 19–20]: v^{n+½} = v^{n-½} + Δt f/m,
/// x^{n+1} = x^n + Δt v^{n+½}. Rotation by the Walton–Braun predictor–corrector on Euler's
/// equations in principal axes with a quaternion update [004 Eq. 16–32] (2D: one angle,
/// central difference). Velocities are stored at half steps, as the integrators need.
template <int dim> class RigidBody {
public:
    /// Read one entry of constant/rigidBodies. Keys: shape {type: …}, density or mass,
    /// position, orientation (3D: quaternion [w, x, y, z] or {axis, angle [deg]}; 2D: angle
    /// [deg]), velocity, angularVelocity (3D world-frame vector; 2D scalar [rad/s]), motion
    /// (free | fixed | {type: prescribed, velocity, angularVelocity} or a table
    /// {type: prescribed, table: [[t, vx, vy(, vz), ω…], …]} interpolated linearly, rows
    /// strictly increasing in t, held constant beyond the ends; ω in the world frame) |
    /// {type: driven, angularVelocity: ω} or {type: driven, table: [[t, ω…], …]} (rotation
    /// prescribed, translation free). The top-level velocity is v^{-½} of a free or driven body,
    /// angularVelocity ω^{-½} of a free body; otherwise they are errors. Exactly one of
    /// density, mass (> 0) for every motion. A levelSet or spheropolygon body may omit
    /// position: it then sits where its mesh (its vertices) put it (shape().meshPose()), and
    /// orientation is applied on top of the mesh's own orientation.
    RigidBody(const Dictionary& dict, std::string name);

    const std::string& name() const { return name_; }
    const Shape<dim>& shape() const { return *shape_; }
    Motion motion() const { return motion_->kind(); }

    double mass() const { return mass_; }
    /// Principal moments of inertia about the centroid [kg m²] (2D: component 2).
    const Vec3& inertia() const { return inertia_; }

    /// Centroid position x^n [m].
    const Vec<dim>& position() const { return x_; }
    /// Velocity of the centroid v^{n-½} [m/s].
    const Vec<dim>& velocity() const { return v_; }
    /// Angular velocity in the world frame ω^{n-½} [rad/s] (2D: component 2).
    Vec3 angularVelocity() const;
    /// Rotation body → world A^n [004 Eq. 32].
    const Mat<dim>& rotation() const { return R_; }
    /// Move the centroid to x, orientation and velocities unchanged (a wrap across a periodic
    /// seam: x differs from position() by whole periods) [m].
    void movePositionTo(const Vec<dim>& x) { x_ = x; }

    /// Signed distance [m] and outward normal (world frame) of world point x.
    double distance(const Vec<dim>& x, Vec<dim>& normal) const {
        Vec<dim> nb;
        const double phi = shape_->distance(R_.transpose() * (x - x_), nb);
        normal = R_ * nb;
        return phi;
    }
    /// Rigid velocity v + ω × r of the body at world point x [m/s].
    Vec<dim> velocityAt(const Vec<dim>& x) const;

    /// Forces of this step: reset, then add the coupling force on the body and its point of
    /// application (world frame).
    void clearForces();
    void addForce(const Vec<dim>& f, const Vec<dim>& at);
    /// Add a force and torque (world frame) directly.
    void addForceAndTorque(const Vec<dim>& f, const Vec3& torque);
    /// Apply an impulse J [N s] at world point x now: v += J/m, ω += I⁻¹ (r × J) (free bodies
    /// only; fixed and prescribed bodies are unaffected). Used to return the momentum a
    /// point loses when it is projected out of the body.
    void applyImpulse(const Vec<dim>& J, const Vec<dim>& at);
    const Vec<dim>& force() const { return f_; }
    /// Velocity and angular velocity (body axes) as dim + 3 numbers, and back: the state that
    /// impulses change (a parallel run adds up the ranks' changes).
    void twist(double* out) const {
        for (int d = 0; d < dim; ++d)
            out[d] = v_[d];
        for (int d = 0; d < 3; ++d)
            out[dim + d] = omegaBody_[d];
    }
    void setTwist(const double* in) {
        for (int d = 0; d < dim; ++d)
            v_[d] = in[d];
        for (int d = 0; d < 3; ++d)
            omegaBody_[d] = in[dim + d];
    }
    const Vec3& torque() const { return torque_; }

    /// Advance pose and twist over dt with gravity g and the accumulated forces, as the body's
    /// motion says; `t` is the time at the start of the step (prescribed motion is evaluated
    /// at t + dt/2).
    void advance(double dt, double t, const Vec<dim>& gravity);

    // The integrators and changes a BodyMotion composes.
    /// A free body's step: v^{n+½} = v^{n-½} + Δt (f/m + g), x^{n+1} = x^n + Δt v^{n+½}
    /// [004 Eq. 19–20]; the rotation by Walton–Braun [004 Eq. 21–31] (2D: central difference).
    void integrate(double dt, const Vec<dim>& gravity);
    /// A kinematic step with v^{n+½} = v and the world ω^{n+½} = ω: x += Δt v, the rotation by
    /// the exact exponential of ω Δt.
    void moveWith(const Vec<dim>& v, const Vec3& omega, double dt);
    /// The free translation's v^{n+½} = v^{n-½} + Δt (f/m + g) [004 Eq. 19].
    Vec<dim> freeVelocity(double dt, const Vec<dim>& gravity) const {
        return v_ + dt * (f_ / mass_ + gravity);
    }
    /// At rest: v = ω = α = 0.
    void hold();
    /// v += J/m.
    void addLinearImpulse(const Vec<dim>& J) { v_ += J / mass_; }
    /// ω += I⁻¹ (r × J), r = at − x.
    void addAngularImpulse(const Vec<dim>& J, const Vec<dim>& at);
    /// v and ω (world frame; 2D: component 2) as given.
    void setVelocities(const Vec<dim>& v, const Vec3& omegaWorld);

    /// Kinetic energy ½ m v² + ½ ωᵀ I ω [J].
    double kineticEnergy() const;

    /// Full state for restart (`uniform/rigidBodies`), in full precision (%.17g), and read back
    /// bit-identically: YAML lines position, velocity, quaternion [w, x, y, z] (3D) or
    /// angle [rad] (2D), omegaBody, alphaPrev, and the force and torque of the last step (what
    /// rigidBodyState reports; optional on reading, zero when absent).
    void writeState(std::ostream& os) const;
    void readState(const Dictionary& dict);

private:
    std::string name_;
    std::unique_ptr<Shape<dim>> shape_;
    std::unique_ptr<BodyMotion<dim>> motion_;
    double mass_ = 0;
    Vec3 inertia_ = Vec3::Zero();

    Vec<dim> x_ = Vec<dim>::Zero();
    Vec<dim> v_ = Vec<dim>::Zero();
    Eigen::Quaterniond q_ = Eigen::Quaterniond::Identity(); ///< 3D orientation
    double theta_ = 0;                                      ///< 2D orientation [rad]
    Vec3 omegaBody_ = Vec3::Zero();                         ///< ω^{n-½} in principal (body) axes
    Vec3 alphaPrev_ = Vec3::Zero(); ///< α^{n-1} in body axes (Walton–Braun)
    Mat<dim> R_ = Mat<dim>::Identity();

    Vec<dim> f_ = Vec<dim>::Zero();
    Vec3 torque_ = Vec3::Zero();

    void updateRotation();
    /// ω^{n-½} from a world-frame vector (2D: component 2), stored in body axes.
    void setAngularVelocity(const Vec3& omegaWorld);
};

} // namespace mpm
