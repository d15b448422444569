// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/FastMath.hpp"
#include "core/SymmetricEigen.hpp"
#include "core/SymmetricSeries.hpp"
#include "materials/Material.hpp"

#include <algorithm>
#include <vector>

namespace mpm {

/// Lanes particles of a Hencky update in structure-of-arrays form, so that every step of the
/// update vectorises across particles (docs/architecture.md): the trial bᵉ = f bᵉ fᵀ
/// (f = 1 + Δt L), its Hencky strain ε = ½ ln bᵉ and the stress τ(ε)/J, all as tensors.
/// Symmetric tensors are kept as their six entries (00 11 22 01 02 12).
template <int Lanes> struct HenckyBatch {
    Index idx[Lanes];                ///< the particles; a short last batch repeats its last one
    alignas(64) double be[6][Lanes]; ///< trial bᵉ
    alignas(64) double jInv[Lanes];  ///< 1/J = V⁰/V

    /// Load ids[first …] (at most Lanes of them) and form the trial bᵉ.
    template <int dim>
    void trial(const Particles<dim>& p, const std::vector<Index>& ids, Index first, double dt) {
        const Index n = static_cast<Index>(ids.size());
        alignas(64) double f[9][Lanes];
        for (int l = 0; l < Lanes; ++l) {
            const Index i = ids[std::min(first + l, n - 1)];
            idx[l] = i;
            const Mat<dim>& L = p.L[i];
            for (int r = 0; r < 3; ++r)
                for (int s = 0; s < 3; ++s)
                    f[3 * r + s][l] =
                        (r == s ? 1.0 : 0.0) + (r < dim && s < dim ? dt * L(r, s) : 0.0);
            const Mat3& b = p.be[i];
            be[0][l] = b(0, 0), be[1][l] = b(1, 1), be[2][l] = b(2, 2);
            be[3][l] = b(0, 1), be[4][l] = b(0, 2), be[5][l] = b(1, 2);
            jInv[l] = p.volume0[i] / p.volume[i];
        }
        // bᵉ ← f bᵉ fᵀ: m = f bᵉ, then the upper triangle of m fᵀ.
#pragma omp simd
        for (int l = 0; l < Lanes; ++l) {
            const double B[3][3] = {{be[0][l], be[3][l], be[4][l]},
                                    {be[3][l], be[1][l], be[5][l]},
                                    {be[4][l], be[5][l], be[2][l]}};
            double m[3][3];
            for (int r = 0; r < 3; ++r)
                for (int s = 0; s < 3; ++s)
                    m[r][s] = f[3 * r][l] * B[0][s] + f[3 * r + 1][l] * B[1][s] +
                              f[3 * r + 2][l] * B[2][s];
            auto mft = [&](int r, int s) {
                return m[r][0] * f[3 * s][l] + m[r][1] * f[3 * s + 1][l] +
                       m[r][2] * f[3 * s + 2][l];
            };
            be[0][l] = mft(0, 0), be[1][l] = mft(1, 1), be[2][l] = mft(2, 2);
            be[3][l] = mft(0, 1), be[4][l] = mft(0, 2), be[5][l] = mft(1, 2);
        }
    }

    /// The trial Hencky strain ε = ½ ln bᵉ: by the artanh series (halfLogLanes) for the usual
    /// elastic strains, or, in a batch with a stretch beyond its range, by the Jacobi
    /// decomposition bᵉ = Q diag(λ) Qᵀ, ε = Q diag(½ ln λ) Qᵀ. Both are accurate to round-off.
    template <int dim> void strain(double (&eps)[6][Lanes]) const {
        constexpr bool plane = dim == 2;
        if (halfLogLanes<Lanes, plane>(be, eps)) return;
        alignas(64) double a[6][Lanes], q[9][Lanes];
        for (int k = 0; k < 6; ++k)
#pragma omp simd
            for (int l = 0; l < Lanes; ++l)
                a[k][l] = be[k][l];
        symmetricEigen3Lanes<Lanes, plane>(a, q); // plane bᵉ: one rotation
#pragma omp simd
        for (int l = 0; l < Lanes; ++l) {
            const double d[3] = {0.5 * fastLog(a[0][l]), 0.5 * fastLog(a[1][l]),
                                 0.5 * fastLog(a[2][l])};
            auto qdq = [&](int r, int s) {
                return q[3 * r][l] * q[3 * s][l] * d[0] + q[3 * r + 1][l] * q[3 * s + 1][l] * d[1] +
                       q[3 * r + 2][l] * q[3 * s + 2][l] * d[2];
            };
            eps[0][l] = qdq(0, 0), eps[1][l] = qdq(1, 1), eps[2][l] = qdq(2, 2);
            eps[3][l] = qdq(0, 1), eps[4][l] = qdq(0, 2), eps[5][l] = qdq(1, 2);
        }
    }

    /// σ = τ/J = (λ tr ε 1 + 2G ε)/J [000 Eq. 4–5] of every lane (one expression for the
    /// elastic and the plastic updates, so that both give the same bits for an elastic point).
    void stress(double lambda, double twoG, const double (&eps)[6][Lanes],
                double (&sig)[6][Lanes]) const {
#pragma omp simd
        for (int l = 0; l < Lanes; ++l) {
            const double tr = eps[0][l] + eps[1][l] + eps[2][l], iso = lambda * tr;
            for (int k = 0; k < 6; ++k)
                sig[k][l] = ((k < 3 ? iso : 0.0) + twoG * eps[k][l]) * jInv[l];
        }
    }

    /// The symmetric tensor of lane l as a matrix.
    static Mat3 tensor(const double (&s)[6][Lanes], int l) {
        Mat3 m;
        m << s[0][l], s[3][l], s[4][l], s[3][l], s[1][l], s[5][l], s[4][l], s[5][l], s[2][l];
        return m;
    }
};

} // namespace mpm
