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
    double a[3][3] = {{A(0, 0), A(0, 1), A(0, 2)},
                      {A(0, 1), A(1, 1), A(1, 2)},
                      {A(0, 2), A(1, 2), A(2, 2)}};
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
            const double t = (theta >= 0 ? 1.0 : -1.0) /
                             (std::fabs(theta) + std::sqrt(theta * theta + 1.0));
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
        for (int j = 0; j < 3; ++j) Q(i, j) = q[i][j];
}

/// Q diag(d) Qᵀ.
inline Mat3 fromEigen(const Mat3& Q, const Vec3& d) { return Q * d.asDiagonal() * Q.transpose(); }

} // namespace mpm
