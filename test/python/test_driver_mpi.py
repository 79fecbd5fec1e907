"""Batch driver built with MPI: a run over 2 (and 3) ranks writes the same files as the
one-process run, byte for byte: every table (.txt, .csv) and the echo of the input, and
nothing else (no stray or temporary file of a worker); standard output and the driver's
stderr lines are the same, and so is the exit status.

The newmark case has 16 records whose lengths differ 15-fold (the synthetic records of
input/records, each repeated 1 to 10 times), so that the ranks finish their units in an
order unlike the serial one; the sdof case (12 records, lengths differing 6-fold) writes
its three tables (spectra, envelope, histories). A third case has a record that cannot be read (exit status 1, its rows
failed, the others computed).

Skipped only when the driver was built without MPI (meson option mpi: the driver's
sources in build/meson-info, else whether the executable links libmpi)."""
import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

TIMEOUT = 600


def built_with_mpi(driver):
    """Whether the driver executable is the MPI build (parallel_mpi.f90 compiled in)."""
    driver = Path(driver).resolve()
    info = driver.parent.parent / "meson-info" / "intro-targets.json"
    if info.is_file():
        for target in json.loads(info.read_text()):
            files = [Path(f).resolve() for f in target.get("filename", [])]
            if driver in files:
                sources = [s for group in target.get("target_sources", [])
                           for s in group.get("sources", [])]
                return any(Path(s).name == "parallel_mpi.f90" for s in sources)
    return b"libmpi" in driver.read_bytes()


@pytest.fixture(scope="module")
def mpi_driver(driver):
    if not built_with_mpi(driver):
        pytest.skip("the driver is built without MPI (meson -Dmpi=disabled or no MPI found)")
    return driver


@pytest.fixture(scope="module")
def launcher(mpi_driver):
    """The mpirun command line before the number of ranks, and its environment."""
    exe = shutil.which("mpirun") or shutil.which("mpiexec")
    assert exe, "the driver is built with MPI but there is no mpirun or mpiexec on PATH"
    version = subprocess.run([exe, "--version"], capture_output=True, text=True,
                             timeout=60).stdout
    cmd = [exe]
    env = dict(os.environ, OMP_NUM_THREADS="1")
    if "Open MPI" in version or "OpenRTE" in version:
        # more ranks than cores; as root (CI containers); Open MPI 4.1 reads these too
        cmd.append("--oversubscribe")
        env.update(OMPI_MCA_rmaps_base_oversubscribe="1",
                   OMPI_MCA_btl_vader_single_copy_mechanism="none")
        if os.geteuid() == 0:
            cmd.append("--allow-run-as-root")
            env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    return cmd, env


def read_accel_g(path):
    """Accelerations (g) and dt (s) of one of the synthetic records of input/records."""
    lines = path.read_text().splitlines()
    if path.suffix == ".AT2":
        dt = float(re.search(r"DT=\s*([0-9.]+)", lines[3]).group(1))
        return [float(x) for line in lines[4:] for x in line.split()], dt
    rows = [line.replace(",", " ").split() for line in lines
            if line.strip() and not line.lstrip().startswith("#")]
    if len(rows[0]) == 1:       # quake_c: one column, cm/s2, dt 0.005 s
        return [float(r[0]) / 980.665 for r in rows], 0.005
    factor = 1.0 / 9.80665 if path.suffix == ".dat" else 1.0   # quake_d: m/s2
    return [float(r[1]) * factor for r in rows], float(rows[1][0]) - float(rows[0][0])


def make_records(source_root, where, count=16, longest=10):
    """`count` one-column records (g) in where/records: the synthetic records, each repeated
    1 to `longest` times; returns their names and dt."""
    bases = sorted((source_root / "input" / "records").glob("quake_*"))
    repeats = [min(r, longest) for r in [1, 10, 3, 7, 2, 9, 1, 5, 8, 1, 4, 10, 6, 2, 1, 3]]
    (where / "records").mkdir(parents=True)
    names, dts = [], []
    for k in range(count):
        accel, dt = read_accel_g(bases[k % len(bases)])
        name = f"rec{k:02d}_{bases[k % len(bases)].stem}_x{repeats[k]}.txt"
        text = "".join(f"{a:.6e}\n" for a in accel * repeats[k])
        (where / "records" / name).write_text(text)
        names.append(name)
        dts.append(dt)
    return names, dts


def records_group(names, dts, extra=""):
    files = ", ".join(f"'records/{n}'" for n in names)
    return (f"&records\n  files = {files}\n  format = 'column'\n  units = 'g'\n"
            f"  dt = {', '.join(repr(d) for d in dts)}\n  target_pga = 0.3\n{extra}/\n")


def newmark_input(names, dts):
    return ("&run analysis = 'newmark', output = 'out/case' /\n"
            + records_group(names, dts)
            + "&newmark\n  ky = 0.02, 0.05, 0.1, 0.15, 0.2\n  mode = 'both'\n"
              "  intensity = .true.\n  sa_periods = 0.2, 1.0\n/\n")


def sdof_input(names, dts):
    return ("&run analysis = 'sdof', output = 'out/case' /\n"
            + records_group(names, dts)
            + "&sdof\n  period_range = 0.05, 3.0\n  period_count = 12\n  spacing = 'log'\n"
              "  damping = 0.02, 0.05\n  envelope = .true.\n  shape = .true.\n/\n"
              "&sdof_history\n  periods = 0.5\n  damping = 0.05\n/\n")


def driver_lines(stderr, analysis):
    """The driver's own stderr lines (not the launcher's)."""
    return [line for line in stderr.splitlines()
            if line.startswith((f"{analysis}:", "seispulse:"))]


def tree(root):
    return {str(p.relative_to(root)): p.read_bytes() for p in sorted(root.rglob("*"))
            if p.is_file()}


def compare_runs(tmp_path, source_root, driver, launcher, ranks, analysis, text, names,
                 expect_status):
    """Run `text` serially and on `ranks` ranks, each in a directory of its own holding the
    same records; the files of the two directories must be identical."""
    cmd, env = launcher
    runs = {}
    for mode in ("serial", "mpi"):
        where = tmp_path / mode
        shutil.copytree(tmp_path / "records", where / "records")
        (where / "case.nml").write_text(text)
        argv = [driver, "case.nml"]
        if mode == "mpi":
            argv = cmd + ["-n", str(ranks)] + argv
        runs[mode] = subprocess.run(argv, cwd=where, capture_output=True, text=True,
                                    env=env, timeout=TIMEOUT)
    serial, mpi = runs["serial"], runs["mpi"]
    assert serial.returncode == expect_status, serial.stderr
    assert mpi.returncode == expect_status, mpi.stderr
    files_serial, files_mpi = tree(tmp_path / "serial"), tree(tmp_path / "mpi")
    assert sorted(files_mpi) == sorted(files_serial)
    outputs = [f for f in files_serial if f.startswith("out/")]
    assert any(f.endswith(".txt") for f in outputs)
    assert any(f.endswith(".csv") for f in outputs)
    assert "out/case_input.nml" in outputs
    for name in files_serial:
        assert files_mpi[name] == files_serial[name], f"{name} differs"
    # every record is in the tables
    table = files_serial[f"out/case_{analysis}.csv"].decode()
    for n in names:
        assert Path(n).stem in table
    assert mpi.stdout == serial.stdout
    assert driver_lines(mpi.stderr, analysis) == driver_lines(serial.stderr, analysis)
    return files_serial


@pytest.mark.parametrize("ranks", [2, 3])
def test_newmark_over_ranks(tmp_path, source_root, mpi_driver, launcher, ranks):
    names, dts = make_records(source_root, tmp_path)
    lengths = [len((tmp_path / "records" / n).read_text().splitlines()) for n in names]
    assert len(names) >= 12 and max(lengths) >= 10 * min(lengths)
    files = compare_runs(tmp_path, source_root, mpi_driver, launcher, ranks, "newmark",
                         newmark_input(names, dts), names, 0)
    assert "out/case_intensity.csv" in files


def test_sdof_over_ranks(tmp_path, source_root, mpi_driver, launcher):
    names, dts = make_records(source_root, tmp_path, count=12, longest=4)
    files = compare_runs(tmp_path, source_root, mpi_driver, launcher, 2, "sdof",
                         sdof_input(names, dts), names, 0)
    for table in ("sdof", "sdof_envelope", "sdof_history"):
        assert f"out/case_{table}.txt" in files and f"out/case_{table}.csv" in files


def test_newmark_failed_record_over_ranks(tmp_path, source_root, mpi_driver, launcher):
    names, dts = make_records(source_root, tmp_path, count=12)
    (tmp_path / "records" / names[5]).write_text("not a number\n")
    files = compare_runs(tmp_path, source_root, mpi_driver, launcher, 2, "newmark",
                         newmark_input(names, dts), names, 1)
    assert "failed" in files["out/case_newmark.csv"].decode()


def test_one_process_without_launcher(tmp_path, source_root, mpi_driver, launcher):
    """Without a launcher the MPI build is a one-process run that does not start MPI (the
    snapshot and regression checks compare its tables with the serial build's); a 1-rank
    MPI job writes the same files."""
    cmd, env = launcher
    plain = {k: v for k, v in env.items()
             if not k.startswith(("OMPI_COMM_WORLD", "PMIX_", "PMI_", "SLURM_", "MV2_"))}
    runs = {}
    for mode in ("plain", "mpi"):
        where = tmp_path / mode
        shutil.copytree(source_root / "input", where / "input")
        argv = [mpi_driver, "input/sdof_example.nml"]
        if mode == "mpi":
            argv = cmd + ["-n", "1"] + argv
        runs[mode] = subprocess.run(argv, cwd=where, capture_output=True, text=True,
                                    env=plain, timeout=TIMEOUT)
        assert runs[mode].returncode == 0, runs[mode].stderr
    assert runs["mpi"].stdout == runs["plain"].stdout
    assert "sdof spectra written to" in runs["plain"].stdout
    files_plain, files_mpi = tree(tmp_path / "plain"), tree(tmp_path / "mpi")
    assert sorted(files_mpi) == sorted(files_plain)
    assert "out/sdof_example_sdof_history.csv" in files_plain
    for name in files_plain:
        assert files_mpi[name] == files_plain[name], f"{name} differs"
