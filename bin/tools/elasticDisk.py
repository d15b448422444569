#!/usr/bin/env python3
"""An elastic disk meeting a rigid body: an independent finite-element reference (numpy only).

The spheropolygon tutorials diskCollision and diskDrop [001 §5.1] ask how much of the impact's
kinetic energy an elastic disk gives back. An ideal exchange gives back all of it; a real elastic
disk keeps part as vibration (Gerl and Zippelius, Phys. Rev. E 59, 2361, 1999: collisions of
elastic disks are inelastic at any finite v/c). This solves the same continuum problem without
MPM, so that the tutorials can compare with a known answer:

- plane strain, the solver's `linearElastic` law (hypoelastic, Jaumann rate of the Cauchy
  stress, forward Euler as src/materials/HypoelasticLaw.hpp) or a compressible neo-Hookean
  (`--law neoHookean`; both are linear elasticity at small strain; St Venant–Kirchhoff is not
  offered: it collapsed under the soft disk's contact), linear triangles on a concentric mesh of the disk (ring k has 6k
  nodes, ring spacing R/n), lumped mass, central differences (velocity Verlet);
- frictionless penalty contact on the rim nodes, force k_c ℓ_i d_i along the normal (ℓ_i the
  node's share of the rim, d_i its penetration), k_c = κ (λ + 2μ)/h_m: κ large is a rigid
  contact (κ = 100 penetrates ~1 % of an element's deformation; κ = 30 / 100 / 300 are
  compared in the docs);
- `collision`: a free rigid disk of the same radius and mass at rest, hit head-on at v₀;
  result v_B/v₀ once they have separated (the ideal exchange: 1);
- `drop`: a fixed flat floor, the disk arriving at v₀ under gravity g; result the rebound
  energy E_r = ½ M v² + M g (y − y_c) of the centre of mass after separation (y_c its height
  at first contact) over ½ M v₀² (the ideal bounce: 1), as diskDrop/validate measures it.

    elasticDisk.py collision|drop [--material soft|hard] [--h 0.5e-3] [--kappa 100]
    import elasticDisk; r = elasticDisk.run("collision", "hard", h=0.5e-3)

Prints and returns the result, the contact time and the energy drift (KE + strain + penalty
[+ gravity], relative to the impact energy) as a check of the integration.
"""
import argparse
import math
import sys

import numpy as np

RADIUS = 0.02  # m, [001 Table 1] read as cm (diskCollision README)
DENSITY = 2000.0  # kg/m³
SPEED = 2.0  # m/s, the impact speed of both tutorials
GRAVITY = 1000.0  # m/s², diskDrop (the paper's 10 cm/s² with time scaled by 1/100)
MATERIALS = {"soft": (500e3, 370e3), "hard": (5e6, 3.7e6)}  # K, G [Pa] [001 Table 1]


def disk_mesh(radius, rings):
    """Nodes (N, 2) and CCW triangles (T, 3) of a disk: centre, then ring k = 1..rings with 6k
    nodes at radius k R/rings; consecutive rings zipped by angle. Also the rim's node ids."""
    nodes = [np.zeros((1, 2))]
    ids = [np.array([0])]
    angles = [np.array([0.0])]
    start = 1
    for k in range(1, rings + 1):
        a = 2 * math.pi * np.arange(6 * k) / (6 * k)
        nodes.append(radius * k / rings * np.column_stack([np.cos(a), np.sin(a)]))
        ids.append(np.arange(start, start + 6 * k))
        angles.append(a)
        start += 6 * k
    x = np.vstack(nodes)
    tris = [[0, int(ids[1][j]), int(ids[1][(j + 1) % 6])] for j in range(6)]
    for k in range(2, rings + 1):
        inner, outer, ai, ao = ids[k - 1], ids[k], angles[k - 1], angles[k]
        ni, no = len(inner), len(outer)
        i = j = 0
        while i < ni or j < no:
            nextInner = ai[(i + 1) % ni] + (2 * math.pi if i + 1 >= ni else 0.0)
            nextOuter = ao[(j + 1) % no] + (2 * math.pi if j + 1 >= no else 0.0)
            if j < no and (i >= ni or nextOuter <= nextInner):
                tris.append([int(inner[i % ni]), int(outer[j % no]), int(outer[(j + 1) % no])])
                j += 1
            else:
                tris.append([int(inner[i % ni]), int(outer[j % no]), int(inner[(i + 1) % ni])])
                i += 1
    t = np.array(tris)
    e1, e2 = x[t[:, 1]] - x[t[:, 0]], x[t[:, 2]] - x[t[:, 0]]
    flip = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0] < 0
    t[flip, 1], t[flip, 2] = t[flip, 2], t[flip, 1].copy()
    return x, t, ids[rings]


class Disk:
    """The elastic disk: reference mesh, lumped masses, internal forces and strain energy."""

    def __init__(self, K, G, h, law="hypoelastic"):
        rings = max(2, round(RADIUS / h))
        self.law = law
        self.X, self.tri, self.rim = disk_mesh(RADIUS, rings)
        self.lam, self.mu = K - 2.0 * G / 3.0, G  # plane strain: λ of the 3D moduli
        P = self.X[self.tri]  # (T, 3, 2)
        D = np.stack([P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]], axis=2)  # columns: edges
        self.area = 0.5 * np.linalg.det(D)
        assert (self.area > 0).all()
        Dinv = np.linalg.inv(D)  # rows: ∇ of the barycentric coordinates 1, 2
        g12 = Dinv  # (T, 2, 2): row a-1 is ∇N_a
        self.grad = np.concatenate([-(g12[:, 0:1] + g12[:, 1:2]), g12], axis=1)  # (T, 3, 2)
        n = len(self.X)
        self.mass = np.bincount(self.tri.ravel(), np.repeat(DENSITY * self.area / 3, 3),
                                minlength=n)
        self.rimLength = 2 * math.pi * RADIUS / len(self.rim)  # ℓ of each rim node
        self.h = RADIUS / rings
        self.sigma = np.zeros((len(self.tri), 3, 3))  # Cauchy stress (hypoelastic)

    def forces(self, u, v=None, dt=0.0):
        """Internal nodal forces (N, 2) and the strain energy [J/m] at displacements u.

        `hypoelastic` (the solver's `linearElastic`): the Cauchy stress of each element advanced
        by σ ← σ + Δt (ℂ : D + W σ − σ W) with L = ∇v on the current element (v the mid-step
        velocities), f_a = −a σ ∇N_a on the current element; energy the complementary
        (p²/(2K) + s:s/(4G)) a, as the solver reports it. `neoHookean`: ψ = μ/2 (tr C − 2)
        − μ ln J + λ/2 (ln J)², P = μ (F − F⁻ᵀ) + λ ln J F⁻ᵀ (plane strain, reference element).
        """
        x = (self.X + u)[self.tri]  # (T, 3, 2)
        Dm = np.stack([x[:, 1] - x[:, 0], x[:, 2] - x[:, 0]], axis=2)
        a = 0.5 * np.linalg.det(Dm)
        if (a <= 0).any():
            raise FloatingPointError("elasticDisk: an element inverted")
        n = len(self.X)
        if self.law == "neoHookean":
            F = np.eye(2) + np.einsum("tai,taj->tij", u[self.tri], self.grad)
            J = a / self.area
            FinvT = np.linalg.inv(F).transpose(0, 2, 1)
            lnJ = np.log(J)
            Pk = self.mu * (F - FinvT) + (self.lam * lnJ)[:, None, None] * FinvT
            fe = -self.area[:, None, None] * np.einsum("tij,taj->tai", Pk, self.grad)
            psi = (0.5 * self.mu * (np.sum(F * F, axis=(1, 2)) - 2) - self.mu * lnJ
                   + 0.5 * self.lam * lnJ**2)
            energy = np.sum(self.area * psi)
        else:
            gi = np.linalg.inv(Dm)
            grad = np.concatenate([-(gi[:, 0:1] + gi[:, 1:2]), gi], axis=1)  # current ∇N
            if v is not None and dt > 0:
                L = np.zeros((len(a), 3, 3))
                L[:, :2, :2] = np.einsum("tai,taj->tij", v[self.tri], grad)
                D = 0.5 * (L + L.transpose(0, 2, 1))
                W = 0.5 * (L - L.transpose(0, 2, 1))
                trD = np.trace(D, axis1=1, axis2=2)
                s = self.sigma
                rate = (self.lam * trD[:, None, None] * np.eye(3) + 2 * self.mu * D
                        + W @ s - s @ W)
                self.sigma = s + dt * rate
            s = self.sigma
            fe = -a[:, None, None] * np.einsum("tij,taj->tai", s[:, :2, :2], grad)
            p = np.trace(s, axis1=1, axis2=2) / 3
            dev = s - p[:, None, None] * np.eye(3)
            K = self.lam + 2 * self.mu / 3
            energy = np.sum(a * (p**2 / (2 * K) + np.sum(dev * dev, axis=(1, 2)) / (4 * self.mu)))
        idx = self.tri.ravel()
        f = np.column_stack([np.bincount(idx, fe[:, :, d].ravel(), minlength=n) for d in (0, 1)])
        return f, energy


def run(case, material="hard", h=0.5e-3, kappa=100.0, law="hypoelastic", quiet=True):
    K, G = MATERIALS[material]
    d = Disk(K, G, h, law)
    M = d.mass.sum()
    pModulus = d.lam + 2 * d.mu
    kc = kappa * pModulus / d.h  # N/m³: force per rim length per penetration
    kNode = kc * d.rimLength
    cp = math.sqrt(pModulus / DENSITY)
    mRim = d.mass[d.rim].min()
    dt = 0.2 * min(d.h / cp, 2.0 / math.sqrt(kNode / mRim))
    n = len(d.X)
    u = np.zeros((n, 2))
    v = np.zeros((n, 2))
    g = np.zeros(2)
    if case == "collision":
        v[:, 0] = SPEED
        xB, vB = np.array([2 * RADIUS, 0.0]), np.zeros(2)  # touching at t = 0
    elif case == "drop":
        v[:, 1] = -SPEED
        g[1] = -GRAVITY
        floor = -RADIUS  # touching at t = 0
    else:
        raise SystemExit(f"elasticDisk: unknown case '{case}' (collision, drop)")
    rim = d.rim

    def contact(x):
        """Forces on the rim nodes, the force on the rigid body and the penalty energy."""
        f = np.zeros((len(rim), 2))
        if case == "collision":
            r = x[rim] - xB
            dist = np.linalg.norm(r, axis=1)
            pen = np.maximum(RADIUS - dist, 0.0)
            f = (kNode * pen / np.maximum(dist, 1e-30))[:, None] * r
        else:
            pen = np.maximum(floor - x[rim, 1], 0.0)
            f[:, 1] = kNode * pen
        return f, -f.sum(axis=0), 0.5 * kNode * np.sum(pen**2)

    def accel(u, vHalf=None):
        fi, es = d.forces(u, vHalf, dt)
        fc, fB, ec = contact(d.X + u)
        fi[rim] += fc
        return fi / d.mass[:, None] + g, fB, es, ec, np.any(fc != 0)

    a, fB, es, ec, touching = accel(u)
    e0 = 0.5 * M * SPEED**2
    ycom0 = 0.0
    t, tEnd, lastTouch, maxDrift, trace = 0.0, None, 0.0, 0.0, []
    tMax = 40.0 * RADIUS / math.sqrt(d.mu / DENSITY)
    # Separated: no contact for 5 R/c_p (a rim node that touches again after a ring would show);
    # for the drop at most half the time v₀/g the rebound takes to its apex.
    wait = 5 * RADIUS / cp if case == "collision" else min(5 * RADIUS / cp, 0.5 * SPEED / GRAVITY)
    while t < tMax:
        v += 0.5 * dt * a
        u += dt * v
        if case == "collision":
            vB += 0.5 * dt * fB / M
            xB = xB + dt * vB
        a, fB, es, ec, touching = accel(u, v)
        v += 0.5 * dt * a
        if case == "collision":
            vB += 0.5 * dt * fB / M
        t += dt
        com = np.sum(d.mass[:, None] * (d.X + u), axis=0) / M
        ke = 0.5 * np.sum(d.mass * np.sum(v * v, axis=1))
        total = ke + es + ec - M * g[1] * (com[1] - ycom0)
        if case == "collision":
            total += 0.5 * M * vB @ vB
        maxDrift = max(maxDrift, abs(total - e0) / e0)
        trace.append((t, com[0], com[1], np.linalg.norm(fB), ke, es))
        if touching:
            lastTouch = t
        elif t > lastTouch + wait and lastTouch > 0:
            tEnd = t
            break
    vcom = np.sum(d.mass[:, None] * v, axis=0) / M
    if case == "collision":
        result = vB[0] / SPEED
    else:
        result = (0.5 * M * vcom @ vcom + M * GRAVITY * (com[1] - ycom0)) / e0
    r = dict(case=case, material=material, law=law, h=d.h, kappa=kappa, nodes=n, elements=len(d.tri),
             result=result, contact=lastTouch, drift=maxDrift, dt=dt, separated=tEnd is not None,
             vOverC=SPEED / cp, trace=np.array(trace))
    if not quiet:
        what = "v_B/v0" if case == "collision" else "E_r/E_d"
        print(f"{case} {material} {law}: h = {d.h * 1e3:.3f} mm, kappa = {kappa:g}, {n} nodes, "
              f"dt = {dt:.3g} s: {what} = {result:.4f}, contact {lastTouch * 1e3:.3f} ms, "
              f"energy drift {maxDrift:.1e}" + ("" if tEnd else " (not separated)"))
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case", choices=["collision", "drop"])
    ap.add_argument("--material", choices=sorted(MATERIALS), default="hard")
    ap.add_argument("--h", type=float, default=0.5e-3, help="ring spacing [m]")
    ap.add_argument("--kappa", type=float, default=100.0, help="k_c (λ + 2μ)⁻¹ h")
    ap.add_argument("--law", choices=["hypoelastic", "neoHookean"], default="hypoelastic")
    a = ap.parse_args()
    r = run(a.case, a.material, a.h, a.kappa, a.law, quiet=False)
    return 0 if r["separated"] else 1


if __name__ == "__main__":
    sys.exit(main())
