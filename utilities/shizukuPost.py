"""What shizukuPlot and shizukuCompare share in reading a case (docs/design.md 1.3): folder
names that are times, the walk of postProcessing/<name>/<startTime>/<file>, the rule by
which a later start time replaces the rows from its start on, and the header and tokens
of one postProcessing file, and the reader of a particles.vtp (its XML header checked
before VTK reads it). Each script turns the tokens into its own numbers: shizukuPlot
forgiving (nan for what is not a number), shizukuCompare strict.

The scripts find this module next to their own real path, so it goes wherever they go:
the source tree, the build tree, or one bin folder they are copied into side by side."""
import math
import os
import re


class InputError(Exception):
    """Unusable input: the scripts print the message and exit with status 1."""


def parse_time(text):
    """The time a folder name stands for (a finite number), or None."""
    if not re.fullmatch(r"[-+0-9.eE]+", text):
        return None
    try:
        v = float(text)
    except ValueError:
        return None
    return v if math.isfinite(v) else None


def time_dirs(folder, filename=None):
    """(time, name) of the sub-folders of `folder` named as times, sorted; with `filename`
    only those holding that file."""
    out = []
    if os.path.isdir(folder):
        for name in os.listdir(folder):
            t = parse_time(name)
            path = os.path.join(folder, name)
            if t is not None and (os.path.isfile(os.path.join(path, filename)) if filename else os.path.isdir(path)):
                out.append((t, name))
    return sorted(out)


def restart_cut(start):
    """Rows of an earlier start time are kept only below this time: a run restarted at
    `start` writes its own rows from there on."""
    return start - 1e-12 * max(1.0, abs(start))


def pp_files(root):
    """{(name, file): [(startTime, path), ...]} of every table below the postProcessing
    folder `root`, by name, then start time, then file name; histograms (one folder
    deeper) and the particle files a health check writes next to the tables (*.vtp)
    are not tables. An absent root gives none."""
    found = {}
    if not os.path.isdir(root):
        return found
    for name in sorted(os.listdir(root)):
        for start, start_name in time_dirs(os.path.join(root, name)):
            folder = os.path.join(root, name, start_name)
            for f in sorted(os.listdir(folder)):
                p = os.path.join(folder, f)
                if os.path.isfile(p) and not f.endswith(".vtp"):  # healthChecks/<t>/offending.vtp
                    found.setdefault((name, f), []).append((start, p))
    return found


TOKEN = re.compile(r"\([^)]*\)|\S+")


def read_tokens(path):
    """(column names, units or None, rows) of one postProcessing file: `# columns:` and
    `# units:` lines, other `#` lines skipped, each row a list of tokens, a vector
    `(x y z)` one token."""
    names, units, rows = None, None, []
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s:
                continue
            if s.startswith("#"):
                body = s[1:].strip()
                if body.startswith("columns:"):
                    names = body[len("columns:"):].split()
                elif body.startswith("units:"):
                    units = body[len("units:"):].split()
                continue
            rows.append(TOKEN.findall(s))
    if names is None:
        raise InputError(f"{path}: no '# columns:' line")
    return names, units, rows


# --- particle files -----------------------------------------------------------

# The unit of each point array of a particles.vtp (docs/output.md), for colour-bar titles.
UNITS = {"p": "Pa", "U": "m/s", "rhoN": "kg/m^3", "normal": "-", "shift": "m", "type": "-",
         "surface": "-", "id": "-", "densityError": "%"}
# How a 3D case is looked at, by shizukuPlot's perspective picture and shizukuPvsm's
# ParaView camera alike: y up, from VIEW_ELEVATION degrees above the horizontal and from
# the +z side turned VIEW_AZIMUTH degrees towards +x, so that the x-y face (the plane
# of the 2D pictures) is in front with x to the right.
VIEW_ELEVATION, VIEW_AZIMUTH = 25.0, 30.0

VTK_SIZES = {"Int8": 1, "UInt8": 1, "Int16": 2, "UInt16": 2, "Int32": 4, "UInt32": 4, "Int64": 8, "UInt64": 8,
             "Float32": 4, "Float64": 8}
MAX_COUNT = 2 ** 31 - 1


def check_count(path, tag, attrs, key):
    """attrs[key] (if present) as a count 0 <= n < 2^31, else InputError naming the file."""
    text = attrs.get(key)
    if text is None:
        return None
    if not re.fullmatch(r"\+?[0-9]+", text.strip()) or int(text) > MAX_COUNT:
        raise InputError(f'{path}: <{tag}> {key}="{text}" is not a count (an integer from 0 to {MAX_COUNT}): '
                         "the file is corrupt")
    return int(text)


def check_appended_array(path, attrs, data, at, header_size, expected):
    """One raw appended array: inside the file, its byte count (the block header)
    equal to expected tuples x components x type size (expected None: unknown)."""
    name, size = attrs.get("Name", "?"), VTK_SIZES.get(attrs.get("type"))
    if size is None:
        raise InputError(f"{path}: array '{name}': unknown type '{attrs.get('type')}': the file is corrupt")
    if at + header_size > len(data):
        raise InputError(f"{path}: array '{name}' starts past the end of the file (cut short or corrupt)")
    nbytes = int.from_bytes(data[at:at + header_size], "little")
    if at + header_size + nbytes > len(data):
        raise InputError(f"{path}: array '{name}' holds {nbytes} bytes by its header but the file ends "
                         f"{len(data) - at - header_size} bytes after it (cut short or corrupt)")
    components = check_count(path, "DataArray", attrs, "NumberOfComponents") or 1
    if expected is not None and nbytes != expected * components * size:
        raise InputError(f"{path}: array '{name}' holds {nbytes} bytes, but {expected} tuples of {components} x "
                         f"{size} bytes are {expected * components * size}: the file is corrupt")


def check_vtp_header(path):
    """Check a particles.vtp before VTK reads it (VTK crashes on some corrupt
    headers): every count of the XML header is an integer 0 <= n < 2^31, and
    every uncompressed raw appended array lies inside the file with the byte
    count its block header states, equal to its tuples (NumberOfPoints, or
    NumberOfTuples in FieldData) times components times type size.
    InputError names the file."""
    with open(path, "rb") as f:
        data = f.read()
    appended = re.search(rb"<AppendedData[^>]*>", data)
    header = data[:appended.start() if appended else len(data)].decode("utf-8", "replace")
    root = re.search(r"<VTKFile([^>]*)>", header)
    if not root:
        raise InputError(f"{path}: no <VTKFile> element: not a VTK XML file")
    top = dict(re.findall(r'(\w+)="([^"]*)"', root.group(1)))
    header_size = 8 if top.get("header_type", "UInt32") == "UInt64" else 4
    raw = bool(appended) and b'encoding="raw"' in appended.group(0) and "compressor" not in top
    start = data.find(b"_", appended.end()) + 1 if appended else 0
    if raw and start == 0:
        raise InputError(f"{path}: the appended data has no '_' marker: the file is corrupt")
    points, section = 0, ""
    for closing, tag, rest in re.findall(r"<(/?)(\w+)([^>]*)>", header):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', rest))
        if tag == "Piece" and not closing:
            for key in ("NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys"):
                check_count(path, tag, attrs, key)
            points = check_count(path, tag, attrs, "NumberOfPoints") or 0
        elif tag == "DataArray" and not closing:
            tuples = check_count(path, tag, attrs, "NumberOfTuples")
            check_count(path, tag, attrs, "NumberOfComponents")
            offset = check_count(path, tag, attrs, "offset")
            if raw and attrs.get("format") == "appended" and offset is not None:
                expected = tuples if section == "FieldData" else points if section in ("Points", "PointData") else None
                check_appended_array(path, attrs, data, start + offset, header_size, expected)
        elif tag != "DataArray":
            section = "" if closing else tag


def particle_file(time_dir):
    """The particle file of a time directory: particles.vtp (a serial run) or particles.pvtp
    (a run on several ranks, one piece per rank); None when it holds neither."""
    for name in ("particles.vtp", "particles.pvtp"):
        if os.path.isfile(os.path.join(time_dir, name)):
            return os.path.join(time_dir, name)
    return None


def particle_times(case):
    """(time, name) of the time directories of a case that hold particles, sorted."""
    return [(t, n) for t, n in time_dirs(case) if particle_file(os.path.join(case, n))]


def pvtp_pieces(path):
    """The piece files of a particles.pvtp, in order: only particles_0.vtp, particles_1.vtp,
    ... beside it are accepted (the names Shizuku writes), so a hostile Source is never
    opened. InputError names the file."""
    if os.path.getsize(path) > 64 << 20:
        raise InputError(f"{path}: larger than 64 MB, which no header of pieces is")
    with open(path, "rb") as f:
        text = f.read().decode("utf-8", "replace")
    if not re.search(r'<VTKFile[^>]*\btype="PPolyData"', text):
        raise InputError(f"{path}: not a VTKFile of type PPolyData")
    sources = re.findall(r"<Piece\b[^>]*>", text)
    if not sources:
        raise InputError(f"{path}: names no piece")
    out = []
    for k, piece in enumerate(sources):
        m = re.search(r'\bSource="([^"]*)"', piece)
        name = m.group(1) if m else ""
        if name != f"particles_{k}.vtp":
            raise InputError(f"{path}: piece {k} is '{name}', expected 'particles_{k}.vtp'")
        out.append(os.path.join(os.path.dirname(path), name))
    return out


def read_one_vtp(path):
    """read_vtp of one VTK PolyData file (a particles.vtp or one piece)."""
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")
    check_vtp_header(path)
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput()
    if data is None or data.GetPoints() is None:
        raise InputError(f"{path}: no particles (missing or corrupt file)")
    points = vtk_to_numpy(data.GetPoints().GetData()).astype(float)
    fields = {}
    pd = data.GetPointData()
    for k in range(pd.GetNumberOfArrays()):
        fields[pd.GetArrayName(k)] = vtk_to_numpy(pd.GetArray(k)).astype(float)
    info = {}
    fd = data.GetFieldData()
    for k in range(fd.GetNumberOfArrays()):
        a = fd.GetAbstractArray(k)
        if a.GetNumberOfTuples() > 0:
            try:
                info[a.GetName()] = float(a.GetVariantValue(0).ToDouble())
            except Exception:
                pass
    return points, fields, info


def read_vtp(path):
    """(points N x 3, {point array name: values}, {field-data name: first value as float})
    of a particles.vtp, of a particles.pvtp (its pieces joined; the particle counts of the
    field data summed over them) or of a time directory holding either, each file's header
    checked first; InputError naming the file when it is missing, corrupt or holds no
    particle. VTK is imported here only, so that the scripts that read no particle file run
    without it."""
    import numpy as np

    if os.path.isdir(path):
        found = particle_file(path)
        if found is None:
            raise InputError(f"{path}: no particles.vtp or particles.pvtp")
        path = found
    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")
    parts = [read_one_vtp(p) for p in pvtp_pieces(path)] if path.endswith(".pvtp") else [read_one_vtp(path)]
    points = np.concatenate([p[0] for p in parts])
    if len(points) == 0:
        raise InputError(f"{path}: no particles (missing or corrupt file)")
    names = set(parts[0][1])
    for k, p in enumerate(parts):
        if set(p[1]) != names:
            raise InputError(f"{path}: piece {k} holds other point arrays than piece 0")
    fields = {n: np.concatenate([p[1][n] for p in parts]) for n in names}
    info = dict(parts[0][2])
    for key in ("fluidParticles", "wallParticles"):
        if all(key in p[2] for p in parts):
            info[key] = float(sum(p[2][key] for p in parts))
    if all("nextId" in p[2] for p in parts):
        info["nextId"] = max(p[2]["nextId"] for p in parts)
    return points, fields, info


def dimension(info):
    """2 or 3, from the field data of a particles.vtp (read_vtp's third item; 2 without it)."""
    return 3 if info.get("dimension", 2) == 3 else 2
