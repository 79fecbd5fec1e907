#!/usr/bin/env python3
"""Check that the Fortran library keeps no state between calls (standard library only).

The Python bindings release the GIL around every Fortran call (README "Python in
parallel"), and the driver runs units in OpenMP threads: two calls may run at once, so a
library procedure must not keep anything between calls. Reads every src/**/*.f90 (a light
reader of the Fortran we write, not a compiler) and reports:

  save          a SAVE attribute or statement anywhere (procedure or module)
  init-local    a variable of a procedure (or of a BLOCK in it) initialised in its
                declaration (`integer :: n = 0`, `real, pointer :: p => null()`): that is an
                implicit SAVE (F2008 5.3.16), shared by every call and thread
  data          a DATA statement (the same implicit SAVE)
  common        a COMMON block
  module-var    a module variable (a declaration in a module's specification part that
                is not a PARAMETER): state shared by every caller
  open-unit     an OPEN without NEWUNIT= (a fixed unit number is shared by every thread)
  parse         a file whose program units this reader cannot pair (an END without its
                start or a unit left open): its verdicts would not hold

Named constants (`parameter`) and the default values of derived-type components are fine:
they are not variables. The f2py layer's held results (python/seispulse/_wrap*.f90) are not
the library and are not read here.

Prints `ok   threads/<check>` or `FAIL threads/<check>: ...` lines (the form
tools/run_tests.py counts) with the offending places, and exits 1 on any failure.

Usage: python tools/check_thread_safety.py [--root DIR] [FILE ...]
"""

import argparse
import re
import sys
from pathlib import Path

from check_doc_comments import split_comment, split_top, top_level   # the same readers

ROOT = Path(__file__).resolve().parent.parent
CHECKS = ("save", "init-local", "data", "common", "module-var", "open-unit", "parse")

TYPE_SPEC = (r"(?:integer|real|complex|logical|character|double\s+precision|double\s+complex"
             r"|type\s*\(|class\s*\(|procedure\s*\()")
DECL_RE = re.compile(r"^" + TYPE_SPEC, re.I)
PROC_RE = re.compile(r"^(?:(?:pure|elemental|impure|recursive|non_recursive|module)\s+|"
                     r"(?:integer|real|complex|logical|character|type|class)\s*"
                     r"(?:\([^()]*(?:\([^()]*\)[^()]*)*\))?\s*|double\s+precision\s+)*"
                     r"(?:subroutine|function)\s+\w+", re.I)
MODULE_RE = re.compile(r"^(?:module\s+(?!procedure\b)\w+|submodule\s*\()", re.I)
PROGRAM_RE = re.compile(r"^program\s+\w+", re.I)
TYPE_DEF_RE = re.compile(r"^type\s*(?:,[^:]*)?::\s*\w+|^type\s+(?!is\b)\w+\s*$", re.I)
INTERFACE_RE = re.compile(r"^(?:abstract\s+)?interface\b", re.I)
ENUM_RE = re.compile(r"^enum\s*,", re.I)
END_RE = re.compile(r"^end\s*(subroutine|function|module|submodule|program|type|interface|"
                    r"enum)?\b", re.I)     # after BLOCK_END_RE: `end do` is not one of these
BLOCK_END_RE = re.compile(r"^end\s*(?:do|if|select|associate|block|where|forall|critical)\b",
                          re.I)


def strip_comment(line):
    """The code of one physical line: the comment (outside quotes) removed."""
    return split_comment(line)[0]


def statements(text):
    """(line number, statement) of a free-form source: comments removed, `&` continuations
    joined, `;` separated statements split (outside quotes and parentheses)."""
    out, pending, first = [], "", 0
    for number, raw in enumerate(text.splitlines(), 1):
        code = strip_comment(raw).rstrip()
        if pending:
            code = code.lstrip()
            if code.startswith("&"):
                code = code[1:]
        else:
            first = number
        if code.endswith("&"):
            pending += code[:-1]
            continue
        for part in split_top(pending + code, ";"):
            if part.strip():
                out.append((first, part.strip()))
        pending = ""
    return out


def initialised(entities):
    """The names in a declaration's entity list that carry an initial value (= or =>)."""
    return [re.match(r"\s*(\w+)", entity).group(1) for entity in split_top(entities, ",")
            if "=" in strip_parens(entity)]


def strip_parens(text):
    """text without what is inside parentheses or quotes, nor these (a(1:n) = 1 -> a = 1)."""
    return "".join(ch for ch, top in top_level(text) if top)


def declaration(stmt):
    """(attributes, entity list) of a type declaration statement (with ::), else None.
    The declarations written without :: (`integer n`) cannot carry an initial value in
    the form this library uses (F2008 5.2.1: `=` needs the ::)."""
    if not DECL_RE.match(stmt) or "::" not in stmt:
        return None
    head, _, entities = stmt.partition("::")
    return head, entities


def check_file(path, text):
    """{check: [(path, line, message)]} for one source file."""
    found = {check: [] for check in CHECKS}
    stack = []              # 'module', 'proc', 'type', 'interface', 'enum', 'program'
    contains = []           # per stack entry: after CONTAINS
    for number, stmt in statements(text):
        low = stmt.lower()
        where = (str(path), number)
        label = re.match(r"^\w+\s*:\s*(?!:)", low)       # construct names `name: block`
        body = low[label.end():] if label else low
        if BLOCK_END_RE.match(body):
            continue
        m = END_RE.match(body)
        if m and (m.group(1) or body.strip() == "end"):
            if not stack:
                found["parse"].append(where + (f"END without a program unit: {stmt}",))
                return found
            stack.pop()
            contains.pop()
            continue
        scope = stack[-1] if stack else None
        if scope == "interface":
            if PROC_RE.match(body):
                stack.append("iproc")
                contains.append(False)
            continue
        if scope == "iproc":
            continue
        if scope == "type":
            if re.match(r"^contains$", body):
                contains[-1] = True
            continue
        if MODULE_RE.match(body):
            stack.append("module")
            contains.append(False)
            continue
        if PROGRAM_RE.match(body):
            stack.append("proc")
            contains.append(False)
            continue
        if INTERFACE_RE.match(body):
            stack.append("interface")
            contains.append(False)
            continue
        if ENUM_RE.match(body):
            stack.append("enum")
            contains.append(False)
            continue
        if TYPE_DEF_RE.match(body):
            stack.append("type")
            contains.append(False)
            continue
        if PROC_RE.match(body) and "::" not in body:
            stack.append("proc")
            contains.append(False)
            continue
        if body == "contains":
            if contains:
                contains[-1] = True
            continue
        statement = "=" not in strip_parens(body)       # not an assignment to `save = ...`
        if statement and re.match(r"^save\b", body):
            found["save"].append(where + (f"SAVE statement: {stmt}",))
            continue
        if statement and re.match(r"^data\b", body):
            found["data"].append(where + (f"DATA statement: {stmt}",))
            continue
        if statement and re.match(r"^common\b", body):
            found["common"].append(where + (f"COMMON block: {stmt}",))
            continue
        if re.match(r"^open\s*\(", body) and "newunit" not in body.replace(" ", ""):
            found["open-unit"].append(where + (f"OPEN without NEWUNIT=: {stmt}",))
            continue
        decl = declaration(body)
        if decl is None or scope is None:
            continue
        attrs, entities = decl
        attr_names = {a.strip().split("(")[0].strip() for a in split_top(attrs, ",")[1:]}
        if "parameter" in attr_names:
            continue
        if "save" in attr_names:
            found["save"].append(where + (f"SAVE attribute: {stmt}",))
            continue
        if scope == "module" and not contains[-1]:
            found["module-var"].append(where + (f"module variable: {stmt}",))
        elif scope == "proc":
            for name in initialised(entities):
                found["init-local"].append(
                    where + (f"{name} initialised in its declaration (implicit SAVE): "
                             f"{stmt}",))
    if stack:
        found["parse"].append((str(path), number, f"{len(stack)} unit(s) without END"))
    return found


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", type=Path, default=ROOT)
    parser.add_argument("files", nargs="*", type=Path, help="default: src/**/*.f90")
    args = parser.parse_args(argv)
    files = args.files or sorted((args.root / "src").rglob("*.f90"))
    if not files:
        print(f"FAIL threads/sources: no .f90 file under {args.root / 'src'}")
        return 1
    total = {check: [] for check in CHECKS}
    for path in files:
        for check, places in check_file(path, path.read_text(encoding="utf-8")).items():
            total[check] += places
    failed = False
    for check in CHECKS:
        places = total[check]
        if not places:
            print(f"ok   threads/{check}")
            continue
        failed = True
        print(f"FAIL threads/{check}: {len(places)} place(s)")
        for path, line, message in places:
            print(f"    {path}:{line}: {message}")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
