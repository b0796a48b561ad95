#!/usr/bin/python3
"""shizukuPlot on a hand-made case (docs/design.md 1.1): two time directories with
a 12 x 8 particle set (fluid with a linear pressure, a row of walls) written
with VTK's XML writer, postProcessing files with scalars, vectors, a restart
folder and a density-error histogram, and a reference CSV. The script must
write every expected PNG, each a real picture (PNG signature, many colours
for the particle pictures), and fail with exit 1 on bad input: a -range that is
not finite or not MIN < MAX, a particles.vtp with a corrupt XML header; -help
prints the usage with exit 0.

usage: plotSmoke.py SHIZUKUPLOT WORKDIR
"""
import os
import shutil
import subprocess
import sys

import matplotlib.image as mpimg
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

PLOT, WORK = sys.argv[1:3]
CASE = os.path.join(WORK, "plotCase")


def write_vtp(path, t, d0=0.01, raw=False):
    nx, ny = 12, 8
    xs, ys = np.meshgrid((np.arange(nx) + 0.5) * d0, (np.arange(ny) + 0.5) * d0)
    x = np.c_[xs.ravel(), ys.ravel(), np.zeros(nx * ny)]
    walls = np.c_[(np.arange(nx) + 0.5) * d0, np.full(nx, -0.5 * d0), np.zeros(nx)]
    pts = np.vstack([x, walls])
    n = len(pts)
    ptype = np.r_[np.zeros(nx * ny), np.ones(nx)].astype(np.uint8)
    p = 1000 * 9.81 * (ny * d0 - pts[:, 1]) * (1 + t)
    U = np.c_[-pts[:, 1], pts[:, 0], np.zeros(n)]
    rhoN = 1000 * (1 - 0.01 * pts[:, 0] / (nx * d0))
    # raw: as Shizuku writes it (raw appended data, UInt64 block headers)
    st.check(st.write_vtp(path, pts, {"U": U, "p": p, "rhoN": rhoN, "type": ptype},
                          {"spacing": d0, "rho0": 1000.0, "time": t, "dimension": 2.0}, raw), f"wrote {path}")


def make_case():
    shutil.rmtree(CASE, ignore_errors=True)
    for t, name in ((0.0, "0"), (0.1, "0.1")):
        write_vtp(os.path.join(CASE, name, "particles.vtp"), t)
    head = "# probes of p\n# columns: time point0 point1\n# units:   s    Pa     Pa\n"
    st.write(f"{CASE}/postProcessing/centre/0/p", head + "".join(
        f"{0.01 * k:g} {100 + k} {50 - k}\n" for k in range(10)))
    # a restart at 0.05: replaces the rows from 0.05 on
    st.write(f"{CASE}/postProcessing/centre/0.05/p", head + "".join(
        f"{0.05 + 0.01 * k:g} {200 + k} nan\n" for k in range(8)))
    st.write(f"{CASE}/postProcessing/cons/0/conservation.dat",
             "# columns: time volume kineticEnergy momentum\n# units:   s    m^2    J/m           kg/s\n" + "".join(
                 f"{0.01 * k:g} 0.01 {1 - 0.01 * k:g} ({0.1 * k:g} {-0.2 * k:g})\n" for k in range(12)))
    rows = "".join(f"{-9.75 + 0.5 * k:g} {max(0, 20 - abs(k - 22) * 3)} {max(0, 30 - abs(k - 21) * 2)}\n"
                   for k in range(40))
    st.write(f"{CASE}/postProcessing/dErr/0/densityError.dat",
             "# columns: time mean rms max mode meanAll rmsAll maxAll modeAll\n# units: s % % % % % % % %\n"
             "0 0 0 0 0.25 0 0 0 0.25\n0.1 1 1.2 3 1.25 2 3 9 0.75\n")
    st.write(f"{CASE}/postProcessing/dErr/0/0.1/histogram.dat",
             "# columns: binCentre countInterior countAll\n# units:   %         -             -\n" + rows)
    # what a run that broke down leaves next to the tables: a binary particle file
    os.makedirs(f"{CASE}/postProcessing/healthChecks/0.1", exist_ok=True)
    with open(f"{CASE}/postProcessing/healthChecks/0.1/offending.vtp", "wb") as f:
        f.write(b"<VTKFile>\x96\xff\x00 appended binary data")
    st.write(f"{WORK}/reference.csv", "# reference data\ntime,point0,p/point1\n0,90,45\n0.05,150,40\n0.09,180,41\n")


def png_ok(path, min_colours):
    pic = st.png_picture(path)
    if pic is None:
        return False, "missing or not a PNG"
    width, height, colours = pic
    return colours >= min_colours and height > 200 and width > 200, f"{width}x{height}, {colours} colours"


def wall_strip(path):
    """Width/height ratio and fill fraction of the grey (0.6) wall pixels."""
    img = mpimg.imread(path)[:, :, :3]
    grey = np.all(np.abs(img - 0.6) < 0.01, axis=2)
    if not grey.any():
        return 0.0, 0.0
    # the strip: rows and columns mostly grey (anti-aliased text has scattered grey pixels)
    rows = np.nonzero(grey.sum(axis=1) > 0.5 * grey.sum(axis=1).max())[0]
    cols = np.nonzero(grey.sum(axis=0) > 0.5 * grey.sum(axis=0).max())[0]
    h, w = rows.max() - rows.min() + 1, cols.max() - cols.min() + 1
    block = grey[rows.min():rows.max() + 1, cols.min():cols.max() + 1]
    return w / h, block.mean()


def run(args):
    return subprocess.run([PLOT] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def main():
    make_case()
    r = run(["-case", CASE, "-field", "p", "-reference", os.path.join(WORK, "reference.csv")])
    print(r.stdout)
    st.check(r.returncode == 0, "shizukuPlot -field p exits 0 (a health check's binary offending.vtp is skipped)")
    plots = os.path.join(CASE, "plots")
    # particle pictures: a linear pressure through the jet map gives many colours
    for name in ("p_0.png", "p_0.1.png"):
        ok, what = png_ok(os.path.join(plots, name), 50)
        st.check(ok, f"{name}: {what}")
    # particles are squares of side d0: the 12 walls (one row, spacing d0) tile a
    # 12 x 1 strip without gaps (ratio within pixel rounding: the strip is ~70 px high)
    ratio, fill = wall_strip(os.path.join(plots, "p_0.png"))
    st.check(abs(ratio - 12) < 0.6 and fill > 0.97, f"wall row drawn as a 12:1 strip of squares: {ratio:.2f}:1, "
             f"filled {100 * fill:.1f} %")
    for name in ("centre_p.png", "cons_conservation.png", "dErr_densityError.png", "dErr_histogram_0.1.png"):
        ok, what = png_ok(os.path.join(plots, name), 10)
        st.check(ok, f"{name}: {what}")
    st.check("Warning" not in r.stdout, "the reference columns matched")
    r = run(["-case", CASE, "-field", "Ux", "-time", "latestTime", "-what", "particles"])
    st.check(r.returncode == 0 and os.path.isfile(os.path.join(plots, "Ux_0.1.png"))
             and not os.path.exists(os.path.join(plots, "Ux_0.png")), "-field Ux -time latestTime: one picture")
    r = run(["-case", CASE, "-field", "densityError", "-time", "0", "-what", "particles", "-range", "-1", "1"])
    ok, what = png_ok(os.path.join(plots, "densityError_0.png"), 20)
    st.check(r.returncode == 0 and ok, f"-field densityError -range: {what}")
    # -against: a second case drawn beside at the same time (walls twice: twice the grey pixels)
    other = os.path.join(WORK, "otherCase")
    shutil.rmtree(other, ignore_errors=True)
    write_vtp(os.path.join(other, "0.1", "particles.vtp"), 2.0)
    r = run(["-case", CASE, "-against", other, "-time", "0.1", "-what", "particles"])
    pair = os.path.join(plots, "p_0.1_vs_otherCase.png")
    ok, what = png_ok(pair, 50)
    st.check(r.returncode == 0 and ok, f"-against: {what}")
    if ok:
        grey = lambda path: int(np.all(np.abs(mpimg.imread(path)[:, :, :3] - 0.6) < 0.01, axis=2).sum())
        single, double = grey(os.path.join(plots, "p_0.1.png")), grey(pair)
        st.check(1.5 < double / max(single, 1) < 2.6, f"-against draws both cases' walls: {double} grey pixels, "
                 f"one case {single}")
    r = run(["-case", CASE, "-against", other, "-time", "0", "-what", "particles"])
    st.check(r.returncode == 0 and "no time 0" in r.stdout, "-against a case without that time: warned, exit 0")
    for bad, why in ((["-case", CASE, "-field", "nothing", "-what", "particles"], "unknown field"),
                     (["-case", CASE, "-against", os.path.join(WORK, "none"), "-what", "particles"],
                      "missing -against case"),
                     (["-case", CASE, "-time", "7", "-what", "particles"], "unknown time"),
                     (["-case", os.path.join(WORK, "none")], "missing case"),
                     (["-case", CASE, "-what", "pictures"], "unknown -what")):
        r = run(bad)
        st.check(r.returncode == 1 and "error" in r.stdout, f"{why}: exit 1 with a message")
    # -range must be finite with MIN below MAX; nothing is drawn otherwise.
    for rng, message in ((["1", "nan"], "-range 1 nan: MIN and MAX must be finite"),
                         (["0", "inf"], "-range 0 inf: MIN and MAX must be finite"),
                         (["-inf", "1"], "argument -range/--range: expected 2 arguments"),
                         (["5", "-5"], "-range: min 5 > max -5"), (["2", "2"], "-range: min 2 = max 2")):
        shutil.rmtree(plots, ignore_errors=True)
        r = run(["-case", CASE, "-what", "particles", "-range"] + rng)
        st.check(r.returncode == 1 and message in r.stdout and not os.path.exists(plots),
                 f"-range {' '.join(rng)}: exit 1, '{message}', no plots/ folder: {r.stdout[-200:]}")
    # -help, -h, --help: the usage on standard output, exit 0 (as the C++ tools)
    for flag in ("-help", "-h", "--help"):
        r = run([flag])
        st.check(r.returncode == 0 and "usage: shizukuPlot" in r.stdout and "-range" in r.stdout, f"{flag}: usage, exit 0")
    # A corrupt XML header is refused, naming the file, before VTK reads it: a negative
    # count (VTK crashes on it), and raw appended arrays whose sizes disagree with it.
    bad = os.path.join(WORK, "badVtp")
    shutil.rmtree(bad, ignore_errors=True)
    write_vtp(os.path.join(bad, "0", "particles.vtp"), 0.0, raw=True)
    path = os.path.join(bad, "0", "particles.vtp")
    good = open(path, "rb").read()
    r = run(["-case", bad, "-what", "particles"])
    st.check(r.returncode == 0, f"a raw appended vtp passes the header check: {r.stdout[-300:]}")
    for edit, message in (((b'NumberOfPoints="108"', b'NumberOfPoints="-5"'), 'NumberOfPoints="-5" is not a count'),
                          ((b'NumberOfPoints="108"', b'NumberOfPoints="200"'), "but 200 tuples of"),
                          ((b'NumberOfVerts="108"', b'NumberOfVerts="1e9"'), 'NumberOfVerts="1e9" is not a count')):
        with open(path, "wb") as f:
            f.write(good.replace(*edit))
        r = run(["-case", bad, "-what", "particles"])
        st.check(r.returncode == 1 and path in r.stdout and message in r.stdout,
                 f"vtp with {edit[1].decode()}: exit 1 naming the file, '{message}': {r.stdout[-300:]}")
    with open(path, "wb") as f:
        f.write(good[:len(good) * 2 // 3])
    r = run(["-case", bad, "-what", "particles"])
    st.check(r.returncode == 1 and path in r.stdout and "cut short" in r.stdout, f"vtp cut short: {r.stdout[-300:]}")
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
