"""The parameter studies of the granular-impact issue on glassDrop40 [000 §4.2, §5].

Base case: tutorials/granularImpact/glassDrop40Coarse (glass sphere D = 38.34 mm, 40 cm drop,
h = 5 mm, 59 114 points, GIMP + FLIP 0.995, Drucker-Prager phi = 30 deg with trans-phase,
barrier coupling, deltaT = 2e-5 s). Every study ends at T_END = 0.08 s unless noted
(resolution: h = 3 mm and APIC at h = 4 mm to 0.06 s, compared at 0.06 s; Young's modulus:
0.04 s; coupling: 0.015 s; time step: 0.02 s). The points are written every 5 ms (splash).
Identical variants of different studies run once (runStudy.py links them).

check(study, results) returns [(label, state, detail)], state one of
  "ok"             the trend (or property) holds,
  "not reproduced" a trend of the paper that the runs do not show (reported, not an error),
  "VIOLATION"      a hard property is broken (barrier penetration > 0, NaN written,
                   no convergence with h): runStudy.py / report.py exit non-zero.
"""
import math
import re

import numpy as np

BASE = "tutorials/granularImpact/glassDrop40Coarse"
D_GLASS = 2 * 0.01917

# Material constants of the base case (for the time-step and coupling numbers).
RHO, E0, NU = 1280.0, 1.0e6, 0.2
M0 = E0 * (1 - NU) / ((1 + NU) * (1 - 2 * NU))   # P-wave modulus [Pa]
C0 = math.sqrt(M0 / RHO)                          # P-wave speed [m/s] (29.46)
H0 = 0.005
V_GLASS = 2.8014                                  # sqrt(2 g 0.4)
V_STEEL60 = math.sqrt(2 * 9.81 * 0.6)             # 3.431 m/s
DT_CRIT = H0 / (C0 + V_GLASS)                     # 1.55e-4 s
VP = H0 ** 3 / 4
MP = RHO * VP
K_CRIT = 4 * MP * math.pi ** 2 * C0 ** 2 / H0 ** 2   # default linear-spring stiffness [N/m]

CD, MAT, RB, GRID, PART, SCH = ("system/controlDict", "constant/materials",
                                "constant/rigidBodies", "constant/grid",
                                "constant/particles", "system/mpmSchemes")

T_END = 0.08
COMMON = [(CD, "endTime", T_END), (CD, "writeInterval", 0.005)]
APIC = [(SCH, "kernel", "cubicBSpline"), (SCH, "transfer", "apic")]


def grid(h, lx, ly, lz_sand, top, x_c, y_c):
    """Box of whole cells of size h, sand lz_sand deep, the sphere 0.5 mm above it."""
    return [(GRID, "cellSize", h), (GRID, "bounds.max", [lx, ly, top]),
            (PART, "sand.region.max", [lx, ly, lz_sand]),
            (RB, "sphere.position", [x_c, y_c, round(lz_sand + 0.01917 + 0.0005, 6)]),
            (CD, "functions.depth.surface", lz_sand)]


H4 = grid(0.004, 0.224, 0.10, 0.08, 0.16, 0.112, 0.05)          # 56 x 25 x 40 cells
H3 = grid(0.003, 0.225, 0.099, 0.081, 0.162, 0.1125, 0.0495)    # 75 x 33 x 54 cells, 8.1 cm sand


def v(name, overrides=(), **params):
    return {"name": name, "overrides": list(overrides), "params": params}


def steel(speed, coupling):
    return [(CD, "endTime", 0.015), (CD, "functions.gap.writeInterval", 1),
            (RB, "sphere.shape.radius", 0.02), (RB, "sphere.density", 7780.0),
            (RB, "sphere.position", [0.1125, 0.05, 0.1005]),
            (RB, "sphere.velocity", [0, 0, -round(speed, 5)]),
            (RB, "sphere.coupling", coupling)]


def dt_variant(scheme, ratio):
    return v(f"{scheme}_r{ratio:g}",
             [(CD, "endTime", T_DT), (CD, "deltaT", float(f"{ratio * DT_CRIT:.6g}")),
              (CD, "allowUnstableDeltaT", True)] + (APIC if scheme == "apic" else []),
             scheme=scheme, ratio=ratio, deltaT=float(f"{ratio * DT_CRIT:.6g}"))


def e_variant(E):
    """Adaptive step, Courant 0.5, capped at the paper's 2e-5 s: 2e-5 s for E = 1 and 10 MPa,
    ~8.4e-6 s for 100 MPa; endTime 0.04 s."""
    return v(f"E{E:g}MPa", [(MAT, "sand.E", E * 1e6), (CD, "endTime", 0.04),
                            (CD, "adjustTimeStep", True), (CD, "maxCo", 0.5),
                            (CD, "maxDeltaT", 2.0e-5)], E=E)


MUI = [(MAT, "sand", {"type": "muI", "density": 1280.0, "E": 1.0e6, "nu": 0.2,
                      "frictionAngle": 30.0, "frictionAngle2": 34.0, "I0": 0.278,
                      "grainDiameter": 0.25e-3, "grainDensity": 2650.0, "transPhase": True})]
SPEEDS = (1, 2, 5, 10)
COUPLINGS = {"barrier": {"type": "barrier"}, "spring": {"type": "linearSpring"},
             "softSpring": {"type": "linearSpring", "stiffness": float(f"{K_CRIT / 100:.4g}")}}
T_DT = 0.02        # end of the time-step runs: the depth is compared there
RATIOS = (0.1, 0.3, 0.5, 0.8, 1.0, 1.5, 3.0)

STUDIES = {
    "resolution": {"base": BASE, "common": COMMON, "variants": [
        v("h5", h=5, scheme="flip"),
        v("h4", H4, h=4, scheme="flip"),
        v("h3", H3 + [(CD, "endTime", 0.06)], h=3, scheme="flip"),
        v("apic_h5", APIC, h=5, scheme="apic"),
        v("apic_h4", H4 + APIC + [(CD, "endTime", 0.06)], h=4, scheme="apic")]},
    "youngsModulus": {"base": BASE, "common": COMMON,
                      "variants": [e_variant(1), e_variant(10), e_variant(100)]},
    "frictionAngle": {"base": BASE, "common": COMMON, "variants": [
        v("phi30", phi=30), v("phi32", [(MAT, "sand.frictionAngle", 32.0)], phi=32),
        v("phi34", [(MAT, "sand.frictionAngle", 34.0)], phi=34)]},
    "muI": {"base": BASE, "common": COMMON, "variants": [
        v("DP30", model="Drucker-Prager 30"),
        v("muI30-34", MUI, model="mu(I) 30-34"),
        v("DP34", [(MAT, "sand.frictionAngle", 34.0)], model="Drucker-Prager 34")]},
    "gasification": {"base": BASE, "common": COMMON, "variants": [
        v("transPhase", transPhase=True),
        v("noTransPhase", [(MAT, "sand.transPhase", False)], transPhase=False)]},
    "scheme": {"base": BASE, "common": COMMON, "variants": [
        v("flip", scheme="GIMP + FLIP 0.995"), v("apic", APIC, scheme="cubic B-spline + APIC")]},
    "coupling": {"base": BASE, "common": COMMON, "variants": [
        v(f"{law}_v{n}", steel(n * V_STEEL60, COUPLINGS[law]), law=law, factor=n,
          speed=n * V_STEEL60)
        for law in COUPLINGS for n in SPEEDS]},
    "timeStep": {"base": BASE, "common": COMMON, "variants": [
        dt_variant(s, r) for s in ("flip", "apic") for r in RATIOS]},
}

ORDER = ["resolution", "frictionAngle", "muI", "gasification", "scheme", "youngsModulus",
         "coupling", "timeStep"]


# --------------------------------------------------------------------------- helpers
def res(results, name):
    return results["variants"][name]["result"]


def ok(cond):
    return "ok" if cond else "not reproduced"


def hard_common(results):
    """Properties every run must have: no NaN written."""
    out = []
    bad = [n for n, r in results["variants"].items() if r["result"].get("nanWritten")]
    out.append(("no NaN in any written particles.vtu", "VIOLATION" if bad else "ok",
                "NaN in " + ", ".join(bad) if bad else
                f"{len(results['variants'])} runs, all writes finite"))
    return out


def check(study, results, series=None):
    """series: optional {variant: {"depth": array, "load": array}} (report.py passes it)."""
    import analysis as A
    if series is None:
        series = A.series(results)
    out = hard_common(results)
    R = {n: r["result"] for n, r in results["variants"].items()}
    failed = [n for n, r in R.items() if r["exitCode"] != 0]
    if study != "timeStep":
        out.append(("all runs end normally", "VIOLATION" if failed else "ok",
                    "failed: " + ", ".join(failed) if failed else "exit 0"))
    if study == "resolution":
        e = A.resolution_errors(results, series)
        for q in ("peak", "depth"):
            if "h5" in e and "h4" in e:
                e5, e4 = e["h5"][q], e["h4"][q]
                out.append((f"{q} converges with h (|4-3| < |5-3|)",
                            "ok" if e4 < e5 else "VIOLATION",
                            f"|5-3| = {100 * e5:.1f} %, |4-3| = {100 * e4:.1f} %"))
    elif study == "youngsModulus":
        names = ["E1MPa", "E10MPa", "E100MPa"]
        pk = [R[n]["peakLoadAverage"] for n in names]
        tp = [R[n]["peakLoadTime"] for n in names]
        fd = [R[n]["finalDepthOverD"] for n in names]
        out.append(("peak load rises with E", ok(pk[0] < pk[1] < pk[2]),
                    ", ".join(f"{p:.1f}" for p in pk) + " N"))
        out.append(("peak comes earlier with E", ok(tp[0] > tp[1] > tp[2]),
                    ", ".join(f"{1000 * t:.1f}" for t in tp) + " ms"))
        spread = (max(fd) - min(fd)) / np.mean(fd)
        out.append(("final depth barely changes (spread < 10 %)", ok(spread < 0.10),
                    ", ".join(f"{d:.3f}" for d in fd) + f" (spread {100 * spread:.1f} %)"))
    elif study == "frictionAngle":
        names = ["phi30", "phi32", "phi34"]
        pk = [R[n]["peakLoadAverage"] for n in names]
        fd = [R[n]["finalDepthOverD"] for n in names]
        out.append(("higher peak with phi", ok(pk[0] < pk[1] < pk[2]),
                    ", ".join(f"{p:.1f}" for p in pk) + " N"))
        out.append(("shallower depth with phi", ok(fd[0] > fd[1] > fd[2]),
                    ", ".join(f"{d:.3f}" for d in fd)))
    elif study == "muI":
        a, m, b = (R[n] for n in ("DP30", "muI30-34", "DP34"))
        between = lambda x, lo, hi: min(lo, hi) <= x <= max(lo, hi)
        out.append(("mu(I) peak between DP 30 and DP 34",
                    ok(between(m["peakLoadAverage"], a["peakLoadAverage"], b["peakLoadAverage"])),
                    f"{a['peakLoadAverage']:.1f} / {m['peakLoadAverage']:.1f} / "
                    f"{b['peakLoadAverage']:.1f} N"))
        out.append(("mu(I) depth between DP 30 and DP 34",
                    ok(between(m["finalDepthOverD"], a["finalDepthOverD"], b["finalDepthOverD"])),
                    f"{a['finalDepthOverD']:.3f} / {m['finalDepthOverD']:.3f} / "
                    f"{b['finalDepthOverD']:.3f}"))
    elif study == "gasification":
        a, b = R["transPhase"], R["noTransPhase"]
        out.append(("higher load without gasification",
                    ok(b["peakLoadAverage"] > a["peakLoadAverage"]),
                    f"{a['peakLoadAverage']:.1f} N with, {b['peakLoadAverage']:.1f} N without"))
        out.append(("more (wider) splash without gasification [000 Fig. 15]",
                    ok(b.get("splashPeakCount", 0) > a.get("splashPeakCount", 0)),
                    f"{a.get('splashPeakCount')} points (r95 {1000 * a.get('splashPeakRadius95', 0):.0f} mm)"
                    f" with, {b.get('splashPeakCount')} (r95 "
                    f"{1000 * b.get('splashPeakRadius95', 0):.0f} mm) without"))
    elif study == "scheme":
        a, b = R["flip"], R["apic"]
        out.append(("APIC: higher load", ok(b["peakLoadAverage"] > a["peakLoadAverage"]),
                    f"FLIP {a['peakLoadAverage']:.1f} N, APIC {b['peakLoadAverage']:.1f} N"))
        out.append(("APIC: less penetration", ok(b["finalDepthOverD"] < a["finalDepthOverD"]),
                    f"FLIP {a['finalDepthOverD']:.3f}, APIC {b['finalDepthOverD']:.3f}"))
        out.append(("APIC: little splash", ok(b.get("splashPeakCount", 0) < a.get("splashPeakCount", 0)),
                    f"FLIP {a.get('splashPeakCount')} points, APIC {b.get('splashPeakCount')}"))
    elif study == "coupling":
        for law in COUPLINGS:
            pen = [R[f"{law}_v{n}"].get("maxPenetration", float("nan")) for n in SPEEDS]
            txt = ", ".join(f"{1000 * p:.3f}" for p in pen) + " mm"
            if law == "barrier":
                out.append(("barrier: no penetration at any speed",
                            "ok" if all(p == 0 for p in pen) else "VIOLATION", txt))
            else:
                out.append((f"{law}: penetration grows with speed",
                            ok(all(b >= a for a, b in zip(pen, pen[1:])) and pen[-1] > 0), txt))
    elif study == "timeStep":
        for s in ("flip", "apic"):
            rs = [(r, R[f"{s}_r{r:g}"]) for r in RATIOS]
            ran = [r for r, x in rs if x["reachedEnd"]]
            stop = [r for r, x in rs if x["exitCode"] != 0]
            out.append((f"{s}: runs that reach {T_DT} s / stop", "ok",
                        f"end: {ran}; stop: {stop}"))
            msgs = [x for r, x in rs if x["exitCode"] != 0 and not re.search(
                r"FATAL ERROR: step \d+ \(t = .*\), phase \w+: particle \d+", x["stopMessage"])]
            out.append((f"{s}: every stop is a FATAL ERROR with step/phase/particle",
                        "VIOLATION" if msgs else "ok",
                        f"{len(stop)} stops" if not msgs else msgs[0]["stopMessage"][:200]))
            out.append((f"{s}: the reference Δt/Δt_crit = 0.1 runs to the end",
                        "ok" if R[f"{s}_r0.1"]["reachedEnd"] else "VIOLATION",
                        f"t = {R[f'{s}_r0.1']['lastTime']:.4f} s"))
    return out
