// SPDX-License-Identifier: GPL-3.0-or-later
#include "monitors/FunctionObject.hpp"

#include <cmath>

namespace mpm {

/// `type: intrusionDepth`: how deep a rigid body (`body:`) has gone below the initial surface
/// of the material, measured against gravity: depth = z_s - z_min(body), with z the height
/// along -g, z_min the lowest point of the body's surface and z_s the `surface` level [m]
/// (default: the top of the particles when the output opens, i.e. at t = 0 on a fresh start —
/// give `surface` explicitly for restarted runs). Columns: depth [m], depth / body size along
/// g (for a sphere, depth / D), height of the body's lowest point [m].
template <int dim> class IntrusionDepth final : public FunctionObject<dim> {
public:
    IntrusionDepth(const Dictionary& dict, const std::string& name)
        : FunctionObject<dim>(dict, name), bodyName_(dict.getString("body")) {
        if (dict.has("surface")) {
            surface_ = dict.getScalar("surface");
            surfaceGiven_ = true;
        }
    }

protected:
    void initialise(const State<dim>& s, const Time&) override {
        for (std::size_t b = 0; b < s.bodies.size(); ++b)
            if (s.bodies[b]->name() == bodyName_) body_ = static_cast<int>(b);
        if (body_ < 0)
            this->dict().error("body",
                               "no rigid body named '" + bodyName_ + "' in constant/rigidBodies");
        if (s.gravity.norm() == 0)
            this->dict().error("type",
                               "intrusionDepth measures along gravity: constant/g is needed");
        up_ = -s.gravity.normalized();
        s.bodies[body_]->shape().surface(points_, cells_);
        if (!surfaceGiven_) {
            surface_ = -1e300;
            const auto& p = s.particles;
            for (std::size_t i = 0; i < p.size(); ++i)
                surface_ =
                    std::max(surface_, up_.dot(p.x[i]) + 0.5 * std::pow(p.volume0[i], 1.0 / dim));
        }
    }
    std::vector<std::string> columns(const State<dim>&) const override {
        return {"depth", "depthOverSize", "lowestPoint"};
    }
    std::vector<double> values(const State<dim>& s) const override {
        const RigidBody<dim>& b = *s.bodies[body_];
        double lo = 1e300, hi = -1e300;
        for (const Vec3& q : points_) {
            const Vec<dim> x = b.position() + b.rotation() * q.template head<dim>();
            lo = std::min(lo, up_.dot(x));
            hi = std::max(hi, up_.dot(x));
        }
        const double depth = surface_ - lo;
        return {depth, depth / (hi - lo), lo};
    }

private:
    std::string bodyName_;
    int body_ = -1;
    double surface_ = 0;
    bool surfaceGiven_ = false;
    Vec<dim> up_ = Vec<dim>::Zero();
    std::vector<Vec3> points_;
    std::vector<std::vector<int>> cells_;
};

MPM_REGISTER_DIMS(FunctionObjectRegistry, IntrusionDepth, "intrusionDepth");
MPM_SCHEMA("functionObjects", "intrusionDepth",
           {"how deep a rigid body has entered the material, along -g",
            {{"body", "string", "-", "required", "the body"},
             {"surface", "scalar", "m", "top of the particles", "height z_s of the free surface"}},
            "{type: intrusionDepth, body: ball, surface: 0.1}"});

} // namespace mpm
