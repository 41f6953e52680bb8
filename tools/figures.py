"""Regenerate the figures the README and docs/ show, or check them against what the commands draw now.

    python tools/figures.py                 # redraw every figure below into docs/
    python tools/figures.py docs/example5.png docs/animation.gif   # only these
    python tools/figures.py --check         # compare the committed figures with fresh drawings; status 1 if any differs
    python tools/figures.py --list          # the command behind each figure

Each figure is drawn by the command a reader would type (``yaseer plot``, ``yaseer animate``,
``yaseer stability``), run in this process from the repository root; the benchmark chart is
redrawn from the committed measurements (``docs/bench_summary.csv``, ``docs/bench_newton.csv``:
timings are not repeatable, the chart of them is).  ``docs/notebook.png`` is the executed
notebook converted by ``jupyter nbconvert`` and photographed by headless ``chromium``; it is
redrawn only where both exist and is not compared (a browser's text rendering is the machine's).

The comparison is of pictures, robust across matplotlib and Pillow versions: both images the
same size, and for the dark ink (text, links, axes) and the coloured ink (the plotted lines,
traces, markers) separately, at least :data:`COVERAGE` of each image's ink lies within
:data:`REACH` pixels of the other's.  A line drawn as dots, a panel missing, a moved curve or
a changed layout fails; antialiasing and a pixel's shift in a glyph do not.
"""

from __future__ import annotations

import argparse
import contextlib
import csv
import io
import os
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

ROOT = Path(__file__).resolve().parents[1]
COVERAGE = 0.97  # share of one image's ink that must lie near the other's
REACH = 2  # pixels: how far a stroke may move between versions of the drawing libraries


@dataclass(frozen=True)
class Figure:
    """A committed picture and how it is drawn: ``draw(out)`` writes it to the path ``out``."""

    path: str
    command: str
    draw: Callable[[Path], None]
    compared: bool = True


def _yaseer(*args: str) -> None:
    """``yaseer ARGS`` in this process from the repository root; an error stops the script with its line."""
    from yaseer.cli import main

    previous = os.getcwd()
    os.chdir(ROOT)
    try:
        with contextlib.redirect_stdout(io.StringIO()):
            status = main(list(args))
    finally:
        os.chdir(previous)
    if status:
        raise SystemExit(f"yaseer {' '.join(args)}: exit status {status}")


def _one_of_several(command: Callable[[Path], None], name: str) -> Callable[[Path], None]:
    """Draw with a command that writes several files into a directory and keep the one named ``name``."""
    def draw(out: Path) -> None:
        with tempfile.TemporaryDirectory() as scratch:
            command(Path(scratch))
            shutil.copyfile(Path(scratch) / name, out)
    return draw


def _bench_chart(out: Path) -> None:
    """The benchmark chart from the committed measurements."""
    from yaseer.evaluation import benchmark

    def rows(name: str) -> list[dict]:
        with open(ROOT / "docs" / name, newline="") as handle:
            return [{k: _number(v) for k, v in row.items()} for row in csv.DictReader(handle)]

    with tempfile.TemporaryDirectory() as scratch:
        for path in benchmark.draw_chart(rows("bench_summary.csv"), rows("bench_newton.csv"), Path(scratch) / "bench"):
            if path.suffix == out.suffix:
                shutil.copyfile(path, out)


def _number(text: str):
    """A CSV field as the benchmark wrote it: an int, a float, or text."""
    for kind in (int, float):
        try:
            return kind(text)
        except ValueError:
            pass
    return text


def _notebook(out: Path) -> None:
    """The executed notebook as HTML, photographed by headless chromium at 1100 x 1600."""
    chromium = shutil.which("chromium") or shutil.which("chromium-browser")
    jupyter = Path(sys.executable).with_name("jupyter")
    if chromium is None or not jupyter.exists():
        raise SystemExit("docs/notebook.png needs chromium and jupyter nbconvert (pip install -e '.[jupyter]')")
    with tempfile.TemporaryDirectory() as scratch:
        html = Path(scratch) / "classroom.html"
        subprocess.run([str(jupyter), "nbconvert", "--to", "html", "--execute", "--output-dir", scratch,
                        str(ROOT / "notebooks" / "classroom.ipynb")], check=True, cwd=ROOT / "notebooks",
                       capture_output=True)
        subprocess.run([chromium, "--headless", "--no-sandbox", "--disable-gpu", "--hide-scrollbars",
                        "--window-size=1100,1600", f"--screenshot={out}", html.as_uri()],
                       check=True, capture_output=True, timeout=300)


FIGURES = [
    Figure("docs/example5.png", "yaseer plot listings/example5.bas --out docs",
           _one_of_several(lambda d: _yaseer("plot", "listings/example5.bas", "--out", str(d)), "example5.png")),
    Figure("docs/animation-frame.png", "yaseer animate listings/example1.bas --out docs/animation-frame.png --frame 5",
           lambda out: _yaseer("animate", "listings/example1.bas", "--out", str(out), "--frame", "5")),
    Figure("docs/animation.gif", "yaseer animate listings/example1.bas --out docs/animation.gif --size 960x540",
           lambda out: _yaseer("animate", "listings/example1.bas", "--out", str(out), "--size", "960x540")),
    Figure("docs/stability.png", "yaseer stability --out docs",
           _one_of_several(lambda d: _yaseer("stability", "--out", str(d)), "stability.png")),
    Figure("docs/stability.svg", "yaseer stability --out docs",
           _one_of_several(lambda d: _yaseer("stability", "--out", str(d)), "stability.svg"), compared=False),
    Figure("docs/bench.png", "yaseer bench's chart redrawn from docs/bench_summary.csv and docs/bench_newton.csv",
           _bench_chart),
    Figure("docs/bench.svg", "yaseer bench's chart redrawn from docs/bench_summary.csv and docs/bench_newton.csv",
           _bench_chart, compared=False),
    Figure("docs/notebook.png", "jupyter nbconvert --to html --execute notebooks/classroom.ipynb; "
           "chromium --headless --screenshot --window-size=1100,1600", _notebook, compared=False),
]


# ------------------------------------------------------------------ comparing pictures


def frames(path: Path) -> list:
    """Every frame of a PNG or GIF as an RGB numpy array (H x W x 3, uint8)."""
    import numpy as np
    from PIL import Image, ImageSequence

    with Image.open(path) as image:
        return [np.asarray(frame.convert("RGB")) for frame in ImageSequence.Iterator(image)]


def _ink(image) -> dict:
    """The dark ink (every channel below 110) and the coloured ink (channels 60 apart) of an RGB array."""
    import numpy as np

    channels = image.astype(np.int16)
    spread = channels.max(axis=2) - channels.min(axis=2)
    return {"dark ink": channels.max(axis=2) < 110, "coloured ink": spread > 60}


def _near(mask, reach: int):
    """``mask`` grown by ``reach`` pixels in every direction."""
    import numpy as np

    grown = mask.copy()
    padded = np.pad(mask, reach)
    height, width = mask.shape
    for dy in range(2 * reach + 1):
        for dx in range(2 * reach + 1):
            grown |= padded[dy:dy + height, dx:dx + width]
    return grown


def differences(committed: Path, drawn: Path) -> list[str]:
    """What differs between two pictures (empty when they match; see the module docstring)."""
    old, new = frames(committed), frames(drawn)
    if len(old) != len(new):
        return [f"{len(old)} frames committed, {len(new)} drawn now"]
    found = []
    for number, (a, b) in enumerate(zip(old, new)):
        where = f"frame {number}: " if len(old) > 1 else ""
        if a.shape != b.shape:
            found.append(f"{where}{a.shape[1]}x{a.shape[0]} committed, {b.shape[1]}x{b.shape[0]} drawn now")
            continue
        ink_a, ink_b = _ink(a), _ink(b)
        for kind in ink_a:
            for mask, other, what in ((ink_a[kind], ink_b[kind], "committed"), (ink_b[kind], ink_a[kind], "new")):
                total = int(mask.sum())
                if total == 0:
                    if other.sum():
                        found.append(f"{where}{kind}: none in the {what} picture")
                    continue
                share = float((mask & _near(other, REACH)).sum()) / total
                if share < COVERAGE:
                    found.append(f"{where}{kind}: {share:.1%} of the {what} picture's lies near the other's "
                                 f"(at least {COVERAGE:.0%} should)")
    return found


def check(figures: list[Figure]) -> dict[str, list[str]]:
    """For each compared figure, the differences between the committed file and a fresh drawing."""
    report = {}
    with tempfile.TemporaryDirectory() as scratch:
        for figure in figures:
            if not figure.compared:
                continue
            fresh = Path(scratch) / Path(figure.path).name
            figure.draw(fresh)
            report[figure.path] = differences(ROOT / figure.path, fresh)
    return report


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("figures", nargs="*", help="paths of the figures to redraw or check (default: all)")
    parser.add_argument("--check", action="store_true", help="compare instead of redrawing")
    parser.add_argument("--list", action="store_true", help="print each figure's command and stop")
    args = parser.parse_args(argv)
    known = {figure.path: figure for figure in FIGURES}
    unknown = [name for name in args.figures if name not in known]
    if unknown:
        parser.error(f"no such figure: {', '.join(unknown)} (known: {', '.join(known)})")
    chosen = [known[name] for name in args.figures] or FIGURES
    if args.list:
        for figure in chosen:
            print(f"{figure.path}: {figure.command}")
        return 0
    if args.check:
        report = check(chosen)
        for path, found in report.items():
            print(f"{path}: " + ("matches" if not found else "DIFFERS\n  " + "\n  ".join(found)))
        return 1 if any(report.values()) else 0
    for figure in chosen:
        figure.draw(ROOT / figure.path)
        print(f"wrote {figure.path}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
