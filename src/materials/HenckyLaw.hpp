// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/FastMath.hpp"
#include "core/Parallel.hpp"
#include "core/SymmetricEigen.hpp"
#include "materials/FlowRules.hpp"
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
/// any, by the return map in principal logarithmic strain of HenckyReturnMap.hpp.
/// An elastic-law policy of ElastoPlastic (static members only).
struct HenckyLaw {
    static constexpr ElasticLaw kind = ElasticLaw::hencky;

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

    /// Advance the particles `ids` over dt with the flow rule `flow` (NoFlow: elastic). Hencky
    /// plasticity is cohesionless: the tension cut-off must be the apex (asserted).
    template <int dim, class Flow>
    static Index update(Particles<dim>& p, const std::vector<Index>& ids, double dt,
                        const ElasticConstants& c, double rhoC, const Flow& flow,
                        [[maybe_unused]] const TensionCutoff& cutoff) {
        assert(cutoff.sigmaT == 0.0 && cutoff.tauC == 0.0);
        if constexpr (std::is_same_v<Flow, NoFlow>)
            return elasticUpdate(p, ids, dt, c);
        else
            return henckyReturnMapUpdate(p, ids, dt, c, rhoC, flow);
    }

    /// Elastic update: bᵉ ← f bᵉ fᵀ, σ = τ(bᵉ) V⁰/V. Returns the first particle whose stress is
    /// not finite, or -1.
    template <int dim>
    static Index elasticUpdate(Particles<dim>& p, const std::vector<Index>& ids, double dt,
                               const ElasticConstants& c) {
        // Particles go through in batches of Lanes so that the eigen-decompositions vectorise
        // across particles (DESIGN §7); the last batch is padded with copies of its first
        // particle.
        constexpr int Lanes = 8;
        const Index n = static_cast<Index>(ids.size());
        const Index batches = (n + Lanes - 1) / Lanes;
        const double lambda = c.lambda, twoG = 2.0 * c.G;
        Index bad = n;
#pragma omp parallel for if (worthThreads(8 * batches)) schedule(static) reduction(min : bad)
        for (Index b = 0; b < batches; ++b) {
            Mat3 be[Lanes], Q[Lanes];
            Vec3 lam[Lanes];
            Index idx[Lanes];
            for (int l = 0; l < Lanes; ++l) {
                const Index k = std::min(b * Lanes + l, n - 1);
                idx[l] = ids[k];
                const Mat3 f = Mat3::Identity() + dt * embed3<dim>(p.L[idx[l]]);
                be[l] = f * p.be[idx[l]] * f.transpose();
            }
            symmetricEigen3Batch<Lanes>(be, lam, Q);
            // ε = ½ ln bᵉ in principal axes, vectorised across the batch.
            double eps[3][Lanes];
#pragma omp simd
            for (int l = 0; l < Lanes; ++l)
                for (int a = 0; a < 3; ++a)
                    eps[a][l] = 0.5 * fastLog(lam[l][a]);
            for (int l = 0; l < Lanes; ++l) {
                if (b * Lanes + l >= n) break;
                const Index i = idx[l];
                // τ = λ tr(ε) 1 + 2G ε [000 Eq. 4–5]; σ = τ/J with J = V/V⁰.
                const Vec3 e(eps[0][l], eps[1][l], eps[2][l]);
                const Vec3 tau = (lambda * e.sum()) * Vec3::Ones() + twoG * e;
                p.be[i] = be[l];
                p.stress[i] = fromEigen(Q[l], tau * (p.volume0[i] / p.volume[i]));
                if (!std::isfinite(p.stress[i].sum())) bad = std::min(bad, b * Lanes + l);
            }
        }
        return bad < n ? ids[bad] : -1;
    }
};

} // namespace mpm
