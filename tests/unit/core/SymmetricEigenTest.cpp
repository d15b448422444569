// SPDX-License-Identifier: GPL-3.0-or-later
// Property tests of the Jacobi eigen-decomposition of symmetric 3×3 matrices.
#include "core/SymmetricEigen.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

namespace mpm {
namespace {

/// A random rotation (from a normalised Gaussian quaternion: uniform on SO(3)).
Mat3 randomRotation(std::mt19937_64& rng) {
    std::normal_distribution<double> n(0.0, 1.0);
    const Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
    return q.normalized().toRotationMatrix();
}

Mat3 randomSymmetric(std::mt19937_64& rng, double scale) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Mat3 a;
    for (int i = 0; i < 9; ++i)
        a(i) = scale * u(rng);
    return 0.5 * (a + a.transpose());
}

/// Decompose A and check Q orthogonal, A = Q diag(λ) Qᵀ, and (if given) the sorted eigenvalues.
void checkDecomposition(const Mat3& A, const Vec3* expected = nullptr) {
    Vec3 lambda;
    Mat3 Q;
    symmetricEigen3(A, lambda, Q);
    const double orth = (Q.transpose() * Q - Mat3::Identity()).cwiseAbs().maxCoeff();
    EXPECT_LE(orth, 1e-14) << "A =\n" << A;
    const double norm = std::max(A.norm(), 1e-300);
    const double err = (fromEigen(Q, lambda) - A).norm();
    EXPECT_LE(err, 1e-13 * norm) << "A =\n" << A;
    // Each column of Q is an eigenvector.
    for (int k = 0; k < 3; ++k)
        EXPECT_LE((A * Q.col(k) - lambda[k] * Q.col(k)).norm(), 1e-13 * norm) << "A =\n" << A;
    if (expected) {
        std::array<double, 3> got{lambda[0], lambda[1], lambda[2]};
        std::array<double, 3> want{(*expected)[0], (*expected)[1], (*expected)[2]};
        std::sort(got.begin(), got.end());
        std::sort(want.begin(), want.end());
        for (int k = 0; k < 3; ++k)
            EXPECT_NEAR(got[k], want[k], 1e-13 * std::max(1.0, std::fabs(want[k]))) << "A =\n" << A;
    }
}

TEST(SymmetricEigen, RandomSymmetricMatrices) {
    std::mt19937_64 rng(42);
    for (int trial = 0; trial < 2000; ++trial) {
        SCOPED_TRACE(trial);
        const double scale = std::pow(10.0, trial % 7 - 3); // 1e-3 … 1e3
        checkDecomposition(randomSymmetric(rng, scale));
    }
}

TEST(SymmetricEigen, KnownSpectrumUnderRandomRotation) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-2.0, 2.0);
    for (int trial = 0; trial < 500; ++trial) {
        const Vec3 lam(u(rng), u(rng), u(rng));
        const Mat3 R = randomRotation(rng);
        Mat3 A = R * lam.asDiagonal() * R.transpose();
        A = 0.5 * (A + A.transpose());
        checkDecomposition(A, &lam);
    }
}

TEST(SymmetricEigen, Identity) {
    const Vec3 ones = Vec3::Ones();
    checkDecomposition(Mat3::Identity(), &ones);
    Vec3 lambda;
    Mat3 Q;
    symmetricEigen3(Mat3::Identity(), lambda, Q);
    EXPECT_EQ(Q, Mat3::Identity()); // nothing to rotate
}

TEST(SymmetricEigen, RepeatedEigenvalues) {
    const Vec3 d(1.0, 1.0, 2.0);
    checkDecomposition(Mat3(d.asDiagonal()), &d);
    std::mt19937_64 rng(3);
    for (int trial = 0; trial < 200; ++trial) {
        const Mat3 R = randomRotation(rng);
        Mat3 A = R * d.asDiagonal() * R.transpose();
        A = 0.5 * (A + A.transpose());
        checkDecomposition(A, &d);
        // Nearly repeated (1 + 1e-12) and triple with noise.
        const Vec3 near(1.0, 1.0 + 1e-12, 2.0);
        Mat3 B = R * near.asDiagonal() * R.transpose();
        B = 0.5 * (B + B.transpose());
        checkDecomposition(B, &near);
        const Vec3 triple(5.0, 5.0, 5.0);
        Mat3 T = R * triple.asDiagonal() * R.transpose();
        T = 0.5 * (T + T.transpose());
        checkDecomposition(T, &triple);
    }
}

TEST(SymmetricEigen, TinyOffDiagonals) {
    for (double eps : {1e-8, 1e-14, 1e-20, 1e-200, 1e-310}) {
        SCOPED_TRACE(eps);
        Mat3 A;
        A << 1.0, eps, -eps, eps, 2.0, eps, -eps, eps, 3.0;
        checkDecomposition(A);
        // Tiny off-diagonals on a repeated eigenvalue.
        A << 1.0, eps, eps, eps, 1.0, eps, eps, eps, 1.0;
        checkDecomposition(A);
    }
}

TEST(SymmetricEigen, ZeroAndWideRange) {
    const Vec3 zero = Vec3::Zero();
    checkDecomposition(Mat3::Zero(), &zero);
    std::mt19937_64 rng(5);
    for (int trial = 0; trial < 100; ++trial) {
        // Eigenvalues spanning 16 decades (e.g. bᵉ of a nearly crushed particle): the
        // reconstruction is checked relative to the largest.
        const Vec3 lam(1e8, 1.0, -1e-8);
        const Mat3 R = randomRotation(rng);
        Mat3 A = R * lam.asDiagonal() * R.transpose();
        A = 0.5 * (A + A.transpose());
        checkDecomposition(A);
    }
}

// ---------------------------------------------------------------------------------------------
// Batched (SIMD across lanes) variant

/// A mix of hard cases for one batch: random, repeated, diagonal, zero, tiny off-diagonals.
std::vector<Mat3> mixedMatrices(std::mt19937_64& rng, int count) {
    std::vector<Mat3> m;
    for (int i = 0; i < count; ++i) {
        switch (i % 6) {
        case 0:
            m.push_back(randomSymmetric(rng, 1.0));
            break;
        case 1: {
            const Mat3 R = randomRotation(rng);
            Mat3 A = R * Vec3(1.0, 1.0, 2.0).asDiagonal() * R.transpose();
            m.push_back(0.5 * (A + A.transpose()));
            break;
        }
        case 2:
            m.push_back(Vec3(3.0, -1.0, 2.0).asDiagonal());
            break;
        case 3:
            m.push_back(i % 12 == 3 ? Mat3(Mat3::Zero()) : Mat3(Mat3::Identity()));
            break;
        case 4: {
            Mat3 A;
            A << 1.0, 1e-200, 1e-310, 1e-200, 1.0, -1e-20, 1e-310, -1e-20, 2.0;
            m.push_back(A);
            break;
        }
        default:
            m.push_back(randomSymmetric(rng, 1e4));
            break;
        }
    }
    return m;
}

template <int Lanes> void checkBatch(unsigned seed) {
    std::mt19937_64 rng(seed);
    for (int trial = 0; trial < 50; ++trial) {
        std::vector<Mat3> A = mixedMatrices(rng, Lanes);
        std::shuffle(A.begin(), A.end(), rng);
        Vec3 lambda[Lanes];
        Mat3 Q[Lanes];
        symmetricEigen3Batch<Lanes>(A.data(), lambda, Q);
        for (int l = 0; l < Lanes; ++l) {
            SCOPED_TRACE(l);
            const double norm = std::max(A[l].norm(), 1e-300);
            EXPECT_LE((Q[l].transpose() * Q[l] - Mat3::Identity()).cwiseAbs().maxCoeff(), 1e-14)
                << "A =\n"
                << A[l];
            EXPECT_LE((fromEigen(Q[l], lambda[l]) - A[l]).norm(), 1e-13 * norm) << "A =\n" << A[l];
            // Same spectrum as the scalar solver.
            Vec3 ref;
            Mat3 Qref;
            symmetricEigen3(A[l], ref, Qref);
            std::sort(ref.data(), ref.data() + 3);
            Vec3 got = lambda[l];
            std::sort(got.data(), got.data() + 3);
            EXPECT_LE((got - ref).cwiseAbs().maxCoeff(), 1e-13 * std::max(1.0, norm));
        }
    }
}

TEST(SymmetricEigen, BatchOfFourMatchesScalar) {
    checkBatch<4>(21);
}

TEST(SymmetricEigen, BatchOfEightMatchesScalar) {
    checkBatch<8>(22);
}

TEST(SymmetricEigen, BatchLaneIndependentOfNeighbours) {
    // A lane's result does not depend on what the other lanes hold beyond round-off.
    std::mt19937_64 rng(23);
    const Mat3 target = randomSymmetric(rng, 1.0);
    Vec3 l1[8], l2[8];
    Mat3 q1[8], q2[8];
    Mat3 a1[8], a2[8];
    for (int l = 0; l < 8; ++l) {
        a1[l] = Mat3::Identity(); // converged at once
        a2[l] = randomSymmetric(rng, 1e3);
    }
    a1[5] = a2[5] = target;
    symmetricEigen3Batch<8>(a1, l1, q1);
    symmetricEigen3Batch<8>(a2, l2, q2);
    EXPECT_LE((fromEigen(q1[5], l1[5]) - fromEigen(q2[5], l2[5])).norm(), 1e-14 * target.norm());
    EXPECT_LE((l1[5] - l2[5]).cwiseAbs().maxCoeff(), 1e-14 * target.norm());
    EXPECT_EQ(q1[0], Mat3::Identity());
}

TEST(SymmetricEigen, PlaneStrainRotationIsBitIdenticalToFullSweeps) {
    // Plane matrices (a02 = a12 = 0): the one (0, 1) rotation gives the bits of the full
    // sweeps, including batches where some lanes are diagonal already, batches all diagonal and
    // batches with an out-of-plane entry (which take the full sweeps).
    std::mt19937_64 rng(24);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int trial = 0; trial < 200; ++trial) {
        alignas(64) double a[6][8] = {}, b[6][8] = {};
        alignas(64) double qa[9][8], qb[9][8];
        for (int l = 0; l < 8; ++l) {
            const double scale = std::pow(10.0, 4.0 * u(rng));
            a[0][l] = scale * (1.0 + 0.5 * u(rng));
            a[1][l] = scale * (1.0 + 0.5 * u(rng));
            a[2][l] = scale * (1.0 + 0.5 * u(rng));
            const int kind = (trial + l) % 5;
            a[3][l] = kind == 0 ? 0.0 : kind == 1 ? 1e-20 * scale : scale * 0.3 * u(rng);
            if (trial % 7 == 0) a[3][l] = 0.0;      // the whole batch diagonal
            if (trial % 11 == 0) a[1][l] = a[0][l]; // repeated eigenvalue
        }
        if (trial % 13 == 0) a[4][3] = 0.1 * a[0][3]; // not plane: the full sweeps
        std::copy(&a[0][0], &a[0][0] + 48, &b[0][0]);
        symmetricEigen3Lanes<8, false>(a, qa);
        symmetricEigen3Lanes<8, true>(b, qb);
        for (int k = 0; k < 6; ++k)
            for (int l = 0; l < 8; ++l)
                ASSERT_EQ(std::memcmp(&a[k][l], &b[k][l], sizeof(double)), 0)
                    << "trial " << trial << ", a[" << k << "][" << l << "]";
        for (int k = 0; k < 9; ++k)
            for (int l = 0; l < 8; ++l)
                ASSERT_EQ(std::memcmp(&qa[k][l], &qb[k][l], sizeof(double)), 0)
                    << "trial " << trial << ", q[" << k << "][" << l << "]";
    }
}

} // namespace
} // namespace mpm
