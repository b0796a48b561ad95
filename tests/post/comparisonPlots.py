#!/usr/bin/python3
"""The tutorials' comparison plots on hand-made postProcessing files:
tutorials/damBreakOPS/plotComparison.py (mode and mean, volume sum, histograms) and
tutorials/rotatingSquarePatchBaseline/plotComparison.py (centre pressure, density; a run that
stopped early is marked and its time printed).
Each must write a real PNG; the dam-break one must pick the latest histogram time the two
runs share, take --time, and fail with a message when they share none.

usage: comparisonPlots.py SOURCE_DIR WORKDIR
"""
import os
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

SRC, WORK = sys.argv[1:3]


def make_case(case, drift, hist_times, end=2):
    """densityError.dat (mean drifting by `drift` % per s), conservation.dat with a
    vector column, histograms at hist_times, a centre-pressure probe."""
    shutil.rmtree(case, ignore_errors=True)
    pp = os.path.join(case, "postProcessing")
    t = np.linspace(0, end, int(round(10 * end)) + 1)
    st.write(f"{pp}/densityError/0/densityError.dat",
             "# columns: time mean rms max mode meanAll rmsAll maxAll modeAll\n# units: s % % % % % % % %\n" +
             "".join(f"{x:g} {drift * x:g} 1 2 {round(drift * x * 4) / 4:g} 3 4 9 0.25\n" for x in t))
    st.write(f"{pp}/conservation/0/conservation.dat",
             "# columns: time volume nominalVolume kineticEnergy momentum angularMomentum\n"
             "# units:   s    m^2    m^2           J/m           kg/s     kg*m/s\n" +
             "".join(f"{x:g} {1 + 0.01 * drift * x:g} 1 0.5 (0 0) -0.1\n" for x in t))
    for th in hist_times:
        st.write(f"{pp}/densityError/0/{th:g}/histogram.dat",
                 "# columns: binCentre countInterior countAll\n# units:   %         -             -\n" +
                 "".join(f"{-4.875 + 0.25 * k:g} {max(0, 30 - 3 * abs(k - 20 - int(drift * th * 4)))} 40\n"
                         for k in range(40)))
    st.write(f"{pp}/centre/0/p", "# columns: time point0\n# units:   s    Pa\n" +
             "".join(f"{x:g} {-144 * (1 - x / 5) + (drift * np.sin(37 * x)):g}\n" for x in t))


def png_ok(path):
    pic = st.png_picture(path)
    if pic is None:
        return False, "missing or not a PNG"
    width, height, colours = pic
    return colours > 20 and width > 600, f"{width}x{height}, {colours} colours"


def run(script, *args):
    r = subprocess.run([sys.executable, os.path.join(SRC, "tutorials", script)] + list(args),
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    print(r.stdout)
    return r


def main():
    a, b, c = (os.path.join(WORK, n) for n in ("proposed", "baseline", "lonely"))
    make_case(a, 0.5, (1, 2))
    make_case(b, 1.5, (1, 2))
    make_case(c, 1.0, (0.5,))
    out = os.path.join(WORK, "damBreak.png")
    r = run("damBreakOPS/plotComparison.py", a, b, out)
    ok, what = png_ok(out)
    st.check(r.returncode == 0 and ok, f"dam-break comparison figure: {what}")
    st.check("histograms at t = 2 s" in r.stdout, "histograms at the latest shared time (2 s)")
    out1 = os.path.join(WORK, "damBreak_t1.png")
    r = run("damBreakOPS/plotComparison.py", a, b, out1, "--time", "1.1")
    st.check(r.returncode == 0 and os.path.isfile(out1) and "histograms at t = 1 s" in r.stdout,
             "--time 1.1 picks the nearest shared histogram time (1 s)")
    r = run("damBreakOPS/plotComparison.py", a, c, os.path.join(WORK, "none.png"))
    st.check(r.returncode != 0 and "no histogram time in common" in r.stdout,
             "no shared histogram time: non-zero exit with a message")
    out = os.path.join(WORK, "rotating.png")
    r = run("rotatingSquarePatchBaseline/plotComparison.py", a, b, out)
    ok, what = png_ok(out)
    st.check(r.returncode == 0 and ok and "stopped" not in r.stdout,
             f"rotating-patch comparison figure: {what}, no run marked as stopped")
    d = os.path.join(WORK, "brokeDown")
    make_case(d, 1.5, (), end=1.3)
    out = os.path.join(WORK, "rotating_breakdown.png")
    r = run("rotatingSquarePatchBaseline/plotComparison.py", a, d, out, "--baselineLabel", "conventional")
    ok, what = png_ok(out)
    st.check(r.returncode == 0 and ok and "conventional stopped at omega t = 1.3" in r.stdout,
             f"a baseline that stopped at omega t = 1.3 is marked and reported: {what}")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
