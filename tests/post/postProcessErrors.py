#!/usr/bin/python3
"""shizukuPostProcess on bad input (docs/postprocessing.md): a small case is run
for two steps (times 0, 0.001, 0.002), then

  - a non-finite -time (inf, inf:, :inf, nan, -inf:) is exit 1 naming it, and
    nothing is written;
  - one corrupt time (its particles.vtp cut short) is exit 1 naming that time;
    the output is all or nothing: no postProcessing/<func>/ folder is left, and
    with -overwrite the earlier output (the live run's densityError.dat) stays
    byte for byte;
  - once the time is repaired, the same command goes ahead (no partial output
    in its way) and writes one row per time.

usage: postProcessErrors.py SHIZUKU SHIZUKUPOSTPROCESS SOURCEDIR WORKDIR
"""
import hashlib
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

SHIZUKU, POST, SRC, WORK = sys.argv[1:5]
CASE = os.path.join(WORK, "postErrorsCase")


def tree(root):
    """path -> content hash of every file below root."""
    out = {}
    for dirpath, dirnames, filenames in os.walk(root):
        for d in dirnames:
            out[os.path.relpath(os.path.join(dirpath, d), root)] = "dir"
        for f in filenames:
            with open(os.path.join(dirpath, f), "rb") as fh:
                out[os.path.relpath(os.path.join(dirpath, f), root)] = hashlib.sha256(fh.read()).hexdigest()
    return out


def post(*args):
    return subprocess.run([POST, "-case", CASE, "-threads", "1"] + list(args), capture_output=True, text=True)


def main():
    shutil.rmtree(CASE, ignore_errors=True)
    shutil.copytree(os.path.join(SRC, "tests", "badInput", "base"), CASE)
    r = subprocess.run([SHIZUKU, "-case", CASE, "-threads", "1"], capture_output=True, text=True)
    st.check(r.returncode == 0, f"the case runs: {r.stderr[-300:]}")
    st.check(st.time_dirs(CASE) and len(st.time_dirs(CASE)) == 3, f"three saved times: {st.time_dirs(CASE)}")
    before = tree(CASE)
    for sel in ("inf", "inf:", ":inf", "nan", "-inf:", "0:nan", "0,inf"):
        r = post("-func", "fluidExtent", "-time", sel)
        st.check(r.returncode == 1 and "is not a finite time" in r.stderr and tree(CASE) == before,
                 f"-time {sel}: exit 1, 'is not a finite time', nothing written: {r.returncode} {r.stderr.strip()[-200:]}")
    vtp = os.path.join(CASE, "0.001", "particles.vtp")
    good = open(vtp, "rb").read()
    with open(vtp, "wb") as f:
        f.write(good[:len(good) // 2])
    before = tree(CASE)
    r = post("-func", "fluidExtent")
    st.check(r.returncode == 1 and "time 0.001" in r.stderr and "0.001/particles.vtp" in r.stderr,
             f"a corrupt time: exit 1 naming it: {r.stderr.strip()[-300:]}")
    st.check(tree(CASE) == before, "a corrupt time: nothing written (no postProcessing/fluidExtent, no temporary)")
    r = post("-func", "densityError", "-overwrite")
    st.check(r.returncode == 1 and "time 0.001" in r.stderr, f"-overwrite, a corrupt time: exit 1: {r.stderr[-200:]}")
    st.check(tree(CASE) == before, "-overwrite, a corrupt time: the live run's densityError output stays as it was")
    with open(vtp, "wb") as f:
        f.write(good)
    r = post("-func", "fluidExtent")
    out = os.path.join(CASE, "postProcessing", "fluidExtent", "0")
    rows = [l for l in open(os.path.join(out, os.listdir(out)[0]))if not l.startswith("#")] if os.path.isdir(out) else []
    st.check(r.returncode == 0 and len(rows) == 3, f"repaired: the rerun goes ahead, 3 rows: {r.stderr[-200:]}")
    st.check(not [n for n in os.listdir(os.path.dirname(out)) if ".tmp-" in n], "no temporary folder left")
    r = post("-func", "densityError", "-overwrite")
    st.check(r.returncode == 0 and tree(CASE) != before, "repaired: -overwrite replaces the densityError output")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
