// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Parallel.hpp"
#include "materials/FlowRules.hpp"
#include "materials/Material.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

// Drucker–Prager with tension cut-off on hypoelastic Jaumann-rate elasticity (HypoelasticLaw with
// DruckerPragerFlow or MuIFlow, FlowRules.hpp) [001 Eq. 25, 31b–36].
//
// Trial stress σ_tr = σ + Δt (C : D + W σ − σ W) (jaumannTrialStress). Invariants, tension
// positive: σ_m = tr σ/3, s = σ − σ_m 1, τ = √J₂ = √(½ s : s) [001 Eq. 33–34] (p = −σ_m, q = τ
// in FlowRules.hpp). Surfaces:
//   shear    f_s = τ + μ σ_m − k ≤ 0  [001 Eq. 31b]  (μ = q_φ, k = k_φ [001 Eq. 35], or the
//            compression fit [000 Eq. 8]),
//   tension  f_t = σ_m − σ_t ≤ 0      [001 Eq. 32]   (σ_t ≤ k/μ = c/tan φ, the cone's apex).
// Flow: shear potential g_s = τ + β σ_m (β = q_ψ of the dilation angle ψ ≤ φ; non-associated for
// ψ < φ), Δεᵖ = Δλ (s/(2τ) + (β/3) 1): with isotropic elasticity the return keeps the direction
// of s and is
//   τ = τ_tr − G Δλ,  σ_m = σ_m,tr − K β Δλ,  s = (τ/τ_tr) s_tr,
// and consistency f_s = 0 gives Δλ = f_s,tr/(G + μ K β) (DruckerPragerFlow; the μ(I) root for
// MuIFlow). Δλ = √2 |Δε̂ᵖ| is the engineering plastic shear strain, as for the Hencky models; the
// plastic volume change is tr Δεᵖ = β Δλ. Tension potential g_t = σ_m: σ_m = σ_t, s unchanged.
//
// Regions. In the (σ_m, τ) plane take the corner C = (σ_t, τ_C), τ_C = k − μ σ_t ≥ 0, and a
// trial's offsets u = σ_m,tr − σ_t, v = τ_tr − τ_C, so that f_s,tr = v + μ u. The shear return
// moves a trial along (−K β, −G) and lands at σ_m − σ_t = n/(G + μ K β) with n = G u − K β v:
// n < 0 is the side of the line through C along the potential's normal (K β, G) from which the
// shear return stays within the cut-off. Then
//   elastic  f_s ≤ 0, u ≤ 0:  σ = σ_tr;
//   shear    f_s > 0, n < 0:  the return above;
//   tension  u > 0, v ≤ 0:    σ_m = σ_t, s = s_tr (then f_s = v ≤ 0);
//   corner   otherwise (f_s > 0, n ≥ 0, v > 0): σ = C, i.e. σ_m = σ_t, s = (τ_C/τ_tr) s_tr.
// The corner region is the cone C + {a (K β, G) + b (K, 0): a, b ≥ 0} of trials whose return
// combines both flows (Koiter's rule, Δλ_s = a, Δλ_t = b ≥ 0), so the map is the closest point
// in the energy norm. With the default σ_t = k/μ the corner is the apex (τ_C = 0) and the tension
// region is empty; c = 0 and σ_t = 0 send every trial beyond the normal line to zero stress.
// The plastic shear strain increment is Δλ in shear, a = (τ_tr − τ_C)/G at the corner, 0 in
// tension. (FLAC's rule for Drucker–Prager with a tension cut-off bounds the shear region by the
// diagonal through C with slope √(1 + μ²) − μ instead and clamps τ afterwards; the two differ
// only in the wedge between that diagonal and the normal line, where FLAC does not return to the
// closest point.)
//
// A μ(I) flow has no cohesion and no tension (C at the origin) and β = 0, so its shear region is
// σ_m,tr < 0 (p > 0), as in the Hencky return map; the multiplier uses the Cauchy pressure.
// Trans-phase relation [000 Eq. 10]: a point with ρ_p = m_p/V_p < ρ_c carries zero stress (it
// starts stress-free when it re-compacts); its plastic strain is unchanged.

namespace mpm {

/// Forward-Euler Jaumann update σ + Δt (C : D + W σ − σ W) [001 Eq. 25, 36] of the stress s for
/// the velocity gradient L (3×3; plane strain: zero third row and column).
inline Mat3 jaumannTrialStress(const ElasticConstants& c, const Mat3& L, const Mat3& s, double dt) {
    const Mat3 D = 0.5 * (L + L.transpose());
    const Mat3 W = 0.5 * (L - L.transpose());
    const double trD = D.trace();
    const Mat3 rate =
        (c.K - 2.0 * c.G / 3.0) * trD * Mat3::Identity() + 2.0 * c.G * D + W * s - s * W;
    return s + dt * rate;
}

/// Advance σ and the plastic strain of `ids` over dt by the return map above with the yield/flow
/// functor `Flow` (chosen at compile time) and the cut-off `cut`; `phase` gasifies points (off:
/// never). Elastic points get exactly the hypoelastic stress. Returns the first particle
/// whose state is not finite, or -1.
template <int dim, class Flow>
Index hypoelasticReturnMapUpdate(Particles<dim>& p, const std::vector<Index>& ids, double dt,
                                 const ElasticConstants& c, const TransPhaseRule& phase,
                                 const Flow& flow, const TensionCutoff& cut) {
    const Index n = static_cast<Index>(ids.size());
    const double G = c.G, Kbeta = c.K * flow.beta;
    Index bad = n;
#pragma omp parallel for if (worthThreads(n)) schedule(static) reduction(min : bad)
    for (Index k = 0; k < n; ++k) {
        const Index i = ids[k];
        const Mat3 trial = jaumannTrialStress(c, embed3<dim>(p.L[i]), p.stress[i], dt);
        const double sm = trial.trace() / 3.0;
        const Mat3 s = trial - sm * Mat3::Identity();
        const double tau = std::sqrt(0.5 * s.squaredNorm());
        const double u = sm - cut.sigmaT, v = tau - cut.tauC;
        const double fs = flow.yield(tau, -sm);
        double dGamma = 0.0;
        Mat3 sig; // built in registers, stored once (the check does not re-read the store)
        if (phase.update(i)) {
            sig.setZero(); // gasified
            // A gas point keeps its volume only: F ← J^(1/dim) I, the same det F. Its F would
            // otherwise shear without bound (entries of 10⁹ at J ≈ 100, where det F rounds to
            // ≤ 0: tutorials/spheropolygon/granularMatrix at h = 2.5 mm).
            p.F[i] = std::pow(p.volume[i] / p.volume0[i], 1.0 / dim) * Mat<dim>::Identity();
        } else if (fs <= 0.0 && u <= 0.0) {
            sig = trial;
        } else if (fs > 0.0 && G * u - Kbeta * v < 0.0) {
            dGamma = flow.multiplier(tau, -sm, 1.0);
            sig = (sm - Kbeta * dGamma) * Mat3::Identity() + ((tau - G * dGamma) / tau) * s;
        } else if (v <= 0.0) {
            sig = cut.sigmaT * Mat3::Identity() + s;
        } else {
            dGamma = v / G;
            sig = cut.sigmaT * Mat3::Identity() + (cut.tauC / tau) * s;
        }
        p.stress[i] = sig;
        p.plasticStrain[i] += dGamma;
        if (!std::isfinite(sig.sum() + trial.sum() + dGamma)) bad = std::min(bad, k);
    }
    return bad < n ? ids[bad] : -1;
}

} // namespace mpm
