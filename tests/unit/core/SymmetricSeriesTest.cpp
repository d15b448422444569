// SPDX-License-Identifier: GPL-3.0-or-later
// The series for ½ ln b and exp A of symmetric 3×3 tensors, against a long-double
// eigen-decomposition of the same double matrices.
#include "core/SymmetricSeries.hpp"
#include "core/Types.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <random>

namespace mpm {
namespace {

using MatL = Eigen::Matrix<long double, 3, 3>;
constexpr int L = 8;

Mat3 fromLanes(const double (&s)[6][L], int l) {
    Mat3 m;
    m << s[0][l], s[3][l], s[4][l], s[3][l], s[1][l], s[5][l], s[4][l], s[5][l], s[2][l];
    return m;
}
void toLanes(const Mat3& m, double (&s)[6][L], int l) {
    s[0][l] = m(0, 0), s[1][l] = m(1, 1), s[2][l] = m(2, 2);
    s[3][l] = m(0, 1), s[4][l] = m(0, 2), s[5][l] = m(1, 2);
}

/// f(A) = Q f(Λ) Qᵀ in long double (64-bit mantissa): the reference, 2¹¹ × more precise.
template <class F> Mat3 reference(const Mat3& a, F f) {
    const Eigen::SelfAdjointEigenSolver<MatL> es(a.cast<long double>());
    Eigen::Matrix<long double, 3, 1> d = es.eigenvalues();
    for (int k = 0; k < 3; ++k)
        d[k] = f(d[k]);
    return (es.eigenvectors() * d.asDiagonal() * es.eigenvectors().transpose()).cast<double>();
}

/// A random rotation (about z if plane).
Mat3 rotation(std::mt19937_64& rng, bool plane) {
    std::normal_distribution<double> n(0.0, 1.0);
    Mat3 R = Mat3::Identity();
    if (plane) {
        const double t = n(rng);
        R.topLeftCorner<2, 2>() << std::cos(t), -std::sin(t), std::sin(t), std::cos(t);
    } else {
        R = Eigen::Quaterniond(n(rng), n(rng), n(rng), n(rng)).normalized().toRotationMatrix();
    }
    return R;
}

/// bᵉ = F Fᵀ of F = R diag(s) with stretches s = exp(N(0, σ)) and a random rotation R.
Mat3 randomB(std::mt19937_64& rng, double sigma, bool plane) {
    std::normal_distribution<double> n(0.0, 1.0);
    const Mat3 R = rotation(rng, plane);
    const Vec3 s(std::exp(sigma * n(rng)), std::exp(sigma * n(rng)), std::exp(sigma * n(rng)));
    Mat3 b = R * s.cwiseAbs2().asDiagonal() * R.transpose();
    b = Mat3(0.5 * (b + b.transpose())); // a copy: transpose() aliases b
    if (plane) b(0, 2) = b(2, 0) = b(1, 2) = b(2, 1) = 0.0;
    return b;
}

template <bool Plane> void checkHalfLog(unsigned seed) {
    std::mt19937_64 rng(seed);
    int decomposed = 0;
    for (int trial = 0; trial < 400; ++trial) {
        // Strains from 10⁻⁹ to 0.3, the same order in every lane of a batch.
        const double sigma = std::pow(10.0, -9.0 + 8.5 * (trial % 40) / 39.0);
        alignas(64) double b[6][L], eps[6][L];
        Mat3 B[L];
        for (int l = 0; l < L; ++l) {
            B[l] = randomB(rng, sigma, Plane);
            toLanes(B[l], b, l);
        }
        if (!halfLogLanes<L, Plane>(b, eps)) {
            ++decomposed;
            EXPECT_GT(sigma, 0.02) << "a small strain left to the decomposition";
            continue;
        }
        for (int l = 0; l < L; ++l) {
            // Of X = bᵉ − 1 (exact in double) and log1p: relative to the strain, however small.
            const Mat3 ref = reference(Mat3(B[l] - Mat3::Identity()),
                                       [](long double x) { return 0.5L * std::log1p(x); });
            const Mat3 got = fromLanes(eps, l);
            // Z is formed from b − 1: the error is relative to the strain however small it is.
            EXPECT_LE((got - ref).cwiseAbs().maxCoeff(), 4e-15 * ref.cwiseAbs().maxCoeff())
                << "sigma " << sigma << ", b =\n"
                << B[l];
            if (Plane) {
                EXPECT_TRUE(got(0, 2) == 0.0 && got(1, 2) == 0.0);
            }
        }
    }
    EXPECT_GT(decomposed, 0); // the largest strains take the decomposition
    EXPECT_LT(decomposed, 120);
}

TEST(SymmetricSeries, HalfLogMatchesLongDoubleDecomposition3D) {
    checkHalfLog<false>(1);
}

TEST(SymmetricSeries, HalfLogMatchesLongDoubleDecomposition2D) {
    checkHalfLog<true>(2);
}

TEST(SymmetricSeries, HalfLogOfIdentityIsExactlyZero) {
    alignas(64) double b[6][L] = {}, eps[6][L];
    for (int l = 0; l < L; ++l)
        b[0][l] = b[1][l] = b[2][l] = 1.0;
    ASSERT_TRUE((halfLogLanes<L, false>(b, eps)));
    for (int k = 0; k < 6; ++k)
        for (int l = 0; l < L; ++l)
            EXPECT_EQ(eps[k][l], 0.0);
}

TEST(SymmetricSeries, HalfLogRefusesLargeStretchAndNonFinite) {
    alignas(64) double b[6][L] = {}, eps[6][L];
    for (int l = 0; l < L; ++l)
        b[0][l] = b[1][l] = b[2][l] = 1.0;
    b[0][3] = 1.6; // z = 0.23 in one lane of eight
    EXPECT_FALSE((halfLogLanes<L, false>(b, eps)));
    b[0][3] = 1.4; // z = 0.167
    EXPECT_TRUE((halfLogLanes<L, false>(b, eps)));
    EXPECT_NEAR(eps[0][3], 0.5 * std::log(1.4), 1e-16);
    b[4][6] = std::nan("");
    EXPECT_FALSE((halfLogLanes<L, false>(b, eps)));
}

TEST(SymmetricSeries, PlaneVariantsTakeTheFullProductsForOutOfPlaneEntries) {
    // A plane-strain batch with one lane out of plane: the full products, the same bits.
    std::mt19937_64 rng(6);
    alignas(64) double b[6][L], e1[6][L], e2[6][L], x1[6][L], x2[6][L];
    for (int l = 0; l < L; ++l)
        toLanes(randomB(rng, 0.03, l != 5), b, l);
    ASSERT_NE(b[4][5], 0.0);
    ASSERT_TRUE((halfLogLanes<L, true>(b, e1)));
    ASSERT_TRUE((halfLogLanes<L, false>(b, e2)));
    expLanes<L, true>(e1, x1);
    expLanes<L, false>(e2, x2);
    for (int k = 0; k < 6; ++k)
        for (int l = 0; l < L; ++l) {
            EXPECT_EQ(e1[k][l], e2[k][l]);
            EXPECT_EQ(x1[k][l], x2[k][l]);
        }
}

TEST(SymmetricSeries, ArtanhTermsGrowWithTheNorm) {
    EXPECT_EQ(artanhTerms(0.0), 0);
    EXPECT_EQ(artanhTerms(1e-4), 3);
    EXPECT_LE(artanhTerms(HalfLogMaxSquaredNorm), 10);
    for (double r2 = 1e-12; r2 < 0.05; r2 *= 1.7) { // the bound holds at the chosen K
        const int k = artanhTerms(r2);
        EXPECT_LE(std::pow(r2, k + 1) / ((2 * k + 3) * (1.0 - r2)), 0x1p-53);
    }
}

template <bool Plane> void checkExp(unsigned seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> n(0.0, 1.0);
    for (int trial = 0; trial < 300; ++trial) {
        // |A| from 10⁻⁸ to about 10 (scaling and squaring beyond ½).
        const double sigma = std::pow(10.0, -8.0 + 8.0 * (trial % 30) / 29.0);
        alignas(64) double a[6][L], e[6][L];
        Mat3 A[L];
        for (int l = 0; l < L; ++l) {
            // A = ln bᵉ of randomB: R diag(2σ n) Rᵀ.
            const Mat3 R = rotation(rng, Plane);
            A[l] = R *
                   Vec3(2.0 * sigma * n(rng), 2.0 * sigma * n(rng), 2.0 * sigma * n(rng))
                       .asDiagonal() *
                   R.transpose();
            A[l] = Mat3(0.5 * (A[l] + A[l].transpose()));
            if (Plane) A[l](0, 2) = A[l](2, 0) = A[l](1, 2) = A[l](2, 1) = 0.0;
            toLanes(A[l], a, l);
        }
        expLanes<L, Plane>(a, e);
        for (int l = 0; l < L; ++l) {
            const Mat3 ref = reference(A[l], [](long double x) { return std::exp(x); });
            const Mat3 got = fromLanes(e, l);
            // exp is conditioned like e^|A|: relative to its largest entry, a few ulps per
            // squaring.
            EXPECT_LE((got - ref).cwiseAbs().maxCoeff(), 2e-14 * ref.cwiseAbs().maxCoeff())
                << "sigma " << sigma << ", A =\n"
                << A[l];
        }
    }
}

TEST(SymmetricSeries, ExpMatchesLongDoubleDecomposition3D) {
    checkExp<false>(3);
}

TEST(SymmetricSeries, ExpMatchesLongDoubleDecomposition2D) {
    checkExp<true>(4);
}

TEST(SymmetricSeries, ExpOfANonFiniteLaneEndsNonFinite) {
    // An infinite entry (a diverged point) must end the series and show in the result.
    alignas(64) double a[6][L] = {}, e[6][L];
    a[0][4] = std::numeric_limits<double>::infinity();
    a[3][1] = std::nan("");
    expLanes<L, false>(a, e);
    EXPECT_FALSE(std::isfinite(e[0][4]));
    EXPECT_FALSE(std::isfinite(e[3][1]));
}

TEST(SymmetricSeries, ExpInvertsHalfLog) {
    // bᵉ = exp 2ε of ε = ½ ln bᵉ: the round trip of a plastic point that does not flow.
    std::mt19937_64 rng(5);
    for (int trial = 0; trial < 100; ++trial) {
        alignas(64) double b[6][L], eps[6][L], twoEps[6][L], back[6][L];
        for (int l = 0; l < L; ++l)
            toLanes(randomB(rng, 0.03, false), b, l);
        ASSERT_TRUE((halfLogLanes<L, false>(b, eps)));
        for (int k = 0; k < 6; ++k)
            for (int l = 0; l < L; ++l)
                twoEps[k][l] = 2.0 * eps[k][l];
        expLanes<L, false>(twoEps, back);
        for (int k = 0; k < 6; ++k)
            for (int l = 0; l < L; ++l)
                EXPECT_NEAR(back[k][l], b[k][l], 2e-15);
    }
}

} // namespace
} // namespace mpm
