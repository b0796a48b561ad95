#!/usr/bin/python3
"""Hydrostatic tank: analytic pressure at the probes, p = rho g (H - y).

usage: makeAnalytic.py WORKCASE   -> WORKCASE/analytic/pressure.csv

The free-surface condition p = 0 is imposed on the surface, d0/2 above the top particle
row, i.e. at the nominal water depth H = 0.4 m (docs/method.md 4.4, eq. 6b).
rho = 1000 kg/m^3, g = 9.81 m/s^2 from constant/; the probe heights are read
from the work case.
"""
import os
import re
import sys

case = sys.argv[1]


def key(path, name):
    with open(os.path.join(case, path)) as f:
        return re.search(r"(?m)^\s*" + name + r"\s+([^;]+);", f.read()).group(1)


rho = float(key("constant/physicalProperties", "rho").split()[0])
g = -float(key("constant/g", "value").strip("() ").split()[1])
H = 0.4
ys = [0.1, 0.2, 0.3]  # the probe points of system/controlDict, x = 0.2
os.makedirs(os.path.join(case, "analytic"), exist_ok=True)
with open(os.path.join(case, "analytic", "pressure.csv"), "w") as f:
    f.write("time," + ",".join(f"pressure/p/point{k}" for k in range(len(ys))) + "\n")
    for t in (0.0, 1e3):
        f.write(f"{t}," + ",".join(f"{rho * g * (H - y):.10g}" for y in ys) + "\n")
