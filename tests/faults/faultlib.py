"""Helpers of the fault tests (tests/faults/run-fault-tests): scratch copies
of the small tank case, running the solver in the background, waiting for
log lines, and checking that a case folder holds only complete time
directories (docs/reliability.md)."""
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

import vtp

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import shizukutest as st  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
CRASH = re.compile(r"terminate called|AddressSanitizer|LeakSanitizer|runtime error:|Segmentation fault|"
                   r"core dumped|std::bad_alloc")
TIME_NAME = re.compile(r"^[-+]?[0-9]+(\.[0-9]+)?([eE][-+]?[0-9]+)?$")


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


class Scratch:
    """A temporary folder, removed at the end unless SHIZUKU_KEEP_TEST_CASES is set."""

    def __init__(self, tag):
        self.path = tempfile.mkdtemp(prefix=f"shizuku-faults-{tag}-")

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        if os.environ.get("SHIZUKU_KEEP_TEST_CASES"):
            print(f"  kept {self.path}")
        else:
            subprocess.run(["chattr", "-R", "-i", self.path], capture_output=True)
            shutil.rmtree(self.path, ignore_errors=True)


def set_entries(path, **entries):
    """Replace top-level `keyword value;` entries of a dictionary file (appending new ones)."""
    text = open(path).read()
    for key, value in entries.items():
        text = st.with_key(text, key, value, append=True)
    tmp = path + ".edit"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)  # as editors and sed -i do: a new file under the old name


def make_case(root, name="case", base="smallTank", **control):
    """A copy of tests/faults/<base> with controlDict entries replaced."""
    case = os.path.join(root, name)
    shutil.copytree(os.path.join(HERE, base), case)
    if control:
        set_entries(os.path.join(case, "system", "controlDict"), **control)
    return case


class Run:
    """The solver running in the background, its output in files."""

    def __init__(self, shizuku, case, extra=(), **popen):
        self.case = case
        self.out_path = case + ".stdout"
        self.err_path = case + ".stderr"
        self.out = open(self.out_path, "w")
        self.err = open(self.err_path, "w")
        env = dict(os.environ, OMP_NUM_THREADS="1")
        self.proc = subprocess.Popen([shizuku, "-case", case, "-threads", "1", *extra], stdout=self.out,
                                     stderr=self.err, env=env, **popen)

    def wait(self, timeout=120):
        try:
            rc = self.proc.wait(timeout)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()
            raise Failure(f"shizuku did not finish in {timeout} s")
        self.out.close()
        self.err.close()
        return rc

    def stdout(self):
        if not self.out.closed:
            self.out.flush()
        return open(self.out_path, errors="replace").read()

    def stderr(self):
        if not self.err.closed:
            self.err.flush()
        return open(self.err_path, errors="replace").read()

    def wait_for(self, regex, timeout=60):
        """Wait until standard output matches regex; returns the match."""
        end = time.time() + timeout
        while time.time() < end:
            m = re.search(regex, self.stdout())
            if m:
                return m
            if self.proc.poll() is not None:
                m = re.search(regex, self.stdout())
                if m:
                    return m
                raise Failure(f"shizuku ended (status {self.proc.returncode}) before printing /{regex}/:\n"
                              + self.stderr())
            time.sleep(0.02)
        raise Failure(f"no /{regex}/ in the log after {timeout} s")

    def signal(self, sig):
        self.proc.send_signal(sig)


def run(shizuku, case, timeout=120, extra=(), **popen):
    r = Run(shizuku, case, extra, **popen)
    rc = r.wait(timeout)
    return rc, r.stdout(), r.stderr()


def check_no_crash(rc, out, err):
    check(rc >= 0, f"shizuku was killed by signal {-rc}\n{err}")
    m = CRASH.search(out + err)
    check(not m, f"crash text in the output: '{m.group(0) if m else ''}'\n{err}")


def read_time_file(path):
    """The entries of <time>/uniform/time as strings."""
    out = {}
    for line in open(path):
        m = re.match(r"^(\w+)\s+(.*?);", line)
        if m:
            out[m.group(1)] = m.group(2).strip('"')
    return out


def time_directories(case):
    """Time directories the solver would list (TimeDirectory.hpp), sorted by time."""
    out = []
    for name in os.listdir(case):
        d = os.path.join(case, name)
        if TIME_NAME.match(name) and os.path.isdir(d) and os.path.isfile(os.path.join(d, "particles.vtp")) \
                and os.path.isfile(os.path.join(d, "uniform", "time")):
            out.append((float(name), name))
    return sorted(out)


def check_complete(case):
    """Every folder with a time name is a complete, readable time directory
    whose uniform/time agrees with its name, and particles.pvd lists only
    those. Returns (list of time directories, leftover *.tmp-* folders)."""
    names = [n for n in os.listdir(case) if TIME_NAME.match(n) and os.path.isdir(os.path.join(case, n))]
    for name in names:
        d = os.path.join(case, name)
        try:
            fields = vtp.read_vtp(os.path.join(d, "particles.vtp"))
        except (OSError, ValueError) as e:
            raise Failure(f"half-written time directory {d}: {e}")
        t = read_time_file(os.path.join(d, "uniform", "time"))
        check("value" in t and abs(float(t["value"]) - float(name)) <= 1e-12 * max(1, abs(float(name))),
              f"{d}/uniform/time does not hold the time {name}: {t}")
        check(abs(fields["time"][0][0] - float(name)) <= 1e-12 * max(1, abs(float(name))),
              f"{d}/particles.vtp holds time {fields['time'][0][0]}, not {name}")
        for key in ("position", "U", "p"):
            check(all(all(v == v and abs(v) < float("inf") for v in row) for row in fields[key]),
                  f"{d}/particles.vtp: non-finite {key}")
    pvd = os.path.join(case, "particles.pvd")
    if os.path.exists(pvd):
        text = open(pvd).read()
        check(text.rstrip().endswith("</VTKFile>"), f"{pvd} is cut short")
        for f in re.findall(r'file="([^"]+)"', text):
            check(os.path.dirname(f) in names, f"{pvd} lists {f}, which is not a complete time directory")
    leftovers = [n for n in os.listdir(case) if ".tmp-" in n]
    return time_directories(case), leftovers


def snapshot(root):
    """path -> (content bytes hash, mtime) of every file below root."""
    import hashlib
    out = {}
    for dirpath, _, filenames in os.walk(root):
        for f in filenames:
            p = os.path.join(dirpath, f)
            with open(p, "rb") as fh:
                out[os.path.relpath(p, root)] = (hashlib.sha256(fh.read()).hexdigest(), os.stat(p).st_mtime_ns)
    return out


def compare_states(a_path, b_path, what):
    """Positions, velocities and pressures of two particles.vtp files, by
    particle id. A restart reads the state back bit for bit; the runs then
    differ only by the round-off of time sums (measured: 1e-16 m, 1.4e-15 m/s,
    1.5e-11 Pa after 50 steps of the small tank), so 1e-9 of the field's scale
    is far above round-off and far below any lost or repeated step."""
    a, b = vtp.read_vtp(a_path), vtp.read_vtp(b_path)
    check(sorted(i[0] for i in a["id"]) == sorted(i[0] for i in b["id"]), f"{what}: different particle ids")
    for field in ("position", "U", "p"):
        fa, fb = vtp.by_id(a, field), vtp.by_id(b, field)
        scale = max(max(abs(x) for x in v) for v in fa.values()) or 1.0
        worst = max(max(abs(x - y) for x, y in zip(fa[i], fb[i])) for i in fa)
        check(worst <= 1e-9 * scale, f"{what}: {field} differs by {worst:.3g} (scale {scale:.3g})")


def check_same_bytes(ref_case, case, name, what):
    """<name>/particles.vtp of two cases byte for byte (a restart continues bit for bit)."""
    a = open(os.path.join(ref_case, name, "particles.vtp"), "rb").read()
    b = open(os.path.join(case, name, "particles.vtp"), "rb").read()
    if a != b:
        compare_states(os.path.join(ref_case, name, "particles.vtp"), os.path.join(case, name, "particles.vtp"), what)
    check(a == b, f"{what}: {name}/particles.vtp differs from the uninterrupted run's (within 1e-9 of the scale)")


def pid_alive(pid):
    try:
        os.kill(pid, 0)
        return True
    except OSError:
        return False


SIGNAL_NAMES = {signal.SIGTERM: "SIGTERM", signal.SIGINT: "SIGINT", signal.SIGHUP: "SIGHUP"}
