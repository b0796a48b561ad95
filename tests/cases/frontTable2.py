#!/usr/bin/python3
"""Issue 18's surge-front measure on the Martin & Moyce dam break (labels `regression` and
`long`).

usage: frontTable2.py CASE WORK --shizuku BIN --compare SHIZUKUCOMPARE [--threads 2] [--full]

Runs the dam-break case (CASE = tests/cases/damBreak: column a = 0.2 m wide, 2a high) at
d0 = a/20 with dt = 0.5 ms, or with --full at a/40 and a/80 (dt 0.25 and 0.125 ms), and
takes the front as damBreak/plotFront.py does: the body of water's leading edge
(fluidExtent connectedOnly) + d0/2, Z = x_front/a against T = t sqrt(2 g / a). The measure
is the mean of |Z/Z_exp - 1| over Martin & Moyce's Table 2 points with T <= 3
(data/..._table2.csv), and its signed mean.

Printed, not asserted (the method does not meet it; docs/validation.md, "Surge front"):
`issue 18 bound: ... (bound 5 %: met / not met)` at each size and, with --full, whether a/80
is no worse than a/40.
Asserted, the guards of the resolution study (2026-12-05; signed mean +11.6, +13.3, +12.8 % at
a/20, a/40, a/80 on 2 threads, +11.3 to +13.5 % on one): the signed mean within that range
widened on each side by 1.5 points (the a/20 to a/80 change), +9.8 to +15 %, at every size (since eq. 11d per size, below); with
--full, a/40 and a/80 within 3 points of each other. Each size is run a second time with
`wallFriction { roughness 0; }` (docs/method.md 11.2): the same guard, and with --full the front
held back by 0.3 to 3 points (measured 1.0, 1.0 and 0.6 at a/20, a/40, a/80: the smooth bed's
stress acts where the tongue is fast; a sign error in the stress would push the front ahead).
Since the wall normal of eq. 11d (2026-12-06) the a/20 hold-back is -0.1 points and a planted
sign error in the stress gives -0.2: at a/20 the first row is 1 cm thick and the stress, spread
over it, moves the front less than the tongue tip's scatter, so it is printed there, not
asserted. The resolution study with eq. 11d (2 threads): signed mean +11.1, +14.9 (one thread:
the same) and +13.5 % at a/20, a/40, a/80; with friction +11.3, +11.5 and +12.7 %, held back by
-0.1, 3.4 (one thread 2.9) and 0.8 points. The guards are that study's: without friction the
signed mean within 1.5 points of each size's (+9.6 to +12.6, +13.4 to +16.4, +12.0 to +15.0 %:
the planted gravity 10 % too strong, +15.3 % at a/20, fails), with friction within the study's
whole range widened by 1.5 points, +9.6 to +16.4 %, and the hold-back within 0.3-5
points with --full (the a/40 front without friction runs ahead by its tongue's tip, so the
hold-back there is the largest).
Planted (a/20): gravity 10 % too strong (g = -10.79 m/s^2) gives +15.3 % and fails. Counting
every fluid particle as the front (connectedOnly no) gives +13.4 % and passes, as it should: a
droplet sliding ahead is a choice of measure, not an error of the method.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

BOUND = 0.05
GUARD = (0.096, 0.164)    # with wallFriction: the study's whole range, widened by 1.5 points
SIZE_GUARD = {"a20": (0.096, 0.126), "a40": (0.134, 0.164), "a80": (0.120, 0.150)}  # without: each size's +-1.5
SPREAD = 0.03
FRICTION_GAIN = (0.003, 0.05)
SIZES = {"a20": ("0.01", "5e-4"), "a40": ("0.005", "2.5e-4"), "a80": ("0.0025", "1.25e-4")}


def main():
    p = st.case_arguments()
    p.add_argument("--full", action="store_true")
    a = p.parse_args()
    plot = st.load_module(os.path.join(a.case, "plotFront.py"), "plotFront")
    table2 = plot.data("dambreak_martin_moyce_1952_n2_2_surge_front_table2.csv")
    signed = {}
    for name in (("a40", "a80") if a.full else ("a20",)):
        for friction in (False, True):
            spacing, dt = SIZES[name]
            label = name + ("-wallFriction" if friction else "")
            case = os.path.join(os.path.abspath(a.work), "frontTable2", label)
            st.copy_case(a.case, case)
            st.set_key(os.path.join(case, "system", "particlesDict"), "spacing", spacing)
            st.set_key(os.path.join(case, "system", "controlDict"), "deltaT", dt)
            st.set_key(os.path.join(case, "system", "controlDict"), "writeInterval", "1")
            if friction:
                with open(os.path.join(case, "constant", "physicalProperties"), "a") as f:
                    f.write("wallFriction { roughness 0; }\n")
            st.run_or_fail(a.shizuku, case, a.threads, f"dam break {label}")
            d0, T, Z = plot.front(case)
            mean, sgn = plot.errors(T, Z, table2)
            signed[label] = sgn
            print(f"issue 18 bound: front at {name.replace('a', 'a/')}{' with wallFriction' if friction else ''} "
                  f"against Martin & Moyce's Table 2 (T <= 3): mean |error| {100 * mean:.1f} %, signed "
                  f"{100 * sgn:+.1f} % (bound {100 * BOUND:.0f} %: {'met' if mean <= BOUND else 'not met'})")
            lo, hi = GUARD if friction else SIZE_GUARD[name]
            st.check(lo <= sgn <= hi, f"{label}: signed mean error {100 * sgn:+.1f} % within "
                     f"[{100 * lo:+.1f}, {100 * hi:+.1f}] % (the resolution study's guard)")
        # The bed's stress can only hold the front back; at a/20 by less than the tip's scatter.
        held = signed[name] - signed[name + "-wallFriction"]
        text = (f"{name}: wallFriction holds the front back by {100 * held:.1f} points (within "
                f"{100 * FRICTION_GAIN[0]:.1f}-{100 * FRICTION_GAIN[1]:.1f})")
        if a.full:
            st.check(FRICTION_GAIN[0] <= held <= FRICTION_GAIN[1], text)
        else:
            print(text + ": not asserted at a/20, where a planted sign error gives the same")
    if a.full:
        finer = abs(signed["a80"]) <= abs(signed["a40"])
        print(f"issue 18 bound: a/80 no worse than a/40: {'met' if finer else 'not met'}")
        st.check(abs(signed["a80"] - signed["a40"]) <= SPREAD,
                 f"a/40 and a/80 within {100 * SPREAD:.0f} points ({100 * signed['a40']:+.1f}, {100 * signed['a80']:+.1f} %)")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
