#!/usr/bin/env python3
"""Run every seispulse test stage and print one summary (standard library only).

Stages, each run even if an earlier one failed:

  build    configure (if needed) and compile build/, then `meson test` (all suites)
  check    build-check/: debug build with -fcheck=all and floating-point traps, unit suite
  install  test/install/check_install.sh: meson install to a temp prefix, link a program
           against it with pkg-config (shared and static)
  pip      test/install/check_pip.sh: pip install into a temp dir, import from outside
  doc      tools/check_doc_comments.py (every argument of a public procedure documented,
           optional ones with their default; README's status codes = errors.f90),
           tools/check_reentrant.py (no function of src/ returns a deferred-length string:
           gfortran keeps its length in a static variable of the caller), then
           tools/make_doc.py (FORD: the HTML API reference, no warning allowed)

Counts come from meson-logs/testlog.json: a test whose output ends with our Fortran
tester's `N passed, N failed` line or with pytest's summary counts those individual
results, any other test counts as one. The install/pip scripts print `ok   <name>` /
`FAIL <name>: why` lines. The last line of output is `N passed, N failed` (`, N skipped`
when there are any); the exit status is 1 if anything failed or a stage could not run.

Usage: python tools/run_tests.py [--builddir build] [--python PATH] [--only STAGE ...]
Run it with .venv's python (`make test` does); meson, ninja and pytest are taken from
.venv/bin when it exists.
"""

import argparse
import json
import os
import re
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
VENV_BIN = ROOT / ".venv" / "bin"

CHECK_DIR = "build-check"
INSTALL_DIR = "build-install"
CHECK_FFLAGS = "-O0 -g -fcheck=all -ffpe-trap=invalid,zero,overflow"
STAGES = ("build", "check", "install", "pip", "doc")
MAIN_SUITES = ("unit", "python", "regression")

FORTRAN_RE = re.compile(r"^\s*(\d+) passed, (\d+) failed(?:, (\d+) skipped)?\s*$")
PYTEST_LINE_RE = re.compile(
    r"^=*\s*((?:\d+ [a-z]+(?:, )?)+|no tests ran)(?: in [\d.]+s(?: \([\d:]+\))?)?\s*=*\s*$")
PYTEST_ITEM_RE = re.compile(r"(\d+) ([a-z]+)")
CHECK_LINE_RE = re.compile(r"^(ok|FAIL)\s+(\S+?)(?::\s*(.*))?$")
WARNING_RE = re.compile(r"(^Warning:|: warning:)")
ANSI_RE = re.compile(r"\x1b\[[0-9;]*[A-Za-z]")
OK_RESULTS = {"OK", "EXPECTEDFAIL", "SKIP"}


class Stage:
    """Counts and notes of one stage."""

    def __init__(self, name):
        self.name = name
        self.passed = 0
        self.failed = 0
        self.skipped = 0
        self.notes = []
        self.seconds = 0.0

    def add(self, passed=0, failed=0, skipped=0):
        self.passed += passed
        self.failed += failed
        self.skipped += skipped

    def broken(self, why):
        """The stage (or a step of it) could not run: one failure."""
        self.failed += 1
        self.notes.append(why)
        print(f"*** {self.name}: {why}", flush=True)


def banner(text):
    print(f"\n==> {text}", flush=True)


def run_quiet(cmd, env, log):
    """Run cmd with its output in the file `log`, printed only if cmd fails; return its
    exit status. meson's and f2py's chatter stays out of the test output."""
    print("$ " + " ".join(str(c) for c in cmd) + f"  (output: {log})", flush=True)
    log = Path(log)
    log.parent.mkdir(parents=True, exist_ok=True)
    try:
        with open(log, "w", encoding="utf-8") as fh:
            rc = subprocess.run([str(c) for c in cmd], cwd=ROOT, env=env, stdin=subprocess.DEVNULL,
                                stdout=fh, stderr=subprocess.STDOUT).returncode
    except OSError as exc:
        print(f"cannot run {cmd[0]}: {exc}", flush=True)
        return 127
    text = log.read_text(encoding="utf-8", errors="replace")
    if rc != 0:
        sys.stdout.write(text)
    else:
        # a compiler warning stays visible even when the step succeeds (gfortran's
        # "Warning:" comes after the line it is about, gcc's ": warning:" on it)
        lines = text.splitlines()
        shown = [i for i, line in enumerate(lines) if WARNING_RE.search(line)]
        for i in shown:
            sys.stdout.write("\n".join(lines[max(0, i - 4):i + 1]) + "\n")
        if shown:
            print(f"*** {len(shown)} compiler warning(s) in {log}")
    sys.stdout.flush()
    return rc


def run(cmd, env, cwd=ROOT, capture=False):
    """Run cmd, streaming its output; return (returncode, output if capture)."""
    print("$ " + " ".join(str(c) for c in cmd), flush=True)
    try:
        if not capture:
            return subprocess.run([str(c) for c in cmd], cwd=cwd, env=env,
                                  stdin=subprocess.DEVNULL).returncode, ""
        proc = subprocess.Popen([str(c) for c in cmd], cwd=cwd, env=env, text=True,
                                stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                stderr=subprocess.STDOUT, errors="replace")
        lines = []
        for line in proc.stdout:
            sys.stdout.write(line)
            sys.stdout.flush()
            lines.append(line)
        return proc.wait(), "".join(lines)
    except OSError as exc:
        print(f"cannot run {cmd[0]}: {exc}", flush=True)
        return 127, ""


# ------------------------------------------------------------------------------------
# counting
# ------------------------------------------------------------------------------------

def parse_fortran(text):
    """Last `N passed, N failed[, N skipped]` line -> (p, f, s) or None."""
    found = None
    for line in text.splitlines():
        m = FORTRAN_RE.match(line)
        if m:
            found = (int(m.group(1)), int(m.group(2)), int(m.group(3) or 0))
    return found


def parse_pytest(text):
    """pytest's last summary line (`12 passed, 1 skipped in 0.3s`) -> (p, f, s) or None."""
    found = None
    for line in text.splitlines():
        m = PYTEST_LINE_RE.match(line.strip())
        if not m:
            continue
        counts = {}
        for num, word in PYTEST_ITEM_RE.findall(m.group(1)):
            counts[word] = counts.get(word, 0) + int(num)
        known = {"passed", "failed", "skipped", "error", "errors", "xfailed", "xpassed",
                 "deselected", "warning", "warnings", "rerun"}
        if m.group(1) != "no tests ran" and (not counts or not set(counts) <= known):
            continue
        found = (counts.get("passed", 0) + counts.get("xpassed", 0) + counts.get("xfailed", 0),
                 counts.get("failed", 0) + counts.get("error", 0) + counts.get("errors", 0),
                 counts.get("skipped", 0))
    return found


def count_test(entry):
    """(passed, failed, skipped) for one testlog.json entry."""
    result = entry.get("result", "ERROR")
    text = ANSI_RE.sub("", (entry.get("stdout") or "") + "\n" + (entry.get("stderr") or ""))
    if result == "SKIP":
        return 0, 0, 1
    if result == "EXPECTEDFAIL":       # should_fail test that failed as it should
        return 1, 0, 0
    parsed = parse_fortran(text) or parse_pytest(text)
    if parsed and sum(parsed) > 0:
        passed, failed, skipped = parsed
    elif result == "OK":
        passed, failed, skipped = 1, 0, 0
    else:
        passed, failed, skipped = 0, 1, 0
    if result not in OK_RESULTS and failed == 0:   # crash, timeout, bad exit after "0 failed"
        failed = 1
    return passed, failed, skipped


def read_testlog(path):
    entries = []
    with open(path, encoding="utf-8", errors="replace") as fh:
        for line in fh:
            line = line.strip()
            if line:
                entries.append(json.loads(line))
    return entries


# ------------------------------------------------------------------------------------
# stages
# ------------------------------------------------------------------------------------

def configured(builddir):
    return (builddir / "meson-private" / "coredata.dat").is_file() and \
        (builddir / "build.ninja").is_file()


def meson_setup(stage, env, builddir, options, always=False):
    """Configure builddir (reconfigure with the same options if it exists)."""
    if configured(builddir) and not always:
        return True
    cmd = ["meson", "setup"]
    if (builddir / "meson-private" / "coredata.dat").is_file():
        cmd.append("--reconfigure")
    rc = run_quiet(cmd + [builddir] + options, env, builddir / "meson-logs" / "setup-output.txt")
    if rc != 0:
        stage.broken(f"meson setup {builddir.name} failed (exit {rc})")
        return False
    return True


def meson_compile(stage, env, builddir):
    rc = run_quiet(["meson", "compile", "-C", builddir], env,
                   builddir / "meson-logs" / "compile-output.txt")
    if rc != 0:
        stage.broken(f"meson compile -C {builddir.name} failed (exit {rc})")
        return False
    return True


def registered_suites(env, builddir):
    """Suite names of the tests registered in builddir (None if introspection fails)."""
    try:
        out = subprocess.run(["meson", "introspect", "--tests", str(builddir)], env=env,
                             cwd=ROOT, capture_output=True, text=True, check=True).stdout
        suites = set()
        for test in json.loads(out):
            for suite in test.get("suite", []):
                suites.add(suite.split(":")[-1])
        return suites
    except (OSError, subprocess.CalledProcessError, ValueError):
        return None


def meson_test(stage, env, builddir, extra, expect_suites):
    suites = registered_suites(env, builddir)
    if suites is not None:
        for name in expect_suites:
            if name not in suites:
                stage.broken(f"no tests registered in suite '{name}' in {builddir.name}")
    log = builddir / "meson-logs" / "testlog.json"
    if log.exists():
        log.unlink()
    rc, _ = run(["meson", "test", "-C", builddir, "--print-errorlogs"] + extra, env)
    if not log.exists():
        stage.broken(f"meson test -C {builddir.name} wrote no testlog.json (exit {rc})")
        return
    try:
        entries = read_testlog(log)
    except ValueError as exc:
        stage.broken(f"cannot read {log}: {exc}")
        return
    if not entries:
        stage.broken(f"meson test -C {builddir.name} ran no test (exit {rc})")
        return
    failed_before = stage.failed
    for entry in entries:
        passed, failed, skipped = count_test(entry)
        stage.add(passed, failed, skipped)
        if failed:
            stage.notes.append(f"{entry.get('name')}: {entry.get('result')}"
                               + (f", {failed} failed" if failed > 1 else ""))
    if rc != 0 and stage.failed == failed_before:
        stage.broken(f"meson test -C {builddir.name} exited {rc} but no test failed")


def script_stage(stage, env, cmd):
    rc, out = run(cmd, env, capture=True)
    oks = fails = 0
    for line in out.splitlines():
        m = CHECK_LINE_RE.match(line.rstrip())
        if not m:
            continue
        if m.group(1) == "ok":
            oks += 1
        else:
            fails += 1
            stage.notes.append(f"{m.group(2)}: {m.group(3) or 'failed'}")
    stage.add(passed=oks, failed=fails)
    if rc != 0 and fails == 0:
        stage.broken(f"{Path(str(cmd[1])).name} exited {rc} without a FAIL line")
    elif rc == 0 and oks == 0:
        stage.broken(f"{Path(str(cmd[1])).name} reported no check")


def stage_build(stage, env, args):
    builddir = ROOT / args.builddir
    banner(f"build: configure + compile {args.builddir}/, meson test (all suites)")
    if not meson_setup(stage, env, builddir, [f"-Dpython={args.python}"]):
        return
    if not meson_compile(stage, env, builddir):
        return
    meson_test(stage, env, builddir, [], MAIN_SUITES)


def stage_check(stage, env, args):
    builddir = ROOT / CHECK_DIR
    banner(f"check: {CHECK_DIR}/ with fortran_args={CHECK_FFLAGS!r}, unit suite")
    options = ["--buildtype=debug", f"-Dfortran_args={CHECK_FFLAGS}",
               "-Dpython_ext=disabled", f"-Dpython={args.python}"]
    if not meson_setup(stage, env, builddir, options, always=True):
        return
    if not meson_compile(stage, env, builddir):
        return
    meson_test(stage, env, builddir, ["--suite", "unit", "--timeout-multiplier", "4"],
               ("unit",))


def stage_install(stage, env, args):
    banner("install: meson install to a temp prefix, link hello.f90 via pkg-config")
    script_stage(stage, env, ["bash", ROOT / "test/install/check_install.sh", INSTALL_DIR])


def stage_pip(stage, env, args):
    banner("pip: pip install --no-build-isolation --target <tmp> ., import outside the tree")
    script_stage(stage, dict(env, PYTHON=args.python),
                 ["bash", ROOT / "test/install/check_pip.sh"])


def stage_doc(stage, env, args):
    banner("doc: doc-comment checker, reentrancy check, FORD API reference")
    script_stage(stage, env, [args.python, ROOT / "tools/check_doc_comments.py"])
    script_stage(stage, env, [args.python, ROOT / "tools/check_reentrant.py", "--builddir",
                              args.builddir])
    script_stage(stage, env, [args.python, ROOT / "tools/make_doc.py", "--builddir",
                              args.builddir])


def make_env(python):
    env = dict(os.environ)
    path = [str(Path(python).parent)]
    if VENV_BIN.is_dir():
        path.append(str(VENV_BIN))
    env["PATH"] = os.pathsep.join(path + [env.get("PATH", "")])
    env["PYTHONDONTWRITEBYTECODE"] = "1"       # no __pycache__ in the source tree
    env["PYTEST_ADDOPTS"] = (env.get("PYTEST_ADDOPTS", "") + " -p no:cacheprovider").strip()
    return env


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--builddir", default="build", help="main build dir (default build)")
    default_python = VENV_BIN / "python"
    parser.add_argument("--python", default=str(default_python if default_python.exists()
                                                  else Path(sys.executable)),
                        help="interpreter for the f2py extension and pip (default .venv's)")
    parser.add_argument("--only", nargs="+", choices=STAGES, help="run these stages only")
    args = parser.parse_args()
    args.python = os.path.abspath(args.python)    # no realpath: keep the venv's own path
    env = make_env(args.python)

    funcs = {"build": stage_build, "check": stage_check, "install": stage_install,
             "pip": stage_pip, "doc": stage_doc}
    stages = []
    for name in args.only or STAGES:
        stage = Stage(name)
        start = time.monotonic()
        try:
            funcs[name](stage, env, args)
        except Exception as exc:                 # a bug here must not hide the other stages
            stage.broken(f"run_tests.py error: {exc!r}")
        stage.seconds = time.monotonic() - start
        stages.append(stage)

    total_p = sum(s.passed for s in stages)
    total_f = sum(s.failed for s in stages)
    total_s = sum(s.skipped for s in stages)
    print("\n==> summary")
    print(f"{'stage':<9}{'passed':>8}{'failed':>8}{'skipped':>9}{'time':>8}")
    for s in stages:
        print(f"{s.name:<9}{s.passed:>8}{s.failed:>8}{s.skipped:>9}{s.seconds:>7.0f}s")
        for note in s.notes:
            print(f"    {note}")
    line = f"{total_p} passed, {total_f} failed"
    if total_s:
        line += f", {total_s} skipped"
    print(line, flush=True)
    return 1 if total_f else 0


if __name__ == "__main__":
    sys.exit(main())
