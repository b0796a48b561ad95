#!/usr/bin/python3
"""The measures of a far-wall pressure history that issue 18 compares with Buchner (2002).

usage: wallPressureMeasures.py [CASE ...] [--sensor P1] [--label NAME ...] [--plot OUT.png]
                               [--heights] [--plotHeights OUT.png] [--plotLiterature OUT.png] [--H 0.6]
       wallPressureMeasures.py --experiment CSV
       wallPressureMeasures.py --literature

Time is t* = t sqrt(g/H), pressure p* = p/(rho g H). For each case folder (default: this
one) it reads postProcessing/P1/0/wallPressure.dat (or another sensor's, --sensor NAME; raw
column `p`, filtered column `p_lowPass` when present) and prints:
  crossing   first t* where the raw p* exceeds 0.3 (issue 18's measure: on a signal that
             rises slowly, as the converged model's does at P1, the first spike above 0.3)
  crossingMean  first t* where the centred moving average of the raw p* over 0.1 in t*
             exceeds 0.3 (the rise of the pressure the water holds, not its first spike)
  peak1      largest filtered p* for t* < 3.5, and its t*
  plateau    mean raw p* over 3.5 <= t* <= 5.5
  peak2      largest filtered p* for 5.5 <= t* <= 6.5, and its t*
  noise      rms of raw p* about its centred moving average over a window of 0.1 in t*,
             over the plateau 3.5 <= t* <= 5.5 (unfiltered)
  noiseRobust   the same deviations' median absolute deviation times 1.4826 (the rms of
             normal noise): the background without the few one-step spikes of an
             incompressible merge (an air gap closing beside the sensor), which set the rms
  interiorNoise  the same noise of the `interior` probe, inside the water 0.12 m from the
             wall and 8 cm up (nan without it)
  balance    the horizontal impulse balance over the plateau (nan without the `farWall`
             and `leftWall` sensors and `conservation`): the change of the water's x
             momentum against the walls' impulse on it, I_left - I_far, as a share of I_far,
             |dM_x - (I_left - I_far)| / I_far. The walls are the only horizontal force on
             the water, so the share is zero when the pressure the sensors read is the
             force the water feels (Newton's third law at the wall); the floor's viscous
             stress and the rest of the discretisation's imbalance are in the share.
--heights prints, at the four heights of Lobovsky et al. (2014)'s sensors scaled to this
tank (S1, S2, S3 and P1: 6, 30, 60 and 160 mm up), the mean p* over the windows
t* = 2.6-3, 3-3.5, 3.5-4.5, 4.5-5.5 and the plateau 3.5-5.5, for each case and for the
references in data/ (README.md there): converged runs of the same equations by other codes
(De Courcy et al. 2024; TrixiParticles.jl's WCSPH and EDAC, all at H/400) and two
experiments (Lobovsky et al. 2014 at H = 0.3 m; Buchner 2002 at P1 only), and each case's
deviation from the mean of the three converged runs' plateaus. --plotHeights draws the same
four sensors.
The same measures on an experiment's digitised points (a few points per unit t*: the noise
cannot be measured there and is printed as nan; peaks from the points themselves).
--literature prints the same measures for the published runs that read P1 with the probe of
Adami et al. (2012) and Marrone et al. (2011), 90 mm tall with its top at 160 mm (70-160 mm,
centre 115 mm; the tutorial's `P1probe90mm`): Marrone et al.'s delta-SPH at H/40, H/80 and
H/320 (digitised) and TrixiParticles.jl's WCSPH and EDAC at H/320 (sampled every 0.02 s,
0.08 in t*); data/README.md.
--plotLiterature draws each case's `P1probe90mm` over those runs and the experiment.
--plot draws each case's raw and filtered sensor over the two digitised experiments in data/
(rho = 1000, g = 9.81 unless --rho, --g). Needs Debian's python3 with numpy and matplotlib.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("SHIZUKU_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")), "utilities"))
import shizukuPost  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))

PLATEAU = (3.5, 5.5)
WINDOW = 0.1


def read_run(path, H=0.6, rho=1000.0, g=9.81):
    header, _, tokens = shizukuPost.read_tokens(path)
    rows = np.array([[float(x) for x in r] for r in tokens])
    scale_t, scale_p = np.sqrt(g / H), rho * g * H
    t = rows[:, 0] * scale_t
    p = rows[:, header.index("p")] / scale_p
    pf = rows[:, header.index("p_lowPass")] / scale_p if "p_lowPass" in header else p
    return t, p, pf


def moving_average(t, p, width):
    """Centred running mean over [t - width/2, t + width/2] (trapezoid-free: sample mean)."""
    c = np.concatenate(([0.0], np.cumsum(p)))
    lo = np.searchsorted(t, t - width / 2, side="left")
    hi = np.searchsorted(t, t + width / 2, side="right")
    return (c[hi] - c[lo]) / (hi - lo)


def first_above(t, p, level=0.3):
    """The first t* at which p* exceeds `level` (nan if it never does)."""
    above = np.nonzero(p > level)[0]
    return float(t[above[0]]) if len(above) else float("nan")


def measures(t, p, pf, noise=True):
    out = {}
    out["crossing"] = first_above(t, p)
    out["crossingMean"] = first_above(t, moving_average(t, p, WINDOW))
    m = t < PLATEAU[0]
    i = np.argmax(np.where(m, pf, -np.inf))
    out["peak1"], out["peak1_t"] = float(pf[i]), float(t[i])
    m = (t >= PLATEAU[0]) & (t <= PLATEAU[1])
    out["plateau"] = float(np.mean(p[m]))
    m2 = (t >= 5.5) & (t <= 6.5)
    if m2.any():
        i = np.argmax(np.where(m2, pf, -np.inf))
        out["peak2"], out["peak2_t"] = float(pf[i]), float(t[i])
    else:
        out["peak2"] = out["peak2_t"] = float("nan")
    if noise:
        avg = moving_average(t, p, WINDOW)
        dev = p[m] - avg[m]
        out["noise"] = float(np.sqrt(np.mean(dev ** 2)))
        out["noiseRobust"] = float(1.4826 * np.median(np.abs(dev - np.median(dev))))
    else:
        out["noise"] = out["noiseRobust"] = float("nan")
    return out


def interior_noise(case, H, rho, g):
    """Noise of the `interior` probe (raw p inside the water 0.12 m from the wall, 8 cm up), the same
    measure as the sensor's over the plateau; nan when the case has no such probe."""
    path = os.path.join(case, "postProcessing", "interior", "0", "p")
    if not os.path.exists(path):
        return float("nan")
    _, _, tokens = shizukuPost.read_tokens(path)
    rows = np.array([[float(x) for x in r] for r in tokens])
    t, p = rows[:, 0] * np.sqrt(g / H), rows[:, 1] / (rho * g * H)
    ok = np.isfinite(p)
    t, p = t[ok], p[ok]
    m = (t >= PLATEAU[0]) & (t <= PLATEAU[1])
    if not m.any():
        return float("nan")
    return float(np.sqrt(np.mean((p[m] - moving_average(t, p, WINDOW)[m]) ** 2)))


def _columns(path, *names):
    header, _, tokens = shizukuPost.read_tokens(path)
    cols = [header.index(n) for n in names]
    return [np.array([float(r[c].strip("()").split()[0]) for r in tokens]) for c in cols]


def impulse_balance(case, H=0.6, g=9.81, window=PLATEAU):
    """|dM_x - (I_left - I_far)| / I_far over `window` in t* (nan without the files)."""
    pp = os.path.join(case, "postProcessing")
    paths = [os.path.join(pp, n, "0", f) for n, f in (("conservation", "conservation.dat"),
                                                       ("leftWall", "wallPressure.dat"),
                                                       ("farWall", "wallPressure.dat"))]
    if not all(os.path.exists(p) for p in paths):
        return float("nan")
    lo, hi = (w / np.sqrt(g / H) for w in window)
    t, mx = _columns(paths[0], "time", "momentum")
    if t[-1] < hi:
        return float("nan")
    change = [np.interp(hi, t, mx) - np.interp(lo, t, mx)]
    for path in paths[1:]:
        tw, imp = _columns(path, "time", "impulse")
        change.append(np.interp(hi, tw, imp) - np.interp(lo, tw, imp))
    dm, left, far = change
    return float(abs(dm - (left - far)) / far)


# Lobovsky et al. (2014)'s sensors 1-4 scaled to H = 0.6 m, and this case's sensors there.
HEIGHTS = (("S1", 0.006), ("S2", 0.030), ("S3", 0.060), ("P1", 0.160))
WINDOWS = ((2.6, 3.0), (3.0, 3.5), (3.5, 4.5), (4.5, 5.5), PLATEAU)


def window_means(t, p):
    """Time mean of p* over each of WINDOWS: the signal linearly interpolated onto a uniform
    grid of 0.001 in t*, since the runs' steps and the digitised curves are not uniform."""
    return [float(np.mean(np.interp(np.arange(a, b, 0.001), t, p))) for a, b in WINDOWS]


def references():
    """{source: {sensor: (t*, p*)}} for the converged runs and experiments in data/."""
    data = os.path.join(HERE, "data")
    out = {"De Courcy 2024 (H/400)": {}}
    d = np.genfromtxt(os.path.join(data, "deCourcy2024_sensors.csv"), delimiter=",", names=True, dtype=None,
                      encoding="ascii")
    for (name, _), ref in zip(HEIGHTS, ("P1", "P2", "P3", "P4")):
        r = d[d["sensor"] == ref]
        order = np.argsort(r["t_sqrt_g_over_H"], kind="stable")
        out["De Courcy 2024 (H/400)"][name] = (r["t_sqrt_g_over_H"][order], r["p_over_rho_g_H"][order])
    for scheme in ("wcsph", "edac"):
        d = np.loadtxt(os.path.join(data, f"trixiparticles_{scheme}_H400_sensors.csv"), delimiter=",", skiprows=1)
        out[f"TrixiParticles {scheme.upper()} (H/400)"] = {name: (d[:, 0], d[:, k + 1])
                                                           for k, (name, _) in enumerate(HEIGHTS)}
    d = np.loadtxt(os.path.join(data, "lobovsky2014_H300_sensors.csv.gz"), delimiter=",", skiprows=1)
    out["Lobovsky 2014 (experiment)"] = {name: (d[:, 0], d[:, k + 1]) for k, (name, _) in enumerate(HEIGHTS)}
    d = np.loadtxt(os.path.join(data, "buchnerP1_trixiparticles.csv"), delimiter=",", skiprows=1)
    out["Buchner 2002 (experiment)"] = {"P1": (d[:, 0], d[:, 1])}
    return out


CONVERGED = ("De Courcy 2024 (H/400)", "TrixiParticles WCSPH (H/400)", "TrixiParticles EDAC (H/400)")


def converged(refs=None):
    """{sensor: (mean, spread)} of the plateau means of the three converged runs (spread: the
    largest minus the smallest), the answer of the equations that the resolution study converges to."""
    refs = refs or references()
    out = {}
    for name, _ in HEIGHTS:
        v = [window_means(*refs[source][name])[-1] for source in CONVERGED]
        out[name] = (float(np.mean(v)), float(max(v) - min(v)))
    return out


def converged_crossing(refs=None, name="P1"):
    """(mean, spread) of the converged runs' crossingMean at sensor `name`, each history
    interpolated onto a uniform grid of 0.01 in t* first (De Courcy's digitised points are not
    uniform)."""
    refs = refs or references()
    v = []
    for source in CONVERGED:
        t, p = refs[source][name]
        grid = np.arange(t[0], t[-1], 0.01)
        v.append(first_above(grid, moving_average(grid, np.interp(grid, t, p), WINDOW)))
    return float(np.mean(v)), float(max(v) - min(v))


def sensor_history(case, name, H=0.6, rho=1000.0, g=9.81):
    """(t*, raw p*) of a case's wallPressure sensor `name`, or None when the case has none."""
    path = os.path.join(case, "postProcessing", name, "0", "wallPressure.dat")
    return read_run(path, H, rho, g)[:2] if os.path.exists(path) else None


def heights(case, H=0.6, rho=1000.0, g=9.81):
    """{sensor: window means} of a case at the four heights (sensors it lacks are left out)."""
    histories = {name: sensor_history(case, name, H, rho, g) for name, _ in HEIGHTS}
    return {name: window_means(*h) for name, h in histories.items() if h is not None}


def print_heights(cases, labels, H, rho, g):
    refs = references()
    conv = converged(refs)
    reached = [heights(case, H, rho, g) for case in cases]
    print("mean p* over t* = " + ", ".join("%g-%g" % w for w in WINDOWS) + " (the last: the plateau)")
    for name, y in HEIGHTS:
        print(f"{name} ({1000 * y:.0f} mm up, {y / H:.3f} H):")
        for source, sensors in refs.items():
            if name in sensors:
                print("  %-34s %s" % (source, " ".join("%6.3f" % v for v in window_means(*sensors[name]))))
        for label, means in zip(labels, reached):
            m = means.get(name)
            if m:
                print("  %-34s %s   plateau %+.1f %% from the converged runs' %.3f (spread %.3f)"
                      % (label, " ".join("%6.3f" % v for v in m), 100 * (m[-1] / conv[name][0] - 1), *conv[name]))


def plot_heights(cases, labels, out, H, rho, g):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    refs = references()
    fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    styles = {"De Courcy 2024 (H/400)": dict(color="k", lw=1.6),
              "TrixiParticles WCSPH (H/400)": dict(color="0.45", lw=1.0, ls="--"),
              "TrixiParticles EDAC (H/400)": dict(color="0.45", lw=1.0, ls=":"),
              "Lobovsky 2014 (experiment)": dict(color="tab:red", lw=0.5, alpha=0.6),
              "Buchner 2002 (experiment)": dict(color="tab:red", marker="o", ms=3, mfc="none", ls="none")}
    for ax, (name, y) in zip(axes.flat, HEIGHTS):
        for source, sensors in refs.items():
            if name in sensors:
                ax.plot(*sensors[name], label=source, **styles[source])
        for case, label in zip(cases, labels):
            h = sensor_history(case, name, H, rho, g)
            if h is not None:
                ax.plot(h[0], moving_average(*h, 0.05), lw=1.0, label=label + " (0.05 moving average)")
        ax.set_title(f"{name}: {1000 * y:.0f} mm up ({y / H:.3f} H)", fontsize=9)
        ax.set_xlim(2, 7.5)
        ax.set_ylim(-0.2, 2.5 if y < 0.1 else 1.6)
        ax.set_ylabel("p / (rho g H)")
    for ax in axes[1]:
        ax.set_xlabel("t sqrt(g/H)")
    axes[0, 0].legend(fontsize=6, loc="upper right")
    axes[1, 1].legend(fontsize=6, loc="upper left")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"{out}: four sensor heights of {len(cases)} run(s) against the converged runs and the experiments")


def _finish_history(fig, ax, out):
    """Axes, legend and file of a p* history figure over t* = 2-7.5."""
    ax.set_xlim(2, 7.5)
    ax.set_ylim(-0.3, 1.6)
    ax.set_xlabel("t sqrt(g/H)")
    ax.set_ylabel("p / (rho g H)")
    ax.legend(fontsize=7, loc="upper left")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out, dpi=120, bbox_inches="tight")


def plot(cases, labels, out, H, rho, g, sensor="P1"):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 4))
    for name, style in (("buchnerP1_trixiparticles.csv", "ko"), ("buchnerP1_pysph.csv", "k^")):
        d = np.loadtxt(os.path.join(HERE, "data", name), delimiter=",", skiprows=1)
        ax.plot(d[:, 0], d[:, 1], style, ms=3, mfc="none", label="Buchner (2002) P1, " + name.split("_")[1][:-4])
    for case, label in zip(cases, labels):
        t, p, pf = read_run(os.path.join(case, "postProcessing", sensor, "0", "wallPressure.dat"), H, rho, g)
        line, = ax.plot(t, p, lw=0.4, alpha=0.5)
        ax.plot(t, pf, lw=1.2, color=line.get_color(), label=label + " (100 Hz low-pass; thin: raw)")
    _finish_history(fig, ax, out)
    print(f"{out}: {sensor} of {len(cases)} run(s) over the experiment")


def plot_literature(cases, labels, out, H, rho, g, sensor="P1probe90mm"):
    """Each case's 90 mm probe (`P1probe90mm` unless --sensor names another, 100 Hz low-pass) over the
    published runs read the same way and the experiment's P1; cases without that sensor are left out."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 4))
    d = np.loadtxt(os.path.join(HERE, "data", "buchnerP1_trixiparticles.csv"), delimiter=",", skiprows=1)
    ax.plot(d[:, 0], d[:, 1], "ko", ms=3, mfc="none", label="Buchner (2002) P1 (centre 160 mm)")
    for label, t, p in literature_probe_references():
        if "H/320" in label:
            ax.plot(t, p, "--", lw=1.0, label=label + ", 90 mm probe")
    drawn = 0
    for case, label in zip(cases, labels):
        path = os.path.join(case, "postProcessing", sensor, "0", "wallPressure.dat")
        if os.path.exists(path):
            t, p, pf = read_run(path, H, rho, g)
            ax.plot(t, pf, lw=1.2, label=label + ", 90 mm probe (100 Hz low-pass)")
            drawn += 1
    _finish_history(fig, ax, out)
    print(f"{out}: {sensor} of {drawn} run(s) over the published runs and the experiment")


def literature_probe_references():
    """(label, t*, p*) of the published runs read with the 90 mm probe (data/README.md). The digitised
    curves are resampled every 0.005 in t*, so that time means are not weighted by where the digitiser
    clicked."""
    d = np.loadtxt(os.path.join(HERE, "data", "marrone2011_P1_deltaSPH.csv"), delimiter=",", skiprows=1)
    t = np.arange(d[0, 0], d[-1, 0], 0.005)
    out = [("Marrone 2011 delta-SPH " + name, t, np.interp(t, d[:, 0], d[:, col]))
           for name, col in (("H/40", 2), ("H/80", 4), ("H/320", 3))]
    d = np.loadtxt(os.path.join(HERE, "data", "trixiparticles_probe90mm_H320_P1.csv"), delimiter=",", skiprows=1)
    out += [("TrixiParticles WCSPH H/320", d[:, 0], d[:, 1]), ("TrixiParticles EDAC H/320", d[:, 0], d[:, 2])]
    return out


def literature_probe_converged():
    """(mean, spread) of the plateau time means of the three published runs at H/320 read with the 90 mm
    probe (Marrone et al.'s delta-SPH, TrixiParticles' WCSPH and EDAC; spread: largest minus smallest)."""
    v = [window_means(t, p)[-1] for label, t, p in literature_probe_references() if "H/320" in label]
    return float(np.mean(v)), float(max(v) - min(v))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="*", default=["."])
    ap.add_argument("--label", nargs="*")
    ap.add_argument("--plot")
    ap.add_argument("--experiment")
    ap.add_argument("--sensor")
    ap.add_argument("--literature", action="store_true")
    ap.add_argument("--plotLiterature")
    ap.add_argument("--heights", action="store_true")
    ap.add_argument("--plotHeights")
    ap.add_argument("--H", type=float, default=0.6)
    ap.add_argument("--rho", type=float, default=1000.0)
    ap.add_argument("--g", type=float, default=9.81)
    a = ap.parse_args()
    if a.experiment:
        d = np.loadtxt(a.experiment, delimiter=",", skiprows=1)
        d = d[np.argsort(d[:, 0], kind="stable")]
        rows = [("experiment", measures(d[:, 0], d[:, 1], d[:, 1], noise=False))]
    elif a.literature:
        rows = [(label, measures(t, p, p, noise=False)) for label, t, p in literature_probe_references()]
    else:
        rows = [(c, dict(measures(*read_run(os.path.join(c, "postProcessing", a.sensor or "P1", "0", "wallPressure.dat"),
                                            a.H, a.rho, a.g)),
                         interiorNoise=interior_noise(c, a.H, a.rho, a.g),
                         balance=impulse_balance(c, a.H, a.g))) for c in a.cases]
    for name, res in rows:
        print(name + ": " + " ".join("%s %.4g" % kv for kv in res.items()))
    labels = a.label or a.cases
    if a.heights:
        print("the converged runs' crossingMean at P1: %.3f (spread %.3f)" % converged_crossing())
        print_heights(a.cases, labels, a.H, a.rho, a.g)
    if a.plotHeights:
        plot_heights(a.cases, labels, a.plotHeights, a.H, a.rho, a.g)
    if a.plotLiterature:
        plot_literature(a.cases, labels, a.plotLiterature, a.H, a.rho, a.g, a.sensor or "P1probe90mm")
    if a.plot:
        plot(a.cases, a.label or a.cases, a.plot, a.H, a.rho, a.g, a.sensor or "P1")
    return 0


if __name__ == "__main__":
    sys.exit(main())
