"""Regenerate the screenshots shown in README.md (PNG, 100 dpi, doc/img/).

    .venv/bin/python tools/make_screenshots.py                  # after `make`
    .venv/bin/python tools/make_screenshots.py --table out/example_pulse.txt

Plots (seispulse.plot, records of input/records/):

* doc/img/spectra.png: PSA of quake_a.AT2 for damping ratios 2, 5, 10 and 20 %;
* doc/img/newmark.png: a rigid block (ky = 0.05 g, two-way) on quake_b.csv: the record
  with the yields, the relative velocity and the sliding displacement.

``--table FILE`` also renders a text table of the batch driver (any text file, drawn in
a monospace font as it is) into doc/img/<FILE's stem>.png, or ``--table-name NAME``.png.
``--out DIR`` writes elsewhere (the tests use it). Runs from any directory: the records
are found from this file's location, and seispulse in this tree's build/python (after
`make`), else the one Python imports.
"""
import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if (ROOT / "build" / "python" / "seispulse" / "__init__.py").exists():   # this tree's build
    sys.path.insert(0, str(ROOT / "build" / "python"))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

from seispulse import newmark, plot, records  # noqa: E402

DPI = 100
# no software version in the files: the same code makes the same bytes
META = {"Software": None}


def spectra(out):
    rec = records.read(ROOT / "input" / "records" / "quake_a.AT2")
    fig = plot.spectra(rec, damping=[0.02, 0.05, 0.10, 0.20],
                       title=f"{rec.name}: response spectra (PSA)")
    fig.set_size_inches(7.0, 4.0)
    fig.savefig(out / "spectra.png", dpi=DPI, metadata=META)
    plt.close(fig)


def newmark_history(out):
    rec = records.read(ROOT / "input" / "records" / "quake_b.csv")
    run = newmark.rigid(rec, ky=0.05, mode="both", history=True)
    fig = plot.newmark(run, rec,   # a two-way run: the yields +-0.05 g from the result
                       title=f"{rec.name}: rigid block, ky = 0.05 g both ways")
    fig.set_size_inches(7.0, 6.0)
    fig.savefig(out / "newmark.png", dpi=DPI, metadata=META)
    plt.close(fig)


def table(path, out, name=None):
    """A text table drawn as it is in a monospace font, the figure sized to the text."""
    text = Path(path).read_text(encoding="utf-8").rstrip("\n").expandtabs()
    lines = text.splitlines() or [""]
    size = 9.0   # points
    width = 0.6 * size / 72 * max(len(line) for line in lines) + 0.3   # inches
    height = 1.25 * size / 72 * len(lines) + 0.3
    fig = plt.figure(figsize=(width, height))
    fig.text(0.15 / width, 1 - 0.15 / height, text, family="monospace", fontsize=size,
             va="top", ha="left")
    target = out / f"{name or Path(path).stem}.png"
    # a tight box: the monospace width estimate above must never cut a long line
    fig.savefig(target, dpi=DPI, metadata=META, bbox_inches="tight", pad_inches=0.1)
    plt.close(fig)
    return target


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=ROOT / "doc" / "img",
                        help="directory of the PNG files (default doc/img)")
    parser.add_argument("--table", type=Path, help="a text table to render as well")
    parser.add_argument("--table-name", help="file name of the table image, without .png")
    args = parser.parse_args(argv)
    args.out.mkdir(parents=True, exist_ok=True)
    spectra(args.out)
    newmark_history(args.out)
    made = [args.out / "spectra.png", args.out / "newmark.png"]
    if args.table:
        made.append(table(args.table, args.out, args.table_name))
    for path in made:
        print(f"{path} ({path.stat().st_size // 1024} kB)")


if __name__ == "__main__":
    main()
