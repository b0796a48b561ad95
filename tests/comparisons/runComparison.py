#!/usr/bin/python3
"""The paper's comparisons at CI size (issue 5; label `comparison`, docs/testing.md).

usage: runComparison.py NAME WORK --shizuku BIN --proposed DIR --baseline DIR
                        --spacing D0 --deltaT DT --endTime T --window T0 T1 [--threads N]

Copies the two tutorial cases (the proposed method and the variant the paper beats) into
WORK/NAME/, overrides `spacing` (system/particlesDict) and `deltaT`, `endTime`
(system/controlDict), runs both, and asserts the paper's ordering:
  1. the proposed method runs to endTime with exit status 0;
  2. it stays stable at least as long as the baseline (which may stop with exit 2);
  3. over the window [T0, T1] (the part of it the baseline reached, at least half of it)
     the time average of the interior density-error mode (eq. 22, densityError.dat) and
     of the interior mean are lower for the proposed method.
Prints the numbers; the last line is `N passed, M failed`."""
import argparse
import os
import re
import shutil
import subprocess
import sys

failures = []
passes = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    (passes if cond else failures).append(what)
    return cond


def set_entry(path, key, value):
    text = open(path).read()
    new, n = re.subn(rf"(?m)^{key}\s+[^;]*;", f"{key} {value};", text)
    if n != 1:
        raise SystemExit(f"runComparison: no single '{key}' entry in {path}")
    open(path, "w").write(new)


def prepare(src, dst, a):
    shutil.rmtree(dst, ignore_errors=True)
    shutil.copytree(src, dst, ignore=shutil.ignore_patterns("[0-9]*", "postProcessing", "plots", "log.*"))
    set_entry(os.path.join(dst, "system", "particlesDict"), "spacing", a.spacing)
    for key in ("deltaT", "endTime"):
        set_entry(os.path.join(dst, "system", "controlDict"), key, getattr(a, key))
    return dst


def run(bin_, case, threads):
    with open(os.path.join(case, "log.shizuku"), "w") as log:
        rc = subprocess.run([bin_, "-case", case, "-threads", str(threads)], stdout=log, stderr=subprocess.STDOUT).returncode
    return rc


def density_error(case):
    """[(t, mean, mode)] of the interior columns of densityError.dat."""
    path = os.path.join(case, "postProcessing", "densityError", "0", "densityError.dat")
    rows = []
    for line in open(path):
        if line.startswith("#") or not line.strip():
            continue
        v = line.split()
        rows.append((float(v[0]), float(v[1]), float(v[4])))
    return rows


def main():
    p = argparse.ArgumentParser()
    p.add_argument("name")
    p.add_argument("work")
    p.add_argument("--shizuku", required=True)
    p.add_argument("--proposed", required=True)
    p.add_argument("--baseline", required=True)
    p.add_argument("--spacing", required=True)
    p.add_argument("--deltaT", required=True)
    p.add_argument("--endTime", required=True)
    p.add_argument("--window", nargs=2, type=float, required=True)
    p.add_argument("--threads", type=int, default=2)
    a = p.parse_args()
    root = os.path.join(a.work, a.name)
    os.makedirs(root, exist_ok=True)
    cases = {k: prepare(src, os.path.join(root, k), a) for k, src in (("proposed", a.proposed), ("baseline", a.baseline))}
    rc = {k: run(a.shizuku, c, a.threads) for k, c in cases.items()}
    series = {k: density_error(c) for k, c in cases.items()}
    end = {k: (s[-1][0] if s else 0.0) for k, s in series.items()}
    for k in cases:
        print(f"     {k}: exit status {rc[k]}, last densityError sample at t = {end[k]:.4g} s ({cases[k]})")
    check(rc["proposed"] == 0 and end["proposed"] >= float(a.endTime) * (1 - 1e-6) - 1e-9,
          f"{a.name}: the proposed method runs to endTime {a.endTime} (exit status {rc['proposed']})")
    check(rc["baseline"] != 0 or rc["proposed"] == 0,
          f"{a.name}: the proposed method stays stable at least as long as the baseline")
    t0, t1 = a.window
    t1 = min(t1, end["baseline"])
    if check(t1 - t0 >= 0.5 * (a.window[1] - a.window[0]),
             f"{a.name}: the baseline reached at least half the window ({t0}, {a.window[1]}) s (t = {end['baseline']:.4g})"):
        avg = {}
        for k, s in series.items():
            w = [r for r in s if t0 <= r[0] <= t1]
            avg[k] = (sum(r[1] for r in w) / len(w), sum(r[2] for r in w) / len(w), len(w))
        for k, (mean, mode, n) in avg.items():
            print(f"     {k}: over {t0} <= t <= {t1:.4g} s ({n} samples) interior density error: mean {mean:.3f} %, "
                  f"mode {mode:.3f} %")
        check(abs(avg["proposed"][1]) < abs(avg["baseline"][1]),
              f"{a.name}: time-averaged interior density-error mode lower for the proposed method "
              f"({avg['proposed'][1]:.3f} % < {avg['baseline'][1]:.3f} %)")
        check(abs(avg["proposed"][0]) < abs(avg["baseline"][0]),
              f"{a.name}: time-averaged interior mean density error lower for the proposed method "
              f"({avg['proposed'][0]:.3f} % < {avg['baseline'][0]:.3f} %)")
    print(f"{len(passes)} passed, {len(failures)} failed")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
