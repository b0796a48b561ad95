#!/usr/bin/python3
"""The measures of the wave-flume tutorial against linear wave-maker theory
(docs/validation.md, "Wave flume").

usage: waveMeasures.py [CASE ...] [--label NAME ...] [--plot OUT.png]

Reads postProcessing/gauges/0/elevation.dat (gauge0, gauge1 one and two wavelengths from the
paddle, gauge2 0.4 m beyond gauge1) and the paddle's motion from system/particlesDict
(`amplitude`, `period`, `rampTime` of the oscillating piston) and the depth from the fluid
box. Theory: omega^2 = g k tanh(k h); Biesel's transfer function H/S = 2 (cosh 2kh - 1) /
(sinh 2kh + 2kh), S = 2 amplitude; group velocity c_g = (omega/k)(1 + 2kh/sinh 2kh)/2.
For gauge j at distance x_j from the paddle the window is five periods starting when the
first full wave arrives, t_j = rampTime + x_j / c_g. Over it:
  height      twice the amplitude of the sinusoid c + A sin(omega t + phi) fitted by least
              squares over the window (omega free, started at the paddle's), i.e. the
              height of the wave at the paddle's frequency (a zero-crossing analysis is also
              printed: it counts the surface particles' jitter as extra waves)
  period      2 pi / omega of that fit
  wavelength  from the two gauges' phases at omega (least-squares fit of a cos + b sin over
              each gauge's window shifted to the same phase of the paddle): k = (2 pi n +
              delta phi) / (x_1 - x_0), n the whole number of theoretical wavelengths between
  reflection  Goda & Suzuki (1976): the incident and reflected amplitudes at omega from
              gauges 1 and 2 over the last five periods of the record, K_r = a_R / a_I
Each is printed with its relative error against theory.
Needs Debian's python3 with numpy (and matplotlib for --plot).
"""
import argparse
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.environ.get("SHIZUKU_DIR", os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")), "utilities"))
import shizukuPost  # noqa: E402

G = 9.81


def number(text, key):
    m = re.search(r"\b" + key + r"\s+\(?\s*([-0-9.eE+]+)", text)
    return float(m.group(1))


def case_parameters(case):
    """Depth, paddle amplitude, period and ramp from the case's particlesDict."""
    text = open(os.path.join(case, "system", "particlesDict")).read()
    water = re.search(r"water\s*\{[^}]*max\s*\(\s*[-0-9.eE+]+\s+([-0-9.eE+]+)", text)
    motion = text[text.index("motion"):]
    return {"h": float(water.group(1)), "amplitude": number(motion, "amplitude"), "period": number(motion, "period"),
            "ramp": number(motion, "rampTime")}


def theory(h, period, amplitude):
    w = 2 * math.pi / period
    k = w * w / G
    for _ in range(100):  # omega^2 = g k tanh(k h), Newton
        f = G * k * math.tanh(k * h) - w * w
        k -= f / (G * math.tanh(k * h) + G * k * h / math.cosh(k * h) ** 2)
    kh2 = 2 * k * h
    HS = 2 * (math.cosh(kh2) - 1) / (math.sinh(kh2) + kh2)
    cg = w / k * 0.5 * (1 + kh2 / math.sinh(kh2))
    return {"omega": w, "k": k, "L": 2 * math.pi / k, "H": HS * 2 * amplitude, "HS": HS, "cg": cg, "T": period}


def read_gauges(case):
    path = os.path.join(case, "postProcessing", "gauges", "0", "elevation.dat")
    header, _, tokens = shizukuPost.read_tokens(path)
    rows = np.array([[float(x) for x in r] for r in tokens])
    first = open(path).readline()
    xs = [float(v) for v in re.findall(r"\(([-0-9.eE+]+) [-0-9.eE+]+\)", first)]
    return rows[:, 0], [rows[:, header.index(f"gauge{j}")] for j in range(len(xs))], xs


def up_crossings(t, e):
    i = np.nonzero((e[:-1] < 0) & (e[1:] >= 0))[0]
    return t[i] - e[i] * (t[i + 1] - t[i]) / (e[i + 1] - e[i])


def waves(t, e, t0, t1):
    """Heights and periods of the zero-up-crossing waves inside [t0, t1]."""
    m = (t >= t0) & (t <= t1)
    tt, ee = t[m], e[m] - e[m].mean()
    c = up_crossings(tt, ee)
    H = [ee[(tt >= a) & (tt < b)].max() - ee[(tt >= a) & (tt < b)].min() for a, b in zip(c[:-1], c[1:])]
    return np.array(H), np.diff(c)


def fit_wave(t, e, w, t0, t1):
    """(height 2A, period 2 pi/omega) of c + A sin(omega t + phi) fitted over [t0, t1]."""
    from scipy.optimize import curve_fit

    m = (t >= t0) & (t <= t1)
    Z = harmonic(t, e, w, t0, t1)
    model = lambda x, c, a, b, om: c + a * np.cos(om * x) + b * np.sin(om * x)  # noqa: E731
    p, _ = curve_fit(model, t[m], e[m], p0=[0.0, Z.real, Z.imag, w], maxfev=20000)
    return 2 * math.hypot(p[1], p[2]), 2 * math.pi / p[3]


def harmonic(t, e, w, t0, t1):
    """Complex amplitude Z of e ~ Re(Z exp(-i w t)) over [t0, t1] (least squares, with a mean)."""
    m = (t >= t0) & (t <= t1)
    A = np.column_stack([np.cos(w * t[m]), np.sin(w * t[m]), np.ones(m.sum())])
    a, b, _ = np.linalg.lstsq(A, e[m], rcond=None)[0]
    return complex(a, b)


def measures(case):
    p = case_parameters(case)
    th = theory(p["h"], p["period"], p["amplitude"])
    t, eta, xs = read_gauges(case)
    out = {"theory": th, "gauges": []}
    for x, e in zip(xs[:2], eta[:2]):  # the measuring gauges: one and two wavelengths out
        t0 = p["ramp"] + x / th["cg"]
        t1 = t0 + 5 * th["T"]
        if t[-1] < t0 + th["T"]:  # not a full period of the window recorded (a smoke test's few steps)
            out["gauges"].append({"x": x, "window": (t0, t1), "H": float("nan"), "T": float("nan"),
                                  "zeroCrossingH": float("nan"), "zeroCrossingT": float("nan"), "count": 0,
                                  "complete": False})
            continue
        Hz, Tz = waves(t, e, t0, t1)
        H, T = fit_wave(t, e, th["omega"], t0, t1)
        out["gauges"].append({"x": x, "window": (t0, t1), "H": H, "T": T, "zeroCrossingH": Hz.mean(),
                              "zeroCrossingT": Tz.mean(), "count": len(Hz), "complete": t[-1] >= t1})
    # Wavelength: phases at omega over windows one period apart in paddle phase.
    if len(xs) >= 2 and not any(math.isnan(g["H"]) for g in out["gauges"]):
        g0, g1 = out["gauges"][0], out["gauges"][1]
        shift = th["T"] * math.ceil((g1["window"][0] - g0["window"][0]) / th["T"])
        Z0 = harmonic(t, eta[0], th["omega"], g0["window"][0], g0["window"][0] + 5 * th["T"])
        Z1 = harmonic(t, eta[1], th["omega"], g0["window"][0] + shift, g0["window"][0] + shift + 5 * th["T"])
        dx = xs[1] - xs[0]
        dphi = math.remainder(np.angle(Z1) - np.angle(Z0), 2 * math.pi)  # Z ~ exp(i k x): phase grows with x
        n = round(th["k"] * dx / (2 * math.pi))
        out["L"] = 2 * math.pi / ((2 * math.pi * n + dphi) / dx)
    # Reflection from gauges 1 and 2 over the last five periods.
    if len(xs) >= 3 and t[-1] >= 5 * th["T"]:
        t1 = t[-1]
        t0 = t1 - 5 * th["T"]
        Za, Zb = harmonic(t, eta[1], th["omega"], t0, t1), harmonic(t, eta[2], th["omega"], t0, t1)
        k = th["k"]
        M = np.array([[np.exp(1j * k * xs[1]), np.exp(-1j * k * xs[1])], [np.exp(1j * k * xs[2]), np.exp(-1j * k * xs[2])]])
        aI, aR = np.linalg.solve(M, np.array([Za, Zb]))
        out["reflection"] = abs(aR) / abs(aI)
        out["reflectionWindow"] = (t0, t1)
    return out


def report(label, m):
    th = m["theory"]
    print(f"{label}: theory H = {th['H']:.5f} m (H/S {th['HS']:.5f}), T = {th['T']:.5f} s, L = {th['L']:.4f} m, "
          f"c_g = {th['cg']:.4f} m/s")
    for g in m["gauges"]:
        flag = "" if g["complete"] else " (record ends inside the window)"
        print(f"  gauge at x = {g['x']:.4f} m, t = {g['window'][0]:.2f}-{g['window'][1]:.2f} s{flag}: "
              f"H = {g['H']:.5f} m ({100 * (g['H'] / th['H'] - 1):+.2f} %), T = {g['T']:.5f} s "
              f"({100 * (g['T'] / th['T'] - 1):+.2f} %); zero crossings: {g['count']} waves, H "
              f"{g['zeroCrossingH']:.5f} m, T {g['zeroCrossingT']:.5f} s")
    if "L" in m:
        print(f"  wavelength {m['L']:.4f} m ({100 * (m['L'] / th['L'] - 1):+.2f} %)")
    if "reflection" in m:
        w = m["reflectionWindow"]
        print(f"  reflection coefficient {m['reflection']:.3f} (gauges 1-2, t = {w[0]:.2f}-{w[1]:.2f} s)")


def plot(cases, labels, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(2, 1, figsize=(9, 6), sharex=True)
    for case, label in zip(cases, labels):
        p = case_parameters(case)
        th = theory(p["h"], p["period"], p["amplitude"])
        t, eta, xs = read_gauges(case)
        for j, ax in enumerate(axes):
            ax.plot(t, 1000 * eta[j], lw=0.8, label=label)
    for j, ax in enumerate(axes):
        x = xs[j]
        tt = np.linspace(0, t[-1], 3000)
        arrive = p["ramp"] + x / th["cg"]
        # Linear theory in the window: a sinusoid of height H at the phase of the first case's fit.
        if t[-1] < arrive + th["T"]:
            continue
        Z = harmonic(t, eta[j], th["omega"], arrive, arrive + 5 * th["T"])
        amp = th["H"] / 2
        phase = np.angle(Z)
        m = tt >= arrive
        ax.plot(tt[m], 1000 * amp * np.cos(th["omega"] * tt[m] - phase), "k--", lw=0.8,
                label=f"linear theory: H = {1000 * th['H']:.1f} mm, T = {th['T']:.3f} s (phase fitted)")
        ax.axvspan(arrive, arrive + 5 * th["T"], color="0.9")
        ax.set_ylabel(f"eta at x = {x:.3f} m [mm]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    axes[-1].set_xlabel("t [s]")
    axes[0].set_title("Piston wave maker: gauges one and two wavelengths from the paddle (grey: measured windows)")
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="*", default=[os.path.dirname(os.path.abspath(__file__))])
    ap.add_argument("--label", action="append", default=[])
    ap.add_argument("--plot")
    args = ap.parse_args()
    labels = args.label + [os.path.basename(os.path.abspath(c)) for c in args.cases[len(args.label):]]
    for case, label in zip(args.cases, labels):
        report(label, measures(case))
    if args.plot:
        plot(args.cases, labels, args.plot)


if __name__ == "__main__":
    main()
