#!/usr/bin/python3
"""SPHERIC Test 2, the 3D dam break against a box (tutorials/damBreak3D), against Kleefsman
et al. (2005): ctest regression.damBreak3D at d0 = 5 cm to t = 1.2 s, long.damBreak3D at
d0 = 2 cm to t = 2 s (--full; 51 min on 2 threads before the wall rows were decided again with the
solved pressure, 2026-12-06, which made the impact phase about 27 % slower at 4 cm). Numbers in the tutorial's README.md and docs/validation.md.

usage: runSpheric2.py TUTORIAL WORK --shizuku BIN --compare SHIZUKUCOMPARE [--threads N] [--full]

Runs the case and measures it with the tutorial's spheric2Measures.py (heights unfiltered,
pressures through the same 100 Hz first-order filter on both sides). Checks:
  - exit status 0: no leak through the tank or the box (healthChecks maxLeaks 0 stops a
    run at the first);
  - arrival times (first h > 2 cm at the gauges H3 and H2, first filtered p > 500 Pa at P1)
    within ARRIVAL of the experiment's;
  - the rms height error at the reservoir gauge H4 and at H2 within HEIGHT, over t <= 1.2 s;
  - full size: also H2's over the whole 2 s within LATE_H2.
The bounds come from the resolution study and from four trajectories at d0 = 5 cm (2 and 1
threads, solver tolerance 1e-8, 1e-9, 1e-10; docs/validation.md, "SPHERIC Test 2"). Up to
1.2 s the trajectories agree (H2 0.0137-0.0139 m, H4 0.0076-0.0078 m) and the 2 cm run gives
0.0150 and 0.0063 m: the bounds are those values with 20-30 % room. After 1.2 s the wave
reflected from the far wall breaks back over the box and the trajectories part: H2's error
over 2 s is 0.024-0.032 m at 5 cm and 0.030 m at 2 cm, so the 2 s bound is the 5 cm
trajectories' largest with room. The arrival bounds are the 2.5 cm run's errors. Pressure
peaks are printed, not asserted (the wall-pressure noise of issue 18); the sensors read the
fluid (`faceValue fluid`).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
import shizukutest as st  # noqa: E402

# Allowed |run - experiment| per measure: (d0 = 5 cm, d0 = 2 cm).
ARRIVAL = {"H3": (0.06, 0.04), "H2": (0.05, 0.03), "P1": (0.05, 0.03)}   # s
HEIGHT = {"H4": (0.01, 0.008), "H2": (0.017, 0.018)}                    # m, rms over t <= SETTLED
SETTLED = 1.2                                                           # s: the trajectories agree up to here
LATE_H2 = 0.035                                                         # m, rms over the whole 2 s (full size)


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
        err = measures.height_error(run, exp, name, -1.0, SETTLED)
        st.check(err <= tol[k], f"{name} rms height error up to {SETTLED} s {err:.4f} m at most {tol[k]} m")
    if a.full:
        err = m["H2"]["error"][0]
        st.check(err <= LATE_H2, f"H2 rms height error up to {until:.2f} s {err:.4f} m at most {LATE_H2} m")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
