// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/SdemCoupling.hpp"

#include "core/Constants.hpp"

#include <cmath>

namespace mpm {

template <int dim>
SdemCoupling<dim>::SdemCoupling(const Dictionary& dict, double h) : CouplingLaw<dim>(dict, h) {
    if (dict.has("slipThreshold"))
        dict.error("slipThreshold", "not a key of sdem: its friction is the k_t spring with the "
                                    "Coulomb cap μ k_n ξ, not the smoothed law");
    kn_ = dict.getScalar("kn", Bounds::positive());
    kt_ = dict.getScalarOr("kt", 0.0, Bounds::nonNegative());
    verletDistance_ = dict.getScalarOr("verletDistance", 0.0, Bounds::nonNegative());
    if (dict.has("radius")) radius_ = dict.getScalar("radius", Bounds::positive());
}

template <int dim> Vec<dim> SdemCoupling<dim>::tangent(const Vec<dim>& n) {
    Vec<dim> t = Vec<dim>::Zero();
    if constexpr (dim == 2) t = Vec<dim>(-n[1], n[0]);
    return t;
}

template <int dim>
void SdemCoupling<dim>::forces(const std::vector<Contact<dim>>& contacts, double dt,
                               std::vector<double>& slip, std::vector<Vec<dim>>& f) const {
    const double mu = this->mu_;
    this->forEachContact(contacts, f, [&](const Contact<dim>& c) -> Vec<dim> {
        const double xi = std::max(c.rp - c.phi, 0.0); // overlap [001 Eq. 44]
        const double fn = kn_ * xi;
        const Vec<dim> t = tangent(c.normal);
        double& delta = slip[c.particle];
        if (kt_ > 0) {
            delta += c.vRel.dot(t) * dt; // δ_t ← δ_t + (v_rel · t) Δt
            const double cap = mu * fn;
            if (kt_ * std::fabs(delta) > cap) delta = std::copysign(cap / kt_, delta); // sliding
        } else {
            delta = 0;
        }
        return fn * c.normal - (kt_ * delta) * t; // [001 Eq. 43]
    });
}

template <int dim> double SdemCoupling<dim>::stableDeltaT(double m, double) const {
    return 2.0 * pi * std::sqrt(m / kn_);
}

template class SdemCoupling<2>;

MPM_REGISTER_ONLY(2, CouplingLawRegistry, SdemCoupling<2>, "sdem");
MPM_SCHEMA("couplingLaws", "sdem",
           {"spheropolygon DEM spring between points and bodies [001 Eq. 43-45]",
            {{"kn", "scalar", "N/m per metre", "required", "normal stiffness k_n (> 0)"},
             {"kt", "scalar", "N/m per metre", "0",
              "tangential stiffness k_t (≥ 0; 0: no friction)"},
             {"radius", "scalar", "m", "(V_p⁰)^(1/2) of each point",
              "the points' contact radius r_p (> 0)"},
             {"verletDistance", "scalar", "m", "0", "neighbour search margin V_d (≥ 0)"}},
            "{type: sdem, kn: 6.0e6, kt: 3.0e5, friction: 0.2}",
            "its tangential spring δ_t is a scalar along the in-plane tangent (seed 001): use "
            "barrier or linearSpring"});

} // namespace mpm
