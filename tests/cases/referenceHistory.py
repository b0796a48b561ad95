"""The reference histories of the `resolution` checks (README.md, "Layout of a case
folder"): a case's makeReference.py reads a fine run of its resolution study with these
and stores one history in <case>/reference/, its header naming the spacing and time step
of that run.
"""
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "utilities"))
import shizukuPost  # noqa: E402


def read_setting(case, dictionary, key):
    """The number given for `key` in CASE/system/DICTIONARY (e.g. spacing, deltaT)."""
    with open(os.path.join(case, "system", dictionary)) as f:
        return float(re.search(rf"(?m)^\s*{key}\s+([^;]+);", f.read()).group(1))


def read_rows(case, obj, name):
    """The rows of CASE/postProcessing/OBJ/0/NAME as token lists (a vector "(x y)" one
    token), read by utilities/shizukuPost.read_tokens."""
    return shizukuPost.read_tokens(os.path.join(case, "postProcessing", obj, "0", name))[2]


def write_history(case_folder, name, header, rows):
    """Write rows (t, value) to CASE_FOLDER/reference/NAME under the '# ' header lines."""
    out = os.path.join(case_folder, "reference", name)
    os.makedirs(os.path.dirname(out), exist_ok=True)
    with open(out, "w") as f:
        f.writelines(f"# {line}\n" for line in header)
        for t, value in rows:
            f.write(f"{t!r} {value!r}\n")
    return os.path.relpath(out, case_folder)
