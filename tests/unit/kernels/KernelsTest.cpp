// SPDX-License-Identifier: GPL-3.0-or-later
// Property tests of the 1D shape functions and their tensor products.
#include "kernels/Kernels.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

namespace mpm {
namespace {

/// Call fn(kernel, name) for every kernel, GIMP with two particle half-widths.
template <class Fn> void forEachKernel(Fn&& fn) {
    fn(LinearKernel{}, "linear");
    GimpKernel g1;
    g1.l = 0.25;
    fn(g1, "gimp(l=0.25)");
    GimpKernel g2;
    g2.l = 0.125;
    fn(g2, "gimp(l=0.125)");
    fn(QuadraticBSplineKernel{}, "quadraticBSpline");
    fn(CubicBSplineKernel{}, "cubicBSpline");
}

/// Random coordinates (cell units) plus awkward ones: integers, half-integers, their neighbours
/// in floating point, and the GIMP branch points.
std::vector<double> samplePoints(unsigned seed, int count = 2000) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(1.0, 40.0);
    std::vector<double> xs(count);
    for (double& x : xs)
        x = u(rng);
    for (int i = 2; i < 5; ++i) {
        for (double f : {0.0, 0.5, 0.125, 0.25, 0.75, 0.875}) {
            const double x = i + f;
            xs.push_back(x);
            xs.push_back(std::nextafter(x, 0.0));
            xs.push_back(std::nextafter(x, 100.0));
        }
    }
    return xs;
}

/// Fractional positions frac(xh) at which some weight of the kernel is not smooth.
std::vector<double> kinks(const LinearKernel&) {
    return {0.0};
}
std::vector<double> kinks(const GimpKernel& k) {
    return {k.l, 1.0 - k.l};
}
std::vector<double> kinks(const QuadraticBSplineKernel&) {
    return {0.5};
}
std::vector<double> kinks(const CubicBSplineKernel&) {
    return {0.0};
}

template <class K> double distanceToKink(const K& k, double xh) {
    const double f = xh - std::floor(xh);
    double d = 1.0;
    for (double c : kinks(k)) {
        const double a = std::fabs(f - c);
        d = std::min(d, std::min(a, 1.0 - a));
    }
    return d;
}

/// Half-width of the support of N(d) in cell units.
double supportRadius(const LinearKernel&) {
    return 1.0;
}
double supportRadius(const GimpKernel& k) {
    return 1.0 + k.l;
}
double supportRadius(const QuadraticBSplineKernel&) {
    return 1.5;
}
double supportRadius(const CubicBSplineKernel&) {
    return 2.0;
}

/// Weight (or derivative) of grid node `node` at xh; zero outside the stencil.
template <class K> double weightAt(const K& k, double xh, int node, bool derivative = false) {
    double w[K::Width], dw[K::Width];
    const int base = k.eval(xh, w, dw);
    const int j = node - base;
    if (j < 0 || j >= K::Width) return 0.0;
    return derivative ? dw[j] : w[j];
}

TEST(Kernels, WeightsSumToOne) {
    forEachKernel([](const auto& k, const std::string& name) {
        using K = std::decay_t<decltype(k)>;
        SCOPED_TRACE(name);
        for (double xh : samplePoints(1)) {
            double w[K::Width], dw[K::Width];
            k.eval(xh, w, dw);
            double sum = 0.0;
            for (double wk : w)
                sum += wk;
            ASSERT_NEAR(sum, 1.0, 1e-14) << "xh = " << xh;
        }
    });
}

TEST(Kernels, DerivativesSumToZero) {
    forEachKernel([](const auto& k, const std::string& name) {
        using K = std::decay_t<decltype(k)>;
        SCOPED_TRACE(name);
        for (double xh : samplePoints(2)) {
            double w[K::Width], dw[K::Width];
            k.eval(xh, w, dw);
            double sum = 0.0;
            for (double d : dw)
                sum += d;
            ASSERT_NEAR(sum, 0.0, 1e-13) << "xh = " << xh;
        }
    });
}

TEST(Kernels, WeightsAreNonNegative) {
    forEachKernel([](const auto& k, const std::string& name) {
        using K = std::decay_t<decltype(k)>;
        SCOPED_TRACE(name);
        for (double xh : samplePoints(3)) {
            double w[K::Width], dw[K::Width];
            k.eval(xh, w, dw);
            for (int j = 0; j < K::Width; ++j)
                ASSERT_GE(w[j], 0.0) << "xh = " << xh << ", k = " << j;
        }
    });
}

TEST(Kernels, StencilWithinColouringExtent) {
    // BlockSort's colouring relies on every stencil lying in [floor(xh) - 1, floor(xh) + 2].
    forEachKernel([](const auto& k, const std::string& name) {
        using K = std::decay_t<decltype(k)>;
        SCOPED_TRACE(name);
        for (double xh : samplePoints(4)) {
            double w[K::Width], dw[K::Width];
            const int base = k.eval(xh, w, dw);
            const int fl = static_cast<int>(std::floor(xh));
            ASSERT_GE(base, fl - 1) << "xh = " << xh;
            ASSERT_LE(base + K::Width - 1, fl + 2) << "xh = " << xh;
        }
    });
}

TEST(Kernels, NoWeightOutsideStencil) {
    // The nodes just outside the stencil are beyond the kernel's support: nothing is lost.
    forEachKernel([](const auto& k, const std::string& name) {
        using K = std::decay_t<decltype(k)>;
        SCOPED_TRACE(name);
        for (double xh : samplePoints(5)) {
            double w[K::Width], dw[K::Width];
            const int base = k.eval(xh, w, dw);
            for (int node : {base - 1, base + K::Width})
                ASSERT_GE(std::fabs(xh - node), supportRadius(k)) << "xh = " << xh;
        }
    });
}

TEST(Kernels, DerivativeMatchesFiniteDifference) {
    const double delta = 1e-6;
    forEachKernel([delta](const auto& k, const std::string& name) {
        using K = std::decay_t<decltype(k)>;
        SCOPED_TRACE(name);
        int checked = 0;
        for (double xh : samplePoints(6)) {
            if (distanceToKink(k, xh) < 1e-4) continue;
            double w[K::Width], dw[K::Width];
            const int base = k.eval(xh, w, dw);
            for (int node = base - 1; node <= base + K::Width; ++node) {
                const double fd =
                    (weightAt(k, xh + delta, node) - weightAt(k, xh - delta, node)) / (2 * delta);
                const double exact = weightAt(k, xh, node, true);
                ASSERT_NEAR(fd, exact, 1e-7) << "xh = " << xh << ", node " << node;
            }
            ++checked;
        }
        EXPECT_GT(checked, 1500);
    });
}

TEST(Kernels, ReproduceLinearFields) {
    // Σ w_k x_k = xh and Σ dw_k x_k = 1 (the gradient of a linear field is exact).
    forEachKernel([](const auto& k, const std::string& name) {
        using K = std::decay_t<decltype(k)>;
        SCOPED_TRACE(name);
        for (double xh : samplePoints(7)) {
            double w[K::Width], dw[K::Width];
            const int base = k.eval(xh, w, dw);
            double x = 0.0, dx = 0.0;
            for (int j = 0; j < K::Width; ++j) {
                x += w[j] * (base + j);
                dx += dw[j] * (base + j);
            }
            ASSERT_NEAR(x, xh, 1e-13 * xh) << "xh = " << xh;
            ASSERT_NEAR(dx, 1.0, 1e-12) << "xh = " << xh;
        }
    });
}

template <class K> void expectConstantInertia(const K& k) {
    // Σ w_k (x_k - xh)² = D / h², the APIC inertia: constant for B-splines [000 Eq. 13].
    for (double xh : samplePoints(8)) {
        double w[K::Width], dw[K::Width];
        const int base = k.eval(xh, w, dw);
        double m2 = 0.0;
        for (int j = 0; j < K::Width; ++j)
            m2 += w[j] * (base + j - xh) * (base + j - xh);
        ASSERT_NEAR(m2, K::InertiaFactor, 1e-13) << "xh = " << xh;
    }
}

TEST(Kernels, QuadraticSecondMomentIsInertiaFactor) {
    expectConstantInertia(QuadraticBSplineKernel{});
}

TEST(Kernels, CubicSecondMomentIsInertiaFactor) {
    expectConstantInertia(CubicBSplineKernel{});
}

TEST(Kernels, KnownValues) {
    double w[4], dw[4];
    // Particle on a node: linear puts all weight there, B-splines are symmetric.
    EXPECT_EQ(LinearKernel{}.eval(3.0, w, dw), 3);
    EXPECT_DOUBLE_EQ(w[0], 1.0);
    EXPECT_DOUBLE_EQ(w[1], 0.0);
    EXPECT_EQ(QuadraticBSplineKernel{}.eval(3.0, w, dw), 2);
    EXPECT_DOUBLE_EQ(w[0], 0.125);
    EXPECT_DOUBLE_EQ(w[1], 0.75);
    EXPECT_DOUBLE_EQ(w[2], 0.125);
    EXPECT_DOUBLE_EQ(dw[1], 0.0);
    EXPECT_EQ(CubicBSplineKernel{}.eval(3.0, w, dw), 2);
    EXPECT_DOUBLE_EQ(w[0], 1.0 / 6.0); // nodes 2..5
    EXPECT_DOUBLE_EQ(w[1], 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(w[2], 1.0 / 6.0);
    EXPECT_DOUBLE_EQ(w[3], 0.0);
    GimpKernel g;
    g.l = 0.25;
    EXPECT_EQ(g.eval(3.0, w, dw), 2);
    EXPECT_DOUBLE_EQ(w[1], 1.0 - 0.25 / 2.0); // 1 - l/2 on the node
    EXPECT_DOUBLE_EQ(w[0], 0.0625);           // (1 + l - 1)² / (4l) = l/4
    EXPECT_DOUBLE_EQ(w[2], 0.0625);
    EXPECT_EQ(kernelNames().size(), 4u);
}

/// Tensor product in dim dimensions: weights sum to one, gradients to zero, and the gradient of
/// the linear field x reproduces the identity.
template <int dim, class K> void checkTensorProduct(const K& k, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> u(1.0, 30.0);
    constexpr int W = K::Width;
    int S = 1;
    for (int d = 0; d < dim; ++d)
        S *= W;
    for (int sample = 0; sample < 300; ++sample) {
        double xh[dim];
        double w[dim][W], dw[dim][W];
        int base[dim];
        for (int d = 0; d < dim; ++d) {
            xh[d] = u(rng);
            base[d] = k.eval(xh[d], w[d], dw[d]);
        }
        double sumW = 0.0;
        double sumGrad[dim] = {};
        double gradX[dim][dim] = {}; // Σ x_a ∂w/∂x_b
        for (int s = 0; s < S; ++s) {
            int idx[dim];
            int r = s;
            for (int d = 0; d < dim; ++d) {
                idx[d] = r % W;
                r /= W;
            }
            double wgt = 1.0;
            for (int d = 0; d < dim; ++d)
                wgt *= w[d][idx[d]];
            sumW += wgt;
            for (int b = 0; b < dim; ++b) {
                double g = 1.0;
                for (int d = 0; d < dim; ++d)
                    g *= d == b ? dw[d][idx[d]] : w[d][idx[d]];
                sumGrad[b] += g;
                for (int a = 0; a < dim; ++a)
                    gradX[a][b] += (base[a] + idx[a]) * g;
            }
        }
        ASSERT_NEAR(sumW, 1.0, 1e-14);
        for (int b = 0; b < dim; ++b) {
            ASSERT_NEAR(sumGrad[b], 0.0, 1e-13) << "component " << b;
            for (int a = 0; a < dim; ++a)
                ASSERT_NEAR(gradX[a][b], a == b ? 1.0 : 0.0, 1e-12) << a << ", " << b;
        }
    }
}

TEST(Kernels, TensorProductGradientSumsToZero2D) {
    forEachKernel([](const auto& k, const std::string& name) {
        SCOPED_TRACE(name);
        checkTensorProduct<2>(k, 11);
    });
}

TEST(Kernels, TensorProductGradientSumsToZero3D) {
    forEachKernel([](const auto& k, const std::string& name) {
        SCOPED_TRACE(name);
        checkTensorProduct<3>(k, 12);
    });
}

} // namespace
} // namespace mpm
