"""The classic interpreter workloads kept in this repository (tests/benchmarks/classic/).

Rugg and Feldman's benchmarks 1-7 (Kilobaud, June and October 1977), the eighth
test that John Coll added (Personal Computer World, February 1978), and David
Ahl's benchmark (Creative Computing, November 1983), written for this repository
from their published descriptions; ``classic/README.md`` says what each one does
and where ours differ from the published text.

Each workload is a listing in the common Microsoft BASIC form (it runs in yaseer
and in PC-BASIC unchanged).  From it this module derives:

* :func:`scaled`: the same program with its main loop count multiplied by a factor
  (the count is written ``FOR K=1 TO n``, ``IF K<n`` or ``FOR N=1 TO n``);
* :func:`for_bwbasic`: the form bwbasic runs as a whole process: its ``END``
  becomes ``SYSTEM`` (bwbasic stays in its shell after ``END``).  bwbasic needs FOR
  and NEXT on lines of their own, so a workload with FOR or NEXT after a colon
  names a peer written that way (``ahl`` -> ``ahl_split``).

A directory of other copies (``--extra DIR`` of interpreter_speed.py) is read by
:func:`from_directory`: ``NAME.bas`` with its bwbasic form ``bw_NAME.bas``.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

DIRECTORY = Path(__file__).resolve().with_name("classic")
NAMES = ("bm1", "bm2", "bm3", "bm4", "bm5", "bm6", "bm7", "bm8", "ahl", "ahl_split")
# The workload whose one-statement-per-line form bwbasic runs instead of it.
BWBASIC_PEER = {"ahl": "ahl_split"}
LOOP_COUNT = re.compile(r"(FOR K=1 TO |IF K<|FOR N=1 TO )(\d+)")
END_LINE = re.compile(r"^(\d+\s+)END\s*$", re.MULTILINE)


@dataclass(frozen=True)
class Workload:
    """One classic program: ``text`` for yaseer (and PC-BASIC), ``bwbasic`` for bwbasic."""

    name: str
    text: str
    bwbasic: str


def scaled(text: str, factor: float) -> str:
    """``text`` with every main loop count multiplied by ``factor`` (at least 1)."""
    return LOOP_COUNT.sub(lambda m: m.group(1) + str(max(1, round(int(m.group(2)) * factor))), text)


def for_bwbasic(text: str) -> str:
    """``text`` as bwbasic runs it as a whole process: ``END`` replaced by ``SYSTEM``.

    A listing without an ``END`` line gets a ``SYSTEM`` line after its last line.
    """
    if END_LINE.search(text):
        return END_LINE.sub(lambda m: m.group(1) + "SYSTEM", text)
    last = max(int(line.split()[0]) for line in text.splitlines() if line.strip())
    return text.rstrip("\n") + f"\n{last + 10} SYSTEM\n"


def in_repo() -> list[Workload]:
    """The workloads of tests/benchmarks/classic/, in the order of :data:`NAMES`."""
    texts = {name: (DIRECTORY / f"{name}.bas").read_text() for name in NAMES}
    return [Workload(name, texts[name], for_bwbasic(texts[BWBASIC_PEER.get(name, name)])) for name in NAMES]


def from_directory(directory: Path) -> list[Workload]:
    """Other copies: every ``NAME.bas`` of ``directory`` that has a ``bw_NAME.bas`` beside it.

    ``ahl``, whose bwbasic copy keeps FOR and NEXT after colons, is run by bwbasic
    in the one-statement-per-line form ``bw_ahl_split.bas`` when there is one.
    """
    workloads = []
    for path in sorted(directory.glob("*.bas")):
        name = path.stem
        if name.startswith("bw_"):
            continue
        peer = directory / f"bw_{BWBASIC_PEER.get(name, name)}.bas"
        if peer.exists():
            workloads.append(Workload(name, path.read_text(), peer.read_text()))
    return workloads
