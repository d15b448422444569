// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/CouplingLaw.hpp"

#include "core/Constants.hpp"

#include <cmath>

namespace mpm {

template <int dim>
CouplingLaw<dim>::CouplingLaw(const Dictionary& dict, double h)
    : h_(h), mu_(dict.getScalarOr("friction", 0.0, Bounds::nonNegative())),
      slipFraction_(dict.getScalarOr("slipThreshold", 0.01, Bounds::positive())),
      gasifiedOnGrid_(dict.getWordOr("gasifiedPoints", "grid", {"grid", "local"}) == "grid") {}

template <int dim>
Vec<dim> CouplingLaw<dim>::frictionForce(const Contact<dim>& c, double fn, double dt,
                                         double& slip) const {
    if (mu_ == 0 || fn <= 0) return Vec<dim>::Zero();
    // Slip direction m: the tangential part of the relative velocity [004 Eq. 38].
    const Vec<dim> vt = c.vRel - c.vRel.dot(c.normal) * c.normal;
    const double speed = vt.norm();
    if (speed == 0) return Vec<dim>::Zero();
    const Vec<dim> m = vt / speed;
    slip += dt * speed; // u_T accumulates along m [004 Eq. 37]
    const double sp = slipFraction_ * c.rp;
    const double u = std::fabs(slip);
    const double smooth = u < sp ? (2.0 * u / sp - u * u / (sp * sp)) : 1.0; // [004 Eq. 36]
    return -smooth * mu_ * fn * m; // opposes the slip [004 Eq. 35]
}

template <int dim>
std::unique_ptr<CouplingLaw<dim>> CouplingLaw<dim>::create(const Dictionary& dict, double h) {
    return CouplingLawRegistry<dim>::create(dict, h);
}

template class CouplingLaw<2>;
template class CouplingLaw<3>;

MPM_FAMILY_INFO("couplingLaws",
                {"<body>.coupling.type in constant/rigidBodies",
                 "8. constant/rigidBodies",
                 {{"type", "word", "-", "barrier", "the normal law"},
                  {"friction", "scalar", "-", "0",
                   "Coulomb μ between the points and the body (≥ 0)"},
                  {"slipThreshold", "scalar", "-", "0.01",
                   "s_p/r_p of the friction smoothing [004 Eq. 36] (> 0; not with sdem)"},
                  {"gasifiedPoints", "word", "-", "grid",
                   "how a gasified point takes its contact force: grid or local"}}});
MPM_FAMILY_DIMS(CouplingLawRegistry, "couplingLaws");

namespace {

/// Barrier coupling [000 Eq. 21–27], [004 Eq. 33–34]:
///   f(ξ) = κ (ξ - r_p) [2 ln(ξ/r_p) - r_p/ξ + 1] for 0 < ξ < r_p, 0 otherwise,
/// with κ from stability: k_N(ξ̄) = k_N,crit = 4 m_p π² c² / h² at ξ̄ = xiBar·r_p [000 Eq. 26–27].
/// κ scales with m_p, so it is computed per point. Keys: friction, slipThreshold (s_p/r_p),
/// xiBar (ξ̄/r_p, default 0.2), minimumGap (ξ_min/r_p, default 0.05): a point that would end a
/// step closer than ξ_min to the body is projected back to ξ_min (non-penetration by
/// construction; see Coupling).
template <int dim> class BarrierCoupling final : public CouplingLaw<dim> {
public:
    BarrierCoupling(const Dictionary& dict, double h) : CouplingLaw<dim>(dict, h) {
        xiBar_ = dict.getScalarOr("xiBar", 0.2, {0.0, 1.0, false, false});
        this->minGapFraction_ = dict.getScalarOr("minimumGap", 0.05, {0.0, 1.0, false, false});
        if (this->minGapFraction_ >= xiBar_)
            dict.error("minimumGap", "minimumGap must be smaller than xiBar");
        // -1 / g(ξ̄/r_p) with k_N = -κ g: g(s) = 2 ln s + (s - 1)(3s + 1)/s² [000 Eq. 25, 27].
        const double s = xiBar_;
        inverseStiffnessShape_ = -1.0 / (2.0 * std::log(s) + (s - 1.0) * (3.0 * s + 1.0) / (s * s));
    }

    void forces(const std::vector<Contact<dim>>& contacts, double dt, std::vector<double>& slip,
                std::vector<Vec<dim>>& f) const override {
        const double fourPi2OverH2 = 4.0 * pi * pi / (this->h_ * this->h_);
        this->forEachContact(contacts, f, [&](const Contact<dim>& c) -> Vec<dim> {
            const double xi = std::max(c.phi, this->minimumGap(c.rp));
            double fn = 0;
            if (xi < c.rp) {
                const double kappa =
                    c.mass * c.wave * c.wave * fourPi2OverH2 * inverseStiffnessShape_;
                fn = kappa * (xi - c.rp) * (2.0 * std::log(xi / c.rp) - c.rp / xi + 1.0);
            }
            return fn * c.normal + this->frictionForce(c, fn, dt, slip[c.particle]);
        });
    }
    bool nonPenetrating() const override { return true; }
    /// κ is chosen so that 2π√(m_p/k_N) ≥ h/c for ξ ≥ ξ̄: the contact does not lower Δt.
    double stableDeltaT(double, double) const override { return 1e300; }

private:
    double xiBar_ = 0.2;
    double inverseStiffnessShape_ = 0;
};

/// The linear spring of the original MP-DEM [000 §3.2]: f = k_N δ, δ = r_p - ξ (overlap), with
/// `stiffness` k_N [N/m] (default: k_N,crit of [000 Eq. 26] for the lightest point,
/// 4 m_p π² c²/h², i.e. the stiffest spring that does not lower Δt). Points can sink in:
/// nothing stops ξ < 0. Keys: stiffness, friction, slipThreshold.
template <int dim> class LinearSpringCoupling final : public CouplingLaw<dim> {
public:
    LinearSpringCoupling(const Dictionary& dict, double h) : CouplingLaw<dim>(dict, h) {
        if (dict.has("stiffness")) stiffness_ = dict.getScalar("stiffness", Bounds::positive());
    }

    void forces(const std::vector<Contact<dim>>& contacts, double dt, std::vector<double>& slip,
                std::vector<Vec<dim>>& f) const override {
        const double fourPi2OverH2 = 4.0 * pi * pi / (this->h_ * this->h_);
        this->forEachContact(contacts, f, [&](const Contact<dim>& c) -> Vec<dim> {
            const double kN =
                stiffness_ > 0 ? stiffness_ : c.mass * c.wave * c.wave * fourPi2OverH2;
            const double fn = c.phi < c.rp ? kN * (c.rp - c.phi) : 0.0;
            return fn * c.normal + this->frictionForce(c, fn, dt, slip[c.particle]);
        });
    }
    bool nonPenetrating() const override { return false; }
    /// Δt ≤ 2π √(m_p / k_N) [000 Eq. 24].
    double stableDeltaT(double m, double c) const override {
        const double kN =
            stiffness_ > 0 ? stiffness_ : 4.0 * pi * pi * m * c * c / (this->h_ * this->h_);
        return 2.0 * pi * std::sqrt(m / kN);
    }

private:
    double stiffness_ = 0;
};

} // namespace

MPM_REGISTER_DIMS(CouplingLawRegistry, BarrierCoupling, "barrier");
MPM_REGISTER_DIMS(CouplingLawRegistry, LinearSpringCoupling, "linearSpring");
MPM_SCHEMA("couplingLaws", "barrier",
           {"barrier potential: no point ends a step inside the body [000 Eq. 21-27]",
            {{"xiBar", "scalar", "-", "0.2",
              "ξ̄/r_p where the barrier's stiffness equals k_N,crit, in (0, 1)"},
             {"minimumGap", "scalar", "-", "0.05",
              "ξ_min/r_p, the smallest gap a point may end a step at, in (0, xiBar)"}},
            "{type: barrier, friction: 0.3}"});
MPM_SCHEMA("couplingLaws", "linearSpring",
           {"linear spring on the overlap [000 §3.2]; points can sink in",
            {{"stiffness", "scalar", "N/m", "k_N,crit of each point",
              "spring stiffness k_N (> 0)"}},
            "{type: linearSpring, friction: 0.3}"});

} // namespace mpm
