#!/usr/bin/python3
"""Rotating square patch: analytic invariants for the run's own lattice.

usage: makeAnalytic.py WORKCASE   -> WORKCASE/analytic/invariants.csv, centreHistory.csv

Exact answers (tests/cases/README.md): initial centre pressure p_c = -0.147342707 rho omega^2 L^2;
kinetic energy rho omega^2 L^4/12 and angular momentum -rho omega L^4/6 (clockwise),
conserved for all time. Conventions used here:
- p = 0 is imposed on the outermost particle row, d0/2 inside the true edge, so the
  effective side is L - d0: p_c = -0.147342707 rho omega^2 (L - d0)^2;
- the particles sit at cell centres, so the discrete sums of the lattice are
  E_k = rho omega^2 L^2 (L^2 - d0^2)/12 and L_z = -rho omega L^2 (L^2 - d0^2)/6
  (the exact integrals times 1 - (d0/L)^2; 0.06 % at L/d0 = 40).
After the start no exact answer exists: centreHistory.csv is the centre-pressure history
of the finest run of the resolution study (reference/centrePressure.dat, stored divided
by rho omega^2 (L - d0)^2, makeReference.py) times that scale for this run's d0.
"""
import os
import re
import sys

case = sys.argv[1]
with open(os.path.join(case, "system/particlesDict")) as f:
    d0 = float(re.search(r"(?m)^\s*spacing\s+([^;]+);", f.read()).group(1))
rho, omega, L = 1000.0, 1.0, 1.0
pc = -0.147342707 * rho * omega ** 2 * (L - d0) ** 2
ek = rho * omega ** 2 * L ** 2 * (L ** 2 - d0 ** 2) / 12
lz = -rho * omega * L ** 2 * (L ** 2 - d0 ** 2) / 6
os.makedirs(os.path.join(case, "analytic"), exist_ok=True)
with open(os.path.join(case, "analytic", "invariants.csv"), "w") as f:
    f.write("time,centre/p/point0,conservation/kineticEnergy,conservation/angularMomentum\n")
    for t in (0.0, 1e3):
        f.write(f"{t},{pc:.10g},{ek:.10g},{lz:.10g}\n")

HERE = os.path.dirname(os.path.abspath(__file__))
with open(os.path.join(HERE, "reference", "centrePressure.dat")) as f, \
        open(os.path.join(case, "analytic", "centreHistory.csv"), "w") as out:
    out.write("time,centre/p/point0\n")
    scale = rho * omega ** 2 * (L - d0) ** 2
    for line in f:
        if line.startswith("#") or not line.strip():
            continue
        t, q = (float(x) for x in line.split()[:2])
        out.write(f"{t!r},{q * scale!r}\n")
