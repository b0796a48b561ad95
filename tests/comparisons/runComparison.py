#!/usr/bin/python3
"""The paper's comparisons at CI size (label `comparison`, docs/testing.md).

usage: runComparison.py NAME WORK --shizuku BIN --compare SHIZUKUCOMPARE --proposed DIR
                        --baseline DIR --spacing D0 --deltaT DT --endTime T --window T0 T1
                        [--threads N] [--measure density|pressureNoise] [--baselineBreaksDown]
                        [--trajectories TOL [TOL ...]]

Copies the two tutorial cases (the proposed method and the variant the paper beats) into
WORK/NAME/, overrides `spacing` (system/particlesDict) and `deltaT`, `endTime`
(system/controlDict) with tests/support/shizukutest.py's helpers, runs both, reads their
postProcessing with shizukuCompare's reader, and asserts the paper's ordering:
  1. the proposed method runs to endTime with exit status 0;
  2. it stays stable at least as long as the baseline (which may stop with exit 2): its
     last densityError sample is not earlier than the baseline's; with --baselineBreaksDown
     the baseline must stop with a numerical failure (exit 2) before endTime (the paper's
     "the conventional method broke down at omega t = 4.3"), its time (of the last good
     state written) read from the log;
  3. over the window [T0, T1] (the part of it the baseline reached: at least half of it, or
     with --baselineBreaksDown at least 1 s)
     the time average of the interior density-error mode (eq. 22, densityError.dat) and
     of the interior mean are smaller in magnitude for the proposed method (--measure
     density, the default), or (--measure pressureNoise) the centre-pressure probe
     `centre/p/point0` fluctuates less about its 0.1 s moving average (the paper's
     "pressure disturbance" of the stabilized source term);
  4. every number it prints is asserted: each run's densityError series (and the centre
     probe) is finite at every sample (a baseline expected to break down: all but its
     last); the pressure measure needs a finite history of at least three widths of the
     moving average in the window (else the check fails, naming it); with --densityBound B the proposed run's time-averaged
     interior |mean| and |mode| (eq. 22) over the window are below B % (from the resolution
     study in docs/testing.md).
With --trajectories the two methods run once per PPE solver tolerance given (one thread
each, two runs at a time): every tolerance converges far below the discretisation error,
but the flow is chaotic, so each is another trajectory of the same method (the same
sampling as the wall-pressure study of docs/validation.md). Checks 1, 2 and 4 hold for
every trajectory; check 3 compares the methods' averages over the trajectories, because
at CI size one trajectory's time-averaged density error scatters as much as the two
methods differ (tests/comparisons/CMakeLists.txt).
Prints the numbers; the last line is `N passed, M failed`."""
import os
import re
import sys
from collections import namedtuple
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402


def pressure_noise(t, p, t0, t1, last_may_fail=False):
    """rms of a probe history about its moving average over 0.1 s, within [t0, t1]: the
    pressure disturbance the paper attributes to the stabilized source term. None when
    the history within the window is not finite (but, with last_may_fail, its last sample:
    a run that broke down) or shorter than three averaging widths."""
    import numpy as np
    inside = (t >= t0) & (t <= t1)
    t, p = t[inside], p[inside]
    if last_may_fail and len(p) and not np.isfinite(p[-1]):
        t, p = t[:-1], p[:-1]
    if len(t) < 2 or not np.all(np.isfinite(p)):
        return None
    w = max(3, int(round(0.1 / float(np.median(np.diff(t))))) | 1)
    if len(t) < 3 * w:
        return None
    smooth = np.convolve(p, np.ones(w) / w, mode="same")
    m = (t >= t0 + 0.05) & (t <= t1 - 0.05)
    return float(np.sqrt(np.mean((p[m] - smooth[m]) ** 2)))


# One solver run: exit status, case folder, its densityError (t, mean, mode), the time of
# its last sample, and (t, p) of the centre probe or None.
Run = namedtuple("Run", "rc case density end probe")


def set_tolerance(path, tol):
    """Set the pressure solver's `tolerance` in system/sphSolution (its one occurrence)."""
    with open(path) as f:
        text = f.read()
    new, n = re.subn(r"(?m)^(\s*tolerance\s+)[^;]+;", lambda m: m.group(1) + str(tol) + ";", text)
    if n != 1:
        raise SystemExit(f"{path}: expected one 'tolerance' entry, found {n}")
    with open(path, "w") as f:
        f.write(new)


def breakdown_time(log):
    """The time of the last good state the solver wrote before stopping on a numerical
    failure (every failure writes it; the failing step is one step later), from its log;
    None when the log has no such line."""
    with open(log) as f:
        m = re.search(r"Writing the last good state \(time ([0-9.eE+-]+)", f.read())
    return float(m.group(1)) if m else None


def main():
    p = st.case_arguments("name")
    p.add_argument("--proposed", required=True)
    p.add_argument("--baseline", required=True)
    p.add_argument("--spacing", required=True)
    p.add_argument("--deltaT", required=True)
    p.add_argument("--endTime", required=True)
    p.add_argument("--window", nargs=2, type=float, required=True)
    p.add_argument("--measure", choices=("density", "pressureNoise"), default="density")
    p.add_argument("--baselineBreaksDown", action="store_true")
    p.add_argument("--trajectories", nargs="+", default=None, metavar="TOL",
                   help="PPE tolerances: one trajectory of each method per value, compared on average")
    p.add_argument("--densityBound", type=float, default=None,
                   help="largest time-averaged interior |mean| and |mode| of the proposed run, percent")
    a = p.parse_args()
    if a.trajectories and a.measure != "density":
        p.error("--trajectories averages the density measure only")
    import numpy as np
    cm = st.load_compare(a.compare)
    tols = a.trajectories or [None]
    jobs = []
    for tol in tols:
        for k, src in (("proposed", a.proposed), ("baseline", a.baseline)):
            case = os.path.join(a.work, a.name, k if tol is None else f"{k}-tolerance{tol}")
            st.copy_case(src, case)
            st.set_key(os.path.join(case, "system", "particlesDict"), "spacing", a.spacing)
            for key in ("deltaT", "endTime"):
                st.set_key(os.path.join(case, "system", "controlDict"), key, getattr(a, key))
            if tol is not None:
                set_tolerance(os.path.join(case, "system", "sphSolution"), tol)
            jobs.append((tol, k, case))
    threads = a.threads if a.trajectories is None else 1
    with ThreadPoolExecutor(max_workers=1 if a.trajectories is None else 2) as pool:
        codes = list(pool.map(lambda job: st.run_solver(a.shizuku, job[2], threads), jobs))
    runs = {}  # (tolerance, method) -> Run
    for (tol, k, case), rc in zip(jobs, codes):
        cols = cm.Series(case).columns
        t, mean = cols["densityError/densityError.dat/mean"]
        run = Run(rc, case, (t, mean, cols["densityError/densityError.dat/mode"][1]),
                  float(t[-1]) if len(t) else 0.0,
                  cols["centre/p/point0"] if a.measure == "pressureNoise" else None)
        runs[(tol, k)] = run
        what = k if tol is None else f"{k} (tolerance {tol})"
        print(f"     {what}: exit status {rc}, last densityError sample at t = {run.end:.4g} s ({case})")
        # A baseline expected to break down may end on the failing sample.
        last = -1 if (k == "baseline" and a.baselineBreaksDown) else None
        finite = len(t) > 0 and all(bool(np.all(np.isfinite(v[:last]))) for v in run.density[1:])
        if run.probe is not None:
            finite = finite and len(run.probe[0]) > 0 and bool(np.all(np.isfinite(run.probe[1][:last])))
        st.check(finite, f"{a.name}: the {what} run's interior density error"
                 + (" and centre pressure are" if run.probe is not None else " is") + " finite at every sample")
    for tol in tols:
        prop, base = runs[(tol, "proposed")], runs[(tol, "baseline")]
        which = "" if tol is None else f" (tolerance {tol})"
        st.check(prop.rc == 0 and prop.end >= float(a.endTime) * (1 - 1e-6),
                 f"{a.name}: the proposed method runs to endTime {a.endTime}{which} (exit status {prop.rc})")
        st.check(prop.end >= base.end, f"{a.name}: the proposed method stays stable at least as long as the baseline"
                 f"{which} (to t = {prop.end:.4g} s against {base.end:.4g} s)")
        if a.baselineBreaksDown:
            when = breakdown_time(os.path.join(base.case, "log.shizuku"))
            st.check(base.rc == 2 and when is not None and when < float(a.endTime),
                     f"{a.name}: the baseline breaks down before endTime {a.endTime}{which} (exit status "
                     f"{base.rc}, last good state at t = {when})")
    methods = ("proposed", "baseline")
    end = {k: min(runs[(tol, k)].end for tol in tols) for k in methods}
    series = {k: [runs[(tol, k)].density for tol in tols] for k in methods}
    probe = {k: runs[(tols[0], k)].probe for k in methods if runs[(tols[0], k)].probe is not None}
    t0, t1 = a.window[0], min(a.window[1], end["baseline"])
    # A baseline expected to break down is compared over the part it ran, at least 1 s (ten
    # widths of the 0.1 s moving average); otherwise over at least half the window.
    need = 1.0 if a.baselineBreaksDown else 0.5 * (a.window[1] - a.window[0])
    if st.check(t1 - t0 >= need,
                f"{a.name}: the baseline ran at least {need:g} s of the window ({t0}, {a.window[1]}) s (to t = {end['baseline']:.4g})"):
        avg = {}
        for k, trajectories in series.items():
            each = []
            for t, mean, mode in trajectories:
                w = (t >= t0) & (t <= t1)
                each.append((float(mean[w].mean()), float(mode[w].mean()), int(w.sum())) if w.any()
                            else (np.nan, np.nan, 0))
            avg[k] = tuple(float(np.mean([e[c] for e in each])) for c in (0, 1)) + (each[0][2],)
            if len(each) > 1:
                print(f"     {k}: each trajectory's mean " + " / ".join(f"{e[0]:.3f}" for e in each)
                      + " %, mode " + " / ".join(f"{e[1]:.3f}" for e in each) + " %")
            print(f"     {k}: over {t0} <= t <= {t1:.4g} s ({avg[k][2]} samples) interior density error: "
                  f"mean {avg[k][0]:.3f} %, mode {avg[k][1]:.3f} %"
                  + (f" (average of {len(each)} trajectories)" if len(each) > 1 else ""))
        if a.densityBound is not None:
            st.check(max(abs(avg["proposed"][0]), abs(avg["proposed"][1])) < a.densityBound,
                     f"{a.name}: the proposed run's time-averaged interior density error is within "
                     f"{a.densityBound:g} % (mean {avg['proposed'][0]:.3f} %, mode {avg['proposed'][1]:.3f} %)")
        if a.measure == "density":
            st.check(abs(avg["proposed"][1]) < abs(avg["baseline"][1]),
                     f"{a.name}: time-averaged interior density-error mode lower for the proposed method "
                     f"(|{avg['proposed'][1]:.3f}| % < |{avg['baseline'][1]:.3f}| %)")
            st.check(abs(avg["proposed"][0]) < abs(avg["baseline"][0]),
                     f"{a.name}: time-averaged interior mean density error lower for the proposed method "
                     f"(|{avg['proposed'][0]:.3f}| % < |{avg['baseline'][0]:.3f}| %)")
        else:
            noise = {k: pressure_noise(*probe[k], t0, t1, k == "baseline" and a.baselineBreaksDown) for k in probe}
            for k, v in noise.items():
                st.check(v is not None, f"{a.name}: {k} centre pressure over {t0} <= t <= {t1:.4g} s finite and "
                         f"at least three 0.1 s averaging widths long; rms about its moving average "
                         + (f"{v:.3g} Pa" if v is not None else "not measurable"))
            if None not in noise.values():
                st.check(noise["proposed"] < noise["baseline"],
                         f"{a.name}: smoother centre pressure for the proposed method "
                         f"({noise['proposed']:.3g} Pa < {noise['baseline']:.3g} Pa)")
    sys.exit(st.summary())


if __name__ == "__main__":
    main()
