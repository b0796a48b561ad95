#!/usr/bin/python3
"""shizukuPostProcess equals the live run (docs/design.md 1.1, 1.3).

A small dam break (fluid column in a walled tank: walls, free surface,
splash, shifting, ADS, XSPH, particle reordering every 20 steps) runs with
every function object sampling every step, on 2 threads. Then
shizukuPostProcess rebuilds the state of each saved time (on 1 thread) and
runs each function object again: every row it writes must be character for
character the row the live run wrote at that time, and every histogram file
identical. A restart then writes under its own start time without touching
the first run's files, and post-processing the restarted times equals it too.
Also: an existing output folder is refused without -overwrite, timing does
nothing in post-processing, an unknown -func is an error (exit 1).

usage: postEqualsLive.py SHIZUKU SHIZUKUPOSTPROCESS WORKDIR
"""
import filecmp
import os
import shutil
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

SHIZUKU, POST, WORK = sys.argv[1:4]
CASE = os.path.join(WORK, "damBreakMini")


def control(end_time):
    return f"""startFrom latestTime; startTime 0; stopAt endTime; endTime {end_time}; deltaT 1e-3;
adjustTimeStep no; writeControl timeStep; writeInterval 7; progressInterval 10;
functions
{{
    probe {{ type probes; fields (p U rhoN); points ((5 3) (10 6) (19.5 1) (30 25)) [cm]; }}
    dErr  {{ type densityError; histogram {{ min -20; max 20; bins 40; }} }}
    cons  {{ type conservation; }}
    box   {{ type fluidExtent; }}
    cpu   {{ type timing; writeControl timeStep; writeInterval 5; }}
}}
"""


def make_case():
    shutil.rmtree(CASE, ignore_errors=True)
    st.write(f"{CASE}/system/controlDict", control(0.03))
    st.write(f"{CASE}/system/particlesDict", """spacing 1 [cm];
regions
{
    column { type fluid; shape box; min (0 0) [cm]; max (20 12) [cm]; }
    tank   { type wall; shape box; min (0 0) [cm]; max (40 30) [cm]; layers 3; open (top); }
}
""")
    st.write(f"{CASE}/system/sphSchemes", """kernel { type cubicSpline; smoothingLengthRatio 1.2; }
derivatives SPH2;
shifting
{
    distribution { type OPS; C 0.2; Rp 0.2; np 4; }
    volumeCorrection { C 0.1; }
    surfaceFitting { C 1e-4; maxCurvature 0.2; minDistance 0.15; maxDistance 0.6; }
    maxShift 0.1;
}
ads { }
xsph { epsilon 0.5; }
""")
    st.write(f"{CASE}/system/sphSolution", "pressure { solver BiCGSTAB; tolerance 1e-10; }\n")
    st.write(f"{CASE}/constant/physicalProperties", "rho 1 [g/cm^3];\nnu 9.8e-3 [cm^2/s];\n")
    st.write(f"{CASE}/constant/g", "value (0 -980) [cm/s^2];\n")


def run(args, threads, log):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads))
    with open(os.path.join(CASE, log), "w") as f:
        return subprocess.run(args, stdout=f, stderr=subprocess.STDOUT, env=env).returncode


def rows(path):
    with open(path) as f:
        return [ln.rstrip("\n") for ln in f if ln.strip() and not ln.startswith("#")]


def snapshot(folder):
    """{relative path: content} of every file below folder."""
    out = {}
    for root, _, files in os.walk(folder):
        for name in files:
            p = os.path.join(root, name)
            with open(p) as f:
                out[os.path.relpath(p, folder)] = f.read()
    return out


def compare(live_root, post_root, start, names, times):
    """Every post-processed row equals the live row of the same time."""
    for name in names:
        post_dir = os.path.join(post_root, name, start)
        live_dir = os.path.join(live_root, name, start)
        for rel in sorted(snapshot(post_dir)):
            post_file, live_file = os.path.join(post_dir, rel), os.path.join(live_dir, rel)
            if rel.endswith("histogram.dat"):
                # a restarted run does not repeat the histogram of its start time: the
                # earlier run wrote it under its own start time
                if not os.path.exists(live_file):
                    others = [os.path.join(live_root, name, s, rel) for s in os.listdir(os.path.join(live_root, name))]
                    live_file = next((f for f in others if os.path.exists(f)), live_file)
                st.check(os.path.exists(live_file) and filecmp.cmp(post_file, live_file, shallow=False),
                         f"{name}/{start}/{rel}: histogram identical to the live one "
                         f"({os.path.relpath(live_file, live_root)})")
                continue
            live = {r.split()[0]: r for r in rows(live_file)}
            post = rows(post_file)
            st.check([r.split()[0] for r in post] == times,
                     f"{name}/{start}/{rel}: post-processed at the saved times {times}")
            bad = [r for r in post if live.get(r.split()[0]) != r]
            for r in bad[:3]:
                print(f"     post: {r}\n     live: {live.get(r.split()[0])}")
            st.check(not bad, f"{name}/{start}/{rel}: {len(post)} rows equal the live rows")


def main():
    make_case()
    st.check(run([SHIZUKU, "-case", CASE], 2, "log.shizuku") == 0, "live run (2 threads) exits 0")
    pp = os.path.join(CASE, "postProcessing")
    times = sorted((d for d in os.listdir(CASE) if os.path.isfile(os.path.join(CASE, d, "particles.vtp"))),
                   key=float)
    st.check(times == ["0", "0.007", "0.014", "0.021", "0.028", "0.03"], f"saved times {times}")
    live = os.path.join(WORK, "live1")
    shutil.rmtree(live, ignore_errors=True)
    shutil.copytree(pp, live)
    names = ["probe", "dErr", "cons", "box"]

    # refusals and no-ops, before anything is overwritten
    before = snapshot(pp)
    st.check(run([POST, "-case", CASE, "-func", "cons"], 1, "log.refuse") == 1, "existing output refused (exit 1)")
    st.check(run([POST, "-case", CASE, "-func", "nothing"], 1, "log.unknown") == 1, "unknown -func: exit 1")
    st.check(run([POST, "-case", CASE, "-func", "cons", "-time", "0.5"], 1, "log.badtime") == 1,
             "unknown -time: exit 1")
    st.check(run([POST, "-case", CASE, "-func", "cpu", "-overwrite"], 1, "log.cpu") == 0, "timing: exit 0")
    st.check(snapshot(pp) == before, "refused, failed and timing post-processing left postProcessing untouched")

    for name in names:
        st.check(run([POST, "-case", CASE, "-func", name, "-overwrite"], 1, f"log.post.{name}") == 0,
                 f"shizukuPostProcess -func {name} (1 thread) exits 0")
    compare(live, pp, "0", names, times)
    st.check(os.path.isfile(os.path.join(pp, "cpu", "0", "timing.dat")), "live timing.dat kept")

    # a type name with default settings
    st.check(run([POST, "-case", CASE, "-func", "conservation", "-time", "0.014,0.028"], 1, "log.type") == 0,
             "-func conservation (a type) exits 0")
    st.check([r.split()[0] for r in rows(os.path.join(pp, "conservation", "0.014", "conservation.dat"))]
             == ["0.014", "0.028"], "type with default settings: rows at the selected times")

    # restart: endTime 0.04 from latestTime 0.03 -> postProcessing/<name>/0.03/, old files untouched
    first = snapshot(pp)
    st.write(f"{CASE}/system/controlDict", control(0.04))
    st.check(run([SHIZUKU, "-case", CASE], 2, "log.shizuku.restart") == 0, "restarted run exits 0")
    after = snapshot(pp)
    st.check(all(after.get(k) == v for k, v in first.items()), "restart left every earlier file unchanged")
    for name in names + ["cpu"]:
        st.check(os.path.isdir(os.path.join(pp, name, "0.03")), f"restart writes {name}/0.03/")
    live2 = os.path.join(WORK, "live2")
    shutil.rmtree(live2, ignore_errors=True)
    shutil.copytree(pp, live2)
    for name in names:
        st.check(run([POST, "-case", CASE, "-func", name, "-time", "0.03:", "-overwrite"], 1,
                     f"log.post2.{name}") == 0, f"post-processing the restart, -func {name}")
    compare(live2, pp, "0.03", names, ["0.03", "0.035", "0.04"])

    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
