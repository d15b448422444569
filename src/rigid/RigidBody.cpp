// SPDX-License-Identifier: GPL-3.0-or-later
#include "rigid/RigidBody.hpp"

#include "case/DictionaryVectors.hpp"
#include "core/Constants.hpp"
#include "core/Format.hpp"

#include <cmath>
#include <ostream>
#include <string>
#include <vector>

namespace mpm {

namespace {

template <class V> std::string fmtList(const V& v) {
    std::string s = "[";
    for (Eigen::Index i = 0; i < v.size(); ++i)
        s += (i > 0 ? ", " : "") + fullPrecision(v[i]);
    return s + "]";
}

Vec3 readVec3(const Dictionary& dict, const std::string& key) {
    return readVec<3>(dict, key);
}

} // namespace

template <int dim>
RigidBody<dim>::RigidBody(const Dictionary& dict, std::string name) : name_(std::move(name)) {
    shape_ = Shape<dim>::create(dict.subDict("shape"));

    motion_ = BodyMotion<dim>::create(dict);

    // Mass properties: density ρ or mass m, exactly one. I = ρ · unitInertia.
    const bool hasDensity = dict.has("density");
    const bool hasMass = dict.has("mass");
    if (hasDensity == hasMass) {
        dict.error(hasDensity ? "mass" : "density",
                   "give exactly one of density [kg/m^3] or mass [kg]");
    }
    const double volume = shape_->volume();
    double density = 0.0;
    if (hasDensity) {
        density = dict.getScalar("density", Bounds::positive());
        mass_ = density * volume;
    } else {
        mass_ = dict.getScalar("mass", Bounds::positive());
        density = mass_ / volume;
    }
    inertia_ = density * shape_->unitInertia();

    // Pose. A shape from a mesh (levelSet) defaults to the mesh's own pose: centroid c and
    // rotation R_mesh (body → mesh); a given orientation R_user turns it about the centroid,
    // R = R_user R_mesh, and a given position moves the centroid.
    Vec<dim> meshCentroid = Vec<dim>::Zero();
    Mat<dim> meshRotation = Mat<dim>::Identity();
    const bool fromMesh = shape_->meshPose(meshCentroid, meshRotation);
    x_ = fromMesh && !dict.has("position") ? meshCentroid : readVec<dim>(dict, "position");
    if constexpr (dim == 3) {
        if (dict.isDict("orientation")) {
            const Dictionary o = dict.subDict("orientation");
            const Vec3 axis = readVec3(o, "axis");
            if (!(axis.norm() > 0.0)) o.error("axis", "the axis must not be zero");
            const double angle = o.getScalar("angle") * pi / 180.0;
            o.checkUnknownKeys();
            q_ = Eigen::Quaterniond(Eigen::AngleAxisd(angle, axis.normalized()));
        } else if (dict.has("orientation")) {
            const std::vector<double> q = dict.getVector("orientation", 4);
            q_ = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
            if (!(q_.norm() > 0.0)) {
                dict.error("orientation", "the quaternion [w, x, y, z] must not be zero");
            }
        }
        q_.normalize();
        if (fromMesh) q_ = (q_ * Eigen::Quaterniond(meshRotation)).normalized();
    } else {
        theta_ = dict.getScalarOr("orientation", 0.0) * pi / 180.0;
    }
    updateRotation();

    // Twist: v^{-½} and ω^{-½} (world frame in the file, body axes inside).
    motion_->start(dict, *this);
    dict.checkUnknownKeys();
}

template <int dim> void RigidBody<dim>::setAngularVelocity(const Vec3& omegaWorld) {
    if constexpr (dim == 3) {
        omegaBody_ = R_.transpose() * omegaWorld;
    } else {
        omegaBody_ = Vec3(0.0, 0.0, omegaWorld[2]);
    }
}

template <int dim> Vec3 RigidBody<dim>::angularVelocity() const {
    if constexpr (dim == 3) {
        return R_ * omegaBody_;
    } else {
        return Vec3(0.0, 0.0, omegaBody_[2]);
    }
}

template <int dim> Vec<dim> RigidBody<dim>::velocityAt(const Vec<dim>& x) const {
    const Vec<dim> r = x - x_;
    if constexpr (dim == 3) {
        return v_ + (R_ * omegaBody_).cross(r);
    } else {
        return v_ + omegaBody_[2] * Vec<dim>(-r[1], r[0]);
    }
}

template <int dim> void RigidBody<dim>::clearForces() {
    f_.setZero();
    torque_.setZero();
}

template <int dim> void RigidBody<dim>::addForce(const Vec<dim>& f, const Vec<dim>& at) {
    f_ += f;
    const Vec<dim> r = at - x_;
    if constexpr (dim == 3) {
        torque_ += r.cross(f);
    } else {
        torque_[2] += r[0] * f[1] - r[1] * f[0];
    }
}

template <int dim> void RigidBody<dim>::addForceAndTorque(const Vec<dim>& f, const Vec3& torque) {
    f_ += f;
    if constexpr (dim == 3) {
        torque_ += torque;
    } else {
        torque_[2] += torque[2];
    }
}

template <int dim> void RigidBody<dim>::applyImpulse(const Vec<dim>& J, const Vec<dim>& at) {
    motion_->applyImpulse(*this, J, at);
}

template <int dim> void RigidBody<dim>::addAngularImpulse(const Vec<dim>& J, const Vec<dim>& at) {
    const Vec<dim> r = at - x_;
    if constexpr (dim == 3) {
        const Vec3 dL = R_.transpose() * r.cross(J); // angular impulse in body axes
        omegaBody_ += dL.cwiseQuotient(inertia_);
    } else {
        omegaBody_[2] += (r[0] * J[1] - r[1] * J[0]) / inertia_[2];
    }
}

template <int dim> void RigidBody<dim>::setVelocities(const Vec<dim>& v, const Vec3& omegaWorld) {
    v_ = v;
    setAngularVelocity(omegaWorld);
}

template <int dim> void RigidBody<dim>::advance(double dt, double t, const Vec<dim>& gravity) {
    motion_->advance(*this, dt, t, gravity);
}

template <int dim> void RigidBody<dim>::hold() {
    v_.setZero();
    omegaBody_.setZero();
    alphaPrev_.setZero();
}

template <int dim> void RigidBody<dim>::moveWith(const Vec<dim>& v, const Vec3& omega, double dt) {
    v_ = v;
    x_ += dt * v_;
    if constexpr (dim == 3) {
        const double angle = omega.norm() * dt;
        if (angle > 0.0) {
            q_ = Eigen::Quaterniond(Eigen::AngleAxisd(angle, omega.normalized())) * q_;
            q_.normalize();
        }
    } else {
        theta_ += dt * omega[2];
    }
    updateRotation();
    setAngularVelocity(omega);
}

template <int dim> void RigidBody<dim>::integrate(double dt, const Vec<dim>& gravity) {
    // Translation by central difference [004 Eq. 19–20]:
    // v^{n+½} = v^{n-½} + Δt (f^n/m + g), x^{n+1} = x^n + Δt v^{n+½}.
    v_ += dt * (f_ / mass_ + gravity);
    x_ += dt * v_;

    if constexpr (dim == 3) {
        // Walton–Braun predictor–corrector on Euler's equations in principal axes
        // [004 Eq. 21–29]; the moment M^n is the world torque in body axes, Rᵀ M.
        const Vec3 moment = R_.transpose() * torque_;
        const Vec3& inertia = inertia_;
        // α_i = [M_i + ω_j ω_k (I_j − I_k)] / I_i, (i, j, k) cyclic [004 Eq. 16–18]. (Eq. 22 of
        // the paper prints ω_1 ω_3 for the first component; Eq. 16 and 26 have ω_2 ω_3.)
        const auto alpha = [&](const Vec3& w) {
            return Vec3((moment[0] + w[1] * w[2] * (inertia[1] - inertia[2])) / inertia[0],
                        (moment[1] + w[2] * w[0] * (inertia[2] - inertia[0])) / inertia[1],
                        (moment[2] + w[0] * w[1] * (inertia[0] - inertia[1])) / inertia[2]);
        };
        const Vec3 omegaEstimate = omegaBody_ + 0.5 * dt * alphaPrev_;  // Eq. 21
        const Vec3 alphaPredict = alpha(omegaEstimate);                 // Eq. 22–24
        const Vec3 omegaPredict = omegaBody_ + 0.5 * dt * alphaPredict; // Eq. 25
        const Vec3 alphaCorrect = alpha(omegaPredict);                  // Eq. 26–28
        omegaBody_ += dt * alphaCorrect;                                // Eq. 29
        alphaPrev_ = alphaCorrect;

        // Quaternion update q^{n+1} = B⁻¹ Bᵀ q^n with β = Δt ω^{n+½}/4 [004 Eq. 30–31]. In
        // Eigen's (w, x, y, z) with R = body → world this Cayley transform is
        // q^{n+1} = q^n ⊗ δq, δq = (1 − |β|², 2β) / (1 + |β|²): a rotation about the body axis
        // ω by 4 atan(|β|) = Δt|ω| + O(Δt³|ω|³). (The paper's (q1, q2, q3, q4) are Eigen's
        // (−y, x, z, w), and its A of Eq. 32 is Rᵀ, world → body.)
        const Vec3 beta = 0.25 * dt * omegaBody_;
        const double beta2 = beta.squaredNorm();
        const double scale = 1.0 / (1.0 + beta2);
        const Eigen::Quaterniond dq((1.0 - beta2) * scale, 2.0 * beta[0] * scale,
                                    2.0 * beta[1] * scale, 2.0 * beta[2] * scale);
        q_ = q_ * dq;
        q_.normalize();
    } else {
        // One angle: ω^{n+½} = ω^{n-½} + Δt M_z/I_z, θ^{n+1} = θ^n + Δt ω^{n+½}.
        omegaBody_[2] += dt * torque_[2] / inertia_[2];
        theta_ += dt * omegaBody_[2];
    }
    updateRotation();
}

template <int dim> void RigidBody<dim>::updateRotation() {
    if constexpr (dim == 3) {
        R_ = q_.toRotationMatrix();
    } else {
        const double c = std::cos(theta_);
        const double s = std::sin(theta_);
        R_ << c, -s, s, c;
    }
}

template <int dim> double RigidBody<dim>::kineticEnergy() const {
    const double rotational = dim == 3 ? inertia_.dot(omegaBody_.cwiseProduct(omegaBody_))
                                       : inertia_[2] * omegaBody_[2] * omegaBody_[2];
    return 0.5 * mass_ * v_.squaredNorm() + 0.5 * rotational;
}

template <int dim> void RigidBody<dim>::writeState(std::ostream& os) const {
    os << "position: " << fmtList(x_) << "\n";
    os << "velocity: " << fmtList(v_) << "\n";
    if constexpr (dim == 3) {
        os << "quaternion: " << fmtList(Eigen::Vector4d(q_.w(), q_.x(), q_.y(), q_.z())) << "\n";
    } else {
        os << "angle: " << fullPrecision(theta_) << "\n";
    }
    os << "omegaBody: " << fmtList(omegaBody_) << "\n";
    os << "alphaPrev: " << fmtList(alphaPrev_) << "\n";
    // Not needed to continue (the next step gathers them anew): mpmFoam -postProcess reports
    // them at a written time as the run did.
    os << "force: " << fmtList(f_) << "\n";
    os << "torque: " << fmtList(torque_) << "\n";
}

template <int dim> void RigidBody<dim>::readState(const Dictionary& dict) {
    x_ = readVec<dim>(dict, "position");
    v_ = readVec<dim>(dict, "velocity");
    if constexpr (dim == 3) {
        const std::vector<double> q = dict.getVector("quaternion", 4);
        q_ = Eigen::Quaterniond(q[0], q[1], q[2], q[3]);
        if (!(q_.norm() > 0.0)) dict.error("quaternion", "the quaternion must not be zero");
    } else {
        theta_ = dict.getScalar("angle");
    }
    omegaBody_ = readVec3(dict, "omegaBody");
    alphaPrev_ = readVec3(dict, "alphaPrev");
    f_ = dict.has("force") ? readVec<dim>(dict, "force") : Vec<dim>::Zero();
    torque_ = dict.has("torque") ? readVec3(dict, "torque") : Vec3::Zero();
    dict.checkUnknownKeys();
    updateRotation();
}

template class RigidBody<2>;
template class RigidBody<3>;

} // namespace mpm
