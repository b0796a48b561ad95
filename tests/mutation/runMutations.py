#!/usr/bin/python3
"""Plant each bug of mutations.py in turn and check that the default test labels catch it
(ctest label `mutation`; docs/testing.md, "The suite catches planted bugs").

    runMutations.py SOURCE WORK [--only NAME ...] [--list] [--binaries] [--jobs 2]

The source tree (tracked and untracked-but-not-ignored files of SOURCE) is copied once to
WORK/src (later runs copy only the files that changed) and configured once in WORK/src/build.
Then, for each mutation: apply it (its old text must occur exactly once, or the whole run
stops before building anything), build incrementally, run the mutation's expected catchers
and then the rest of the default labels (`ctest -LE 'long|mutation'`), stopping at the first
failing test, and revert. Prints `caught by <test>` or `SURVIVED` per mutation and a
summary; exit status 0 only when every mutation is caught, 1 when one survives, 2 when the
list or the build is broken. --binaries builds each mutant's solver and keeps it
(WORK/bin/shizuku.NAME), running no test: for measuring what a bug does to a case.
"""

import argparse
import contextlib
import os
import re
import shutil
import subprocess
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from mutations import MUTATIONS  # noqa: E402

DEFAULT_LABELS = ["-LE", "long|mutation"]


def sourceFiles(src):
    out = subprocess.run(["git", "-C", src, "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
                         check=True, capture_output=True).stdout.decode()
    return [f for f in out.split("\0") if f and os.path.isfile(os.path.join(src, f))]


def syncTree(src, dst):
    """Copy every source file whose content differs (keeps timestamps of unchanged ones,
    so the scratch build stays incremental)."""
    copied = 0
    for f in sourceFiles(src):
        a, b = os.path.join(src, f), os.path.join(dst, f)
        with open(a, "rb") as fa:
            data = fa.read()
        if os.path.exists(b):
            with open(b, "rb") as fb:
                if fb.read() == data:
                    continue
        os.makedirs(os.path.dirname(b), exist_ok=True)
        shutil.copy2(a, b)
        copied += 1
    return copied


def checkList(src, mutations):
    """Every old text must occur exactly once; returns the problems found."""
    problems = []
    names = set()
    for m in mutations:
        if m.name in names:
            problems.append(f"{m.name}: name used twice")
        names.add(m.name)
        path = os.path.join(src, m.file)
        if not os.path.isfile(path):
            problems.append(f"{m.name}: {m.file} does not exist")
            continue
        with open(path) as f:
            n = f.read().count(m.old)
        if n != 1:
            problems.append(f"{m.name}: the old text occurs {n} times in {m.file} (must be exactly once): {m.old!r}")
        if m.old == m.new:
            problems.append(f"{m.name}: old and new text are the same")
    return problems


def run(cmd, log, **kw):
    with open(log, "a") as f:
        f.write("$ " + " ".join(cmd) + "\n")
        f.flush()
        return subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, **kw).returncode


def failedTests(build):
    path = os.path.join(build, "Testing", "Temporary", "LastTestsFailed.log")
    if not os.path.exists(path):
        return []
    with open(path) as f:
        return [line.strip().split(":", 1)[1] for line in f if ":" in line]


def ctest(build, log, select):
    """Runs ctest with the default labels and the given selection; returns the first failing test or None."""
    failed = os.path.join(build, "Testing", "Temporary", "LastTestsFailed.log")
    if os.path.exists(failed):
        os.remove(failed)
    cmd = ["ctest", "--test-dir", build, *DEFAULT_LABELS, *select, "--stop-on-failure", "-j1",
           "--output-on-failure", "--no-tests=ignore"]
    status = run(cmd, log)
    names = failedTests(build)
    if status != 0 and not names:
        return "ctest itself (exit %d)" % status
    return names[0] if names else None


@contextlib.contextmanager
def planted(m, src):
    """The mutation applied to the scratch copy for the duration of the block, then reverted."""
    path = os.path.join(src, m.file)
    with open(path) as f:
        original = f.read()
    try:
        with open(path, "w") as f:
            f.write(original.replace(m.old, m.new, 1))
        yield
    finally:
        with open(path, "w") as f:
            f.write(original)


def testOne(m, src, build, log, jobs):
    with planted(m, src):
        if run(["cmake", "--build", build, "-j", str(jobs)], log) != 0:
            return "BUILD FAILED", None
        catchers = "|".join(f"({c})" for c in m.catchers)
        first = ctest(build, log, ["-R", catchers]) if catchers else None
        if first:
            return "caught", first
        rest = ctest(build, log, ["-E", catchers] if catchers else [])
        return ("caught", rest) if rest else ("SURVIVED", None)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("source")
    ap.add_argument("work")
    ap.add_argument("--only", nargs="+", default=None, help="mutation names to run (default: all)")
    ap.add_argument("--list", action="store_true", help="check and list the mutations, run nothing")
    ap.add_argument("--jobs", type=int, default=2, help="build jobs (tests always run one at a time)")
    ap.add_argument("--binaries", action="store_true",
                    help="run no test: build each mutant and keep its solver as WORK/bin/shizuku.NAME (for studies)")
    a = ap.parse_args()
    source = os.path.abspath(a.source)
    mutations = MUTATIONS
    if a.only:
        unknown = set(a.only) - {m.name for m in MUTATIONS}
        if unknown:
            print("unknown mutation(s): " + ", ".join(sorted(unknown)))
            return 2
        mutations = [m for m in MUTATIONS if m.name in a.only]
    problems = checkList(source, MUTATIONS)
    if problems:
        print("mutation list broken (tests/mutation/mutations.py):\n  " + "\n  ".join(problems))
        return 2
    if a.list:
        for m in mutations:
            print(f"{m.name:26s} {m.file}: {m.why}")
        return 0

    work = os.path.abspath(a.work)
    # The build tree sits at src/build, as build/ does in a work tree: the compiler then sees
    # the same relative paths and ccache (base_dir above both) serves the unchanged objects.
    src = os.path.join(work, "src")
    build = os.path.join(src, "build")
    os.makedirs(src, exist_ok=True)
    log = os.path.join(work, "mutation.log")
    open(log, "w").close()
    t0 = time.time()
    print(f"copying {source} to {src}: {syncTree(source, src)} files changed", flush=True)
    if not os.path.exists(os.path.join(build, "CMakeCache.txt")):
        launcher = ["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache", "-DCMAKE_C_COMPILER_LAUNCHER=ccache"] \
            if shutil.which("ccache") else []
        if run(["cmake", "-S", src, "-B", build, "-G", "Ninja", "-DCMAKE_BUILD_TYPE=Release", *launcher], log):
            print(f"configure failed (log {log})")
            return 2
    if run(["cmake", "--build", build, "-j", str(a.jobs)], log) != 0:
        print(f"the unmutated copy does not build (log {log})")
        return 2
    print(f"unmutated copy built after {time.time() - t0:.0f} s; log {log}", flush=True)

    if a.binaries:
        os.makedirs(os.path.join(work, "bin"), exist_ok=True)
        for m in mutations:
            with planted(m, src):
                ok = run(["cmake", "--build", build, "-j", str(a.jobs), "--target", "shizuku"], log) == 0
                if ok:
                    shutil.copy2(os.path.join(build, "solver", "shizuku"), os.path.join(work, "bin", "shizuku." + m.name))
            print(f"{m.name:26s} " + ("built" if ok else "BUILD FAILED"), flush=True)
        run(["cmake", "--build", build, "-j", str(a.jobs)], log)
        return 0

    results = []
    for m in mutations:
        t = time.time()
        with open(log, "a") as f:
            f.write(f"\n===== {m.name}: {m.file}\n")
        verdict, test = testOne(m, src, build, log, a.jobs)
        dt = time.time() - t
        results.append((m, verdict, test, dt))
        line = f"{m.name:26s} " + (f"caught by {test}" if verdict == "caught" else verdict)
        print(f"{line:80s} {dt:6.0f} s", flush=True)
    # Rebuild the unmutated copy so the scratch build never holds a mutant.
    run(["cmake", "--build", build, "-j", str(a.jobs)], log)

    survived = [m.name for m, v, _, _ in results if v == "SURVIVED"]
    broken = [m.name for m, v, _, _ in results if v == "BUILD FAILED"]
    caught = len(results) - len(survived) - len(broken)
    print(f"\n{caught} of {len(results)} mutations caught, {len(survived)} survived"
          + (": " + ", ".join(survived) if survived else "")
          + (f"; {len(broken)} did not build: " + ", ".join(broken) if broken else "")
          + f"; {time.time() - t0:.0f} s")
    return 2 if broken else 1 if survived else 0


if __name__ == "__main__":
    sys.exit(main())
