// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Constants.hpp"
#include "core/Parallel.hpp"
#include "core/Types.hpp"
#include "particles/Particles.hpp"

#include <cmath>
#include <vector>

// Per-step yield/flow functors shared by the elastic laws' return maps (HenckyReturnMap.hpp,
// HypoelasticReturnMap.hpp). Both laws write the yield surface in the invariants
//   p = −tr σ/3 (pressure, > 0 in compression),  q = √½ |σ − (tr σ/3) 1| = √J₂  [000 Eq. 6],
// which are p = −σ_m and q = τ of [001 Eq. 33–34]. A functor provides
//   beta                 the dilatancy of its potential g = q − β p [-] (0: isochoric flow),
//   yield(q, p)          the rate-independent (static) yield function [Pa],
//   multiplier(q, p, j)  the plastic multiplier Δγ of a trial state (q, p) with yield(q, p) > 0,
//                        from consistency with the elastic return q = q_tr − G Δγ,
//                        p = p_tr + K β Δγ; j = V⁰/V turns a Kirchhoff p into a Cauchy one.
// They are chosen at compile time: no per-particle virtual call or option branch.

namespace mpm {

constexpr double degree = pi / 180.0;

/// Drucker–Prager coefficient fitted to the compression corners of Mohr–Coulomb,
/// μ = 2√3 sin φ / (3 − sin φ) [000 Eq. 8], for an angle φ in degrees.
inline double frictionCoefficient(double angleDegrees) {
    const double s = std::sin(angleDegrees * pi / 180.0);
    return 2.0 * std::sqrt(3.0) * s / (3.0 - s);
}

/// Cohesion coefficient of the same fit, k = 2√3 c cos φ / (3 − sin φ) [Pa] (apex at p = −c/tan φ).
inline double cohesionCoefficient(double cohesion, double angleDegrees) {
    const double s = std::sin(angleDegrees * degree), co = std::cos(angleDegrees * degree);
    return 2.0 * std::sqrt(3.0) * cohesion * co / (3.0 - s);
}

/// Drucker–Prager coefficient fitted to Mohr–Coulomb in plane strain [001 Eq. 35],
/// q_φ = 3 tan φ / √(9 + 12 tan² φ), for an angle φ in degrees (q_φ(35°) = 0.5445).
inline double planeStrainFrictionCoefficient(double angleDegrees) {
    const double t = std::tan(angleDegrees * degree);
    return 3.0 * t / std::sqrt(9.0 + 12.0 * t * t);
}

/// Cohesion coefficient of the plane-strain fit, k_φ = 3c / √(9 + 12 tan² φ) [Pa] [001 Eq. 35].
inline double planeStrainCohesionCoefficient(double cohesion, double angleDegrees) {
    const double t = std::tan(angleDegrees * degree);
    return 3.0 * cohesion / std::sqrt(9.0 + 12.0 * t * t);
}

/// The trans-phase relation of a step [000 Eq. 10]: a point is gasified (grains out of
/// contact: no stress, elastic strain reset) while the density ρ̄_p of its neighbourhood (the
/// `phaseDensity` field, transfers/PhaseDensity.hpp) is below ρ_c; a loose region is compacted
/// back to ρ_c under its own weight before it carries load, and all its points start again
/// stress-free together. The state is written to the `gasified` flag (ParaView, the coupling).
/// Where no neighbourhood density was computed (a material driven on its own, as in the unit
/// tests) the point's own m_p/V_p [000 Eq. 18] stands for it. ρ_c = 0: off (never gasified).
struct TransPhaseRule {
    double rhoC = 0.0;               ///< critical density ρ_c [kg/m³] (0: off)
    const double* density = nullptr; ///< ρ̄_p per particle [kg/m³], or null: m_p/V_p
    const double* mass = nullptr;    ///< m_p (for m_p/V_p)
    const double* volume = nullptr;  ///< V_p (for m_p/V_p)
    int* gasified = nullptr;         ///< the state flag per particle (1: gasified), or null

    bool on() const { return gasified != nullptr; }
    /// ρ̄_p < ρ_c (false when off).
    bool gas(Index i) const {
        return rhoC > 0.0 && (density != nullptr ? density[i] : mass[i] / volume[i]) < rhoC;
    }
    /// gas(i), also stored in the flag.
    bool update(Index i) const {
        const bool g = gas(i);
        if (gasified != nullptr) gasified[i] = g ? 1 : 0;
        return g;
    }

    /// With `gasVolume: neighbourhood` (the default): a gasified point takes its neighbourhood's
    /// density,
    ///     V_p ← m_p / ρ̄_p,   F ← (V_p'/V_p)^(1/dim) F   (V_p = det F V⁰ kept).
    /// Grains out of contact keep no memory of the sub-cell volume their point's path gave them;
    /// without this a loose pocket caged by dense neighbours stays a little below ρ_c for good,
    /// because the neighbours hold the grid still. A point marked in `nearBody` (within
    /// nearBodyCells cells of a coupled body, transfers/PhaseDensity.hpp) keeps its volume: the gap
    /// a body's motion opens is real, and the body's work in closing it again is the bed's damping
    /// (docs/settingsGuide.md, "A gasified point's volume"). Mass and momentum are untouched.
    template <int dim>
    void relaxGasVolumes(Particles<dim>& p, const std::vector<Index>& ids,
                         const int* nearBody) const {
        if (density == nullptr || gasified == nullptr) return;
        const Index n = static_cast<Index>(ids.size());
#pragma omp parallel for if (worthThreads(n)) schedule(static)
        for (Index k = 0; k < n; ++k) {
            const Index i = ids[k];
            if (gasified[i] == 0 || !(density[i] > 0.0) ||
                (nearBody != nullptr && nearBody[i] != 0))
                continue;
            const double v = p.mass[i] / density[i];
            p.F[i] *= std::pow(v / p.volume[i], 1.0 / dim);
            p.volume[i] = v;
        }
    }
};

/// The Mohr–Coulomb friction angle [deg] whose plane-strain fit [001 Eq. 35] is the cone
/// coefficient μ: tan φ = 3μ/√(9 − 12μ²) (90° when 12μ² ≥ 9: steeper than any plane-strain
/// Mohr–Coulomb surface).
inline double planeStrainAngle(double mu) {
    const double d = 9.0 - 12.0 * mu * mu;
    return d > 0.0 ? std::atan(3.0 * mu / std::sqrt(d)) / degree : 90.0;
}

/// The Mohr–Coulomb friction angle [deg] whose compression-corner fit [000 Eq. 8] is μ:
/// sin φ = 3μ/(2√3 + μ) (90° beyond μ = √3).
inline double compressionAngle(double mu) {
    const double s = 3.0 * mu / (2.0 * std::sqrt(3.0) + mu);
    return s < 1.0 ? std::asin(s) / degree : 90.0;
}

/// No plastic flow: the elastic laws' plain update.
struct NoFlow {};

/// The corner of the shear surface with the tension cut-off [001 Eq. 32] in (σ_m, τ):
/// C = (σ_t, τ_C) with τ_C = k − μ σ_t ≥ 0. The default (0, 0) is the apex of a cohesionless
/// cone (no tension). Used by the hypoelastic return map only.
struct TensionCutoff {
    double sigmaT = 0.0; ///< tension strength σ_t [Pa] (mean stress, tension positive)
    double tauC = 0.0;   ///< τ = √J₂ at the corner [Pa]
};

/// Rate-independent Drucker–Prager flow [000 Eq. 6–8], [001 Eq. 31b]: yield q − μ p − k ≤ 0,
/// potential g = q − β p.
struct DruckerPragerFlow {
    double mu;      ///< friction coefficient μ_s (q_φ) [-]
    double beta;    ///< dilatancy β (q_ψ) [-] (0: isochoric)
    double G;       ///< shear modulus [Pa]
    double K;       ///< bulk modulus [Pa]
    double k = 0.0; ///< cohesion coefficient k (k_φ) [Pa] (0: cohesionless)

    /// f = q − μ p − k [Pa].
    double yield(double q, double p) const { return q - mu * p - k; }
    /// Plastic multiplier Δγ = f_tr/(G + μ K β) of a trial state (q, p) [Pa] (≤ 0: elastic).
    /// jInv = V⁰/V is unused (rate- and density-independent).
    double multiplier(double q, double p, double /*jInv*/) const {
        return (q - mu * p - k) / (G + mu * K * beta);
    }
};

/// μ(I) rheology [000 Eq. 9] with isochoric flow: μ(I) = μ_s + (μ₂ − μ_s)/(I₀/I + 1),
/// I = γ̇ᵖ √(d² ρ_s / p) with p the Cauchy pressure and γ̇ᵖ = Δγ/Δt the engineering plastic shear
/// rate (Δγ = √2 |Δε̂ᵖ|, conjugate to q = √½ |s|; simple shear: the shear rate).
struct MuIFlow {
    static constexpr double beta = 0.0; ///< isochoric flow
    double muS;                         ///< static friction coefficient μ_s [-]
    double dMu;                         ///< μ₂ − μ_s [-]
    double I0;                          ///< I₀ [-]
    double G;                           ///< shear modulus [Pa]
    double rateScale; ///< d √ρ_s / Δt [kg^½ m^-½ s⁻¹]: I = rateScale Δγ / √p

    /// μ(I) [000 Eq. 9] (μ_s at I = 0).
    double mu(double I) const { return muS + dMu * I / (I0 + I); }

    /// Static yield function q − μ_s p [Pa]: the flow starts where it is positive.
    double yield(double q, double p) const { return q - muS * p; }

    /// Plastic multiplier Δγ of a trial state (q, p) [Pa], p > 0, jInv = V⁰/V.
    /// Consistency q_tr − G Δγ = μ(I) p with I = c Δγ, c = rateScale/√(p jInv), is, times
    /// (I₀ + c Δγ) > 0, the quadratic G c Δγ² + B Δγ − F I₀ = 0 with F = q_tr − μ_s p,
    /// B = G I₀ + c (Δμ p − F). The residual is strictly decreasing in Δγ, so for F > 0 there
    /// is exactly one root, in (0, F/G]; it is taken in closed form without cancellation
    /// (2 F I₀/(B + √D) for B > 0, (√D − B)/(2 G c) otherwise, D = B² + 4 G c F I₀). c = 0
    /// (d → 0 or Δt → ∞) gives F/G, the Drucker–Prager return with μ_s. F ≤ 0 gives 0.
    double multiplier(double q, double p, double jInv) const {
        const double f0 = q - muS * p, f = f0 > 0.0 ? f0 : 0.0;
        const double pc = p * jInv;
        const double c = rateScale / std::sqrt(pc > 1e-300 ? pc : 1e-300);
        const double b = G * I0 + c * (dMu * p - f);
        const double sq = std::sqrt(b * b + 4.0 * G * c * f * I0);
        return b > 0.0 ? 2.0 * f * I0 / (b + sq) : (sq - b) / (2.0 * G * c);
    }
};

/// μ(I) of the viscoelastic model [002 Eq. 43–44]: τ = μ(I) p, μ(I) = μ_s + (μ₂ − μ_s)/(I₀/I + 1),
/// I = γ̇ᵖ d √(ρ_s/p), with μ_s = tan φ_s and μ₂ = tan φ₂ in τ = √J₂ [002 §4]; isochoric, no
/// tension. The viscous return map (ViscoelasticReturnMap.hpp) returns with it in closed form
/// [002 Eq. 55–58].
struct TanMuIFlow {
    double muS;           ///< μ_s [-]
    double mu2;           ///< μ₂ [-]
    double I0;            ///< I₀ [-]
    double grainDiameter; ///< d [m]
    double grainDensity;  ///< ρ_s [kg/m³]

    /// α/√p_tr = I₀ G̃ Δt/(d √ρ_s) [Pa^½] of [002 Eq. 55], for G̃ [Pa] and Δt [s].
    double alphaCoefficient(double Gt, double dt) const {
        return I0 * Gt * dt / (grainDiameter * std::sqrt(grainDensity));
    }
    /// Above the static yield surface, τ_tr > μ_s p_tr [002 Eq. 53] (τ, p [Pa]).
    bool flows(double tauTr, double pTr) const { return tauTr > muS * pTr; }
    /// τ after the return [Pa] [002 Eq. 55–58], the smaller root of τ = μ(I) p_tr with
    /// I = I₀ (τ_tr − τ)/α: S₀ = μ_s p_tr, S₂ = μ₂ p_tr, B = S₂ + τ_tr + α, H = S₂ τ_tr + S₀ α,
    /// τ = 2H/(B + √(B² − 4H)) (α = alphaCoefficient √p_tr [Pa]).
    double shearStress(double tauTr, double pTr, double alpha) const {
        const double S0 = muS * pTr, S2 = mu2 * pTr;
        const double B = S2 + tauTr + alpha, H = S2 * tauTr + S0 * alpha;
        const double disc = B * B - 4.0 * H;
        return 2.0 * H / (B + std::sqrt(disc > 0.0 ? disc : 0.0));
    }
};

} // namespace mpm
