#!/usr/bin/python3
"""Dam break: the experimental surge front in the run's units.

usage: makeAnalytic.py WORKCASE
  -> WORKCASE/analytic/frontKO.csv, frontMM.csv, frontHistory.csv
     (columns time, front/extent.dat/max_x)

data/ holds the digitised experiments (copied from the project's reference data; sources
in tests/cases/README.md): Koshizuka & Oka (1996) and Martin & Moyce (1952, n^2 = 2,
the larger column, a = 2.25 inch), as Z = x_front/a against T = t sqrt(2 g / a)
for a column a wide and 2a high. Converted with this case's a = 0.2 m, g = 9.81 m/s^2.
The run's fluidExtent gives the largest particle x; a particle stands for a cell of side
d0, so the front x_front corresponds to max_x = x_front - d0/2 (d0 read from the work case).
Points beyond Z = 4.6 (the tank is 5a long) are dropped.
frontHistory.csv is the front x_front(t) of the finest run of the resolution study
(reference/frontHistory.dat, makeReference.py), likewise minus this run's d0/2.
"""
import csv
import math
import os
import re
import sys

case = sys.argv[1]
here = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(case, "system/particlesDict")) as f:
    d0 = float(re.search(r"(?m)^\s*spacing\s+([^;]+);", f.read()).group(1))
a, g = 0.2, 9.81
scale = math.sqrt(2 * g / a)


def rows(name):
    with open(os.path.join(here, "data", name)) as f:
        r = list(csv.reader(f))
    return [[float(x) for x in row] for row in r[1:]]


ko = [(T, Z) for T, Z in rows("dambreak_koshizuka_oka_1996_surge_front.csv")]
mm = sorted((T, Z) for size, T, Z in rows("dambreak_martin_moyce_1952_n2_2_surge_front_fig3_digitized.csv")
            if size == 2.25)
os.makedirs(os.path.join(case, "analytic"), exist_ok=True)
for name, data in (("frontKO.csv", ko), ("frontMM.csv", mm)):
    with open(os.path.join(case, "analytic", name), "w") as f:
        f.write("time,front/extent.dat/max_x\n")
        for T, Z in data:
            if Z <= 4.6:
                f.write(f"{T / scale:.6g},{Z * a - d0 / 2:.6g}\n")

with open(os.path.join(here, "reference", "frontHistory.dat")) as f, \
        open(os.path.join(case, "analytic", "frontHistory.csv"), "w") as out:
    out.write("time,front/extent.dat/max_x\n")
    for line in f:
        if line.startswith("#") or not line.strip():
            continue
        t, x_front = (float(x) for x in line.split()[:2])
        out.write(f"{t!r},{x_front - d0 / 2!r}\n")
