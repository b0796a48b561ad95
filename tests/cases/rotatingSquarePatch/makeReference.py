#!/usr/bin/python3
"""Rotating square patch: the centre-pressure history of a fine run, as the reference of
the `resolution` check (README.md, "Resolution study").

usage: makeReference.py FINE_RUN_CASE   -> reference/centrePressure.dat (this folder)

FINE_RUN_CASE is this case run at a finer spacing (runCase.py --spacing D0 --deltaT DT).
Its history p(t) at the centre probe is stored divided by rho omega^2 (L - d0)^2, the
scale of the exact initial pressure with p = 0 on the outermost particle row (d0/2 inside
the true edge: makeAnalytic.py); makeAnalytic.py multiplies it back for the spacing of
the run being checked. The file header records the spacing and time step it came from.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from referenceHistory import read_rows, read_setting, write_history  # noqa: E402

RHO, OMEGA, L = 1000.0, 1.0, 1.0


def main():
    case = sys.argv[1]
    d0 = read_setting(case, "particlesDict", "spacing")
    dt = read_setting(case, "controlDict", "deltaT")
    scale = RHO * OMEGA ** 2 * (L - d0) ** 2
    rows = [(float(r[0]), float(r[1]) / scale) for r in read_rows(case, "centre", "p")]
    out = write_history(HERE, "centrePressure.dat", [
        "Rotating square patch: centre pressure / (rho omega^2 (L - d0)^2), from a run at",
        f"L/d0 = {L / d0:g} (d0 = {d0:g} m, dt = {dt:g} s), written by makeReference.py",
        "columns: time [s]  p / (rho omega^2 (L - d0)^2) [-]"], rows)
    print(f"makeReference: {len(rows)} samples from L/d0 = {L / d0:g} -> {out}")


if __name__ == "__main__":
    main()
