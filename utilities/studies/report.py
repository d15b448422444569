#!/usr/bin/python3
"""Charts, markdown tables and trend checks of the glassDrop40 parameter studies.

Reads runs/<study>/results.json (runStudy.py), writes docs/images/study_<study>.png, prints
one markdown table and the check outcomes per study. Exit code 1 when a check finds a
violation of a hard property (barrier penetration > 0, NaN written, no convergence with h,
a run of a physical study that does not end normally); trends of the paper that are not
reproduced are listed as such but do not fail.

Usage: report.py [STUDY ...]   (default: all studies that have results)
"""
import os
import re
import sys

import numpy as np
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import analysis as A  # noqa: E402
import studies as S  # noqa: E402
from runStudy import ROOT, load_results  # noqa: E402

IMAGES = os.path.join(ROOT, "docs", "images")


def fmt(x, f="{:.3f}"):
    return "–" if x is None or (isinstance(x, float) and not np.isfinite(x)) else f.format(x)


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(str(c) for c in r) + " |" for r in rows]
    return "\n".join(out)


def label(study, name, params):
    if study == "resolution":
        return f"h = {params['h']} mm ({'APIC' if params['scheme'] == 'apic' else 'FLIP'})"
    if study == "youngsModulus":
        return f"E = {params['E']:g} MPa"
    if study == "frictionAngle":
        return f"φ = {params['phi']}°"
    if study == "muI":
        return {"DP30": "Drucker–Prager 30°", "DP34": "Drucker–Prager 34°"}.get(name, "μ(I) 30–34°")
    if study == "gasification":
        return "with gasification" if params["transPhase"] else "without gasification"
    if study == "scheme":
        return params["scheme"]
    return name


def common_row(r):
    return [fmt(r.get("peakLoadAverage"), "{:.1f}"), fmt(1000 * r["peakLoadTime"], "{:.1f}")
            if "peakLoadTime" in r else "–", fmt(r.get("finalDepthOverD")),
            fmt(r.get("maxDepthOverD")), fmt(1000 * r["smallestGap"], "{:.3f}")
            if "smallestGap" in r else "–", r.get("splashPeakCount", "–"),
            fmt(1000 * r.get("splashPeakRadius95", float("nan")), "{:.0f}"),
            f"{r['particles']}", fmt(r.get("wallTime"), "{:.0f}"),
            fmt(r.get("particleUpdatesPerSecond", float("nan")) / 1e6, "{:.2f}")]


COMMON_HEADER = ["case", "peak load (2 ms avg) [N]", "at [ms]", "depth/D at end", "max depth/D",
                 "smallest gap [mm]", "splash points (peak)", "splash r95 [mm]", "points",
                 "wall [s]", "M updates/s"]


def time_series_chart(study, results, ser, path, splash=False):
    n = 3 if splash else 2
    fig, ax = plt.subplots(1, n, figsize=(4.6 * n, 3.8))
    for name, item in results["variants"].items():
        s = ser[name]
        lab = label(study, name, item["params"])
        if len(s["load"]):
            ax[0].plot(1000 * s["load"][:, 0], s["load"][:, 2], lw=1, label=lab)
        if len(s["depth"]):
            ax[1].plot(1000 * s["depth"][:, 0], s["depth"][:, 2], lw=1.5, label=lab)
        if splash:
            sp = item["result"].get("splash", [])
            ax[2].plot([1000 * x["time"] for x in sp], [x["count"] for x in sp], "o-", ms=3,
                       label=lab)
    ax[0].set_ylabel("load on the bottom (2 ms average) [N]")
    ax[1].set_ylabel("intrusion depth / D")
    if splash:
        ax[2].set_ylabel("points > 1 cm above the surface")
    for a in ax:
        a.set_xlabel("t [ms]")
        a.grid(alpha=0.3)
    ax[1].legend(fontsize=8)
    fig.suptitle(f"glassDrop40, h = 5 mm: {study}")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def report_resolution(results, ser, path):
    e = A.resolution_errors(results, ser)
    rows = []
    for name, item in results["variants"].items():
        r = item["result"]
        x = e.get(name, {})
        rows.append([label("resolution", name, item["params"])] + common_row(r) +
                    [fmt(x.get("peakValue"), "{:.1f}"), fmt(x.get("depthValue")),
                     fmt(100 * x["peak"], "{:.1f}") if x else "–",
                     fmt(100 * x["depth"], "{:.1f}") if x else "–",
                     fmt(x.get("wall"), "{:.0f}")])
    print(table(COMMON_HEADER + [f"peak ≤ {A.T_COMPARE} s [N]", f"depth/D at {A.T_COMPARE} s",
                                 "peak error vs h=3 [%]", "depth error vs h=3 [%]",
                                 f"wall for {A.T_COMPARE} s [s]"], rows))
    fig, ax = plt.subplots(1, 3, figsize=(14, 3.9))
    for name, item in results["variants"].items():
        s = ser[name]
        lab = label("resolution", name, item["params"])
        ls = "--" if item["params"]["scheme"] == "apic" else "-"
        ax[0].plot(1000 * s["load"][:, 0], s["load"][:, 2], ls, lw=1, label=lab)
        ax[1].plot(1000 * s["depth"][:, 0], s["depth"][:, 2], ls, lw=1.5, label=lab)
    for scheme, mk in (("flip", "o"), ("apic", "s")):
        pts = [(n, x) for n, x in e.items() if n != "h3" and
               results["variants"][n]["params"]["scheme"] == scheme]
        if not pts:
            continue
        pts.sort(key=lambda p: p[1]["wall"])
        for q, c in (("peak", "C0"), ("depth", "C1")):
            ax[2].plot([p[1]["wall"] for p in pts], [100 * p[1][q] for p in pts], mk + "-",
                       color=c, mfc="none" if scheme == "apic" else c,
                       label=f"{'FLIP/GIMP' if scheme == 'flip' else 'APIC/cubic'}: {q}")
            for n, x in pts:
                ax[2].annotate(f"h={results['variants'][n]['params']['h']}", (x["wall"], 100 * x[q]),
                               fontsize=7, xytext=(3, 3), textcoords="offset points")
    if "h3" in e:
        ax[2].axvline(e["h3"]["wall"], color="k", lw=0.8, ls=":", label="h = 3 mm (reference)")
    ax[0].set_ylabel("load (2 ms avg) [N]")
    ax[1].set_ylabel("intrusion depth / D")
    ax[2].set_ylabel("error vs h = 3 mm FLIP [%]")
    ax[2].set_xlabel(f"wall time for {A.T_COMPARE} s simulated [s] (2 threads)")
    ax[2].set_xscale("log")
    for a in ax[:2]:
        a.set_xlabel("t [ms]")
    for a in ax:
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig.suptitle("glassDrop40: resolution (convergence) and speed against accuracy")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def report_coupling(results, ser, path):
    rows = []
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.9))
    for law, mk in zip(S.COUPLINGS, "os^"):
        xs, pen, gaps = [], [], []
        for n in S.SPEEDS:
            name = f"{law}_v{n}"
            if name not in results["variants"]:
                continue
            r = results["variants"][name]["result"]
            xs.append(n * S.V_STEEL60)
            pen.append(1000 * r.get("maxPenetration", np.nan))
            gaps.append(1000 * r.get("smallestGap", np.nan))
            rows.append([law, f"{n}× = {n * S.V_STEEL60:.2f}", r["exitCode"],
                         fmt(1000 * r.get("smallestGap", np.nan), "{:.3f}"),
                         fmt(1000 * r.get("maxPenetration", np.nan), "{:.3f}"),
                         fmt(r.get("maxDepthOverD")), fmt(r.get("peakLoadAverage"), "{:.0f}"),
                         fmt(r.get("wallTime"), "{:.0f}"),
                         r["stopMessage"][:120] if r["exitCode"] else ""])
        lab = {"barrier": "barrier", "spring": f"linear spring, k = {S.K_CRIT:.3g} N/m (default)",
               "softSpring": f"linear spring, k = {S.K_CRIT / 100:.3g} N/m"}[law]
        ax[0].plot(xs, pen, mk + "-", label=lab)
        ax[1].plot(xs, gaps, mk + "-", label=lab)
    ax[0].set_ylabel("max penetration max(0, −ξ_min) [mm]")
    ax[1].set_ylabel("smallest gap ξ_min [mm]")
    ax[1].axhline(0, color="k", lw=0.8)
    for a in ax:
        a.set_xlabel("impact speed [m/s] (steel sphere D = 40 mm)")
        a.set_xscale("log")
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    fig.suptitle("barrier vs linear-spring coupling as the impact speed rises (h = 5 mm)")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"Default linear-spring stiffness k_N,crit = 4 m_p π² c²/h² = {S.K_CRIT:.4g} N/m "
          f"(m_p = {S.MP:.4g} kg, c = {S.C0:.3f} m/s, h = {S.H0} m); soft spring k = "
          f"{S.K_CRIT / 100:.4g} N/m.\n")
    print(table(["coupling", "speed [m/s]", "exit", "smallest gap [mm]", "max penetration [mm]",
                 "max depth/D", "peak load [N]", "wall [s]", "stop message"], rows))


def report_timestep(results, ser, path):
    rows = []
    fig, ax = plt.subplots(1, 2, figsize=(10, 3.9))
    for scheme, mk in (("flip", "o"), ("apic", "s")):
        ref = ser.get(f"{scheme}_r0.1")
        dref = A.value_at(ref["depth"], 2, S.T_DT, 1e-5) if ref is not None else None
        xr, err, xw, wall, xf = [], [], [], [], []
        for ratio in S.RATIOS:
            name = f"{scheme}_r{ratio:g}"
            if name not in results["variants"]:
                continue
            r = results["variants"][name]["result"]
            d = A.value_at(ser[name]["depth"], 2, S.T_DT, 0.5 * r["deltaT"] + 1e-12) \
                if r["reachedEnd"] else None
            e = abs(d - dref) / dref if (d is not None and dref) else None
            if e is not None and ratio != 0.1:
                xr.append(ratio)
                err.append(100 * e)
            if r["reachedEnd"]:
                xw.append(ratio)
                wall.append(r["wallTime"])
            else:
                xf.append(ratio)
            rows.append([scheme, ratio, f"{r['deltaT']:.4g}",
                         r["exitCode"], "yes" if r["reachedEnd"] else stopped_at(r),
                         "yes" if r["nanWritten"] else "no", fmt(d),
                         fmt(100 * e, "{:.2f}") if e is not None else "–",
                         fmt(r.get("wallTime"), "{:.1f}"), r["stopMessage"][:220]])
        ax[0].plot(xr, err, mk + "-", label=f"{scheme.upper()} runs that reach {S.T_DT} s")
        ax[1].plot(xw, wall, mk + "-", label=scheme.upper())
        if xf:
            ax[0].scatter(xf, [400 if scheme == "flip" else 600] * len(xf), marker="x" if scheme == "flip" else "+",
                          color="r", s=50, label=f"{scheme.upper()} stopped (FATAL ERROR)")
    ax[0].set_ylabel(f"depth/D error at {S.T_DT} s vs Δt/Δt_crit = 0.1 [%]")
    ax[1].set_ylabel("wall time [s]")
    for a in ax:
        a.set_xlabel("Δt / Δt_crit,  Δt_crit = h/(c + v_impact) = %.3g s" % S.DT_CRIT)
        a.set_xscale("log")
        a.grid(alpha=0.3)
        a.legend(fontsize=7)
    ax[0].set_yscale("log")
    ax[1].set_yscale("log")
    fig.suptitle("time step beyond the stable limit (allowUnstableDeltaT), h = 5 mm")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(table(["scheme", "Δt/Δt_crit", "Δt [s]", "exit", f"reaches {S.T_DT} s", "NaN written",
                 f"depth/D at {S.T_DT} s", "error vs 0.1 [%]", "wall [s]", "stop message"], rows))


def stopped_at(r):
    m = re.search(r"step (\d+) \(t = (\S+) s\), phase (\w+)", r["stopMessage"])
    return f"no: step {m.group(1)} (t = {1000 * float(m.group(2)):.2f} ms), {m.group(3)}" if m \
        else f"no (t = {1000 * r['lastTime']:.2f} ms)"


def main(argv):
    names = argv or [s for s in S.ORDER if load_results(s)]
    status = 0
    os.makedirs(IMAGES, exist_ok=True)
    for study in names:
        results = load_results(study)
        if not results or not results["variants"]:
            print(f"### {study}: no results\n")
            continue
        ser = A.series(results)
        path = os.path.join(IMAGES, f"study_{study}.png")
        print(f"### {study}\n")
        if study == "resolution":
            report_resolution(results, ser, path)
        elif study == "coupling":
            report_coupling(results, ser, path)
        elif study == "timeStep":
            report_timestep(results, ser, path)
        else:
            rows = [[label(study, n, it["params"])] + common_row(it["result"])
                    for n, it in results["variants"].items()]
            print(table(COMMON_HEADER, rows))
            time_series_chart(study, results, ser, path,
                              splash=study in ("gasification", "scheme"))
        try:
            checks = S.check(study, results, ser)
        except KeyError as e:   # a variant not run yet
            checks = [("checks", "not run", f"variant {e} missing")]
        print("\nChecks:\n")
        for lab, state, detail in checks:
            print(f"- **{state}**: {lab}: {detail}")
            if state == "VIOLATION":
                status = 1
        print(f"\n![{study}](images/study_{study}.png)\n")
    return status


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
