#!/usr/bin/python3
"""Resolution study of a regression case: run it at several spacings and tabulate the
worst deviation of every checked quantity (the numbers the case README records and
the tolerances are set from; docs/testing.md).

usage: resolutionStudy.py CASE_SRC WORK_DIR --shizuku BIN --compare SHIZUKUCOMPARE
                          --level D0:DT [--level D0:DT ...] [--threads N] [--tabulate-only]

Each level runs tests/cases/runCase.py with --spacing D0 --deltaT DT into
WORK_DIR/<D0>/ and keeps its JSON; the table printed at the end (markdown) has one row
per quantity and check, one column per level: the worst |run - reference| over the
window (for bounds-only entries, the run value closest to the bound), and the ratio
to the allowed deviation of the current tolerance file in brackets.
"""
import json
import os
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    ap = st.case_arguments()
    ap.add_argument("--level", action="append", required=True, help="D0:DT")
    ap.add_argument("--tabulate-only", action="store_true", help="only read the JSON of earlier runs")
    a = ap.parse_args()
    levels = [lv.split(":") for lv in a.level]
    results = {}
    for d0, dt in levels:
        work = os.path.join(a.work, d0)
        out = os.path.join(work, "results.json")
        if not a.tabulate_only:
            os.makedirs(work, exist_ok=True)
            subprocess.call([sys.executable, os.path.join(HERE, "runCase.py"), a.case, work, "--shizuku", a.shizuku,
                             "--compare", a.compare, "--threads", str(a.threads), "--spacing", d0, "--deltaT", dt,
                             "--json", out])
        if os.path.isfile(out):
            with open(out) as f:
                results[d0] = json.load(f)
    rows = {}
    for d0, checks in results.items():
        for check, res in checks.items():
            for r in res:
                key = (check, r["quantity"])
                value = r["dev"] if r.get("dev") is not None else r["run"]
                rows.setdefault(key, {})[d0] = (value, r["ratio"], r["ok"])
    head = "| check | quantity | " + " | ".join(f"d0 = {d0}, dt = {dt}" for d0, dt in levels) + " |"
    print(head)
    print("|" + "---|" * (2 + len(levels)))
    for (check, q), per in sorted(rows.items()):
        cells = []
        for d0, _ in levels:
            if d0 in per:
                v, ratio, ok = per[d0]
                cells.append(f"{v:.3g} ({ratio:.2f}){'' if ok else ' FAIL'}" if v is not None else "-")
            else:
                cells.append("-")
        print(f"| {check} | {q} | " + " | ".join(cells) + " |")
    return 0


if __name__ == "__main__":
    sys.exit(main())
