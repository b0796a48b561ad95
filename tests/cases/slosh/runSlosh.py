#!/usr/bin/python3
"""Sloshing in a tank (tutorials/slosh) against linear theory and SPHERIC Test 10
(ctest regression.slosh; long.slosh with --full). Numbers in the tutorial's README.md.

usage: runSlosh.py TUTORIAL WORK --shizuku BIN --compare SHIZUKUCOMPARE [--threads N] [--full]

Free decay of the first mode (L = 1 m, h = 0.5 m, a = 0.02 m, started flat with the mode's
linear velocity field): the period at the gauge 0.1 m from the left wall, fitted over the
first two periods of linear theory, within 2 % of T1 = 2 pi / omega_1, omega_1^2 =
g (pi/L) tanh(pi h/L) = 1.1818 s (the issue's bound). Measured 2026-12-06 (one thread
unless two are named): 2D +1.11 % at d0 = 2 cm, +1.03 % at 1 cm, +0.54 % at 5 mm (two);
the 3D thin tank 8 cm broad (no-slip front and back walls) +0.88 % at 2 cm and +1.07 % /
+1.45 % (one / two) at 1 cm, eight particles across. 4 cm broad, four across, five runs gave
+1.14 to +2.11 % (no-slip or slip side walls, or no viscous term), so the 3D check runs the
tank 8 cm broad (tutorials/slosh/README.md).
  default: 2D at d0 = 1 cm to 2.4 s (about 1 min);
  --full:  2D at 5 mm to 4.2 s, the 3D thin tank at d0 = 1 cm, 8 cm broad, to 2.5 s (15 min
           on one thread), and SPHERIC Test 10 at d0 = 3 mm: the first impact's peak time within 20 ms of the
           experiment's 2.3749 s (measured -12.7 ms at 6 mm) and the quasi-static hump's
           peak within 20 % of 386 Pa (+12 % at 6 mm). The impact peaks are printed, not
           asserted (the note and README say why). Since the wall normal of eq. 11d
           (2026-12-06) the impact's time is its first burst's (sloshMeasures.first_burst:
           the largest sample within 10 ms of the first above half the experiment's peak, on
           both): -5.2 ms, 5186 Pa against 3683; the window's largest sample is then a
           one-step spike of 37.5 kPa at 2.4729 s (+98 ms), where the experiment reads 700 Pa.
           With the wall normal before, the impact was the window's largest, 66 kPa at +11 ms.
           Measured then: 2D +0.56 %, 3D +0.91 %, hump 374 Pa (-3 %).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
import shizukutest as st  # noqa: E402

BOUND = 0.02


def run_decay(a, measures, src, name, spacing, end, what, edits=()):
    case = os.path.join(os.path.abspath(a.work), name)
    st.copy_case(src, case)
    for path, old, new in edits:
        st.replace_once(os.path.join(case, path), old, new)
    st.set_key(os.path.join(case, "system", "particlesDict"), "spacing", spacing)
    st.set_key(os.path.join(case, "system", "controlDict"), "endTime", end)
    st.run_or_fail(a.shizuku, case, a.threads, name)
    m = measures.measures(*measures.read_elevation(case), 1.0, 0.5, 0.02)
    st.check(abs(m["error"]) <= 100 * BOUND,
             f"{what}: first-mode period {m['period']:.4f} s within {100 * BOUND:.0f} % of {m['theory']:.4f} s "
             f"({m['error']:+.2f} %)")
    st.check(0.9 <= m["amplitude"] <= 1.15, f"{what}: fitted amplitude {m['amplitude']:.3f} of the linear mode's")


def main():
    a, case = st.full_size_case("slosh")
    measures = st.load_module(os.path.join(a.tutorial, "sloshMeasures.py"), "sloshMeasures")
    if not a.full:
        run_decay(a, measures, a.tutorial, "sloshDecay2D", "0.01", "2.4", "2D, d0 = 1 cm")
        return st.summary()
    run_decay(a, measures, a.tutorial, "sloshDecay2DFine", "0.005", "4.2", "2D, d0 = 5 mm")
    run_decay(a, measures, os.path.join(a.tutorial, "thinTank3D"), "sloshDecay3D", "0.01", "2.5",
              "3D thin tank 8 cm broad, d0 = 1 cm")
    spheric = os.path.join(os.path.abspath(a.work), "sphericTest10")
    st.copy_case(os.path.join(a.tutorial, "sphericTest10"), spheric)
    import shutil
    shutil.copytree(os.path.join(a.tutorial, "sphericTest10", "data"), os.path.join(spheric, "data"))
    st.set_key(os.path.join(spheric, "system", "controlDict"), "endTime", "2.6")
    st.run_or_fail(a.shizuku, spheric, a.threads, "sphericTest10")
    m = measures.spheric_measures(spheric)
    hump, impact = m["hump"], m["impact1"]
    st.check(abs(hump["peak"] / hump["expPeak"] - 1) <= 0.2,
             f"SPHERIC 10: quasi-static hump {hump['peak']:.0f} Pa within 20 % of {hump['expPeak']:.0f} Pa")
    st.check(abs(impact["burstTime"] - impact["expBurstTime"]) <= 0.02,
             f"SPHERIC 10: first impact at {impact['burstTime']:.4f} s within 20 ms of {impact['expBurstTime']:.4f} s")
    print(f"not asserted: first impact peak {impact['burstPeak']:.0f} Pa against the experiment's "
          f"{impact['expBurstPeak']:.0f} Pa; the window's largest sample {impact['peak']:.0f} Pa at {impact['time']:.4f} s")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
