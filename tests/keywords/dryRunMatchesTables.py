#!/usr/bin/python3
"""Generated keyword tables match -dryRun: for every tutorial (tutorials/*),
`shizuku -dryRun` prints the parameters in effect from the declarations; every
keyword it prints must appear in the committed generated tables of
docs/dictionaries.md under the same scope, and every value it marks
"(default)" must equal the table's default (a "(default, computed)" value
depends on other settings and is only checked for its keyword).

Usage: dryRunMatchesTables.py SHIZUKU
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def committed_tables():
    """scope -> {keyword: default} from the `all` block of docs/dictionaries.md."""
    with open(os.path.join(TOP, "docs", "dictionaries.md")) as f:
        text = f.read()
    m = re.search(r"<!-- keywords:begin all -->\n(.*?)<!-- keywords:end -->", text, re.S)
    if not m:
        sys.exit("docs/dictionaries.md has no <!-- keywords:begin all --> block")
    tables, scope = {}, None
    for line in m.group(1).splitlines():
        if line.startswith("#### "):
            scope = line[5:].strip()
            tables[scope] = {}
        row = re.match(r"\| `([^`]+)` \| (.*?) \| ", line)
        if row and scope:
            tables[scope][row.group(1)] = row.group(2).replace("\\|", "|")
    return tables


def dry_run(shizuku, case):
    with tempfile.TemporaryDirectory() as tmp:
        dst = os.path.join(tmp, os.path.basename(case))
        shutil.copytree(case, dst, ignore=shutil.ignore_patterns("[0-9]*", "postProcessing", "*.pvd", "log.*"))
        run = subprocess.run([shizuku, "-case", dst, "-dryRun"], capture_output=True, text=True, timeout=600)
    if run.returncode != 0:
        sys.exit(f"{case}: -dryRun failed ({run.returncode}):\n{run.stderr}")
    return run.stdout


def main():
    shizuku = sys.argv[1]
    tables = committed_tables()
    failures, checked = [], 0
    for case in sorted(glob.glob(os.path.join(TOP, "tutorials", "*", "system", "controlDict"))):
        case = os.path.dirname(os.path.dirname(case))
        name = os.path.basename(case)
        out = dry_run(shizuku, case)
        if "Parameters in effect" not in out:
            failures.append(f"{name}: -dryRun printed no 'Parameters in effect'")
            continue
        scope = None
        for line in out.split("Parameters in effect", 1)[1].splitlines()[1:]:
            head = re.match(r"  \[(.+?)\]", line)
            if head:
                scope = head.group(1)
                continue
            entry = re.match(r"    (\S+) = (.*?)( \(default\)| \(default, computed\))?$", line)
            if not entry:
                break
            key, value, mark = entry.groups()
            checked += 1
            if scope not in tables or key not in tables[scope]:
                failures.append(f"{name}: [{scope}] {key} is printed by -dryRun but not in the generated tables")
            elif mark == " (default)" and tables[scope][key] != value:
                failures.append(f"{name}: [{scope}] {key}: -dryRun default '{value}', table '{tables[scope][key]}'")
    for f in failures:
        print("FAIL " + f)
    print(f"{checked} parameters checked, {len(failures)} mismatches")
    return 1 if failures or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main())
