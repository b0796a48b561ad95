#!/usr/bin/python3
"""Regular waves from a piston wave maker (tutorials/waveFlume) against linear wave-maker
theory (ctest regression.waveFlume; long.waveFlume with --full). Numbers in the tutorial's
README.md.

usage: runWaveFlume.py TUTORIAL WORK --shizuku BIN --compare SHIZUKUCOMPARE [--threads N] [--full]

Depth h = 0.4 m, period T = 1.45383 s (k h = 1, L = 2.5133 m), stroke S = 0.050926 m:
Biesel's H/S = 0.98179 gives H = 0.05 m. At the gauges one and two wavelengths from the
paddle, over five periods from the arrival of the first full wave (waveMeasures.py), the
issue's bounds: wave height within 5 %, period within 1 %, wavelength (the two gauges'
phase) within 3 %. The damping zone's reflection coefficient is printed.
  default: d0 = 2 cm (H/d0 = 2.5, h/d0 = 20), 12 s;
  --full:  the tutorial's d0 = 1 cm, 15 s.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
import shizukutest as st  # noqa: E402

BOUNDS = {"H": 0.05, "T": 0.01, "L": 0.03}


def main():
    a, case = st.full_size_case("waveFlume")
    if not a.full:
        st.set_key(os.path.join(case, "system", "particlesDict"), "spacing", "0.02")
        st.set_key(os.path.join(case, "system", "controlDict"), "endTime", "12")
    st.run_or_fail(a.shizuku, case, a.threads, "waveFlume")
    measures = st.load_module(os.path.join(a.tutorial, "waveMeasures.py"), "waveMeasures")
    m = measures.measures(case)
    measures.report("waveFlume", m)
    th = m["theory"]
    for g in m["gauges"]:
        st.check(g["complete"], f"gauge at {g['x']:.3f} m: the record covers its window")
        st.check(abs(g["H"] / th["H"] - 1) <= BOUNDS["H"],
                 f"gauge at {g['x']:.3f} m: H = {g['H']:.5f} m within 5 % of {th['H']:.5f} m")
        st.check(abs(g["T"] / th["T"] - 1) <= BOUNDS["T"],
                 f"gauge at {g['x']:.3f} m: T = {g['T']:.5f} s within 1 % of {th['T']:.5f} s")
    st.check(abs(m["L"] / th["L"] - 1) <= BOUNDS["L"], f"wavelength {m['L']:.4f} m within 3 % of {th['L']:.4f} m")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
