#!/usr/bin/python3
"""Writes docs/accuracy-cost.md and docs/images/accuracy-cost/*.png from
bench/results/accuracy-cost.csv and accuracy-cost-stages.csv (called by
bench/accuracy-cost/run; every number in the document comes from the CSVs).

Plots: per case, error against wall seconds (log-log), one panel per error measure, one
colour per variant, marker size growing with resolution, the Pareto front (runs that no
other run beats in both error and time) ringed and joined. The stage split: microseconds
per particle-step in each stage, per variant, for the paper's two cases.
"""
import csv
import math
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
RESULTS = os.path.join(ROOT, "bench/results/accuracy-cost.csv")
STAGES = os.path.join(ROOT, "bench/results/accuracy-cost-stages.csv")
RUNINFO = os.path.join(ROOT, "bench/results/accuracy-cost-run.txt")
DOC = os.path.join(ROOT, "docs/accuracy-cost.md")
IMG = os.path.join(ROOT, "docs/images/accuracy-cost")

VARIANT_TEXT = {
    "proposed": "the paper's method: SPH2, OPS + volume correction + surface fitting (the tutorials)",
    "corrected": "corrected (first-order consistent) operators instead of SPH2, proposed shifting",
    "standard": "standard SPH operators instead of SPH2, proposed shifting",
    "OPS": "SPH2, OPS shifting alone (distribution term only)",
    "noShift": "SPH2, no shifting",
    "baseline": "the paper's baseline: SPH2, OPS alone, stabilized ISPH (densityInvariant, alpha 1e-3)",
    "proposed+stab": "the paper's method plus the stabilized PPE source term",
    "compressible": "proposed with the compressibility term (soundSpeed ten times the largest flow speed, "
                    "eq. 6c); only on damBreakWallPressure",
    "noTaylor": "proposed without the Taylor correction of the velocity after the shift "
                "(taylorCorrection off; tutorials/damBreakWallPressure's choice)",
}
COLOURS = {"proposed": "tab:red", "corrected": "tab:orange", "standard": "tab:brown", "OPS": "tab:blue",
           "noShift": "tab:gray", "baseline": "tab:green", "proposed+stab": "tab:purple",
           "compressible": "tab:pink", "noTaylor": "tab:olive"}
MARKERS = {"proposed": "o", "corrected": "s", "standard": "D", "OPS": "^", "noShift": "v", "baseline": "P",
           "proposed+stab": "X", "compressible": "*", "noTaylor": "h"}
CASE_TEXT = {
    "rotatingSquarePatch": ("rotating square patch (tests/cases/rotatingSquarePatch: L = 1 m, omega = 1 rad/s, "
                            "inviscid, no walls; omega t <= 1; dt = 0.16 d0 s, Courant number 0.1 at the corners)",
                            lambda d0: f"L/d0 = {1 / d0:.0f}"),
    "poiseuilleStartup": ("start-up Poiseuille flow (tests/cases/poiseuilleStartup: H = 0.1 m, periodic, "
                          "nu = 1e-3 m^2/s; t <= 2 s; dt proportional to d0^2, dt nu/h^2 = 0.11)",
                          lambda d0: f"H/d0 = {0.1 / d0:.0f}"),
    "damBreak": ("dam break in the experiments' shape (tests/cases/damBreak: column a = 0.2 m wide, 2a high, "
                 "tank 5a; t <= 0.36 s; dt = 0.05 d0 s, Courant number 0.17 at 4 m/s)",
                 lambda d0: f"a/d0 = {0.2 / d0:.0f}"),
    "damBreakWallPressure": ("dam break against a wall, Buchner's (2002) geometry (tutorials/damBreakWallPressure: "
                             "H = 0.6 m, column 2H, tank 5.366 H; t sqrt(g/H) <= 7.48; adaptive dt, maxCo 0.2), "
                             "sensor P1 on the far wall against the experiment",
                             lambda d0: f"H/d0 = {0.6 / d0:.0f}"),
}
MEASURE_TEXT = {
    "sensorNoise": "wall-pressure noise at P1: rms of p/(rho g H) about its centred moving average over 0.1 in "
                   "t sqrt(g/H), over the plateau 3.5 <= t sqrt(g/H) <= 5.5, unfiltered (the experiment's: 0.007)",
    "interiorNoise": "the same noise at the probe `interior`, in the water 0.12 m from the wall, 8 cm up",
    "crossingError": "relative error of the first time P1 exceeds 0.3 rho g H (experiment: t sqrt(g/H) = 2.616)",
    "peak1Error": "relative error of the first peak of P1 low-pass filtered at 100 Hz (experiment: 0.687)",
    "plateauError": "relative error of P1's mean over 3.5 <= t sqrt(g/H) <= 5.5 (experiment: 0.538)",
    "peak2Error": "relative error of the second peak of P1 low-pass filtered at 100 Hz (experiment: 0.877)",
    "plateauConvergedError": "the largest relative error of the plateau mean (3.5 <= t sqrt(g/H) <= 5.5) at the "
                             "four heights S1, S2, S3, P1 against the mean of three converged runs of the same "
                             "equations at H/400 (the tutorial's data/README.md; the sensors read the fluid)",
    "centrePressure": "centre pressure: max |p(0,0) - p_c| / |p_c| over 0.016 <= t <= 0.05 s, "
                      "p_c = -0.147342707 rho omega^2 L^2 (p = 0 is imposed at the patch's edge, d0/2 outside "
                      "the outer particle row, eq. 6b, so the side is L)",
    "kineticEnergyDrift": "kinetic energy: max |E(t)/E(0) - 1| over omega t <= 1 (exactly conserved)",
    "angularMomentumDrift": "angular momentum: max |L(t)/L(0) - 1| over omega t <= 1 (exactly conserved)",
    "volumeDrift": "fluid volume (conservation's fluidVolume: interior particles m/<rho>, the others m/rho0; "
                   "sum m/<rho> in runs before 2026-12-02): max |V(t)/V(0) - 1| over the run (constant for "
                   "incompressible flow)",
    "velocityL2": "velocity: L2 relative error of u at the four probes (y = H/8, H/4, H/2, 3H/4) against the "
                  "series solution, over every sample of 0 < t <= 2 s",
    "velocityMax": "velocity: max |u - u_exact| over the probes and times, divided by the steady centre-line "
                   "speed 0.01 m/s",
    "frontKO": "surge front x_front = max fluid x + d0/2 (the body of water: fluidExtent connectedOnly, since 2026-12-02) against Koshizuka & Oka (1996): RMS of the relative "
               "error (x - x_KO)/x_KO over the experiment's times (t <= 0.31 s)",
    "frontKOBias": "the mean of the signed relative front error against Koshizuka & Oka (> 0: the computed "
                   "front leads; not plotted)",
    "frontMMBias": "the same against Martin & Moyce",
    "frontMM": "surge front against Martin & Moyce (1952, n^2 = 2, a = 2.25 in): RMS relative error over the "
               "experiment's times (0.09 <= t <= 0.33 s)",
}
PRIMARY = {"rotatingSquarePatch": "centrePressure", "poiseuilleStartup": "velocityL2", "damBreak": "frontKO",
           "damBreakWallPressure": "sensorNoise"}
# Stage columns of the split table (the timing function object's names; the columns are disjoint timers).
GROUPS = [("neighbours", ["neighbours"]), ("weights", ["weights"]), ("density", ["density"]),
          ("freeSurface", ["freeSurface"]), ("surfaceFit", ["surfaceFit"]), ("predictor", ["predictor"]),
          ("ppeAssembly", ["ppeAssembly"]), ("ppeSolve", ["ppeSolve"]), ("corrector", ["corrector"]),
          ("advection+xsph", ["advection", "xsph"]), ("ads", ["ads"]),
          ("shifting (Taylor, refresh, cap)", ["shifting"]),
          ("shift terms", ["shifting/distribution", "shifting/volumeCorrection", "shifting/surfaceFitting"]),
          ("functionObjects+output", ["functionObjects", "output"])]


def num(x):
    try:
        v = float(x)
        return v if math.isfinite(v) else None
    except (TypeError, ValueError):
        return None


def g(x, d=3):
    v = num(x)
    return "-" if v is None else f"{v:.{d}g}"


def pct(x):
    v = num(x)
    return "-" if v is None else (f"{100 * v:.3g} %" if abs(v) >= 1e-4 else f"{100 * v:.2g} %")


def status_cell(r):
    if r["status"] == "ok":
        return "ok"
    return f"**{r['status']}** (reached t = {r['t_reached']} of {r['t_end']} s)"


def geomean(xs):
    xs = [x for x in xs if x and x > 0]
    return math.exp(sum(map(math.log, xs)) / len(xs)) if xs else None


def load():
    rows = list(csv.DictReader(open(RESULTS))) if os.path.isfile(RESULTS) else []
    stages = list(csv.DictReader(open(STAGES))) if os.path.isfile(STAGES) else []
    info = {}
    if os.path.isfile(RUNINFO):
        for line in open(RUNINFO):
            k, _, v = line.strip().partition(" ")
            info[k] = v
    return rows, stages, info


def runs_of(rows):
    """One entry per run (case, variant, d0) with its errors by measure."""
    runs = {}
    for r in rows:
        key = (r["case"], r["variant"], float(r["d0"]))
        run = runs.setdefault(key, dict(r, errors={}))
        run["errors"][r["error_measure"]] = num(r["error"])
    return runs


def pareto(points):
    """Points (wall, error, label) not beaten in both by another point, sorted by wall."""
    front, best = [], math.inf
    for p in sorted(points, key=lambda p: (p[0], p[1])):
        if p[1] < best:
            front.append(p)
            best = p[1]
    return front


def cases_in(runs):
    return [c for c in CASE_TEXT if any(k[0] == c for k in runs)]


def variants_in(runs):
    return [v for v in VARIANT_TEXT if any(k[1] == v for k in runs)]


def measures_of(runs, case):
    """The case's error measures in the CSV's order."""
    out = []
    for k, r in runs.items():
        if k[0] == case:
            out += [m for m in r["errors"] if m not in out]
    return out


def plot_case(runs, case, path):
    measures = [m for m in measures_of(runs, case) if not m.endswith("Bias")]   # signed: no log axis
    n = len(measures)
    cols = 2 if n > 1 else 1
    nrows = (n + cols - 1) // cols
    fig, axes = plt.subplots(nrows, cols, figsize=(5.2 * cols, 4 * nrows), squeeze=False)
    d0s = sorted({k[2] for k in runs if k[0] == case}, reverse=True)
    label = CASE_TEXT[case][1]
    for ax, m in zip(axes.flat, measures):
        pts = []
        for v in variants_in(runs):
            xs, ys, ss = [], [], []
            for d0 in d0s:
                r = runs.get((case, v, d0))
                if r and r["status"] == "ok" and r["errors"].get(m) is not None:
                    xs.append(float(r["wall_s"]))
                    ys.append(max(r["errors"][m], 1e-12))
                    ss.append(20 + 35 * d0s.index(d0))
                    pts.append((xs[-1], ys[-1], f"{v} {label(d0)}"))
            if xs:
                ax.plot(xs, ys, "-", color=COLOURS[v], lw=0.8, alpha=0.6)
                ax.scatter(xs, ys, s=ss, color=COLOURS[v], marker=MARKERS[v], label=v, zorder=3)
        front = pareto(pts)
        if front:
            ax.step([p[0] for p in front], [p[1] for p in front], where="post", color="k", lw=1, ls="--",
                    label="Pareto front", zorder=2)
            ax.scatter([p[0] for p in front], [p[1] for p in front], s=140, facecolors="none", edgecolors="k",
                       lw=1.2, zorder=4)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("wall time per run [s] (2 threads)")
        ax.set_ylabel("relative error")
        ax.set_title(m, fontsize=10)
        ax.grid(True, which="both", alpha=0.3)
    for ax in list(axes.flat)[n:]:
        ax.axis("off")
    fig.legend(*axes.flat[0].get_legend_handles_labels(), fontsize=8, loc="lower center", ncol=8)
    fig.suptitle(f"{case}: error vs wall time (marker size: {', '.join(label(d) for d in d0s)})", fontsize=10)
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    fig.savefig(path, dpi=90)
    plt.close(fig)


def stage_table(stages):
    """{(case, variant): dict(steps, particles, wall, total, groups{name: us/particle-step}, raw{stage: s})}."""
    out = {}
    for r in stages:
        key = (r["case"], r["variant"])
        e = out.setdefault(key, dict(r, raw={}))
        if r["stage"]:
            e["raw"][r["stage"]] = float(r["seconds"])
    for e in out.values():
        ps = (num(e["steps"]) or 0) * (num(e["particles"]) or 0)
        e["total"] = sum(e["raw"].values())
        e["groups"] = {name: (sum(e["raw"].get(s, 0) for s in parts) / ps * 1e6 if ps else None)
                       for name, parts in GROUPS}
    return out


def stage_summary(st):
    """Sentences on the stage split, from its numbers (us per particle-step)."""
    out = []
    for case in ("rotatingSquarePatch", "damBreak"):
        p = st.get((case, "proposed"))
        if not p or not p["raw"]:
            continue
        ps = float(p["steps"]) * float(p["particles"])
        us = {k: v / ps * 1e6 for k, v in p["raw"].items()}
        total = sum(us.values())
        shift = sum(v for k, v in us.items() if k.startswith("shifting") or k == "surfaceFit")
        text = (f"**{case}**: a step of the proposed method costs {total:.3g} us per particle-step; the PPE "
                f"solve takes {100 * us.get('ppeSolve', 0) / total:.0f} % of it, the operator weights "
                f"{100 * us.get('weights', 0) / total:.0f} %, the proposed shifting (shared part, its three "
                f"terms and the surface fit) {100 * shift / total:.0f} %.")
        w = {v: st[(case, v)]["groups"]["weights"] for v in ("proposed", "corrected", "standard") if (case, v) in st}
        if len(w) == 3:
            text += (f" Weights: SPH2 {w['proposed']:.3g}, corrected {w['corrected']:.3g}, standard "
                     f"{w['standard']:.3g} us per particle-step.")
        tot = {v: st[(case, v)]["total"] / ps * 1e6 for v in ("OPS", "noShift", "baseline", "proposed+stab")
               if (case, v) in st and st[(case, v)]["steps"] == p["steps"]}
        if tot:
            text += " Whole step: " + ", ".join(f"`{v}` {x:.3g}" for v, x in tot.items()) + " us per particle-step."
        out.append(text)
    return out


def plot_stages(st, path):
    cases = [c for c in ("rotatingSquarePatch", "damBreak") if any(k[0] == c for k in st)]
    if not cases:
        return False
    fig, axes = plt.subplots(1, len(cases), figsize=(6.5 * len(cases), 4.2), squeeze=False)
    cmap = plt.get_cmap("tab20")
    for ax, case in zip(axes.flat, cases):
        vs = [v for v in VARIANT_TEXT if (case, v) in st]
        left = [0.0] * len(vs)
        for k, (name, _) in enumerate(GROUPS):
            w = [st[(case, v)]["groups"][name] or 0 for v in vs]
            ax.barh(vs, w, left=left, color=cmap(k), label=name)
            left = [a + b for a, b in zip(left, w)]
        ax.invert_yaxis()
        ax.set_xlabel("us per particle-step (wall, 2 threads)")
        e = st[(case, vs[0])]
        ax.set_title(f"{case}, {e['particles']} fluid particles, {e['steps']} steps", fontsize=10)
    fig.legend(*axes.flat[0].get_legend_handles_labels(), fontsize=7, loc="center right")
    fig.tight_layout(rect=(0, 0, 0.84, 1))
    fig.savefig(path, dpi=90)
    plt.close(fig)
    return True


# "Which choice for which need": each need is an error bound on one measure; the answer
# (the cheapest run of the study that meets it) is computed, never written by hand.
NEEDS = [("rotatingSquarePatch", "centrePressure", 1e-2, "pressure within 1 %"),
         ("rotatingSquarePatch", "centrePressure", 1e-3, "pressure within 0.1 %"),
         ("rotatingSquarePatch", "angularMomentumDrift", 1e-2, "angular momentum within 1 %"),
         ("rotatingSquarePatch", "volumeDrift", 0.1, "fluid volume within 10 %"),
         ("poiseuilleStartup", "velocityL2", 1e-2, "velocity history within 1 % (L2)"),
         ("poiseuilleStartup", "velocityL2", 5e-3, "velocity history within 0.5 % (L2)"),
         ("damBreak", "frontKO", 0.08, "surge front within 8 % RMS of Koshizuka & Oka"),
         ("damBreak", "frontMM", 0.10, "surge front within 10 % RMS of Martin & Moyce"),
         ("damBreak", "volumeDrift", 0.1, "fluid volume within 10 %")]


def err(runs, case, v, d0, m):
    r = runs.get((case, v, d0))
    return r["errors"].get(m) if r and r["status"] == "ok" else None


def ratio_to_proposed(runs, v, case, m):
    """Geometric mean over the resolutions of error(v) / error(proposed)."""
    rs = []
    for k in runs:
        if k[0] == case and k[1] == "proposed":
            a, b = err(runs, case, v, k[2], m), err(runs, case, "proposed", k[2], m)
            if a and b:
                rs.append(a / b)
    return geomean(rs)


def cost_to_proposed(runs, v):
    """Geometric mean over the finest resolution of each case of (particle-steps/s of proposed) /
    (particle-steps/s of v); the coarse runs last a second or less and mostly time the start-up."""
    rs = []
    finest = {}
    for k in runs:
        finest[k[0]] = min(finest.get(k[0], 1e300), k[2])
    for k, r in runs.items():
        if k[2] != finest[k[0]]:
            continue
        p = runs.get((k[0], "proposed", k[2]))
        if k[1] == v and p and num(r["particle_steps_per_s"]) and num(p["particle_steps_per_s"]):
            rs.append(num(p["particle_steps_per_s"]) / num(r["particle_steps_per_s"]))
    return geomean(rs)


def needs_table(runs):
    out = ["| need (case, measure) | cheapest run that meets it | its error | its wall s | "
           "runs that meet it |", "|---|---|---|---|---|"]
    for case, m, bound, text in NEEDS:
        ok = [(float(r["wall_s"]), r["errors"][m], k) for k, r in runs.items()
              if k[0] == case and r["status"] == "ok" and r["errors"].get(m) is not None]
        if not ok:
            continue
        meet = sorted(p for p in ok if p[1] <= bound)
        if meet:
            w, e, k = meet[0]
            near = [p for p in meet[1:] if p[0] <= 1.25 * w]
            also = (" (within 1.25x of its time also: " +
                    ", ".join(f"`{p[2][1]}` {CASE_TEXT[case][1](p[2][2])}" for p in near) + ")") if near else ""
            out.append(f"| {text} ({case}, `{m}`) | `{k[1]}` {CASE_TEXT[case][1](k[2])}{also} | {pct(e)} | "
                       f"{w:.3g} | {len(meet)} of {len(ok)} |")
        else:
            best = min(ok, key=lambda p: p[1])
            out.append(f"| {text} ({case}, `{m}`) | none (best: `{best[2][1]}` {CASE_TEXT[case][1](best[2][2])}) | "
                       f"{pct(best[1])} | {best[0]:.3g} | 0 of {len(ok)} |")
    return out


def reading(runs):
    """The reading bullets; every number and every comparison word comes from the runs."""
    out = []
    cases = cases_in(runs)
    finest = {c: min(k[2] for k in runs if k[0] == c) for c in cases}
    failed = sorted(k for k, r in runs.items() if r["status"] != "ok")
    if failed:
        out.append("**Runs that failed** (kept in the CSV with their exit status): " +
                   "; ".join(f"{c} `{v}` d0 = {d0:g}: {runs[(c, v, d0)]['status']}, reached t = "
                             f"{runs[(c, v, d0)]['t_reached']} of {runs[(c, v, d0)]['t_end']} s"
                             for c, v, d0 in failed) + ".")
    c = "rotatingSquarePatch"
    if c in cases:
        d = finest[c]
        e = {v: err(runs, c, v, d, "centrePressure") for v in ("proposed", "corrected", "standard")}
        if all(e.values()):
            worst = max(e, key=e.get)
            out.append(f"**Operators and pressure.** At {CASE_TEXT[c][1](d)} the centre pressure right after the "
                       f"start is off by {pct(e['proposed'])} with SPH2, {pct(e['corrected'])} with corrected "
                       f"and {pct(e['standard'])} with standard operators; the shifting and stabilization "
                       f"variants (all SPH2) give {spread(runs, c, d, 'centrePressure')}. "
                       + converge_text(runs, c, "centrePressure") + " "
                       + (f"`{worst}` is {e[worst] / min(e.values()):.3g}x the best: not a choice for pressures "
                          "(loads, probes)." if e[worst] > 3 * min(e.values()) else ""))
    c = "poiseuilleStartup"
    if c in cases:
        d = finest[c]
        e = {v: err(runs, c, v, d, "velocityL2") for v in VARIANT_TEXT if (c, v, d) in runs}
        e = {v: x for v, x in e.items() if x}
        if e:
            best = min(e, key=e.get)
            out.append(f"**Operators and viscous flow.** In the Poiseuille start-up at {CASE_TEXT[c][1](d)} the "
                       "velocity L2 error is " + ", ".join(f"{pct(x)} (`{v}`)" for v, x in e.items()) +
                       f": `{best}` is the most accurate. The SPH2 variants (shifting and stabilization choices; "
                       "no free surface here) give " + spread(runs, c, d, "velocityL2") + ".")
    for c in ("rotatingSquarePatch", "damBreak"):
        if c not in cases:
            continue
        d = finest[c]
        vol = {v: err(runs, c, v, d, "volumeDrift") for v in VARIANT_TEXT if (c, v, d) in runs}
        vol = {v: x for v, x in vol.items() if x}
        if vol:
            best = min(vol, key=vol.get)
            out.append(f"**Volume conservation, {c}** at {CASE_TEXT[c][1](d)}: largest fluid-volume change " +
                       ", ".join(f"{pct(x)} (`{v}`)" for v, x in sorted(vol.items(), key=lambda kv: kv[1])) +
                       f". Smallest: `{best}`. None keeps the volume within the 5 % the regression cases ask "
                       "for (their known failure)." if min(vol.values()) > 0.05 else
                       f"**Volume conservation, {c}** at {CASE_TEXT[c][1](d)}: largest fluid-volume change " +
                       ", ".join(f"{pct(x)} (`{v}`)" for v, x in sorted(vol.items(), key=lambda kv: kv[1])) + ".")
    c = "damBreak"
    if c in cases:
        ds = sorted({k[2] for k in runs if k[0] == c}, reverse=True)
        fr = [err(runs, c, "proposed", d, "frontKO") for d in ds]
        bias = [err(runs, c, "proposed", d, "frontKOBias") for d in ds]
        leads = all(b is not None and b > 0 for b in bias)
        if all(fr) and len(fr) > 1:
            if fr[-1] > fr[0] and leads:
                out.append("**The dam-break front does not converge to the experiments.** With the proposed "
                           "method the RMS front error against Koshizuka & Oka goes " +
                           " -> ".join(pct(x) for x in fr) + " as a/d0 goes " +
                           " -> ".join(f"{0.2 / d:.0f}" for d in ds) + ", and its signed mean is " +
                           " -> ".join(pct(x) for x in bias) + ": the computed front leads the "
                           "experiments, more at the finer resolutions than at the coarsest (the gate's opening and bottom friction are not "
                           "modelled; the two experiments differ by about 6 %)." +
                           (" For the front position the coarsest resolution is both the cheapest and the "
                            "closest; refining buys the shape of the flow, not the front." if fr[0] == min(fr) else ""))
            else:
                out.append("**Dam-break front.** With the proposed method the RMS front error against Koshizuka "
                           "& Oka goes " + " -> ".join(pct(x) for x in fr) + " (signed mean " +
                           " -> ".join(pct(x) for x in bias) + ") as a/d0 goes " +
                           " -> ".join(f"{0.2 / d:.0f}" for d in ds) + ".")
        st = {v: ratio_to_proposed(runs, v, c, "frontKO") for v in VARIANT_TEXT if v != "proposed"}
        st = {v: x for v, x in st.items() if x}
        if st:
            out.append("Front error (Koshizuka & Oka) relative to the proposed method, geometric mean over the "
                       "resolutions (below 1: closer to the experiment): " +
                       ", ".join(f"`{v}` {x:.3g}x" for v, x in st.items()) + ".")
    cs = {v: cost_to_proposed(runs, v) for v in variants_in(runs) if v != "proposed"}
    cs = {v: x for v, x in cs.items() if x}
    if cs:
        lo, hi = min(cs.values()), max(cs.values())
        out.append("**Cost per particle-step** relative to the proposed method (particle-steps per second as the "
                   "solver reports it, geometric mean over the finest run of each case; above 1: dearer): " +
                   ", ".join(f"`{v}` {x:.3g}x" for v, x in cs.items()) +
                   f". On this shared machine these ratios carry the noise of single runs; the per-stage "
                   "split below (300-step runs at the paper's resolution) shows where the differences come "
                   f"from. The schemes change the cost of a step by {100 * (lo - 1):+.0f} % to {100 * (hi - 1):+.0f} %; "
                   "halving d0 multiplies the cost of a run by about 8 in 2D (4x the particles, 2x the steps; "
                   "16x where the viscous limit sets dt), so for a given accuracy the resolution is the "
                   "lever, the scheme the fine adjustment (see the per-stage split below for what each "
                   "choice adds to a step at the paper's resolution).")
    return out


def converge_text(runs, case, m):
    """How the proposed method's error moves with resolution, as a sentence."""
    ds = sorted({k[2] for k in runs if k[0] == case}, reverse=True)
    xs = [err(runs, case, "proposed", d, m) for d in ds]
    if len(xs) < 2 or not all(xs):
        return ""
    text = (f"With SPH2 it goes {' -> '.join(pct(x) for x in xs)} as "
            f"{' -> '.join(CASE_TEXT[case][1](d) for d in ds)}")
    if xs[-1] >= xs[-2]:
        text += (f"; the last refinement does not lower it, so below about {pct(min(xs))} this measure no "
                 "longer ranks the choices")
    return text + "."


def spread(runs, case, d0, m):
    """Range of an error over the SPH2 variants (shifting and stabilization choices)."""
    xs = [err(runs, case, v, d0, m) for v in ("proposed", "OPS", "noShift", "baseline", "proposed+stab")]
    xs = [x for x in xs if x is not None]
    return f"{pct(min(xs))} to {pct(max(xs))}" if xs else "-"


def write_doc(rows, stages, info):
    runs = runs_of(rows)
    os.makedirs(IMG, exist_ok=True)
    L = []
    add = L.append
    add("# What accuracy costs in time: the accuracy-cost study")
    add("")
    add("Generated by `bench/accuracy-cost/run` from `bench/results/accuracy-cost.csv` "
        "and `bench/results/accuracy-cost-stages.csv`; do not edit by hand: rerun the command.")
    add("")
    add("Every choice the case dictionaries offer (derivative operators, particle shifting, the stabilized "
        "pressure equation) changes both the answer and the time to get it. This study runs the regression "
        "cases whose answer is known (analytic, or the experiments) with each choice at several resolutions, "
        "and puts the error next to the wall time, so a user can pick the cheapest setting that meets the "
        "accuracy they need. The per-stage split at the paper's resolution (item 3) shows where a step's time "
        "goes. Throughput and the solver's own performance targets are in [performance.md](performance.md).")
    add("")
    add("## How to run")
    add("")
    add("```sh")
    add("bench/accuracy-cost/run                 # the whole study (2 threads, one run at a time)")
    add("bench/accuracy-cost/run --quick         # two coarse resolutions, short stage runs, no repeats (~2 min)")
    add("bench/accuracy-cost/run --only damBreak # rerun one case, keep the other rows of the CSV")
    add("bench/accuracy-cost/run --report-only   # rewrite this page and its plots from the CSVs")
    add("```")
    add("")
    add("Cases are copied into `build/accuracy-cost/` (`--work DIR` to change it), re-sized by rewriting "
        "`spacing` (system/particlesDict) and `deltaT` (system/controlDict), and run with "
        "`shizuku -case ... -threads 2` and `OMP_WAIT_POLICY=PASSIVE`. Wall time is measured by the script "
        "around the whole process; runs shorter than 5 s are repeated up to three times and the shortest wall "
        "time is kept (the machine may be shared; not with `--quick`). The errors are computed by the script from the "
        "`postProcessing/` files of each run.")
    add("")
    dates = sorted({r["date"] for r in rows})
    commits = sorted({r["commit"] for r in rows})
    loads = [num(r["load"]) for r in rows if num(r["load"]) is not None]
    add(f"Machine: {info.get('cpu', '?')}, {info.get('cores', '?')} cores; commit {', '.join(commits)}; "
        f"{', '.join(dates)}. Load average (1 min) at the start of the runs: "
        f"{min(loads):.2g} to {max(loads):.2g} (above 2: other work shared the two cores and wall times are "
        "inflated; the CSV also has each run's CPU seconds)." if loads else "No runs recorded.")
    if info.get("full_study_wall_s"):
        add(f"The whole default study (`bench/accuracy-cost/run`) last took "
            f"{float(info['full_study_wall_s']) / 60:.1f} min of wall time.")
    if info.get("total_wall_s"):
        add(f"The last invocation ({'quick' if info.get('quick') == '1' else 'default'} mode, parts "
            f"{info.get('parts', '?')}) took {float(info['total_wall_s']) / 60:.1f} min of wall time.")
    if info.get("quick") == "1":
        add("**Quick run (two coarse resolutions, 50-step stage runs): a smoke test, not the reference numbers.**")
    builds = sorted({r.get("build") or "?" for r in rows + stages})
    add(f"Solver binary built {', '.join(builds)} (each invocation runs a copy taken at its start, so a rebuild "
        "during the study cannot mix two builds" + ("; **the rows come from more than one build**)." if
                                                    len(builds) > 1 else ")."))
    add("")
    add("## Variants")
    add("")
    add("| variant | derivatives | shifting | PPE stabilization | what it is |")
    add("|---|---|---|---|---|")
    for v in variants_in(runs):
        r = next(r for k, r in runs.items() if k[1] == v)
        add(f"| `{v}` | {r['derivatives']} | {r['shifting']} | {r['stabilization']} | {VARIANT_TEXT[v]} |")
    add("")
    add("Shifting `proposed` = `distribution { type OPS; C 0.2; Rp 0.2; np 4; } volumeCorrection { C 0.1; } "
        "surfaceFitting { C 1e-4; maxCurvature 0.2; minDistance 0.15; maxDistance 0.6; } maxShift 0.1;`; "
        "`OPS` = the distribution term alone; `none` = no `shifting` entry. Stabilization `on` = "
        "`pressureStabilization { type densityInvariant; alpha 1e-3; }`. Every variant keeps the tutorials' "
        "cubic spline kernel (h = 1.2 d0), `ads { }` (ADS at 0.95 d0, the default since 2026-11-30) and `xsph { epsilon 0.5; }`, "
        "and the case's `constant/` files; `compressible` adds `soundSpeed 48` (eq. 6c) to damBreakWallPressure's; "
        "shifting `proposedNoTaylor` is `proposed` with `taylorCorrection off;`.")
    add("")
    add("## Cases and error measures")
    add("")
    for c in cases_in(runs):
        add(f"- **{c}**: {CASE_TEXT[c][0]}.")
        for m in measures_of(runs, c):
            if m in MEASURE_TEXT:
                add(f"  - `{m}`{' (the Pareto list below)' if PRIMARY[c] == m else ''}: {MEASURE_TEXT[m]}.")
    add("")
    add("## Results")
    for c in cases_in(runs):
        measures = measures_of(runs, c)
        add("")
        add(f"### {c}")
        add("")
        fname = f"{c}.png"
        plot_case(runs, c, os.path.join(IMG, fname))
        add(f"![{c}: error against wall time](images/accuracy-cost/{fname})")
        add("")
        add("| variant | resolution | d0 [m] | dt [s] | fluid particles | steps | " +
            " | ".join(f"`{m}`" for m in measures) + " | wall s | CPU s | particle-steps/s | load | status |")
        add("|" + "---|" * (11 + len(measures)))
        keys = sorted((k for k in runs if k[0] == c),
                      key=lambda k: (list(VARIANT_TEXT).index(k[1]) if k[1] in VARIANT_TEXT else 99, -k[2]))
        for k in keys:
            r = runs[k]
            add(f"| `{k[1]}` | {CASE_TEXT[c][1](k[2])} | {k[2]:g} | {r['dt']} | {r['particles'] or '-'} | "
                f"{r['steps'] or '-'} | " + " | ".join(pct(r["errors"].get(m)) for m in measures) +
                f" | {g(r['wall_s'])} | {g(r['cpu_s'])} | {g(r['particle_steps_per_s'])} | {r['load']} | "
                f"{status_cell(r)} |")
        pts = [(float(r["wall_s"]), r["errors"][PRIMARY[c]], f"`{k[1]}` {CASE_TEXT[c][1](k[2])}")
               for k, r in runs.items() if k[0] == c and r["status"] == "ok" and r["errors"].get(PRIMARY[c])]
        front = pareto(pts)
        add("")
        add(f"Pareto front for `{PRIMARY[c]}` (cheapest first; each is the most accurate run at its cost): " +
            "; ".join(f"{p[2]} ({pct(p[1])}, {p[0]:.3g} s)" for p in front) + ".")
    add("")
    add("## Reading: which choice for which need")
    add("")
    add("The cheapest run of this study that meets each need (wall time of the whole run on 2 threads; the "
        "bounds are examples, the CSV answers others):")
    add("")
    L.extend(needs_table(runs))
    add("")
    for b in reading(runs):
        add(f"- {b}")
    add("")
    st = stage_table(stages)
    add("## Where the time of a step goes")
    add("")
    if not st:
        add("No stage runs recorded.")
    else:
        e0 = next(iter(st.values()))
        add(f"The paper's two cases at the paper's resolution: `tutorials/rotatingSquarePatch` (L = 1 m, "
            f"L/d0 = 100) and `tutorials/damBreak` (80 x 50 cm column, d0 = 1 cm), dt = 1e-4 s, **{e0['steps']} "
            f"steps measured** from the start (t <= {float(e0['steps']) * 1e-4:g} s: the start of each flow; later "
            "states, with splashes and more free-surface particles, are not measured here), 2 threads, every "
            "variant, each run " + ("once" if info.get("quick") == "1" else
                                    "three times, keeping the shortest process wall time and, stage by stage, "
                                    "the shortest stage time (another job on the two cores inflates some stages "
                                    "of some runs; the minimum is the best estimate of the unshared cost)") + ". "
            "The numbers are the `timing` function object's per-stage wall seconds (`postProcessing/timing/0/"
            "timing.dat`, summed over its rows), divided by steps x fluid particles. The stage timers are "
            "disjoint: `shifting` is the shared part (velocity gradient for the Taylor correction, geometry and "
            "density refresh, cap, move) and `shift terms` the distribution, volume-correction and "
            "surface-fitting terms themselves.")
        add("")
        for b in stage_summary(st):
            add(f"- {b}")
        add("")
        if plot_stages(st, os.path.join(IMG, "stages.png")):
            add("![per-stage cost](images/accuracy-cost/stages.png)")
            add("")
        for case in ("rotatingSquarePatch", "damBreak"):
            vs = [v for v in VARIANT_TEXT if (case, v) in st]
            if not vs:
                continue
            e = st[(case, vs[0])]
            add(f"**{case}** ({e['particles']} fluid + {e['wall_particles']} wall particles, {e['steps']} steps), "
                "us per particle-step by stage:")
            add("")
            add("| variant | steps | wall s | CPU s | load | stage total | x proposed | " +
                " | ".join(n for n, _ in GROUPS) + " | status |")
            add("|" + "---|" * (8 + len(GROUPS)))
            ref = st.get((case, "proposed"))
            for v in vs:
                e = st[(case, v)]
                ps = (num(e["steps"]) or 0) * (num(e["particles"]) or 0)
                tot = e["total"] / ps * 1e6 if ps else None
                rel = e["total"] / ref["total"] if ref and ref["total"] and ref["steps"] == e["steps"] else None
                add(f"| `{v}` | {e['steps']} | {g(e['wall_s'])} | {g(e.get('cpu_s'))} | {e['load']} | {g(tot)} | "
                    f"{g(rel)} | " +
                    " | ".join(g(e["groups"][n], 2) for n, _ in GROUPS) + f" | {e['status']} |")
            add("")
            if (case, "proposed") in st:
                e = st[(case, "proposed")]
                tot = e["total"]
                ps = float(e["steps"]) * float(e["particles"])
                add(f"The proposed method in detail ({case}, {e['steps']} steps, stage total {tot:.3g} s of "
                    f"{float(e['wall_s']):.3g} s process wall time, the shortest of the repeats):")
                add("")
                add("| stage | s | ms per step | us per particle-step | share |")
                add("|---|---|---|---|---|")
                for s, sec in sorted(e["raw"].items(), key=lambda kv: -kv[1]):
                    add(f"| {s} | {sec:.3g} | {1e3 * sec / float(e['steps']):.3g} | {1e6 * sec / ps:.3g} | "
                        f"{100 * sec / tot:.1f} % |")
                add("")
    with open(DOC, "w") as f:
        f.write("\n".join(L).rstrip() + "\n")
    print(f"accuracy-cost: wrote {os.path.relpath(DOC, ROOT)} and {os.path.relpath(IMG, ROOT)}/")


def main():
    rows, stages, info = load()
    write_doc(rows, stages, info)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
