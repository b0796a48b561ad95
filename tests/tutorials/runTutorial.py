#!/usr/bin/python3
"""Tutorial smoke test (ctest label `tutorial`, docs/testing.md).

usage: runTutorial.py TUTORIAL_DIR WORK_DIR --repo REPO --build BUILD [--steps N] [--threads N]

1. Copies the tutorial to WORK_DIR/run/<name> (emptied first). The tutorial itself is never
   edited: the copy is shortened here, in its system/controlDict, to N steps of its own
   deltaT (endTime = startTime + N deltaT, adjustTimeStep no) with a time directory after
   every step (writeControl timeStep; writeInterval 1), and every function object samples
   at every step too.
2. Runs the copy's own Allrun (which runs shizuku and shizukuPlot) with SHIZUKU_DIR=REPO
   and SHIZUKU_BUILD=BUILD; the number of threads is set by OMP_NUM_THREADS.
3. Checks the outputs are there and finite:
   - exit status 0, the solver log with no numerical failure;
   - a time directory for every step, each with a particles.vtp that VTK reads, with
     finite positions, U, p and rhoN, and the same particles in every one (with inlets or
     outlets, which add and remove particles: unique ids in every one); particles.pvd
     listing every time;
   - every postProcessing file parses, has rows and no nan or inf, except a probe value,
     which may be nan only where the point is outside the fluid: the kernel sum
     S = sum_j V W(|x - x_j|) over the fluid particles of the time directory of that
     sample is below the probe's minKernelSum (0.5), recomputed here independently;
   - shizukuPlot wrote non-empty PNG files.
The last line is `N passed, M failed`; exit status 0 when every check passes.
"""
import argparse
import math
import os
import re
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402


def strip_comments(text):
    return re.sub(r"//[^\n]*|/\*.*?\*/", " ", text, flags=re.S)


SECONDS = {"s": 1.0, "ms": 1e-3}


def seconds(value):
    m = re.fullmatch(r"([-+0-9.eE]+)\s*(?:\[\s*(\w+)\s*\])?", value)
    if not m or (m.group(2) and m.group(2) not in SECONDS):
        raise SystemExit(f"runTutorial: cannot read the time '{value}'")
    return float(m.group(1)) * SECONDS[m.group(2) or "s"]


def shorten(control, steps):
    """Rewrite the copied controlDict: `steps` steps of deltaT, a time directory each step."""
    with open(control) as f:
        raw = f.read()
    dt = seconds(st.find_key(raw, "deltaT").group(1).strip())
    start = st.find_key(raw, "startTime")
    t0 = seconds(start.group(1).strip()) if start else 0.0
    end = t0 + steps * dt
    new = {"endTime": f"{end!r}", "writeControl": "timeStep", "writeInterval": "1", "adjustTimeStep": "no",
           "startFrom": "startTime", "progressInterval": "1"}
    for key, value in new.items():
        raw = st.with_key(raw, key, value, append=True)
    raw = sample_every_step(raw)
    with open(control, "w") as f:
        f.write(raw)
    return dt, end


def sample_every_step(raw):
    """Make every function object of the top-level `functions` dictionary sample at every
    step (writeControl timeStep; writeInterval 1), so each file gets a row per step."""
    text = re.sub(r"//[^\n]*|/\*.*?\*/", lambda m: " " * len(m.group(0)), raw, flags=re.S)  # same offsets
    m = re.search(r"(?m)^[ \t]*functions\s*\{", text)
    if not m:
        return raw
    depth, pos, entries = 1, m.end(), []
    while depth and pos < len(text):
        c = text[pos]
        if c == "{":
            depth += 1
            if depth == 2:
                start = pos
        elif c == "}":
            if depth == 2:
                entries.append((start, pos))
            depth -= 1
        pos += 1
    for start, stop in reversed(entries):
        body = raw[start + 1:stop]
        body = re.sub(r"\b(writeControl|writeInterval)\s+[^;]*;", "", body)
        raw = raw[:start + 1] + body.rstrip() + " writeControl timeStep; writeInterval 1; " + raw[stop:]
    return raw


def kernel_sum(points, fluid_xy, V, h, kernel, dim):
    """S(x) = sum_j V W(|x - x_j|, h) at each point (cubic spline or Wendland C2, support 2h)."""
    r = np.sqrt(((fluid_xy[None, :, :] - points[:, None, :]) ** 2).sum(axis=2))
    q = r / h
    if kernel == "cubicSpline":
        sigma = (10 / (7 * math.pi) if dim == 2 else 1 / math.pi) / h ** dim
        w = np.where(q < 1, 1 - 1.5 * q ** 2 + 0.75 * q ** 3, np.where(q < 2, 0.25 * (2 - q) ** 3, 0.0))
    else:
        sigma = (7 / (4 * math.pi) if dim == 2 else 21 / (16 * math.pi)) / h ** dim
        t = np.clip(1 - 0.5 * q, 0, None)
        w = t ** 4 * (2 * q + 1)
    return V * sigma * w.sum(axis=1)


def probe_points(file_path):
    pts = []
    with open(file_path) as f:
        for line in f:
            m = re.match(r"#\s*point\d+\s+\(([^)]*)\)", line)
            if m:
                pts.append([float(x) for x in m.group(1).split()])
    return np.array(pts)


def scheme_kernel(case):
    with open(os.path.join(case, "system/sphSchemes")) as f:
        text = strip_comments(f.read())
    m = re.search(r"kernel\s*\{([^}]*)\}", text)
    kernel, ratio = "cubicSpline", 1.2
    if m:
        t = re.search(r"type\s+(\w+)", m.group(1))
        r = re.search(r"smoothingLengthRatio\s+([-+0-9.eE]+)", m.group(1))
        kernel = t.group(1) if t else kernel
        ratio = float(r.group(1)) if r else ratio
    return kernel, ratio


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tutorial")
    ap.add_argument("work")
    ap.add_argument("--repo", required=True)
    ap.add_argument("--build", required=True)
    ap.add_argument("--steps", type=int, default=4)
    ap.add_argument("--threads", type=int, default=2)
    a = ap.parse_args()
    cmpmod = st.load_compare(os.path.join(a.build, "utilities", "shizukuCompare"))

    src = os.path.abspath(a.tutorial)
    name = os.path.basename(src.rstrip("/"))
    # Allrun sources $SHIZUKU_DIR/etc/tutorialFunctions (SHIZUKU_DIR=REPO below), as a
    # user's copy with etc/bashrc sourced does.
    case = os.path.abspath(os.path.join(a.work, "run", name))
    shutil.rmtree(case, ignore_errors=True)
    shutil.copytree(src, case, ignore=shutil.ignore_patterns("[0-9]*", "postProcessing", "plots", "log.*",
                                                              "particles.pvd"))
    dt, end = shorten(os.path.join(case, "system/controlDict"), a.steps)
    print(f"{name}: shortened to {a.steps} steps of {dt:g} s (endTime {end:g})")
    # Sub-cases a tutorial's Allrun also runs (tutorials/slosh): shortened the same way.
    for sub in sorted(os.listdir(case)):
        control = os.path.join(case, sub, "system", "controlDict")
        if os.path.isfile(control):
            shorten(control, a.steps)
            print(f"{name}/{sub}: shortened to {a.steps} steps")

    env = dict(os.environ, SHIZUKU_DIR=os.path.abspath(a.repo), SHIZUKU_BUILD=os.path.abspath(a.build),
               OMP_NUM_THREADS=str(a.threads))
    rc = subprocess.call(["sh", os.path.join(case, "Allrun")], env=env, cwd=case)
    st.check(rc == 0, f"{name}: Allrun exit status {rc}")
    log = os.path.join(case, "log.shizuku")
    if st.check(os.path.isfile(log), f"{name}: log.shizuku written"):
        with open(log) as f:
            text = f.read()
        st.check("numerical failure" not in text, f"{name}: no numerical failure in the log")
        if rc != 0:
            print(text[-3000:])

    # time directories and particles
    times = st.time_dirs(case)
    st.check(len(times) == a.steps + 1, f"{name}: {len(times)} time directories (expected {a.steps + 1})")
    st.check(abs(times[-1][0] - end) <= 1e-9 * max(1, end) if times else False, f"{name}: the last time is endTime")
    first = None
    with open(os.path.join(case, "system", "particlesDict")) as f:
        open_ends = re.search(r"\btype\s+(inlet|outlet)\s*;", strip_comments(f.read())) is not None
    states = {}
    for t, tname in times:
        p = st.read_vtp(os.path.join(case, tname, "particles.vtp"))
        if not st.check(p is not None, f"{name}: {tname}/particles.vtp read by VTK"):
            continue
        finite = all(np.all(np.isfinite(p[k])) for k in ("position", "U", "p", "rhoN") if k in p)
        st.check(finite and all(k in p for k in ("U", "p", "rhoN", "type", "id")),
                 f"{name}: {tname}: U, p, rhoN present and finite for {len(p['position'])} particles")
        ids = np.sort(p["id"])
        if open_ends:
            st.check(len(np.unique(ids)) == len(ids), f"{name}: {tname}: {len(ids)} unique ids")
        elif first is None:
            first = ids
        else:
            st.check(np.array_equal(ids, first), f"{name}: {tname}: the same particles as at the start")
        states[t] = p
    pvd = os.path.join(case, "particles.pvd")
    if st.check(os.path.isfile(pvd), f"{name}: particles.pvd written"):
        with open(pvd) as f:
            listed = re.findall(r'file="([^"]+)"', f.read())
        st.check(len(listed) == len(times), f"{name}: particles.pvd lists {len(listed)} of {len(times)} times")

    # postProcessing
    kernel, ratio = scheme_kernel(case)
    pp = os.path.join(case, "postProcessing")
    files = []
    for root, _, fnames in os.walk(pp):
        files += [os.path.join(root, f) for f in fnames if not f.endswith(".vtp")]  # particle files, not series
    st.check(len(files) > 0, f"{name}: postProcessing has {len(files)} files")
    for path in sorted(files):
        rel = os.path.relpath(path, case)
        try:
            cols, arr = cmpmod.read_series_file(path)
        except Exception as e:  # noqa: BLE001 - any parse problem is the failure reported
            st.check(False, f"{rel}: parses ({e})")
            continue
        if not st.check(arr.shape[0] > 0, f"{rel}: {arr.shape[0]} rows, columns {' '.join(cols)}"):
            continue
        bad = ~np.isfinite(arr)
        if "histogram.dat" in rel:
            st.check(not bad.any(), f"{rel}: finite")
            continue
        is_probe = bool(re.search(r"#\s*probes of", open(path).read(300)))
        if not is_probe:
            st.check(not bad.any(), f"{rel}: no nan or inf")
            continue
        st.check(not np.isinf(arr).any() and np.all(np.isfinite(arr[:, 0])), f"{rel}: no inf")
        pts = probe_points(path)
        ncomp = (len(cols) - 1) // max(len(pts), 1)
        wrong = []
        checked = 0
        for row in arr:
            t = row[0]
            match = [s for s in states if abs(s - t) <= 1e-9 * max(1, abs(t))]
            if not match:
                if np.isnan(row[1:]).any():
                    wrong.append(f"t = {t:g}: nan at a time with no time directory")
                continue
            state = states[match[0]]
            fluid = state["type"] == 0
            dim = int(state.get("field:dimension", [2])[0])
            xy = state["position"][fluid][:, :dim]
            d0 = float(state["field:spacing"][0])
            V = float(state["field:volume"][0])
            S = kernel_sum(pts[:, :dim], xy, V, ratio * d0, kernel, dim)
            for k in range(len(pts)):
                vals = row[1 + k * ncomp: 1 + (k + 1) * ncomp]
                checked += 1
                if np.isnan(vals).any() and S[k] >= 0.5 + 1e-6:
                    wrong.append(f"t = {t:g}: point{k} is nan but its kernel sum is {S[k]:.3f} >= 0.5")
                if not np.isnan(vals).any() and S[k] < 0.5 - 1e-6:
                    wrong.append(f"t = {t:g}: point{k} has a value but its kernel sum is {S[k]:.3f} < 0.5")
        st.check(not wrong, f"{rel}: nan exactly where the point is outside the fluid "
                            f"({checked} point samples at write times)" + ("; " + "; ".join(wrong[:5]) if wrong else ""))

    # pictures
    plots = os.path.join(case, "plots")
    pngs = [f for f in os.listdir(plots) if f.endswith(".png")] if os.path.isdir(plots) else []
    good = [f for f in pngs if open(os.path.join(plots, f), "rb").read(8) == b"\x89PNG\r\n\x1a\n"]
    st.check(len(pngs) > 0 and len(good) == len(pngs), f"{name}: shizukuPlot wrote {len(good)} PNG files")

    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
