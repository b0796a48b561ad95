#!/usr/bin/python3
"""Interior density-error mode and mean (eq. 22) over time of two dam-break runs, the
proposed method and OPS alone (the paper's Fig. 6 comparison as a time series).

usage: plotComparison.py PROPOSED_CASE OPS_CASE OUT.png"""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def series(case):
    t, mean, mode = [], [], []
    for line in open(f"{case}/postProcessing/densityError/0/densityError.dat"):
        if line.startswith("#") or not line.strip():
            continue
        v = line.split()
        t.append(float(v[0])), mean.append(float(v[1])), mode.append(float(v[4]))
    return t, mean, mode


def main():
    proposed, ops, out = sys.argv[1:4]
    fig, ax = plt.subplots(figsize=(7, 3.6))
    for case, label, colour in ((proposed, "proposed (OPS + volume + surface fit)", "C0"), (ops, "OPS alone", "C3")):
        t, mean, mode = series(case)
        avg = sum(mode) / len(mode)
        ax.plot(t, mode, color=colour, lw=1, label=f"{label}: mode, time average {avg:.2f} %")
        ax.plot(t, mean, color=colour, lw=1, ls="--", alpha=0.7, label=f"{label}: mean")
    ax.set_xlabel("t [s]")
    ax.set_ylabel("interior density error [%]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    print(f"  {out}")


if __name__ == "__main__":
    main()
