#!/usr/bin/env python3
"""Size limits of the C++ sources (docs/architecture.md, "Rules"): no function longer than
80 lines and no class longer than 400 lines, comments and blank lines excluded.

  checkSizes.py REPO_ROOT [-functions 80] [-classes 400] [-report]

A light brace scanner, not a C++ parser: comments, strings and preprocessor lines are
blanked, then every brace block is classified by the text before its `{`: `class X`/
`struct X` is a class (its own lines, nested functions included), a `)` (optionally
followed by const, override, noexcept, an initialiser list ...) is a function; namespaces,
lambdas inside a function and control blocks count toward their function. A class's
member functions defined in a .cpp count toward the class by their qualified name
(`Simulation<D>::run`). Exit 1 listing every piece over its limit.
"""
import argparse, os, re, subprocess, sys
from collections import defaultdict


def strip(text):
    """Blank comments, string and character literals and preprocessor lines, keep newlines."""
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            j = text.find("\n", i)
            j = n if j < 0 else j
            i = j
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            out.append("\n" * text.count("\n", i, j))
            i = j
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == "\\" else 1
            out.append(c + c)
            i = j + 1
        elif c == "#" and (i == 0 or text[i - 1] == "\n"):
            j = text.find("\n", i)
            while j > 0 and text[j - 1] == "\\":
                j = text.find("\n", j + 1)
            j = n if j < 0 else j
            i = j
        else:
            out.append(c)
            i += 1
    return "".join(out)


def code_lines(text, a, b):
    return sum(1 for line in text[a:b].split("\n") if line.strip())


CLASS = re.compile(r"\b(class|struct)\s+([A-Za-z_]\w*)[^;{}()]*$")
FUNC = re.compile(r"\)\s*(const)?\s*(noexcept)?\s*(override|final)?\s*(->\s*[\w:<>]+)?\s*(:[^;{}]*)?$", re.S)
QUAL = re.compile(r"([A-Za-z_]\w*)(<[^<>]*>)?::~?[A-Za-z_]\w*\s*\([^;{}]*$", re.S)


def scan(path, text, limits, report, classes):
    s = strip(text)
    stack = []  # (kind, name, start)
    problems = []
    for m in re.finditer(r"[{}]", s):
        pos = m.start()
        if m.group() == "{":
            head = s[max(0, pos - 400):pos]
            head = head[max(head.rfind(";"), head.rfind("}"), head.rfind("{")) + 1:]
            kind, name = "block", ""
            inside_function = any(k == "function" for k, _, _ in stack)
            cm = CLASS.search(head)
            if cm and not inside_function and "(" not in head.split(cm.group(2), 1)[-1]:
                kind, name = "class", cm.group(2)
            elif FUNC.search(head.rstrip()) and not inside_function:
                kind = "function"
                fm = re.search(r"([~\w:<>]+)\s*\([^()]*(\([^()]*\)[^()]*)*\)[^()]*$", head, re.S)
                name = fm.group(1) if fm else "?"
            stack.append((kind, name, pos))
        elif stack:
            kind, name, start = stack.pop()
            n = code_lines(s, start, pos)
            line = s.count("\n", 0, start) + 1
            if kind == "class":
                classes[name] += n
                report.append((n, "class", name, "%s:%d" % (path, line)))
            elif kind == "function":
                q = QUAL.search(s[max(0, start - 400):start])
                if q and not any(k == "class" for k, _, _ in stack):
                    classes[q.group(1)] += n
                report.append((n, "function", name, "%s:%d" % (path, line)))
                if n > limits["function"]:
                    problems.append("%s:%d: function %s has %d lines (limit %d)" % (path, line, name, n, limits["function"]))
    return problems


def self_test():
    """Plant a function of 81 lines, one of 80 and a class of 401 lines: exactly two reports."""
    import tempfile
    body = lambda n: "".join("  x += %d;\n" % k for k in range(n))
    src = ("// header comment\nnamespace a {\nint f81() {\n  int x = 0;\n" + body(78) + "  return x;\n}\n"
           "int f80() {\n  int x = 0;\n" + body(77) + "  return x;\n}\n"
           "class Big {\n public:\n" + "".join("  int m%d;\n" % k for k in range(399)) + "};\n}\n")
    with tempfile.TemporaryDirectory() as d:
        open(os.path.join(d, "a.cpp"), "w").write(src)
        report, classes = [], defaultdict(int)
        problems = scan("a.cpp", src, {"function": 80, "class": 400}, report, classes)
        problems += ["class %s" % k for k, n in classes.items() if n > 400]
    ok = len(problems) == 2 and "f81" in problems[0] and "Big" in problems[1]
    print("\n".join(problems))
    print("checkSizes self-test: %s" % ("passed" if ok else "FAILED"))
    return 0 if ok else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    ap = argparse.ArgumentParser()
    ap.add_argument("root")
    ap.add_argument("-functions", type=int, default=80)
    ap.add_argument("-classes", type=int, default=400)
    ap.add_argument("-report", action="store_true")
    a = ap.parse_args()
    files = subprocess.run(["git", "-C", a.root, "ls-files", "*.cpp", "*.hpp"], stdout=subprocess.PIPE,
                           text=True).stdout.split()
    if not files:
        files = [os.path.relpath(os.path.join(d, f), a.root) for d, _, fs in os.walk(a.root) for f in fs
                 if f.endswith((".cpp", ".hpp")) and "/build" not in d]
    limits = {"function": a.functions, "class": a.classes}
    report, problems, classes = [], [], defaultdict(int)
    for f in files:
        if f.startswith(("tests/", "fuzz/")):
            continue  # test programs are lists of cases, not classes and functions to keep small
        problems += scan(f, open(os.path.join(a.root, f), errors="replace").read(), limits, report, classes)
    for name, n in sorted(classes.items(), key=lambda kv: -kv[1]):
        if n > a.classes:
            problems.append("class %s has %d lines in all its files (limit %d)" % (name, n, a.classes))
    if a.report:
        for n, kind, name, where in sorted(report, reverse=True)[:25]:
            print("%5d  %-8s %-40s %s" % (n, kind, name, where))
        for name, n in sorted(classes.items(), key=lambda kv: -kv[1])[:10]:
            print("%5d  class total %s" % (n, name))
    for p in problems:
        print(p)
    print("checkSizes: %d C++ files, %d over a limit" % (len(files), len(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
