// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "transfers/AntiLocking.hpp"

#include <functional>
#include <vector>

namespace mpm {

/// F̄ anti-locking (system/mpmSchemes `antiLocking: fBar`), the assumed deformation gradient
/// with a volume average built from the particle–grid transfers (Zhao, Jiang & Choo 2022,
/// "Circumventing volumetric locking in explicit material point methods", cited in [004 §5.2]).
///
/// Isochoric plastic flow (μ(I), Drucker–Prager with ψ = 0) asks every point to keep its
/// volume, which the few grid velocities cannot honour point by point: the volume changes
/// ΔJ_p oscillate from point to point and so does the pressure (volumetric locking). F̄
/// replaces each point's volume change by its neighbourhood's average and keeps its own
/// isochoric part:
///
///     ΔF_p = I + Δt L_p,  ΔJ_p = det ΔF_p                      (this step's increment)
///     ΔJ_i = Σ_p w_ip m_p ΔJ_p / m_i                           (mass-weighted nodal average)
///     ΔJ̄_p = Σ_i w_ip ΔJ_i
///     ΔF̄_p = (ΔJ̄_p / ΔJ_p)^(1/d) ΔF_p,   L̄_p = (ΔF̄_p − I) / Δt
///
/// with d = dim (plane strain: the in-plane volume). The mass weights m_p = ρ_p V_p equal the
/// paper's volume weights for uniform density and reuse the grid mass of this step's P2G. The
/// weights are those of x^n (the stencils the step's L_p came from). L̄ replaces L, so every
/// material and the solver's F ← ΔF F, V = J V⁰ see the averaged volume change. A uniform ΔJ is
/// kept exactly (Σ_i w_ip = 1), and the total volume change Σ m_p ΔJ_p is preserved.
template <int dim> class FBar final : public AntiLocking<dim> {
public:
    FBar() = default;
    explicit FBar(const Dictionary&) {}

    /// Replace p.L by L̄ (grid mass from this step's P2G).
    void apply(Particles<dim>& p, const Grid<dim>& g, const Transfer<dim>& transfer,
               const BlockSort<dim>& sort, double dt) override;

    /// On a periodic lattice: `fold(q)` folds a nodal scalar's image nodes onto their owners
    /// (BoundaryConditions::foldField); with several ranks it also sums the halo. Set once at
    /// set-up.
    void setNodalFold(std::function<void(NodeArray<double>&)> fold) override {
        foldNodal_ = std::move(fold);
    }

private:
    std::function<void(NodeArray<double>&)> foldNodal_;
    std::vector<double> weighted_; ///< m_p ΔJ_p
    NodeArray<double> nodal_;      ///< Σ_p w_ip m_p ΔJ_p, then ΔJ_i
    std::vector<double> average_;  ///< ΔJ̄_p
};

} // namespace mpm
