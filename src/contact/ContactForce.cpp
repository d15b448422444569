// SPDX-License-Identifier: GPL-3.0-or-later
#include "contact/ContactForce.hpp"

namespace mpm {

RestitutionDashpot::RestitutionDashpot(double e) {
    if (e >= 1.0) return;
    // e(ζ) falls monotonically from 1 (ζ = 0) to e⁻² (ζ → 1): bisection.
    double lo = 0.0, hi = 1.0 - 1e-12;
    for (int k = 0; k < 200 && hi - lo > 1e-15; ++k) {
        const double mid = 0.5 * (lo + hi);
        (restitution(mid) > e ? lo : hi) = mid;
    }
    zeta_ = 0.5 * (lo + hi);
}

double RestitutionDashpot::restitution(double zeta) {
    const double w = std::sqrt(1.0 - zeta * zeta); // ω/ω₀
    const double r = zeta / w;                     // β/ω
    const double a = zeta < std::sqrt(0.5) ? pi - std::atan(2.0 * zeta * w / (w * w - zeta * zeta))
                                           : std::atan(2.0 * zeta * w / (zeta * zeta - w * w));
    return std::exp(-r * a);
}

} // namespace mpm
