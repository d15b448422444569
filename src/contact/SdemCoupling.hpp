// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "contact/CouplingLaw.hpp"

namespace mpm {

/// The MPM–SDEM coupling of seed 001 [001 §4.1, Eq. 43–50] (`coupling: {type: sdem, …}`, 2D).
///
/// A point within r_p + V_d of the body's surface is an identified material point (IMP), a disk
/// of radius r_p (`radius`; default (V_p⁰)^(1/2)). With φ the body's signed distance at x_p
/// and n its outward normal, the overlap is ξ = r_p − φ [001 Eq. 44] and, for ξ > 0, the force
/// on the point is [001 Eq. 43]
///
///     f = k_n ξ n − k_t δ_t t,   t = (−n_y, n_x),   |k_t δ_t| ≤ μ k_n ξ,
///
/// with δ_t the point's tangential spring [m]: δ_t ← δ_t + (v_rel · t) Δt each step in contact
/// (v_rel the point's velocity relative to the body's rigid motion at x_p), scaled back to
/// μ k_n ξ / k_t when the Coulomb cap is exceeded (sliding), and 0 out of contact. δ_t is the
/// per-point `contactSlip` (restart state). The body receives −f at the contact point
/// p = x_p − (r_p − ξ/2) n, the middle of the overlap [001 Eq. 41, 49–50]. Penalty law: points
/// may sink in (nonPenetrating() is false). No IMP–IMP contact (the material handles it).
///
/// Time step: Δt ≤ 2π √(m_p,min / k_n) [000 Eq. 24], times maxCo (the κ of [001 Eq. 51]).
template <int dim> class SdemCoupling final : public CouplingLaw<dim> {
public:
    SdemCoupling(const Dictionary& dict, double h);

    void forces(const std::vector<Contact<dim>>& contacts, double dt, std::vector<double>& slip,
                std::vector<Vec<dim>>& f) const override;
    bool nonPenetrating() const override { return false; }
    /// 2π √(m / k_n) [000 Eq. 24] [s].
    double stableDeltaT(double m, double c) const override;

    double contactRadius(double rpDefault) const override {
        return radius_ > 0 ? radius_ : rpDefault;
    }
    double searchBand() const override { return verletDistance_; }
    /// p = x − (r_p − ξ/2) n = x − ½ (r_p + φ) n [001 Eq. 41].
    Vec<dim> contactPoint(const Vec<dim>& x, const Contact<dim>& c) const override {
        return x - 0.5 * (c.rp + c.phi) * c.normal;
    }
    bool resetsAllSlip() const override { return true; }

    /// The in-plane tangent t = (−n_y, n_x) of normal n (zero in 3D, never used there).
    static Vec<dim> tangent(const Vec<dim>& n);

private:
    double kn_ = 0;             ///< normal stiffness k_n [N/m per metre of depth]
    double kt_ = 0;             ///< tangential stiffness k_t [N/m per metre of depth]
    double verletDistance_ = 0; ///< V_d [m]
    double radius_ = 0;         ///< r_p [m]; 0: each point's (V_p⁰)^(1/2)
};

} // namespace mpm
