"""Batch driver: the echo of the effective input. It goes to out/<base>_input.nml (the
table name 'input' with extension .nml), holds only the keys the input gave (no NaN, no
padded strings), is a valid namelist that re-runs the same analysis to the same tables,
and goes to standard output too only with verbose = .true. in &run."""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from driver_echo import echo_path, echo_text, with_output

SOURCE = Path(__file__).resolve().parents[2]
INPUTS = sorted((SOURCE / "input").glob("*.nml"))


def run(driver, cwd, path):
    return subprocess.run([driver, str(path)], cwd=cwd, capture_output=True, text=True,
                          timeout=600)


def written(stdout):
    """Every table file named on stdout ("... written to a and b")."""
    files = []
    for line in stdout.splitlines():
        if " written to " in line and not line.startswith("effective input"):
            files += re.split(r" and |, ", line.split(" written to ", 1)[1])
    return files


def body(path):
    """The lines of a table without its header comments."""
    return [ln for ln in Path(path).read_text().splitlines() if not ln.startswith("#")]


def given_keys(text):
    """{group: [keys]} of a namelist text (comments dropped)."""
    text = re.sub(r"!.*", "", text)
    out = {}
    for m in re.finditer(r"&(\w+)(.*?)/", text, flags=re.S):
        keys = re.findall(r"(\w+)\s*(?:\([^)]*\))?\s*=", re.sub(r"'[^']*'", "''", m.group(2)))
        out[m.group(1).lower()] = sorted(k.lower() for k in keys)
    return out


@pytest.mark.parametrize("nml", INPUTS, ids=[p.stem for p in INPUTS])
def test_every_example_echo_reruns_to_the_same_tables(driver, tmp_path, nml):
    """Run the example, then its echo file where it lies (record paths relative to it)
    with another prefix: the same exit status, the same tables, line for line."""
    shutil.copytree(SOURCE / "input", tmp_path / "input")
    work = tmp_path / "work"
    work.mkdir()
    proc = run(driver, work, Path("..") / "input" / nml.name)
    assert proc.returncode in (0, 1), proc.stderr
    path = echo_path(work, proc.stdout)
    text = path.read_text()
    out = re.search(r"output = '([^']*)'", text).group(1)
    assert path == work / f"{out}_input.nml"
    # only what is set: no NaN, no padded strings, the keys of the input
    assert "nan" not in text.lower()
    assert not re.search(r"[^=,\s] +'", text), "a string padded with blanks"
    assert max(len(ln) for ln in text.splitlines()[1:]) <= 100
    assert given_keys(text) == given_keys(nml.read_text())
    # the echo re-runs the same analysis
    rerun = path.with_name("rerun.nml")
    rerun.write_text(with_output(text, out, out + "_again"))
    proc2 = run(driver, work, rerun.relative_to(work))
    assert proc2.returncode == proc.returncode, proc2.stderr
    assert proc2.stderr.count("warning") == proc.stderr.count("warning"), proc2.stderr
    tables, tables2 = written(proc.stdout), written(proc2.stdout)
    assert tables and len(tables2) == len(tables)
    # the same tables in the same order, under the other prefix (the file names follow
    # the overlap rule of the output prefix and the table name, so they may differ more)
    for first, again in zip(tables, tables2):
        assert Path(again).name.startswith(Path(out + "_again").name), (first, again)
        assert Path(first).suffix == Path(again).suffix
        assert body(work / first) == body(work / again), first


def test_verbose_echoes_on_stdout_too(driver, tmp_path):
    text = ("&run analysis = 'pulse', output = 'p', verbose = .true. /\n"
            "&pulse kind = 'half_sine', amp = 0.3, amp_unit = 'g', duration = 0.25 /\n")
    (tmp_path / "a.nml").write_text(text)
    proc = run(driver, tmp_path, "a.nml")
    assert proc.returncode == 0, proc.stderr
    echo = echo_text(tmp_path, proc.stdout)
    expected = ("&run\n    analysis = 'pulse'\n    output = 'p'\n    verbose = .true.\n/\n"
                "&pulse\n    kind = 'half_sine'\n    amp = 0.3\n    amp_unit = 'g'\n"
                "    duration = 0.25\n/\n")
    assert echo.split("\n", 1)[1] == expected
    assert echo.startswith("! effective input of a.nml")
    assert expected in proc.stdout
    # without verbose: only the "written to" lines
    (tmp_path / "b.nml").write_text(text.replace(", verbose = .true.", ""))
    proc = run(driver, tmp_path, "b.nml")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines() == ["pulse table written to p_pulse.txt and p_pulse.csv",
                                        "effective input written to p_input.nml"]


def test_echo_values_as_the_analysis_reads_them(driver, tmp_path):
    """Lists trimmed to their length, one value per record file, shortest reals,
    embedded quotes doubled, record paths relative to the echo file's folder."""
    shutil.copytree(SOURCE / "input" / "records", tmp_path / "cases" / "records")
    (tmp_path / "cases" / "c.nml").write_text(
        "&run analysis='newmark', output='res/deep/it''s' /\n"
        "&records files='records/quake_a.AT2', './records/quake_b.csv', units='auto', "
        "'g', target_pga=0.3 /\n&newmark ky=0.05, 0.1, 1e-9 /\n")
    proc = run(driver, tmp_path, "cases/c.nml")
    assert proc.returncode == 0, proc.stderr
    path = echo_path(tmp_path, proc.stdout)
    assert path == tmp_path / "res" / "deep" / "it's_input.nml"
    text = path.read_text()
    assert "    output = 'res/deep/it''s'\n" in text
    assert re.search(r"    files = '\.\./\.\./cases/records/quake_a\.AT2',\s+"
                     r"'\.\./\.\./cases/records/quake_b\.csv'\n", text), text
    assert "    units = 'auto', 'g'\n" in text
    assert "    target_pga = 2*0.3\n" in text
    assert "    ky = 0.05, 0.1, 1e-09\n" in text
    assert "mode" not in text and "g =" not in text     # defaults: not given, not echoed
    # it re-runs from its own folder to the same table
    (path.parent / "again.nml").write_text(with_output(text, "res/deep/it''s", "again"))
    proc2 = run(driver, tmp_path, "res/deep/again.nml")
    assert proc2.returncode == 0, proc2.stderr
    assert body(tmp_path / "res/deep/it's_newmark.csv") == body(tmp_path / "again_newmark.csv")


def test_no_echo_file_on_an_input_error(driver, tmp_path):
    (tmp_path / "a.nml").write_text("&run analysis = 'pulse', output = 'p', verbose = .true. /"
                                    "\n&pulse kind = 'half_sine', duration = -1 /\n")
    proc = run(driver, tmp_path, "a.nml")
    assert proc.returncode == 2
    assert not (tmp_path / "p_input.nml").exists()
    assert "effective input written" not in proc.stdout


def test_failed_edited_echo_file_survives(driver, tmp_path):
    """An echo file edited to hold an input error and re-run under its own prefix (the
    file names its own path as the echo) fails with exit 2, and the file is still there,
    whether reached by its own name or through a symbolic link."""
    (tmp_path / "a.nml").write_text("&run analysis = 'pulse', output = 'e/ex' /\n"
                                    "&pulse kind = 'half_sine', duration = 1 /\n")
    proc = run(driver, tmp_path, "a.nml")
    assert proc.returncode == 0, proc.stderr
    echo = tmp_path / "e" / "ex_input.nml"
    text = echo.read_text()
    bad = re.sub(r"duration = [^,\n/]*", "duration = -1", text)
    assert bad != text
    echo.write_text(bad)
    proc = run(driver, tmp_path, "e/ex_input.nml")
    assert proc.returncode == 2
    assert echo.read_text() == bad
    assert not (tmp_path / "e" / "ex_pulse.txt").exists()   # the stale table is gone
    (tmp_path / "link.nml").symlink_to(echo)
    proc = run(driver, tmp_path, "./link.nml")
    assert proc.returncode == 2
    assert echo.read_text() == bad


def test_failed_run_removes_other_analyses_tables_and_echo(driver, tmp_path):
    """A failed run of one analysis removes every stale table of its prefix, those of
    another analysis too, with the echo file: no table stays without its echo."""
    (tmp_path / "a.nml").write_text("&run analysis = 'pulse', output = 'o/blk' /\n"
                                    "&pulse kind = 'half_sine', duration = 1 /\n")
    assert run(driver, tmp_path, "a.nml").returncode == 0
    assert (tmp_path / "o" / "blk_pulse.csv").exists()
    assert (tmp_path / "o" / "blk_input.nml").exists()
    (tmp_path / "b.nml").write_text("&run analysis = 'sliding', output = 'o/blk' /\n"
                                    "&pulse kind = 'half_sine', duration = -1 /\n")
    assert run(driver, tmp_path, "b.nml").returncode == 2
    assert sorted(p.name for p in (tmp_path / "o").iterdir()) == []


def test_no_two_examples_share_an_output_prefix():
    """Every input/*.nml has its own output prefix: one example never overwrites, or
    after an error removes, another's tables or echo file."""
    prefixes = {}
    for nml in INPUTS:
        m = re.search(r"^[^!]*\boutput\s*=\s*'([^']*)'", nml.read_text(), flags=re.M)
        assert m, nml.name
        prefixes.setdefault(m.group(1), []).append(nml.name)
    shared = {k: v for k, v in prefixes.items() if len(v) > 1}
    assert not shared
