#!/usr/bin/python3
"""Two dam-break runs, the proposed method against OPS alone (the paper's Fig. 6, 7
comparison), in three panels:
  1. interior density-error mode and mean (eq. 22) over time (densityError.dat);
  2. fluid volume sum m/<rho> over all fluid, change from its initial value, over time
     (conservation.dat);
  3. interior density-error histograms of both runs at one time (histogram.dat; default:
     the latest time both runs wrote), each with its mode marked.
The pressure fields side by side come from `shizukuPlot -case A -against B -field p`.

usage: plotComparison.py PROPOSED_CASE OPS_CASE OUT.png [--time T]"""
import argparse
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def columns(path, usecols=None):
    """The scalar columns of a postProcessing file as an array (comments skipped)."""
    return np.loadtxt(path, comments="#", ndmin=2, usecols=usecols)


def histograms(case):
    """{time: (bin centres, interior counts)} of the case's densityError histograms."""
    root = os.path.join(case, "postProcessing", "densityError", "0")
    out = {}
    for name in os.listdir(root):
        path = os.path.join(root, name, "histogram.dat")
        if os.path.isfile(path):
            d = columns(path)
            out[float(name)] = (d[:, 0], d[:, 1])
    return out


def main():
    p = argparse.ArgumentParser()
    p.add_argument("proposed")
    p.add_argument("ops")
    p.add_argument("out")
    p.add_argument("--time", type=float, help="time of the histograms (default: the latest both runs wrote)")
    a = p.parse_args()
    cases = ((a.proposed, "proposed (OPS + volume + surface fit)", "C0"), (a.ops, "OPS alone", "C3"))
    hist = [histograms(c) for c, _, _ in cases]
    common = sorted(set(hist[0]) & set(hist[1]))
    if not common:
        raise SystemExit("plotComparison.py: the two runs have no histogram time in common")
    th = a.time if a.time is not None else common[-1]
    th = min(common, key=lambda t: abs(t - th))
    fig, (ax1, ax2, ax3) = plt.subplots(1, 3, figsize=(15, 3.8))
    for (case, label, colour), h in zip(cases, hist):
        d = columns(os.path.join(case, "postProcessing", "densityError", "0", "densityError.dat"))
        t, mean, mode = d[:, 0], d[:, 1], d[:, 4]
        ax1.plot(t, mode, color=colour, lw=1, label=f"{label}: mode, time average {np.nanmean(mode):.2f} %")
        ax1.plot(t, mean, color=colour, lw=1, ls="--", alpha=0.7, label=f"{label}: mean")
        c = columns(os.path.join(case, "postProcessing", "conservation", "0", "conservation.dat"), usecols=(0, 1, 2))
        rel = (c[:, 1] / c[0, 1] - 1) * 100
        ax2.plot(c[:, 0], rel, color=colour, lw=1, label=f"{label}: largest rise {rel.max():+.1f} %")
        centre, counts = h[th]
        width = centre[1] - centre[0]
        ax3.step(centre, counts, where="mid", color=colour, lw=1.2,
                 label=f"{label}: mode {centre[int(np.argmax(counts))]:g} %")
        ax3.axvline(centre[int(np.argmax(counts))], color=colour, ls=":", lw=1)
    ax1.set_xlabel("t [s]")
    ax1.set_ylabel("interior density error [%]")
    ax1.legend(fontsize=7, loc="lower right")
    ax2.set_xlabel("t [s]")
    ax2.set_ylabel("fluid volume sum m/<rho>, change [%]")
    ax2.legend(fontsize=7, loc="upper left")
    ax3.set_xlabel("interior density error (rho0 - <rho>)/rho0 [%]")
    ax3.set_ylabel(f"particles per {width:g} % bin")
    ax3.set_title(f"histogram at t = {th:g} s", fontsize=9)
    ax3.legend(fontsize=7)
    lo = min(centre[np.nonzero(h[th][1])[0]].min() for h in hist) - 1
    hi = max(centre[np.nonzero(h[th][1])[0]].max() for h in hist) + 1
    ax3.set_xlim(lo, hi)
    for ax in (ax1, ax2, ax3):
        ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(a.out, dpi=130)
    print(f"  {a.out} (histograms at t = {th:g} s)")


if __name__ == "__main__":
    main()
