#!/usr/bin/python3
"""Dam break: the surge-front history of a fine run, as the reference of the `resolution`
check (README.md, "Resolution study of the front").

usage: makeReference.py FINE_RUN_CASE   -> reference/frontHistory.dat (this folder)

FINE_RUN_CASE is this case run at a finer spacing (runCase.py --spacing D0 --deltaT DT).
fluidExtent's max_x is the centre of the foremost particle, which stands for a cell of
side d0: the front is x_front = max_x + d0/2. The file stores x_front(t), so it does not
depend on the fine run's d0; makeAnalytic.py subtracts the checked run's d0/2. The file
header records the spacing and time step it came from.
"""
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.dirname(HERE))
from referenceHistory import read_rows, read_setting, write_history  # noqa: E402

A = 0.2  # column width [m]


def main():
    case = sys.argv[1]
    d0 = read_setting(case, "particlesDict", "spacing")
    dt = read_setting(case, "controlDict", "deltaT")
    # time (min_x min_y) (max_x max_y)
    rows = [(float(r[0]), float(r[2].strip("()").split()[0]) + d0 / 2)
            for r in read_rows(case, "front", "extent.dat")]
    out = write_history(HERE, "frontHistory.dat", [
        "Dam break: surge front x_front = max_x + d0/2, from a run at",
        f"d0 = a/{A / d0:g} (d0 = {d0:g} m, dt = {dt:g} s), written by makeReference.py",
        "columns: time [s]  x_front [m]"], rows)
    print(f"makeReference: {len(rows)} samples from d0 = a/{A / d0:g} -> {out}")


if __name__ == "__main__":
    main()
