#!/usr/bin/env python3
"""Run every tutorial for a few steps with two builds of shizuku and compare the fields.

  bench/compareBuilds.py OLD_SHIZUKU NEW_SHIZUKU [-steps 50] [-threads 2] [-tutorials a,b] [-adaptive]

For a change that should not alter results (a restructuring, a faster kernel): each
tutorial is copied twice into a temporary folder, its controlDict set to stop after
`steps` steps of its own deltaT and to write only then, run with each build, and the
particle fields of the last time compared (largest absolute difference of position,
velocity and pressure, and whether they are identical bit for bit). -adaptive also runs
the tutorials with `adjustTimeStep yes` (the time-step limits of the effects).
Exit 1 when a run fails. Prints one line per tutorial.
"""
import argparse, os, re, shutil, subprocess, sys, tempfile
import numpy as np
from vtk.util.numpy_support import vtk_to_numpy
import vtk

TOP = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def read_fields(vtp):
    r = vtk.vtkXMLPolyDataReader()
    r.SetFileName(vtp)
    r.Update()
    out = r.GetOutput()
    f = {"x": vtk_to_numpy(out.GetPoints().GetData())}
    pd = out.GetPointData()
    for name in ("U", "p", "id"):
        a = pd.GetArray(name)
        if a is not None:
            f[name] = vtk_to_numpy(a)
    order = np.argsort(f["id"])  # the same particle in both runs, whatever the ordering
    return {k: v[order] for k, v in f.items()}


def set_entry(text, key, value):
    pat = re.compile(r"^(\s*)%s\s+[^;]*;" % re.escape(key), re.M)
    if pat.search(text):
        return pat.sub(lambda m: "%s%s %s;" % (m.group(1), key, value), text, count=1)
    return text + "\n%s %s;\n" % (key, value)


def prepare(src, dst, steps, adaptive):
    shutil.copytree(src, dst, ignore=shutil.ignore_patterns("[0-9]*", "postProcessing", "plots", "log.*", "*.pvd"))
    cd = os.path.join(dst, "system", "controlDict")
    text = open(cd).read()
    dt = float(re.search(r"^\s*deltaT\s+([^;\s]+)", text, re.M).group(1))
    text = set_entry(text, "endTime", repr(steps * dt))
    text = set_entry(text, "writeControl", "timeStep")
    text = set_entry(text, "writeInterval", str(steps))
    text = set_entry(text, "progressInterval", str(steps))
    if adaptive:
        text = set_entry(text, "adjustTimeStep", "yes")
    open(cd, "w").write(text)


def last_time(case):
    times = [d for d in os.listdir(case) if re.fullmatch(r"[0-9.e+-]+", d) and os.path.isdir(os.path.join(case, d))]
    return max(times, key=float)


def run(exe, case, threads):
    r = subprocess.run([exe, "-case", case, "-threads", str(threads), "-noFunctionObjects"],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        sys.stderr.write(r.stdout[-3000:])
        raise SystemExit("compareBuilds: %s failed on %s (exit %d)" % (exe, case, r.returncode))
    return read_fields(os.path.join(case, last_time(case), "particles.vtp")), last_time(case)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("-steps", type=int, default=50)
    ap.add_argument("-threads", type=int, default=2)
    ap.add_argument("-tutorials", default="")
    ap.add_argument("-adaptive", action="store_true")
    a = ap.parse_args()
    names = a.tutorials.split(",") if a.tutorials else sorted(os.listdir(os.path.join(TOP, "tutorials")))
    variants = [False, True] if a.adaptive else [False]
    with tempfile.TemporaryDirectory(prefix="compareBuilds") as tmp:
        for name in names:
            src = os.path.join(TOP, "tutorials", name)
            if not os.path.isfile(os.path.join(src, "system", "controlDict")):
                continue
            for adaptive in variants:
                label = name + (" (adaptive dt)" if adaptive else "")
                res = []
                for tag, exe in (("old", a.old), ("new", a.new)):
                    case = os.path.join(tmp, "%s-%s-%d" % (name, tag, adaptive))
                    prepare(src, case, a.steps, adaptive)
                    res.append(run(os.path.abspath(exe), case, a.threads))
                (f0, t0), (f1, t1) = res
                diffs = {k: float(np.max(np.abs(f0[k] - f1[k]))) if len(f0[k]) else 0.0 for k in ("x", "U", "p")}
                same = all(np.array_equal(f0[k], f1[k]) for k in ("x", "U", "p"))
                print("%-44s t = %-8s n = %6d  max|dx| %.3g m  max|dU| %.3g m/s  max|dp| %.3g Pa  %s"
                      % (label, t1, len(f0["x"]), diffs["x"], diffs["U"], diffs["p"],
                         "identical" if same else "differs") + ("" if t0 == t1 else "  (times %s / %s)" % (t0, t1)))


if __name__ == "__main__":
    main()
