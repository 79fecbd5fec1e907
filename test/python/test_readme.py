"""Every fenced block of README.md runs as written, or is listed in NOT_RUN with the reason.

Each block is classified by its tag (the word after the opening fence):

* ``python``: run alone, in a fresh interpreter (this one, with its PYTHONPATH), in a
  temporary working directory that holds a copy of the repository's ``input/`` (so
  ``input/records/quake_a.AT2`` reads as it does from the source tree). A ``text`` block
  that follows it and is introduced by a line starting with "prints" is its exact output.
* ``fortran``: a complete program (``program`` ... ``end program``) compiled against the
  build tree's library and ``.mod`` files and run; it must exit with status 0.
* ``namelist``: a complete input (it has ``&run``) is run by the driver; it must exit
  with status 0 and write its tables (a ``records/`` path is relative to the input file,
  which is written into the copy of ``input/``).
* ``sh``: each command (comments dropped) ``seispulse <file.nml>`` is run by the driver
  as above; every other command is listed in NOT_RUN.
* ``text``: program output, error messages and listings: not code, never run.

A block with no tag or another tag fails (tag it); a python, fortran or namelist block
that is not run, and every sh command that is not a driver run, must be listed in
NOT_RUN, and every entry of NOT_RUN must still match a block, so a new block is never
skipped silently and a stale entry is noticed.
"""
import importlib.util
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(os.environ.get("SEISPULSE_SOURCE_ROOT", Path(__file__).resolve().parents[2]))
README = ROOT / "README.md"
TAGS = ("python", "fortran", "namelist", "sh", "text")

#: Blocks (python, fortran, namelist: by their first line) and sh commands that are not
#: run, with the reason. A key ending in '*' matches by prefix.
NOT_RUN = {
    ("sh", "make run"): "builds the project; its driver run is input/example.nml, run here "
                        "as `seispulse input/example.nml`",
    ("sh", "make test"): "runs the test suite this test is part of",
    ("sh", "OMP_NUM_THREADS=4 seispulse input/newmark_example.nml"):
        "a driver run on threads: test_driver_restart.py compares the tables and standard "
        "error of 2 threads with those of one",
    ("sh", "meson setup build -Dpython=$(which python3)"):
        "configures the build this test runs in (make build does the same)",
    ("sh", "meson compile -C build"): "compiles the build this test runs in",
    ("sh", "export PKG_CONFIG_PATH=*"):
        "needs a `meson install`ed library: test/install/check_install.sh installs one and "
        "links a program through pkg-config; the program itself is compiled here against "
        "the build tree",
    ("sh", "libdir=$(pkg-config --variable=libdir seispulse)"):
        "as the line above: the libdir of an installed library",
    ("sh", "gfortran design_check.f90 *"):
        "links against an installed library: check_install.sh links a program through "
        "pkg-config, shared and static, and runs it; design_check itself is compiled here "
        "against the build tree",
    ("sh", "-o design_check"): "the continuation line of the gfortran commands above",
    ("sh", "$(pkg-config --static --libs seispulse*"):
        "the continuation line of the static link above (check_install.sh links statically)",
    ("sh", "./design_check"): "runs the program linked above against an installed library",
    ("sh", "LD_LIBRARY_PATH=$libdir ./design_check"):
        "as the line above, finding the shared library through LD_LIBRARY_PATH",
    ("sh", "make doc"): "the `doc` stage of make test runs the same (tools/make_doc.py)",
    ("sh", "export PATH=$PWD/.venv/bin:$PATH"):
        "changes the user's shell; the tests call .venv/bin/meson by its path",
    ("sh", "meson configure build --prefix=$HOME/.local"):
        "reconfigures the user's build directory: check_install.sh configures a separate "
        "build with a temporary --prefix and installs it",
    ("sh", "meson install -C build"):
        "installs into the user's prefix (check_install.sh installs into a temporary one)",
    ("sh", "PYTHONPATH=build/python python3 bench/*"):
        "a benchmark: minutes per run, timing figures, and peer programs to compare with",
    ("sh", "export OMP_NUM_THREADS=1"): "changes the user's shell (the MPI runs of the tests "
                                       "set it for mpirun)",
    ("sh", "mpirun -n *"): "an MPI job: test_driver_mpi.py runs the driver with mpirun over 2 "
                           "and 3 ranks and compares every file with the one-process run",
    ("sh", "srun *"): "a Slurm job step: needs a Slurm cluster (the MPI runs of the tests use "
                      "mpirun)",
    ("namelist", "&run analysis = 'newmark', output = 'out/case' /"):
        "the key reference of &records and &newmark (values such as `...`), not an input",
    ("namelist", "&run analysis = 'empirical', output = 'out/case' /"):
        "the key reference of &empirical (with `&records ... /`), not an input",
    ("namelist", "&sdof"): "the key reference of &sdof and &sdof_history, not an input",
}


class Block:
    """One fenced block: its ordinal, opening line (1-based), tag, text, and the prose
    between the previous block (or the section start) and this one."""

    def __init__(self, number, line, tag, text, prose):
        self.number, self.line, self.tag, self.text, self.prose = number, line, tag, text, prose

    @property
    def first(self):
        for line in self.text.splitlines():
            if line.strip():
                return line.strip()
        return ""

    @property
    def name(self):
        return f"L{self.line}-{self.tag or 'untagged'}"


def read_blocks(path=README):
    lines = path.read_text(encoding="utf-8").splitlines()
    blocks, prose, i = [], [], 0
    while i < len(lines):
        m = re.match(r"^(`{3,})\s*([^`\s]*)\s*$", lines[i])
        if not m:
            prose.append(lines[i])
            i += 1
            continue
        fence, tag, j = m.group(1), m.group(2), i + 1
        while j < len(lines) and not lines[j].startswith(fence):
            j += 1
        if j == len(lines):
            raise AssertionError(f"README.md:{i + 1}: the fenced block is never closed")
        blocks.append(Block(len(blocks) + 1, i + 1, tag, "\n".join(lines[i + 1:j]) + "\n",
                            "\n".join(prose).strip()))
        prose = []
        i = j + 1
    return blocks


BLOCKS = read_blocks()


def sh_commands(block):
    """The commands of an sh block: one per line, comments and blank lines dropped."""
    out = []
    for line in block.text.splitlines():
        cmd = re.sub(r"\s+#.*$", "", line).strip()
        if cmd and not cmd.startswith("#"):
            out.append(cmd)
    return out


def driver_input(cmd):
    """The input file of a driver command `seispulse <file.nml>`, else None."""
    m = re.fullmatch(r"seispulse\s+(\S+\.nml)", cmd)
    return m.group(1) if m else None


def output_block(index):
    """The text block that shows the output of BLOCKS[index] (a python block), or None."""
    if index + 1 < len(BLOCKS):
        nxt = BLOCKS[index + 1]
        if nxt.tag == "text" and nxt.prose.startswith("prints"):
            return nxt
    return None


# ------------------------------------------------------------------ classification

def not_run_keys(b):
    """What of block b is not run: sh commands other than driver runs, the first line of
    an incomplete fortran or namelist block; [] when all of it runs."""
    if b.tag == "sh":
        return [c for c in sh_commands(b) if driver_input(c) is None]
    if b.tag == "fortran" and not re.search(r"(?im)^\s*end\s+program\b", b.text):
        return [b.first]
    if b.tag == "namelist" and (not re.search(r"(?im)^\s*&run\b", b.text) or "..." in b.text):
        return [b.first]
    return []


def classification_errors(blocks):
    """Problems of the classification: unknown tags, blocks or commands neither run nor
    in NOT_RUN, entries of NOT_RUN that match nothing."""
    bad, used = [], set()
    for b in blocks:
        if b.tag not in TAGS:
            bad.append(f"README.md:{b.line}: block tagged {b.tag!r}: tag it as one of "
                       f"{', '.join(TAGS)} (first line: {b.first!r})")
            continue
        for key in not_run_keys(b):
            matched = [k for k in NOT_RUN if k[0] == b.tag and (
                key == k[1] or k[1].endswith("*") and key.startswith(k[1][:-1]))]
            if not matched:
                bad.append(f"README.md:{b.line}: {b.tag} {key!r} is neither run nor listed "
                           "in NOT_RUN of test_readme.py")
            used.update(matched)
    bad += [f"NOT_RUN entry {k!r} matches no block of README.md" for k in NOT_RUN
            if k not in used]
    return bad


def test_every_block_is_classified():
    """Every block has a known tag; whatever is not run is listed with its reason, and
    every entry of NOT_RUN matches a block."""
    assert BLOCKS, "README.md has no fenced block"
    bad = classification_errors(BLOCKS)
    assert not bad, "\n".join(bad)


def test_classification_catches_new_blocks(tmp_path):
    """An untagged block, an unknown tag, an unlisted command and an incomplete input are
    reported; the blocks of a README that has only runnable blocks are not."""
    readme = tmp_path / "README.md"
    readme.write_text("# t\n\n```\nx\n```\n\n```bash\nls\n```\n\n```sh\nrm -rf out  # c\n"
                      "seispulse input/example.nml\n```\n\n```namelist\n&pulse /\n```\n"
                      "```python\nprint(1)\n```\nprints\n\n```text\n1\n```\n", encoding="utf-8")
    blocks = read_blocks(readme)
    assert [(b.tag, b.line) for b in blocks] == [("", 3), ("bash", 7), ("sh", 11),
                                                 ("namelist", 16), ("python", 19),
                                                 ("text", 24)]
    assert blocks[5].prose == "prints" and blocks[2].first == "rm -rf out  # c"
    bad = "\n".join(classification_errors(blocks))
    assert "README.md:3: block tagged ''" in bad and "README.md:7: block tagged 'bash'" in bad
    assert "README.md:11: sh 'rm -rf out' is neither run" in bad
    assert "README.md:16: namelist '&pulse /' is neither run" in bad
    assert "matches no block" in bad
    assert sh_commands(blocks[2]) == ["rm -rf out", "seispulse input/example.nml"]


def runnable(tag):
    """The blocks of this tag that run (all of a python block; a complete program or
    input; an sh block with a driver command)."""
    out = []
    for i, b in enumerate(BLOCKS):
        if b.tag != tag:
            continue
        if tag == "sh" and not any(driver_input(c) for c in sh_commands(b)):
            continue
        if tag in ("fortran", "namelist") and not_run_keys(b):
            continue
        out.append(pytest.param(i, id=b.name))
    return out


@pytest.fixture
def workdir(tmp_path):
    """A working directory with a copy of the repository's input/ (records included)."""
    shutil.copytree(ROOT / "input", tmp_path / "input")
    return tmp_path


def build_dir():
    drv = os.environ.get("SEISPULSE_DRIVER")
    if not drv or not Path(drv).exists():
        pytest.skip("SEISPULSE_DRIVER not set: run through `meson test` or `make test`")
    return Path(drv).resolve().parent.parent


def run_driver(driver, nml, cwd, where):
    proc = subprocess.run([driver, nml], cwd=cwd, capture_output=True, text=True, timeout=600,
                          stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, f"{where}: seispulse {nml} exited {proc.returncode}:\n" \
                                 f"{proc.stderr}{proc.stdout[-2000:]}"
    assert "written to" in proc.stdout, f"{where}: no table written:\n{proc.stdout[-2000:]}"
    return proc


# ------------------------------------------------------------------ python

#: Optional packages a python block needs when it uses these names.
OPTIONAL = {"records.sample(": "pyslammer", "plot": "matplotlib", "to_frame(": "pandas",
            "import dask": "dask", "dask.distributed": "distributed"}


@pytest.mark.parametrize("index", runnable("python"))
def test_python_block(index, workdir):
    b = BLOCKS[index]
    for use, package in OPTIONAL.items():
        if use in b.text and importlib.util.find_spec(package) is None:
            pytest.skip(f"README.md:{b.line} uses {use}...: needs {package} (pip install "
                        f"{package})")
    script = workdir / f"readme_block_{b.number}.py"
    script.write_text(b.text, encoding="utf-8")
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONDONTWRITEBYTECODE="1")
    proc = subprocess.run([sys.executable, script.name], cwd=workdir, env=env,
                          capture_output=True, text=True, timeout=900, stdin=subprocess.DEVNULL)
    assert proc.returncode == 0, (f"README.md:{b.line}: the python block fails:\n"
                                  f"{proc.stderr[-4000:]}")
    shown = output_block(index)
    if shown is not None:
        assert proc.stdout == shown.text, (f"README.md:{shown.line}: the output shown is not "
                                           f"what README.md:{b.line} prints:\n{proc.stdout}")


# ------------------------------------------------------------------ fortran

@pytest.mark.parametrize("index", runnable("fortran"))
def test_fortran_block(index, workdir):
    b = BLOCKS[index]
    m = re.search(r"(?im)^\s*program\s+(\w+)", b.text)
    assert m, f"README.md:{b.line}: no program statement"
    build = build_dir()
    mods = sorted(build.glob("*.p/seispulse.mod"))
    libs = sorted(build.glob("libseispulse.so*")) + sorted(build.glob("libseispulse.a"))
    if not mods or not libs:
        pytest.skip(f"no seispulse.mod or libseispulse in {build}")
    fc = shutil.which(os.environ.get("FC", "gfortran"))
    if fc is None:
        pytest.skip("no Fortran compiler (gfortran) on PATH")
    src = workdir / f"{m.group(1)}.f90"
    src.write_text(b.text, encoding="utf-8")
    exe = workdir / m.group(1)
    # shared library when there is one (rpath to the build tree), else the static one
    if any(".so" in p.name for p in libs):
        link = [f"-L{build}", "-lseispulse", f"-Wl,-rpath,{build}"]
    else:
        link = [str(build / "libseispulse.a"), "-llapack", "-fopenmp"]
    cmd = [fc, src.name, f"-I{mods[0].parent}", *link, "-o", exe.name]
    comp = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True, timeout=300)
    assert comp.returncode == 0, f"README.md:{b.line}: {' '.join(cmd)}:\n{comp.stderr}"
    proc = subprocess.run([str(exe)], cwd=workdir, capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, (f"README.md:{b.line}: the program exits {proc.returncode}:\n"
                                  f"{proc.stdout}{proc.stderr}")


# ------------------------------------------------------------------ namelist, sh

@pytest.mark.parametrize("index", runnable("namelist"))
def test_namelist_block(index, workdir, driver):
    b = BLOCKS[index]
    nml = workdir / "input" / f"readme_block_{b.number}.nml"
    nml.write_text(b.text, encoding="utf-8")
    run_driver(driver, str(nml.relative_to(workdir)), workdir, f"README.md:{b.line}")


@pytest.mark.parametrize("index", runnable("sh"))
def test_sh_block(index, workdir, driver):
    b = BLOCKS[index]
    for cmd in sh_commands(b):
        nml = driver_input(cmd)
        if nml is not None:      # the other commands: NOT_RUN (test_every_block_is_classified)
            assert (workdir / nml).is_file(), f"README.md:{b.line}: {nml} does not exist"
            run_driver(driver, nml, workdir, f"README.md:{b.line}")


def test_output_blocks_follow_python():
    """A text block introduced by "prints" shows the output of the python block before
    it (compared in test_python_block)."""
    for i, b in enumerate(BLOCKS):
        if b.tag == "text" and b.prose.startswith("prints"):
            assert i > 0 and BLOCKS[i - 1].tag == "python", \
                f"README.md:{b.line}: an output block that follows no python block"
