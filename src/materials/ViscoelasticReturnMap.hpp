// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Parallel.hpp"
#include "materials/FlowRules.hpp"
#include "materials/HenckyBatch.hpp"
#include "materials/Material.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

// The viscous return map of the hypoelastic law (HypoelasticLaw::viscousUpdate): a viscosity
// policy (Viscosity.hpp) with the μ(I) flow of [002] (TanMuIFlow), the kernel of
// `viscoelasticMuI` [002 §2–3]:
//   σ = σᵉ + σᵛ [Eq. 10], σᵉ hypoelastic (Jaumann rate, rotationally neutralised update)
//   [Eq. 11–12], σᵛ the policy's viscous stress on the viscoelastic part Dᵛᵉ = D − Dᵖ of the rate
//   only [Eq. 13], μ(I) flow τ = μ(I) p [Eq. 43–44] with I = γ̇ᵖ d √(ρ_s/p), isochoric
//   Dᵖ = γ̇ᵖ σ_dev/(2τ) [Eq. 48–49], and no tension: σ = σᵉ = 0 when p_tr ≤ 0 or ρ ≤ ρ_c
//   [Eq. 46–47] (the separation rule; it replaces the trans-phase relation of the inviscid
//   return maps).
// Per step and point ([002 §3.2], App. A), with ΔF = 1 + Δt L, D = sym L, W = skw L, ϑ and η the
// policy's bulk and shear viscosities:
//   1. σᵉ_tr = Q σᵉ Qᵀ + ℂ : Δt D, Q = exp(Δt W) (exact for a rigid rotation, [Eq. 52]; the
//      increment in the end-of-step frame, docs/viscoelastic.md §5);
//   2. σ_tr = σᵉ_tr + ϑ tr D 1 + 2η D_dev [Eq. 51]; p_tr = −tr σ_tr/3, τ_tr = √(½ s_tr : s_tr);
//   3. separated if p_tr ≤ 0 or ρ ≤ ρ_c: σ = σᵉ = 0, γ̇ᵖ = 0;
//   4. elastic if τ_tr ≤ μ_s p_tr [Eq. 53]: σ = σ_tr, σᵉ = σᵉ_tr, γ̇ᵖ = 0;
//   5. flowing otherwise, with G̃ = G + η/Δt: α = I₀ G̃ Δt √p_tr/(d √ρ_s), τ the closed-form
//      root of TanMuIFlow::shearStress [Eq. 55–58], p = p_tr [Eq. 56],
//      γ̇ᵖ = (τ_tr − τ)/(G̃ Δt) [Eq. 59], σ = (τ/τ_tr) s_tr − p 1 [Eq. 60];
//   6. σᵉ = σ − ϑ tr D 1 − 2η (D_dev − γ̇ᵖ N/√2), N = s_tr/|s_tr| [Eq. 61].
// With ϑ = η = 0 (e = 1) it is the undamped hypoelastic μ(I) model: σ = σᵉ.

namespace mpm {

/// Which branch of the return map a point took in its last step (`flowState` in the VTU).
enum ViscoelasticState : int { elasticState = 0, flowingState = 1, separatedState = 2 };

/// The state of a viscous material, declared by ElastoPlastic: the handles of σᵉ
/// (`elasticStress`, restarted), γ̇ᵖ [1/s] (`plasticStrainRate`) and the ViscoelasticState
/// (`flowState`).
struct ViscoelasticFields {
    std::size_t elasticStress = 0, strainRate = 0, state = 0;
};

namespace detail {

/// Rodrigues' coefficients of exp([w]×) = 1 + a [w]× + b [w]×², from t² = |w|²:
/// a = sin t / t, b = (1 − cos t)/t²; by their series below t = 0.1 (the next terms, t¹⁰/11! and
/// t¹⁰/12!, are under 3·10⁻¹⁸).
inline void rodrigues(double t2, double& a, double& b) {
    if (t2 < 1e-2) {
        a = 1.0 - t2 / 6.0 * (1.0 - t2 / 20.0 * (1.0 - t2 / 42.0 * (1.0 - t2 / 72.0)));
        b = 0.5 - t2 / 24.0 * (1.0 - t2 / 30.0 * (1.0 - t2 / 56.0 * (1.0 - t2 / 90.0)));
        return;
    }
    const double t = std::sqrt(t2);
    a = std::sin(t) / t;
    b = (1.0 - std::cos(t)) / t2;
}

} // namespace detail

/// Advance σ, σᵉ, γ̇ᵖ, the flow state and the plastic strain (∫ γ̇ᵖ dt) of `ids` over dt by the
/// return map above, with the viscosity `visc` (ϑ tr D by `volumetric`, 2η d by `deviatoric`, η by
/// `shearViscosity`) and the separation density ρ_c [kg/m³]. Returns the first particle whose
/// state is not finite, or -1.
template <int dim, class Viscosity>
Index viscoelasticReturnMapUpdate(Particles<dim>& p, const std::vector<Index>& ids, double dt,
                                  const ElasticConstants& c, const TanMuIFlow& flow,
                                  const Viscosity& visc, double rhoC,
                                  const ViscoelasticFields& fields) {
    // Points go through in batches of Lanes in structure-of-arrays form, so that the update
    // vectorises across points (as HenckyBatch, whose lane-to-tensor helper stores the results);
    // the three outcomes are selected per lane.
    // Symmetric tensors are kept as their six entries (00 11 22 01 02 12).
    constexpr int Lanes = 8;
    const Index n = static_cast<Index>(ids.size());
    const Index batches = (n + Lanes - 1) / Lanes;
    const double lambda = c.lambda, G = c.G;
    const double Gt = G + visc.shearViscosity() / dt;       // G̃ [Eq. 55]
    const double alphaCoef = flow.alphaCoefficient(Gt, dt); // α/√p
    std::vector<Mat3>& sigmaE = p.tensor(fields.elasticStress);
    std::vector<double>& rate = p.scalar(fields.strainRate);
    std::vector<int>& state = p.flag(fields.state);
    Index bad = n;
#pragma omp parallel for if (worthThreads(8 * batches)) schedule(static) reduction(min : bad)
    for (Index b = 0; b < batches; ++b) {
        Index idx[Lanes];
        alignas(64) double d[6][Lanes], w[3][Lanes], se[6][Lanes], rho[Lanes], ra[Lanes], rb[Lanes];
        for (int l = 0; l < Lanes; ++l) {
            const Index i = ids[std::min(b * Lanes + l, n - 1)];
            idx[l] = i;
            const Mat3 L = embed3<dim>(p.L[i]);
            // D = sym L, Δt W = [w]× with W = skw L.
            d[0][l] = L(0, 0), d[1][l] = L(1, 1), d[2][l] = L(2, 2);
            d[3][l] = 0.5 * (L(0, 1) + L(1, 0));
            d[4][l] = 0.5 * (L(0, 2) + L(2, 0));
            d[5][l] = 0.5 * (L(1, 2) + L(2, 1));
            w[0][l] = dt * (0.5 * (L(2, 1) - L(1, 2)));
            w[1][l] = dt * (0.5 * (L(0, 2) - L(2, 0)));
            w[2][l] = dt * (0.5 * (L(1, 0) - L(0, 1)));
            detail::rodrigues(w[0][l] * w[0][l] + w[1][l] * w[1][l] + w[2][l] * w[2][l], ra[l],
                              rb[l]);
            const Mat3& S = sigmaE[i];
            se[0][l] = S(0, 0), se[1][l] = S(1, 1), se[2][l] = S(2, 2);
            se[3][l] = S(0, 1), se[4][l] = S(0, 2), se[5][l] = S(1, 2);
            rho[l] = p.mass[i] / p.volume[i];
        }
        alignas(64) double sig[6][Lanes], sigE[6][Lanes], gdot[Lanes], st[Lanes];
#pragma omp simd
        for (int l = 0; l < Lanes; ++l) {
            // 1. Objective elastic trial [Eq. 52]: σᵉ rotated by Q = exp(Δt W) (Rodrigues,
            //    [w]×² = w wᵀ − |w|² 1), the increment ℂ : Δt D taken at the end of the step (not
            //    half-rotated): the return is implicit, and in fast flow the stress must align
            //    with the rate it returns to (docs/viscoelastic.md §5).
            const double wx = w[0][l], wy = w[1][l], wz = w[2][l];
            const double a = ra[l], bb = rb[l], t2 = wx * wx + wy * wy + wz * wz;
            const double Q[3][3] = {
                {1.0 + bb * (wx * wx - t2), -a * wz + bb * wx * wy, a * wy + bb * wx * wz},
                {a * wz + bb * wx * wy, 1.0 + bb * (wy * wy - t2), -a * wx + bb * wy * wz},
                {-a * wy + bb * wx * wz, a * wx + bb * wy * wz, 1.0 + bb * (wz * wz - t2)}};
            const double S[3][3] = {{se[0][l], se[3][l], se[4][l]},
                                    {se[3][l], se[1][l], se[5][l]},
                                    {se[4][l], se[5][l], se[2][l]}};
            double M[3][3]; // Q σᵉ
            for (int r = 0; r < 3; ++r)
                for (int k = 0; k < 3; ++k)
                    M[r][k] = Q[r][0] * S[0][k] + Q[r][1] * S[1][k] + Q[r][2] * S[2][k];
            auto rot = [&](int r, int k) { // (Q σᵉ Qᵀ)_rk
                return M[r][0] * Q[k][0] + M[r][1] * Q[k][1] + M[r][2] * Q[k][2];
            };
            const double trD = d[0][l] + d[1][l] + d[2][l];
            const double diagE = dt * lambda * trD, twoGdt = 2.0 * G * dt;
            double e[6] = {
                rot(0, 0) + diagE + twoGdt * d[0][l], rot(1, 1) + diagE + twoGdt * d[1][l],
                rot(2, 2) + diagE + twoGdt * d[2][l], rot(0, 1) + twoGdt * d[3][l],
                rot(0, 2) + twoGdt * d[4][l],         rot(1, 2) + twoGdt * d[5][l]};
            // 2. Viscoelastic trial [Eq. 51]: σ_tr = σᵉ_tr + ϑ tr D 1 + 2η D_dev.
            const double trThird = trD / 3.0;
            double dev[6]; // D_dev
            for (int k = 0; k < 6; ++k)
                dev[k] = d[k][l] - (k < 3 ? trThird : 0.0);
            double tr[6];
            for (int k = 0; k < 6; ++k)
                tr[k] = e[k] + (k < 3 ? visc.volumetric(trD) : 0.0) + visc.deviatoric(dev[k]);
            const double pTr = -(tr[0] + tr[1] + tr[2]) / 3.0;
            double s[6]; // deviator of the trial
            for (int k = 0; k < 6; ++k)
                s[k] = tr[k] + (k < 3 ? pTr : 0.0);
            const double tauTr = std::sqrt(0.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] +
                                                  2.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5])));
            // 3.–5. Separated [Eq. 46–47], below the static yield surface [Eq. 53], or the
            //        modified radial return [Eq. 55–60] (computed in every lane, selected).
            const bool separated = (pTr <= 0.0) | (rho[l] <= rhoC);
            const bool flowing = !separated & flow.flows(tauTr, pTr);
            const double alpha = alphaCoef * std::sqrt(pTr > 0.0 ? pTr : 0.0);
            const double tau = flow.shearStress(tauTr, pTr, alpha);
            const double gammaDot = flowing ? (tauTr - tau) / (Gt * dt) : 0.0;
            const double scale = tau / tauTr;
            // 6. Elastic stress for the next step [Eq. 61]: Dᵖ = γ̇ᵖ N/√2, N = s/|s|.
            const double dpScale = 0.5 * gammaDot / tauTr;
            for (int k = 0; k < 6; ++k) {
                const double sf = scale * s[k] - (k < 3 ? pTr : 0.0);
                const double ef = sf - (k < 3 ? visc.volumetric(trD) : 0.0) -
                                  visc.deviatoric(dev[k] - dpScale * s[k]);
                sig[k][l] = separated ? 0.0 : (flowing ? sf : tr[k]);
                sigE[k][l] = separated ? 0.0 : (flowing ? ef : e[k]);
            }
            gdot[l] = gammaDot;
            st[l] = separated ? 2.0 : (flowing ? 1.0 : 0.0);
        }
        for (int l = 0; l < Lanes; ++l) {
            if (b * Lanes + l >= n) break;
            const Index i = idx[l];
            p.stress[i] = HenckyBatch<Lanes>::tensor(sig, l);
            sigmaE[i] = HenckyBatch<Lanes>::tensor(sigE, l);
            state[i] = st[l] == 2.0 ? separatedState : (st[l] == 1.0 ? flowingState : elasticState);
            rate[i] = gdot[l];
            p.plasticStrain[i] += gdot[l] * dt;
            // Checked on the lanes, not re-read from the tensors just stored.
            double sum = gdot[l];
            for (int k = 0; k < 6; ++k)
                sum += sig[k][l] + sigE[k][l];
            if (!std::isfinite(sum)) bad = std::min(bad, b * Lanes + l);
        }
    }
    return bad < n ? ids[bad] : -1;
}

} // namespace mpm
