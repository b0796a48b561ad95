#!/usr/bin/python3
"""shizukuPvsm on a hand-made 3D case (docs/postprocessing.md, "shizukuPvsm"): a block of
10 x 6 x 5 fluid particles over a floor of walls at two times, with particles.pvd
(shizukutest.write_block_case).

Without --paraview (no ParaView needed): the state file is XML naming the absolute path
of particles.pvd, at the latest time (or -time firstTime), the fluid (type 0) as
spheres of radius d0/2 coloured by p over the fluid's min and max at that time (or
-range), a colour bar titled with the field and unit, -field U by magnitude and Uy by
component, the walls (type 1 to 3) translucent or hidden (-walls hidden), the camera on
the fluid's centre from the oblique view direction with every particle inside the view
angle; bad input (no particles.pvd, a corrupt one, an unknown field or time, a bad
-range) is exit 1 naming what is wrong, with no file written.

With --paraview: the state written is loaded by ParaView's pvbatch (LoadState) and
rendered off-screen (under xvfb-run when there is no display): the three sources, the
time, the colour range, the fluid and wall counts after the thresholds, and a PNG with
many colours. Exit 77 (skipped) when no pvbatch that imports paraview.simple is found:
$SHIZUKU_PVBATCH, else pvbatch on the PATH.

usage: pvsmSmoke.py SHIZUKUPVSM WORKDIR [--paraview]
"""
import json
import math
import os
import shutil
import subprocess
import sys
import xml.etree.ElementTree as ET

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

PVSM, WORK = sys.argv[1:3]
CASE = os.path.abspath(os.path.join(WORK, "pvsmBlock"))
STATE = os.path.join(CASE, "particles.pvsm")
D0, ELEVATION, AZIMUTH = 0.01, 25.0, 30.0
SKIP = 77


def run(args):
    return subprocess.run([PVSM] + args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)


def expected_p(points, t, ny=6):
    """The pressure write_block_case gives the particles at time t."""
    return (1000 * 9.81 * (ny * D0 - points[:, 1]) + 50 * points[:, 0] / D0) * (1 + t)


class Pvsm:
    """A state file's proxies, found by the name they are registered under."""

    def __init__(self, path):
        self.root = ET.parse(path).getroot()
        self.by_id = {p.get("id"): p for p in self.root.iter("Proxy") if p.get("group")}
        self.names = {(pc.get("name"), it.get("name")): it.get("id")
                      for pc in self.root.iter("ProxyCollection") for it in pc.iter("Item")}

    def values(self, collection, name, prop):
        proxy = self.by_id[self.names[(collection, name)]]
        el = proxy.find(f"Property[@name='{prop}']")
        if el is None:
            return None
        return [e.get("value") for e in el.findall("Element")] + [p.get("value") for p in el.findall("Proxy")]

    def number(self, collection, name, prop, k=0):
        return float(self.values(collection, name, prop)[k])


def near(a, b):
    return abs(a - b) <= 1e-9 * max(1.0, abs(a), abs(b))


def check_default_state(fluid, walls):
    r = run(["-case", CASE])
    st.check(r.returncode == 0 and os.path.isfile(STATE), f"shizukuPvsm -case: exit 0, {STATE}: {r.stdout[-300:]}")
    s = Pvsm(STATE)
    st.check(s.values("sources", "particles.pvd", "FileName") == [os.path.join(CASE, "particles.pvd")],
             "reads the absolute path of particles.pvd")
    st.check(s.values("sources", "fluid", "SelectInputScalars")[4] == "type"
             and [s.number("sources", "fluid", k) for k in ("LowerThreshold", "UpperThreshold")] == [0, 0]
             and [s.number("sources", "walls", k) for k in ("LowerThreshold", "UpperThreshold")] == [1, 3],
             "fluid is type 0, walls type 1 to 3")
    st.check(near(s.number("animation", "AnimationScene1", "AnimationTime"), 0.1)
             and near(s.number("views", "RenderView1", "ViewTime"), 0.1), "opens at the latest time, 0.1")
    p = expected_p(fluid, 0.1)
    rgb = [float(v) for v in s.values("lookup_tables", "p.PVLookupTable", "RGBPoints")]
    st.check(near(rgb[0], p.min()) and near(rgb[-4], p.max()),
             f"colour range = the fluid's p at 0.1: {rgb[0]:g} to {rgb[-4]:g} (fluid {p.min():g} to {p.max():g})")
    st.check(s.values("representations", "fluid", "Representation") == ["Point Gaussian"]
             and near(s.number("representations", "fluid", "GaussianRadius"), 0.5 * D0)
             and s.values("representations", "fluid", "ColorArrayName")[4] == "p",
             "fluid: spheres of radius d0/2 coloured by p")
    st.check(s.values("scalar_bars", "colourBar", "Title") == ["p [Pa]"], "colour bar 'p [Pa]'")
    st.check(s.number("representations", "walls", "Visibility") == 1
             and 0 < s.number("representations", "walls", "Opacity") < 0.5, "walls translucent")
    check_camera(s, fluid, walls)


def check_camera(s, fluid, walls):
    """Focal point on the fluid's centre, the oblique direction, every particle in view."""
    position = np.array([float(v) for v in s.values("views", "RenderView1", "CameraPosition")])
    focal = np.array([float(v) for v in s.values("views", "RenderView1", "CameraFocalPoint")])
    centre = 0.5 * (fluid.min(axis=0) + fluid.max(axis=0))
    e, a = math.radians(ELEVATION), math.radians(AZIMUTH)
    direction = np.array([math.cos(e) * math.sin(a), math.sin(e), math.cos(e) * math.cos(a)])
    axis = (position - focal) / np.linalg.norm(position - focal)
    st.check(np.allclose(focal, centre) and np.allclose(axis, direction),
             f"camera on the fluid's centre {centre.round(4).tolist()}, from {axis.round(3).tolist()}")
    rays = np.vstack([fluid, walls]) - position
    angles = np.degrees(np.arccos(np.clip(rays @ -axis / np.linalg.norm(rays, axis=1), -1, 1)))
    angle = s.number("views", "RenderView1", "CameraViewAngle")
    st.check(angles.max() < 0.5 * angle, f"every particle within the view: {angles.max():.1f} < {angle / 2:g} degrees")


def check_options(fluid):
    out = os.path.join(WORK, "first.pvsm")
    r = run(["-case", CASE, "-time", "firstTime", "-field", "U", "-walls", "hidden", "-output", out])
    s = Pvsm(out) if r.returncode == 0 else None
    speed = np.linalg.norm(np.c_[fluid[:, 1], -fluid[:, 0]], axis=1)
    rgb = [float(v) for v in s.values("lookup_tables", "U.PVLookupTable", "RGBPoints")] if s else [0.0]
    st.check(s is not None and near(s.number("animation", "AnimationScene1", "AnimationTime"), 0)
             and s.values("scalar_bars", "colourBar", "Title") == ["|U| [m/s]"]
             and near(rgb[0], speed.min()) and near(rgb[-4], speed.max())
             and s.number("representations", "walls", "Visibility") == 0,
             f"-time firstTime -field U -walls hidden -output: |U| at 0 from {rgb[0]:g}, walls hidden")
    r = run(["-case", CASE, "-field", "Uy", "-range", "-1", "2", "-output", out])
    s = Pvsm(out) if r.returncode == 0 else None
    st.check(s is not None and s.number("lookup_tables", "U.PVLookupTable", "VectorMode") == 1
             and s.number("lookup_tables", "U.PVLookupTable", "VectorComponent") == 1
             and s.values("lookup_tables", "U.PVLookupTable", "RGBPoints")[0::4] == [
                 repr(-1.0 + f * 3.0) for f in (0.0, 0.111111, 0.365079, 0.492063, 0.619048, 0.873016, 1.0)],
             "-field Uy -range -1 2: component 1, colours spread over -1 to 2")


def check_bad_input():
    empty = os.path.join(WORK, "noSeries")
    shutil.rmtree(empty, ignore_errors=True)
    os.makedirs(empty)
    corrupt = os.path.join(WORK, "corruptSeries")
    shutil.rmtree(corrupt, ignore_errors=True)
    st.write(os.path.join(corrupt, "particles.pvd"), "<VTKFile><Collection><DataSet timestep=")
    for args, message in ((["-case", os.path.join(WORK, "none")], "-case " + os.path.join(WORK, "none") + ": no such folder"),
                          (["-case", empty], f"{empty}/particles.pvd: no such file"),
                          (["-case", corrupt], f"{corrupt}/particles.pvd: not a VTK collection file"),
                          (["-case", CASE, "-field", "nothing"], "no field 'nothing'; fields: U p type"),
                          (["-case", CASE, "-time", "7"], "-time 7: not a time of"),
                          (["-case", CASE, "-range", "1", "nan"], "-range 1 nan: give finite MIN below MAX"),
                          (["-case", CASE, "-walls", "opaque"], "argument -walls/--walls: invalid choice")):
        if os.path.exists(STATE):
            os.remove(STATE)
        r = run(args)
        st.check(r.returncode == 1 and message in r.stdout and not os.path.exists(STATE),
                 f"{' '.join(args[-2:])}: exit 1, '{message}', nothing written: {r.stdout[-200:]}")
    leftovers = [f for f in os.listdir(CASE) if ".tmp-" in f]
    st.check(not leftovers, f"no temporary file left in the case: {leftovers}")


# --- ParaView -----------------------------------------------------------------------------

LOAD_SCRIPT = r'''
import json, sys
from paraview.simple import *
LoadState(sys.argv[1])
view = GetActiveViewOrCreate("RenderView")
lut = GetColorTransferFunction("p")
count = lambda name: FindSource(name).GetDataInformation().GetNumberOfPoints()
SaveScreenshot(sys.argv[2], view, ImageResolution=[800, 600])
print("RESULT " + json.dumps({"sources": sorted(k[0] for k in GetSources()), "time": view.ViewTime,
      "range": [lut.RGBPoints[0], lut.RGBPoints[-4]], "fluid": count("fluid"), "walls": count("walls"),
      "colour": list(GetDisplayProperties(FindSource("fluid"), view).ColorArrayName)}))
'''


def pvbatch_command():
    """The command that runs a pvbatch script, or None when ParaView cannot be run here:
    $SHIZUKU_PVBATCH or pvbatch on the PATH, importing paraview.simple; under xvfb-run
    when there is no display (Debian's ParaView renders through X only)."""
    exe = os.environ.get("SHIZUKU_PVBATCH") or shutil.which("pvbatch")
    if not exe:
        return None, "no pvbatch on the PATH and SHIZUKU_PVBATCH unset"
    cmd = [exe]
    if not os.environ.get("DISPLAY") and shutil.which("xvfb-run"):
        cmd = ["xvfb-run", "-a", exe]
    probe = os.path.join(WORK, "probe.py")
    st.write(probe, "import paraview.simple\nprint('PROBE', paraview.simple.GetParaViewVersion())\n")
    r = subprocess.run(cmd + [probe], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=120)
    if "PROBE" not in r.stdout:
        return None, f"{exe} cannot import paraview.simple: {r.stdout.strip()[-200:]}"
    print(f"ParaView: {exe}, version {r.stdout.split('PROBE', 1)[1].split()[0:2]}")
    return cmd, ""


def check_paraview(fluid, walls):
    cmd, why = pvbatch_command()
    if cmd is None:
        print(f"skipped: {why}")
        return SKIP
    r = run(["-case", CASE])
    st.check(r.returncode == 0, f"shizukuPvsm: exit 0: {r.stdout[-200:]}")
    script, png = os.path.join(WORK, "load.py"), os.path.join(WORK, "pvsm.png")
    st.write(script, LOAD_SCRIPT)
    if os.path.exists(png):
        os.remove(png)
    r = subprocess.run(cmd + [script, STATE, png], stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                       timeout=300)
    line = next((x for x in r.stdout.splitlines() if x.startswith("RESULT ")), None)
    st.check(line is not None, f"pvbatch loads the state: {r.stdout[-400:] if line is None else 'ok'}")
    if line is None:
        return st.summary()
    got = json.loads(line[len("RESULT "):])
    p = expected_p(fluid, 0.1)
    st.check(got["sources"] == ["fluid", "particles.pvd", "walls"], f"sources {got['sources']}")
    st.check(near(got["time"], 0.1) and got["colour"][-1] == "p", f"at t = {got['time']}, coloured by p")
    st.check(near(got["range"][0], p.min()) and near(got["range"][1], p.max()), f"colour range {got['range']}")
    st.check(got["fluid"] == len(fluid) and got["walls"] == len(walls),
             f"thresholds: {got['fluid']} fluid, {got['walls']} walls (expected {len(fluid)}, {len(walls)})")
    pic = st.png_picture(png)
    st.check(pic is not None and pic[2] >= 50, f"rendered {png}: {pic}")
    return st.summary()


def main():
    shutil.rmtree(CASE, ignore_errors=True)
    fluid, walls = st.write_block_case(CASE, [0.0, 0.1], d0=D0)
    if "--paraview" in sys.argv[3:]:
        return check_paraview(fluid, walls)
    check_default_state(fluid, walls)
    check_options(fluid)
    check_bad_input()
    return st.summary()


if __name__ == "__main__":
    sys.exit(main())
