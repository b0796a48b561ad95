#!/usr/bin/python3
"""shizukuPlot on a hand-made 3D case (docs/postprocessing.md, "shizukuPlot"): a block of
10 x 6 x 5 fluid particles over a floor of walls (shizukutest.write_block_case), two
times. Checks: each time gets a perspective picture <field>_<time>_3d.png (walls
translucent) and a slice <field>_<time>_slice_z.png, real pictures (PNG signature, many
colours), and no x-y projection; a slice holds exactly the particles within d0/2 of its plane (the counts the
script prints, and its helper in_slab at the slab's edges); -slice x=, y= choose other
planes; a plane with no particle near it, a bad -slice argument, a repeated axis and
-slice on a 2D case are exit 1 with a clear message; -against draws the slices side by
side.

usage: plot3dSmoke.py SHIZUKUPLOT WORKDIR
"""
import os
import shutil
import subprocess
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

PLOT, WORK = sys.argv[1:3]
CASE = os.path.join(WORK, "block3d")
PLOTS = os.path.join(CASE, "plots")
NX, NY, NZ, D0 = 10, 6, 5, 0.01


def run(args):
    return subprocess.run([PLOT] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def png_ok(name, min_colours):
    pic = st.png_picture(os.path.join(PLOTS, name))
    if pic is None:
        return False, f"{name}: missing or not a PNG"
    width, height, colours = pic
    return colours >= min_colours and width > 200 and height > 200, f"{name}: {width}x{height}, {colours} colours"


def slice_count(out, axis, value, fluid, total):
    """The script's line for a slice holds the expected particle counts."""
    line = f"slice {axis} = {value:g} m at t = 0 s: {total} particles ({fluid} fluid) within d0/2 = {D0 / 2:g} m"
    return st.check(line in out, f"slice {axis} = {value:g}: {total} particles, {fluid} fluid (one layer)"
                    + ("" if line in out else f"; the script said: {out[:300]}"))


def opaque_grey_pixels(name):
    """Pixels of the grey 0.6 (shizukuPlot's wall colour) drawn opaque."""
    import matplotlib.image as mpimg

    img = mpimg.imread(os.path.join(PLOTS, name))[:, :, :3]
    return int(((np.ptp(img, axis=2) < 0.02) & (np.abs(img.mean(axis=2) - 0.6) < 0.05)).sum())


def check_default_pictures():
    r = run(["-case", CASE, "-what", "particles"])
    st.check(r.returncode == 0, f"3D case: exit 0: {r.stdout[-300:]}")
    for t in ("0", "0.1"):
        ok, what = png_ok(f"p_{t}_3d.png", 100)
        st.check(ok, f"perspective view {what}")
        ok, what = png_ok(f"p_{t}_slice_z.png", 20)
        st.check(ok, f"slice {what}")
        st.check(not os.path.exists(os.path.join(PLOTS, f"p_{t}.png")), f"no x-y projection p_{t}.png for a 3D case")
    # translucent walls: the floor seen around the block is no opaque grey (opaque, it
    # paints ~50000 pixels; axis text leaves ~1000 grey pixels)
    grey = opaque_grey_pixels("p_0_3d.png") if os.path.isfile(os.path.join(PLOTS, "p_0_3d.png")) else -1
    st.check(0 <= grey < 5000, f"perspective view: walls translucent ({grey} opaque grey pixels)")
    # default plane: the fluid layer at the middle of nz = 5 layers, z = 2.5 d0; the slab
    # holds that layer of NX x NY fluid and the floor row of NX + 2 walls below it
    slice_count(r.stdout, "z", 2.5 * D0, NX * NY, NX * NY + NX + 2)


def check_in_slab():
    """The helper itself at the slab's edges: plane - d0/2 is in, plane + d0/2 is out."""
    plot = st.load_module(PLOT, "shizukuPlotModule")
    plane = 0.3
    offsets = np.array([-0.5, -0.4999, 0.0, 0.4999, 0.5, 0.5001, -0.5001, 1.0, -1.0])
    got = plot.in_slab(plane + offsets * D0, plane, D0)
    want = np.array([True, True, True, True, False, False, False, False, False])
    st.check(np.array_equal(got, want), f"in_slab: within d0/2, half-open: {got.tolist()}")


def check_chosen_planes():
    shutil.rmtree(PLOTS, ignore_errors=True)
    # planes off the layers (a layer 1.5 d0 / 10 away), so that a slab thicker than d0
    # takes two layers whatever the rounding
    r = run(["-case", CASE, "-what", "particles", "-time", "0", "-slice", "x=0.0435", "-slice", "y = 0.0265"])
    st.check(r.returncode == 0, f"-slice x=0.0435 -slice y=0.0265: exit 0: {r.stdout[-300:]}")
    for name in ("p_0_slice_x.png", "p_0_slice_y.png"):
        ok, what = png_ok(name, 10)
        st.check(ok, what)
    st.check(not os.path.exists(os.path.join(PLOTS, "p_0_slice_z.png")), "given slices replace the default z slice")
    # the layers x = 4.5 d0 (NY x NZ fluid, the floor's column of NZ + 2 walls) and
    # y = 2.5 d0 (NX x NZ fluid)
    slice_count(r.stdout, "x", 0.0435, NY * NZ, NY * NZ + NZ + 2)
    slice_count(r.stdout, "y", 0.0265, NX * NZ, NX * NZ)
    r = run(["-case", CASE, "-what", "particles", "-time", "0", "-field", "Uz", "-slice", "x"])
    ok, what = png_ok("Uz_0_slice_x.png", 10)
    st.check(r.returncode == 0 and ok and os.path.isfile(os.path.join(PLOTS, "Uz_0_3d.png")),
             f"-field Uz -slice x (through the fluid's centre): {what}")


def check_bad_input():
    vtp = os.path.join(CASE, "0", "particles.vtp")
    r = run(["-case", CASE, "-what", "particles", "-time", "0", "-slice", "z=5"])
    st.check(r.returncode == 1 and vtp in r.stdout and "no particle within d0/2 = 0.005 m of the plane z = 5 m"
             in r.stdout, f"-slice z=5 (no particle there): exit 1 naming the file: {r.stdout[-300:]}")
    for bad in ("q=1", "z=abc", "z=nan", "z=inf", "z=", "zz", "x=1=2", ""):
        shutil.rmtree(PLOTS, ignore_errors=True)
        r = run(["-case", CASE, "-what", "particles", "-slice", bad])
        st.check(r.returncode == 1 and f"-slice '{bad}': expected AXIS or AXIS=VALUE" in r.stdout
                 and not os.path.exists(PLOTS), f"-slice '{bad}': exit 1, usage of -slice, nothing written: "
                 f"{r.stdout[-200:]}")
    r = run(["-case", CASE, "-what", "particles", "-slice", "z", "-slice", "z=0.01"])
    st.check(r.returncode == 1 and "-slice: axis z given twice" in r.stdout, f"-slice z twice: exit 1: {r.stdout[-200:]}")
    flat = os.path.join(WORK, "block2d")
    shutil.rmtree(flat, ignore_errors=True)
    st.write_block_case(flat, [0.0], n=(NX, NY, 0), d0=D0)
    r = run(["-case", flat, "-what", "particles", "-slice", "z"])
    st.check(r.returncode == 1 and "is 2D; slices are drawn of 3D cases only" in r.stdout,
             f"-slice on a 2D case: exit 1: {r.stdout[-200:]}")
    r = run(["-case", flat, "-what", "particles"])
    st.check(r.returncode == 0 and os.path.isfile(os.path.join(flat, "plots", "p_0.png"))
             and not os.path.exists(os.path.join(flat, "plots", "p_0_3d.png")), "a 2D case: the flat picture only")


def check_against():
    other = os.path.join(WORK, "other3d")
    shutil.rmtree(other, ignore_errors=True)
    st.write_block_case(other, [0.1], d0=D0)
    shutil.rmtree(PLOTS, ignore_errors=True)
    r = run(["-case", CASE, "-against", other, "-time", "0.1", "-what", "particles"])
    ok, what = png_ok("p_0.1_slice_z_vs_other3d.png", 20)
    st.check(r.returncode == 0 and ok, f"-against: slices side by side: {what}")
    st.check(not os.path.exists(os.path.join(PLOTS, "p_0.1_3d.png")), "-against: no perspective view")


def main():
    shutil.rmtree(CASE, ignore_errors=True)
    st.write_block_case(CASE, [0.0, 0.1], n=(NX, NY, NZ), d0=D0)
    check_default_pictures()
    check_in_slab()
    check_chosen_planes()
    check_bad_input()
    check_against()
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
