// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include "core/Types.hpp"

#include <cmath>

namespace mpm {

/// Eigen-decomposition A = Q diag(λ) Qᵀ of a symmetric 3×3 matrix by cyclic Jacobi rotations.
///
/// Branch-light and accurate to round-off even for repeated eigenvalues (where closed-form
/// solvers lose digits); typically 3–5 sweeps. Q is orthogonal to round-off, which is what
/// isotropic functions f(A) = Q f(λ) Qᵀ (Hencky strain, return maps) need.
inline void symmetricEigen3(const Mat3& A, Vec3& lambda, Mat3& Q) {
    double a[3][3] = {
        {A(0, 0), A(0, 1), A(0, 2)}, {A(0, 1), A(1, 1), A(1, 2)}, {A(0, 2), A(1, 2), A(2, 2)}};
    double q[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    const double scale = std::fabs(a[0][0]) + std::fabs(a[1][1]) + std::fabs(a[2][2]) +
                         std::fabs(a[0][1]) + std::fabs(a[0][2]) + std::fabs(a[1][2]);
    const double tol = 1e-30 + 1e-16 * scale;
    for (int sweep = 0; sweep < 12; ++sweep) {
        const double off = std::fabs(a[0][1]) + std::fabs(a[0][2]) + std::fabs(a[1][2]);
        if (off <= tol) break;
        for (int pq = 0; pq < 3; ++pq) {
            const int p = pq == 2 ? 1 : 0;
            const int r = pq == 0 ? 1 : 2;
            const double apq = a[p][r];
            if (std::fabs(apq) <= 1e-300) continue;
            const double theta = (a[r][r] - a[p][p]) / (2.0 * apq);
            const double t =
                (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
            const double c = 1.0 / std::sqrt(t * t + 1.0);
            const double s = t * c;
            // A ← Jᵀ A J for the rotation J in the (p, r) plane.
            for (int k = 0; k < 3; ++k) {
                const double akp = a[k][p], akr = a[k][r];
                a[k][p] = c * akp - s * akr;
                a[k][r] = s * akp + c * akr;
            }
            for (int k = 0; k < 3; ++k) {
                const double apk = a[p][k], ark = a[r][k];
                a[p][k] = c * apk - s * ark;
                a[r][k] = s * apk + c * ark;
            }
            for (int k = 0; k < 3; ++k) {
                const double qkp = q[k][p], qkr = q[k][r];
                q[k][p] = c * qkp - s * qkr;
                q[k][r] = s * qkp + c * qkr;
            }
        }
    }
    lambda = Vec3(a[0][0], a[1][1], a[2][2]);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            Q(i, j) = q[i][j];
}

namespace detail {

/// One Jacobi rotation in the (P, R) plane for all lanes; PR, KP, KR are the slots of a_pr,
/// a_kp, a_kr in the symmetric storage (a00 a11 a22 a01 a02 a12).
template <int Lanes, int P, int R, int PR, int KP, int KR>
inline void jacobiRotate(double (&a)[6][Lanes], double (&q)[9][Lanes]) {
#pragma omp simd
    for (int l = 0; l < Lanes; ++l) {
        const double apr = a[PR][l];
        const double d = a[R][l] - a[P][l];
        const double sd = d >= 0 ? 1.0 : -1.0;
        const double t =
            sd * 2.0 * apr / (std::fabs(d) + std::sqrt(d * d + 4.0 * apr * apr) + 1e-300);
        const double c = 1.0 / std::sqrt(t * t + 1.0);
        const double s = t * c;
        a[P][l] -= t * apr;
        a[R][l] += t * apr;
        a[PR][l] = 0.0;
        const double akp = a[KP][l], akr = a[KR][l];
        a[KP][l] = c * akp - s * akr;
        a[KR][l] = s * akp + c * akr;
        for (int row = 0; row < 3; ++row) {
            const double qp = q[3 * row + P][l], qr = q[3 * row + R][l];
            q[3 * row + P][l] = c * qp - s * qr;
            q[3 * row + R][l] = s * qp + c * qr;
        }
    }
}

} // namespace detail

/// symmetricEigen3 for `Lanes` matrices at once, the lanes in SIMD registers (AVX2: 4 doubles).
///
/// The same cyclic Jacobi rotations, written branch-free with
/// t = sgn(d) 2a_pq / (|d| + √(d² + 4a_pq²)), d = a_qq - a_pp (t = 0 when a_pq = 0), so that the
/// compiler vectorises across lanes; sweeps stop when every lane has converged. Each lane gives
/// the same result as it would alone, whatever its neighbours (extra sweeps leave a converged
/// lane unchanged to round-off only, so results are deterministic for a fixed batching).
///
/// `Plane` (2D updates): where every lane has a02 = a12 = 0 (plane strain), one rotation in the
/// (0, 1) plane diagonalises the batch, bit for bit the result of the full sweeps, whose other
/// rotations are then exact no-ops; a batch with any out-of-plane entry takes the full sweeps.
template <int Lanes, bool Plane = false>
void symmetricEigen3Lanes(double (&a)[6][Lanes], double (&q)[9][Lanes]);

template <int Lanes> void symmetricEigen3Batch(const Mat3* A, Vec3* lambda, Mat3* Q) {
    alignas(64) double a[6][Lanes];
    alignas(64) double q[9][Lanes];
    for (int l = 0; l < Lanes; ++l) {
        const Mat3& m = A[l];
        a[0][l] = m(0, 0), a[1][l] = m(1, 1), a[2][l] = m(2, 2);
        a[3][l] = m(0, 1), a[4][l] = m(0, 2), a[5][l] = m(1, 2);
    }
    symmetricEigen3Lanes<Lanes>(a, q);
    for (int l = 0; l < Lanes; ++l) {
        lambda[l] = Vec3(a[0][l], a[1][l], a[2][l]);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                Q[l](i, j) = q[3 * i + j][l];
    }
}

/// symmetricEigen3Batch on matrices already in lanes (structure of arrays): a holds
/// (a00 a11 a22 a01 a02 a12) of each lane on entry and the eigenvalues in a[0…2] on return
/// (a[3…5] ≈ 0); q gets the eigenvectors, q[3 i + j] = Q_ij (column j the j-th eigenvector).
template <int Lanes, bool Plane>
void symmetricEigen3Lanes(double (&a)[6][Lanes], double (&q)[9][Lanes]) {
    alignas(64) double tol[Lanes];
#pragma omp simd
    for (int l = 0; l < Lanes; ++l) {
        for (int k = 0; k < 9; ++k)
            q[k][l] = (k % 4 == 0) ? 1.0 : 0.0;
        tol[l] = 1e-30 + 1e-16 * (std::fabs(a[0][l]) + std::fabs(a[1][l]) + std::fabs(a[2][l]) +
                                  std::fabs(a[3][l]) + std::fabs(a[4][l]) + std::fabs(a[5][l]));
    }
    bool plane = Plane;
    if constexpr (Plane)
        for (int l = 0; l < Lanes; ++l)
            plane = plane && a[4][l] == 0.0 && a[5][l] == 0.0;
    for (int sweep = 0; sweep < (plane ? 1 : 12); ++sweep) {
        bool done = true;
        for (int l = 0; l < Lanes; ++l)
            done &= std::fabs(a[3][l]) + std::fabs(a[4][l]) + std::fabs(a[5][l]) <= tol[l];
        if (done) break;
        detail::jacobiRotate<Lanes, 0, 1, 3, 4, 5>(a, q);
        if (!plane) {
            detail::jacobiRotate<Lanes, 0, 2, 4, 3, 5>(a, q);
            detail::jacobiRotate<Lanes, 1, 2, 5, 3, 4>(a, q);
        }
    }
}

/// Q diag(d) Qᵀ.
inline Mat3 fromEigen(const Mat3& Q, const Vec3& d) {
    return Q * d.asDiagonal() * Q.transpose();
}

} // namespace mpm
