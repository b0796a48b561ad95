#!/usr/bin/python3
"""The surge front of damBreak runs against Martin & Moyce (1952) and Koshizuka & Oka (1996).

usage: plotFront.py OUT.png CASE[=LABEL] [CASE[=LABEL] ...]

Each CASE is a run of this case (any spacing; tests/cases/runCase.py --spacing --deltaT writes
one). Its front is the body of water's leading edge, postProcessing/front/0/extent.dat's
largest x (fluidExtent connectedOnly) + d0/2, as Z = x_front/a against T = t sqrt(2 g / a)
(a = 0.2 m, g = 9.81 m/s^2). Printed per case: issue 18's measure, the mean absolute and the
signed relative error against Martin & Moyce's Table 2 over its points with T <= 3 (the run
interpolated linearly in T), and the same with T + 0.175 (the release offset Lethe's
validation of this case applies; docs/validation.md, "Surge front"). The figure draws every run
over Table 2, Martin & Moyce's Fig. 3 (a = 2.25 in) and Koshizuka & Oka. Needs numpy and
matplotlib (Debian's python3).
"""
import csv
import math
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "utilities"))
import shizukuPost  # noqa: E402
A, G = 0.2, 9.81
T_MAX = 3.0
OFFSET = 0.175


def data(name, keep=lambda row: True, cols=(0, 1)):
    with open(os.path.join(HERE, "data", name)) as f:
        rows = [[float(x) for x in r] for r in list(csv.reader(f))[1:]]
    return np.array([[r[cols[0]], r[cols[1]]] for r in rows if keep(r)])


def front(case):
    with open(os.path.join(case, "system", "particlesDict")) as f:
        d0 = float(re.search(r"(?m)^\s*spacing\s+([^;\s]+)", f.read()).group(1))
    names, _, rows = shizukuPost.read_tokens(os.path.join(case, "postProcessing", "front", "0", "extent.dat"))
    i = names.index("max")
    t = np.array([float(r[0]) for r in rows])
    x = np.array([float(r[i].strip("()").split()[0]) for r in rows])
    return d0, t * math.sqrt(2 * G / A), (x + d0 / 2) / A


def errors(T, Z, table, offset=0.0):
    use = table[table[:, 0] <= T_MAX]
    z = np.interp(use[:, 0] - offset, T, Z)  # the run plotted at T + offset
    rel = z / use[:, 1] - 1
    return float(np.mean(np.abs(rel))), float(np.mean(rel))


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    table2 = data("dambreak_martin_moyce_1952_n2_2_surge_front_table2.csv")
    fig3 = data("dambreak_martin_moyce_1952_n2_2_surge_front_fig3_digitized.csv", lambda r: r[0] == 2.25, (1, 2))
    ko = data("dambreak_koshizuka_oka_1996_surge_front.csv")
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 4.5))
    ax.plot(table2[:, 0], table2[:, 1], "ko", mfc="none", label="Martin & Moyce (1952), Table 2")
    ax.plot(fig3[:, 0], fig3[:, 1], "k^", mfc="none", ms=5, label="Martin & Moyce, Fig. 3 (a = 2.25 in)")
    ax.plot(ko[:, 0], ko[:, 1], "ks", mfc="none", ms=5, label="Koshizuka & Oka (1996)")
    print(f"{'run':24s} {'d0 [m]':>8s} {'Table 2 |err|':>14s} {'signed':>8s} {'T+0.175 |err|':>14s} {'signed':>8s}")
    for arg in sys.argv[2:]:
        case, _, label = arg.partition("=")
        d0, T, Z = front(case)
        label = label or os.path.basename(os.path.normpath(case))
        e, s = errors(T, Z, table2)
        eo, so = errors(T, Z, table2, OFFSET)
        print(f"{label:24s} {d0:8.4g} {100 * e:13.1f}% {100 * s:+7.1f}% {100 * eo:13.1f}% {100 * so:+7.1f}%")
        ax.plot(T, Z, "-", lw=1.3, label=f"{label} (Table 2: {100 * e:.1f} %)")
    ax.set_xlim(0, 3.6)
    ax.set_ylim(1, 5)
    ax.set_xlabel("T = t sqrt(2g/a)")
    ax.set_ylabel("Z = x_front / a")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper left")
    fig.tight_layout()
    fig.savefig(sys.argv[1], dpi=110)


if __name__ == "__main__":
    main()
