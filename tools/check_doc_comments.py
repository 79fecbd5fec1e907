#!/usr/bin/env python3
"""Check the FORD doc comments of the public Fortran API (standard library only).

Parses every src/**/*.f90 (a light reader of the subset of Fortran we write, not a
compiler) and reports, for every public procedure of a module (named on a `public ::`
line, a specific of a public generic interface, the target of a binding of a public
derived type, or a public abstract interface):

  undocumented   a dummy argument without a doc comment (`!!` after its declaration or
                 `!>` before it)
  no-default     an optional dummy argument whose comment does not say what happens
                 when it is absent (words: default, absent, omitted, not present, if
                 present, when present, required, if given, when given, optional);
                 optional outputs (intent(out), errmsg) are exempt
  metadata       a doc block whose first line reads `word: ...` and that has more lines
                 (or whose `word` is one of FORD's metadata keys): FORD takes that line
                 for metadata and drops it (write `word. ...` or reword)

and, in README.md and doc/ford.md, that the list of status codes is the one of
src/seispulse/core/errors.f90 (every SEISPULSE_* code with its value).

Prints `ok   doc/<check>` or `FAIL doc/<check>: why` lines (the form tools/run_tests.py
counts), the offending places under a FAIL, and exits 1 on any failure.

Usage: python tools/check_doc_comments.py [--root DIR] [--list] [--units]
  --list   print every public procedure and its arguments with their comments, for review
  --units  also list the real/complex arguments whose comment names no unit (a heuristic:
           a unit in parentheses, an SI unit word, "dimensionless", "ratio", ...); a
           review aid, not a failure
"""

import argparse
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent

# the keys FORD knows as an entity's metadata (fields of ford.settings.EntitySettings)
FORD_META_KEYS = {
    "author", "category", "copy_subdir", "date", "deprecated", "display", "graph",
    "graph_maxdepth", "graph_maxnodes", "license", "num_lines", "ordered_subpage",
    "proc_internals", "since", "source", "summary", "title", "version",
}
META_RE = re.compile(r"^[ ]{0,3}(?P<key>[A-Za-z0-9_-]+):\s*(?P<value>.*)")
UNIT_RE = re.compile(
    r"\((?:[^()]*\b(?:m|s|kg|N|rad|Hz|g|Pa|kPa|MPa|kN|J|W|deg|degrees|radians|percent|cm|mm|"
    r"1/s)\b[^()]*)\)|\(-\)|\b(?:m/s\S*|rad/s|N m|kN/m\S*|dimensionless|ratio|fraction|factor|"
    r"coefficient|any unit|units? of|unit|deg|degrees|radians|percent|A_g|t_d|g|s|m|rad|Hz)\b|%|/",
    re.IGNORECASE)
DEFAULT_RE = re.compile(r"default|absent|omitted|not present|if present|when present|required|"
                        r"if given|when given|optional", re.IGNORECASE)

IDENT = r"[a-z][a-z0-9_]*"
PREFIX_RE = r"(?:(?:pure|elemental|impure|recursive|module|non_recursive)\s+|" \
            r"(?:real|integer|logical|complex|character|type|class)\s*(?:\([^()]*" \
            r"(?:\([^()]*\)[^()]*)*\))?\s*)*"
PROC_RE = re.compile(r"^\s*" + PREFIX_RE + r"(?P<kind>subroutine|function)\s+(?P<name>"
                     + IDENT + r")\s*(?:\((?P<args>[^)]*)\))?", re.IGNORECASE)
END_RE = re.compile(r"^\s*end\s*(?P<what>subroutine|function|module|interface|type|"
                    r"program|submodule)?\b", re.IGNORECASE)
MODULE_RE = re.compile(r"^\s*module\s+(?!procedure\b)(?P<name>" + IDENT + r")\s*$",
                       re.IGNORECASE)
INTERFACE_RE = re.compile(r"^\s*(?P<abstract>abstract\s+)?interface\b\s*(?P<name>"
                          + IDENT + r")?", re.IGNORECASE)
TYPE_RE = re.compile(r"^\s*type\s*(?:,\s*(?P<attrs>[^:]*))?::\s*(?P<name>" + IDENT + r")",
                     re.IGNORECASE)
TYPE_PLAIN_RE = re.compile(r"^\s*type\s+(?P<name>" + IDENT + r")\s*$", re.IGNORECASE)
ACCESS_RE = re.compile(r"^\s*(?P<access>public|private)\s*(?:::\s*(?P<names>.*))?$",
                       re.IGNORECASE)
MODPROC_RE = re.compile(r"^\s*module\s+procedure\s*(?:::)?\s*(?P<names>.*)$", re.IGNORECASE)
BINDING_RE = re.compile(r"^\s*(?:procedure|generic)\s*(?:\((?P<iface>" + IDENT
                        + r")\))?\s*(?P<attrs>(?:,\s*[a-z_]+)*)\s*::\s*(?P<rest>.*)$",
                        re.IGNORECASE)
CONTAINS_RE = re.compile(r"^\s*contains\s*$", re.IGNORECASE)


def split_comment(line):
    """(code, comment) of one physical line; quotes are respected."""
    quote = None
    for i, ch in enumerate(line):
        if quote:
            if ch == quote:
                quote = None
        elif ch in "'\"":
            quote = ch
        elif ch == "!":
            return line[:i], line[i:]
    return line, ""


def doc_text(comment):
    """Text of a `!!` or `!>` comment, else None."""
    c = comment.strip()
    if c.startswith("!!") or c.startswith("!>"):
        return c[2:]
    return None


class Statement:
    """One logical statement: joined code, its doc lines, first line number."""

    def __init__(self, code, line, doc, predoc):
        self.code = code
        self.line = line
        self.doc = doc          # `!!` text on/after the statement
        self.predoc = predoc    # `!>` text before it


def statements(text):
    """Logical statements of a free-form file with their doc comments."""
    lines = text.splitlines()
    out = []
    predoc = []
    i = 0
    n = len(lines)
    while i < n:
        code, comment = split_comment(lines[i])
        if not code.strip():
            d = doc_text(comment)
            c = comment.strip()
            if c.startswith("!>"):
                predoc.append(d)
            elif c.startswith("!!") and out and out[-1].doc is not None and \
                    out[-1].line_end == i - 1:
                out[-1].doc.append(d)
                out[-1].line_end = i
            i += 1
            continue
        start = i
        parts = []
        doc = []
        while True:
            code, comment = split_comment(lines[i])
            d = doc_text(comment)
            if d is not None and comment.strip().startswith("!!"):
                doc.append(d)
            stripped = code.rstrip()
            cont = stripped.endswith("&")
            if cont:
                stripped = stripped[:-1]
            s = stripped.strip()
            if s.startswith("&"):
                s = s[1:]
            parts.append(s)
            if not cont or i + 1 >= n:
                break
            i += 1
            # comment-only lines inside a continued statement
            while i < n and not split_comment(lines[i])[0].strip():
                d = doc_text(split_comment(lines[i])[1])
                if d is not None and split_comment(lines[i])[1].strip().startswith("!!"):
                    doc.append(d)
                i += 1
        joined = " ".join(parts)
        for piece in split_semicolons(joined):
            st = Statement(piece, start + 1, list(doc), list(predoc))
            st.line_end = i
            out.append(st)
        predoc = []
        i += 1
    return out


def split_semicolons(code):
    """The statements of a line split at top-level semicolons (blank ones dropped)."""
    return split_top(code, ";")


def top_level(s):
    """(ch, top) for each character of s: top is True outside parentheses, brackets and
    quotes (the brackets and quote characters themselves are not top)."""
    depth, quote = 0, None
    for ch in s:
        if quote:
            if ch == quote:
                quote = None
            yield ch, False
        elif ch in "'\"":
            quote = ch
            yield ch, False
        elif ch in "([":
            depth += 1
            yield ch, False
        elif ch in ")]":
            depth -= 1
            yield ch, False
        else:
            yield ch, depth == 0


def split_top(s, sep=","):
    """Split on sep outside parentheses, brackets and quotes."""
    parts, cur = [], ""
    for ch, top in top_level(s):
        if top and ch == sep:
            parts.append(cur.strip())
            cur = ""
        else:
            cur += ch
    if cur.strip():
        parts.append(cur.strip())
    return parts


class Proc:
    def __init__(self, name, kind, args, line, path, in_interface):
        self.name = name
        self.kind = kind
        self.args = args
        self.line = line
        self.path = path
        self.in_interface = in_interface
        self.docs = {}          # arg -> doc text ('' when none)
        self.optional = set()
        self.outputs = set()    # intent(out) or errmsg
        self.types = {}         # arg -> declared type (lower case, e.g. 'real(dp)')
        self.decl_line = {}
        self.predoc = []


class Module:
    def __init__(self, name, path):
        self.name = name
        self.path = path
        self.default_public = True
        self.public = set()
        self.private = set()
        self.procs = {}
        self.generics = {}      # generic name -> specific names
        self.abstract = set()   # names of abstract interface procedures
        self.types = {}         # type name -> binding targets


def parse_file(path):
    text = path.read_text(encoding="utf-8", errors="replace")
    mods = []
    meta_problems = []
    mod = None
    stack = []      # entries: ('proc', Proc) | ('interface', name, abstract) | ('type', name)
    in_type_contains = False
    proc_contains = []   # parallel to proc entries: has the procedure reached `contains`?
    for st in statements(text):
        code = st.code.strip()
        low = code.lower()
        # doc blocks that FORD would read as metadata
        for block in (st.predoc, st.doc):
            if block:
                first = block[0][1:] if block[0].startswith(" ") else block[0]
                m = META_RE.match(first)
                if m and (len(block) > 1 or m.group("key").lower() in FORD_META_KEYS):
                    meta_problems.append((path, st.line, first.strip()))
        if mod is None:
            m = MODULE_RE.match(code)
            if m:
                mod = Module(m.group("name").lower(), path)
                mods.append(mod)
            continue
        m = END_RE.match(code)
        if m and not re.match(r"^\s*end\s*(if|do|select|associate|block|where|forall)\b",
                              low):
            what = (m.group("what") or "").lower()
            if what == "module" or (not what and not stack):
                mod = None
                stack = []
                continue
            if stack:
                top = stack.pop()
                if top[0] == "type":
                    in_type_contains = False
            continue
        top = stack[-1] if stack else None
        if top and top[0] == "type":
            if CONTAINS_RE.match(code):
                in_type_contains = True
                continue
            if in_type_contains:
                b = BINDING_RE.match(code)
                if b and "private" not in (b.group("attrs") or "").lower():
                    targets = mod.types.setdefault(top[1], [])
                    if b.group("iface"):
                        targets.append(b.group("iface").lower())
                    elif not code.lower().startswith("generic"):
                        for item in split_top(b.group("rest")):
                            tgt = item.split("=>")[-1].strip().lower()
                            targets.append(tgt)
            continue
        if top and top[0] == "interface":
            mp = MODPROC_RE.match(code)
            if mp and top[1]:
                mod.generics.setdefault(top[1], []).extend(
                    x.strip().lower() for x in mp.group("names").split(",") if x.strip())
                continue
        if CONTAINS_RE.match(code):
            if top and top[0] == "proc":
                top[2][0] = True
            continue
        pm = PROC_RE.match(code)
        if pm and not low.startswith("end"):
            args = [a.strip().lower() for a in (pm.group("args") or "").split(",")
                    if a.strip()]
            in_iface = bool(top and top[0] == "interface")
            proc = Proc(pm.group("name").lower(), pm.group("kind").lower(), args, st.line,
                        path, in_iface)
            proc.predoc = st.predoc
            internal = bool(top and top[0] == "proc")
            if not internal:
                if in_iface and top[2]:
                    mod.abstract.add(proc.name)
                    mod.procs.setdefault(proc.name, proc)
                elif not in_iface:
                    mod.procs[proc.name] = proc
            stack.append(("proc", proc, [False], internal))
            continue
        im = INTERFACE_RE.match(code)
        if im and not low.startswith("end"):
            stack.append(("interface", (im.group("name") or "").lower(),
                          bool(im.group("abstract"))))
            continue
        tm = TYPE_RE.match(code) or TYPE_PLAIN_RE.match(code)
        if tm and not low.startswith("type(") and not re.match(r"^\s*type\s*\(", code, re.I):
            attrs = (tm.groupdict().get("attrs") or "").lower()
            name = tm.group("name").lower()
            if "private" in attrs:
                mod.private.add(name)
            elif "public" in attrs:
                mod.public.add(name)
            stack.append(("type", name))
            in_type_contains = False
            continue
        if not stack:
            am = ACCESS_RE.match(code)
            if am:
                names = am.group("names")
                acc = am.group("access").lower()
                if names is None:
                    mod.default_public = acc == "public"
                else:
                    target = mod.public if acc == "public" else mod.private
                    target.update(x.strip().lower() for x in split_top(names))
            continue
        if top and top[0] == "proc" and not top[2][0] and not top[3] and "::" in code:
            proc = top[1]
            attrs, _, ents = code.partition("::")
            doc = " ".join(x.strip() for x in st.predoc + st.doc).strip()
            optional = "optional" in attrs.lower()
            output = re.search(r"intent\s*\(\s*out\s*\)", attrs, re.I) is not None
            typ = split_top(attrs)[0].strip().lower() if attrs.strip() else ""
            for ent in split_top(ents):
                name = re.match(r"\s*(" + IDENT + ")", ent, re.I)
                if not name:
                    continue
                name = name.group(1).lower()
                if name in proc.args:
                    proc.docs[name] = doc
                    proc.decl_line[name] = st.line
                    proc.types[name] = typ
                    if optional:
                        proc.optional.add(name)
                    if output or name == "errmsg":
                        proc.outputs.add(name)
    return mods, meta_problems


def public_procs(mod):
    """Procedures of mod reachable from outside it."""
    def is_public(name):
        if name in mod.private:
            return False
        return name in mod.public or mod.default_public
    names = set()
    for name in mod.procs:
        if is_public(name):
            names.add(name)
    for gen, specs in mod.generics.items():
        if is_public(gen):
            names.update(specs)
    for tname, targets in mod.types.items():
        if is_public(tname):
            names.update(targets)
    return sorted(n for n in names if n in mod.procs)


def check(root, listing=False, units=False):
    files = sorted((root / "src").rglob("*.f90"))
    nfail = 0
    undocumented, nodefault, meta, nounit = [], [], [], []
    nprocs = nargs = 0
    for f in files:
        mods, problems = parse_file(f)
        meta.extend(problems)
        for mod in mods:
            for pname in public_procs(mod):
                proc = mod.procs[pname]
                nprocs += 1
                if listing:
                    print(f"{f.relative_to(root)}:{proc.line}: {mod.name}::{pname}"
                          f"({', '.join(proc.args)})")
                for a in proc.args:
                    nargs += 1
                    doc = proc.docs.get(a, "")
                    where = f"{f.relative_to(root)}:{proc.decl_line.get(a, proc.line)}"
                    if listing:
                        opt = " [optional]" if a in proc.optional else ""
                        print(f"    {a}{opt}: {doc}")
                    if units and doc and proc.types.get(a, "").startswith(("real", "complex")) \
                            and not UNIT_RE.search(doc):
                        nounit.append(f"{where}: {pname}: {a}: {doc}")
                    if not doc:
                        undocumented.append(f"{where}: {pname}: {a}")
                    elif a in proc.optional and a not in proc.outputs and \
                            not DEFAULT_RE.search(doc):
                        nodefault.append(f"{where}: {pname}: {a}: {doc}")
    for name, items, why in (
            ("undocumented", undocumented, "dummy arguments without a doc comment"),
            ("no-default", nodefault, "optional arguments whose comment gives no default"),
            ("metadata", [f"{p.relative_to(root)}:{ln}: {t}" for p, ln, t in meta],
             "doc blocks FORD reads as metadata (`word: ...` first)")):
        if items:
            nfail += 1
            print(f"FAIL doc/{name}: {len(items)} {why}")
            for item in items:
                print(f"    {item}")
        else:
            print(f"ok   doc/{name}: {nprocs} public procedures, {nargs} arguments")
    nfail += check_status_codes(root)
    if units:
        print(f"note: {len(nounit)} real/complex arguments whose comment names no unit "
              "(heuristic, review aid)")
        for item in nounit:
            print(f"    {item}")
    return nfail


def check_status_codes(root):
    """The lists of status codes in README.md and doc/ford.md = the SEISPULSE_* constants
    of errors.f90."""
    src = (root / "src/seispulse/core/errors.f90").read_text(encoding="utf-8")
    codes = dict((m.group(1), int(m.group(2))) for m in re.finditer(
        r"integer,\s*parameter\s*::\s*(SEISPULSE_[A-Z_]+)\s*=\s*(\d+)", src))
    problems = []
    if not codes:
        problems.append("no SEISPULSE_* constants found in errors.f90")
    for doc in ("README.md", "doc/ford.md"):
        text = (root / doc).read_text(encoding="utf-8")
        listed = {}
        for m in re.finditer(r"`(SEISPULSE_[A-Z_]+) = (\d+)`", text):
            listed.setdefault(m.group(1), set()).add(int(m.group(2)))
        for name, value in sorted(codes.items(), key=lambda kv: kv[1]):
            if name not in listed:
                problems.append(f"{doc} lists no `{name} = {value}`")
            elif listed[name] != {value}:
                problems.append(f"{doc} gives {name} = {sorted(listed[name])}, "
                                f"errors.f90 {value}")
        for name in sorted(set(listed) - set(codes)):
            problems.append(f"{doc} lists {name}, which errors.f90 does not define")
    if problems:
        print(f"FAIL doc/status-codes: {len(problems)} differences from "
              "src/seispulse/core/errors.f90")
        for p in problems:
            print(f"    {p}")
        return 1
    print(f"ok   doc/status-codes: {len(codes)} codes, README.md and doc/ford.md as in "
          "errors.f90")
    return 0


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--root", default=str(ROOT), help="repository root")
    parser.add_argument("--list", action="store_true", help="list the public procedures")
    parser.add_argument("--units", action="store_true", help="list arguments without a unit")
    args = parser.parse_args()
    return 1 if check(Path(args.root), args.list, args.units) else 0


if __name__ == "__main__":
    sys.exit(main())
