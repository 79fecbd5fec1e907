#!/usr/bin/env python3
"""Build-time generator of the f2py layer (run by python/seispulse/meson.build).

    gen_binding.py f2py --outdir DIR --f2cmap FILE --src LIBSRC... --wrap WRAP.f90...
    gen_binding.py codes --out FILE.py --src LIBSRC...
    gen_binding.py loops --spec _wrap_loops.txt --out _wrap_loops.f90

The wrapper sources are the only hand-written signatures: f2py reads them (with their
inline ``!f2py`` directives) into ``DIR/_seispulse.pyf``; module blocks (helpers of the
wrappers, not for Python) and ``use`` lines are dropped, and library parameters used as
dimensions (``PULSE_NPARAM``) are replaced by their values read from LIBSRC. f2py then
writes ``_seispulsemodule.c`` and ``_seispulse-f2pywrappers.f`` from that file, with
``real(dp)`` mapped to C double by FILE.

Every wrapper carries an ``!f2py threadsafe`` line: the generated C releases the GIL
around each Fortran call, so Python threads run them in parallel; the build fails for a
routine whose C keeps the GIL.

Then the kinds are checked: a kind f2py does not map becomes C float and gives wrong
numbers without any error, so any ``float`` argument in the generated C fails the build.

f2py's output goes to ``DIR/_seispulse_f2py.log``; it is printed only when a step fails.

``codes`` writes the library's named integer constants (status codes, regions, modes,
outcomes, method and format codes: every upper-case ``integer, parameter``) as a Python
module, so that the Python layer never retypes a Fortran code.

``loops`` writes the element-by-element wrappers (a loop over arrays calling a scalar
routine) from their one-line descriptions in _wrap_loops.txt (format described there).
"""

import argparse
import re
import subprocess
import sys
from pathlib import Path

MODULE = "_seispulse"

PARAM_RE = re.compile(r"^\s*integer\s*,\s*parameter\s*::\s*(.*)$", re.I)
ASSIGN_RE = re.compile(r"^\s*([a-z_]\w*)\s*=\s*([+-]?\d+)\s*$", re.I)


def fortran_statements(path):
    """Statements of a free-form Fortran file: comments stripped, & continuations joined."""
    statements, pending = [], ""
    for raw in Path(path).read_text(encoding="utf-8").splitlines():
        line = raw.split("!", 1)[0].rstrip()     # no '!' inside strings on parameter lines
        if pending:
            line = line.lstrip()
            if line.startswith("&"):
                line = line[1:]
        if line.endswith("&"):
            pending += line[:-1]
            continue
        statements.append(pending + line)
        pending = ""
    return statements


def integer_parameters(paths, upper_only=False):
    """{NAME: value} of every `integer, parameter :: NAME = <integer literal>` in paths
    (names upper-case; None for a name given two values). upper_only: only the names the
    library writes in upper case (its named codes; lower-case ones are local limits)."""
    found = {}
    for path in paths:
        for stmt in fortran_statements(path):
            m = PARAM_RE.match(stmt)
            if not m:
                continue
            for item in m.group(1).split(","):
                a = ASSIGN_RE.match(item)
                if a and (a.group(1) == a.group(1).upper() or not upper_only):
                    name, value = a.group(1).upper(), int(a.group(2))
                    found[name] = value if found.get(name, value) == value else None
    return found


class StepFailed(Exception):
    pass


def run_logged(cmd, log):
    """Run cmd with its output appended to the open log; StepFailed if it fails."""
    log.write("$ " + " ".join(map(str, cmd)) + "\n")
    log.flush()
    proc = subprocess.run([str(c) for c in cmd], stdout=log, stderr=subprocess.STDOUT,
                          stdin=subprocess.DEVNULL)
    if proc.returncode != 0:
        raise StepFailed(f"{Path(str(cmd[2])).name if len(cmd) > 2 else cmd[0]} "
                         f"exited {proc.returncode}")


def clean_signatures(text, params):
    """The generated .pyf for the Python module: no module blocks, no use lines, library
    parameters in dimensions (names that are not arguments) replaced by their values."""
    out, depth, args = [], 0, set()
    lower = {name.lower(): value for name, value in params.items()}

    def value(name):
        if lower[name] is None:
            raise StepFailed(f"dimension {name}: defined with different values")
        return str(lower[name])
    for line in text.splitlines():
        s = line.strip().lower()
        if depth == 0 and re.match(r"module\s+\w+", s) and not s.startswith("module procedure"):
            depth = 1
            continue
        if depth:
            if re.match(r"end\s+module\b", s):
                depth = 0
            continue
        if re.match(r"use\s+\w+", s):
            continue
        m = re.match(r"subroutine\s+\w+\s*\(([^)]*)\)", s)
        if m:
            args = {a.strip() for a in m.group(1).split(",")}
        if "dimension(" in line:
            def subst(m):
                dims = re.sub(r"\b[a-z_]\w*\b",
                              lambda w: value(w.group(0))
                              if w.group(0) in lower and w.group(0) not in args
                              else w.group(0), m.group(1))
                return f"dimension({dims})"
            line = re.sub(r"dimension\(([^)]*)\)", subst, line)
        out.append(line)
    return "\n".join(out) + "\n"


KIND_RE = re.compile(r"\b(real|complex)\s*\(\s*kind\s*=\s*(\w+)\s*\)", re.I)
# C types f2py uses for single precision: scalars, arrays, complex.
FLOAT_C_RE = re.compile(r"^\s*(float|complex_float)\s+\w+|NPY_C?FLOAT\b", re.M)


def check_kinds(pyf_text, c_text, f2cmap):
    """Problems with the kind mapping (an empty list when every real is double)."""
    problems = []
    mapping = eval(Path(f2cmap).read_text(encoding="utf-8"), {}, {})  # f2py's own format
    for m in KIND_RE.finditer(pyf_text):
        kinds = {k.lower() for k in mapping.get(m.group(1).lower(), {})}
        if m.group(2).lower() not in kinds:
            problems.append(f"{m.group(0)} is not in {f2cmap}")
    for m in FLOAT_C_RE.finditer(c_text):
        line = c_text[:m.start()].count("\n") + 1
        problems.append(f"single precision in the generated C, line {line}: "
                        f"{c_text.splitlines()[line - 1].strip()}")
    return sorted(set(problems))


ROUTINE_C_RE = re.compile(r"^static PyObject \*f2py_rout_\w+?_(sp_\w+)\(", re.M)


def check_threadsafe(c_text):
    """Routines of the generated C that keep the GIL during the Fortran call (an empty list
    when every one releases it: `!f2py threadsafe` in each wrapper, so that Python threads
    run Fortran calls in parallel; see README "Python in parallel")."""
    starts = [(m.start(), m.group(1)) for m in ROUTINE_C_RE.finditer(c_text)]
    if not starts:
        return ["no wrapper routine found in the generated C"]
    ends = [s for s, _ in starts[1:]] + [len(c_text)]
    return [name for (start, name), end in zip(starts, ends)
            if "Py_BEGIN_ALLOW_THREADS" not in c_text[start:end]]


def cmd_f2py(args):
    outdir = Path(args.outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    pyf = outdir / f"{MODULE}.pyf"
    log_path = outdir / f"{MODULE}_f2py.log"
    f2py = [sys.executable, "-m", "numpy.f2py"]
    with open(log_path, "w", encoding="utf-8") as log:
        try:
            raw = outdir / f"{MODULE}.raw.pyf"
            run_logged(f2py + ["-h", raw, "-m", MODULE, "--lower", "--overwrite-signature"]
                       + args.wrap, log)
            params = integer_parameters(args.src)
            pyf.write_text(clean_signatures(raw.read_text(encoding="utf-8"), params),
                           encoding="utf-8")
            raw.unlink()
            run_logged(f2py + [pyf, "--lower", "--f2cmap", args.f2cmap,
                               "--build-dir", outdir], log)
            c_file = outdir / f"{MODULE}module.c"
            problems = check_kinds(pyf.read_text(encoding="utf-8"),
                                   c_file.read_text(encoding="utf-8"), args.f2cmap)
            if problems:
                more = f"; and {len(problems) - 5} more" if len(problems) > 5 else ""
                raise StepFailed("kind mapping: " + "; ".join(problems[:5]) + more)
            held = check_threadsafe(c_file.read_text(encoding="utf-8"))
            if held:
                raise StepFailed("the GIL is kept (no `!f2py threadsafe` line after "
                                 "`implicit none`) by: " + ", ".join(held))
        except StepFailed as exc:
            log.flush()
            sys.stderr.write(log_path.read_text(encoding="utf-8", errors="replace"))
            sys.stderr.write(f"gen_binding.py f2py: {exc} (log: {log_path})\n")
            return 1
    return 0


def cmd_codes(args):
    params = integer_parameters(args.src, upper_only=True)
    lines = ['"""Named integer constants of the Fortran library (status codes, regions, modes,',
             'outcomes, method and format codes), read from its sources at build time by',
             'gen_binding.py: generated, do not edit. Constants defined twice with different',
             'values are left out."""', ""]
    lines += [f"{name} = {value}" for name, value in sorted(params.items())
              if value is not None]
    Path(args.out).write_text("\n".join(lines) + "\n", encoding="utf-8")
    return 0


LOOP_HEAD_RE = re.compile(r"^(sp_\w+)\((.*)\)$")
LOOP_CALL_RE = re.compile(r"^(\w+):\s*(?:(\w+)\s*=\s*)?(\w+)\((.*)\)$", re.S)
LOOP_ARG_RE = re.compile(r"^(>?)(\w+)(?:\((\d+)\))?(?::(int|real|complex))?(?:=(\w+%\w+))?$")
LOOP_MODULE_RE = re.compile(r"^\w+:\s")
LOOP_LOCAL_RE = re.compile(r"^type\((\w+)\)\s*::\s*(\w+)$")
TYPES = {"int": "integer", "real": "real(dp)", "complex": "complex(dp)"}
ZERO = {"int": "0", "real": "0.0_dp", "complex": "(0.0_dp, 0.0_dp)"}


def loop_entries(text):
    """(doc lines, head, calls, local) of each entry of a _wrap_loops.txt text."""
    entries, doc, lines = [], [], []
    for raw in text.splitlines() + [""]:
        if raw.startswith("#"):
            continue
        if raw.startswith("!>"):
            doc.append(raw)
        elif raw.strip():
            lines.append(raw.strip())
        elif lines:
            local = lines.pop() if LOOP_LOCAL_RE.match(lines[-1]) else None
            k = 1                                   # the head ends where its parentheses do
            while k < len(lines) and " ".join(lines[:k]).count("(") > \
                    " ".join(lines[:k]).count(")"):
                k += 1
            calls = []                              # a statement starts with `module:`
            for line in lines[k:]:
                if LOOP_MODULE_RE.match(line) or not calls:
                    calls.append(line)
                else:
                    calls[-1] += " " + line
            entries.append((doc, " ".join(lines[:k]), calls, local))
            doc, lines = [], []
    return entries


def wrap_line(text, indent, width=100):
    """`text` broken after commas into Fortran continuation lines of at most `width`."""
    out, line = [], indent + text
    hang = " " * (line.index("(") + 1)
    while len(line) > width:
        cut = line.rfind(", ", 0, width - 1)
        out.append(line[:cut + 1] + " &")
        line = hang + line[cut + 2:]
    return "\n".join(out + [line])


def loop_routine(doc, head, calls, local=None):
    """The Fortran of one element-by-element wrapper."""
    m, cs = LOOP_HEAD_RE.match(head), [LOOP_CALL_RE.match(call) for call in calls]
    if not m or not all(cs):
        raise StepFailed(f"loops: cannot read {head!r} / {calls!r}")
    name = m.group(1)
    args, decls, zero, arrays, after = [], [], [], {}, []
    for token in (t.strip() for t in m.group(2).split(",")):
        a = LOOP_ARG_RE.match(token)
        if not a:
            raise StepFailed(f"loops: {name}: cannot read argument {token!r}")
        out, arg, cols, kind = a.group(1) == ">", a.group(2), a.group(3), a.group(4) or "real"
        args.append(arg)
        if a.group(5):                                      # a component of the local result
            after.append(f"{arg}(i) = {a.group(5)}")
        if not out and a.group(4):                          # scalar input
            decls.append(f"{TYPES[kind]}, intent(in) :: {arg}")
            continue
        dims = f"n, {cols}" if cols else "n"
        decls.append(f"{TYPES[kind]}, intent({'out' if out else 'in'}) :: {arg}({dims})")
        arrays[arg] = cols
        if out:
            zero.append(f"{arg} = {ZERO[kind]}")

    def element(w):
        arg, sub = w.group(1), w.group(2)
        if arg not in arrays:
            return w.group(0)
        if sub:
            return f"{arg}(i, {sub})"
        return f"{arg}(i, :)" if arrays[arg] else f"{arg}(i)"
    uses, locals_, body = {}, [], []           # {module: names}, declarations, loop body
    if local:
        ltype, lname = LOOP_LOCAL_RE.match(local).groups()
        uses[cs[0].group(1)], locals_ = [ltype], [f"    type({ltype}) :: {lname}"]
    for c in cs:
        module, result, routine = c.group(1), c.group(2), c.group(3)
        uses.setdefault(module, []).append(routine)
        actual = re.sub(r"\b([a-z_]\w*)\b(?:\((\d+)\))?", element, c.group(4))
        if result:                              # a function without stat: y(i) = f(...)
            body.append(wrap_line(f"{result}(i) = {routine}({actual})", " " * 8))
        else:
            body += [wrap_line(f"call {routine}({actual})", " " * 8),
                     "        if (stat /= SEISPULSE_SUCCESS) return"]
    lines = doc + [wrap_line(f"subroutine {name}(n, {', '.join(args)}, stat, errmsg)", "")]
    lines += ["    use seispulse_kinds, only: dp",
              "    use seispulse_errors, only: SEISPULSE_SUCCESS"]
    lines += [f"    use {module}, only: {', '.join(names)}" for module, names in uses.items()]
    lines += ["    implicit none",
              "    !f2py threadsafe",
              "    !f2py intent(hide) :: n",
              "    integer, intent(in) :: n"]
    lines += ["    " + d for d in decls]
    lines += ["    integer, intent(out) :: stat",
              "    character(len=256), intent(out) :: errmsg"] + locals_ + [
              "    integer :: i",
              "    errmsg = ''",
              "    stat = SEISPULSE_SUCCESS"]
    lines += ["    " + z for z in zero]
    lines += ["    do i = 1, n"] + body
    lines += ["        " + a for a in after]
    lines += ["    end do",
              f"end subroutine {name}"]
    return "\n".join(lines)


def cmd_loops(args):
    try:
        entries = loop_entries(Path(args.spec).read_text(encoding="utf-8"))
        body = "\n\n".join(loop_routine(*entry) for entry in entries)
    except StepFailed as exc:
        sys.stderr.write(f"gen_binding.py loops: {exc}\n")
        return 1
    header = ("! Element-by-element wrappers of the f2py layer, generated by gen_binding.py from\n"
              f"! {Path(args.spec).name}: do not edit.\n\n")
    Path(args.out).write_text(header + body + "\n", encoding="utf-8")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    sub = parser.add_subparsers(dest="cmd", required=True)
    p = sub.add_parser("f2py", help="signatures + C of the extension from the wrappers")
    p.add_argument("--outdir", required=True)
    p.add_argument("--f2cmap", required=True)
    p.add_argument("--src", nargs="+", default=[], help="library sources (parameters)")
    p.add_argument("--wrap", nargs="+", required=True, help="thin-layer sources")
    p = sub.add_parser("codes", help="the library's named integer constants as Python")
    p.add_argument("--out", required=True)
    p.add_argument("--src", nargs="+", required=True, help="library sources")
    p = sub.add_parser("loops", help="the element-by-element wrappers from their spec")
    p.add_argument("--spec", required=True)
    p.add_argument("--out", required=True)
    args = parser.parse_args()
    return {"f2py": cmd_f2py, "codes": cmd_codes, "loops": cmd_loops}[args.cmd](args)


if __name__ == "__main__":
    sys.exit(main())
