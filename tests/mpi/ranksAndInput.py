#!/usr/bin/python3
"""How a distributed run starts, stops and reports (docs/parallel.md 2, 8, 9), on copies of
the dam-break tutorial run without function objects:
  - several ranks started without -parallel: exit 1, one error message (not one per rank)
    naming -parallel, nothing written;
  - a misspelt keyword (controlDict `endTme`) on two ranks: exit 1, one error naming the
    file, the line and the keyword it misspells, nothing written;
  - SIGTERM sent to every rank (what a batch system's cancel does) in the middle of a run:
    exit 0, one time directory written at the step all ranks stopped at, holding every
    particle exactly once: particles.pvtp naming particles_0.vtp and particles_1.vtp, one
    non-empty piece per rank, listed in particles.pvd;
  - `stopAt writeNow` written into system/controlDict while two ranks run: the same;
  - a folder of the user's (holding notes.txt) where a time is due, two ranks: exit 1, one
    error naming it, the folder as it was, no temporary folder left;
  - the channel tutorial with an inlet velocity that stops being finite at t = 0.05 s, on two
    ranks of which one holds the inlet: both stop together (no abort), exit 2, the failure
    reported once, the last good state (t = 0.04 s) written;
  - a restart on the same rank count (2 and 3): 40 steps writing at step 20, and the same
    case restarted from its step-20 time, equal at step 40 bit for bit (the uninterrupted
    run rebuilds its partition from scratch after each scheduled write, as a restart does);
  - a restart across rank counts: 20 steps on 2 ranks (their time written in two pieces),
    20 more on 3 from the time written (three ranks reading two pieces), 20 more on 1
    (serial, reading three): equal to one serial run of 60 steps within
    compareWithSerial.py's bounds (pressure solved to 1e-11, as there);
  - five ranks, one of which holds no fluid at all (the tank's upper walls): 20 steps equal
    to the serial run within the same bounds.

usage: ranksAndInput.py SOURCE WORK --shizuku BIN --mpirun "mpirun --allow-run-as-root --oversubscribe"
"""
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import time

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "support"))
import shizukutest as st  # noqa: E402

compare = st.load_module(os.path.join(HERE, "compareWithSerial.py"), "compareWithSerial")


def fresh(a, name, end=0.002, write=0.002):
    case = os.path.join(a.work, name)
    st.copy_case(os.path.join(a.source, "tutorials", "damBreak"), case)
    compare.set_control(case, end, write)
    st.set_key(os.path.join(case, "system", "controlDict"), "progressInterval", 10)
    return case


def launch(a, case, ranks, parallel=True):
    cmd = shlex.split(a.mpirun) + ["-np", str(ranks), a.shizuku, "-case", case, "-threads", "1", "-noFunctionObjects"]
    return cmd + (["-parallel"] if parallel else [])


def errors(text):
    return [line for line in text.splitlines() if line.startswith("Error:")]


def written(case):
    return [name for _, name in st.time_dirs(case)]


def stopped_run(a, name, stop):
    """Start two ranks on a long run, stop them with `stop(case, process)` once step 20 is
    logged; returns (case, exit status, log text)."""
    case = fresh(a, name, end=1, write=0.5)
    log = open(os.path.join(case, "log.parallel"), "w")
    p = subprocess.Popen(launch(a, case, 2), stdout=log, stderr=subprocess.STDOUT)
    deadline = time.time() + 120
    while time.time() < deadline and p.poll() is None:
        with open(os.path.join(case, "log.parallel")) as f:
            if re.search(r"^step 20 ", f.read(), re.M):
                break
        time.sleep(0.2)
    stop(case, p)
    try:
        rc = p.wait(timeout=120)
    except subprocess.TimeoutExpired:
        p.kill()
        rc = "hung"
    log.close()
    with open(os.path.join(case, "log.parallel")) as f:
        return case, rc, f.read()


def check_stop(name, case, rc, text, ranks_total):
    times = written(case)
    st.check(rc == 0, f"{name}: exit status {rc} (0 expected)")
    new = [t for t in times if t != "0"]
    if st.check(len(new) == 1, f"{name}: one time directory written after the start ({new})"):
        data = st.read_vtp(os.path.join(case, new[0]))
        ids = data["id"] if data is not None else np.array([])
        st.check(len(ids) == ranks_total and len(np.unique(ids)) == ranks_total,
                 f"{name}: time {new[0]} holds every particle once ({len(ids)} of {ranks_total})")
        check_pieces(name, case, new[0], 2)


def check_pieces(name, case, time_name, ranks):
    """The time directory holds particles.pvtp naming one non-empty piece per rank, and the
    series lists the pvtp (docs/parallel.md 7)."""
    folder = os.path.join(case, time_name)
    pieces = sorted(n for n in os.listdir(folder) if n.startswith("particles_"))
    sizes = [len(st.read_vtp(os.path.join(folder, n))["id"]) for n in pieces]
    with open(os.path.join(folder, "particles.pvtp")) as f:
        sources = re.findall(r'Source="([^"]*)"', f.read())
    with open(os.path.join(case, "particles.pvd")) as f:
        listed = f'file="{time_name}/particles.pvtp"' in f.read()
    st.check(sources == [f"particles_{k}.vtp" for k in range(ranks)] and sorted(sources) == pieces and
             all(n > 0 for n in sizes) and listed and not os.path.exists(os.path.join(folder, "particles.vtp")),
             f"{name}: {time_name}/particles.pvtp names one piece per rank ({sources}; particles {sizes}), "
             f"listed in particles.pvd")


def main():
    a = compare.arguments().parse_args()
    a.work = os.path.abspath(a.work)
    os.makedirs(a.work, exist_ok=True)

    case = fresh(a, "withoutParallel")
    r = subprocess.run(launch(a, case, 2, parallel=False), capture_output=True, text=True)
    out = r.stdout + r.stderr
    st.check(r.returncode != 0, f"two ranks without -parallel: exit status {r.returncode}")
    errs = errors(out)
    st.check(len(errs) == 1 and "-parallel" in errs[0], f"two ranks without -parallel: one error naming -parallel {errs}")
    st.check(written(case) == [], "two ranks without -parallel: nothing written")

    case = fresh(a, "misspelt")
    path = os.path.join(case, "system", "controlDict")
    with open(path) as f:
        text = f.read()
    with open(path, "w") as f:
        f.write(text.replace("\nendTime ", "\nendTme ", 1))
    r = subprocess.run(launch(a, case, 2), capture_output=True, text=True)
    errs = errors(r.stdout + r.stderr)
    st.check(r.returncode == 1, f"a misspelt keyword on two ranks: exit status {r.returncode} (1 expected)")
    st.check(len(errs) == 1 and "endTme" in errs[0] and "misspelling" in errs[0] and "controlDict" in errs[0],
             f"a misspelt keyword on two ranks: one error naming the file, keyword and its correction {errs}")
    st.check(written(case) == [], "a misspelt keyword on two ranks: nothing written")

    whole = 6418  # the dam-break tutorial's fluid and wall particles

    def terminate(case, p):
        pids = subprocess.run(["pgrep", "-f", f"^{a.shizuku} -case {case} "], capture_output=True, text=True).stdout.split()
        for pid in pids:
            os.kill(int(pid), signal.SIGTERM)
    case, rc, text = stopped_run(a, "sigterm", terminate)
    check_stop("SIGTERM to both ranks", case, rc, text, whole)

    def write_now(case, p):
        path = os.path.join(case, "system", "controlDict")
        st.set_key(path, "stopAt", "writeNow")
    case, rc, text = stopped_run(a, "writeNow", write_now)
    check_stop("stopAt writeNow on two ranks", case, rc, text, whole)

    # A folder of the user's where a time is due: every rank stops, one error, the folder kept.
    case = fresh(a, "inTheWay", end=0.004, write=0.002)
    os.makedirs(os.path.join(case, "0.002"))
    with open(os.path.join(case, "0.002", "notes.txt"), "w") as f:
        f.write("mine")
    r = subprocess.run(launch(a, case, 2), capture_output=True, text=True)
    errs = errors(r.stdout + r.stderr)
    st.check(r.returncode == 1 and len(errs) == 1 and "0.002" in errs[0] and "move it away" in errs[0],
             f"a user's folder where a time is due, two ranks: exit {r.returncode} (1 expected), one error {errs}")
    st.check(os.listdir(os.path.join(case, "0.002")) == ["notes.txt"] and written(case) == ["0"] and
             not any(".tmp-" in n for n in os.listdir(case)),
             f"a user's folder where a time is due: kept as it was, time 0 complete, no temporary left "
             f"({sorted(os.listdir(case))})")

    # A numerical failure one rank meets alone: the channel's inlet lies on one rank only
    # (the cut runs across the channel), and its velocity stops being finite at t = 0.05 s.
    case = os.path.join(a.work, "inletFailure")
    st.copy_case(os.path.join(a.source, "tutorials", "channelPoiseuille"), case)
    path = os.path.join(case, "system", "particlesDict")
    with open(path) as f:
        text = f.read()
    st.write(path, text.replace("velocity { type uniform; value (0.01 0); }",
                                'velocity { type expression; value ("t < 0.05 ? 0.01 : sqrt(-1)" "0"); }'))
    st.set_key(os.path.join(case, "system", "controlDict"), "endTime", 0.2)
    r = subprocess.run(launch(a, case, 2), capture_output=True, text=True, timeout=120)
    out = r.stdout + r.stderr
    st.check(r.returncode == 2 and out.count("the velocity expressions give") == 1 and "MPI_ABORT" not in out,
             f"a non-finite inlet velocity on one of two ranks: every rank stops together, exit {r.returncode} "
             f"(2 expected), the failure reported once")
    st.check(written(case)[-1:] == ["0.04"], f"a non-finite inlet velocity: the last good state written ({written(case)})")

    # A restart on the same rank count continues bit for bit: 40 steps on N ranks writing
    # at step 20, against the same run restarted from its step-20 time.
    for ranks in (2, 3):
        whole = fresh(a, f"sameRanks{ranks}", end=0.004, write=0.002)
        rw = compare.parallel(a, whole, ranks)
        again = os.path.join(a.work, f"sameRanksRestart{ranks}")
        st.copy_case(whole, again)
        shutil.copytree(os.path.join(whole, "0.002"), os.path.join(again, "0.002"))
        rr = compare.parallel(a, again, ranks)
        x, y = st.read_vtp(os.path.join(whole, "0.004")), st.read_vtp(os.path.join(again, "0.004"))
        same = rw == 0 and rr == 0 and x is not None and y is not None and all(
            np.array_equal(x[k][np.argsort(x["id"])], y[k][np.argsort(y["id"])]) for k in ("position", "U", "p", "rhoN"))
        st.check(same, f"restart on {ranks} ranks from the time written at step 20: step 40 equal to the "
                       f"uninterrupted run's bit for bit (exits {rw}, {rr})")

    # Restart 2 -> 3 -> 1 ranks: each leg starts from the time the last one wrote.
    ref = fresh(a, "restartSerial", end=0.006, write=0.002)
    compare.tighten(ref)
    got = fresh(a, "restart", end=0.002, write=0.002)
    compare.tighten(got)
    legs = []
    for ranks, end in ((2, 0.002), (3, 0.004), (1, 0.006)):
        compare.set_control(got, end, 0.002)
        legs.append(compare.parallel(a, got, ranks) if ranks > 1 else compare.serial(a, got))
        with open(os.path.join(got, "log.parallel" if ranks > 1 else "log.serial")) as f:
            legs[-1] = (legs[-1], re.search(r"^Starting at time (\S+)", f.read(), re.M))
        if ranks == 2:
            check_pieces("restart, 2 ranks", got, "0.002", 2)
    starts = [m.group(1) if m else None for _, m in legs]
    rs = compare.serial(a, ref)
    if st.check(rs == 0 and all(rc == 0 for rc, _ in legs) and starts == ["0", "0.002", "0.004"],
                f"restart 2 -> 3 -> 1 ranks: each leg ran from the last one's time (starts {starts})"):
        compare.compare("restart 2 -> 3 -> 1 ranks, against serial", os.path.join(ref, "0.006"),
                        os.path.join(got, "0.006"), 3, 0.01)

    ref = fresh(a, "fiveSerial")
    got = fresh(a, "fiveRanks")
    compare.tighten(ref)
    compare.tighten(got)
    rs = compare.serial(a, ref)
    rp = compare.parallel(a, got, 5)
    if st.check(rs == 0 and rp == 0, f"serial and five-rank runs (exit {rs}, {rp})"):
        with open(os.path.join(got, "log.parallel")) as f:
            line = next((x for x in f if x.startswith("Decomposition:")), "")
        st.check("(0 fluid" in line, f"five ranks: one rank holds no fluid ({line.strip()})")
        compare.compare("damBreak from the start", os.path.join(ref, "0.002"),
                        os.path.join(got, "0.002"), 5, 0.01)
    sys.exit(st.summary())


if __name__ == "__main__":
    main()
