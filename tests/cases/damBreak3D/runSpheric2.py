#!/usr/bin/python3
"""SPHERIC Test 2, the 3D dam break against a box (tutorials/damBreak3D), against Kleefsman
et al. (2005): ctest regression.damBreak3D at d0 = 5 cm to t = 1.2 s, long.damBreak3D at
d0 = 2 cm to t = 2 s (--full; about 100 min on 2 threads). Numbers in the tutorial's README.md and docs/validation.md.

usage: runSpheric2.py TUTORIAL WORK --shizuku BIN --compare SHIZUKUCOMPARE [--threads N] [--full]

Runs the case and measures it with the tutorial's spheric2Measures.py (heights unfiltered,
pressures through the same 100 Hz first-order filter on both sides). Checks:
  - exit status 0: no leak through the tank or the box (healthChecks maxLeaks 0 stops a
    run at the first);
  - arrival times (first h > 2 cm at the gauges H3 and H2, first filtered p > 500 Pa at P1)
    within ARRIVAL of the experiment's;
  - the rms height error over the run at the reservoir gauge H4 and at H2 within HEIGHT.
The bounds come from the resolution study (d0 = 5, 2.5 and 2 cm; docs/validation.md,
"SPHERIC Test 2"): the coarse run's errors with room for the second thread's different
trajectory. Full size: the arrival bounds are the 2.5 cm run's errors, the height bounds the
5 cm run's over the same 2 s (H2 0.0286 m, H4 0.0085 m; the 2 cm run: 0.022 and 0.0065 m,
2026-12-03; 0.0304 and 0.0061 m on 2026-12-06, after the solver changes of 2026-12-04 and 05,
which fails H2: docs/validation.md, "SPHERIC Test 2"). Pressure peaks are printed, not asserted
(the wall-pressure noise of issue 18); the sensors read the fluid (`faceValue fluid`).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
import shizukutest as st  # noqa: E402

# Allowed |run - experiment| per measure: (d0 = 5 cm, d0 = 2 cm).
ARRIVAL = {"H3": (0.06, 0.04), "H2": (0.05, 0.03), "P1": (0.05, 0.03)}   # s
HEIGHT = {"H4": (0.02, 0.01), "H2": (0.025, 0.028)}                     # m, rms


def main():
    a, case = st.full_size_case("damBreak3D")
    st.set_key(os.path.join(case, "system", "particlesDict"), "spacing", "2 [cm]" if a.full else "5 [cm]")
    st.set_key(os.path.join(case, "system", "controlDict"), "endTime", "2" if a.full else "1.2")
    st.run_or_fail(a.shizuku, case, a.threads, "damBreak3D")
    st.check(True, "damBreak3D: exit status 0 (a leak through the tank or the box would have stopped it: maxLeaks 0)")
    measures = st.load_module(os.path.join(a.tutorial, "spheric2Measures.py"), "spheric2Measures")
    run, exp = measures.read_run(case), measures.read_experiment()
    until = float(run["H1"][0][-1])
    m = measures.measures(run, exp, until)
    measures.print_measures("damBreak3D", m, until)
    k = 1 if a.full else 0
    for name, tol in ARRIVAL.items():
        r, e = m[name]["arrival"]
        st.check(abs(r - e) <= tol[k], f"{name} arrival {r:.3f} s within {tol[k]} s of the experiment's {e:.3f} s")
    for name, tol in HEIGHT.items():
        err = m[name]["error"][0]
        st.check(err <= tol[k], f"{name} rms height error {err:.4f} m at most {tol[k]} m")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
