#!/usr/bin/env python3
"""An elastic body meeting a rigid one: an independent finite-element reference (numpy only).

The spheropolygon tutorials diskCollision, diskDrop and rodImpact [001 §5.1, §5.4] ask how much
of an impact's kinetic energy an elastic body gives back. An ideal exchange gives back all of
it; a real elastic body keeps part as vibration (Gerl and Zippelius, Phys. Rev. E 59, 2361,
1999: collisions of elastic disks are inelastic at any finite v/c). This solves the same
continuum problems without MPM, so that the tutorials can compare with a known answer:

- plane strain, the solver's `linearElastic` law (hypoelastic, Jaumann rate of the Cauchy
  stress, forward Euler as src/materials/HypoelasticLaw.hpp) or a compressible neo-Hookean
  (`--law neoHookean`; both are linear elasticity at small strain; St Venant–Kirchhoff is not
  offered: it collapsed under the soft disk's contact), linear triangles, lumped masses,
  central differences (velocity Verlet);
- frictionless penalty contact on the boundary nodes, force k_c ℓ_i d_i along the normal (ℓ_i
  the node's share of the boundary, d_i its penetration), k_c = κ (λ + 2μ)/h: κ large is a
  rigid contact (κ = 100 penetrates ~1 % of an element's deformation; κ = 30 / 300 change the
  answers by ≤ 0.007, the tutorials' READMEs);
- `collision` (diskCollision): the disk R = 2 cm at v₀ = 2 m/s hits a free rigid disk of the
  same radius and mass at rest head-on; result v_B/v₀ after they separate (ideal: 1);
- `drop` (diskDrop): the disk arrives at v₀ on a fixed flat floor under g = 1000 m/s²; result
  the rebound energy E_r = ½ M v² + M g (y − y_c) of the centre of mass after separation (y_c
  its height at first contact) over ½ M v₀² (ideal: 1), as diskDrop/validate measures it;
- `rod` (rodImpact): the rod 100 mm × 4 mm at v₀ hits a free rigid capsule (core 4 mm, radius
  2 mm, the rod's mass) on its axis; result v_B/v₀ (1D wave theory: 1 − e⁻² = 0.865).

    elasticImpact.py collision|drop|rod [--material soft|hard] [--h 0.5e-3] [--kappa 100]
    import elasticImpact; r = elasticImpact.run("collision", "hard", h=0.5e-3)

Prints and returns the result, the contact time and the energy drift (KE + strain + penalty
[+ gravity], relative to the impact energy): a check of the integration for the hyperelastic
law; with the hypoelastic one the strain energy is the complementary energy the solver reports,
not a conserved potential.
"""
import argparse
import math
import sys

import numpy as np

RADIUS = 0.02  # m, the disk of [001 Table 1] read as cm (diskCollision README)
ROD = (0.1, 0.004)  # m, length and thickness of the rodImpact rod
CAPSULE = (0.004, 0.002)  # m, core length and radius of its rigid rod
DENSITY = 2000.0  # kg/m³
SPEED = 2.0  # m/s, the impact speed of all three tutorials
GRAVITY = 1000.0  # m/s², diskDrop (the paper's 10 cm/s² with time scaled by 1/100)
MATERIALS = {"soft": (500e3, 370e3), "hard": (5e6, 3.7e6)}  # K, G [Pa] [001 Table 1]


def disk_mesh(radius, rings):
    """Nodes (N, 2) and triangles (T, 3) of a disk centred at 0: centre, then ring k = 1..rings
    with 6k nodes at radius k R/rings; consecutive rings zipped by angle."""
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
    return np.vstack(nodes), np.array(tris)


def rect_mesh(length, thickness, h):
    """Nodes and triangles of the rectangle [−length, 0] × [−thickness/2, thickness/2] (its
    front face at x = 0), cells of about h split along alternating diagonals."""
    nx, ny = max(1, round(length / h)), max(2, round(thickness / h))
    xs, ys = np.linspace(-length, 0, nx + 1), np.linspace(-thickness / 2, thickness / 2, ny + 1)
    X = np.array([(x, y) for y in ys for x in xs])
    idx = lambda i, j: j * (nx + 1) + i  # noqa: E731
    tris = []
    for j in range(ny):
        for i in range(nx):
            a, b, c, d = idx(i, j), idx(i + 1, j), idx(i + 1, j + 1), idx(i, j + 1)
            tris += [[a, b, c], [a, c, d]] if (i + j) % 2 == 0 else [[a, b, d], [b, c, d]]
    return X, np.array(tris)


class Body:
    """The elastic body: reference mesh, lumped masses, boundary nodes with their share of the
    boundary length, internal forces and strain energy."""

    def __init__(self, X, tri, K, G, h, law="hypoelastic"):
        self.X, self.tri, self.h, self.law = X, tri, h, law
        e1, e2 = X[tri[:, 1]] - X[tri[:, 0]], X[tri[:, 2]] - X[tri[:, 0]]
        flip = e1[:, 0] * e2[:, 1] - e1[:, 1] * e2[:, 0] < 0
        tri[flip, 1], tri[flip, 2] = tri[flip, 2], tri[flip, 1].copy()
        self.lam, self.mu = K - 2.0 * G / 3.0, G  # plane strain: λ of the 3D moduli
        P = X[tri]
        D = np.stack([P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]], axis=2)  # columns: edges
        self.area = 0.5 * np.linalg.det(D)
        assert (self.area > 0).all()
        g12 = np.linalg.inv(D)  # rows: ∇ of the barycentric coordinates 1, 2
        self.grad = np.concatenate([-(g12[:, 0:1] + g12[:, 1:2]), g12], axis=1)  # (T, 3, 2)
        n = len(X)
        self.mass = np.bincount(tri.ravel(), np.repeat(DENSITY * self.area / 3, 3), minlength=n)
        # Boundary: the edges of one triangle only; each gives half its length to both ends.
        edges = np.sort(np.concatenate([tri[:, [0, 1]], tri[:, [1, 2]], tri[:, [2, 0]]]), axis=1)
        uniq, count = np.unique(edges, axis=0, return_counts=True)
        bnd = uniq[count == 1]
        half = 0.5 * np.linalg.norm(X[bnd[:, 0]] - X[bnd[:, 1]], axis=1)
        share = np.bincount(bnd.ravel(), np.repeat(half, 2), minlength=n)
        self.rim = np.nonzero(share)[0]
        self.rimLength = share[self.rim]
        self.sigma = np.zeros((len(tri), 3, 3))  # Cauchy stress (hypoelastic)

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
            raise FloatingPointError("elasticImpact: an element inverted")
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


def segment_push(x, a, b, radius):
    """Penetration of the points x into the capsule of core a–b and `radius`, and the unit
    normals pointing out of it."""
    ab = b - a
    s = np.clip(((x - a) @ ab) / (ab @ ab), 0.0, 1.0)
    r = x - (a + s[:, None] * ab)
    dist = np.linalg.norm(r, axis=1)
    return np.maximum(radius - dist, 0.0), r / np.maximum(dist, 1e-30)[:, None]


def run(case, material="hard", h=0.5e-3, kappa=100.0, law="hypoelastic", quiet=True):
    K, G = MATERIALS[material]
    if case in ("collision", "drop"):
        rings = max(2, round(RADIUS / h))
        d = Body(*disk_mesh(RADIUS, rings), K, G, RADIUS / rings, law)
        size = RADIUS
    elif case == "rod":
        d = Body(*rect_mesh(*ROD, h), K, G, h, law)
        size = ROD[0]
    else:
        raise SystemExit(f"elasticImpact: unknown case '{case}' (collision, drop, rod)")
    M = d.mass.sum()
    pModulus = d.lam + 2 * d.mu
    kc = kappa * pModulus / d.h  # N/m³: force per boundary length per penetration
    kNode = kc * d.rimLength
    cp = math.sqrt(pModulus / DENSITY)
    dt = 0.2 * min(d.h / cp, 2.0 / math.sqrt((kNode / d.mass[d.rim]).max()))
    n = len(d.X)
    u, v, g = np.zeros((n, 2)), np.zeros((n, 2)), np.zeros(2)
    free = case != "drop"  # the rigid body moves (collision, rod) or is the floor (drop)
    if case == "drop":
        v[:, 1] = -SPEED
        g[1] = -GRAVITY
        floor = -RADIUS  # touching at t = 0
    else:
        v[:, 0] = SPEED
        # touching at t = 0: the disk's centre 2R ahead, the capsule's core a ahead of the face
        xB, vB = np.array([2 * RADIUS if case == "collision" else CAPSULE[1], 0.0]), np.zeros(2)
    rim = d.rim

    def contact(x):
        """Forces on the boundary nodes, the force on the rigid body and the penalty energy."""
        f = np.zeros((len(rim), 2))
        if case == "collision":
            r = x[rim] - xB
            dist = np.linalg.norm(r, axis=1)
            pen = np.maximum(RADIUS - dist, 0.0)
            f = (kNode * pen / np.maximum(dist, 1e-30))[:, None] * r
        elif case == "rod":
            pen, normal = segment_push(x[rim], xB, xB + np.array([CAPSULE[0], 0.0]), CAPSULE[1])
            f = (kNode * pen)[:, None] * normal
        else:
            pen = np.maximum(floor - x[rim, 1], 0.0)
            f[:, 1] = kNode * pen
        return f, -f.sum(axis=0), 0.5 * np.sum(kNode * pen**2)

    def accel(u, vHalf=None):
        fi, es = d.forces(u, vHalf, dt)
        fc, fB, ec = contact(d.X + u)
        fi[rim] += fc
        return fi / d.mass[:, None] + g, fB, es, ec, np.any(fc != 0)

    a, fB, es, ec, touching = accel(u)
    e0 = 0.5 * M * SPEED**2
    com0 = np.sum(d.mass[:, None] * d.X, axis=0) / M
    t, tEnd, lastTouch, maxDrift = 0.0, None, 0.0, 0.0
    tMax = 40.0 * size / math.sqrt(d.mu / DENSITY)
    # Separated: no contact for 5 R/c_p (a boundary node that touches again after a ring would
    # show); for the drop at most half the time v₀/g the rebound takes to its apex.
    wait = 5 * RADIUS / cp if free else min(5 * RADIUS / cp, 0.5 * SPEED / GRAVITY)
    while t < tMax:
        v += 0.5 * dt * a
        u += dt * v
        if free:
            vB += 0.5 * dt * fB / M
            xB = xB + dt * vB
        a, fB, es, ec, touching = accel(u, v)
        v += 0.5 * dt * a
        if free:
            vB += 0.5 * dt * fB / M
        t += dt
        com = np.sum(d.mass[:, None] * (d.X + u), axis=0) / M
        ke = 0.5 * np.sum(d.mass * np.sum(v * v, axis=1))
        total = ke + es + ec - M * g[1] * (com[1] - com0[1])
        if free:
            total += 0.5 * M * vB @ vB
        maxDrift = max(maxDrift, abs(total - e0) / e0)
        if touching:
            lastTouch = t
        elif t > lastTouch + wait and lastTouch > 0:
            tEnd = t
            break
    vcom = np.sum(d.mass[:, None] * v, axis=0) / M
    if free:
        result = vB[0] / SPEED
    else:
        result = (0.5 * M * vcom @ vcom + M * GRAVITY * (com[1] - com0[1])) / e0
    r = dict(case=case, material=material, law=law, h=d.h, kappa=kappa, nodes=n,
             elements=len(d.tri), result=result, contact=lastTouch, drift=maxDrift, dt=dt,
             separated=tEnd is not None, vOverC=SPEED / cp)
    if not quiet:
        what = "E_r/E_d" if case == "drop" else "v_B/v0"
        print(f"{case} {material} {law}: h = {d.h * 1e3:.3f} mm, kappa = {kappa:g}, {n} nodes, "
              f"dt = {dt:.3g} s: {what} = {result:.4f}, contact {lastTouch * 1e3:.3f} ms, "
              f"energy drift {maxDrift:.1e}" + ("" if tEnd else " (not separated)"))
    return r


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("case", choices=["collision", "drop", "rod"])
    ap.add_argument("--material", choices=sorted(MATERIALS), default="hard")
    ap.add_argument("--h", type=float, default=0.5e-3, help="mesh size [m]")
    ap.add_argument("--kappa", type=float, default=100.0, help="k_c (λ + 2μ)⁻¹ h")
    ap.add_argument("--law", choices=["hypoelastic", "neoHookean"], default="hypoelastic")
    a = ap.parse_args()
    r = run(a.case, a.material, a.h, a.kappa, a.law, quiet=False)
    return 0 if r["separated"] else 1


if __name__ == "__main__":
    sys.exit(main())
