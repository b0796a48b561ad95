#!/usr/bin/python3
"""shizukuCompare on hand-made postProcessing folders with known answers (label `unit`).

usage: compareSelfTest.py SHIZUKUCOMPARE WORKDIR

Each case writes a small run (and reference) by hand, runs shizukuCompare and checks
its exit status and the row it reports: a deviation just inside and just outside a
tolerance, abs + rel combined, windows (including a run that stops before the window
end), vectors split into components, restarts joined, nan handling, bounds, constants,
`reference initial`, analytic files named by a trailing part of the column name, and
unusable input (unknown keyword, ambiguous column) refused with exit status 1.
"""
import json
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

COMPARE, WORK = sys.argv[1:3]


def series(case, obj, start, fname, columns, rows):
    text = "# hand-made\n# columns: " + " ".join(columns) + "\n" + "".join(" ".join(r) + "\n" for r in rows)
    st.write(os.path.join(case, "postProcessing", obj, start, fname), text)


def run(args, tol):
    tfile = os.path.join(WORK, "tol")
    st.write(tfile, tol)
    out = os.path.join(WORK, "out.json")
    if os.path.exists(out):
        os.remove(out)
    p = subprocess.run([sys.executable, COMPARE] + args + ["-tolerances", tfile, "-json", out],
                       capture_output=True, text=True)
    res = json.load(open(out)) if os.path.exists(out) else []
    return p.returncode, res, p.stdout + p.stderr


shutil.rmtree(WORK, ignore_errors=True)
RUN = os.path.join(WORK, "run")
REF = os.path.join(WORK, "ref")
# p at one probe: run = 100 + t, reference = 100; a vector U; a restart at t = 2
series(RUN, "probe", "0", "p", ["time", "point0"], [[f"{t}", f"{100 + t}"] for t in (0, 1, 2, 3)])
series(RUN, "probe", "2", "p", ["time", "point0"], [[f"{t}", f"{200 + t}"] for t in (2, 3, 4)])
series(REF, "probe", "0", "p", ["time", "point0"], [[f"{t}", "100"] for t in (0, 1, 2, 3, 4)])
series(RUN, "probe", "0", "U", ["time", "point0"], [["0", "(0 0)"], ["1", "(0.5 -0.25)"]])
series(REF, "probe", "0", "U", ["time", "point0"], [["0", "(0 0)"], ["1", "(0.5 -0.2)"]])
series(RUN, "cons", "0", "conservation.dat", ["time", "volume", "kineticEnergy"],
       [["0", "1", "0"], ["1", "1.01", "2"], ["2", "0.98", "nan"]])

# restart joined: samples 0,1 from the first start (dev 0, 1), 2,3,4 from the second (dev 102..104)
rc, res, out = run([RUN, REF], "probe/p { abs 104; }")
st.check(rc == 0 and res[0]["dev"] == 104 and res[0]["time"] == 4, "restart joined; worst deviation 104 at t = 4 passes abs 104")
rc, res, out = run([RUN, REF], "probe/p { abs 103.999; }")
st.check(rc == 1 and not res[0]["ok"], "abs 103.999 fails")
rc, res, out = run([RUN, REF], "probe/p { abs 4; rel 1; }")
st.check(rc == 0 and abs(res[0]["allowed"] - 104) < 1e-12, "abs 4 + rel 1 x |100| allows 104")
rc, res, out = run([RUN, REF], "probe/p { abs 1; window (0 1); }")
st.check(rc == 0 and res[0]["samples"] == 2, "window (0 1): 2 samples, worst deviation 1")
rc, res, out = run([RUN, REF], "probe/p { abs 1000; window (0 5); }")
st.check(rc == 1 and "before the window end" in res[0]["why"], "a run that stops before the window end fails")
# vectors: U point0 split into _x and _y; the _y deviation 0.05
rc, res, out = run([RUN, REF], "probe/U { abs 0.05000001; }")
names = sorted(r["quantity"] for r in res)
st.check(rc == 0 and names == ["probe/U/point0_x", "probe/U/point0_y"], "a vector column is split into _x, _y")
rc, res, out = run([RUN, REF], "probe/U/point0 { abs 0.0499; }")
st.check(rc == 1 and [r["ok"] for r in sorted(res, key=lambda r: r["quantity"])] == [True, False],
         "vector component _y fails at abs 0.0499, _x passes")
# nan in the run: fails unless allowed
rc, res, out = run([RUN], "cons/kineticEnergy { max 10; }")
st.check(rc == 1, "a nan in the run fails a bound")
rc, res, out = run([RUN], "cons/kineticEnergy { max 10; nan allow; }")
st.check(rc == 0, "nan allow skips it")
# bounds, constants, reference initial
rc, res, out = run([RUN], "cons/volume { min 0.98; max 1.01; }")
st.check(rc == 0, "bounds [0.98, 1.01] hold")
rc, res, out = run([RUN], "cons/volume { max 1.009; }")
st.check(rc == 1 and res[0]["time"] == 1, "max 1.009 fails at t = 1")
rc, res, out = run([RUN], "cons/volume { rel 0.0201; reference initial; }")
st.check(rc == 0 and abs(res[0]["dev"] - 0.02) < 1e-12, "reference initial: worst change 0.02 within rel 0.0201")
rc, res, out = run([RUN], "cons/volume { rel 0.0199; value 1; }")
st.check(rc == 1, "value 1 with rel 0.0199 fails")
# analytic file, matched by a trailing part of the column name; interpolated in time
st.write(os.path.join(WORK, "analytic.csv"), "time,p/point0\n0,100\n10,110\n")
rc, res, out = run([RUN, "-analytic", os.path.join(WORK, "analytic.csv")], "probe/p { abs 1e-9; window (0 1); }")
st.check(rc == 0, "analytic p/point0 = 100 + t (linear interpolation) matches the first start exactly")
st.write(os.path.join(WORK, "analytic2.csv"), "time kineticEnergy\n0 0\n1 2\n")
rc, res, out = run([RUN, "-analytic", os.path.join(WORK, "analytic2.csv")],
                   "cons/kineticEnergy { abs 1e-9; window (0 2); }")
st.check(rc == 1 and "not the window" in res[0]["why"], "an analytic file that does not cover the window fails")
# unusable input
rc, res, out = run([RUN], "probe/p { abs 1; tolerance 2; }")
st.check(rc == 1 and "unknown keyword" in out, "an unknown keyword is refused")
rc, res, out = run([RUN], "probe/point0 { abs 1; }")
st.check(rc == 1 and "several files" in out, "an ambiguous column is refused")
rc, res, out = run([RUN], "nothing/p { abs 1; }")
st.check(rc == 1 and "no function object" in out, "an unknown function object is refused")
rc, res, out = run([RUN], "probe/p { window (0 1); }")
st.check(rc == 1 and "no reference" in out, "abs/rel without a reference fails")
sys.exit(st.summary())
