#!/usr/bin/python3
"""The measures of the sloshing tutorial against linear theory (docs/validation.md, "Sloshing").

usage: sloshMeasures.py [CASE ...] [--label NAME ...] [--L 1] [--h 0.5] [--a 0.02] [--window S] [--plot OUT.png]
       sloshMeasures.py --forced CASE --plot OUT.png
       sloshMeasures.py --spheric CASE [--plot OUT.png]

Free decay of the first mode: for each case folder (default: this one) it reads the wave
gauges postProcessing/gauges/0/elevation.dat (gauge0 0.1 m from the left wall) and prints
  period     the first mode's period at the gauge: the least-squares fit of
             c + A exp(-gamma t) sin(omega t + phi) to eta over 0 <= t <= window (default two
             periods of linear theory), period = 2 pi / omega (scipy.optimize.curve_fit)
  theory     T1 = 2 pi / omega_1, omega_1^2 = g (pi/L) tanh(pi h/L)  (linear, inviscid)
  error      (period - theory) / theory, %
  amplitude  the fitted A over a cos(k x_gauge) (1: the linear mode's amplitude)
  damping    gamma / omega_1 (the fitted decay per radian)
  whole      the same fit over the whole record, and its rms residual over A (the part of the
             signal that is not the first mode)
--plot draws each case's eta at gauge0 over the linear solution a cos(k x) sin(omega_1 t).

--forced: the forced case's gauge0 elevation and left-wall sensor pressure over time (a figure).

--spheric: SPHERIC Test 10 (lateral impact, 93 mm of water): the simulated sensor1 pressure's
maximum over the experiment's 5 ms windows (data/sensor1_pressure_minmax5ms.csv, its `max`
points), and for each impact the peak and its time in the window around it, against the
experiment's, and the impact's first burst: the largest sample within 10 ms of the first one
above half the experiment's peak, on both (a later one-step spike, as of an air gap closing
beside the sensor, can be the window's largest sample):
  hump     0.5-1.5 s (the quasi-static pressure as the wall goes down)
  impact1  2.2-2.6 s (first impact: 3683 Pa at 2.3749 s)
  impact2  3.8-4.3 s (second impact: 3890 Pa at 4.0667 s)
Needs Debian's python3 with numpy (and matplotlib for --plot).
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("SHIZUKU_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")), "utilities"))
import shizukuPost  # noqa: E402

G = 9.81
GAUGE_X = 0.1


def omega1(L, h, g=G):
    k = math.pi / L
    return math.sqrt(g * k * math.tanh(k * h))


def read_elevation(case, column="gauge0"):
    header, _, tokens = shizukuPost.read_tokens(os.path.join(case, "postProcessing", "gauges", "0", "elevation.dat"))
    rows = np.array([[float(x) for x in r] for r in tokens])
    return rows[:, 0], rows[:, header.index(column)]


def fit_mode(t, eta, T1, window):
    """c + A exp(-gamma t) sin(omega t + phi) fitted over t <= window: (omega, A, gamma, rms residual)."""
    from scipy.optimize import curve_fit

    m = t <= window
    tt, ee = t[m], eta[m]
    model = lambda x, c, A, g, w, ph: c + A * np.exp(-g * x) * np.sin(w * x + ph)  # noqa: E731
    p0 = [0.0, max(abs(ee.max()), abs(ee.min())), 0.0, 2 * math.pi / T1, 0.0]
    p, _ = curve_fit(model, tt, ee, p0=p0, maxfev=20000)
    if p[1] < 0:
        p[1], p[4] = -p[1], p[4] + math.pi
    rms = float(np.sqrt(np.mean((model(tt, *p) - ee) ** 2)))
    return p[3], p[1], p[2], rms


def measures(t, eta, L, h, a, x=GAUGE_X, window=None):
    w1 = omega1(L, h)
    T1 = 2 * math.pi / w1
    window = 2 * T1 if window is None else window
    if t[-1] < 0.5 * T1:  # a record too short to fit (a smoke test's few steps)
        nan = float("nan")
        return {"theory": T1, "window": window, "period": nan, "error": nan, "amplitude": nan, "damping": nan,
                "wholePeriod": nan, "wholeError": nan, "wholeResidual": nan}
    w, A, g, _ = fit_mode(t, eta, T1, window)
    ww, Aw, _, rms = fit_mode(t, eta, T1, t[-1])
    return {"theory": T1, "window": window, "period": 2 * math.pi / w, "error": 100 * (w1 / w - 1),
            "amplitude": A / (a * math.cos(math.pi * x / L)), "damping": g / w1,
            "wholePeriod": 2 * math.pi / ww, "wholeError": 100 * (w1 / ww - 1), "wholeResidual": rms / Aw}


def save(fig, out):
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def plot(cases, labels, out, L, h, a):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    w = omega1(L, h)
    fig, ax = plt.subplots(figsize=(8, 4))
    for case, label in zip(cases, labels):
        t, eta = read_elevation(case)
        ax.plot(t, 1000 * eta, lw=1, label=label)
    tt = np.linspace(0, ax.get_xlim()[1], 800)
    ax.plot(tt, 1000 * a * math.cos(math.pi * GAUGE_X / L) * np.sin(w * tt), "k--", lw=1,
            label=f"linear theory, T1 = {2 * math.pi / w:.4f} s")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("eta at x = 0.1 m [mm]")
    ax.set_title(f"Free sloshing, first mode: L = {L} m, h = {h} m, a = {a} m")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, out)


SPHERIC_WINDOWS = {"hump": (0.5, 1.5), "impact1": (2.2, 2.6), "impact2": (3.8, 4.3)}


def read_sensor(case, name):
    header, _, tokens = shizukuPost.read_tokens(os.path.join(case, "postProcessing", name, "0", "wallPressure.dat"))
    rows = np.array([[float(x) for x in r] for r in tokens])
    return rows[:, 0], rows[:, header.index("p")]


def read_spheric_experiment(case):
    path = os.path.join(case, "data", "sensor1_pressure_minmax5ms.csv")
    rows = [line.strip().split(",") for line in open(path).readlines()[1:]]
    t = np.array([float(r[0]) for r in rows if r[2] == "max"])
    p = np.array([float(r[1]) for r in rows if r[2] == "max"])
    return t, p


def window_maxima(t, p, edges):
    """The largest p within each window [edges[i], edges[i+1]) (nan where no sample)."""
    idx = np.searchsorted(edges, t, side="right") - 1
    out = np.full(len(edges) - 1, np.nan)
    for i, v in zip(idx, p):
        if 0 <= i < len(out) and not (v <= out[i]):
            out[i] = v
    return out


BURST = 0.01  # s: an impact's burst, from its first sample above half the experiment's peak


def first_burst(t, p, threshold):
    """The peak and its time within BURST of the first sample above threshold (None without one)."""
    above = np.nonzero(p > threshold)[0]
    if len(above) == 0:
        return None
    t0 = t[above[0]]
    m = (t >= t0) & (t <= t0 + BURST)
    i = np.argmax(np.where(m, p, -np.inf))
    return float(t[i]), float(p[i])


def spheric_measures(case):
    t, p = read_sensor(case, "sensor1")
    te, pe = read_spheric_experiment(case)
    out = {}
    for name, (a, b) in SPHERIC_WINDOWS.items():
        m, me = (t >= a) & (t < b), (te >= a) & (te < b)
        if not m.any() or t[-1] < b:
            continue
        i, j = np.argmax(p[m]), np.argmax(pe[me])
        out[name] = {"time": float(t[m][i]), "peak": float(p[m][i]), "expTime": float(te[me][j]),
                     "expPeak": float(pe[me][j])}
        if name.startswith("impact"):
            # The impact itself: the burst that first exceeds half the experiment's peak (a
            # later one-step spike of a closing air gap can be the window's largest sample).
            half = 0.5 * out[name]["expPeak"]
            run, exp = first_burst(t[m], p[m], half), first_burst(te[me], pe[me], half)
            if run and exp:
                out[name].update(burstTime=run[0], burstPeak=run[1], expBurstTime=exp[0], expBurstPeak=exp[1])
    return out


def plot_spheric(case, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t, p = read_sensor(case, "sensor1")
    te, pe = read_spheric_experiment(case)
    edges = np.concatenate(([0.0], 0.5 * (te[1:] + te[:-1]), [te[-1] + 0.005]))
    sim = window_maxima(t, p, edges)
    fig, ax = plt.subplots(figsize=(9, 4))
    m = te <= t[-1]
    ax.plot(te[m], pe[m], "k-", lw=0.8, label="experiment (max of each 5 ms window)")
    ax.plot(te[m], sim[m], lw=0.8, label="Shizuku (max over the same windows)")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("sensor 1 pressure [Pa]")
    ax.set_title("SPHERIC Test 10, lateral water impact (2D section, measured roll)")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    save(fig, out)


def plot_forced(case, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    t, eta = read_elevation(case)
    ts, ps = read_sensor(case, "sensor")
    fig, axes = plt.subplots(2, 1, figsize=(9, 5), sharex=True)
    axes[0].plot(t, 1000 * eta, lw=0.8)
    axes[0].set_ylabel("eta at x = 0.1 m [mm]")
    axes[1].plot(ts, ps, lw=0.8)
    axes[1].set_ylabel("left wall, 0.3 m up [Pa]")
    axes[1].set_xlabel("t [s]")
    axes[0].set_title("Tank shaken at 1.1 T1 (A = 5 mm), from rest")
    for ax in axes:
        ax.grid(alpha=0.3)
    save(fig, out)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="*", default=[os.path.dirname(os.path.abspath(__file__))])
    ap.add_argument("--label", action="append", default=[])
    ap.add_argument("--L", type=float, default=1.0)
    ap.add_argument("--h", type=float, default=0.5)
    ap.add_argument("--a", type=float, default=0.02)
    ap.add_argument("--window", type=float, help="fit over t <= window (s); default two periods")
    ap.add_argument("--plot")
    ap.add_argument("--forced", help="the forced case: draw it (needs --plot)")
    ap.add_argument("--spheric", help="the SPHERIC Test 10 case: its measures (and --plot)")
    args = ap.parse_args()
    if args.forced:
        plot_forced(args.forced, args.plot)
        return
    if args.spheric:
        for name, m in spheric_measures(args.spheric).items():
            print(f"{name}: peak {m['peak']:.0f} Pa at {m['time']:.4f} s; experiment {m['expPeak']:.0f} Pa at "
                  f"{m['expTime']:.4f} s (time {1000 * (m['time'] - m['expTime']):+.1f} ms, peak "
                  f"{100 * (m['peak'] / m['expPeak'] - 1):+.0f} %)")
            if "burstTime" in m:
                print(f"{name}, first burst above half the experiment's peak: {m['burstPeak']:.0f} Pa at "
                      f"{m['burstTime']:.4f} s; experiment {m['expBurstPeak']:.0f} Pa at {m['expBurstTime']:.4f} s "
                      f"(time {1000 * (m['burstTime'] - m['expBurstTime']):+.1f} ms, peak "
                      f"{100 * (m['burstPeak'] / m['expBurstPeak'] - 1):+.0f} %)")
        if args.plot:
            plot_spheric(args.spheric, args.plot)
        return
    labels = args.label + [os.path.basename(os.path.abspath(c)) for c in args.cases[len(args.label):]]
    for case, label in zip(args.cases, labels):
        m = measures(*read_elevation(case), args.L, args.h, args.a, window=args.window)
        print(f"{label}: period {m['period']:.4f} s over t <= {m['window']:.3f} s, theory {m['theory']:.4f} s, "
              f"error {m['error']:+.2f} %, amplitude {m['amplitude']:.3f} of a cos(k x), damping "
              f"{m['damping']:.4f} per radian; whole record: period {m['wholePeriod']:.4f} s "
              f"({m['wholeError']:+.2f} %), residual {m['wholeResidual']:.2f} of the amplitude")
    if args.plot:
        plot(args.cases, labels, args.plot, args.L, args.h, args.a)


if __name__ == "__main__":
    main()
