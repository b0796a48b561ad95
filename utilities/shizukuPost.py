"""What shizukuPlot and shizukuCompare share in reading a case (docs/design.md 1.3): folder
names that are times, the walk of postProcessing/<name>/<startTime>/<file>, the rule by
which a later start time replaces the rows from its start on, and the header and tokens
of one postProcessing file. Each script turns the tokens into its own numbers:
shizukuPlot forgiving (nan for what is not a number), shizukuCompare strict.

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
