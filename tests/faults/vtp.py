"""Reader for the particles.vtp files Shizuku writes (VTK XML PolyData with
raw appended data and UInt64 block headers, docs/design.md 1.3), enough for the
fault tests to check that a file is complete and to compare fields.

read_vtp(path) -> dict name -> list of tuples (one tuple per point or per
field-data tuple); raises ValueError naming the file when the file is cut
short or malformed."""
import re
import struct

_TYPES = {"Float64": ("d", 8), "Float32": ("f", 4), "Int64": ("q", 8), "Int32": ("i", 4),
          "UInt8": ("B", 1), "Int8": ("b", 1), "UInt64": ("Q", 8), "UInt32": ("I", 4)}


def _layout(path):
    """(file bytes, {name: (type code, size, components, data offset, count)})."""
    with open(path, "rb") as f:
        data = f.read()
    marker = b'<AppendedData encoding="raw">'
    at = data.find(marker)
    if at < 0:
        raise ValueError(f"{path}: no raw appended data section")
    start = data.find(b"_", at + len(marker))
    if start < 0:
        raise ValueError(f"{path}: appended data has no '_' marker")
    start += 1
    if not data.rstrip().endswith(b"</VTKFile>"):
        raise ValueError(f"{path}: file does not end with </VTKFile> (cut short)")
    header = data[:at].decode("utf-8")
    if 'header_type="UInt64"' not in header:
        raise ValueError(f"{path}: expected header_type UInt64")
    fields = {}
    for m in re.finditer(r"<DataArray ([^>]*)/?>", header):
        attrs = dict(re.findall(r'(\w+)="([^"]*)"', m.group(1)))
        name = attrs.get("Name")
        if not name or attrs.get("format") != "appended" or name in ("connectivity", "offsets"):
            continue
        code, size = _TYPES[attrs["type"]]
        ncomp = int(attrs.get("NumberOfComponents", "1"))
        off = start + int(attrs["offset"])
        if off + 8 > len(data):
            raise ValueError(f"{path}: array {name} starts past the end of the file")
        (nbytes,) = struct.unpack_from("<Q", data, off)
        if off + 8 + nbytes > len(data) or nbytes % (size * ncomp):
            raise ValueError(f"{path}: array {name} is cut short")
        fields[name] = (code, size, ncomp, off + 8, nbytes // size)
    if "position" not in fields:
        raise ValueError(f"{path}: no position array")
    return data, fields


def read_vtp(path):
    data, layout = _layout(path)
    fields = {}
    for name, (code, size, ncomp, off, n) in layout.items():
        values = struct.unpack_from("<%d%s" % (n, code), data, off)
        fields[name] = [tuple(values[i:i + ncomp]) for i in range(0, n, ncomp)]
    return fields


def poke(path, name, index_of, component, value):
    """Overwrite one number of a Float64 array in place: tuple index_of(ids)
    (ids: the particle ids in file order), component `component`."""
    data, layout = _layout(path)
    code, size, ncomp, off, n = layout[name]
    if code != "d":
        raise ValueError(f"{path}: {name} is not Float64")
    ids = [i[0] for i in read_vtp(path)["id"]]
    at = off + (index_of(ids) * ncomp + component) * size
    with open(path, "r+b") as f:
        f.seek(at)
        f.write(struct.pack("<d", value))


def by_id(fields, name):
    """Field `name` as a dict particle id -> tuple."""
    return {int(i[0]): v for i, v in zip(fields["id"], fields[name])}
