// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/FastMath.hpp"
#include "core/Parallel.hpp"
#include "core/SymmetricEigen.hpp"
#include "materials/FlowRules.hpp"
#include "materials/HenckyBatch.hpp"
#include "materials/HenckyReturnMap.hpp"
#include "materials/Material.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <type_traits>
#include <vector>

namespace mpm {

/// Hencky hyperelasticity in the elastic left Cauchy–Green tensor bᵉ [000 Eq. 4–5]:
///   ψ = ½ λ (ln Jᵉ)² + G tr(εᵉ²),  εᵉ = ½ ln bᵉ,  τ = 2bᵉ ∂ψ/∂bᵉ = λ tr(εᵉ) 1 + 2G εᵉ,  σ = τ/J.
/// bᵉ is advanced by the incremental deformation f = 1 + Δt L: bᵉ ← f bᵉ fᵀ; plastic flow, if
/// any, by the return map in logarithmic strain of HenckyReturnMap.hpp. ε is found without an
/// eigen-decomposition for the usual elastic strains (HenckyBatch::strain).
/// An elastic-law policy of ElastoPlastic (static members only).
struct HenckyLaw {
    static constexpr ElasticLaw kind = ElasticLaw::hencky;
    /// ElastoPlastic::strainEnergies uses the batched strainEnergies below.
    static constexpr bool batchedEnergy = true;

    /// Kirchhoff stress τ(bᵉ) [Pa].
    static Mat3 kirchhoff(const ElasticConstants& c, const Mat3& be);
    /// Energy density ψ(bᵉ) per unit reference volume [J/m³] [000 Eq. 5].
    static double energyDensity(const ElasticConstants& c, const Mat3& be);
    /// bᵉ = exp(2ε) with ε = C⁻¹:τ, the elastic strain of a prescribed Kirchhoff stress.
    static Mat3 leftCauchyGreenFromStress(const ElasticConstants& c, const Mat3& tau);

    /// bᵉ from σ₀ by inverting the elasticity (J = 1 at seeding); not projected onto a yield
    /// surface: a σ₀ outside it returns in the first step.
    template <int dim>
    static void initialise(const ElasticConstants& c, Particles<dim>& p, Index i,
                           const Mat3& sigma0) {
        p.be[i] = sigma0.isZero(0) ? Mat3::Identity() : leftCauchyGreenFromStress(c, sigma0);
        p.stress[i] = sigma0;
    }

    /// Energy of the elastic part, ψ(bᵉ) V⁰ [J] [000 Eq. 5].
    template <int dim>
    static double strainEnergy(const ElasticConstants& c, const Particles<dim>& p, Index i) {
        return energyDensity(c, p.be[i]) * p.volume0[i];
    }

    /// strainEnergy of the particles `ids` into out[i], 8 at a time: the eigenvalues of bᵉ by
    /// the batched Jacobi (symmetricEigen3Lanes) and fastLog, about 5× cheaper than one point
    /// at a time; the same ψ to round-off.
    template <int dim>
    static void strainEnergies(const ElasticConstants& c, const Particles<dim>& p,
                               const std::vector<Index>& ids, std::vector<double>& out) {
        constexpr int Lanes = 8;
        const Index n = static_cast<Index>(ids.size());
        const Index batches = (n + Lanes - 1) / Lanes;
#pragma omp parallel for if (worthThreads(8 * batches)) schedule(static)
        for (Index b = 0; b < batches; ++b) {
            Index idx[Lanes];
            alignas(64) double a[6][Lanes], q[9][Lanes], psi[Lanes];
            for (int l = 0; l < Lanes; ++l) {
                idx[l] = ids[std::min(b * Lanes + l, n - 1)];
                const Mat3& be = p.be[idx[l]];
                a[0][l] = be(0, 0), a[1][l] = be(1, 1), a[2][l] = be(2, 2);
                a[3][l] = be(0, 1), a[4][l] = be(0, 2), a[5][l] = be(1, 2);
            }
            symmetricEigen3Lanes<Lanes, dim == 2>(a, q);
#pragma omp simd
            for (int l = 0; l < Lanes; ++l) {
                const double e0 = 0.5 * fastLog(a[0][l]), e1 = 0.5 * fastLog(a[1][l]);
                const double e2 = 0.5 * fastLog(a[2][l]);
                const double tr = e0 + e1 + e2;
                psi[l] = 0.5 * c.lambda * tr * tr + c.G * (e0 * e0 + e1 * e1 + e2 * e2);
            }
            for (int l = 0; l < Lanes && b * Lanes + l < n; ++l)
                out[idx[l]] = psi[l] * p.volume0[idx[l]];
        }
    }

    /// Advance the particles `ids` over dt with the flow rule `flow` (NoFlow: elastic). Hencky
    /// plasticity is cohesionless: the tension cut-off must be the apex (asserted).
    template <int dim, class Flow>
    static Index update(Particles<dim>& p, const std::vector<Index>& ids, double dt,
                        const ElasticConstants& c, const TransPhaseRule& phase, const Flow& flow,
                        [[maybe_unused]] const TensionCutoff& cutoff) {
        assert(cutoff.sigmaT == 0.0 && cutoff.tauC == 0.0);
        if constexpr (std::is_same_v<Flow, NoFlow>)
            return elasticUpdate(p, ids, dt, c);
        else
            return henckyReturnMapUpdate(p, ids, dt, c, phase, flow);
    }

    /// Elastic update: bᵉ ← f bᵉ fᵀ, σ = τ(bᵉ) V⁰/V. Returns the first particle whose stress is
    /// not finite, or -1.
    template <int dim>
    static Index elasticUpdate(Particles<dim>& p, const std::vector<Index>& ids, double dt,
                               const ElasticConstants& c) {
        // Particles go through in batches of Lanes, vectorised across particles (HenckyBatch).
        constexpr int Lanes = 8;
        const Index n = static_cast<Index>(ids.size());
        const Index batches = (n + Lanes - 1) / Lanes;
        const double lambda = c.lambda, twoG = 2.0 * c.G;
        Index bad = n;
#pragma omp parallel for if (worthThreads(8 * batches)) schedule(static) reduction(min : bad)
        for (Index b = 0; b < batches; ++b) {
            HenckyBatch<Lanes> h;
            h.trial(p, ids, b * Lanes, dt);
            alignas(64) double eps[6][Lanes], sig[6][Lanes];
            h.template strain<dim>(eps);
            h.stress(lambda, twoG, eps, sig);
            for (int l = 0; l < Lanes; ++l) {
                if (b * Lanes + l >= n) break;
                const Index i = h.idx[l];
                p.be[i] = HenckyBatch<Lanes>::tensor(h.be, l);
                p.stress[i] = HenckyBatch<Lanes>::tensor(sig, l);
                if (!std::isfinite(sig[0][l] + sig[1][l] + sig[2][l] + sig[3][l] + sig[4][l] +
                                   sig[5][l]))
                    bad = std::min(bad, b * Lanes + l);
            }
        }
        return bad < n ? ids[bad] : -1;
    }
};

} // namespace mpm
