#!/usr/bin/env python3
"""Generate the HTML API reference of the Fortran library with FORD (`make doc`).

Steps: install FORD into the running interpreter's environment if it is missing (pip, the
`ford` package from PyPI; `make doc` runs this with .venv's python); copy the theory pages
doc/*.md into <builddir>/doc/pages with the title line FORD needs (doc/README.md becomes
the index, links between pages point to the HTML pages); run FORD on doc/ford.md (src/ only)
with the output in <builddir>/doc/api. Any warning or error of FORD is a failure: every
source file must parse and no doc comment may be read as FORD metadata.

Prints `ok   doc/ford: ...` or `FAIL doc/ford: why` (the form tools/run_tests.py counts)
and exits 1 on failure.

Usage: python tools/make_doc.py [--builddir build] [--no-install]
"""

import argparse
import importlib.util
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
FORD_SPEC = "ford>=7,<8"
LINK_RE = re.compile(r"\]\((?!https?:|#)([A-Za-z0-9_-]+)\.md(#[^)]*)?\)")
ANSI_RE = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")


def ensure_ford(install):
    if importlib.util.find_spec("ford") is not None:
        return True
    if not install:
        print("FAIL doc/ford: FORD is not installed (pip install ford)")
        return False
    print(f"doc: pip install '{FORD_SPEC}' into {sys.prefix}", flush=True)
    rc = subprocess.run([sys.executable, "-m", "pip", "install", "-q",
                         "--disable-pip-version-check", FORD_SPEC]).returncode
    if rc != 0:
        print(f"FAIL doc/ford: pip install {FORD_SPEC} failed (exit {rc})")
        return False
    return True


def write_pages(pages):
    """doc/*.md -> pages/ with a `title:` line; doc/README.md is the index."""
    if pages.exists():
        shutil.rmtree(pages)
    pages.mkdir(parents=True)
    names = []
    for src in sorted((ROOT / "doc").glob("*.md")):
        if src.name == "ford.md":
            continue
        text = src.read_text(encoding="utf-8")
        lines = text.splitlines()
        title = src.stem
        if lines and lines[0].startswith("# "):
            title = lines[0][2:].strip()
            lines = lines[1:]
        body = "\n".join(lines)
        body = LINK_RE.sub(lambda m: f"]({'index' if m.group(1) == 'README' else m.group(1)}"
                           f".html{m.group(2) or ''})", body)
        dest = "index.md" if src.name == "README.md" else src.name
        if dest != "index.md":
            names.append(dest)
        (pages / dest).write_text(f"title: {title}\n\n{body}\n", encoding="utf-8")
    index = pages / "index.md"
    if not index.exists():
        index.write_text("title: Theory\n\n", encoding="utf-8")
    # the menu order of the index's table, then the rest
    text = index.read_text(encoding="utf-8")
    order = [m + ".md" for m in re.findall(r"\]\(([A-Za-z0-9_-]+)\.html", text)]
    order = list(dict.fromkeys(o for o in order if o in names)) + \
        [n for n in names if n not in order]
    head, _, rest = text.partition("\n")
    index.write_text(head + "\nordered_subpage: " + "\n    ".join(order) + "\n" + rest,
                     encoding="utf-8")
    return len(names) + 1


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--builddir", default="build", help="build directory (default build)")
    parser.add_argument("--no-install", action="store_true", help="never pip install FORD")
    args = parser.parse_args()
    builddir = (ROOT / args.builddir).resolve()
    out = builddir / "doc" / "api"
    pages = builddir / "doc" / "pages"
    start = time.monotonic()
    if not ensure_ford(not args.no_install):
        return 1
    npages = write_pages(pages)
    if out.exists():
        shutil.rmtree(out)
    log = builddir / "doc" / "ford-output.txt"
    cmd = [sys.executable, "-m", "ford", "--quiet", "-o", str(out), "-p", str(pages),
           str(ROOT / "doc" / "ford.md")]
    print("$ " + " ".join(cmd) + f"  (output: {log})", flush=True)
    proc = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, errors="replace")
    text = ANSI_RE.sub("", proc.stdout + proc.stderr)
    log.write_text(text, encoding="utf-8")
    bad = [ln for ln in text.splitlines()
           if re.search(r"\b(warning|error)\b", ln, re.IGNORECASE)]
    seconds = time.monotonic() - start
    if proc.returncode != 0 or bad or not (out / "index.html").is_file():
        sys.stdout.write(text)
        why = f"exit {proc.returncode}" if proc.returncode else f"{len(bad)} warning/error lines"
        print(f"FAIL doc/ford: FORD on doc/ford.md: {why} (log {log})")
        return 1
    nproc = len(list((out / "proc").glob("*.html"))) if (out / "proc").is_dir() else 0
    nmod = len(list((out / "module").glob("*.html"))) if (out / "module").is_dir() else 0
    print(f"ok   doc/ford: {nmod} modules, {nproc} procedure pages, {npages} theory pages, "
          f"{seconds:.0f} s")
    print(f"API reference: {out / 'index.html'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
