"""What the Python test scripts share (docs/testing.md): one assertion and summary
style, the case-dictionary edits, copying and running a case, reading and writing particle
files and time directories. Every script of tests/ imports it after putting this
folder on sys.path:

    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
    import shizukutest as st

check() prints `ok   what` or `FAIL what` and records it; summary() prints the last
line `N passed, M failed` and returns the exit status (0 when nothing failed).
VTK and numpy are imported only by the functions that need them, so the scripts
that read no particle files run without them."""
import argparse
import importlib.util
import os
import re
import shutil
import subprocess
import sys
from importlib.machinery import SourceFileLoader

PASSED, FAILED, XFAILED = [], [], []


# --- assertions -------------------------------------------------------------------------

def check(cond, what, xpass=None, xfail=None, quiet=False):
    """One assertion, printed and recorded; returns cond. Given xfail (and xpass), the
    hints printed, it is a strict expected failure: failing prints XFAIL and is not
    counted, passing prints XPASS and counts as a failure, so that the mark is removed
    as soon as the method is fixed. quiet: record without printing (the output of
    what was checked already tells)."""
    if xfail is not None:
        if cond:
            print(f"XPASS {what}: {xpass}")
            FAILED.append(what)
        else:
            print(f"XFAIL {what} [{xfail}]")
            XFAILED.append(what)
        return cond
    if not quiet:
        print(("ok   " if cond else "FAIL ") + what)
    (PASSED if cond else FAILED).append(what)
    return cond


def summary():
    """Print `N passed, M failed`; the exit status: 1 when any check failed."""
    print(f"{len(PASSED)} passed, {len(FAILED)} failed")
    return 1 if FAILED else 0


def finish(ok, what):
    """One check and the summary line of a single-check script, then exit."""
    check(ok, what)
    sys.exit(summary())


# --- files and modules ------------------------------------------------------------------

def write(path, text):
    """Write a text file, making its folder."""
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def load_module(path, name):
    """A Python file (with or without .py) imported as a module."""
    loader = SourceFileLoader(name, path)
    spec = importlib.util.spec_from_loader(name, loader)
    mod = importlib.util.module_from_spec(spec)
    loader.exec_module(mod)
    return mod


def load_compare(path):
    """shizukuCompare (a script without .py) imported as a module, for its dictionary parser
    and its postProcessing reader."""
    return load_module(path, "shizukuCompare")


# --- postProcessing tables -------------------------------------------------------------

def read_table(path):
    """The rows of a postProcessing table as {column: value}, by the names of its
    `# columns:` line (vector columns, written "(x y)", are skipped); the reader is
    utilities/shizukuPost.py's, which shizukuPlot and shizukuCompare use."""
    sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "utilities"))
    import shizukuPost
    names, _, rows = shizukuPost.read_tokens(path)
    return [{k: float(v) for k, v in zip(names, r) if not v.startswith("(")} for r in rows]


# --- case dictionaries ------------------------------------------------------------------

def find_key(text, key):
    """The match of the first top-level `key value;` entry of a dictionary text (outside
    braces and comments; group 1 the value), or None."""
    depth = 0
    pat = re.compile(r"//[^\n]*|/\*.*?\*/|[{}]|(?m:^[ \t]*" + re.escape(key) + r"[ \t]+([^;{}]*);)", re.S)
    for m in pat.finditer(text):
        tok = m.group(0)
        if tok.startswith("//") or tok.startswith("/*"):
            continue
        if tok == "{":
            depth += 1
        elif tok == "}":
            depth -= 1
        elif depth == 0:
            return m
    return None


def with_key(text, key, value, append=False):
    """The text with its top-level `key ...;` entry replaced by `key value;` (appended when
    missing and append is set; else a missing key ends the script with a message)."""
    m = find_key(text, key)
    if m:
        return text[:m.start()] + f"{key} {value};" + text[m.end():]
    if append:
        return text + f"\n{key} {value};\n"
    raise SystemExit(f"no top-level '{key}' in the dictionary")


def get_key(path, key):
    """The value text of the top-level `key ...;` entry of a dictionary file."""
    with open(path) as f:
        m = find_key(f.read(), key)
    if not m:
        raise SystemExit(f"no top-level '{key}' in {path}")
    return m.group(1).strip()


def set_key(path, key, value):
    """Replace the top-level `key ...;` entry of a dictionary file."""
    with open(path) as f:
        text = f.read()
    if not find_key(text, key):
        raise SystemExit(f"no top-level '{key}' in {path}")
    with open(path, "w") as f:
        f.write(with_key(text, key, value))


def replace_once(path, old, new):
    """Replace the one occurrence of `old` in a file by `new` (an error unless it occurs once)."""
    with open(path) as f:
        text = f.read()
    if text.count(old) != 1:
        raise SystemExit(f"{path}: '{old}' does not occur exactly once")
    with open(path, "w") as f:
        f.write(text.replace(old, new))


def _entry_match(text, path, entry, key):
    """The match of `key VALUE` inside the one-level sub-dictionary `entry { ... }`."""
    m = re.search(r"(\b" + re.escape(entry) + r"\s*\{[^}]*\b" + re.escape(key) + r"\s+)([^;\s]+)", text)
    if not m:
        raise SystemExit(f"no '{entry} {{ ... {key} ... }}' in {path}")
    return m


def get_entry_key(path, entry, key):
    """The value text of `key` in the sub-dictionary `entry { ... }` (e.g. a function object's
    writeInterval) of a dictionary file."""
    with open(path) as f:
        return _entry_match(f.read(), path, entry, key).group(2)


def set_entry_key(path, entry, key, value):
    """Replace the value of `key` in the sub-dictionary `entry { ... }` of a dictionary file."""
    with open(path) as f:
        text = f.read()
    m = _entry_match(text, path, entry, key)
    with open(path, "w") as f:
        f.write(text[:m.start(2)] + str(value) + text[m.end(2):])


# --- cases and runs ---------------------------------------------------------------------

def case_arguments(first="case"):
    """The arguments of the scripts that run a case: FIRST WORK --shizuku BIN --compare
    SHIZUKUCOMPARE [--threads N] (default 2); the caller adds its own."""
    ap = argparse.ArgumentParser()
    ap.add_argument(first)
    ap.add_argument("work")
    ap.add_argument("--shizuku", required=True)
    ap.add_argument("--compare", required=True)
    ap.add_argument("--threads", type=int, default=2)
    return ap


def full_size_case(name):
    """The arguments of a tutorial's validation script (case_arguments plus --full), and a
    fresh copy of the tutorial at WORK/<name> (WORK/<name>Full with --full)."""
    ap = case_arguments("tutorial")
    ap.add_argument("--full", action="store_true")
    a = ap.parse_args()
    case = os.path.join(os.path.abspath(a.work), name + ("Full" if a.full else ""))
    copy_case(a.tutorial, case)
    return a, case


def copy_case(src, dst):
    """A fresh copy of a case's system/ and constant/ at dst (emptied first)."""
    shutil.rmtree(dst, ignore_errors=True)
    os.makedirs(dst)
    for name in ("system", "constant"):
        shutil.copytree(os.path.join(src, name), os.path.join(dst, name))


def remove_shifting(case):
    """Switch off the particle shift, ADS and XSPH of a copied case (the bare projection method)."""
    schemes = os.path.join(case, "system", "sphSchemes")
    with open(schemes) as f:
        s = f.read()
    s = re.sub(r"(?s)\nshifting\s*\{.*?\n\}", "\n", s)
    s = re.sub(r"\n\s*(ads|xsph)\s*\{[^}]*\}", "\n", s)
    with open(schemes, "w") as f:
        f.write(s)


def run_solver(shizuku, case, threads):
    """Run the solver on a case, its output in case/log.shizuku; returns the exit status."""
    with open(os.path.join(case, "log.shizuku"), "w") as log:
        return subprocess.run([shizuku, "-case", case, "-threads", str(threads)], stdout=log,
                              stderr=subprocess.STDOUT).returncode


def run_or_fail(shizuku, case, threads, what):
    """run_solver; on a non-zero exit a FAIL line naming `what`, the summary line, and exit 1."""
    rc = run_solver(shizuku, case, threads)
    if rc != 0:
        finish(False, f"{what}: exit status {rc} (log: {case}/log.shizuku)")


# --- particle files and time directories ------------------------------------------------

def particle_file(time_dir):
    """The particle file of a time directory: particles.vtp (a serial run) or particles.pvtp
    (a run on several ranks: one piece per rank, docs/parallel.md 7); None when neither."""
    for name in ("particles.vtp", "particles.pvtp"):
        if os.path.isfile(os.path.join(time_dir, name)):
            return os.path.join(time_dir, name)
    return None


def time_dirs(case):
    """(time, name) of the time directories of a case holding particles, sorted by time."""
    out = []
    for name in os.listdir(case):
        try:
            t = float(name)
        except ValueError:
            continue
        if particle_file(os.path.join(case, name)):
            out.append((t, name))
    return sorted(out)


def read_vtp(path):
    """The particles of a particles.vtp, a particles.pvtp (all its pieces) or a time
    directory holding either, read by VTK: {"position": N x 3, point array name: values,
    "field:" + field array name: values} (numpy copies); None when VTK finds no points."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader, vtkXMLPPolyDataReader

    if os.path.isdir(path):
        path = particle_file(path)
        if path is None:
            return None
    r = vtkXMLPPolyDataReader() if path.endswith(".pvtp") else vtkXMLPolyDataReader()
    r.SetFileName(path)
    r.Update()
    poly = r.GetOutput()
    if poly is None or poly.GetNumberOfPoints() == 0:
        return None
    out = {"position": vtk_to_numpy(poly.GetPoints().GetData()).copy()}
    pd = poly.GetPointData()
    for k in range(pd.GetNumberOfArrays()):
        out[pd.GetArrayName(k)] = vtk_to_numpy(pd.GetArray(k)).copy()
    fd = poly.GetFieldData()
    for k in range(fd.GetNumberOfArrays()):
        a = fd.GetArray(k)
        if a is not None:
            out["field:" + a.GetName()] = vtk_to_numpy(a).copy()
    return out


def write_vtp(path, points, arrays, field_data, raw=False):
    """Write a hand-made particles.vtp (making its folder): points N x 3, one vertex cell
    per particle, point arrays {name: numpy values}, field data {name: float}. raw: raw
    appended data with UInt64 block headers, as Shizuku writes it; else VTK's inline
    binary. Returns True when VTK wrote it."""
    from vtkmodules.util.numpy_support import numpy_to_vtk
    from vtkmodules.vtkCommonCore import vtkDoubleArray, vtkPoints
    from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
    from vtkmodules.vtkIOXML import vtkXMLPolyDataWriter

    poly = vtkPolyData()
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(points, deep=True))
    poly.SetPoints(pts)
    cells = vtkCellArray()
    for i in range(len(points)):
        cells.InsertNextCell(1)
        cells.InsertCellPoint(i)
    poly.SetVerts(cells)
    for name, values in arrays.items():
        a = numpy_to_vtk(values, deep=True)
        a.SetName(name)
        poly.GetPointData().AddArray(a)
    for name, value in field_data.items():
        a = vtkDoubleArray()
        a.SetName(name)
        a.InsertNextValue(value)
        poly.GetFieldData().AddArray(a)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    w = vtkXMLPolyDataWriter()
    w.SetFileName(path)
    w.SetInputData(poly)
    if raw:
        w.SetDataModeToAppended()
        w.EncodeAppendedDataOff()
        w.SetCompressorTypeToNone()
        w.SetHeaderTypeToUInt64()
    else:
        w.SetDataModeToBinary()
    return w.Write() == 1


def write_block_case(case, times, n=(10, 6, 5), d0=0.01, raw=True):
    """A hand-made case of particle files only: at each time a block of nx x ny x nz fluid
    particles at ((i + 1/2) d0, (j + 1/2) d0, (k + 1/2) d0) over a floor of walls one
    particle thick at y = -d0/2, one particle wider than the block on each side
    ((nx + 2) x (nz + 2)); nz = 0 makes it 2D (z = 0, a floor row of nx + 2). Pressure
    hydrostatic times (1 + t) plus 50 Pa per d0 in x, U = (y, 0, -x) times (1 + t). Writes
    <time>/particles.vtp and particles.pvd. Returns the fluid and wall positions of the
    first time (they are the same at every time)."""
    import numpy as np

    nx, ny, nz = n
    dim = 3 if nz > 0 else 2
    g = lambda m, lo=0: (np.arange(lo, m) + 0.5) * d0  # noqa: E731
    zs, wz = (g(nz), g(nz + 1, -1)) if dim == 3 else (np.zeros(1), np.zeros(1))
    fluid = np.array(np.meshgrid(g(nx), g(ny), zs, indexing="ij")).reshape(3, -1).T
    walls = np.array(np.meshgrid(g(nx + 1, -1), [-0.5 * d0], wz, indexing="ij")).reshape(3, -1).T
    pts = np.vstack([fluid, walls])
    kind = np.r_[np.zeros(len(fluid)), np.ones(len(walls))].astype(np.uint8)
    entries = []
    for t in times:
        name = f"{t:g}"
        p = (1000 * 9.81 * (ny * d0 - pts[:, 1]) + 50 * pts[:, 0] / d0) * (1 + t)
        U = np.c_[pts[:, 1], np.zeros(len(pts)), -pts[:, 0]] * (1 + t)
        info = {"spacing": d0, "rho0": 1000.0, "time": t, "dimension": float(dim)}
        if not write_vtp(os.path.join(case, name, "particles.vtp"), pts, {"U": U, "p": p, "type": kind}, info, raw):
            raise RuntimeError(f"{case}/{name}/particles.vtp: VTK did not write it")
        entries.append(f'    <DataSet timestep="{name}" group="" part="0" file="{name}/particles.vtp"/>\n')
    write(os.path.join(case, "particles.pvd"), '<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">'
          "\n  <Collection>\n" + "".join(entries) + "  </Collection>\n</VTKFile>\n")
    return fluid, walls


def png_picture(path):
    """(width, height, number of distinct colours) of a PNG file; None when the file is
    missing or not a PNG."""
    if not os.path.isfile(path):
        return None
    with open(path, "rb") as f:
        if f.read(8) != b"\x89PNG\r\n\x1a\n":
            return None
    import matplotlib.image as mpimg
    import numpy as np

    img = mpimg.imread(path)
    return img.shape[1], img.shape[0], len(np.unique(img.reshape(-1, img.shape[-1]), axis=0))
