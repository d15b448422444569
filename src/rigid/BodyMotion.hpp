// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "case/Dictionary.hpp"
#include "core/Types.hpp"

#include <memory>

namespace mpm {

template <int dim> class RigidBody;

/// What kind of motion a body has (for the parts of the solver that treat bodies by kind: a
/// fixed body is coupled where it lies, a prescribed or driven one bounds the time step).
enum class Motion {
    Free,       ///< integrated from gravity and coupling forces
    Fixed,      ///< never moves (terrain, walls, baffles)
    Prescribed, ///< velocity and angular velocity given as functions of time
    Driven      ///< angular velocity given, translation free (a driven wheel)
};

/// How a rigid body moves (`motion:` of a body in constant/rigidBodies; BodyMotionRegistry,
/// family `bodyMotions`): `free`, `fixed`, `prescribed` (velocity and angular velocity as
/// functions of time) or `driven` (angular velocity given, translation free). A word is the
/// map `{type: word}` of a type that takes no keys. The motion advances its body with the
/// body's integrators and decides what an impulse changes.
template <int dim> class BodyMotion {
public:
    virtual ~BodyMotion() = default;

    virtual Motion kind() const = 0;
    /// Give `b` its twist at the start, v^{-½} [m/s] and ω^{-½} [rad/s], from its entry `body`
    /// (`velocity`, `angularVelocity`, where this motion takes them; an error where not).
    virtual void start(const Dictionary& body, RigidBody<dim>& b) const = 0;
    /// Advance `body` over dt from time t under gravity g [m/s²] and its accumulated forces.
    virtual void advance(RigidBody<dim>& body, double dt, double t,
                         const Vec<dim>& gravity) const = 0;
    /// Apply the impulse J [N s] at world point x to `body` as this motion lets it.
    virtual void applyImpulse(RigidBody<dim>& body, const Vec<dim>& J,
                              const Vec<dim>& at) const = 0;

    /// The motion of the body entry `body`: its `motion` word or map, `free` when absent.
    static std::unique_ptr<BodyMotion> create(const Dictionary& body);
};

template <class Base, class... Args> class Registry; // case/Registry.hpp
template <int dim> using BodyMotionRegistry = Registry<BodyMotion<dim>>;

extern template class BodyMotion<2>;
extern template class BodyMotion<3>;

} // namespace mpm
