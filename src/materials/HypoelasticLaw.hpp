// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Parallel.hpp"
#include "materials/FlowRules.hpp"
#include "materials/HypoelasticReturnMap.hpp"
#include "materials/Material.hpp"
#include "materials/ViscoelasticReturnMap.hpp"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <vector>

namespace mpm {

/// Hypoelastic linear elasticity with the Jaumann rate [001 Eq. 25, 36]:
///   σ̇ = C : D + W σ − σ W,  C_ijkl = K δ_ij δ_kl + G (δ_ik δ_jl + δ_il δ_jk − ⅔ δ_ij δ_kl),
/// with D = sym L and W = skew L, integrated by forward Euler over the step
/// (jaumannTrialStress); plastic flow, if any, by the return map of HypoelasticReturnMap.hpp.
/// The stress is the state (bᵉ stays 1). With a viscosity policy (Viscosity.hpp) the state is
/// the elastic stress σᵉ beside σ, and viscousUpdate runs the viscous return map
/// (ViscoelasticReturnMap.hpp: exact rotation [002 Eq. 52]). An elastic-law policy of
/// ElastoPlastic (static members only).
struct HypoelasticLaw {
    static constexpr ElasticLaw kind = ElasticLaw::hypoelastic;
    /// The energy is a few products per point: ElastoPlastic uses the plain loop.
    static constexpr bool batchedEnergy = false;

    /// σ = σ₀, bᵉ = 1 (not projected onto a yield surface: a σ₀ outside it returns in the first
    /// step).
    template <int dim>
    static void initialise(const ElasticConstants& /*c*/, Particles<dim>& p, Index i,
                           const Mat3& sigma0) {
        p.be[i] = Mat3::Identity();
        p.stress[i] = sigma0;
    }

    /// Complementary energy ½ σ : C⁻¹ : σ · V = (p²/(2K) + s:s/(4G)) V [J].
    template <int dim>
    static double strainEnergy(const ElasticConstants& c, const Particles<dim>& p, Index i) {
        const Mat3& s = p.stress[i];
        const double pr = s.trace() / 3.0;
        const Mat3 dev = s - pr * Mat3::Identity();
        return (pr * pr / (2.0 * c.K) + dev.squaredNorm() / (4.0 * c.G)) * p.volume[i];
    }
    /// The same of a stress s [Pa] on a volume V [m³] (per metre of depth in 2D): the energy of
    /// σᵉ of a viscous material. (strainEnergy keeps its own body: through this function it
    /// compiles to a reordered loop.)
    static double complementaryEnergy(const ElasticConstants& c, const Mat3& s, double volume) {
        const double pr = s.trace() / 3.0;
        const Mat3 dev = s - pr * Mat3::Identity();
        return (pr * pr / (2.0 * c.K) + dev.squaredNorm() / (4.0 * c.G)) * volume;
    }

    /// Advance the particles `ids` over dt with the flow rule `flow` (NoFlow: elastic), the
    /// tension cut-off `cutoff` and the trans-phase relation `phase`.
    template <int dim, class Flow>
    static Index update(Particles<dim>& p, const std::vector<Index>& ids, double dt,
                        const ElasticConstants& c, const TransPhaseRule& phase, const Flow& flow,
                        const TensionCutoff& cutoff) {
        if constexpr (std::is_same_v<Flow, NoFlow>)
            return elasticUpdate(p, ids, dt, c);
        else
            return hypoelasticReturnMapUpdate(p, ids, dt, c, phase, flow, cutoff);
    }

    /// The viscous update of a material with a viscosity policy `visc` and the flow `flow`
    /// (viscoelasticReturnMapUpdate: σ, the elastic stress and the flow state of `fields`,
    /// separation below ρ_c = rhoC [kg/m³]).
    template <int dim, class Flow, class Viscosity>
    static Index viscousUpdate(Particles<dim>& p, const std::vector<Index>& ids, double dt,
                               const ElasticConstants& c, const Flow& flow, const Viscosity& visc,
                               double rhoC, const ViscoelasticFields& fields) {
        static_assert(std::is_same_v<Flow, TanMuIFlow>,
                      "the viscous return map is written for the μ(I) flow of [002] (TanMuIFlow)");
        return viscoelasticReturnMapUpdate(p, ids, dt, c, flow, visc, rhoC, fields);
    }

    /// Elastic update σ ← σ + Δt σ̇. Returns the first particle whose stress is not finite,
    /// or -1.
    template <int dim>
    static Index elasticUpdate(Particles<dim>& p, const std::vector<Index>& ids, double dt,
                               const ElasticConstants& c) {
        const Index n = static_cast<Index>(ids.size());
        Index bad = n;
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(min : bad)
        for (Index k = 0; k < n; ++k) {
            const Index i = ids[k];
            p.stress[i] = jaumannTrialStress(c, embed3<dim>(p.L[i]), p.stress[i], dt);
            if (!std::isfinite(p.stress[i].sum())) bad = std::min(bad, k);
        }
        return bad < n ? ids[bad] : -1;
    }
};

} // namespace mpm
