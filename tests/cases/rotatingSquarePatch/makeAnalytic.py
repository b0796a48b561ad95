#!/usr/bin/python3
"""Rotating square patch: analytic invariants for the run's own lattice.

usage: makeAnalytic.py WORKCASE   -> WORKCASE/analytic/invariants.csv, centreHistory.csv

Exact answers (tests/cases/README.md): initial centre pressure p_c = -0.147342707 rho omega^2 L^2;
kinetic energy rho omega^2 L^4/12 and angular momentum -rho omega L^4/6 (clockwise),
conserved for all time. Conventions used here:
- the side the pressure sees, effective_side(): L with p = 0 on the surface (the default,
  freeSurface { pressureCondition surface; }, docs/method.md 4.4: d0/2 outside the outer
  particle row, the true edge); L - d0 with pressureCondition particles (p = 0 on the outer
  row, d0/2 inside the edge); p_c = -0.147342707 rho omega^2 side^2;
- the particles sit at cell centres, so the discrete sums of the lattice are
  E_k = rho omega^2 L^2 (L^2 - d0^2)/12 and L_z = -rho omega L^2 (L^2 - d0^2)/6
  (the exact integrals times 1 - (d0/L)^2; 0.06 % at L/d0 = 40).
After the start no exact answer exists: centreHistory.csv is the centre-pressure history
of the finest run of the resolution study (reference/centrePressure.dat, stored divided
by rho omega^2 side^2, makeReference.py) times that scale for this run.
"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from referenceHistory import read_setting  # noqa: E402

RHO, OMEGA, L = 1000.0, 1.0, 1.0


def effective_side(case):
    """(d0, side): the side of the square on whose edge p = 0 (module docstring)."""
    d0 = read_setting(case, "particlesDict", "spacing")
    with open(os.path.join(case, "system", "sphSchemes")) as f:
        on_particles = re.search(r"\bpressureCondition\s+particles\s*;", f.read())
    return d0, (L - d0 if on_particles else L)


def main():
    case = sys.argv[1]
    d0, side = effective_side(case)
    scale = RHO * OMEGA ** 2 * side ** 2
    pc = -0.147342707 * scale
    ek = RHO * OMEGA ** 2 * L ** 2 * (L ** 2 - d0 ** 2) / 12
    lz = -RHO * OMEGA * L ** 2 * (L ** 2 - d0 ** 2) / 6
    os.makedirs(os.path.join(case, "analytic"), exist_ok=True)
    with open(os.path.join(case, "analytic", "invariants.csv"), "w") as f:
        f.write("time,centre/p/point0,conservation/kineticEnergy,conservation/angularMomentum\n")
        for t in (0.0, 1e3):
            f.write(f"{t},{pc:.10g},{ek:.10g},{lz:.10g}\n")
    with open(os.path.join(HERE, "reference", "centrePressure.dat")) as f, \
            open(os.path.join(case, "analytic", "centreHistory.csv"), "w") as out:
        out.write("time,centre/p/point0\n")
        for line in f:
            if line.startswith("#") or not line.strip():
                continue
            t, q = (float(x) for x in line.split()[:2])
            out.write(f"{t!r},{q * scale!r}\n")


if __name__ == "__main__":
    main()
