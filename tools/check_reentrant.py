#!/usr/bin/env python3
"""No function of the library returns a deferred-length character result.

gfortran (12) keeps the length of a `character(len=:), allocatable` function result in a
STATIC variable of the caller (`static integer(kind=8) slen.N` in -fdump-tree-original):
two threads at the same call site race on it, and since that length sizes the result's
allocation and copies, the race corrupts texts and memory. The library runs in OpenMP
threads (the batch driver) and from Python threads with the GIL released, so a function
returning text gives its length by a specification expression instead (a pure *_len
function of the same arguments, see src/seispulse/core/format.f90), or is a subroutine
with a `character(len=:), allocatable, intent(out)` argument (safe: its length lives in
the caller's frame).

Checks (standard library only):

  reentrant/deferred-results  every `function` in src/**/*.f90 whose result variable is
                              declared `character(len=:)` (or `character(:)`) is an error
  reentrant/static-lengths    (with --builddir, when BUILDDIR/compile_commands.json exists)
                              every library source compiled with -fdump-tree-original
                              (-O0, into a temp dir): no `static integer(kind=8) slen.N`

Prints `ok   reentrant/<check>: ...` or `FAIL reentrant/<check>: why` lines (the form
tools/run_tests.py counts); exit status 1 on a failure.

Usage: python tools/check_reentrant.py [--builddir build]
"""

import argparse
import json
import re
import shlex
import subprocess
import sys
import tempfile
from pathlib import Path

from check_thread_safety import statements   # tools/: the same reader of free-form source

ROOT = Path(__file__).resolve().parent.parent

FUNC_RE = re.compile(
    r"^\s*(?:(?:pure|elemental|impure|recursive|module)\s+)*"
    r"(?:[a-z]+(?:\s*\([^)]*\))?\s+)?function\s+(\w+)\s*\(([^)]*)\)"
    r"(?:\s*result\s*\(\s*(\w+)\s*\))?", re.I)
END_RE = re.compile(r"^\s*end\s*function\b", re.I)
DEFERRED_RE = re.compile(r"^\s*character\s*\(\s*(?:len\s*=\s*)?:\s*\)(.*?)::(.*)$", re.I)
STATIC_RE = re.compile(r"static integer\(kind=8\) (slen\.\d+);")


def deferred_functions(root):
    """(file, function) of every function whose result is deferred-length text."""
    found = []
    for path in sorted((root / "src").rglob("*.f90")):
        lines = [stmt for _, stmt in statements(path.read_text(encoding="utf-8"))]
        i = 0
        while i < len(lines):
            m = FUNC_RE.match(lines[i])
            if not m or lines[i].lstrip().lower().startswith("end"):
                i += 1
                continue
            name, result = m.group(1), (m.group(3) or m.group(1)).lower()
            j = i + 1
            while j < len(lines) and not END_RE.match(lines[j]):
                d = DEFERRED_RE.match(lines[j])
                if d:
                    names = [re.sub(r"[(=].*", "", v).strip().lower()
                             for v in re.split(r",(?![^(]*\))", d.group(2))]
                    if result in names:
                        found.append((path.relative_to(root), name))
                j += 1
            i = j + 1
    return found


def static_lengths(root, builddir):
    """{function: number of call sites} of calls whose result length is a static variable,
    from -fdump-tree-original of every library source; None without compile_commands."""
    db = builddir / "compile_commands.json"
    if not db.exists():
        return None
    calls = {}
    with tempfile.TemporaryDirectory(prefix="check_reentrant_") as tmp:
        for entry in json.loads(db.read_text()):
            src = (Path(entry["directory"]) / entry["file"]).resolve()
            if root / "src" not in src.parents:
                continue
            args, skip = [], False
            for a in shlex.split(entry["command"]):
                if skip:
                    skip = False
                elif a == "-o":
                    skip = True
                elif not (a.startswith("-J") or a.startswith("-O")
                          or a.startswith("-fdiagnostics-color")):
                    args.append(a)
            args += ["-O0", f"-J{tmp}", "-fdump-tree-original", "-S", "-o", "/dev/null",
                     "-dumpdir", tmp + "/"]
            r = subprocess.run(args, cwd=entry["directory"], capture_output=True, text=True)
            if r.returncode != 0:
                raise RuntimeError(f"{src.name}: {r.stderr.strip()[:300]}")
        for dump in Path(tmp).glob("*.original"):
            text = dump.read_text(errors="replace")
            for slen in STATIC_RE.findall(text):
                m = re.search(r"(\w+) \(&pstr\.\d+, &" + re.escape(slen) + r"\b", text)
                fname = m.group(1) if m else f"? ({dump.name}: {slen})"
                calls[fname] = calls.get(fname, 0) + 1
    return calls


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--builddir", help="a configured build dir (also checks the dumps)")
    args = parser.parse_args()
    failed = False

    found = deferred_functions(ROOT)
    bad = found
    if bad:
        failed = True
        print(f"FAIL reentrant/deferred-results: {len(bad)} functions return "
              "character(len=:) (give the length by a specification expression)")
        for f, n in bad:
            print(f"    {f}: {n}")
    else:
        print("ok   reentrant/deferred-results: none in src/")

    if args.builddir:
        builddir = Path(args.builddir)
        if not builddir.is_absolute():
            builddir = ROOT / builddir
        try:
            calls = static_lengths(ROOT, builddir)
        except RuntimeError as exc:
            calls = None
            failed = True
            print(f"FAIL reentrant/static-lengths: a source did not compile: {exc}")
        if calls is not None:
            other = calls
            if other:
                failed = True
                print(f"FAIL reentrant/static-lengths: {sum(other.values())} call sites "
                      "keep a result length in a static variable")
                for k, v in sorted(other.items(), key=lambda kv: -kv[1]):
                    print(f"    {k}: {v}")
            else:
                print("ok   reentrant/static-lengths: no static result length in the "
                      "library")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
