#!/usr/bin/env python3
"""Checks that the repository explains itself: every reference in it resolves inside it.

Usage: checkReferences.py REPO_ROOT      scan the repository (tracked files: `git ls-files`;
                                          without git, every file under REPO_ROOT)
       checkReferences.py --self-test    plant each kind of bad reference in a scratch tree
                                          and check that each one is reported

Reported, as file:line: message, with exit status 1:
  (a) a reference to the project's shared notes outside the repository (the parent folder's
      `shared` directory), to an absolute path of the machine's work area, or to the notes'
      check scripts (a `verify` folder the repository does not have);
  (b) a citation `docs/method.md N[.M]` / `method.md N[.M]` or `docs/design.md N[.M]` /
      `design.md N[.M]` / `design.md part N` whose section has no heading in that document
      (headings `## 4. Title`, `### 4.2 Title`, `## Part 2. Title`); a list such as
      `method.md 8.3, 14.5` or `method.md 5.1-5.3` is checked number by number;
      and any mention of the old notes outside the repository, `methods`+`.md` or
      `methods` followed by a section number (cite docs/method.md N instead);
  (c) a relative link `[text](target)` in a Markdown file whose target is not a tracked file
      or folder, or whose `#anchor` names no heading of the target Markdown file.
Exit status 0 when every reference resolves. Python 3 standard library only.
"""
import os
import re
import subprocess
import sys
import tempfile

# Built from pieces so that this file does not report itself.
SHARED = ".." + "/shared"
WORK_AREA = "/" + "work" + "/"
OUTSIDE = re.compile(re.escape(SHARED) + r"\b|(?<![\w.~-])" + re.escape(WORK_AREA) + r"\S*")
# The shared notes' check scripts and outputs (not in the repository; cite the repository's tests).
NOTES_SCRIPTS = re.compile(r"(?<![\w./-])" + "veri" + r"fy/[\w.-]+")

NUM = r"\d+(?:\.\d+)?"
NUM_LIST = NUM + r"(?:\s*(?:,|-|–|and|&)\s*" + NUM + r")*"
CITE = re.compile(r"(?<![\w/.-])(?:docs/)?(method|design)\.md\s*(?:sections?\s+|§\s*)?(part\s+)?(" + NUM_LIST + r")",
                  re.IGNORECASE)
OLD_NAME = "methods" + ".md"
OLD_CITE = re.compile(r"(?<![\w-])" + re.escape(OLD_NAME) + r"\b")
OLD_SHORT = re.compile(r"(?<![\w./-])methods (" + NUM_LIST + r")")
HEADING = re.compile(r"^(#{1,6})\s+(.*?)\s*#*\s*$")
SECTION = re.compile(r"^(part\s+)?(\d+(?:\.\d+)*)\.?(?:\s|$)", re.IGNORECASE)
LINK = re.compile(r"!?\[(?:[^\]\[]|\[[^\]]*\])*\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
FENCE = re.compile(r"^\s*(```|~~~)")


def tracked_files(root):
    """The repository's text files; fuzzing corpora are inputs, not documentation."""
    return [f for f in all_files(root) if not f.startswith("fuzz/corpus/")]


def all_files(root):
    try:
        out = subprocess.run(["git", "-C", root, "ls-files", "-z"], capture_output=True, check=True).stdout
        files = [f for f in out.decode("utf-8", "replace").split("\0") if f]
        if files:
            return files
    except (OSError, subprocess.CalledProcessError):
        pass
    files = []
    for d, dirs, names in os.walk(root):
        dirs[:] = [x for x in dirs if x not in (".git", "build") and not x.startswith("build-")]
        for n in names:
            files.append(os.path.relpath(os.path.join(d, n), root).replace(os.sep, "/"))
    return sorted(files)


def read_text(path):
    try:
        with open(path, "rb") as f:
            data = f.read()
    except OSError:
        return None
    if b"\0" in data:
        return None
    return data.decode("utf-8", "replace")


def slug(title):
    """GitHub's anchor for a Markdown heading."""
    t = re.sub(r"<[^>]+>", "", title).strip().lower()
    t = re.sub(r"\[([^\]]*)\]\([^)]*\)", r"\1", t)
    t = re.sub(r"[^\w\- ]", "", t)
    return t.replace(" ", "-")


def headings(text):
    """(section numbers, anchors) of a Markdown text; fenced blocks are skipped."""
    sections, anchors, fenced, seen = set(), set(), False, {}
    for line in text.splitlines():
        if FENCE.match(line):
            fenced = not fenced
            continue
        m = None if fenced else HEADING.match(line)
        if not m:
            continue
        title = m.group(2)
        s = SECTION.match(title.replace("`", ""))
        if s:
            sections.add(("part " if s.group(1) else "") + s.group(2))
        a = slug(title)
        n = seen.get(a, 0)
        seen[a] = n + 1
        anchors.add(a if n == 0 else "%s-%d" % (a, n))
    return sections, anchors


def expand(numbers):
    return [n for n in re.findall(NUM, numbers)]


def check(root):
    root = os.path.abspath(root)
    files = tracked_files(root)
    fileset = set(files)
    dirset = set()
    for f in files:
        parts = f.split("/")
        for k in range(1, len(parts)):
            dirset.add("/".join(parts[:k]))
    has_old = any(f.split("/")[-1] == OLD_NAME for f in files)
    has_notes_scripts = any(f.startswith("veri" + "fy/") for f in files)
    docs = {}
    for name in ("method", "design"):
        text = read_text(os.path.join(root, "docs", name + ".md"))
        docs[name] = headings(text)[0] if text is not None and "docs/%s.md" % name in fileset else None
    anchor_cache = {}

    problems, checked = [], 0

    def report(f, n, msg):
        problems.append("%s:%d: %s" % (f, n, msg))

    for f in files:
        text = read_text(os.path.join(root, f))
        if text is None:
            continue
        is_md = f.endswith(".md")
        fenced = False
        for n, line in enumerate(text.splitlines(), 1):
            # (a) references outside the repository
            for m in OUTSIDE.finditer(line):
                checked += 1
                report(f, n, "refers to '%s', outside the repository" % m.group(0).rstrip(").,;:'\"`"))
            if not has_notes_scripts:
                for m in NOTES_SCRIPTS.finditer(line):
                    checked += 1
                    report(f, n, "refers to '%s', a check of the notes outside the repository; state the "
                           "result or cite the repository's test" % m.group(0).rstrip(".,;:)"))
            # (b) section citations
            for m in CITE.finditer(line):
                doc = m.group(1).lower()
                part = bool(m.group(2))
                for num in expand(m.group(3)):
                    checked += 1
                    key = ("part " if part else "") + num
                    if docs[doc] is None:
                        report(f, n, "cites docs/%s.md %s, but docs/%s.md is not in the repository" % (doc, key, doc))
                    elif key not in docs[doc]:
                        report(f, n, "cites docs/%s.md %s, which has no such section heading" % (doc, key))
            if not has_old:
                for m in OLD_CITE.finditer(line):
                    checked += 1
                    report(f, n, "cites %s, which is not in the repository; cite docs/method.md" % OLD_NAME)
                for m in OLD_SHORT.finditer(line):
                    checked += 1
                    report(f, n, "cites 'methods %s' (%s, not in the repository); cite docs/method.md %s"
                           % (m.group(1), OLD_NAME, m.group(1)))
            # (c) relative Markdown links
            if not is_md:
                continue
            if FENCE.match(line):
                fenced = not fenced
                continue
            if fenced:
                continue
            for m in LINK.finditer(line):
                target = m.group(1)
                if re.match(r"^[a-zA-Z][a-zA-Z0-9+.-]*:", target) or target.startswith("/"):
                    continue
                checked += 1
                path, _, anchor = target.partition("#")
                if path:
                    resolved = os.path.normpath(os.path.join(os.path.dirname(f), path)).replace(os.sep, "/")
                else:
                    resolved = f
                if resolved == ".." or resolved.startswith("../"):
                    report(f, n, "links to '%s', outside the repository" % target)
                    continue
                if resolved != "." and resolved not in fileset and resolved not in dirset:
                    report(f, n, "links to '%s': no such file in the repository" % target)
                    continue
                if anchor and resolved.endswith(".md") and resolved in fileset:
                    if resolved not in anchor_cache:
                        anchor_cache[resolved] = headings(read_text(os.path.join(root, resolved)) or "")[1]
                    if anchor.lower() not in anchor_cache[resolved]:
                        report(f, n, "links to '%s': %s has no heading with anchor #%s" % (target, resolved, anchor))
    return checked, problems


def self_test():
    """Plants one bad reference of each kind in a scratch tree and expects each to be reported."""
    # Citations are spelt through M and G so that this file does not cite anything itself.
    M, G = "method" + ".md", "design" + ".md"
    good = {
        "docs/" + M: "# Method\n## 0. Notation\n## 4. Projection\n### 4.2 Pressure equation\n## 14. Open points\n### 14.4 Sign\n",
        "docs/" + G: "# Design\n## Part 1. The contract\n### 1.3 Output\n## Part 2. Building\n",
        "docs/other.md": "See [method](%s#42-pressure-equation) and [the design](%s).\n"
                         "```\n[not a link](nowhere.md)\n```\n" % (M, G),
        "README.md": "Read [docs/%s](docs/%s), [the tests](tests/).\n" % (M, M),
        "src/a.cpp": "// docs/%s 4.2, %s 1.3, %s part 2, %s 0 and 14.4\n" % (M, G, G, M),
        "tests/t.py": "# %s 4.2\n" % M,
    }
    bad = {
        "src/b.cpp": ("// docs/%s 4.7\n" % M, "has no such section"),
        "src/c.cpp": ("// %s part 3\n" % G, "has no such section"),
        "src/d.cpp": ("// see %s 4.2\n" % OLD_NAME, "cite docs/method.md"),
        "docs/i.md": ("| detection (%s 5) |\n" % OLD_NAME[:-3], "cite docs/method.md 5"),
        "src/e.hpp": ("// see %s 4.2, 14.9\n" % M, "14.9"),
        "README2.md": ("Notes in [here](%s/docs/notes.md).\n" % SHARED, "outside the repository"),
        "src/j.cpp": ("// numbers of %s/sph2_check.out\n" % ("veri" + "fy"), "check of the notes"),
        "src/f.py": ("DATA = '%sshared/refdata/x.csv'\n" % WORK_AREA, "outside the repository"),
        "docs/g.md": ("See [missing](missing.md).\n", "no such file"),
        "docs/h.md": ("See [anchor](%s#99-nothing).\n" % M, "no heading with anchor"),
    }
    failures = 0
    with tempfile.TemporaryDirectory() as tmp:
        def write(files):
            for p, t in files.items():
                os.makedirs(os.path.join(tmp, os.path.dirname(p)), exist_ok=True)
                with open(os.path.join(tmp, p), "w") as fh:
                    fh.write(t)
        write(good)
        checked, problems = check(tmp)
        if problems or checked < 10:
            print("self-test: the clean tree was not clean (%d checked):\n  %s" % (checked, "\n  ".join(problems)))
            failures += 1
        for p, (t, expect) in bad.items():
            write({p: t})
            _, problems = check(tmp)
            hits = [x for x in problems if x.startswith(p + ":") and expect in x]
            if not hits or len(hits) != len(problems):
                print("self-test: planted %s (%r) expected one problem with %r, got:\n  %s"
                      % (p, t.strip(), expect, "\n  ".join(problems) or "none"))
                failures += 1
            os.remove(os.path.join(tmp, p))
    total = len(bad) + 1
    print("self-test: %d passed, %d failed" % (total - failures, failures))
    return 1 if failures else 0


def main(argv):
    if len(argv) == 2 and argv[1] == "--self-test":
        return self_test()
    if len(argv) != 2:
        print(__doc__.strip().split("\n\n")[1])
        return 2
    checked, problems = check(argv[1])
    for p in problems:
        print(p)
    print("%d references checked: %d resolve, %d do not" % (checked, checked - len(problems), len(problems)))
    if problems:
        print("FAILED: every reference must resolve inside the repository (docs/method.md, docs/design.md, "
              "relative links); see tests/docs/checkReferences.py")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
