#!/usr/bin/python3
"""Run one regression or stability case and check it (docs/testing.md).

usage: runCase.py CASE_SRC WORK_DIR --shizuku BIN --compare SHIZUKUCOMPARE
                  [--threads N] [--spacing D0] [--deltaT DT] [--endTime T] [--json OUT]
                  [--variant NAME] [--skip-run] [--update-reference]

CASE_SRC is a folder of tests/cases or tests/stability: system/, constant/ (the case),
README.md, and `checks`, a dictionary in the case syntax with one entry per check:

    analytic  { tolerances tolerances.analytic; analytic (analytic/pressure.csv); }
    reference { tolerances tolerances.reference; reference reference; }
    stability { stability stability.limits; }        // tests/stability/checkStability.py
    health    { tolerances tolerances.health; knownFailure yes; }   // strict expected failure:
                                                      // XFAIL when it fails, counted as a
                                                      // failure (XPASS) when it passes
    exitCode  2;                                      // optional, default 0
    variants  { long { spacing 0.01; deltaT 1e-3; } }  // optional sizes, see --variant

The case is copied to WORK_DIR/<case name> (emptied first), optionally re-sized
(--spacing rewrites `spacing` in system/particlesDict, --deltaT and --endTime the keys of
system/controlDict: used by the resolution studies), and run with
`shizuku -case ... -threads N` (log in log.shizuku). If CASE_SRC has makeAnalytic.py it
is run next as `makeAnalytic.py WORKCASE`: it writes the analytic reference files into
WORKCASE/analytic/ for the run's own spacing. Then each check runs shizukuCompare (paths
of `analytic` relative to the work case, of `tolerances` and `reference` relative to
CASE_SRC) or the stability checker. A `reference` folder holds the postProcessing files of
an earlier run at the committed size ("same as last time"); --update-reference rewrites
it from this run (after a deliberate change of the method; review the diff). The last line is `N passed, M failed`; exit status 0
when every check passes.
"""
import argparse
import json
import os
import re
import shutil
import subprocess
import sys
import time
import importlib.util
from importlib.machinery import SourceFileLoader

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON = "/usr/bin/python3"


def _top_level(text, path, key):
    """The match of the top-level `key ...;` entry (first one outside braces and comments)."""
    depth = 0
    for m in re.finditer(r"//[^\n]*|/\*.*?\*/|[{}]|(?m:^[ \t]*" + re.escape(key) + r"[ \t]+([^;]*);)", text, re.S):
        tok = m.group(0)
        if tok == "{":
            depth += 1
        elif tok == "}":
            depth -= 1
        elif depth == 0 and not tok.startswith("//") and not tok.startswith("/*"):
            return m
    raise SystemExit(f"runCase: no top-level '{key}' in {path}")


def get_key(path, key):
    """The value text of the top-level `key ...;` entry of a dictionary file."""
    with open(path) as f:
        return _top_level(f.read(), path, key).group(1).strip()


def set_key(path, key, value):
    """Replace the top-level `key ...;` entry of a dictionary file (first one outside braces)."""
    with open(path) as f:
        text = f.read()
    m = _top_level(text, path, key)
    with open(path, "w") as f:
        f.write(text[:m.start()] + f"{key} {value};" + text[m.end():])


def _entry_match(text, path, entry, key):
    """The match of `key VALUE` inside the one-level sub-dictionary `entry { ... }`."""
    m = re.search(r"(\b" + re.escape(entry) + r"\s*\{[^}]*\b" + re.escape(key) + r"\s+)([^;\s]+)", text)
    if not m:
        raise SystemExit(f"runCase: no '{entry} {{ ... {key} ... }}' in {path}")
    return m


def get_entry_key(path, entry, key):
    """The value text of `key` in the sub-dictionary `entry { ... }` (e.g. a function object's
    writeInterval) of a dictionary file."""
    with open(path) as f:
        return _entry_match(f.read(), path, entry, key).group(2)


def set_entry_key(path, entry, key, value):
    """Replace the value of `key` in the sub-dictionary `entry { ... }` of a dictionary file."""
    with open(path) as f:
        text = f.read()
    m = _entry_match(text, path, entry, key)
    with open(path, "w") as f:
        f.write(text[:m.start(2)] + str(value) + text[m.end(2):])


def load_module(path, name):
    """A Python file (with or without .py) imported as a module."""
    loader = SourceFileLoader(name, path)
    spec = importlib.util.spec_from_loader(name, loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    return mod


def load_compare(path):
    """shizukuCompare (a script without .py) imported as a module, for its dictionary parser."""
    return load_module(path, "shizukuCompare")


def copy_case(src, dst):
    shutil.rmtree(dst, ignore_errors=True)
    os.makedirs(dst)
    for name in ("system", "constant"):
        shutil.copytree(os.path.join(src, name), os.path.join(dst, name))


def remove_shifting(case):
    """Switch off the particle shift, ADS and XSPH of a copied case (the bare projection method)."""
    schemes = os.path.join(case, "system", "sphSchemes")
    with open(schemes) as f:
        s = f.read()
    s = re.sub(r"(?s)\nshifting\s*\{.*?\n\}", "\n", s)
    s = re.sub(r"\n\s*(ads|xsph)\s*\{[^}]*\}", "\n", s)
    with open(schemes, "w") as f:
        f.write(s)


def run_solver(shizuku, case, threads):
    """Run the solver on a case, its output in case/log.shizuku; returns the exit status."""
    with open(os.path.join(case, "log.shizuku"), "w") as log:
        return subprocess.run([shizuku, "-case", case, "-threads", str(threads)], stdout=log,
                              stderr=subprocess.STDOUT).returncode


def run_or_fail(shizuku, case, threads, what):
    """run_solver; on a non-zero exit print a FAIL line naming `what` and the summary line,
    and exit 1."""
    rc = run_solver(shizuku, case, threads)
    if rc != 0:
        print(f"FAIL {what}: exit status {rc} (log: {case}/log.shizuku)")
        print("0 passed, 1 failed")
        sys.exit(1)


def finish(ok, what):
    """Print one check line and the summary line of a single-check script, and exit."""
    print(("ok   " if ok else "FAIL ") + what)
    print(f"{1 if ok else 0} passed, {0 if ok else 1} failed")
    sys.exit(0 if ok else 1)


def update_reference(cmp_mod, src, case, checks):
    """Copy the run's postProcessing files that the reference checks compare into the
    case's reference folder (only those files: a reference stays small)."""
    run = cmp_mod.Series(case)
    for entry in checks.values():
        if not isinstance(entry, dict) or "reference" not in entry:
            continue
        dst = os.path.join(src, entry["reference"], "postProcessing")
        shutil.rmtree(dst, ignore_errors=True)
        tol = cmp_mod.read_dictionary(os.path.join(src, entry["tolerances"]))
        files = {tuple(full.split("/")[:2]) for key in tol for full in run.resolve(key)}
        for obj, fname in sorted(files):
            odir = os.path.join(case, "postProcessing", obj)
            for start in os.listdir(odir):
                path = os.path.join(odir, start, fname)
                if os.path.isfile(path):
                    os.makedirs(os.path.join(dst, obj, start), exist_ok=True)
                    shutil.copy(path, os.path.join(dst, obj, start, fname))
                    print(f"reference updated: {os.path.relpath(os.path.join(dst, obj, start, fname), src)}")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("work")
    ap.add_argument("--shizuku", required=True)
    ap.add_argument("--compare", required=True)
    ap.add_argument("--threads", type=int, default=2)
    ap.add_argument("--spacing")
    ap.add_argument("--deltaT")
    ap.add_argument("--endTime")
    ap.add_argument("--variant", help="apply the overrides of checks/variants/<name> (e.g. long)")
    ap.add_argument("--json", help="write every compared quantity as JSON here")
    ap.add_argument("--skip-run", action="store_true", help="check an existing work case again")
    ap.add_argument("--update-reference", action="store_true",
                    help="after the run, copy the postProcessing files named by the `reference` checks' "
                         "tolerances into CASE_SRC/<reference> (review with git diff before committing)")
    a = ap.parse_args()

    src = os.path.abspath(a.case)
    name = os.path.basename(src.rstrip("/"))
    cmp_mod = load_compare(a.compare)
    checks = cmp_mod.read_dictionary(os.path.join(src, "checks"))
    expect_exit = int(checks.pop("exitCode", 0))
    variants = checks.pop("variants", {})
    if a.variant:
        if a.variant not in variants:
            raise SystemExit(f"runCase: {src}/checks has no variants/{a.variant}")
        for key, value in variants[a.variant].items():
            if getattr(a, key, None) is None:
                setattr(a, key, value if isinstance(value, str) else repr(value))
        name_suffix = "." + a.variant
    else:
        name_suffix = ""
    case = os.path.abspath(os.path.join(a.work, name + name_suffix))

    if not a.skip_run:
        copy_case(src, case)
        if a.spacing:
            set_key(os.path.join(case, "system/particlesDict"), "spacing", a.spacing)
        if a.deltaT:
            set_key(os.path.join(case, "system/controlDict"), "deltaT", a.deltaT)
        if a.endTime:
            set_key(os.path.join(case, "system/controlDict"), "endTime", a.endTime)
        t0 = time.time()
        rc = run_solver(a.shizuku, case, a.threads)
        wall = time.time() - t0
        with open(os.path.join(case, "exitCode"), "w") as f:
            f.write(f"{rc}\n")
        print(f"{name}: shizuku exit status {rc} after {wall:.1f} s wall (log: {case}/log.shizuku)")
    else:
        with open(os.path.join(case, "exitCode")) as f:
            rc = int(f.read())
    passed, failed, xfailed = [], [], []
    if rc != expect_exit:
        with open(os.path.join(case, "log.shizuku")) as f:
            lines = f.readlines()
        errors = [ln for ln in lines if "rror" in ln or "arning" in ln][:10]
        print(f"FAIL {name}: shizuku exit status {rc}, expected {expect_exit}; errors and warnings of the log:\n"
              + "".join(errors))
        failed.append("exit status")
    else:
        passed.append("exit status")
    if os.path.isfile(os.path.join(src, "makeAnalytic.py")):
        subprocess.check_call([PYTHON, os.path.join(src, "makeAnalytic.py"), case])
    if a.update_reference:
        update_reference(cmp_mod, src, case, checks)
    all_results = {}
    for check, entry in checks.items():
        if not isinstance(entry, dict):
            raise SystemExit(f"runCase: {src}/checks: '{check}' must be a sub-dictionary")
        print(f"--- check {check}")
        if "stability" in entry:
            cmd = [PYTHON, os.path.join(HERE, "..", "stability", "checkStability.py"), case,
                   os.path.join(src, entry["stability"]), "--compare", a.compare]
            if a.variant:
                cmd += ["--variant", a.variant]
        else:
            cmd = [PYTHON, a.compare, case]
            if "reference" in entry:
                cmd.append(os.path.join(src, entry["reference"]))
            files = entry.get("analytic", [])
            for f in files if isinstance(files, list) else [files]:
                cmd += ["-analytic", os.path.join(case, f)]
            cmd += ["-tolerances", os.path.join(src, entry["tolerances"])]
        if a.json:
            cmd += ["-json", os.path.join(case, f"check.{check}.json")]
        ok = subprocess.call(cmd) == 0
        if entry.get("knownFailure") in ("yes", "on", "true"):  # strict expected failure
            if ok:
                print(f"XPASS {name}/{check}: marked knownFailure but passes; remove the mark from {src}/checks")
                failed.append(check)
            else:
                print(f"XFAIL {name}/{check} [knownFailure in {src}/checks; see the case README]")
                xfailed.append(check)
            continue
        (passed if ok else failed).append(check)
        if a.json and os.path.isfile(os.path.join(case, f"check.{check}.json")):
            with open(os.path.join(case, f"check.{check}.json")) as f:
                all_results[check] = json.load(f)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(all_results, f, indent=1)
    if xfailed:
        print(f"{name}: known failures (not counted): {' '.join(xfailed)}")
    if failed:
        print(f"{name}: failed checks: {' '.join(failed)}")
    print(f"{len(passed)} passed, {len(failed)} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
