#!/usr/bin/python3
"""The Buchner (2002) dam-break impact against the far wall (tutorials/damBreakWallPressure):
sensor P1 against the experiment, and four sensor heights against converged runs of other
codes (ctest regression.damBreakWallPressure at d0 = H/30, long.damBreakWallPressure at the
tutorial's H/60). Numbers in the tutorial's README.md.

usage: runWallPressure.py TUTORIAL WORK --shizuku BIN --compare SHIZUKUCOMPARE
                          [--threads N] [--full]

Copies the tutorial to WORK/damBreakWallPressure (WORK/damBreakWallPressureFull with
--full), sets d0 = 2 cm without --full, runs it to t sqrt(g/H) = 7.48 and measures P1 with
the tutorial's wallPressureMeasures.py. The checks are issue 18's, against the digitised
P1 (TrixiParticles' set; the PySPH set agrees within its reading error):
  - exit status 0, no particle lost;
  - the first crossing of 0.3 rho g H within 3 % of t sqrt(g/H) = 2.616;
  - the first and second peaks of the 100 Hz low-pass signal within 20 % of 0.687 and
    0.877;
  - the plateau's mean over 3.5 <= t sqrt(g/H) <= 5.5 within 10 % of 0.538;
  - the plateau's noise (unfiltered, rms about the moving average over 0.1 in
    t sqrt(g/H)) at most 0.02 rho g H.
Each is printed with its measured value as `issue 18 bound`, none is asserted. The noise
bound is met on 8 of 9 H/60 trajectories of the tutorial without the Taylor correction of the
velocity (`taylorCorrection off`, 2026-12-07): 0.013-0.018 on the solver before the AMG fix of
that day (1 and 2 threads, first steps 0.18-0.22 ms), 0.0164 and 0.0216 after it (1 and 2
threads; the fix changes the coarse levels and so the trajectory). The rms is set by a few
one-step events (docs/validation.md, "The Taylor correction and the sensor noise"). The
others are not met (README.md of the tutorial, "Against the experiment").
What is asserted are the guards the resolution study supports. P1 reads the face value from
the fluid (`faceValue fluid`, docs/postprocessing.md); measured 2026-12-06 on 2 threads at
H/30, H/60 and H/120, the H/30 trajectories on 1 and 2 threads with solver tolerance 1e-8 and
1e-9, H/60 with 1e-8 and 1e-9 (in brackets: with the steps to each write time made equal,
the same day, 1 and 2 threads at H/30):
  - at H/30 only, the crossing (the first sample above 0.3: the impact's first burst at this
    size) within 6 % of 2.616 (+3.8 %; [+1.9, +1.9 %]);
  - with --full, the crossingMean (the 0.1 moving average above 0.3) within 5 % of the
    converged runs' 3.768 (spread 0.020): [H/60 3.769, H/120 3.675]; before the equal
    steps 3.72-3.73 at H/60 with three wall conditions. At H/60 the first sample above 0.3 is
    a spike on a slow rise (2.72 before the equal steps, [2.79]) and is not asserted; at H/30
    the first burst lifts the moving average early ([3.51, 3.51]), which is not asserted
    either (docs/validation.md, "Steps cut short at write times"). Planted at H/60: p = 0 on
    the surface particles (`pressureCondition particles`) gives 3.988 (+5.8 %) and fails,
    where the first sample above 0.3 (2.696, +3.1 %) passed the old 6 % guard;
  - filtered first peak at most 2 rho g H (0.59 on three trajectories, 0.28 and 0.31, 0.28;
    the wall row before 2026-12-02 7.2, 4.2, 6.6);
  - plateau mean within 35 % of 0.538 (-27 to -28 %, -30 and -29 %, -26 %: the water's
    plateau in this discretisation, docs/validation.md, "Which pressure the water feels");
  - plateau noise at most 0.1 rho g H (without the Taylor correction H/30 0.028-0.033 on 1
    thread, 0.035 on 2; before it 0.053-0.060 over the three H/30 trajectories, 0.062
    and 0.057, 0.066; [0.047, 0.046; H/60 0.048, H/120 0.096]; with eq. 11b decided with the
    solved pressure, H/30 0.040-0.042, H/60 0.041-0.051; with the wall normal of eq. 11d H/30
    0.024-0.057, H/60 0.014-0.039 over five trajectories; with the compressibility term
    soundSpeed 48, not in the tutorial, H/30 0.028-0.084 and H/60 0.015-0.032; the wall layers'
    reading 0.077-0.094, the wall row before 2026-12-02 0.36, 0.24, 0.30);
  - with --full, the plateau's noise at most 0.025 rho g H and its robust noise (noiseRobust:
    1.4826 times the median absolute deviation about the same moving average, the background
    without the few one-step spikes of an air gap closing beside the sensor) at most 0.015:
    without the Taylor correction 0.013-0.0216 and 0.009-0.011 over nine trajectories (above);
    the correction planted back (`taylorCorrection on`) gives 0.041 and 0.0185 on this
    solver's 2-thread trajectory and fails both. The rms guard is weaker than issue 18's 0.02:
    of the eight with-correction trajectories before the AMG fix (rms 0.014-0.039; robust 0.014
    and 0.018 on 2 threads, 0.019 on 1), three were above 0.02 and two above 0.025; 0.045 (rms 0.050) with the
    wall normal taken toward the wall particles' weighted centre, which tilts as the water runs
    up past the wall's lattice (docs/validation.md, "The wall normal the wall row sees");
  - the impulse balance over the plateau (wallPressureMeasures.py: the water's change of x
    momentum against the end walls' impulse, |dM_x - (I_left - I_far)| / I_far; conservation
    written every step here) at most 0.05: 0.002-0.011, 0.0008 and 0.0001, 0.00006; the same
    sensors reading the wall layers 0.13-0.16 over four H/30 trajectories and 0.11, 0.13 at
    H/60 (they read more than the water feels), and fail.
The same equations solved by other codes, converged (De Courcy et al. 2024 and
TrixiParticles.jl's WCSPH and EDAC, all at H/400; the tutorial's data/README.md), give P1's
plateau 0.392-0.400, and both experiments (Buchner 0.538, Lobovsky et al. 2014 0.520) lie
above every one of them: the experiment bounds above ask for physics the 2D one-phase model
does not have (docs/validation.md, "The converged model against two experiments"). What is
asserted against them:
  - the plateau mean at each of the four heights of Lobovsky's sensors (S1, S2, S3, P1:
    6, 30, 60 and 160 mm) within 10 % (H/30) or 7 % (--full, H/60) of the mean of the three
    converged runs' plateaus. Measured (2026-12-06): H/30 -2.8, -5.0, -4.9, -0.4 % on one
    thread and -4.1, -7.3, -4.6, -1.5 % on two; H/60 -4.0, -3.5, -2.8, -0.1 %; H/120 -5.2,
    -3.7, -1.1, +3.1 % [H/30 -3.6, -5.1, -5.1, -2.4 and -3.6, -4.9, -5.1, -1.8 %; H/60 -2.3,
    -2.7, -2.1, +0.1 %; H/120 -5.0, -4.1, -1.5, +3.7 %]; the three converged runs themselves spread by 3.7, 1.8, 1.6 and 2.3 %
    of their mean. The surface condition on the particles (p = 0 half a spacing too low,
    `pressureCondition particles`) gives -4.0, -7.1, -9.3 and -15.0 % at H/30 and fails;
    P1 read from the wall layers gives +36 % and fails.
The published single-phase runs that agree with the experiment at P1 read it with a lower,
larger probe: a 90 mm segment whose top is at 160 mm (Marrone et al. 2011, Adami et al. 2012;
the tutorial's data/README.md). The tutorial's `P1probe90mm` reads that segment; issue 18's
bounds (the four measures and the noise) are printed for it too, and asserted is:
  - its plateau's time mean within 10 % (H/30) or 7 % (--full) of the mean of the three
    published runs at H/320 read the same way (Marrone's delta-SPH 0.550, TrixiParticles' WCSPH
    0.586 and EDAC 0.587; mean 0.574, spread 0.037). Measured 2026-12-07 on 2 threads: H/30
    0.557 (-3.0 %), H/60 0.573 (-0.3 %; 0.573 on 1 thread), H/120 0.586 (+2.0 %). The surface
    condition on the particles planted back (`pressureCondition particles`) gives 0.509
    (-11.3 %) at H/30 and fails.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
import shizukutest as st  # noqa: E402

EXPERIMENT = {"crossing": 2.616, "peak1": 0.687, "plateau": 0.538, "peak2": 0.877}
ISSUE_BOUND = {"crossing": 0.03, "peak1": 0.20, "plateau": 0.10, "peak2": 0.20}
ISSUE_NOISE = 0.02
GUARD = {"crossing": 0.06, "plateau": 0.35}
GUARD_PEAK1, GUARD_NOISE = 2.0, 0.10
GUARD_NOISE_ROBUST_FULL = 0.015
GUARD_NOISE_FULL = 0.025
GUARD_BALANCE = 0.05
GUARD_CROSSING_MEAN = 0.05
GUARD_CONVERGED = {False: 0.10, True: 0.07}


def print_issue_bounds(prefix, m):
    """Issue 18's five P1 bounds against the experiment, with the measured values (printed, not asserted)."""
    for key, ref in EXPERIMENT.items():
        dev = m[key] / ref - 1
        when = f" at t* = {m[key + '_t']:.3f}" if key + "_t" in m else ""
        print(f"{prefix} {key} {m[key]:.3f}{when} against the experiment's {ref:.3f}: {100 * dev:+.1f} % "
              f"(bound {100 * ISSUE_BOUND[key]:.0f} %: {'met' if abs(dev) <= ISSUE_BOUND[key] else 'not met'})")
    print(f"{prefix} plateau noise {m['noise']:.4f} rho g H (bound {ISSUE_NOISE}: "
          f"{'met' if m['noise'] <= ISSUE_NOISE else 'not met'})")


def main():
    a, case = st.full_size_case("damBreakWallPressure")
    if not a.full:
        st.set_key(os.path.join(case, "system", "particlesDict"), "spacing", "2 [cm]")
    st.set_entry_key(os.path.join(case, "system", "controlDict"), "conservation", "writeInterval", "1")
    st.run_or_fail(a.shizuku, case, a.threads, "damBreakWallPressure")
    st.check(True, "damBreakWallPressure: exit status 0")
    measures = st.load_module(os.path.join(a.tutorial, "wallPressureMeasures.py"), "wallPressureMeasures")
    m = measures.measures(*measures.read_run(os.path.join(case, "postProcessing", "P1", "0", "wallPressure.dat")))
    print_issue_bounds("issue 18 bound: P1", m)
    for key, tol in GUARD.items():
        if key == "crossing" and a.full:
            continue  # at H/60 the first sample above 0.3 is a spike on a slow rise: crossingMean below
        dev = m[key] / EXPERIMENT[key] - 1
        st.check(abs(dev) <= tol, f"P1 {key} {m[key]:.3f} within {100 * tol:.0f} % of {EXPERIMENT[key]} ({100 * dev:+.1f} %)")
    conv_crossing, conv_spread = measures.converged_crossing()
    dev = m["crossingMean"] / conv_crossing - 1
    text = (f"P1 crossingMean (the 0.1 moving average above 0.3) {m['crossingMean']:.3f} against the converged "
            f"runs' {conv_crossing:.3f} (spread {conv_spread:.3f}): {100 * dev:+.1f} %")
    if a.full:
        st.check(abs(dev) <= GUARD_CROSSING_MEAN, text + f", within {100 * GUARD_CROSSING_MEAN:.0f} %")
    else:
        print(text + " (not asserted at H/30: the impact's first burst lifts the mean there)")
    st.check(m["peak1"] <= GUARD_PEAK1, f"P1 first peak (100 Hz low-pass) {m['peak1']:.3f} at most {GUARD_PEAK1} rho g H")
    st.check(m["noise"] <= GUARD_NOISE, f"P1 plateau noise {m['noise']:.4f} at most {GUARD_NOISE} rho g H")
    robust = f"P1 plateau robust noise {m['noiseRobust']:.4f} rho g H"
    if a.full:
        st.check(m["noiseRobust"] <= GUARD_NOISE_ROBUST_FULL, robust + f" at most {GUARD_NOISE_ROBUST_FULL}")
        st.check(m["noise"] <= GUARD_NOISE_FULL, f"P1 plateau noise {m['noise']:.4f} at most {GUARD_NOISE_FULL} rho g H")
    else:
        print(robust + " (asserted at full size only)")
    converged, tol = measures.converged(), GUARD_CONVERGED[bool(a.full)]
    reached = measures.heights(case)
    for name, y in measures.HEIGHTS:
        mean, spread = converged[name]
        dev = reached[name][-1] / mean - 1
        st.check(abs(dev) <= tol,
                 f"{name} ({1000 * y:.0f} mm up) plateau {reached[name][-1]:.3f} within {100 * tol:.0f} % of "
                 f"the converged runs' {mean:.3f} (spread {spread:.3f}): {100 * dev:+.1f} %")
    t, p, pf = measures.read_run(os.path.join(case, "postProcessing", "P1probe90mm", "0", "wallPressure.dat"))
    print_issue_bounds("issue 18 bound, P1 read as the published runs read it (90 mm, 70-160 mm up):",
                       measures.measures(t, p, pf))
    mean, spread = measures.literature_probe_converged()
    plateau = measures.window_means(t, p)[-1]
    dev = plateau / mean - 1
    tol = GUARD_CONVERGED[bool(a.full)]
    st.check(abs(dev) <= tol, f"P1 over the published runs' 90 mm probe: plateau time mean {plateau:.3f} within "
             f"{100 * tol:.0f} % of their {mean:.3f} at H/320 (spread {spread:.3f}): {100 * dev:+.1f} %")
    balance = measures.impulse_balance(case)
    st.check(balance <= GUARD_BALANCE, f"far and left walls' impulse over the plateau against the water's change of "
             f"x momentum: {100 * balance:.2f} % of the far wall's impulse apart, at most {100 * GUARD_BALANCE:.0f} %")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
