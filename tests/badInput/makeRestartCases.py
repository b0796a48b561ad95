#!/usr/bin/python3
"""Regenerate the damaged restart files of the bad-input corpus and the seed
corpus of fuzz/fuzz_restart.cpp (docs/reliability.md, "Restart files are
validated before they are read").

    tests/badInput/makeRestartCases.py build/solver/shizuku

Runs a tiny tank (4 fluid and 8 wall particles, the base case's spacing) for
two steps, takes its 0.002/ (particles.vtp and uniform/time), rewrites the vtp
with a compact header (same arrays, no RangeMin/RangeMax or padding, so the
files stay a few KB) and writes one damaged copy per case below into
tests/badInput/<case>/<time>/, plus fuzz/corpus/restart/<name> (vtp bytes,
the separator line, uniform/time text). Each case's `expect` is kept by hand.
"""
import math
import os
import re
import shutil
import struct
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
SEPARATOR = b"\n--- uniform/time ---\n"  # fuzz/fuzz_restart.cpp splits its input here
SIZES = {"Float64": ("d", 8), "Int64": ("q", 8), "UInt8": ("B", 1)}

TINY = """spacing 0.01;
regions
{
    water { type fluid; shape box; min (0 0); max (0.02 0.02); }
    tank  { type wall;  shape box; min (0 0); max (0.02 0.03); layers 1; open (top); }
}
"""


class Vtp:
    """A particles.vtp as Shizuku writes it: piece counts and the arrays in
    file order, each [section, name, type, components, list of values]."""

    def __init__(self, data):
        marker = b'<AppendedData encoding="raw">'
        at = data.index(marker)
        start = data.index(b"_", at) + 1
        header = data[:at].decode()
        self.points = int(re.search(r'NumberOfPoints="(\d+)"', header).group(1))
        self.arrays = []
        section = None
        for m in re.finditer(r"<(/?)(\w+)([^>]*?)/?>", header):
            closing, tag, attrs = m.groups()
            if tag != "DataArray":
                section = None if closing else tag
                continue
            a = dict(re.findall(r'(\w+)="([^"]*)"', attrs))
            code, size = SIZES[a["type"]]
            off = start + int(a["offset"])
            (nbytes,) = struct.unpack_from("<Q", data, off)
            values = list(struct.unpack_from("<%d%s" % (nbytes // size, code), data, off + 8))
            self.arrays.append([section, a["Name"], a["type"], int(a.get("NumberOfComponents", "1")), values])

    def get(self, name):
        return next(a for a in self.arrays if a[1] == name)

    def bytes(self, points=None, verts=None):
        """The file, with a compact header; points/verts override the counts written in <Piece>."""
        points = self.points if points is None else points
        verts = self.points if verts is None else verts
        out = ['<VTKFile type="PolyData" version="1.0" byte_order="LittleEndian" header_type="UInt64">',
               "<PolyData>"]
        blocks = b""
        sections = ["FieldData", "Piece", "PointData", "CellData", "Points", "Verts", "Lines", "Strips", "Polys"]
        for s in sections:
            if s == "Piece":
                out.append(f'<Piece NumberOfPoints="{points}" NumberOfVerts="{verts}" NumberOfLines="0" '
                           f'NumberOfStrips="0" NumberOfPolys="0">')
                continue
            out.append(f"<{s}>")
            for section, name, typ, comps, values in self.arrays:
                if section != s:
                    continue
                tuples = f' NumberOfTuples="{len(values) // comps}"' if s == "FieldData" else ""
                out.append(f'<DataArray type="{typ}" Name="{name}" NumberOfComponents="{comps}"{tuples} '
                           f'format="appended" offset="{len(blocks)}"/>')
                payload = struct.pack("<%d%s" % (len(values), SIZES[typ][0]), *values)
                blocks += struct.pack("<Q", len(payload)) + payload
            out.append(f"</{s}>")
        out += ["</Piece>", "</PolyData>", '<AppendedData encoding="raw">']
        return ("\n".join(out) + "\n_").encode() + blocks + b"\n</AppendedData>\n</VTKFile>\n"


def run_tiny(shizuku, tmp):
    case = os.path.join(tmp, "tiny")
    shutil.copytree(os.path.join(HERE, "base"), case)
    with open(os.path.join(case, "system", "particlesDict"), "w") as f:
        f.write(TINY)
    r = subprocess.run([shizuku, "-case", case], capture_output=True, text=True, env=dict(os.environ, OMP_NUM_THREADS="1"))
    if r.returncode != 0:
        sys.exit("the tiny case failed:\n" + r.stderr)
    with open(os.path.join(case, "0.002", "particles.vtp"), "rb") as f:
        vtp = Vtp(f.read())
    with open(os.path.join(case, "0.002", "uniform", "time")) as f:
        time = f.read()
    return vtp, time


def set_key(text, key, value):
    return re.sub(r"^(%s\s+)[^;]*;" % key, lambda m: m.group(1) + value + ";", text, count=1, flags=re.M)


def damaged(vtp, time):
    """case name -> (time folder, vtp bytes, uniform/time text)."""
    def change(edit):
        import copy
        v = copy.deepcopy(vtp)
        edit(v)
        return v.bytes()
    good = vtp.bytes()
    n = vtp.points
    cases = {  # name: (what is broken, time folder, vtp bytes, uniform/time text)
        "restartNegativePoints": ("<Piece NumberOfPoints=\"-5\">", "0.002", vtp.bytes(points=-5), time),
        "restartPointsCut": ("NumberOfPoints (and NumberOfVerts) 4 less than the data holds", "0.002",
                             vtp.bytes(points=n - 4, verts=n - 4), time),
        "restartTypeSeven": ("point 5 has type byte 7", "0.002", change(lambda v: v.get("type")[4].__setitem__(5, 7)), time),
        "restartTimeNan": ("uniform/time: value nan", "0.002", good, set_key(time, "value", "nan")),
        "restartNanPosition": ("point 2 has y = nan", "0.002",
                               change(lambda v: v.get("position")[4].__setitem__(3 * 2 + 1, math.nan)), time),
        "restartInfPressure": ("point 6 has p = -inf", "0.002", change(lambda v: v.get("p")[4].__setitem__(6, -math.inf)), time),
        "restartDuplicateId": ("point 7 has the id of point 2", "0.002",
                               change(lambda v: v.get("id")[4].__setitem__(7, v.get("id")[4][2])), time),
        "restartHugeId": ("point 3 has id 2^40", "0.002", change(lambda v: v.get("id")[4].__setitem__(3, 1 << 40)), time),
        "restartTimeDisagrees": ("the vtp's field data time is 0.0021, uniform/time says 0.002", "0.002",
                                 change(lambda v: v.get("time")[4].__setitem__(0, 0.0021)), time),
        "restartNegativeIndex": ("uniform/time: index -2", "0.002", good, set_key(time, "index", "-2")),
        "restartBadDeltaT": ("uniform/time: deltaT -0.001", "0.002", good, set_key(time, "deltaT", "-0.001")),
        "restartWrongFolder": ("folder 5/ holds time 0.002", "5", good, time),
    }

    def drop_wall_particles(v):  # a consistent file that has lost particles: the stated counts catch it
        keep = [i for i, t in enumerate(v.get("type")[4]) if t == 0 or i % 2]
        for a in v.arrays:
            if a[0] in ("PointData", "Points"):
                a[4] = [x for i in keep for x in a[4][i * a[3]:(i + 1) * a[3]]]
        v.get("connectivity")[4] = list(range(len(keep)))
        v.get("offsets")[4] = list(range(1, len(keep) + 1))
        v.points = len(keep)
    cases["restartParticlesLost"] = ("half the wall particles removed, the file otherwise consistent", "0.002",
                                     change(drop_wall_particles), time)
    return good, cases


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with tempfile.TemporaryDirectory() as tmp:
        vtp, time = run_tiny(os.path.abspath(sys.argv[1]), tmp)
    good, cases = damaged(vtp, time)
    corpus = os.path.join(ROOT, "fuzz", "corpus", "restart")
    os.makedirs(corpus, exist_ok=True)
    with open(os.path.join(corpus, "valid"), "wb") as f:
        f.write(good + SEPARATOR + time.encode())
    for name, (what, folder, data, text) in cases.items():
        d = os.path.join(HERE, name)
        for old in os.listdir(d) if os.path.isdir(d) else []:
            if old not in ("expect", "args", "remove"):
                shutil.rmtree(os.path.join(d, old))
        os.makedirs(os.path.join(d, folder, "uniform"), exist_ok=True)
        with open(os.path.join(d, folder, "particles.vtp"), "wb") as f:
            f.write(data)
        with open(os.path.join(d, folder, "uniform", "time"), "w") as f:
            f.write(text)
        with open(os.path.join(d, "README"), "w") as f:
            f.write(f"A damaged restart ({folder}/): {what}. Made by ../makeRestartCases.py.\n")
        with open(os.path.join(corpus, name), "wb") as f:
            f.write(data + SEPARATOR + text.encode())
        print(f"{name}: {folder}/particles.vtp {len(data)} bytes")


if __name__ == "__main__":
    main()
