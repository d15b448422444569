// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Constants.hpp"
#include "rigid/RigidBody.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

namespace mpm {

// What the body–body contact laws (linearSpring, sdem) share: one normal dashpot with the
// restitution the user asks, one tangential spring, one reduced mass and one step limit.

/// Reduced mass of a contact pair m* = m_a m_b/(m_a + m_b) [kg] (per metre in 2D); a fixed body's
/// mass counts as infinite (m* is then the other body's mass).
template <int dim> double reducedMass(const RigidBody<dim>& a, const RigidBody<dim>& b) {
    if (a.motion() == Motion::Fixed) return b.mass();
    if (b.motion() == Motion::Fixed) return a.mass();
    return a.mass() * b.mass() / (a.mass() + b.mass());
}

/// The stable step of a linear contact spring k_n [001 Eq. 51]: 2π κ₂ √(m_min/k_n), κ₂ = 0.1 (a
/// tenth of the contact period), m_min the smallest mass of the bodies that are not fixed [s].
template <int dim>
double contactStepLimit(const std::vector<std::unique_ptr<RigidBody<dim>>>& bodies, double kn) {
    constexpr double kappa2 = 0.1;
    double mMin = 1e300;
    for (const auto& b : bodies)
        if (b->motion() != Motion::Fixed) mMin = std::min(mMin, b->mass());
    return 2.0 * pi * kappa2 * std::sqrt(mMin / kn);
}

/// The normal dashpot of a contact law with restitution e: f_n = max(k_n δ − c v_n, 0) (no
/// attraction), c = 2 ζ √(k_n m*). Because f_n is cut at zero the grains separate before δ = 0,
/// so ζ is not the textbook −ln e/√(π² + ln² e) (the restitution of the uncut dashpot: a cut one
/// with that ζ bounces higher than e, e.g. 0.32 for e = 0.2): ζ solves e(ζ) = e for the exact
/// restitution of the cut linear dashpot (Schwager & Pöschel 2007, Granular Matter 9:465), with
/// β = ζ ω₀, ω = ω₀√(1 − ζ²):
///   e = exp(−(β/ω)(π − atan(2βω/(ω² − β²)))) for ζ < 1/√2,
///   e = exp(−(β/ω) atan(2βω/(β² − ω²)))      for 1/√2 ≤ ζ < 1,
/// so an underdamped dashpot reaches e(1) = e⁻² ≈ 0.135 at the least: restitution is limited to
/// [0.14, 1] (RestitutionDashpot::lowest).
class RestitutionDashpot {
public:
    /// e ∈ [0.14, 1]; 1: no dashpot.
    explicit RestitutionDashpot(double e);

    /// What restitution may be asked: [0.14, 1].
    static constexpr double lowest = 0.14;

    /// The damping ratio ζ ∈ [0, 1) giving the restitution asked (0 for e = 1).
    double dampingRatio() const { return zeta_; }
    bool any() const { return zeta_ > 0; }
    /// c = 2 ζ √(k_n m*) [N s/m] (per metre in 2D).
    double coefficient(double kn, double reducedMass) const {
        return 2.0 * zeta_ * std::sqrt(kn * reducedMass);
    }
    /// Restitution of the cut linear dashpot with damping ratio ζ ∈ [0, 1) (see the class).
    static double restitution(double zeta);

private:
    double zeta_ = 0;
};

/// The tangential spring of a contact with friction [001 Eq. 43]: ξ ← P(ξ) + Δt v_t (P: the
/// projection on the tangent plane of the normal n, v_t = v_rel − v_n n), f_t = −k_t ξ [N],
/// capped at μ f_n with ξ scaled back to the cap (sliding). Returns f_t and advances `xi` [m].
template <int dim>
Vec<dim> tangentialSpring(Vec<dim>& xi, const Vec<dim>& normal, const Vec<dim>& vRel, double vn,
                          double kt, double mu, double fn, double dt) {
    xi -= xi.dot(normal) * normal;
    xi += dt * (vRel - vn * normal);
    Vec<dim> ft = -kt * xi;
    const double cap = mu * fn;
    if (ft.norm() > cap) {
        ft *= cap / ft.norm();
        xi = kt > 0 ? Vec<dim>(-ft / kt) : Vec<dim>::Zero();
    }
    return ft;
}

} // namespace mpm
