#!/usr/bin/python3
"""Regression test of the weir tutorial at a reduced size (ctest regression.weir; the
tutorial's full size: long.weir). See README.md here for the numbers.

usage: runWeir.py TUTORIAL WORK --shizuku BIN --compare SHIZUKUCOMPARE [--threads N] [--full]

Copies tutorials/weir to WORK/weir (or WORK/weirFull with --full); without --full its
system/particlesDict is replaced by this folder's (the same flume at d0 = 1 cm) and
endTime set to 4 s. Runs the solver, then the tutorial's weirDischarge.py over t >= 2.5 s
(the tutorial's own window with --full), and checks:
  - exit status 0;
  - the discharge per unit width over the crest against the critical-flow relation,
    |q / (sqrt(g) (2E/3)^(3/2)) - 1| <= 0.08 (README.md: the resolution study and the
    measured range of broad-crested weirs);
  - steady state: the discharge over the crest and the outlet's capture rate within 2 %
    of the inlet's release rate;
  - the mass balance at every written time: N_fluid = N_fluid(0) + released - captured
    - removed, exactly (whole particles), and the `conservation` file's fluidMass at
    the last written time equal to that count times the particle mass to 1e-12.
"""
import json
import os
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
import shizukutest as st  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
# The tutorial's geometry (crest x0 x1 P, the approach section, the stretch of crest where q is taken).
GEOMETRY = ["--crest", "0.35", "0.65", "0.05", "--upstream", "0.05", "0.15", "--over", "0.4", "0.6"]


def main():
    a, case = st.full_size_case("weir")
    start = "3"
    if not a.full:
        shutil.copy(os.path.join(HERE, "particlesDict"), os.path.join(case, "system", "particlesDict"))
        st.set_key(os.path.join(case, "system", "controlDict"), "endTime", "4")
        start = "2.5"
    st.run_or_fail(a.shizuku, case, a.threads, "weir")
    st.check(True, "weir: exit status 0")
    rc = subprocess.call([os.path.join(a.tutorial, "weirDischarge.py"), case, "--from", start, "--no-plot"] + GEOMETRY)
    if not st.check(rc == 0, f"weirDischarge.py exit status {rc}"):
        return st.summary()
    with open(os.path.join(case, "plots", "weirDischarge.json")) as f:
        m = json.load(f)
    ratio = m["q"] / m["qc"]
    st.check(abs(ratio - 1) <= 0.08, f"q = {m['q']:.5f} m^2/s over the crest, sqrt(g)(2E/3)^1.5 = {m['qc']:.5f} "
                                     f"(E = {m['E']:.5f} m): ratio {ratio:.4f} within 8 %")
    for what, key in (("over the crest", "q"), ("captured by the outlet", "qOutlet")):
        st.check(abs(m[key] / m["qInlet"] - 1) <= 0.02,
                 f"steady: q {what} {m[key]:.5f} within 2 % of the inlet's {m['qInlet']:.5f} m^2/s")
    st.check(m["balance"] == 0, f"N_fluid = N0 + released - captured - removed at every written time "
                                f"(largest difference {m['balance']} particles)")
    # conservation at every written time: fluidMass + capturedMass + removedMass - releasedMass
    # is the initial fluid mass, and fluidMass is N_fluid m of the written particles
    weir = st.load_module(os.path.join(a.tutorial, "weirDischarge.py"), "weirDischarge")
    rows = weir.read_table(os.path.join(case, "postProcessing", "conservation", "0", "conservation.dat"))
    # each column printed to 12 significant digits: each term rounded by up to 5e-12 of itself
    m0 = rows[0]["fluidMass"]
    worst_balance = max(abs(r["fluidMass"] + r["capturedMass"] + r["removedMass"] - r["releasedMass"] - m0)
                        / (5e-12 * (r["fluidMass"] + r["capturedMass"] + r["removedMass"] + r["releasedMass"] + m0))
                        for r in rows)
    st.check(worst_balance <= 1, f"fluidMass + capturedMass + removedMass - releasedMass = initial fluid mass at "
                                 f"{len(rows)} rows, within the rounding of 12 printed digits "
                                 f"(largest difference {worst_balance:.2f} of that rounding)")
    worst, matched = 0.0, 0
    for t, name in st.time_dirs(case):
        p = st.read_vtp(os.path.join(case, name, "particles.vtp"))
        nm = int(np.sum(p["type"] == 0)) * float(p["field:mass"][0])
        row = [r for r in rows if abs(r["time"] - t) <= 1e-9 * max(1.0, t)]
        if row:
            matched += 1
            worst = max(worst, abs(row[0]["fluidMass"] / nm - 1))
    st.check(matched == len(st.time_dirs(case)) and worst <= 1e-12,
             f"conservation's fluidMass = N_fluid m at {matched} written times (largest relative difference {worst:.1e})")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
