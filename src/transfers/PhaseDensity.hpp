// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "grid/Grid.hpp"
#include "particles/BlockSort.hpp"
#include "particles/Particles.hpp"
#include "transfers/Transfer.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace mpm {

/// The particle fields of the trans-phase relation: `phaseDensity`, the density ρ̄_p that
/// decides it [kg/m³] (below), and `gasified`, 1 while the point is gasified. Declared by the
/// first caller (every trans-phase material and the solver share them); restart state (the
/// coupling reads them before the step's stress update) and written, so ParaView shows the gas.
struct TransPhaseFields {
    std::size_t density;  ///< Particles::scalar handle of ρ̄_p
    std::size_t gasified; ///< Particles::flag handle of the gas state
};
template <int dim> TransPhaseFields transPhaseFields(Particles<dim>& p) {
    return {p.addScalar(FieldInfo{"phaseDensity"}), p.addFlag(FieldInfo{"gasified"})};
}
/// The trans-phase fields of `p` if they were declared.
template <int dim> std::optional<TransPhaseFields> findTransPhaseFields(const Particles<dim>& p) {
    std::optional<std::size_t> density, gasified;
    for (std::size_t k = 0; k < p.scalars.size(); ++k)
        if (p.scalars[k].info.name == "phaseDensity") density = k;
    for (std::size_t k = 0; k < p.flags.size(); ++k)
        if (p.flags[k].info.name == "gasified") gasified = k;
    if (!density || !gasified) return std::nullopt;
    return TransPhaseFields{*density, *gasified};
}

/// The width of the band next to a coupled body, in cells, whose gasified points keep their
/// own volume (TransPhaseRule::relaxGasVolumes). Measured (docs/settingsGuide.md): with 2 cells
/// a dropped sphere sinks (the band's loose edge spreads outwards as its neighbours take its
/// density); 4 and 6 let a dropped sphere and rock rest as with [000]'s rule, 6 with its
/// margins.
constexpr double nearBodyCells = 6.0;

/// The `nearBody` flag a coupling with bodies keeps for the trans-phase relation (1: within
/// nearBodyCells cells of a coupled body's surface this step; contact/Coupling.cpp), or null
/// without one.
template <int dim> const int* nearBodyFlag(const Particles<dim>& p) {
    for (const auto& f : p.flags)
        if (f.info.name == "nearBody") return f.data.data();
    return nullptr;
}

/// The density that decides the trans-phase state [000 Eq. 10, 18]: the neighbourhood's mass
/// over its volume, through the grid,
///
///     V_i = Σ_p w_ip V_p,   ρ_i = m_i / V_i,   ρ̄_p = Σ_i w_ip ρ_i,
///
/// instead of the point's own m_p/V_p (materials/FlowRules.hpp, TransPhaseRule, for the rule
/// that uses it). Why: a point's own
/// volume carries the history of its flow (the apex return keeps every dilation), so after a
/// collapse the deposit is a mixture of points just above and just below ρ_c at the sub-cell
/// scale; the dense ones carry the weight, the loose ones are never compacted because their
/// dense neighbours hold the grid still, and half the deposit shows no stress
/// (docs/settingsGuide.md). With the neighbourhood's density a loose region is loose as a
/// whole, falls under its own weight and becomes dense again at ρ_c together. A uniform density
/// is kept exactly (Σ_i w_ip = 1); a free surface does not dilute it (V_i counts the points'
/// volume, not the cell's). The weights are those of the step's P2G (x^n), as F̄'s.
template <int dim> class PhaseDensity {
public:
    explicit PhaseDensity(std::size_t handle) : handle_(handle) {}

    /// ρ̄_p into p.scalar(handle) from the points' current volumes and this step's grid mass.
    void apply(Particles<dim>& p, const Grid<dim>& g, const Transfer<dim>& transfer,
               const BlockSort<dim>& sort);

    /// Fold a nodal scalar's periodic images and ghost contributions (as FBar::setNodalFold).
    void setNodalFold(std::function<void(NodeArray<double>&)> fold) {
        foldNodal_ = std::move(fold);
    }

private:
    std::size_t handle_;
    std::function<void(NodeArray<double>&)> foldNodal_;
    NodeArray<double> nodal_; ///< V_i, then ρ_i
};

} // namespace mpm
