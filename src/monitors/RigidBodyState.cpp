// SPDX-License-Identifier: GPL-3.0-or-later
#include "monitors/FunctionObject.hpp"

namespace mpm {

/// `type: rigidBodyState`: for every rigid body (or the one named by `body:`), position [m],
/// velocity [m/s], angular velocity [rad/s], and the coupling force [N] and torque [N m]
/// the material exerted on it in the last step (world frame). 2D: x y, vx vy, ωz, Fx Fy, Tz.
template <int dim> class RigidBodyState final : public FunctionObject<dim> {
public:
    RigidBodyState(const Dictionary& dict, const std::string& name)
        : FunctionObject<dim>(dict, name), only_(dict.getStringOr("body", "")) {}

protected:
    void initialise(const State<dim>& s, const Time&) override {
        bool found = only_.empty();
        for (const auto& b : s.bodies)
            found |= b->name() == only_;
        if (!found)
            this->dict().error("body",
                               "no rigid body named '" + only_ + "' in constant/rigidBodies");
        if (s.bodies.empty())
            this->dict().error("type", "rigidBodyState needs rigid bodies (constant/rigidBodies)");
    }
    std::vector<std::string> columns(const State<dim>& s) const override {
        std::vector<std::string> c;
        const char* axes = "xyz";
        for (const auto& b : s.bodies) {
            if (!only_.empty() && b->name() != only_) continue;
            const std::string n = b->name() + "_";
            for (int d = 0; d < dim; ++d)
                c.push_back(n + axes[d]);
            for (int d = 0; d < dim; ++d)
                c.push_back(n + "v" + axes[d]);
            for (int d = (dim == 2 ? 2 : 0); d < 3; ++d)
                c.push_back(n + "omega" + axes[d]);
            for (int d = 0; d < dim; ++d)
                c.push_back(n + "F" + axes[d]);
            for (int d = (dim == 2 ? 2 : 0); d < 3; ++d)
                c.push_back(n + "T" + axes[d]);
        }
        return c;
    }
    std::vector<double> values(const State<dim>& s) const override {
        std::vector<double> v;
        for (const auto& b : s.bodies) {
            if (!only_.empty() && b->name() != only_) continue;
            const Vec3 w = b->angularVelocity();
            for (int d = 0; d < dim; ++d)
                v.push_back(b->position()[d]);
            for (int d = 0; d < dim; ++d)
                v.push_back(b->velocity()[d]);
            for (int d = (dim == 2 ? 2 : 0); d < 3; ++d)
                v.push_back(w[d]);
            for (int d = 0; d < dim; ++d)
                v.push_back(b->force()[d]);
            for (int d = (dim == 2 ? 2 : 0); d < 3; ++d)
                v.push_back(b->torque()[d]);
        }
        return v;
    }

private:
    std::string only_;
};

MPM_REGISTER_DIMS(FunctionObjectRegistry, RigidBodyState, "rigidBodyState");
MPM_SCHEMA("functionObjects", "rigidBodyState",
           {"centroid, velocities, contact force and torque of the rigid bodies",
            {{"body", "string", "-", "all bodies", "the body to report"}},
            "{type: rigidBodyState, body: ball}"});

} // namespace mpm
