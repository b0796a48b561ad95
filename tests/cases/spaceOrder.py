#!/usr/bin/python3
"""Order of convergence in the particle spacing (label `regression`).

usage: spaceOrder.py CASE WORK --shizuku BIN --compare SHIZUKUCOMPARE
                     [--levels 10,20,40] [--shifting on|off] [--threads 2] [--min-order P]

Runs the Poiseuille start-up case (CASE = tests/cases/poiseuilleStartup, channel height
H = 0.1 m) at H/d0 = 10, 20, 40 with dt scaled like d0^2 (the viscous limit, so the time
error shrinks at least as fast as a second-order spatial error), and measures the error of
the probe velocities at y = H/4, H/2, 3H/4 against the analytic series solution (the
case's makeAnalytic.py, imported):
    e_k = max over probes and over 0.2 <= t <= 2 s of |u_k(y, t) - u(y, t)|.
The order is the least-squares slope of log e_k against log d0. With --shifting off the
shift, ADS and XSPH are switched off (the bare projection method); on, the full method.
Asserts order >= --min-order (default 0.9).
Measured 2026-11-30 (1 thread, machine shared; 4.5 s for the three runs):
  shifting off, H/d0 = 10, 20, 40: e = 1.15e-4, 4.79e-5, 2.15e-5 m/s, ratios 2.40, 2.23
                (orders 1.26, 1.16), fitted order 1.21;
  shifting on,  H/d0 = 10, 20, 40, 80: e = 1.15e-4, 4.64e-5, 2.07e-5, 1.06e-5 m/s, ratios
                2.49, 2.24, 1.95 (orders 1.32, 1.16, 0.96), fitted 1.15 (100 s).
The method is first order in d0 on this wall-bounded flow, although the SPH2 operators
are second order on their own (tests/unit/test_operators_convergence); the likely limit is
the no-slip wall treatment (dummy layers), not yet investigated. The test asserts order >= 0.9
(the measured 1.21 with a margin for the two-level scatter): a scheme that stopped
converging (order near 0), or one that converged more slowly than first order, fails."""
import math
import os
import re
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402


def main():
    p = st.case_arguments()
    p.add_argument("--levels", default="10,20,40")
    p.add_argument("--shifting", choices=("on", "off"), default="off")
    p.add_argument("--min-order", type=float, default=0.9)
    a = p.parse_args()
    cm = st.load_compare(a.compare)
    root = os.path.join(a.work, "spaceOrder")
    shutil.rmtree(root, ignore_errors=True)
    exact = st.load_module(os.path.join(a.case, "makeAnalytic.py"), "makeAnalytic")  # u(y, t), ys, H
    dt0 = float(st.get_key(os.path.join(a.case, "system", "controlDict"), "deltaT"))
    d00 = float(st.get_key(os.path.join(a.case, "system", "particlesDict"), "spacing"))
    results = []
    for n in (int(v) for v in a.levels.split(",")):
        d0 = exact.H / n
        dt = dt0 * (d0 / d00) ** 2
        steps = int(round(2.0 / dt))
        case = os.path.join(root, f"H{n}")
        st.copy_case(a.case, case)
        st.set_key(os.path.join(case, "system", "particlesDict"), "spacing", repr(d0))
        path = os.path.join(case, "system", "controlDict")
        st.set_key(path, "deltaT", repr(dt))
        # probes every 0.02 s whatever dt is
        st.set_entry_key(path, "profile", "writeInterval", max(1, int(round(0.02 / dt))))
        if a.shifting == "off":
            st.remove_shifting(case)
        st.run_or_fail(a.shizuku, case, a.threads, f"H/d0 = {n}")
        cols = cm.Series(case).columns
        names = sorted(c for c in cols if c.startswith("profile/U/"))
        e = 0.0
        for c in names:
            m = re.match(r"profile/U/point(\d+)_x$", c)
            if not m:
                continue
            t, u = cols[c]
            y = exact.ys[int(m.group(1))]
            if y < 0.2 * exact.H:
                continue  # y = H/8 is 1.25 d0 from the wall at H/d0 = 10 (README.md)
            for ti, ui in zip(t, u):
                if 0.2 <= ti <= 2.0 + 1e-9 and ui == ui:
                    e = max(e, abs(ui - exact.u(y, ti)))
        results.append((d0, e, dt, steps))
        print(f"     H/d0 = {n}: dt = {dt:.3g} s ({steps} steps), max |u - u_exact| = {e:.3g} m/s")
    for (d, e, _, _), (d2, e2, _, _) in zip(results, results[1:]):
        print(f"     ratio {e / e2:.2f} for d0 {d:.4g} -> {d2:.4g} m (order {math.log(e / e2) / math.log(d / d2):.2f})")
    xs = [math.log(d) for d, _, _, _ in results]
    ys = [math.log(e) for _, e, _, _ in results]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    order = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    st.finish(order >= a.min_order,
              f"order in d0 {order:.2f} (shifting {a.shifting}; accepted >= {a.min_order}), H/d0 = {a.levels}")


if __name__ == "__main__":
    main()
