"""The echo file of a driver run (table_path(prefix, 'input', 'nml'), e.g.
out/example_input.nml), for the tests: where stdout says it went, its text, and the text
with another output prefix (to re-run it)."""
import re
from pathlib import Path

ECHO_LINE = re.compile(r"^effective input written to (.+)$", re.MULTILINE)


def echo_path(cwd, stdout):
    """The echo file named on stdout (relative to the working directory cwd)."""
    found = ECHO_LINE.findall(stdout)
    assert len(found) == 1, stdout
    return Path(cwd) / found[0]


def echo_text(cwd, stdout):
    return echo_path(cwd, stdout).read_text()


def with_output(text, old, new):
    """The echo with output = 'new' instead of output = 'old'."""
    out = text.replace(f"output = '{old}'", f"output = '{new}'")
    assert out != text, text
    return out
