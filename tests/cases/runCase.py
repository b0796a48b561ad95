#!/usr/bin/python3
"""Run one regression or stability case and check it (docs/testing.md).

usage: runCase.py CASE_SRC WORK_DIR --shizuku BIN --compare SHIZUKUCOMPARE
                  [--threads N] [--spacing D0] [--deltaT DT] [--endTime T] [--json OUT]
                  [--variant NAME] [--skip-run]

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
CASE_SRC) or the stability checker. A `reference` folder holds postProcessing files from a
resolution study (a finer run, written by the case's own makeReference.py with its
provenance in the file header), never this code's output at the committed size. The last
line is `N passed, M failed`; exit status 0 when every check passes.
"""
import json
import os
import subprocess
import sys
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
PYTHON = "/usr/bin/python3"


def main():
    ap = st.case_arguments()
    ap.add_argument("--spacing")
    ap.add_argument("--deltaT")
    ap.add_argument("--endTime")
    ap.add_argument("--variant", help="apply the overrides of checks/variants/<name> (e.g. long)")
    ap.add_argument("--json", help="write every compared quantity as JSON here")
    ap.add_argument("--skip-run", action="store_true", help="check an existing work case again")
    a = ap.parse_args()

    src = os.path.abspath(a.case)
    name = os.path.basename(src.rstrip("/"))
    cmp_mod = st.load_compare(a.compare)
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
        st.copy_case(src, case)
        if a.spacing:
            st.set_key(os.path.join(case, "system/particlesDict"), "spacing", a.spacing)
        if a.deltaT:
            st.set_key(os.path.join(case, "system/controlDict"), "deltaT", a.deltaT)
        if a.endTime:
            st.set_key(os.path.join(case, "system/controlDict"), "endTime", a.endTime)
        t0 = time.time()
        rc = st.run_solver(a.shizuku, case, a.threads)
        wall = time.time() - t0
        with open(os.path.join(case, "exitCode"), "w") as f:
            f.write(f"{rc}\n")
        print(f"{name}: shizuku exit status {rc} after {wall:.1f} s wall (log: {case}/log.shizuku)")
    else:
        with open(os.path.join(case, "exitCode")) as f:
            rc = int(f.read())
    if rc != expect_exit:
        with open(os.path.join(case, "log.shizuku")) as f:
            lines = f.readlines()
        errors = [ln for ln in lines if "rror" in ln or "arning" in ln][:10]
        print(f"FAIL {name}: shizuku exit status {rc}, expected {expect_exit}; errors and warnings of the log:\n"
              + "".join(errors))
    st.check(rc == expect_exit, "exit status", quiet=True)
    if os.path.isfile(os.path.join(src, "makeAnalytic.py")):
        subprocess.check_call([PYTHON, os.path.join(src, "makeAnalytic.py"), case])
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
            st.check(ok, f"{name}/{check}", xpass=f"marked knownFailure but passes; remove the mark from {src}/checks",
                     xfail=f"knownFailure in {src}/checks; see the case README")
            continue
        st.check(ok, check, quiet=True)
        if a.json and os.path.isfile(os.path.join(case, f"check.{check}.json")):
            with open(os.path.join(case, f"check.{check}.json")) as f:
                all_results[check] = json.load(f)
    if a.json:
        with open(a.json, "w") as f:
            json.dump(all_results, f, indent=1)
    if st.XFAILED:
        print(f"{name}: known failures (not counted): {' '.join(st.XFAILED)}")
    if st.FAILED:
        print(f"{name}: failed checks: {' '.join(st.FAILED)}")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
