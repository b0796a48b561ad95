#!/usr/bin/python3
"""Hydrostatic tank: analytic pressure at the probes, p = rho g (H - d0/2 - y).

usage: makeAnalytic.py WORKCASE   -> WORKCASE/analytic/pressure.csv

The free-surface condition p = 0 is imposed on the top particle row, which lies d0/2
below the nominal water depth H = 0.4 m (the same convention as the rotating patch's
L - d0 side, tests/cases/README.md).
rho = 1000 kg/m^3, g = 9.81 m/s^2 from constant/; the probe heights and d0 are read
from the work case, so the file matches the run's own resolution.
"""
import os
import re
import sys

case = sys.argv[1]


def key(path, name):
    with open(os.path.join(case, path)) as f:
        return re.search(r"(?m)^\s*" + name + r"\s+([^;]+);", f.read()).group(1)


d0 = float(key("system/particlesDict", "spacing"))
rho = float(key("constant/physicalProperties", "rho").split()[0])
g = -float(key("constant/g", "value").strip("() ").split()[1])
H = 0.4
ys = [0.1, 0.2, 0.3]  # the probe points of system/controlDict, x = 0.2
os.makedirs(os.path.join(case, "analytic"), exist_ok=True)
with open(os.path.join(case, "analytic", "pressure.csv"), "w") as f:
    f.write("time," + ",".join(f"pressure/p/point{k}" for k in range(len(ys))) + "\n")
    for t in (0.0, 1e3):
        f.write(f"{t}," + ",".join(f"{rho * g * (H - d0 / 2 - y):.10g}" for y in ys) + "\n")
