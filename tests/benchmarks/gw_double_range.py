"""What GW's 56-bit doubles cost: double-precision loops compiled two ways in one run,
as ratios (no wall-clock claims).

* MBF: what yaseer compiles (``_dad _dsb _dml _ddv``, arith_policy.py: a float fast
  path where the exact result is a float, else the 56-bit routines of mbf_double.py on
  integer mantissas, whose results no float holds are ``values.Wide``);
* IEEE: Python's 53-bit float arithmetic with the inline range check yaseer compiled
  before (``number_models._in_double_range``): fast, but a 16th digit may differ from
  GW's (``12345670#/3`` shows 4115223.333333334, GW 4115223.333333333).

The same loop in casio (its 13-digit decimal arithmetic, decimal_arith.py) is timed in
the same run as a third reference.  Times are the process's CPU time (the machine is
shared), the best of 5 runs.

Run: ``YASEER_CACHE_DIR= python tests/benchmarks/gw_double_range.py`` (the empty
cache directory switches the compiled-program cache off, so each way is compiled).
"""

from __future__ import annotations

import io
import time

from yaseer.basic.compile import number_models
from yaseer.basic.machine.machine import Machine

PROGRAMS = {
    # whole numbers and halves: every result a float (the fast paths)
    "whole": ("10 DEFDBL A-Z\n20 S = 0: FOR I% = 1 TO 30000: A = I% * 1.5#: S = S + A * A - A / 2: NEXT\n"
              "30 PRINT S\n"),
    # sevenths: most results need 56 bits (the integer routines)
    "fractions": ("10 DEFDBL A-Z\n20 S = 0: FOR I% = 1 TO 30000: A = I% / 7#: S = S + A * A - A / 3: NEXT\n"
                  "30 PRINT S\n"),
}
# the loops in casio, whose variables have no types
CASIO = {name: program.replace("10 DEFDBL A-Z\n", "").replace("I%", "I").replace("#", "")
         for name, program in PROGRAMS.items()}


def best_time(program: str, repeats: int = 5, dialect: str = "gw") -> tuple[float, str]:
    """The fastest of ``repeats`` runs of ``program`` (seconds), and what it printed."""
    best, printed = float("inf"), ""
    for _ in range(repeats):
        machine = Machine(screen=io.StringIO(), dialect=dialect)
        machine.load(program)
        start = time.process_time()
        machine.run()
        best = min(best, time.process_time() - start)
        printed = machine.screen.stream.getvalue()
    return best, printed


def ieee(self, op, left, lkind, right, rkind):
    """The double operations as yaseer compiled them before GW's 56 bits."""
    kind = lkind if number_models._RANK[lkind] >= number_models._RANK[rkind] else rkind
    if kind == "#" and op in "+-*/":
        return number_models._in_double_range(f"{left} {op} {right}"), "#"
    return original(self, op, left, lkind, right, rkind)


original = number_models.TypedNumbers.arithmetic


def main() -> None:
    for name, program in PROGRAMS.items():
        mbf, printed = best_time(program)
        number_models.TypedNumbers.arithmetic = ieee
        try:
            fast, printed_ieee = best_time(program)
        finally:
            number_models.TypedNumbers.arithmetic = original
        casio, _ = best_time(CASIO[name], dialect="casio")
        print(f"{name:10s} MBF {mbf * 1e3:7.1f} ms  IEEE {fast * 1e3:7.1f} ms  casio {casio * 1e3:7.1f} ms"
              f"  MBF/IEEE {mbf / fast:5.2f}  MBF/casio {mbf / casio:5.2f}"
              f"   prints {printed.strip()} (IEEE: {printed_ieee.strip()})")


if __name__ == "__main__":
    main()
