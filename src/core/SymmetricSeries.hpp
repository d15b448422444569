// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once

#include <algorithm>
#include <cmath>

// Isotropic tensor functions of symmetric 3×3 tensors by power series, for batches of `Lanes`
// tensors in structure-of-arrays form (entry k of lane l at [k][l], the entries in the order
// 00 11 22 01 02 12). Every function of one tensor commutes with it, so each product below is
// of two commuting symmetric tensors and is itself symmetric: only its upper triangle is formed.
// No eigen-decomposition, no branch per lane: the lane loops vectorise, and the number of terms
// is chosen once per batch from the largest norm in it (so a lane's last bit may depend on the
// batch it shares; batches follow the material lists, the same for any thread count and after
// a restart; terms per lane cost 10 %: docs/benchmarks.md).
//
// Cost against the batched Jacobi of SymmetricEigen.hpp (docs/benchmarks.md): ½ ln b of an
// elastic strain of 10⁻² is four products and one 3×3 inverse, about a tenth of the Jacobi's
// square roots and divisions.

namespace mpm {

/// A symmetric 3×3 tensor by its six entries.
struct Sym3 {
    double xx, yy, zz, xy, xz, yz;
};

/// AB for commuting symmetric A and B (then AB is symmetric): 18 multiply-adds. `Plane`: A and
/// B have xz = yz = 0 (plane strain), and so has AB: 7 multiply-adds.
template <bool Plane> inline Sym3 commutingProduct(const Sym3& a, const Sym3& b) {
    if constexpr (Plane)
        return {a.xx * b.xx + a.xy * b.xy,
                a.xy * b.xy + a.yy * b.yy,
                a.zz * b.zz,
                a.xx * b.xy + a.xy * b.yy,
                0.0,
                0.0};
    else
        return {a.xx * b.xx + a.xy * b.xy + a.xz * b.xz, a.xy * b.xy + a.yy * b.yy + a.yz * b.yz,
                a.xz * b.xz + a.yz * b.yz + a.zz * b.zz, a.xx * b.xy + a.xy * b.yy + a.xz * b.yz,
                a.xx * b.xz + a.xy * b.yz + a.xz * b.zz, a.xy * b.xz + a.yy * b.yz + a.yz * b.zz};
}

template <int Lanes> inline Sym3 loadSym(const double (&s)[6][Lanes], int l) {
    return {s[0][l], s[1][l], s[2][l], s[3][l], s[4][l], s[5][l]};
}
template <int Lanes> inline void storeSym(double (&s)[6][Lanes], int l, const Sym3& v) {
    s[0][l] = v.xx, s[1][l] = v.yy, s[2][l] = v.zz, s[3][l] = v.xy, s[4][l] = v.xz, s[5][l] = v.yz;
}

/// Every lane has xz = yz = 0.
template <int Lanes> inline bool isPlane(const double (&s)[6][Lanes]) {
    bool plane = true;
    for (int l = 0; l < Lanes; ++l)
        plane = plane && s[4][l] == 0.0 && s[5][l] == 0.0;
    return plane;
}

/// |A|² = A : A, the squared Frobenius norm (at least the squared spectral radius).
inline double squaredNorm(const Sym3& a) {
    return a.xx * a.xx + a.yy * a.yy + a.zz * a.zz +
           2.0 * (a.xy * a.xy + a.xz * a.xz + a.yz * a.yz);
}

/// The largest |Z|² for which halfLogLanes uses its series: |z| ≤ 0.2 for every eigenvalue
/// z = (λ − 1)/(λ + 1) of Z, i.e. principal stretches √λ within [0.82, 1.22] at least. Beyond it
/// the series would need more than 10 terms and the Jacobi is cheaper.
inline constexpr double HalfLogMaxSquaredNorm = 0.04;

/// Terms K of artanh Z = Σ_{j=0..K} Z^{2j+1}/(2j+1) for |Z|² ≤ r2 < 1: the smallest K whose
/// remainder, at most r^{2K+3}/((2K+3)(1 − r²)) for spectral radius r, is below 2⁻⁵³ r (round-off
/// of the leading term).
inline int artanhTerms(double r2) {
    int k = 0;
    for (double p = r2; p > 0x1p-53 * (2 * k + 3) * (1.0 - r2); p *= r2)
        ++k;
    return k;
}

/// ε = ½ ln b of `Lanes` symmetric positive definite tensors b, by
///   ½ ln b = artanh Z = Σ_j Z^{2j+1}/(2j+1),   Z = (b − 1)(b + 1)⁻¹,
/// (the eigenvalues z = (λ − 1)/(λ + 1) of Z lie in (−1, 1) and ½ ln λ = artanh z), with the
/// terms of artanhTerms for the batch's largest |Z|². Z is formed from b − 1, so a small strain
/// keeps its relative accuracy (the eigenvalues of b itself carry an absolute round-off of
/// 10⁻¹⁶). Returns false, eps unset, when some lane has |Z|² > HalfLogMaxSquaredNorm (or is not
/// finite): the caller decomposes that batch instead. `Plane`: plane strain is expected
/// (xz = yz = 0, the cheaper products); a batch with an out-of-plane entry takes the full ones.
template <int Lanes, bool Plane>
bool halfLogLanes(const double (&b)[6][Lanes], double (&eps)[6][Lanes]) {
    if constexpr (Plane)
        if (!isPlane(b)) return halfLogLanes<Lanes, false>(b, eps);
    alignas(64) double z[6][Lanes], z2[6][Lanes], r2[Lanes];
#pragma omp simd
    for (int l = 0; l < Lanes; ++l) {
        // X = b − 1 and (2 + X)⁻¹ by its cofactors.
        const Sym3 x{b[0][l] - 1.0, b[1][l] - 1.0, b[2][l] - 1.0, b[3][l], b[4][l], b[5][l]};
        const double m00 = 2.0 + x.xx, m11 = 2.0 + x.yy, m22 = 2.0 + x.zz;
        const double c00 = m11 * m22 - x.yz * x.yz, c11 = m00 * m22 - x.xz * x.xz;
        const double c22 = m00 * m11 - x.xy * x.xy, c01 = x.xz * x.yz - x.xy * m22;
        const double c02 = x.xy * x.yz - x.xz * m11, c12 = x.xy * x.xz - m00 * x.yz;
        const double inv = 1.0 / (m00 * c00 + x.xy * c01 + x.xz * c02);
        const Sym3 zl = commutingProduct<Plane>(
            x, Sym3{c00 * inv, c11 * inv, c22 * inv, c01 * inv, c02 * inv, c12 * inv});
        storeSym(z, l, zl);
        storeSym(z2, l, commutingProduct<Plane>(zl, zl));
        r2[l] = squaredNorm(zl);
    }
    bool ok = true;
    double r2max = 0.0;
    for (int l = 0; l < Lanes; ++l) {
        ok = ok && r2[l] <= HalfLogMaxSquaredNorm; // false for NaN
        r2max = std::max(r2max, r2[l]);
    }
    if (!ok) return false;
    const int terms = artanhTerms(r2max);
    // Horner in Z²: S = 1/(2K+1), S ← S Z² + 1/(2j+1) for j = K−1 … 0; ε = Z S.
    alignas(64) double s[6][Lanes];
    const double top = 1.0 / (2 * terms + 1);
#pragma omp simd
    for (int l = 0; l < Lanes; ++l)
        storeSym(s, l, Sym3{top, top, top, 0.0, 0.0, 0.0});
    for (int j = terms - 1; j >= 0; --j) {
        const double c = 1.0 / (2 * j + 1);
#pragma omp simd
        for (int l = 0; l < Lanes; ++l) {
            Sym3 v = commutingProduct<Plane>(loadSym(s, l), loadSym(z2, l));
            v.xx += c, v.yy += c, v.zz += c;
            storeSym(s, l, v);
        }
    }
#pragma omp simd
    for (int l = 0; l < Lanes; ++l)
        storeSym(eps, l, commutingProduct<Plane>(loadSym(z, l), loadSym(s, l)));
    return true;
}

/// exp A of `Lanes` symmetric tensors by scaling and squaring: the Taylor series
/// Σ_{k=0..K} (A/2ˢ)ᵏ/k! (Horner), squared s times, with s the fewest halvings that bring the
/// batch's largest |A| to ½ or below and K the fewest terms whose remainder,
/// at most rᴷ⁺¹ eʳ/(K+1)! for r = |A|/2ˢ, is below 2⁻⁵³. `Plane`: as for halfLogLanes.
template <int Lanes, bool Plane>
void expLanes(const double (&a)[6][Lanes], double (&out)[6][Lanes]) {
    if constexpr (Plane)
        if (!isPlane(a)) return expLanes<Lanes, false>(a, out);
    double r2max = 0.0;
    for (int l = 0; l < Lanes; ++l)
        r2max = std::max(r2max, squaredNorm(loadSym(a, l)));
    double r = std::sqrt(r2max);
    int squarings = 0;
    while (r > 0.5 && squarings < 64) {
        r *= 0.5;
        ++squarings;
    }
    // eʳ ≤ e^½ < 1.65 once r ≤ ½; at most 30 terms (r = ½ needs 17): a lane that is not finite
    // (r = ∞ after the capped halvings) ends with a non-finite result, not an endless loop.
    int terms = 0;
    for (double t = 1.0; t * 1.65 > 0x1p-53 && terms < 30;)
        t *= r / ++terms; // t = rᴷ/K!
    const double scale = std::ldexp(1.0, -squarings);
    // T = 1; T ← 1 + (A/2ˢ) T / k for k = K … 1.
#pragma omp simd
    for (int l = 0; l < Lanes; ++l)
        storeSym(out, l, Sym3{1.0, 1.0, 1.0, 0.0, 0.0, 0.0});
    for (int k = terms; k >= 1; --k) {
        const double c = scale / k;
#pragma omp simd
        for (int l = 0; l < Lanes; ++l) {
            const Sym3 al = loadSym(a, l);
            Sym3 v = commutingProduct<Plane>(
                Sym3{c * al.xx, c * al.yy, c * al.zz, c * al.xy, c * al.xz, c * al.yz},
                loadSym(out, l));
            v.xx += 1.0, v.yy += 1.0, v.zz += 1.0;
            storeSym(out, l, v);
        }
    }
    for (int q = 0; q < squarings; ++q)
#pragma omp simd
        for (int l = 0; l < Lanes; ++l) {
            const Sym3 v = loadSym(out, l);
            storeSym(out, l, commutingProduct<Plane>(v, v));
        }
}

} // namespace mpm
