#!/usr/bin/python3
"""Rotating square patch, the proposed method against the paper's baseline (OPS +
stabilized ISPH): centre pressure p/(rho omega^2 L^2) and interior mean density error
(eq. 22) against omega t (the paper's Fig. 5, plus the density it discusses with Fig. 4).

A run that stopped before the other (a numerical breakdown: shizuku writes the last good
state and exits 2) is marked with a cross at its last sample, and the time is printed.

usage: plotComparison.py PROPOSED_CASE BASELINE_CASE OUT.png [--rho 1000 --omega 1 --L 1 --d0 0.01]
                         [--baselineLabel TEXT]"""
import argparse

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def main():
    p = argparse.ArgumentParser()
    p.add_argument("proposed")
    p.add_argument("baseline")
    p.add_argument("out")
    p.add_argument("--rho", type=float, default=1000.0)
    p.add_argument("--omega", type=float, default=1.0)
    p.add_argument("--L", type=float, default=1.0)
    p.add_argument("--d0", type=float, default=0.01)
    p.add_argument("--baselineLabel", default="OPS + stabilized ISPH")
    a = p.parse_args()
    scale = a.rho * a.omega ** 2 * a.L ** 2
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 3.4))
    runs = ((a.proposed, "proposed", "C0"), (a.baseline, a.baselineLabel, "C3"))
    probes = {case: np.loadtxt(f"{case}/postProcessing/centre/0/p", comments="#", ndmin=2).T
              for case, _, _ in runs}
    last = max(float(t[-1]) for t, _ in probes.values())
    for case, label, colour in runs:
        t, pc = probes[case]
        ax1.plot(a.omega * t, pc / scale, color=colour, lw=1, label=label)
        if t[-1] < last * (1 - 1e-6):
            stop = f"{label}: stopped at omega t = {a.omega * t[-1]:.2f}"
            good = np.isfinite(pc)
            if good.any():  # the cross at the last value the probe had
                ax1.plot(a.omega * t[good][-1], pc[good][-1] / scale, "x", color=colour, ms=9, mew=2, label=stop)
            else:
                ax1.axvline(a.omega * t[-1], color=colour, ls="--", lw=1, label=stop)
            print(f"  {label} stopped at omega t = {a.omega * t[-1]:.3g}")
        d = np.loadtxt(f"{case}/postProcessing/densityError/0/densityError.dat", comments="#")
        ax2.plot(a.omega * d[:, 0], d[:, 1], color=colour, lw=1, label=f"{label}: time average {np.nanmean(d[:, 1]):.2f} %")
    ax1.axhline(-0.147343 * (1 - a.d0 / a.L) ** 2, color="k", lw=0.6, ls=":", label="analytic at t = 0 (side L - d0)")
    ax1.set_xlabel("omega t [rad]")
    ax1.set_ylabel("centre pressure p / (rho omega^2 L^2)")
    ax2.set_xlabel("omega t [rad]")
    ax2.set_ylabel("interior mean density error [%]")
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(a.out, dpi=130)
    print(f"  {a.out}")


if __name__ == "__main__":
    main()
