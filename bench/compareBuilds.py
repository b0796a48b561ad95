#!/usr/bin/python3
"""Run every tutorial for a few steps with two builds of shizuku and compare the fields.

  bench/compareBuilds.py OLD_SHIZUKU NEW_SHIZUKU [-steps 50] [-threads 2] [-tutorials a,b] [-adaptive]
  bench/compareBuilds.py OLD_SHIZUKU NEW_SHIZUKU -speed 5 [-steps 300] [-threads 1] [-tutorials damBreak]

For a change that should not alter results (a restructuring, a faster kernel): each
tutorial is copied twice into a temporary folder, its controlDict set to stop after
`steps` steps of its own deltaT and to write only then, run with each build, and the
particle fields of the last time compared (largest absolute difference of position,
velocity and pressure, and whether they are identical bit for bit). -adaptive also runs
the tutorials with `adjustTimeStep yes` (the time-step limits of the effects).
Exit 1 when a run fails. Prints one line per tutorial.

-speed N: instead, time each tutorial N times with each build, alternating old and new in
one sitting (old-new, then new-old, ...), and print the best (smallest) time-loop wall time per particle-step (the log's
"us per particle-step") and the best process CPU time (user + system) per particle-step of
each build, with the ratio new/old. Measure on an idle machine.
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
    dt = float(re.search(r"^\s*deltaT\s+([0-9.eE+-]+)\s*;", text, re.M).group(1))  # not a comment line that names it
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


def execute(exe, case, threads):
    """Runs the solver; returns its log and its CPU time (user + system, s)."""
    with tempfile.TemporaryFile("w+") as log:
        proc = subprocess.Popen([exe, "-case", case, "-threads", str(threads), "-noFunctionObjects"],
                                stdout=log, stderr=subprocess.STDOUT)
        _, status, usage = os.wait4(proc.pid, 0)
        proc.returncode = os.waitstatus_to_exitcode(status)
        log.seek(0)
        text = log.read()
    if proc.returncode != 0:
        sys.stderr.write(text[-3000:])
        raise SystemExit("compareBuilds: %s failed on %s (exit %d)" % (exe, case, proc.returncode))
    return text, usage.ru_utime + usage.ru_stime


def run(exe, case, threads):
    execute(exe, case, threads)
    return read_fields(os.path.join(case, last_time(case), "particles.vtp")), last_time(case)


def speed(a, names):
    """Best of a.speed alternating runs per build: loop wall and process CPU per particle-step."""
    with tempfile.TemporaryDirectory(prefix="compareSpeed") as tmp:
        for name in names:
            src = os.path.join(TOP, "tutorials", name)
            best = {"old": [float("inf")] * 2, "new": [float("inf")] * 2}
            for rep in range(a.speed):
                # ABBA order: the machine may favour the first or the second run of a pair.
                pair = (("old", a.old), ("new", a.new))
                for tag, exe in (pair if rep % 2 == 0 else pair[::-1]):
                    case = os.path.join(tmp, "%s-%s-%d" % (name, tag, rep))
                    prepare(src, case, a.steps, False)
                    text, cpu = execute(os.path.abspath(exe), case, a.threads)
                    us = float(re.search(r"\(([0-9.eE+-]+) us per particle-step\)", text).group(1))
                    steps = int(re.search(r"End: (\d+) steps", text).group(1))
                    fluid = int(re.search(r"Pipeline \(\dD, (\d+) fluid", text).group(1))
                    cpu_us = cpu / (steps * fluid) * 1e6
                    best[tag] = [min(best[tag][0], us), min(best[tag][1], cpu_us)]
                    shutil.rmtree(case)
            o, n = best["old"], best["new"]
            print("%-32s %d steps, %d thread(s), best of %d: loop %.4g -> %.4g us/particle-step (x%.3f); "
                  "process CPU %.4g -> %.4g us/particle-step (x%.3f)"
                  % (name, a.steps, a.threads, a.speed, o[0], n[0], n[0] / o[0], o[1], n[1], n[1] / o[1]))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("old")
    ap.add_argument("new")
    ap.add_argument("-steps", type=int, default=50)
    ap.add_argument("-threads", type=int, default=2)
    ap.add_argument("-tutorials", default="")
    ap.add_argument("-adaptive", action="store_true")
    ap.add_argument("-speed", type=int, default=0)
    a = ap.parse_args()
    names = a.tutorials.split(",") if a.tutorials else sorted(os.listdir(os.path.join(TOP, "tutorials")))
    if a.speed:
        return speed(a, names)
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
