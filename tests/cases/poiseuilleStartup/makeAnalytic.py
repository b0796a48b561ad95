#!/usr/bin/python3
"""Start-up plane Poiseuille flow: the analytic velocity history (series solution).

usage: makeAnalytic.py WORKCASE   -> WORKCASE/analytic/profile.csv
(importable: u(y, t), px(t) and the probe heights ys are used by tests/cases/spaceOrder.py)

A channel of height H between no-slip walls at y = 0 and y = H, fluid at rest at t = 0,
driven by a body force g along x from t = 0 on. The exact solution of
du/dt = nu d2u/dy2 + g, u(0) = u(H) = 0, u(y, 0) = 0 is
  u(y, t) = g y (H - y) / (2 nu)
            - sum_{n odd} 4 g H^2 / (nu pi^3 n^3) sin(n pi y / H) exp(-n^2 pi^2 nu t / H^2)
and the x momentum of the fluid (per unit depth, channel length Lx)
  P_x(t) = rho Lx [ g H^3 / (12 nu) - sum_{n odd} 8 g H^3 / (nu pi^4 n^4) exp(-n^2 pi^2 nu t / H^2) ].
The walls' surfaces are the faces of the wall box (y = 0 and y = H), so no spacing
convention enters; v = 0 everywhere.
"""
import math
import os
import sys

H, Lx, nu, g, rho = 0.1, 0.05, 1e-3, 8e-3, 1000.0
ys = [0.0125, 0.025, 0.05, 0.075]  # the probe points of system/controlDict


def u(y, t):
    s = g * y * (H - y) / (2 * nu)
    for n in range(1, 400, 2):
        s -= 4 * g * H ** 2 / (nu * math.pi ** 3 * n ** 3) * math.sin(n * math.pi * y / H) * \
            math.exp(-n * n * math.pi ** 2 * nu * t / H ** 2)
    return s


def px(t):
    s = g * H ** 3 / (12 * nu)
    for n in range(1, 400, 2):
        s -= 8 * g * H ** 3 / (nu * math.pi ** 4 * n ** 4) * math.exp(-n * n * math.pi ** 2 * nu * t / H ** 2)
    return rho * Lx * s


def main(case):
    os.makedirs(os.path.join(case, "analytic"), exist_ok=True)
    with open(os.path.join(case, "analytic", "profile.csv"), "w") as f:
        cols = [f"profile/U/point{k}_x" for k in range(len(ys))] + [f"profile/U/point{k}_y" for k in range(len(ys))]
        f.write("time," + ",".join(cols) + ",conservation/momentum_x\n")
        for k in range(0, 2001):
            t = k * 0.002  # 0 .. 4 s
            f.write(f"{t:g}," + ",".join(f"{u(y, t):.10g}" for y in ys) + "," + ",".join("0" for _ in ys) +
                    f",{px(t):.10g}\n")


if __name__ == "__main__":
    main(sys.argv[1])
