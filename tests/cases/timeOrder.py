#!/usr/bin/python3
"""Order of convergence in the time step (label `regression`).

usage: timeOrder.py CASE WORK --shizuku BIN --compare SHIZUKUCOMPARE [--levels 5]
                    [--endTime 0.4] [--threads 2]

Runs the Poiseuille start-up case (CASE = tests/cases/poiseuilleStartup) at its spacing
with dt = dt0, dt0/2, ..., dt0/2^(levels-1) to endTime, the probes sampled at the same
times, and measures the self-convergence of the probe velocities against the finest run:
e_k = max |u_k - u_finest|. For a method of order p, e_k = C (dt_k^p - dt_f^p), so the
slope of log e_k against log(dt_k - dt_f) (p = 1) or the fitted p is the order.

The projection step is first order in time (explicit predictor, one pressure solve), so
p = 1 is expected; the test asserts 0.9 <= p <= 1.1. Particle shifting, ADS and XSPH
are switched off here: they act once per step, so halving dt doubles the number of
shifts and the run does not converge in dt (measured with the proposed shifting:
differences 4.4e-6, 2.0e-6, 2.0e-6, 1.0e-6 m/s for dt = 4, 2, 1, 0.5 ms).
Measured without them: e = 4.43e-6, 2.06e-6, 8.84e-7, 2.95e-7 m/s, ratios 2.15, 2.34,
3.00 (first order predicts 2.14, 2.33, 3.00), p = 1.00."""
import math
import os
import shutil
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402


def main():
    p = st.case_arguments()
    p.add_argument("--levels", type=int, default=5)
    p.add_argument("--endTime", default="0.4")
    a = p.parse_args()
    cm = st.load_compare(a.compare)
    root = os.path.join(a.work, "timeOrder")
    shutil.rmtree(root, ignore_errors=True)
    control = os.path.join(a.case, "system", "controlDict")
    dt0 = float(st.get_key(control, "deltaT"))
    interval = int(st.get_entry_key(control, "profile", "writeInterval"))
    results = []
    for k in range(a.levels):
        case = os.path.join(root, f"dt{k}")
        st.copy_case(a.case, case)
        path = os.path.join(case, "system", "controlDict")
        st.set_key(path, "deltaT", repr(dt0 / 2 ** k))
        st.set_key(path, "endTime", a.endTime)
        # the profile probes every `interval` steps at dt0: sample at the same times
        st.set_entry_key(path, "profile", "writeInterval", interval * 2 ** k)
        st.remove_shifting(case)
        st.run_or_fail(a.shizuku, case, a.threads, f"dt = {dt0 / 2 ** k:g}")
        cols = cm.Series(case).columns
        names = sorted(c for c in cols if c.startswith("profile/U/"))
        results.append((dt0 / 2 ** k, cols[names[0]][0], [cols[c][1] for c in names]))
    dtf, tf, finest = results[-1]
    errors = []
    for dt, t, values in results[:-1]:
        if len(t) != len(tf) or abs(t - tf).max() > 1e-9:
            st.finish(False, f"dt = {dt:g}: probe times differ from the finest run's")
        e = max(float(abs(v - f)[(v == v) & (f == f)].max()) for v, f in zip(values, finest))
        errors.append((dt, e))
    for (dt, e), nxt in zip(errors, errors[1:] + [None]):
        ratio = f", ratio {e / nxt[1]:.2f} (first order: {(dt - dtf) / (nxt[0] - dtf):.2f})" if nxt else ""
        print(f"     dt = {dt:g} s: max |u - u(dt = {dtf:g})| = {e:.3g} m/s{ratio}")
    # Least-squares slope of log e against log(dt - dt_f): the order for p = 1; refine p by
    # fitting e = C (dt^p - dt_f^p) over a grid of p.
    best = None
    for i in range(501):
        pp = 0.5 + i * 0.003
        xs = [math.log(dt ** pp - dtf ** pp) for dt, _ in errors]
        ys = [math.log(e) for _, e in errors]
        c = sum(y - x for x, y in zip(xs, ys)) / len(xs)
        res = sum((y - x - c) ** 2 for x, y in zip(xs, ys))
        if best is None or res < best[1]:
            best = (pp, res)
    order = best[0]
    st.finish(0.9 <= order <= 1.1, f"order in dt {order:.2f} (expected 1: first-order projection; "
              f"accepted 0.9 to 1.1), {a.levels} time steps from {dt0:g} s to {dtf:g} s")


if __name__ == "__main__":
    main()
