#!/usr/bin/python3
"""Stability checker for a finished run of a hard case (label `stability`, docs/testing.md).

usage: checkStability.py CASE LIMITS --compare SHIZUKUCOMPARE

CASE is a run case folder (after tests/cases/runCase.py: it holds `exitCode` and
log.shizuku); LIMITS a dictionary in the case syntax:

    volume           { rel 0.05; }     // |V(t) - V(0)| <= rel V(0), V = sum m/<rho> (conservation.dat)
    energy           { rel 0.05; }     // total energy growth bound, below
    densityErrorMode { max 2; }        // |mode| of eq. 22 over interior particles, in %
    densityErrorRms  { max 5; }        // optional: interior rms, in %
    densityErrorMean { window (0 0.5); max 0.1; }  // optional: |time average of the interior
                                       // mean| over the window, in % (early, well-resolved flow)
    wallTolerance    0;                // how far (times d0) a fluid particle centre may lie
                                       // beyond a wall surface before it counts as inside
    knownFailures    (densityErrorMode);   // optional: strict expected failures, below
    variantKnownFailures { long (volume); }  // optional: the list for one size (--variant)

It asserts, each as its own line:
 1. the health guards did not fire: exit status 0, no 'numerical failure' in the log and
    no postProcessing/healthChecks folder (where a guard writes the offending particles);
 2. no NaN or Inf: every postProcessing file and every field of every time directory;
 3. no particle lost: every time directory holds the same fluid particle ids, except those
    the solver removed from the domain and logged in outflow/removed.dat (printed, not
    failed), the nominal fluid volume (N m/rho0) of conservation.dat changes only with
    those removals, and no fluid
    particle is out of the container: past the layers of a closed wall face, unless an
    earlier time directory saw it beyond an open face of that wall region (spray thrown
    over the top of a side wall and falling outside it has left an open container the
    way real water would; such particles are counted and printed, not failed);
 4. no particle inside a wall: in every time directory no fluid particle centre lies
    beyond a closed face of a wall region of system/particlesDict and within its layers,
    more than wallTolerance d0 (the face's slab: its layers across; along, the box plus
    the layers of closed neighbouring faces, so a particle resting on the top edge of a
    side wall under an open top is not inside it);
 5. the fluid volume stays within `volume/rel` of its initial value (every sample);
 6. the kinetic energy is bounded by what the physics allows. Nothing feeds energy in
    (fixed walls, constant gravity), so the total energy E = E_k + E_p, E_p = -sum m g.x,
    may only fall. At every time directory E(t) <= E(0) + rel B, where B = E(0) - E_p,floor
    is the energy available above the floor (E_p,floor: every fluid particle at the lowest
    height its centre can reach, the container floor + d0/2; without gravity B = E_k(0));
    and at every conservation.dat sample E_k(t) <= E_k(0) + (1 + rel) (E_p(0) - E_p,floor);
 7. the interior density-error mode (densityError.dat) stays within densityErrorMode/max
    (and the rms within densityErrorRms/max when given); with densityErrorMean, the time
    average of the interior mean over its window (which the run must reach) is within max
    (a drift of the shift terms shows here long before anything blows up).
An assertion whose id (healthGuards finite (time directories) finiteSeries
(postProcessing) lost walls volume energy kineticEnergy densityErrorMode densityErrorRms
densityErrorMean) is listed in knownFailures is a strict expected failure:
its failure is printed as XFAIL and not counted, and its passing is counted as a failure
(XPASS), so the list must be emptied as soon as the method is fixed. The case README
says why each listed id fails.
The last line is `N passed, M failed`; exit status 0 when all pass.
"""
import argparse
import math
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

KNOWN = set()  # ids listed in the limits' knownFailures


def check(cond, what, ident=None):
    """One assertion. An id listed in knownFailures is a strict expected failure: its
    failure is reported (XFAIL) but not counted; its passing fails (XPASS), so that the
    list is emptied as soon as the method is fixed."""
    if ident in KNOWN:
        return st.check(cond, what, xpass=f"listed in knownFailures but passes; remove '{ident}' from knownFailures",
                        xfail=f"known failure '{ident}', see the case README")
    return st.check(cond, what)


def vec(v):
    return np.array([float(x) for x in v])


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("case")
    ap.add_argument("limits")
    ap.add_argument("--compare", required=True)
    ap.add_argument("--variant", help="a size of the case (e.g. long): its own knownFailures, if the limits give them")
    a = ap.parse_args()
    cm = st.load_compare(a.compare)
    lim = cm.read_dictionary(a.limits)
    known = lim.get("knownFailures", [])
    # variantKnownFailures { long (volume); }: a size whose known failures differ
    byVariant = lim.get("variantKnownFailures", {})
    if a.variant and a.variant in byVariant:
        known = byVariant[a.variant]
    KNOWN.update(known if isinstance(known, list) else [known])
    ids = {"healthGuards", "finite", "finiteSeries", "lost", "walls", "volume", "energy", "kineticEnergy", "densityErrorMode",
           "densityErrorRms", "densityErrorMean"}
    if KNOWN - ids:
        raise SystemExit(f"checkStability: unknown ids in knownFailures: {' '.join(sorted(KNOWN - ids))} "
                         f"(known: {' '.join(sorted(ids))})")
    case = a.case
    name = os.path.basename(os.path.normpath(case))

    # 1. health guards
    rc = int(open(os.path.join(case, "exitCode")).read()) if os.path.isfile(os.path.join(case, "exitCode")) else -1
    log = open(os.path.join(case, "log.shizuku")).read() if os.path.isfile(os.path.join(case, "log.shizuku")) else ""
    fired = [ln for ln in log.splitlines() if "numerical failure" in ln]
    if os.path.isdir(os.path.join(case, "postProcessing", "healthChecks")):  # a guard's offending particles
        fired.append("postProcessing/healthChecks exists (a guard wrote its offending particles)")
    check(rc == 0 and not fired, f"{name}: health guards did not fire (exit status {rc}"
                                 f"{'; ' + fired[0].strip() if fired else ''})", "healthGuards")
    ends = re.findall(r"End: .*", log)
    if ends:
        print("     " + ends[-1])

    # 2. finite postProcessing
    pp = os.path.join(case, "postProcessing")
    series = cm.Series(case)
    bad = [k for k, (t, v) in series.columns.items() if not (np.all(np.isfinite(t)) and np.all(np.isfinite(v)))]
    check(len(series.columns) > 0 and not bad, f"{name}: no nan or inf in {len(series.columns)} postProcessing "
                                                f"columns{': ' + ' '.join(bad[:5]) if bad else ''}", "finiteSeries")

    # particlesDict walls and gravity
    pdict = cm.read_dictionary(os.path.join(case, "system/particlesDict"))
    d0 = float(pdict["spacing"])
    walls = []
    for rname, reg in pdict.get("regions", {}).items():
        if isinstance(reg, dict) and reg.get("type") == "wall":
            opened = reg.get("open", [])
            opened = opened if isinstance(opened, list) else [opened]
            walls.append((rname, vec(reg["min"]), vec(reg["max"]), set(opened), float(reg.get("layers", 3)) * d0))
    gfile = os.path.join(case, "constant/g")
    g = vec(cm.read_dictionary(gfile)["value"]) if os.path.isfile(gfile) else None
    wall_tol = float(lim.get("wallTolerance", 0.0)) * d0

    # 2-4, 6 over the time directories
    times = st.time_dirs(case)
    check(len(times) >= 2, f"{name}: {len(times)} time directories")
    # particles the solver removed from the domain (outflow/removed.dat): time, id
    rem_t, rem_id = series.columns.get("outflow/removed.dat/id", (np.array([]), np.array([])))

    def removed_by(t):
        return rem_id[rem_t <= t + 1e-12].astype(np.int64)
    if len(rem_id):
        print(f"     {name}: {len(rem_id)} fluid particle(s) removed from the domain (outflow/removed.dat): "
              f"ids {sorted(int(i) for i in rem_id)[:10]}")
    ids0, energy0, floor_pe, budget = None, None, None, None
    worst_wall = (0.0, None, None)
    worst_energy = (-math.inf, None)
    nonfinite, lost, escaped = [], [], []
    overOpen = {}  # per wall region: ids seen beyond one of its open faces (spray over the top)
    spill = {}     # per wall region: of those, the ids later found outside a closed face
    e_rel = float(lim["energy"]["rel"])
    for t, tname in times:
        p = st.read_vtp(os.path.join(case, tname, "particles.vtp"))
        for k, v in p.items():
            if np.issubdtype(np.asarray(v).dtype, np.floating) and not np.all(np.isfinite(v)):
                nonfinite.append(f"{tname}/{k}")
        fluid = p["type"] == 0
        dim = int(p.get("field:dimension", [2])[0])
        x = p["position"][fluid][:, :dim]
        u = p["U"][fluid][:, :dim]
        m = float(p["field:mass"][0])
        fids = p["id"][fluid]
        ids = np.sort(fids)
        if ids0 is None:
            ids0 = ids
        elif not np.array_equal(ids, np.setdiff1d(ids0, removed_by(t))):
            lost.append(f"{tname}: {len(ids)} fluid particles, {len(ids0)} at the start")
        for wname, lo, hi, opened, thick in walls:
            axes = ["left", "right", "bottom", "top", "front", "back"]
            for k in range(dim):
                # The face's slab spans the box along the other axes, plus the layers where
                # the adjacent face is closed (corners); a particle above the end of a side
                # wall under an open top (resting on its top edge) is not inside it.
                along = np.ones(len(x), dtype=bool)
                for j in range(dim):
                    if j != k:
                        below = 0.0 if axes[2 * j] in opened else thick
                        above = 0.0 if axes[2 * j + 1] in opened else thick
                        along &= (x[:, j] >= lo[j] - below) & (x[:, j] <= hi[j] + above)
                for side, beyond in ((axes[2 * k], lo[k] - x[:, k]), (axes[2 * k + 1], x[:, k] - hi[k])):
                    if side in opened:
                        overOpen.setdefault(wname, set()).update(int(i) for i in fids[beyond > 0])
                        continue
                    beyond = np.where(along, beyond, -np.inf)
                    # within the wall's layers: inside the wall; past them: out of the container
                    inside = beyond[(beyond <= thick) & np.isfinite(beyond)]
                    depth = float(np.max(inside)) if len(inside) else 0.0
                    if depth > worst_wall[0]:
                        worst_wall = (depth, tname, f"{wname} {side}")
                    # past the layers: out of the container, unless seen over an open face of
                    # this wall region before (spray that left an open container)
                    past = beyond > thick
                    spilled = past & np.isin(fids, list(overOpen.get(wname, ())))
                    if spilled.any():
                        spill.setdefault(wname, set()).update(int(i) for i in fids[spilled])
                    out = past & ~spilled
                    if out.any() and not escaped:
                        escaped.append(f"{tname}: {int(out.sum())} fluid particle(s) past the {wname} {side} wall, "
                                       f"up to {float(np.max(beyond[out])) / d0:.3g} d0 beyond its surface")
        ek = 0.5 * m * float(np.sum(u * u))
        ep = -m * float(np.sum(x @ g[:dim])) if g is not None else 0.0
        if energy0 is None:
            energy0 = (ek, ep)
            if g is not None and np.linalg.norm(g) > 0:
                # the lowest height a centre can reach: the container floor + d0/2
                # (gravity along an axis; the height is -g.x/|g|)
                k = int(np.argmax(np.abs(g[:dim])))
                if not walls or abs(g[k]) < 0.999999 * np.linalg.norm(g[:dim]):
                    raise SystemExit("checkStability: needs a wall region and gravity along an axis")
                h_floor = max((lo[k] + 0.5 * d0) if g[k] < 0 else -(hi[k] - 0.5 * d0) for _, lo, hi, _, _ in walls)
                floor_pe = m * np.linalg.norm(g[:dim]) * h_floor * len(x)
                budget = ek + ep - floor_pe
            else:
                floor_pe = 0.0
                budget = ek
            print(f"     energy at t = {t:g}: kinetic {ek:.6g}, potential {ep:.6g}, available above the floor {budget:.6g}")
        else:
            growth = (ek + ep) - sum(energy0)
            if growth / budget > worst_energy[0]:
                worst_energy = (growth / budget, tname)
    check(not nonfinite, f"{name}: every time directory finite{': ' + ' '.join(nonfinite[:5]) if nonfinite else ''}",
          "finite")
    check(not lost, f"{name}: no particle lost ({len(ids0) if ids0 is not None else 0} fluid particles in every "
                    f"time directory){': ' + '; '.join(lost[:3]) if lost else ''}", "lost")
    for wname, s in spill.items():
        if s:
            print(f"     {name}: {len(s)} fluid particle(s) thrown over an open face of {wname} and "
                  f"fallen outside it (spray leaving the container, not counted as lost): ids {sorted(s)[:10]}")
    check(not escaped, f"{name}: no fluid particle out of the container (past a wall's layers)"
                       f"{': ' + escaped[0] if escaped else ''}", "lost")
    nominal = [k for k in series.columns if k.endswith("/nominalVolume")]
    if nominal:
        tv, v = series.columns[nominal[0]]
        n0 = len(ids0) if ids0 is not None else 1
        left = np.array([n0 - len(removed_by(t)) for t in tv], dtype=float)
        check(np.allclose(v * n0 / left, v[0], rtol=1e-9, atol=0),
              f"{name}: nominal fluid volume constant over {len(v)} samples (less the removed particles')", "lost")
    check(worst_wall[0] <= wall_tol, f"{name}: no fluid particle inside a wall (deepest beyond a wall surface: "
                                     f"{worst_wall[0] / d0:.3g} d0{' at ' + str(worst_wall[1]) + ' ' + worst_wall[2] if worst_wall[1] else ''}"
                                     f"; allowed {wall_tol / d0:.3g} d0)", "walls")
    check(worst_energy[0] <= e_rel, f"{name}: total energy never above E(0) + {e_rel:g} B (largest growth "
                                    f"{worst_energy[0]:.3g} B at t = {worst_energy[1]})", "energy")

    # 5. volume, 6b. dense kinetic-energy bound, 7. density error
    vol = [k for k in series.columns if k.endswith("conservation.dat/volume")]
    if check(len(vol) == 1, f"{name}: conservation volume present"):
        t, v = series.columns[vol[0]]
        dev = float(np.max(np.abs(v - v[0])) / v[0])
        check(dev <= float(lim["volume"]["rel"]), f"{name}: fluid volume within {lim['volume']['rel']:g} of its "
                                                   f"initial value (largest change {dev:.3g})", "volume")
    ke = [k for k in series.columns if k.endswith("conservation.dat/kineticEnergy")]
    if check(len(ke) == 1, f"{name}: conservation kineticEnergy present") and energy0 is not None:
        t, k_ = series.columns[ke[0]]
        bound = energy0[0] + (1 + e_rel) * (energy0[1] - floor_pe) if g is not None else energy0[0] * (1 + e_rel)
        i = int(np.argmax(k_))
        check(k_[i] <= bound, f"{name}: kinetic energy at most {bound:.6g} (physics bound; largest {k_[i]:.6g} "
                              f"at t = {t[i]:g})", "kineticEnergy")
    de = [k for k in series.columns if k.endswith("densityError.dat/mode")]
    if check(len(de) == 1, f"{name}: densityError mode present"):
        t, mode = series.columns[de[0]]
        i = int(np.argmax(np.abs(mode)))
        check(abs(mode[i]) <= float(lim["densityErrorMode"]["max"]),
              f"{name}: |density-error mode| at most {lim['densityErrorMode']['max']:g} % (largest {mode[i]:.3g} % "
              f"at t = {t[i]:g})", "densityErrorMode")
    if "densityErrorRms" in lim:
        t, rms = series.columns[de[0].replace("/mode", "/rms")]
        i = int(np.argmax(rms))
        check(rms[i] <= float(lim["densityErrorRms"]["max"]),
              f"{name}: density-error rms at most {lim['densityErrorRms']['max']:g} % (largest {rms[i]:.3g} % "
              f"at t = {t[i]:g})", "densityErrorRms")
    if "densityErrorMean" in lim:
        t, mean = series.columns[de[0].replace("/mode", "/mean")]
        t0, t1 = (float(x) for x in lim["densityErrorMean"]["window"])
        w = (t >= t0) & (t <= t1)
        avg = float(np.mean(mean[w])) if w.any() else math.nan
        check(len(t) > 0 and t[-1] >= t1 and abs(avg) <= float(lim["densityErrorMean"]["max"]),
              f"{name}: interior mean density error averaged over {t0:g} <= t <= {t1:g} at most "
              f"{lim['densityErrorMean']['max']:g} % ({avg:.3g} % over {int(w.sum())} samples)", "densityErrorMean")
    if st.XFAILED:
        print(f"{len(st.XFAILED)} known failures (knownFailures in {a.limits}): " + "; ".join(st.XFAILED))
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
