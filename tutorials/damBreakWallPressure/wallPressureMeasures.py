#!/usr/bin/python3
"""The measures of a far-wall pressure history that issue 18 compares with Buchner (2002).

usage: wallPressureMeasures.py [CASE ...] [--label NAME ...] [--plot OUT.png] [--H 0.6]
       wallPressureMeasures.py --experiment CSV

Time is t* = t sqrt(g/H), pressure p* = p/(rho g H). For each case folder (default: this
one) it reads postProcessing/P1/0/wallPressure.dat (raw column `p`, filtered column
`p_lowPass` when present) and prints:
  crossing   first t* where the raw p* exceeds 0.3
  peak1      largest filtered p* for t* < 3.5, and its t*
  plateau    mean raw p* over 3.5 <= t* <= 5.5
  peak2      largest filtered p* for 5.5 <= t* <= 6.5, and its t*
  noise      rms of raw p* about its centred moving average over a window of 0.1 in t*,
             over the plateau 3.5 <= t* <= 5.5 (unfiltered)
  interiorNoise  the same noise of the `interior` probe, inside the water 0.12 m from the
             wall and 8 cm up (nan without it)
  balance    the horizontal impulse balance over the plateau (nan without the `farWall`
             and `leftWall` sensors and `conservation`): the change of the water's x
             momentum against the walls' impulse on it, I_left - I_far, as a share of I_far,
             |dM_x - (I_left - I_far)| / I_far. The walls are the only horizontal force on
             the water, so the share is zero when the pressure the sensors read is the
             force the water feels (Newton's third law at the wall); the floor's viscous
             stress and the rest of the discretisation's imbalance are in the share.
The same measures on an experiment's digitised points (a few points per unit t*: the noise
cannot be measured there and is printed as nan; peaks from the points themselves).
--plot draws each case's raw and filtered P1 over the two digitised experiments in data/
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


def measures(t, p, pf, noise=True):
    out = {}
    above = np.nonzero(p > 0.3)[0]
    out["crossing"] = float(t[above[0]]) if len(above) else float("nan")
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
        out["noise"] = float(np.sqrt(np.mean((p[m] - avg[m]) ** 2)))
    else:
        out["noise"] = float("nan")
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


def plot(cases, labels, out, H, rho, g):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(8, 4))
    for name, style in (("buchnerP1_trixiparticles.csv", "ko"), ("buchnerP1_pysph.csv", "k^")):
        d = np.loadtxt(os.path.join(HERE, "data", name), delimiter=",", skiprows=1)
        ax.plot(d[:, 0], d[:, 1], style, ms=3, mfc="none", label="Buchner (2002) P1, " + name.split("_")[1][:-4])
    for case, label in zip(cases, labels):
        t, p, pf = read_run(os.path.join(case, "postProcessing", "P1", "0", "wallPressure.dat"), H, rho, g)
        line, = ax.plot(t, p, lw=0.4, alpha=0.5)
        ax.plot(t, pf, lw=1.2, color=line.get_color(), label=label + " (100 Hz low-pass; thin: raw)")
    ax.set_xlim(2, 7.5)
    ax.set_ylim(-0.3, 1.6)
    ax.set_xlabel("t sqrt(g/H)")
    ax.set_ylabel("p / (rho g H)")
    ax.legend(fontsize=7, loc="upper left")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"{out}: P1 of {len(cases)} run(s) over the experiment")


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="*", default=["."])
    ap.add_argument("--label", nargs="*")
    ap.add_argument("--plot")
    ap.add_argument("--experiment")
    ap.add_argument("--H", type=float, default=0.6)
    ap.add_argument("--rho", type=float, default=1000.0)
    ap.add_argument("--g", type=float, default=9.81)
    a = ap.parse_args()
    if a.experiment:
        d = np.loadtxt(a.experiment, delimiter=",", skiprows=1)
        d = d[np.argsort(d[:, 0], kind="stable")]
        rows = [("experiment", measures(d[:, 0], d[:, 1], d[:, 1], noise=False))]
    else:
        rows = [(c, dict(measures(*read_run(os.path.join(c, "postProcessing", "P1", "0", "wallPressure.dat"),
                                            a.H, a.rho, a.g)),
                         interiorNoise=interior_noise(c, a.H, a.rho, a.g),
                         balance=impulse_balance(c, a.H, a.g))) for c in a.cases]
    for name, res in rows:
        print(name + ": " + " ".join("%s %.4g" % kv for kv in res.items()))
    if a.plot:
        plot(a.cases, a.label or a.cases, a.plot, a.H, a.rho, a.g)
    return 0


if __name__ == "__main__":
    sys.exit(main())
