#!/usr/bin/python3
"""The weir tutorial's measurement: the discharge per unit width over the crest against
the critical-flow relation of a broad-crested weir,

    q = sqrt(g) (2 E / 3)^(3/2),    E = h1 + u1^2 / (2 g) - P,

E the upstream energy head above the crest (h1 the water depth, u1 the depth-mean
velocity in the approach section, P the crest height), and the free-surface profile along
the flume. Everything is averaged over the written times of a window after the start-up
transient (--from T0, default: the later half of the written times).

  - the free-surface level in a column of width d0: the highest fluid particle + d0/2;
  - the approach section (--upstream XA XB, a few heads upstream of the weir's face):
    h1 the mean of its columns' levels, u1 the mean x-velocity of its fluid particles
    (every particle stands for the same volume, so this is the depth mean);
  - q over the crest: sum V u_x / (XB - XA) over the fluid particles in the stretch
    XA <= x < XB of the crest (--over XA XB; the mean over that stretch of the slab
    estimate at each plane x = const, which in a steady flow is q at every plane, with
    the noise of single slabs averaged out), averaged over the times; and the mean over
    the window of the case's `flux` function object --flux NAME (default crest) when its
    postProcessing/NAME/0/flux.dat exists (sampled far more often than the written
    times; it is then the q compared with the relation); also the inlet's
    release rate and the outlet's capture rate (particles per second times V, from the
    `released` and `captured` counts in <time>/uniform/time): in a steady state all three
    agree;
  - the mass balance at every written time: N_fluid = N_fluid(0) + released - captured
    - removed (particle counts, exact integers).

Writes plots/weirDischarge.txt (the numbers), plots/weirDischarge.json (the same for
scripts) and, unless --no-plot, plots/weirProfile.png
(the mean surface profile, the weir, the critical depth over the crest, the numbers in
the title). The last line printed is `q/qc = R` (qc = sqrt(g) (2E/3)^(3/2)).

usage: weirDischarge.py CASE [--from T0] [--crest X0 X1 P] [--upstream XA XB]
                             [--over XA XB] [--flux NAME] [--g G] [--no-plot]
"""
import argparse
import json
import math
import os
import re
import sys

import numpy as np


def read_vtp(path):
    """{"position": N x 3, point arrays by name, "field:" + field arrays} of a particles.vtp."""
    from vtkmodules.util.numpy_support import vtk_to_numpy as array_of
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    poly = reader.GetOutput()
    arrays = {"position": array_of(poly.GetPoints().GetData()).copy()}
    for prefix, data in (("", poly.GetPointData()), ("field:", poly.GetFieldData())):
        for k in range(data.GetNumberOfArrays()):
            if data.GetArray(k) is not None:
                arrays[prefix + data.GetArrayName(k)] = array_of(data.GetArray(k)).copy()
    return arrays


def time_dirs(case):
    out = []
    for name in os.listdir(case):
        if re.fullmatch(r"[0-9.eE+-]+", name) and os.path.isfile(os.path.join(case, name, "particles.vtp")):
            out.append((float(name), name))
    return sorted(out)


def balance_counts(case, name):
    """(released, captured, removedCount) from <time>/uniform/time (absent: 0)."""
    vals = {"released": 0, "captured": 0, "removedCount": 0}
    path = os.path.join(case, name, "uniform", "time")
    if os.path.isfile(path):
        with open(path) as f:
            for line in f:
                m = re.match(r"\s*(released|captured|removedCount)\s+([-+0-9.eE]+)\s*;", line)
                if m:
                    vals[m.group(1)] = int(float(m.group(2)))
    return vals["released"], vals["captured"], vals["removedCount"]


def read_table(path):
    """The rows of a postProcessing table as {column: value} (vector columns skipped),
    by shizukuPost.read_tokens, the reader shizukuPlot uses (found beside shizukuPlot on
    the PATH, as the tutorial functions put it there)."""
    import shutil
    plot = shutil.which("shizukuPlot")
    here = os.path.dirname(os.path.realpath(__file__))
    sys.path[:0] = ([os.path.dirname(os.path.realpath(plot))] if plot else []) + [os.path.join(here, "..", "..", "utilities")]
    import shizukuPost
    names, _, rows = shizukuPost.read_tokens(path)
    return [{k: float(v) for k, v in zip(names, r) if not v.startswith("(")} for r in rows]


def flux_mean(path, ta, tb):
    """The mean of the `flux` column of a flux.dat over ta <= time <= tb (nan without the file)."""
    if not os.path.isfile(path):
        return math.nan
    inside = [r["flux"] for r in read_table(path) if ta - 1e-9 <= r["time"] <= tb + 1e-9]
    return float(np.mean(inside)) if inside else math.nan


def surface_levels(x, y, edges, d0):
    """The level of each column [edges[k], edges[k+1]): its highest particle + d0/2 (nan if empty)."""
    k = np.digitize(x, edges) - 1
    top = np.full(len(edges) - 1, -np.inf)
    ok = (k >= 0) & (k < len(top))
    np.maximum.at(top, k[ok], y[ok])
    top[~np.isfinite(top)] = np.nan
    return top + 0.5 * d0


def measure(case, a):
    times = time_dirs(case)
    if not times:
        raise SystemExit(f"weirDischarge.py: no time directories with particles in {case}")
    first = read_vtp(os.path.join(case, times[0][1], "particles.vtp"))
    d0 = float(first["field:spacing"][0])
    V = float(first["field:volume"][0])
    n0 = int(np.sum(first["type"] == 0))
    t0 = a.t0 if a.t0 is not None else times[len(times) // 2][0]
    window = [(t, n) for t, n in times if t >= t0 - 1e-9]
    if len(window) < 2:
        window = times[len(times) // 2:] if len(times) >= 2 else times
        print(f"weirDischarge.py: fewer than 2 times from {t0:g} s; averaging over {window[0][0]:g} .. {window[-1][0]:g} s")
    xmin, xmax = first["position"][:, 0].min(), first["position"][:, 0].max()
    edges = np.arange(xmin, xmax + d0, d0)
    levels, h1s, u1s, qs = [], [], [], []
    worst_balance = 0
    for t, name in times:
        p = read_vtp(os.path.join(case, name, "particles.vtp"))
        fluid = p["type"] == 0
        released, captured, removed = balance_counts(case, name)
        worst_balance = max(worst_balance, abs(int(fluid.sum()) - (n0 + released - captured - removed)))
        if (t, name) not in window:
            continue
        x, y, u = p["position"][fluid, 0], p["position"][fluid, 1], p["U"][fluid, 0]
        levels.append(surface_levels(x, y, edges, d0))
        cols = np.arange(a.upstream[0], a.upstream[1] + 1e-12, d0)
        h1s.append(np.nanmean(surface_levels(x, y, cols, d0)))
        inside = (x >= a.upstream[0]) & (x < a.upstream[1])
        u1s.append(u[inside].mean())
        qs.append(V * u[(x >= a.over[0]) & (x < a.over[1])].sum() / (a.over[1] - a.over[0]))
    (ta, na), (tb, nb) = window[0], window[-1]
    counts = np.array(balance_counts(case, nb)) - np.array(balance_counts(case, na))
    q_inlet, q_outlet = (V * counts[:2] / (tb - ta)) if tb > ta else (math.nan, math.nan)
    h1, u1, q_particles = float(np.mean(h1s)), float(np.mean(u1s)), float(np.mean(qs))
    q_flux = flux_mean(os.path.join(case, "postProcessing", a.flux, "0", "flux.dat"), ta, tb)
    q = q_flux if math.isfinite(q_flux) else q_particles
    E = h1 + u1 ** 2 / (2 * a.g) - a.crest[2]
    qc = math.sqrt(a.g) * (2 * E / 3) ** 1.5
    return dict(d0=d0, V=V, n0=n0, window=(ta, tb), nTimes=len(window), edges=edges,
                level=np.nanmean(np.array(levels), axis=0), h1=h1, u1=u1, q=q, qParticles=q_particles, qFlux=q_flux, qInlet=float(q_inlet), qOutlet=float(q_outlet),
                qSpread=(float(np.min(qs)), float(np.max(qs))), E=E, qc=qc,
                yc=(q ** 2 / a.g) ** (1 / 3), balance=worst_balance, fluid=int(fluid.sum()))


def report(m, a):
    lines = [
        f"window                 {m['window'][0]:g} .. {m['window'][1]:g} s ({m['nTimes']} written times)",
        f"spacing d0             {m['d0']:g} m; fluid particles at the last time {m['fluid']}",
        f"approach section       x in [{a.upstream[0]:g}, {a.upstream[1]:g}] m",
        f"  depth h1             {m['h1']:.5f} m (highest particle + d0/2 per column)",
        f"  mean velocity u1     {m['u1']:.5f} m/s",
        f"  energy head E        {m['E']:.5f} m above the crest (P = {a.crest[2]:g} m)",
        f"q over the crest       {m['qFlux']:.5f} m^2/s (function object '{a.flux}', mean over the window)",
        f"  from the particles   {m['qParticles']:.5f} m^2/s (sum V u / (XB - XA) over x in [{a.over[0]:g}, {a.over[1]:g}] m;"
        f" single times {m['qSpread'][0]:.5f} .. {m['qSpread'][1]:.5f})",
        f"q released by inlet    {m['qInlet']:.5f} m^2/s",
        f"q captured by outlet   {m['qOutlet']:.5f} m^2/s",
        f"critical depth y_c     {m['yc']:.5f} m = {m['yc'] / m['d0']:.1f} d0",
        f"qc = sqrt(g)(2E/3)^1.5 {m['qc']:.5f} m^2/s",
        f"q/qc                   {m['q'] / m['qc']:.4f} (q = {m['q']:.5f}; inlet: {m['qInlet'] / m['qc']:.4f})",
        f"mass balance           largest |N_fluid - (N0 + released - captured - removed)| = {m['balance']} particles",
    ]
    return "\n".join(lines)


def plot(m, a, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x0, x1, P = a.crest
    xc = 0.5 * (m["edges"][1:] + m["edges"][:-1])
    fig, ax = plt.subplots(figsize=(11, 3.6))
    ax.fill_between([x0, x1], 0, P, color="0.6", label="weir")
    ax.plot(xc, m["level"], "C0", lw=1.5, label=f"free surface, mean over {m['window'][0]:g}..{m['window'][1]:g} s")
    ax.hlines(P + m["yc"], x0, x1, colors="C3", linestyles="--", label=f"critical depth over the crest, y_c = {m['yc']:.4f} m")
    ax.hlines(P + m["E"], m["edges"][0], x1, colors="C2", linestyles=":", label=f"energy line upstream, E = {m['E']:.4f} m above the crest")
    ax.axvspan(a.upstream[0], a.upstream[1], color="C1", alpha=0.15, label="approach section (h1, u1)")
    ax.axvspan(a.over[0], a.over[1], color="C4", alpha=0.1, label="q measured over this stretch")
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    ax.set_ylim(0, None)
    ax.set_title(f"Broad-crested weir: q = {m['q']:.4f} m$^2$/s over the crest, "
                 f"$\\sqrt{{g}}(2E/3)^{{3/2}}$ = {m['qc']:.4f} m$^2$/s, ratio {m['q'] / m['qc']:.3f}", fontsize=10)
    ax.legend(fontsize=7, loc="lower left")
    fig.tight_layout()
    fig.savefig(path, dpi=130)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("--from", dest="t0", type=float)
    ap.add_argument("--crest", type=float, nargs=3, default=[0.5, 0.9, 0.06], metavar=("X0", "X1", "P"))
    ap.add_argument("--upstream", type=float, nargs=2, default=[0.15, 0.25], metavar=("XA", "XB"))
    ap.add_argument("--over", type=float, nargs=2, default=[0.4, 0.6], metavar=("XA", "XB"))
    ap.add_argument("--flux", default="crest")
    ap.add_argument("--g", type=float, default=9.81)
    ap.add_argument("--no-plot", action="store_true")
    a = ap.parse_args()
    m = measure(a.case, a)
    text = report(m, a)
    print(text)
    plots = os.path.join(a.case, "plots")
    os.makedirs(plots, exist_ok=True)
    with open(os.path.join(plots, "weirDischarge.txt"), "w") as f:
        f.write(text + "\n")
    with open(os.path.join(plots, "weirDischarge.json"), "w") as f:
        json.dump({k: v for k, v in m.items() if k not in ("edges", "level")}, f, indent=1)
    if not a.no_plot:
        plot(m, a, os.path.join(plots, "weirProfile.png"))
    print(f"q/qc = {m['q'] / m['qc']:.6f}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
