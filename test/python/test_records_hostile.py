"""seispulse.records.read on hostile or mistaken files (the limits documented in
records.py and doc/records.md): every one raises a documented error naming the file
and, where there is one, the line -- in bounded time and memory. The 1 GiB file is a
sparse file (os.truncate: no disk, no time); the sample limit is hit for real with a
column of MAX_RECORD_SAMPLES + 1 rows (20 MB)."""
import os
import time

import pytest

from seispulse import records as R
from seispulse.errors import FileError, InvalidInputError

AT2_HEAD = (b"PEER NGA STRONG MOTION DATABASE RECORD\ntitle\n"
            b"ACCELERATION TIME SERIES IN UNITS OF G\n")


def write(tmp_path, name, data):
    path = tmp_path / name
    path.write_bytes(data)
    return str(path)


def test_limits_are_public():
    assert R.MAX_RECORD_SAMPLES == 10_000_000
    assert R.MAX_RECORD_BYTES == 512 * 1024 * 1024
    assert "MAX_RECORD_SAMPLES" in R.__all__ and "MAX_RECORD_BYTES" in R.__all__


# (file name, content, read keywords, message after "<path>", parts of the message)
HOSTILE = [
    ("n1e8.at2", AT2_HEAD + b"NPTS= 100000000, DT= .01 SEC\n1 2 3\n", {}, ":4: ",
     ["NPTS = 100000000", "MAX_RECORD_SAMPLES = 10000000"]),
    ("n1e20.at2", AT2_HEAD + b"NPTS= 99999999999999999999, DT= .01\n1\n", {}, ":4: ",
     ["more samples than a record may have"]),
    ("nneg.at2", AT2_HEAD + b"NPTS= -5, DT= .01\n1\n", {}, ":4: ",
     ["NPTS = '-5' is not a positive integer"]),
    ("nfar.at2", AT2_HEAD + b"NPTS= 9999999, DT= .01\n1 2 3\n", {}, ": ",
     ["NPTS = 9999999", "only 3 values (line 5)"]),
    ("nul.csv", b"0 1\n0.5 2\x00\n", {}, ":2: ", ["a NUL byte (column 6)", "binary data"]),
    ("zeros.txt", b"\x00" * 65536, {}, ":1: ", ["a NUL byte (column 1)"]),
    ("empty.txt", b"", {}, ": ", ["empty file"]),
    ("midnum.txt", b"1.0\n2.5e", {"dt": 0.01}, ":2: ", ["'2.5e'"]),
    ("midnum.at2", AT2_HEAD + b"NPTS= 3, DT= .01\n1 2 -", {}, ":5: ", ["'-'"]),
    ("esc.txt", b"0 1 \x1b[31m\n", {}, ":1: ", ["found '0 1 \\x1B[31m'"]),
    ("mbline.txt", b"0 1\n1 " + b"7" * 1_000_000 + b" 3\n", {}, ":2: ", ["found 3"]),
    ("mbtoken.txt", b"x" * 1_000_000 + b"\n", {}, ":1: ", ["expected 1 or 2 numbers"]),
]


@pytest.mark.parametrize("name,data,kw,head,parts", HOSTILE, ids=[h[0] for h in HOSTILE])
def test_hostile_file(tmp_path, name, data, kw, head, parts):
    path = write(tmp_path, name, data)
    start = time.perf_counter()
    with pytest.raises(InvalidInputError) as err:
        R.read(path, **kw)
    assert time.perf_counter() - start < 5.0
    msg = str(err.value)
    assert msg.startswith(path + head), msg
    for part in parts:
        assert part in msg, msg
    assert len(msg) < len(path) + 400, "a message quotes at most 40 characters of a line"
    assert "\x00" not in msg and "\x1b" not in msg


def test_sparse_gigabyte_file(tmp_path):
    """1 GiB of NUL bytes (a hole: no disk used) is refused from its size, at once."""
    path = tmp_path / "huge.AT2"
    with open(path, "wb") as fh:
        os.truncate(fh.fileno(), 1 << 30)
    start = time.perf_counter()
    with pytest.raises(InvalidInputError) as err:
        R.read(path)
    assert time.perf_counter() - start < 1.0
    assert str(err.value) == (
        f"{path}: the file has 1073741824 bytes, more than a record file may have "
        "(MAX_RECORD_BYTES = 536870912 bytes, 512 MiB): not an accelerogram, or too long "
        "to read")


def test_directory(tmp_path):
    with pytest.raises(FileError) as err:
        R.read(tmp_path)
    assert str(err.value).startswith(f"{tmp_path}: cannot read: ")


def test_sample_limit_rows(tmp_path):
    """MAX_RECORD_SAMPLES rows read; one more is refused at its line."""
    n = R.MAX_RECORD_SAMPLES
    path = write(tmp_path, "limit.txt", b"# limit\n" + b"0\n" * n)
    rec = R.read(path, dt=0.01)
    assert rec.npts == n and rec.pga == 0.0
    with open(path, "ab") as fh:
        fh.write(b"1\n")
    with pytest.raises(InvalidInputError) as err:
        R.read(path, dt=0.01)
    assert str(err.value) == (
        f"{path}:{n + 2}: a row of data: more samples than a record may have "
        f"(MAX_RECORD_SAMPLES = {n} samples, the limit of the reader)")
