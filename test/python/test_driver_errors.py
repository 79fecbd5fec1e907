"""Batch driver: every error has the form `file:line: &group: key: problem` (or
`file:line: &group: problem` when the group itself is the problem: unknown, given twice,
missing, not closed, rows failed), the line that of the group (of &run for a missing
group); a problem inside a record file follows as `recordfile:line: problem`. One or
more cases per analysis, and the steep backfill of analysis 'walls'."""
import re
import shutil
import subprocess
from pathlib import Path

import pytest

SOURCE = Path(__file__).resolve().parents[2]
FORM = re.compile(r"^seispulse: error: (?P<file>[^:\s]+):(?P<line>[1-9]\d*): "
                  r"&(?P<group>[a-z_]+): (?P<rest>\S.*)$")
KEY = re.compile(r"^(?P<key>[a-z_0-9]+(\(\d+\))?(, [a-z_0-9]+(\(\d+\))?)*)"
                 r"( = [^:]+)?: \S.*$")

WALLS = (SOURCE / "input" / "walls.nml").read_text()
CASES = {
    # name: (input text, group, key or None for a group-level problem)
    "walls_steep_backfill": (WALLS.replace("beta_deg = 0.0 ", "beta_deg = 30.0"),
                             "backfill", "beta_deg"),
    "walls_slope_range": (WALLS.replace("beta_deg = 0.0 ", "beta_deg = 95.0"),
                          "backfill", "beta_deg"),
    "walls_missing_group": ("&run analysis='walls', output='o' /\n"
                            "&backfill gamma=20, phi_deg=30 /\n"
                            "&seismic code='direct', kh=0.1 /\n", "wall", None),
    "pulse": ("&run analysis='pulse', output='o' /\n&pulse kind='half_sine', duration=-1 /\n",
              "pulse", "duration"),
    "pulse_unit": ("&run analysis='pulse', output='o' /\n"
                   "&pulse kind='half_sine', amp_unit='ft/s2' /\n", "pulse", "amp_unit"),
    "pulse_time": ("&run analysis='pulse', output='o' /\n&pulse kind='half_sine' /\n"
                   "&time dt=1e-9 /\n", "time", "dt"),
    "sliding": ("&run analysis='sliding', output='o' /\n&pulse kind='half_sine', amp=3 /\n"
                "&block mu=-0.2 /\n", "block", "mu"),
    "rocking": ("&run analysis='rocking', output='o' /\n&block b=-0.2, h=0.8 /\n"
                "&pulse kind='half_sine' /\n", "block", "b"),
    "newmark": ("&run analysis='newmark', output='o' /\n&records files='records/quake_a.AT2' /\n"
                "&newmark ky=-0.1 /\n", "newmark", "ky"),
    "newmark_units": ("&run analysis='newmark', output='o' /\n"
                      "&records files='records/quake_a.AT2', units='ft' /\n&newmark ky=0.1 /\n",
                      "records", "units"),
    "newmark_no_records": ("&run analysis='newmark', output='o' /\n&newmark ky=0.1 /\n",
                           "records", None),
    "sdof": ("&run analysis='sdof', output='o' /\n&records files='records/quake_a.AT2' /\n"
             "&sdof periods=1.0, damping=1.5 /\n", "sdof", "damping"),
    "newmark_sa_periods_twice": ("&run analysis='newmark', output='o' /\n"
                                 "&records files='records/quake_a.AT2' /\n"
                                 "&newmark ky=0.1, intensity=.true., sa_periods=1.0, 0.5, 1.0 /\n",
                                 "newmark", "sa_periods(3)"),
    "sdof_beta": ("&run analysis='sdof_beta', output='o' /\n&sdof_beta ratios=1, 2, gamma=-1 /\n",
                  "sdof_beta", "gamma"),
    "sdof_shock": ("&run analysis='sdof_shock', output='o' /\n&pulse kind='half_sine' /\n"
                   "&sdof_shock periods=-1 /\n", "sdof_shock", "periods"),
    "cylinder": ("&run analysis='cylinder', output='o' /\n&body shape='solid', r=-1, h=1, mass=100 /\n"
                 "&cylinder what='props' /\n", "body", "r"),
    "winkler": ("&run analysis='winkler', output='o' /\n&winkler what='pushover', b=-1 /\n",
                "winkler", "b"),
    "empirical": ("&run analysis='empirical', output='o' /\n&empirical ky=-0.1 /\n",
                  "empirical", "ky"),
    "spectra": ("&run analysis='spectra', output='o' /\n"
                "&records files='records/quake_a.AT2', 'records/quake_b.csv' /\n"
                "&suite t1=-1, min_records=2 /\n&ec8 ag=0.2 /\n", "suite", "t1"),
    "run_key": ("&run analysis='pulse', output='o', foo=1 /\n", "run", "foo"),
    "bad_value": ("&run analysis='pulse', output='o' /\n&pulse kind='half_sine', amp='x' /\n",
                  "pulse", "amp"),
    "unknown_group": ("&run analysis='pulse', output='o' /\n&foo a=1 /\n", "foo", None),
    "not_closed": ("&run analysis='pulse', output='o' /\n\n&pulse kind='half_sine'\n",
                   "pulse", None),
}


def group_line(text, group):
    """The line of &group in text, else of &run (a missing group)."""
    for name in (group, "run"):
        for i, line in enumerate(text.splitlines(), 1):
            if re.match(rf"\s*&{name}\b", line, flags=re.I):
                return i
    raise AssertionError(group)


@pytest.mark.parametrize("name", sorted(CASES))
def test_error_form(driver, tmp_path, name):
    text, group, key = CASES[name]
    shutil.copytree(SOURCE / "input" / "records", tmp_path / "records")
    (tmp_path / "in.nml").write_text(text)
    proc = subprocess.run([driver, "in.nml"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 2, (proc.stdout, proc.stderr)
    errors = [ln for ln in proc.stderr.splitlines() if ln.startswith("seispulse: error:")]
    assert len(errors) == 1, proc.stderr
    m = FORM.match(errors[0])
    assert m, errors[0]
    assert m["file"] == "in.nml" and m["group"] == group, errors[0]
    assert int(m["line"]) == group_line(text, group), errors[0]
    if key is not None:
        k = KEY.match(m["rest"])
        assert k and k["key"] == key, errors[0]
    assert not (tmp_path / "o_input.nml").exists()


def test_record_file_error_form(driver, tmp_path):
    """A bad line in a record file: the input's place, then `recordfile:line: problem`;
    the summary of failed rows at &records."""
    shutil.copytree(SOURCE / "input" / "records", tmp_path / "records")
    (tmp_path / "records" / "bad.csv").write_text("0.01\n0.02\n0.0.3\n")
    (tmp_path / "in.nml").write_text("&run analysis='newmark', output='o' /\n\n"
                                     "&records files='records/quake_a.AT2', 'records/bad.csv', "
                                     "units='g', dt=0.01 /\n&newmark ky=0.1 /\n")
    proc = subprocess.run([driver, "in.nml"], cwd=tmp_path, capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 1, proc.stderr
    errors = [ln for ln in proc.stderr.splitlines() if ln.startswith("seispulse: error:")]
    assert len(errors) == 2, proc.stderr
    assert re.match(r"^seispulse: error: in\.nml:3: &records: files\(2\) = 'records/bad\.csv': "
                    r"records/bad\.csv:3: \S", errors[0]), errors[0]
    assert re.match(r"^seispulse: error: in\.nml:3: &records: 1 of 2 rows failed", errors[1])
