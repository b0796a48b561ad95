#!/usr/bin/python3
"""Rotating square patch: the centre-pressure history of a fine run, as the reference of
the `resolution` check (README.md, "Resolution study").

usage: makeReference.py FINE_RUN_CASE   -> reference/centrePressure.dat (this folder)

FINE_RUN_CASE is this case run at a finer spacing (runCase.py --spacing D0 --deltaT DT).
Its history p(t) at the centre probe is stored divided by rho omega^2 side^2, the scale of
the exact initial pressure for the side on whose edge p = 0 (makeAnalytic.effective_side:
L with the default pressureCondition surface, L - d0 with particles); makeAnalytic.py
multiplies it back for the run being checked. The file header records the spacing, time
step and side it came from.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.dirname(HERE))
from makeAnalytic import L, OMEGA, RHO, effective_side  # noqa: E402
from referenceHistory import read_rows, read_setting, write_history  # noqa: E402


def main():
    case = sys.argv[1]
    d0, side = effective_side(case)
    dt = read_setting(case, "controlDict", "deltaT")
    scale = RHO * OMEGA ** 2 * side ** 2
    rows = [(float(r[0]), float(r[1]) / scale) for r in read_rows(case, "centre", "p")]
    out = write_history(HERE, "centrePressure.dat", [
        f"Rotating square patch: centre pressure / (rho omega^2 side^2), side = {side:g} m, from a run",
        f"at L/d0 = {L / d0:g} (d0 = {d0:g} m, dt = {dt:g} s), written by makeReference.py",
        "columns: time [s]  p / (rho omega^2 side^2) [-]"], rows)
    print(f"makeReference: {len(rows)} samples from L/d0 = {L / d0:g} -> {out}")


if __name__ == "__main__":
    main()
