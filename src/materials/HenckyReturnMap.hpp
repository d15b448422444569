// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/FastMath.hpp"
#include "core/Parallel.hpp"
#include "core/SymmetricEigen.hpp"
#include "materials/FlowRules.hpp"
#include "materials/HenckyBatch.hpp"
#include "materials/Material.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

// Cohesionless granular plasticity on Hencky elasticity (HenckyLaw with DruckerPragerFlow or
// MuIFlow, FlowRules.hpp).
//
// Return map in logarithmic strain (multiplicative plasticity, F = Fᵉ Fᵖ [000 Eq. 3]).
// bᵉ_tr = f bᵉ fᵀ, f = 1 + Δt L; ε = ½ ln bᵉ_tr is the trial elastic Hencky strain, coaxial with
// the Kirchhoff stress τ (isotropy). Everything below is isotropic in ε, so the return is done
// on the tensors themselves (ε by a series, bᵉ = exp 2ε by another: SymmetricSeries.hpp), with
// no eigen-decomposition for the usual strains. With ε_v = tr ε,
// ε̂ = ε − (ε_v/3) 1 and n = ε̂/|ε̂| [000 Eq. 4–5]:
//   τ = λ ε_v 1 + 2G ε = K ε_v 1 + 2G ε̂,   p = −K ε_v,   s = 2G ε̂,   q = √½ |s| = √2 G |ε̂|,
// and the yield function is F = q − μ p [000 Eq. 6] (homogeneous of degree one in the stress, so
// the same surface for τ and σ = τ/J).
//
// Flow rule: potential g = q − β p (β = μ of the dilation angle ψ by [000 Eq. 8]; β = 0 is
// isochoric flow, β = μ associated flow). With ∂q/∂τ = s/(√2|s|) = n/√2 and ∂p/∂τ = −1/3,
//   Δεᵖ = Δγ ∂g/∂τ = Δγ (n/√2 + (β/3) 1).
// The exponential map of multiplicative plasticity (bᵉ = exp 2ε) makes the return additive
// (ε, ε_tr and Δεᵖ are coaxial), ε = ε_tr − Δεᵖ:
//   |ε̂| = |ε̂_tr| − Δγ/√2,   ε_v = ε_v,tr − β Δγ,   i.e.  q = q_tr − G Δγ,  p = p_tr + K β Δγ.
// Δγ = √2 |Δε̂ᵖ| is the engineering plastic shear strain (simple shear: the plastic shear angle),
// work-conjugate to q (s : Δε̂ᵖ = q Δγ); Particles::plasticStrain accumulates it.
//  - ψ = 0: the flow is deviatoric; ε_v, hence det bᵉ and p, are unchanged by the return.
//  - ψ > 0: plastic dilation tr Δεᵖ = β Δγ > 0; with the total deformation of the step given,
//    the elastic volumetric strain ε_v (and det bᵉ) decreases and p rises by K β Δγ, which pushes
//    the point to expand in the following steps.
// Drucker–Prager consistency q_tr − G Δγ = μ (p_tr + K β Δγ) gives Δγ = F_tr / (G + μ K β), and
// the returned pressure
//   p = p_tr + K β Δγ = (G p_tr + K β q_tr) / (G + μ K β).
// Apex region. The return moves the trial along the fixed direction (K β, −G) in the (p, q)
// plane, the normal of the potential in the elastic metric; the trials it brings to the apex
// lie on the line through the apex along that direction, G p_tr + K β q_tr = 0. A trial on the
// cone side of it (G p_tr + K β q_tr > 0, i.e. q_tr/G > −p_tr/(K β)) returns onto the cone
// with p ≥ 0 — also a tensile trial (p_tr < 0) with enough shear when ψ > 0; a trial on the
// other side (or on it) returns to the apex: zero stress, bᵉ = 1 (cohesionless), plastic strain
// += q_tr/G = √2 |ε̂_tr| (the shear part of the corner return). In Hencky strain
// (p_tr = −K ε_v, q_tr = √2 G |ε̂|) the apex region is
//   ε_v ≥ √2 β |ε̂_tr|,
// which for ψ = 0 (β = 0) is exactly ε_v ≥ 0: the hydrostatic axis. μ(I) flows are isochoric
// (β = 0), so theirs is ε_v ≥ 0 too.
//
// Trans-phase relation [000 Eq. 10]: when the density ρ̄_p of the point's neighbourhood
// (PhaseDensity.hpp; the point's own m_p/V_p in [000 Eq. 18]) is below ρ_c the point is
// gasified: zero stress and bᵉ = 1 (it starts stress-free when it re-compacts); its plastic
// strain is unchanged.

namespace mpm {

/// Advance bᵉ, σ and the plastic strain of `ids` over dt by the return map above with the
/// yield/flow functor `Flow` (chosen at compile time: no per-particle virtual call or option
/// branch). Flow provides `beta` and `multiplier(q, p, jInv)`. Particles go through in batches of
/// 8 so that the strains, the return and exp 2ε (only in a batch with a plastic point) vectorise
/// across particles, as in HenckyLaw::elasticUpdate. `phase` gasifies points (off: never).
/// Elastic points get exactly HenckyLaw::elasticUpdate's bᵉ and σ. Returns the first particle
/// whose state is not finite, or -1.
template <int dim, class Flow>
Index henckyReturnMapUpdate(Particles<dim>& p, const std::vector<Index>& ids, double dt,
                            const ElasticConstants& c, const TransPhaseRule& phase,
                            const Flow& flow) {
    constexpr int Lanes = 8;
    const Index n = static_cast<Index>(ids.size());
    const Index batches = (n + Lanes - 1) / Lanes;
    const double lambda = c.lambda, twoG = 2.0 * c.G, K = c.K;
    const double sqrt2 = std::sqrt(2.0), sqrt2G = sqrt2 * c.G;
    Index bad = n;
#pragma omp parallel for if (worthThreads(8 * batches)) schedule(static) reduction(min : bad)
    for (Index b = 0; b < batches; ++b) {
        HenckyBatch<Lanes> h;
        h.trial(p, ids, b * Lanes, dt);
        const double* jInv = h.jInv;
        alignas(64) double gasLane[Lanes]; // 1: gasified (TransPhaseRule)
        for (int l = 0; l < Lanes; ++l)
            gasLane[l] = phase.gas(h.idx[l]) ? 1.0 : 0.0;
        alignas(64) double eps[6][Lanes], twoEps[6][Lanes], dGamma[Lanes];
        alignas(64) double state[Lanes]; // 0: elastic (trial bᵉ), 1: plastic, 2: stress-free
        h.template strain<dim>(eps);
#pragma omp simd
        for (int l = 0; l < Lanes; ++l) {
            const double ev = eps[0][l] + eps[1][l] + eps[2][l], evThird = ev / 3.0;
            const double d0 = eps[0][l] - evThird, d1 = eps[1][l] - evThird;
            const double d2 = eps[2][l] - evThird;
            const double dn = std::sqrt(d0 * d0 + d1 * d1 + d2 * d2 +
                                        2.0 * (eps[3][l] * eps[3][l] + eps[4][l] * eps[4][l] +
                                               eps[5][l] * eps[5][l])); // |ε̂|
            const double q = sqrt2G * dn, pk = -K * ev;
            const double m = flow.multiplier(q, pk, jInv[l]);
            const double dg = m > 0.0 ? m : 0.0;
            const bool plastic = dg > 0.0;
            const bool gas = gasLane[l] != 0.0;
            // Apex region ε_v ≥ √2 β |ε̂_tr| (see above; ε_v ≥ 0 for β = 0).
            const bool stressFree = gas | (ev >= sqrt2 * flow.beta * dn);
            // ε = ε_v/3 1 + (|ε̂| − Δγ/√2) n after a return, the trial ε if elastic, 0 at the apex.
            const double ratio = 1.0 - dg / (sqrt2 * (dn > 1e-300 ? dn : 1e-300));
            const double evNewThird = (ev - flow.beta * dg) / 3.0;
            // Entry k of the new ε from its deviatoric part dk (written out, not looped: the lane
            // loop stays free of control flow and vectorises).
            auto set = [&](int k, double iso, double dk) {
                double e = plastic ? iso + ratio * dk : eps[k][l];
                e = stressFree ? 0.0 : e;
                eps[k][l] = e;
                twoEps[k][l] = 2.0 * e;
            };
            set(0, evNewThird, d0);
            set(1, evNewThird, d1);
            set(2, evNewThird, d2);
            set(3, 0.0, eps[3][l]);
            set(4, 0.0, eps[4][l]);
            set(5, 0.0, eps[5][l]);
            dGamma[l] = stressFree ? (gas ? 0.0 : sqrt2 * dn) : dg;
            state[l] = stressFree ? 2.0 : (plastic ? 1.0 : 0.0);
        }
        bool anyPlastic = false;
        for (int l = 0; l < Lanes; ++l)
            anyPlastic = anyPlastic || state[l] == 1.0;
        alignas(64) double beNew[6][Lanes], sig[6][Lanes];
        h.stress(lambda, twoG, eps, sig);
        if (anyPlastic) expLanes<Lanes, dim == 2>(twoEps, beNew); // bᵉ = exp 2ε
        for (int l = 0; l < Lanes; ++l) {
            if (b * Lanes + l >= n) break;
            const Index i = h.idx[l];
            if (state[l] == 2.0) {
                p.be[i].setIdentity();
                p.stress[i].setZero();
            } else {
                p.be[i] = HenckyBatch<Lanes>::tensor(state[l] == 0.0 ? h.be : beNew, l);
                p.stress[i] = HenckyBatch<Lanes>::tensor(sig, l);
            }
            p.plasticStrain[i] += dGamma[l];
            if (phase.on()) phase.gasified[i] = gasLane[l] != 0.0 ? 1 : 0;
            // The trial bᵉ catches a non-finite L also where the point ends stress-free (summed
            // from the lanes, not re-read from the tensors just stored).
            double sum = dGamma[l];
            for (int k = 0; k < 6; ++k)
                sum += h.be[k][l] + sig[k][l];
            if (!std::isfinite(sum)) bad = std::min(bad, b * Lanes + l);
        }
    }
    return bad < n ? ids[bad] : -1;
}

} // namespace mpm
