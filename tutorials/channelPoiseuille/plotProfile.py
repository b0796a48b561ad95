#!/usr/bin/python3
"""The developed velocity profile of the channelPoiseuille tutorial against the parabola.

usage: plotProfile.py [CASE] [--from T]

Reads the `profile` probes (u at several heights y of each station x) and the inlet's
uniform speed U (system/particlesDict, region `inflow`), averages u over the samples with
time >= T (default: the last 3/8 of the run, where the flow is steady), and draws u/U
against y/H at each station with the analytic developed profile u = 6 U (y/H)(1 - y/H)
(plane Poiseuille flow with the inlet's flow rate U H) -> CASE/plots/profile.png.
Prints the largest deviation as a fraction of the centre-line speed 1.5 U.
The test tests/cases/channelPoiseuille.py uses read_probes, steady_profile and analytic.
Needs Debian's python3 with numpy and matplotlib.
"""
import argparse
import os
import re
import sys

import numpy as np

H = 0.1  # channel height [m]: the fluid box of system/particlesDict


def read_probes(path):
    """(points P x 2, times T, u T x P) of a probes file of a vector field; the x component."""
    points, rows = [], []
    with open(path) as f:
        for line in f:
            m = re.match(r"#\s*point\d+\s+\(([^)]*)\)", line)
            if m:
                points.append([float(v) for v in m.group(1).split()[:2]])
            elif line.strip() and not line.startswith("#"):
                t, rest = line.split(None, 1)
                vectors = re.findall(r"\(([^)]*)\)", rest)
                rows.append([float(t)] + [float(v.split()[0]) for v in vectors])
    a = np.array(rows)
    return np.array(points), a[:, 0], a[:, 1:]


def probes_of(case, name="profile", field="U"):
    """The probes of a function object joined over restarts: a later start replaces the
    rows from its start time on."""
    root = os.path.join(case, "postProcessing", name)
    starts = sorted(os.listdir(root), key=float)
    points, t, u = read_probes(os.path.join(root, starts[0], field))
    for s in starts[1:]:
        _, t2, u2 = read_probes(os.path.join(root, s, field))
        keep = t < float(s) - 1e-12
        t, u = np.concatenate([t[keep], t2]), np.vstack([u[keep], u2])
    return points, t, u


def inlet_speed(case):
    """U of the `inflow` region's uniform velocity in system/particlesDict."""
    with open(os.path.join(case, "system", "particlesDict")) as f:
        text = re.sub(r"//[^\n]*", "", f.read())
    m = re.search(r"inflow\s*\{[^}]*velocity\s*\{[^}]*value\s*\(\s*([-+0-9.eE]+)", text)
    if not m:
        raise SystemExit(f"plotProfile: no uniform velocity in region 'inflow' of {case}/system/particlesDict")
    return float(m.group(1))


def analytic(y, U):
    """Developed plane Poiseuille flow carrying U H per unit depth."""
    return 6 * U * (y / H) * (1 - y / H)


def steady_profile(case, t_from=None):
    """(points, time-averaged u per point, averaging start) over the samples at t >= t_from
    (default: the last 3/8 of the run)."""
    points, t, u = probes_of(case)
    if t_from is None:
        t_from = t[-1] - 0.375 * (t[-1] - t[0])
    sel = t >= t_from - 1e-12
    return points, u[sel].mean(axis=0), t_from


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case", nargs="?", default=".")
    ap.add_argument("--from", dest="t_from", type=float)
    a = ap.parse_args()
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    U = inlet_speed(a.case)
    points, u, t_from = steady_profile(a.case, a.t_from)
    err = np.abs(u - analytic(points[:, 1], U)) / (1.5 * U)
    fig, ax = plt.subplots(figsize=(5, 4.5))
    y = np.linspace(0, H, 101)
    ax.plot(analytic(y, U) / U, y / H, "k-", label="6 (y/H)(1 - y/H)")
    for k, x in enumerate(sorted(set(points[:, 0]))):
        at = points[:, 0] == x
        ax.plot(u[at] / U, points[at, 1] / H, "os^v"[k % 4], mfc="none", label=f"x = {x / H:g} H")
    ax.set_xlabel("u / U")
    ax.set_ylabel("y / H")
    ax.set_xlim(0, 1.6)
    ax.set_ylim(0, 1)
    ax.legend(loc="lower right", fontsize=8)
    ax.set_title(f"u averaged over t >= {t_from:g} s; largest deviation {100 * err.max():.2f} % of 1.5 U",
                 fontsize=8)
    os.makedirs(os.path.join(a.case, "plots"), exist_ok=True)
    out = os.path.join(a.case, "plots", "profile.png")
    fig.savefig(out, dpi=120, bbox_inches="tight")
    print(f"{out}: largest deviation from 6 U (y/H)(1 - y/H) {100 * err.max():.3f} % of 1.5 U "
          f"({len(points)} probes, t >= {t_from:g} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
