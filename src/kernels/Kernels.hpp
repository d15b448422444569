// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <cmath>
#include <string>
#include <vector>

namespace mpm {

/// Shape functions of the background grid, one 1D factor per axis (tensor-product kernels).
///
/// Each kernel maps a particle coordinate in cell units, `xh = (x - origin) / h`, to the first
/// node of its stencil, `base`, and `Width` weights w_k = N(xh - (base + k)) with derivatives
/// dw_k = dN/dxh (multiply by 1/h for d/dx). Weights sum to 1 and derivatives to 0 for any xh.
/// The stencil of every kernel lies in [floor(xh) - 1, floor(xh) + 2], which the block
/// colouring of P2G relies on (4-cell blocks, 2^dim colours).

/// Linear hat function (classic MPM): N(d) = 1 - |d| for |d| < 1.
struct LinearKernel {
    static constexpr int Width = 2;
    static constexpr const char* Name = "linear";
    inline int eval(double xh, double* w, double* dw) const {
        const double fb = std::floor(xh);
        const double fx = xh - fb;
        w[0] = 1.0 - fx;
        w[1] = fx;
        dw[0] = -1.0;
        dw[1] = 1.0;
        return static_cast<int>(fb);
    }
};

/// Uniform GIMP (Bardenhagen & Kober 2004) with particle half-width l (cell units, l < 1/2):
///   N(d) = 1 - (d² + l²)/(2l)        |d| < l
///        = 1 - |d|                    l ≤ |d| < 1 - l
///        = (1 + l - |d|)² / (4l)      1 - l ≤ |d| < 1 + l.
/// Used with FLIP in [000 §2.3].
struct GimpKernel {
    static constexpr int Width = 3;
    static constexpr const char* Name = "gimp";
    double l = 0.25; ///< particle half-width / h
    inline int eval(double xh, double* w, double* dw) const {
        const double fb = std::floor(xh - 0.5);
        for (int k = 0; k < 3; ++k) {
            const double d = xh - (fb + k);
            const double a = std::fabs(d);
            const double s = d < 0 ? -1.0 : 1.0;
            if (a < l) {
                w[k] = 1.0 - (d * d + l * l) / (2.0 * l);
                dw[k] = -d / l;
            } else if (a < 1.0 - l) {
                w[k] = 1.0 - a;
                dw[k] = -s;
            } else if (a < 1.0 + l) {
                const double r = 1.0 + l - a;
                w[k] = r * r / (4.0 * l);
                dw[k] = -s * r / (2.0 * l);
            } else {
                w[k] = 0.0;
                dw[k] = 0.0;
            }
        }
        return static_cast<int>(fb);
    }
};

/// Quadratic B-spline [mpm88]: fx = xh - base ∈ [0.5, 1.5),
/// w = ½(1.5 - fx)², ¾ - (fx - 1)², ½(fx - 0.5)².
struct QuadraticBSplineKernel {
    static constexpr int Width = 3;
    static constexpr const char* Name = "quadraticBSpline";
    /// APIC inertia D_p = h²/4 · I (in cell units: 1/4) [000 Eq. 13].
    static constexpr double InertiaFactor = 0.25;
    inline int eval(double xh, double* w, double* dw) const {
        const double fb = std::floor(xh - 0.5);
        const double fx = xh - fb;
        const double a = 1.5 - fx, b = fx - 1.0, c = fx - 0.5;
        w[0] = 0.5 * a * a;
        w[1] = 0.75 - b * b;
        w[2] = 0.5 * c * c;
        dw[0] = -a;
        dw[1] = -2.0 * b;
        dw[2] = c;
        return static_cast<int>(fb);
    }
};

/// Cubic B-spline: N(d) = ½|d|³ - d² + ⅔ for |d| < 1, (2 - |d|)³/6 for 1 ≤ |d| < 2.
/// Used with APIC in [000 §2.3].
struct CubicBSplineKernel {
    static constexpr int Width = 4;
    static constexpr const char* Name = "cubicBSpline";
    /// APIC inertia D_p = h²/3 · I (in cell units: 1/3) [000 Eq. 13].
    static constexpr double InertiaFactor = 1.0 / 3.0;
    inline int eval(double xh, double* w, double* dw) const {
        const double fb = std::floor(xh) - 1.0;
        const double fx = xh - fb; // ∈ [1, 2)
        // d_k = fx - k: d0 ∈ [1,2), d1 ∈ [0,1), d2 ∈ (-1,0], d3 ∈ (-2,-1]
        const double r0 = 2.0 - fx; // 2 - |d0|
        const double d1 = fx - 1.0; // |d1|
        const double d2 = 2.0 - fx; // |d2|
        const double r3 = fx - 1.0; // 2 - |d3|
        w[0] = r0 * r0 * r0 / 6.0;
        w[1] = 0.5 * d1 * d1 * d1 - d1 * d1 + 2.0 / 3.0;
        w[2] = 0.5 * d2 * d2 * d2 - d2 * d2 + 2.0 / 3.0;
        w[3] = r3 * r3 * r3 / 6.0;
        dw[0] = -0.5 * r0 * r0;
        dw[1] = 1.5 * d1 * d1 - 2.0 * d1;
        dw[2] = -(1.5 * d2 * d2 - 2.0 * d2);
        dw[3] = 0.5 * r3 * r3;
        return static_cast<int>(fb);
    }
};

/// Names accepted by `kernel:` in system/mpmSchemes.
inline std::vector<std::string> kernelNames() {
    return {LinearKernel::Name, GimpKernel::Name, QuadraticBSplineKernel::Name,
            CubicBSplineKernel::Name};
}

} // namespace mpm
