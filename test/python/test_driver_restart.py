"""Batch driver, batches of records (driver_batch): the restart journal and OpenMP threads.

A job of 40 short records (made here from input/records/quake_b.csv, scaled, repeated and
resampled) is run once uninterrupted; the same job killed (SIGKILL) at seeded random
moments and restarted with `restart = .true.` until it ends gives the same tables byte
for byte, every unit printed at most once over all runs (a unit whose log was printed is
in the journal and never computed again), and the final run restores units from the
journal. A journal of another input is refused, as is one with a damaged line; an
unterminated last line is dropped and that unit computed again. Threads
(OMP_NUM_THREADS=2) give the tables and the standard error of one thread. The journal's
lines are checked against an independent FNV-1a and the values against the table."""
import os
import random
import re
import shutil
import signal
import struct
import subprocess
import time
from pathlib import Path

import pytest

HERE = Path(__file__).resolve().parent
SOURCE = HERE.parents[1] / "input" / "records" / "quake_b.csv"
NREC = 40
TABLES = ["batch_newmark.txt", "batch_newmark.csv", "batch_intensity.txt",
          "batch_intensity.csv"]
SDOF_TABLES = ["batch_sdof.txt", "batch_sdof.csv", "batch_sdof_envelope.txt",
               "batch_sdof_envelope.csv", "batch_sdof_history.txt", "batch_sdof_history.csv"]
PROGRESS = re.compile(r"^(newmark|sdof): record (\d+)/(\d+): ", re.M)
RESTORED = re.compile(r"^(newmark|sdof): (\d+) of (\d+) units restored from (\S+)$", re.M)


def fnv1a64(data: bytes) -> int:
    """FNV-1a, 64 bits (offset basis 0xcbf29ce484222325, prime 0x100000001b3)."""
    h = 0xCBF29CE484222325
    for b in data:
        h ^= b
        h = (h * 0x100000001B3) & 0xFFFFFFFFFFFFFFFF
    return h


def test_fnv1a64_reference():
    # the published test vectors of FNV-1a 64
    assert fnv1a64(b"") == 0xCBF29CE484222325
    assert fnv1a64(b"a") == 0xAF63DC4C8601EC8C
    assert fnv1a64(b"foobar") == 0x85944171F73967E8


def make_records(folder: Path):
    """NREC records (time, accel in g): quake_b scaled by 0.5 + 0.037 k, repeated 1..3
    times (the repeats turned over at 0.8), every other one resampled to dt/2 (linear)."""
    rows = [line.split(",") for line in SOURCE.read_text().splitlines()
            if line and not line.startswith("#")]
    acc = [float(a) for _, a in rows]
    folder.mkdir()
    names = []
    for k in range(NREC):
        series = []
        for r in range(1 + k % 3):
            series += [(0.5 + 0.037 * k) * x * (1.0 if r % 2 == 0 else -0.8) for x in acc]
        dt = 0.02
        if k % 2:
            fine = []
            for i in range(len(series) - 1):
                fine += [series[i], 0.5 * (series[i] + series[i + 1])]
            series = fine + [series[-1]]
            dt = 0.01
        lines = [f"# synthetic record {k}", "# time_s, accel_g"]
        lines += [f"{i * dt:.4f},{x:.7f}" for i, x in enumerate(series)]
        (folder / f"r{k:02d}.csv").write_text("\n".join(lines) + "\n")
        names.append(f"'records/r{k:02d}.csv'")
    return names


@pytest.fixture(scope="module")
def record_set(tmp_path_factory):
    base = tmp_path_factory.mktemp("batch_records")
    return base / "records", make_records(base / "records")


def newmark_input(files, restart, ky_step=0.002, bad=False):
    ky = ", ".join(f"{0.01 + ky_step * i:.4f}" for i in range(50))
    files = list(files)
    if bad:
        files[7] = "'records/missing.csv'"
    return (f"&run analysis = 'newmark', output = 'out/batch', "
            f"restart = {'.true.' if restart else '.false.'} /\n"
            f"&records files = {', '.join(files)} /\n"
            f"&newmark ky = {ky}, intensity = .true., sa_periods = 0.2, 1.0 /\n")


def sdof_input(files, restart):
    return (f"&run analysis = 'sdof', output = 'out/batch', "
            f"restart = {'.true.' if restart else '.false.'} /\n"
            f"&records files = {', '.join(files[:12])} /\n"
            "&sdof periods = 0.0, 0.1, 0.25, 0.5, 1.0, 2.0, damping = 0.02, 0.05, "
            "envelope = .true., shape = .true. /\n"
            "&sdof_history periods = 0.3, damping = 0.05 /\n")


def case(tmp_path, name, record_set, text):
    folder = tmp_path / name
    folder.mkdir()
    shutil.copytree(record_set[0], folder / "records")
    (folder / "in.nml").write_text(text)
    return folder


def run(driver, folder, threads=1, **environ):
    env = dict(os.environ, OMP_NUM_THREADS=str(threads), **environ)
    return subprocess.run([driver, "in.nml"], cwd=folder, capture_output=True, text=True,
                          timeout=120, env=env)


def tables(folder, names=TABLES):
    return {n: (folder / "out" / n).read_bytes() for n in names}


def full_journal(driver, folder, table="batch_newmark.txt"):
    """Run to the end but fail committing `table` (a directory in the way of its final
    name, so the rename of its .part fails): exit 2 after every unit is journaled, so the
    journal is complete and kept."""
    blocker = folder / "out" / table
    if blocker.is_file():
        blocker.unlink()             # the table of an earlier run
    blocker.mkdir(parents=True)
    r = run(driver, folder)
    blocker.rmdir()
    assert r.returncode == 2, r.stderr
    journal = folder / "out" / "batch.journal"
    assert journal.exists()
    return journal


def test_restart_after_kills(driver, tmp_path, record_set):
    ref = case(tmp_path, "ref", record_set, newmark_input(record_set[1], False))
    r = run(driver, ref)
    assert r.returncode == 0, r.stderr
    assert len(PROGRESS.findall(r.stderr)) == NREC

    job = case(tmp_path, "job", record_set, newmark_input(record_set[1], True))
    journal = job / "out" / "batch.journal"
    env = dict(os.environ, OMP_NUM_THREADS="2")
    rng = random.Random(20261127)
    printed = []            # unit indices whose progress line a run printed
    kills, early, late = 0, 0, 0
    restored_seen = []
    for attempt in range(60):
        lines0 = journal.read_bytes().count(b"\n") if journal.exists() else 0
        # late kills stop at half the job (it must still be running at the 6th kill)
        is_late = attempt >= 2 and rng.random() >= 0.25 and lines0 + 1 < NREC // 2
        p = subprocess.Popen([driver, "in.nml"], cwd=job, env=env, stdout=subprocess.DEVNULL,
                             stderr=subprocess.PIPE, text=True)
        if not is_late:
            # early: before or while the journal is started
            time.sleep(rng.uniform(0.0, 0.02))
        else:
            # late: once the journal holds 1 to 3 more units, then a moment more (a kill
            # may land while a line is being written)
            target = min(lines0 + rng.randint(1, 3), NREC // 2)
            t0 = time.monotonic()
            while p.poll() is None and time.monotonic() - t0 < 20:
                try:
                    if journal.read_bytes().count(b"\n") >= target:
                        break
                except FileNotFoundError:
                    pass
                time.sleep(0.001)
            time.sleep(rng.uniform(0.0, 0.004))
        alive = p.poll() is None
        if alive:
            p.send_signal(signal.SIGKILL)
        err = p.communicate()[1]
        printed += [int(m[1]) for m in PROGRESS.findall(err)]
        restored_seen += [int(m[1]) for m in RESTORED.findall(err)]
        if alive:
            kills += 1
            late += is_late
            early += not is_late
            assert p.returncode == -signal.SIGKILL
        else:
            assert p.returncode == 0, err
            break
        if kills >= 6 and late >= 3:
            break
    assert kills >= 5 and early >= 1 and late >= 3, (kills, early, late)
    # journaled units are never lost: each restart restores at least what the last one did
    assert restored_seen == sorted(restored_seen)

    # the last run, to the end
    r = run(driver, job, threads=2)
    assert r.returncode == 0, r.stderr
    printed += [int(m[1]) for m in PROGRESS.findall(r.stderr)]
    restored = RESTORED.findall(r.stderr)
    assert restored and 0 < int(restored[0][1]) <= NREC and int(restored[0][2]) == NREC
    assert restored[0][3] == "out/batch.journal"
    computed = PROGRESS.findall(r.stderr)
    assert len(computed) == NREC - int(restored[0][1]) < NREC
    # a unit is printed only after it is journaled: never twice over all runs
    assert len(printed) == len(set(printed)) <= NREC
    assert tables(job) == tables(ref)
    assert not journal.exists(), "the journal is removed with the tables committed"
    assert not (job / "out" / "batch.journal.tmp").exists()


def test_error_without_restart_removes_its_journal(driver, tmp_path, record_set):
    """restart = .false. and an output error once every record is done (the table cannot
    be renamed to its name): no output left, the journal neither; a journal this run did
    not start (an input error before the batch) stays."""
    job = case(tmp_path, "job", record_set, newmark_input(record_set[1], False))
    (job / "out" / "batch_newmark.txt").mkdir(parents=True)
    r = run(driver, job)
    assert r.returncode == 2
    assert len(PROGRESS.findall(r.stderr)) == NREC, "every record was computed"
    assert sorted(p.name for p in (job / "out").iterdir()) == ["batch_newmark.txt"]
    (job / "out" / "batch_newmark.txt").rmdir()
    (job / "out" / "batch.journal").write_text("not a journal\n")
    (job / "in.nml").write_text(newmark_input(record_set[1], False).replace("ky =", "kx ="))
    r = run(driver, job)
    assert r.returncode == 2 and "kx" in r.stderr
    assert (job / "out" / "batch.journal").read_text() == "not a journal\n"


def test_complete_journal_restores_all(driver, tmp_path, record_set):
    ref = case(tmp_path, "ref", record_set, newmark_input(record_set[1], True))
    assert run(driver, ref).returncode == 0
    job = case(tmp_path, "job", record_set, newmark_input(record_set[1], True))
    journal = full_journal(driver, job)
    r = run(driver, job)
    assert r.returncode == 0, r.stderr
    assert f"newmark: {NREC} of {NREC} units restored from out/batch.journal" in r.stderr
    assert not PROGRESS.search(r.stderr)
    assert tables(job) == tables(ref)
    assert not journal.exists()


def test_journal_format(driver, tmp_path, record_set):
    """Every line's checksum is FNV-1a of the line before it; the values are the doubles'
    bits (the first unit's PGA after scaling is the table's pga, exactly)."""
    job = case(tmp_path, "job", record_set, newmark_input(record_set[1], True))
    journal = full_journal(driver, job)
    lines = journal.read_bytes().split(b"\n")
    assert lines[-1] == b""
    head = lines[0].split(b" ")
    assert head[0] == b"seispulse-journal" and head[1] == b"2" and len(head[2]) == 16
    assert int(head[3]) == NREC
    units = set()
    for line in lines[1:-1]:
        body, _, check = line.rpartition(b" ")
        assert int(check, 16) == fnv1a64(body)
        words = body.split(b" ")
        assert words[0] == b"u"
        i, n = int(words[1]), int(words[2])
        units.add(i)
        values = [struct.unpack(">d", bytes.fromhex(w.decode()))[0] for w in words[3:3 + n]]
        assert len(words) == 3 + n + 2
        if i == 1:
            first = values
            assert words[3 + n].startswith(b"=")       # text: r00 ...
            assert b"r00" in words[3 + n]
            assert b"%0a" not in words[4 + n] and b"newmark:%20record%201/40" in words[4 + n]
    assert units == set(range(1, NREC + 1))
    # pack_record: ok, format, npts, dt, PGA read, factor, PGA after scaling
    assert first[0] == 1.0 and first[2] == 200.0 and first[3] == 0.02
    assert run(driver, job).returncode == 0
    csv_lines = (job / "out" / "batch_newmark.csv").read_text().splitlines()
    assert float(csv_lines[1].split(",")[1]) == first[6]


def test_foreign_journal_refused(driver, tmp_path, record_set):
    job = case(tmp_path, "job", record_set, newmark_input(record_set[1], True))
    journal = full_journal(driver, job)
    before = journal.read_bytes()
    # another input: other yield accelerations
    (job / "in.nml").write_text(newmark_input(record_set[1], True, ky_step=0.003))
    r = run(driver, job)
    assert r.returncode == 2
    line = r.stderr.strip().splitlines()[-1]
    assert line.startswith("seispulse: error: out/batch.journal:1: the journal of another run")
    assert "restart = .false." in line and "delete the journal" in line
    assert not PROGRESS.search(r.stderr)
    assert not (job / "out" / "batch_newmark.txt").exists()
    assert journal.read_bytes() == before, "a refused journal stays as it was"


def test_damaged_line_refused(driver, tmp_path, record_set):
    job = case(tmp_path, "job", record_set, newmark_input(record_set[1], True))
    journal = full_journal(driver, job)
    lines = journal.read_bytes().split(b"\n")
    # one hex digit of a value in the middle of line 20: still well formed
    k = 20 - 1
    words = lines[k].split(b" ")
    w = bytearray(words[5])
    w[7] = ord("1") if w[7] != ord("1") else ord("2")
    words[5] = bytes(w)
    lines[k] = b" ".join(words)
    journal.write_bytes(b"\n".join(lines))
    r = run(driver, job)
    assert r.returncode == 2
    line = r.stderr.strip().splitlines()[-1]
    assert line.startswith("seispulse: error: out/batch.journal:20: damaged line (its checksum")
    assert "restart = .false." in line
    assert not PROGRESS.search(r.stderr)

    # restart = .false.: the damaged journal is replaced (a warning says so), all computed
    (job / "in.nml").write_text(newmark_input(record_set[1], False))
    r = run(driver, job)
    assert r.returncode == 0, r.stderr
    assert "warning: out/batch.journal: the journal of an earlier run is replaced" in r.stderr
    assert len(PROGRESS.findall(r.stderr)) == NREC
    assert not journal.exists()


def test_unit_twice_refused(driver, tmp_path, record_set):
    job = case(tmp_path, "job", record_set, newmark_input(record_set[1], True))
    journal = full_journal(driver, job)
    lines = journal.read_bytes().split(b"\n")
    journal.write_bytes(b"\n".join(lines[:-1] + [lines[3], b""]))
    r = run(driver, job)
    assert r.returncode == 2
    assert f"out/batch.journal:{NREC + 2}: unit " in r.stderr and "given twice" in r.stderr


def test_unterminated_last_line(driver, tmp_path, record_set):
    ref = case(tmp_path, "ref", record_set, newmark_input(record_set[1], True))
    assert run(driver, ref).returncode == 0
    job = case(tmp_path, "job", record_set, newmark_input(record_set[1], True))
    journal = full_journal(driver, job)
    data = journal.read_bytes()
    last = data[:-1].rfind(b"\n") + 1
    unit = int(data[last:].split(b" ")[1])
    journal.write_bytes(data[:last + (len(data) - last) // 2])   # killed mid-line
    r = run(driver, job)
    assert r.returncode == 0, r.stderr
    assert f"newmark: {NREC - 1} of {NREC} units restored" in r.stderr
    assert [int(m[1]) for m in PROGRESS.findall(r.stderr)] == [unit]
    assert tables(job) == tables(ref)


def test_restart_without_journal(driver, tmp_path, record_set):
    ref = case(tmp_path, "ref", record_set, newmark_input(record_set[1], False))
    assert run(driver, ref).returncode == 0
    job = case(tmp_path, "job", record_set, newmark_input(record_set[1], True))
    r = run(driver, job)
    assert r.returncode == 0, r.stderr
    assert f"newmark: restart: no journal out/batch.journal: all {NREC} units" in r.stderr
    assert [int(m[1]) for m in PROGRESS.findall(r.stderr)] == list(range(1, NREC + 1))
    assert tables(job) == tables(ref)
    # the echo keeps restart (a key the input gave)
    assert "restart = .true." in (job / "out" / "batch_input.nml").read_text()
    assert "restart" not in (ref / "out" / "batch_input.nml").read_text().replace(
        "restart = .false.", "")


def test_threads_same_tables_and_stderr(driver, tmp_path, record_set):
    """OMP_NUM_THREADS=2 writes what one thread writes, stderr too (a record that cannot
    be read among them: exit 1, its error in its place)."""
    one = case(tmp_path, "one", record_set, newmark_input(record_set[1], False, bad=True))
    two = case(tmp_path, "two", record_set, newmark_input(record_set[1], False, bad=True))
    r1, r2 = run(driver, one, threads=1), run(driver, two, threads=2)
    assert r1.returncode == r2.returncode == 1
    assert "files(8) = 'records/missing.csv'" in r1.stderr
    assert r1.stderr == r2.stderr and r1.stdout == r2.stdout
    assert tables(one) == tables(two)


def test_sdof_threads_and_journal(driver, tmp_path, record_set):
    one = case(tmp_path, "one", record_set, sdof_input(record_set[1], False))
    two = case(tmp_path, "two", record_set, sdof_input(record_set[1], True))
    r1, r2 = run(driver, one, threads=1), run(driver, two, threads=2)
    assert r1.returncode == 0, r1.stderr
    assert r2.returncode == 0, r2.stderr
    assert r1.stderr == r2.stderr.replace(
        "sdof: restart: no journal out/batch.journal: all 12 units are computed\n", "")
    assert tables(one, SDOF_TABLES) == tables(two, SDOF_TABLES)
    # every unit from a complete journal: the same tables (spectra, shape, histories)
    journal = full_journal(driver, two, table="batch_sdof_history.txt")
    r = run(driver, two, threads=2)
    assert r.returncode == 0, r.stderr
    assert "sdof: 12 of 12 units restored from out/batch.journal" in r.stderr
    assert tables(one, SDOF_TABLES) == tables(two, SDOF_TABLES)
    assert not journal.exists()


def test_restart_of_another_analysis_is_ignored(driver, tmp_path, source_root):
    """Only the batches keep a journal: restart = .true. elsewhere is a warning."""
    text = (source_root / "input" / "example.nml").read_text()
    text = text.replace("    analysis = 'pulse'", "    restart = .true.\n    analysis = 'pulse'")
    (tmp_path / "in.nml").write_text(text)
    r = subprocess.run([driver, "in.nml"], cwd=tmp_path, capture_output=True, text=True,
                       timeout=60)
    assert r.returncode == 0, r.stderr
    assert r.stderr.startswith("warning: in.nml:4: &run: restart: only the analyses "
                               "'newmark' and 'sdof' keep a journal")
    assert not list((tmp_path / "out").glob("*journal*"))


def test_journal_that_cannot_be_replaced(driver, tmp_path, record_set):
    """A directory where the journal goes: the new journal cannot take its name, so the
    run warns once and goes on without one (it used to crash closing the journal twice);
    the tables equal a plain run's and no .tmp is left."""
    ref = case(tmp_path, "ref", record_set, newmark_input(record_set[1], False))
    assert run(driver, ref).returncode == 0
    job = case(tmp_path, "job", record_set, newmark_input(record_set[1], False))
    (job / "out" / "batch.journal").mkdir(parents=True)
    r = run(driver, job)
    assert r.returncode == 0, r.stderr
    assert r.stderr.count("warning: cannot write the journal out/batch.journal") == 1
    assert tables(job) == tables(ref)
    assert not (job / "out" / "batch.journal.tmp").exists()
    assert (job / "out" / "batch.journal").is_dir()


def long_first(folder, files, repeats=40):
    """files with a record `repeats` times as long as r00 (records/long.csv) first: two
    threads then finish many later records while the first is still running."""
    rows = [line for line in (folder / "records" / "r00.csv").read_text().splitlines()
            if line and not line.startswith("#")]
    acc = [a for _, a in (r.split(",") for r in rows)]
    lines = ["# r00 repeated", "# time_s, accel_g"]
    lines += [f"{i * 0.02:.4f},{a}" for i, a in enumerate(acc * repeats)]
    (folder / "records" / "long.csv").write_text("\n".join(lines) + "\n")
    return ["'records/long.csv'"] + list(files)


@pytest.mark.parametrize("analysis", ["newmark", "sdof"])
def test_results_set_aside_in_the_journal(driver, tmp_path, record_set, analysis):
    """SEISPULSE_BATCH_HOLD_MB=0: every result finished out of turn waits in the journal
    and is read back in its turn (as a long first record makes happen on two threads):
    the tables, stdout and stderr are those of one thread holding everything, also when
    some units are restored from a journal."""
    def make(name, restart):
        folder = case(tmp_path, name, record_set, "")
        files = long_first(folder, record_set[1])
        text = (newmark_input(files, restart, bad=True) if analysis == "newmark"
                else sdof_input(files, restart))
        (folder / "in.nml").write_text(text)
        return folder
    names = TABLES if analysis == "newmark" else SDOF_TABLES
    one, two = make("one", False), make("two", False)
    r1 = run(driver, one, threads=1)
    r2 = run(driver, two, threads=2, SEISPULSE_BATCH_HOLD_MB="0")
    assert r1.returncode == r2.returncode, r2.stderr
    assert r1.stderr == r2.stderr and r1.stdout == r2.stdout
    assert tables(one, names) == tables(two, names)
    # restored units and units set aside together: a journal of the first half
    three = make("three", True)
    journal = full_journal(driver, three, table=names[0])
    lines = journal.read_bytes().split(b"\n")
    journal.write_bytes(b"\n".join(lines[:len(lines) // 2]) + b"\n")
    r3 = run(driver, three, threads=2, SEISPULSE_BATCH_HOLD_MB="0")
    assert r3.returncode == r1.returncode, r3.stderr
    assert tables(one, names) == tables(three, names)
