#!/usr/bin/python3
"""Parameters and analytic answers of the spherical-compaction tutorial [002 §2.2–2.3, §4.1].

A linear-viscoelastic ball (3D) or cylinder (2D, plane strain) of radius a, bulk viscosity ϑ
only, given its fundamental breathing mode v = −A_r R(k r) r̂ (R = j₁, k a = π in 3D; R = J₁,
k a = j₀,₁ = 2.405 in 2D, both for λ/G → ∞). Separation of variables [002 Eq. 20–30] gives
T̈ + ξ̃ Ṫ + ω₀² T = 0 with ξ̃ = k² ϑ/ρ, ω₀ = k c_p, c_p = √(M/ρ), and the damping ratio
ζ = ξ̃/(2ω₀) = k ϑ/(2√(M ρ)) (sphere: ζ = π ϑ̃/2, ϑ̃ = ϑ/(a √(M ρ)) [002 Eq. 36]). The body
separates when the total stress (∝ the acceleration) returns to zero, at t_c, and flies off at
−ℰ v(0), ℰ = continuumRestitution(ζ) [002 Eq. 37] (real form, derived in docs/viscoelastic.md
§1; velocityRatio() below finds t_c and ℰ numerically without it).

    ./parameters.py theta DIM THETA_TILDE    prints ϑ [Pa s] for the run (Allrun)
    ./parameters.py table                    prints ℰ, t_c for the tutorial's ϑ̃
"""
import math
import sys

import numpy as np

A = 0.5                           # m, radius
LAMBDA = 1.0e11                   # Pa, Lamé λ (λ/G = 10⁷)
G = 1.0e4                         # Pa, shear modulus
RHO = 2500.0 * math.pi / 6.0      # kg/m3, ρ₀ = φ₀ ρ_s
M = LAMBDA + 2.0 * G              # Pa, P-wave modulus
CP = math.sqrt(M / RHO)           # m/s
AMPLITUDE = 1.0e-3                # m/s, A_r
THETA_TILDES = (0.0, 0.1, 0.5, 1.0, 5.0)   # [002 Fig. 6b]
J01 = 2.404825557695773           # first zero of J₀


def wavenumber(dim):
    """k [1/m] of the breathing mode in the incompressible limit [002 Eq. 26]."""
    return (math.pi if dim == 3 else J01) / A


def zeta(thetaTilde):
    """Damping ratio ζ = π ϑ̃/2 (the 2D runs set ϑ so that ζ is the sphere's)."""
    return 0.5 * math.pi * thetaTilde


def viscosity(dim, thetaTilde):
    """ϑ [Pa s] giving ζ = π ϑ̃/2: ϑ = 2 ζ √(M ρ)/k (3D: ϑ̃ a √(M ρ))."""
    return 2.0 * zeta(thetaTilde) * math.sqrt(M * RHO) / wavenumber(dim)


def restitution(z):
    """ℰ(ζ) [002 Eq. 37], real form; the same formula as continuumRestitution()."""
    if z < 1.0:
        return math.exp(-z * (math.pi - 2.0 * math.asin(z)) / math.sqrt(1.0 - z * z))
    if z == 1.0:
        return math.exp(-2.0)
    r = math.sqrt(z * z - 1.0)
    return math.exp(-(2.0 * z / r) * math.atanh(r / z))


def approximateRestitution(thetaTilde):
    """ℰ ≈ exp(−2.5 ϑ̃^(2/π)) [002 Eq. 38]."""
    return math.exp(-2.5 * thetaTilde ** (2.0 / math.pi))


def velocityRatio(dim, thetaTilde, t):
    """v_r(r, t)/v_r(r, 0) of the damped mode (any r): the solution of T̈ + ξ̃Ṫ + ω₀²T = 0
    with T(0) = 0 until the acceleration first vanishes (t_c), then constant. Returns
    (ratio array, t_c)."""
    w0 = wavenumber(dim) * CP
    z = zeta(thetaTilde) * (1.0 + 1e-12) if thetaTilde > 0 else 0.0   # no exact ζ = 1
    wd = w0 * np.sqrt(complex(1.0 - z * z))                         # ω̃ (imaginary if ζ > 1)

    def ratio(s):
        s = np.asarray(s, dtype=float)
        return np.real(np.exp(-z * w0 * s) * (np.cos(wd * s) - z * w0 / wd * np.sin(wd * s)))

    # acceleration ∝ d(ratio)/dt = e^{−ζω₀t}(−(ω̃ + ζ²ω₀²/ω̃) sin ω̃t + ...): find its first
    # zero numerically (t > 0) on a fine grid and refine by bisection
    s = np.linspace(0.0, 4.0 * math.pi / w0, 200001)
    acc = np.gradient(ratio(s), s)
    i = np.argmax(np.sign(acc[1:]) != np.sign(acc[1]))
    lo, hi = s[i], s[i + 2]
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        h = 1e-6 / w0
        if np.sign((ratio(mid + h) - ratio(mid - h))) == np.sign(acc[1]):
            lo = mid
        else:
            hi = mid
    tc = 0.5 * (lo + hi)
    t = np.asarray(t, dtype=float)
    return np.where(t < tc, ratio(np.minimum(t, tc)), ratio(tc)), tc


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "theta":
        print(repr(viscosity(int(sys.argv[2]), float(sys.argv[3]))))
    elif len(sys.argv) == 2 and sys.argv[1] == "table":
        print(" ϑ̃      ζ       ℰ(37)    ℰ(38)   t_c c_p/a   −v(t_c)/v(0)")
        for tt in THETA_TILDES:
            v, tc = velocityRatio(3, tt, [1.0])
            print(f"{tt:5g}  {zeta(tt):6.4f}  {restitution(zeta(tt)):.4f}  "
                  f"{approximateRestitution(tt):.4f}  {tc * CP / A:8.4f}  {-v[0]:.4f}")
    else:
        sys.exit(__doc__)
