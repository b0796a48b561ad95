#!/usr/bin/python3
"""Developed channel flow from a uniform inlet (label `regression`; full size label `long`).

usage: channelPoiseuille.py TUTORIAL WORK --shizuku BIN --compare SHIZUKUCOMPARE
                            [--spacing D0 --deltaT DT] [--endTime T] [--threads 2]
                            [--profileTolerance 0.01] [--fluxTolerance 0.01]
                            [--planeTolerance 0.03] [--gradientTolerance 0.01] [--skip-run]

Runs tutorials/channelPoiseuille (a plane channel H = 0.1 m, L = 5 H, uniform inlet
U = 0.01 m/s, outlet at p = 0, no-slip walls, Re = 10, 60 s), at its own size
(H/d0 = 40) or re-sized by --spacing and --deltaT, and checks over the steady part of the
run (the last 3/8 of it, t >= 37.5 s):
  - profile: the `profile` probes (u at y = H/8 .. 7H/8 at x = 2H, 2.5H, 3H) averaged in
    time lie within profileTolerance x 1.5 U of the developed parabola 6 U (y/H)(1 - y/H);
  - flux: the volume flow rate in (particles released by the inlet x d0^2, per time)
    equals the flow rate out (captured by the outlet) within fluxTolerance, both from the
    crossing counts of <time>/uniform/time at the first and last write times of the
    window, the flow rate in is U H (the inlet releases H/d0 rows at U/d0 a second), and
    the time-averaged slab flux through the plane x = 2.5 H (`midPlane`) is U H within
    planeTolerance (the slab estimate fluctuates by about 1/N of the particles in it);
  - pressure gradient: the time-averaged centre-line pressure falls between x = 2H and 4H
    at 12 mu U / H^2 within gradientTolerance (the inlet's wall-rule pressure and the
    outlet's Dirichlet p = 0 together; the probes sample every step, since the pressure
    level pulses with each row the inlet releases: measured +0.33 % at H/d0 = 20, +0.46 %
    at 40; sampled every 25 steps, one phase of the pulse, -11 % at 40);
  - mass balance: at every write time the fluid mass of `conservation` equals its initial
    value + (released - captured - removed) m, m the particle mass of the vtp, to round-off
    (the 12 digits the file prints), and so at every row from its releasedMass,
    capturedMass and removedMass columns; the last state holds exactly that many fluid
    particles, with unique ids.
Tolerances from the resolution study of tutorials/channelPoiseuille/README.md.
"""
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402


def time_state(case, name):
    """released, captured and removedCount of <case>/<name>/uniform/time (0 when absent)."""
    with open(os.path.join(case, name, "uniform", "time")) as f:
        text = f.read()
    out = {}
    for key in ("released", "captured", "removedCount"):
        m = re.search(rf"(?m)^\s*{key}\s+([0-9]+)\s*;", text)
        out[key] = int(m.group(1)) if m else 0
    return out


def columns_of(path):
    """The column names of a function-object file (its `# columns:` line)."""
    with open(path) as f:
        return [ln for ln in f if ln.startswith("# columns:")][0].split()[2:]


def table(path, column):
    """(time, values) of a scalar column of a function-object file (a vector is one token)."""
    k = columns_of(path).index(column)
    rows = []
    with open(path) as f:
        for ln in f:
            if ln.strip() and not ln.startswith("#"):
                tokens = re.findall(r"\([^)]*\)|\S+", ln)
                rows.append((float(tokens[0]), float(tokens[k])))
    a = np.array(rows)
    return a[:, 0], a[:, 1]


def main():
    ap = st.case_arguments("tutorial")
    ap.add_argument("--spacing")
    ap.add_argument("--deltaT")
    ap.add_argument("--endTime")
    ap.add_argument("--profileTolerance", type=float, default=0.01)
    ap.add_argument("--fluxTolerance", type=float, default=0.01)
    ap.add_argument("--planeTolerance", type=float, default=0.03)
    ap.add_argument("--gradientTolerance", type=float, default=0.01)
    ap.add_argument("--name", default="channelPoiseuille")
    ap.add_argument("--skip-run", action="store_true", help="check an existing work case again")
    a = ap.parse_args()
    tutorial = os.path.abspath(a.tutorial)
    plot = st.load_module(os.path.join(tutorial, "plotProfile.py"), "plotProfile")
    case = os.path.abspath(os.path.join(a.work, a.name))
    if not a.skip_run:
        st.copy_case(tutorial, case)
        control = os.path.join(case, "system", "controlDict")
        st.set_key(control, "startFrom", "startTime")
        for key, value, path in (("spacing", a.spacing, "particlesDict"), ("deltaT", a.deltaT, "controlDict"),
                                 ("endTime", a.endTime, "controlDict")):
            if value:
                st.set_key(os.path.join(case, "system", path), key, value)
        st.run_or_fail(a.shizuku, case, a.threads, a.name)
    d0 = float(st.get_key(os.path.join(case, "system", "particlesDict"), "spacing"))
    U = plot.inlet_speed(case)
    H = plot.H

    # profile over the middle of the channel, averaged over the steady part
    points, u, t_from = plot.steady_profile(case)
    dev = (u - plot.analytic(points[:, 1], U)) / (1.5 * U)
    worst = int(np.argmax(np.abs(dev)))
    print(f"profile (t >= {t_from:g} s, {len(points)} probes): largest deviation {100 * dev[worst]:+.3f} % of 1.5 U "
          f"at x = {points[worst, 0]:g}, y = {points[worst, 1]:g}; rms {100 * np.sqrt((dev ** 2).mean()):.3f} %")
    st.check(np.all(np.isfinite(dev)) and np.abs(dev).max() <= a.profileTolerance,
             f"profile within {100 * a.profileTolerance:g} % of 1.5 U of the parabola")

    # flux in and out over the same window, from the crossing counts at write times
    times = [(t, n) for t, n in st.time_dirs(case) if t >= t_from - 1e-9]
    (t1, n1), (t2, n2) = times[0], times[-1]
    s1, s2 = time_state(case, n1), time_state(case, n2)
    q_in = (s2["released"] - s1["released"]) * d0 ** 2 / (t2 - t1)
    q_out = (s2["captured"] - s1["captured"]) * d0 ** 2 / (t2 - t1)
    print(f"flux over {t1:g} <= t <= {t2:g} s: in {q_in:.6g} m^2/s, out {q_out:.6g} m^2/s "
          f"(out/in - 1 = {100 * (q_out / q_in - 1):+.3f} %), U H = {U * H:.6g} m^2/s")
    st.check(abs(q_out - q_in) <= a.fluxTolerance * q_in, f"flux in = out within {100 * a.fluxTolerance:g} %")
    st.check(abs(q_in - U * H) <= a.fluxTolerance * U * H, f"flux in = U H within {100 * a.fluxTolerance:g} %")
    plane = os.path.join(case, "postProcessing", "midPlane")
    t, q = table(os.path.join(plane, sorted(os.listdir(plane), key=float)[0], "flux.dat"), "flux")
    q_plane = q[t >= t_from - 1e-9].mean()
    print(f"flux through the plane x = 2.5 H, mean over t >= {t_from:g} s: {q_plane:.6g} m^2/s "
          f"({100 * (q_plane / (U * H) - 1):+.3f} % of U H)")
    st.check(abs(q_plane - U * H) <= a.planeTolerance * U * H,
             f"flux through the middle plane = U H within {100 * a.planeTolerance:g} %")

    # the pressure gradient that drives the developed flow, from the inlet's wall-rule
    # pressure to the outlet's p = 0: -dp/dx = 12 mu U / H^2 between x = 2H and 4H
    line = os.path.join(case, "postProcessing", "centreLine")
    cols = st.read_table(os.path.join(line, sorted(os.listdir(line), key=float)[0], "p"))
    window = [r for r in cols if r["time"] >= t_from - 1e-9]
    p2, p4 = (np.mean([r[f"point{k}"] for r in window]) for k in (2, 4))
    mu = 1000.0 * 1e-4
    grad, exact = (p2 - p4) / (2 * H), 12 * mu * U / H ** 2
    print(f"pressure gradient between x = 2H and 4H, mean over t >= {t_from:g} s: {grad:.6g} Pa/m, "
          f"12 mu U / H^2 = {exact:g} Pa/m ({100 * (grad / exact - 1):+.2f} %)")
    st.check(abs(grad - exact) <= a.gradientTolerance * exact,
             f"pressure gradient 12 mu U / H^2 within {100 * a.gradientTolerance:g} %")

    # mass balance at every write time, and the last state's particles
    cons = os.path.join(case, "postProcessing", "conservation")
    cons = os.path.join(cons, sorted(os.listdir(cons), key=float)[0], "conservation.dat")
    t_rows, mass = table(cons, "fluidMass")
    fluid_mass = dict(zip(t_rows, mass))
    last = st.read_vtp(os.path.join(case, times[-1][1], "particles.vtp"))
    m = float(last["field:mass"][0])
    m0 = fluid_mass[min(fluid_mass)]
    worst_balance, matched = 0.0, 0
    for t, n in st.time_dirs(case):
        s = time_state(case, n)
        expected = m0 + (s["released"] - s["captured"] - s["removedCount"]) * m
        rows = [tc for tc in fluid_mass if abs(tc - t) <= 1e-9 * max(1.0, t)]
        if rows:
            matched += 1
            worst_balance = max(worst_balance, abs(fluid_mass[rows[0]] - expected) / m0)
    print(f"mass balance: largest |fluid mass - (initial + (released - captured - removed) m)| / initial "
          f"= {worst_balance:.2g} over the {matched} write times with a conservation row")
    st.check(matched >= 3 and worst_balance <= 1e-11, "mass balance closes to round-off")
    inflow, outflow, lost = (table(cons, c)[1] for c in ("releasedMass", "capturedMass", "removedMass"))
    row_balance = np.abs(mass - (mass[0] + inflow - outflow - lost)).max() / mass[0]
    print(f"mass balance at every conservation row ({len(t_rows)}): largest relative {row_balance:.2g}")
    st.check(row_balance <= 1e-11, "mass balance closes to round-off at every conservation row")
    fluid = last["type"] == 0
    n_expected = round(m0 / m) + s2["released"] - s2["captured"] - s2["removedCount"]
    ids = last["id"]
    print(f"last state ({t2:g} s): {int(fluid.sum())} fluid particles, expected {n_expected}; "
          f"{len(ids)} particles, {len(np.unique(ids))} distinct ids")
    st.check(int(fluid.sum()) == n_expected and len(np.unique(ids)) == len(ids), "last state: count and ids")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
