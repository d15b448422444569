// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "materials/HenckyReturnMap.hpp"

namespace mpm {

/// Cohesionless Drucker–Prager plasticity on Hencky elasticity [000 Eq. 3–8, 10]:
/// F = q − μ_s p ≤ 0 with μ_s = 2√3 sin φ/(3 − sin φ), p = −tr σ/3, q = √½ |σ − p1|
/// [000 Eq. 6, 8]; flow potential g = q − β p with β from the dilation angle ψ by the same
/// formula (ψ = 0: isochoric); return map in principal logarithmic strain and trans-phase
/// gasification below ρ_c as described in HenckyReturnMap.hpp.
/// Keys: density, E, nu, frictionAngle [deg] (0, 90), dilationAngle [deg] [0, φ] (default 0),
/// transPhase (default true), criticalDensity [kg/m³] (default density).
template <int dim> class DruckerPrager : public HenckyGranular<dim> {
public:
    DruckerPrager(const Dictionary& dict, const std::string& name);

    Index updateStress(Particles<dim>& p, const std::vector<Index>& ids, double dt) const override;

    /// Dilation angle ψ [deg].
    double dilationAngle() const { return psi_; }
    /// Dilatancy β = 2√3 sin ψ/(3 − sin ψ) [-].
    double dilatancy() const { return beta_; }

private:
    double psi_;
    double beta_;
};

} // namespace mpm
