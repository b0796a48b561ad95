"""What the post-processing test scripts share: `check` prints ok/FAIL and records a
failure, `write` writes a text file (making its folder), `finish` prints the count and
returns the exit status (non-zero when any check failed)."""
import os

FAILURES = []


def check(cond, what):
    print(("ok   " if cond else "FAIL ") + what)
    if not cond:
        FAILURES.append(what)
    return cond


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def finish():
    print(f"\n{len(FAILURES)} failure(s)")
    return 1 if FAILURES else 0
