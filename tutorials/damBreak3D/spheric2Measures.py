#!/usr/bin/python3
"""The measures that compare a damBreak3D run with SPHERIC Test 2 (Kleefsman et al. 2005).

usage: spheric2Measures.py [CASE ...] [--label NAME ...] [--plot PREFIX] [--until T]

For each case folder (default: this one) it reads the sensors
postProcessing/P1..P8/0/wallPressure.dat (column p_lowPass: the disc's mean pressure,
first-order low-pass at 100 Hz) and the gauges postProcessing/gauges/0/height.dat
(point0..point3 = H1..H4), and the experiment data/kleefsman2005.csv, whose pressures are
passed through the same 100 Hz first-order filter (the same measure on both sides; the
heights are compared unfiltered). Up to the case's last time (or --until) it prints:
  H1..H3 arrival   first t where the height exceeds 0.02 m (the front reaching the gauge)
  H1..H4 error     rms of h_run - h_exp over the run, on the experiment's 1 kHz times (m;
                   height_error gives it over any window)
  P1..P8 arrival   first t where the filtered pressure exceeds 500 Pa
  P1..P8 peak      largest filtered pressure and its time
for the run and the experiment side by side. --plot PREFIX draws PREFIX_heights.png and
PREFIX_pressures.png (each run over the experiment). The run's time series are
interpolated linearly to the experiment's times. Needs Debian's python3 with numpy and
matplotlib.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("SHIZUKU_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")), "utilities"))
import shizukuPost  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CUTOFF = 100.0        # Hz, the sensors' filter in system/controlDict
WET = 0.02            # m: a gauge is reached when the height exceeds this
LOADED = 500.0        # Pa: a sensor is hit when the filtered pressure exceeds this
GAUGES = ["H1", "H2", "H3", "H4"]
SENSORS = ["P%d" % k for k in range(1, 9)]


def low_pass(t, p, cutoff=CUTOFF):
    """First-order low-pass, the solver's LowPassFilter (first-order hold between samples)."""
    tau = 1.0 / (2 * np.pi * cutoff)
    y = np.empty_like(p)
    y[0] = p[0]
    for k in range(1, len(p)):
        dt = t[k] - t[k - 1]
        a = np.exp(-dt / tau)
        # exact response to a linear input between the samples
        b = tau / dt * (1 - a) if dt > 0 else 1.0
        y[k] = a * y[k - 1] + (1 - b) * p[k] + (b - a) * p[k - 1]
    return y


def read_columns(path):
    header, _, tokens = shizukuPost.read_tokens(path)
    rows = np.array([[float(x) for x in r] for r in tokens])
    return {name: rows[:, i] for i, name in enumerate(header)}


def read_run(case):
    out = {}
    g = read_columns(os.path.join(case, "postProcessing", "gauges", "0", "height.dat"))
    for k, name in enumerate(GAUGES):
        out[name] = (g["time"], g["point%d" % k])
    for name in SENSORS:
        s = read_columns(os.path.join(case, "postProcessing", name, "0", "wallPressure.dat"))
        out[name] = (s["time"], s["p_lowPass"])
    return out


def read_experiment(path=os.path.join(HERE, "data", "kleefsman2005.csv")):
    data = np.genfromtxt(path, delimiter=",", names=True)
    t = data["t_s"]
    out = {}
    for k, name in enumerate(GAUGES):
        col = [c for c in data.dtype.names if c.startswith(name + "_")][0]
        out[name] = (t, data[col])
    for name in SENSORS:
        out[name] = (t, low_pass(t, data[name + "_Pa"]))
    return out


def first_above(t, v, level):
    i = np.nonzero(v > level)[0]
    return float(t[i[0]]) if len(i) else float("nan")


def height_error(run, exp, name, start, end):
    """rms of h_run - h_exp at gauge `name` over the experiment's times in (start, end] (m)."""
    tr, hr = run[name]
    te, he = exp[name]
    m = (te > start) & (te <= min(end, tr[-1]))
    return float(np.sqrt(np.mean((np.interp(te[m], tr, hr) - he[m]) ** 2)))


def measures(run, exp, until):
    """{name: {measure: (run, experiment)}} up to time `until`."""
    out = {}
    for name in GAUGES:
        tr, hr = run[name]
        te, he = exp[name]
        m = te <= until
        out[name] = {"error": (height_error(run, exp, name, -np.inf, until), 0.0)}
        if name != "H4":
            out[name]["arrival"] = (first_above(tr, hr, WET), first_above(te[m], he[m], WET))
    for name in SENSORS:
        tr, pr = run[name]
        te, pe = exp[name]
        m, mr = te <= until, tr <= until
        ir, ie = np.argmax(pr[mr]), np.argmax(pe[m])
        out[name] = {"arrival": (first_above(tr[mr], pr[mr], LOADED), first_above(te[m], pe[m], LOADED)),
                     "peak": (float(pr[mr][ir]), float(pe[m][ie])),
                     "peakTime": (float(tr[mr][ir]), float(te[m][ie]))}
    return out


def print_measures(label, res, until):
    print("%s (up to t = %.3f s): measure  run  experiment" % (label, until))
    for name, ms in res.items():
        for key, (a, b) in ms.items():
            print("  %-3s %-9s %12.5g %12.5g" % (name, key, a, b))


def plot(prefix, runs, exp, until):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    for kind, names, unit in (("heights", GAUGES, "h [m]"), ("pressures", SENSORS, "p [Pa], 100 Hz low-pass")):
        rows = 2 if kind == "heights" else 4
        fig, axes = plt.subplots(rows, 2, figsize=(10, 2.6 * rows), sharex=True)
        for ax, name in zip(axes.flat, names):
            te, ve = exp[name]
            m = te <= until
            ax.plot(te[m], ve[m], "k-", lw=0.8, label="experiment (Kleefsman et al. 2005)")
            for label, run in runs:
                tr, vr = run[name]
                ax.plot(tr, vr, lw=0.9, label=label)
            ax.set_title(name, fontsize=9)
            ax.set_ylabel(unit, fontsize=8)
            ax.grid(alpha=0.3)
        for ax in axes[-1]:
            ax.set_xlabel("t [s]")
        axes.flat[0].legend(fontsize=7)
        fig.suptitle("SPHERIC Test 2: %s" % kind)
        fig.tight_layout()
        fig.savefig("%s_%s.png" % (prefix, kind), dpi=110)
        plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("cases", nargs="*", default=[HERE])
    ap.add_argument("--label", action="append", default=[])
    ap.add_argument("--plot")
    ap.add_argument("--until", type=float)
    a = ap.parse_args(argv)
    exp = read_experiment()
    runs = []
    for k, case in enumerate(a.cases):
        label = a.label[k] if k < len(a.label) else os.path.basename(os.path.abspath(case))
        try:
            run = read_run(case)
        except (OSError, shizukuPost.InputError) as e:
            print("spheric2Measures.py: %s" % e, file=sys.stderr)
            return 1
        until = a.until if a.until else float(run["H1"][0][-1])
        print_measures(label, measures(run, exp, until), until)
        runs.append((label, run))
    if a.plot:
        until = a.until if a.until else max(float(r["H1"][0][-1]) for _, r in runs)
        plot(a.plot, runs, exp, until)
    return 0


if __name__ == "__main__":
    sys.exit(main())
