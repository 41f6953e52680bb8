"""What keeping gw doubles in MBF's range costs: a double-precision loop compiled
three ways in one run, as ratios (no wall-clock claims).

* inline: the range check yaseer compiles (``number_models._in_double_range``, a
  chained comparison around each double ``+ - *``);
* call: the same check through the ``_dk`` helper (one Python call per operation);
* unchecked: plain Python float arithmetic (no Overflow at 1.7D+38: wrong in gw).

Run: ``YASEER_CACHE_DIR= python tests/benchmarks/gw_double_range.py`` (the empty
cache directory switches the compiled-program cache off, so each way is compiled).
"""

from __future__ import annotations

import io
import time

from yaseer.basic.compile import number_models
from yaseer.basic.machine.machine import Machine

PROGRAM = ("10 DEFDBL A-H\n20 S = 0: FOR I% = 1 TO 30000: A = I% * 1.5#: S = S + A * A - A / 3: NEXT\n"
           "30 PRINT S\n")


def best_time(repeats: int = 7) -> tuple[float, str]:
    """The fastest of ``repeats`` runs of PROGRAM (seconds), and what it printed."""
    best, printed = float("inf"), ""
    for _ in range(repeats):
        machine = Machine(screen=io.StringIO(), dialect="gw")
        machine.load(PROGRAM)
        start = time.perf_counter()
        machine.run()
        best = min(best, time.perf_counter() - start)
        printed = machine.screen.stream.getvalue()
    return best, printed


def main() -> None:
    inline, printed = best_time()
    original = number_models._in_double_range
    try:
        number_models._in_double_range = lambda code: f"_dk({code})"
        call, printed_call = best_time()
        number_models._in_double_range = lambda code: f"({code})"
        unchecked, printed_unchecked = best_time()
    finally:
        number_models._in_double_range = original
    assert printed == printed_call == printed_unchecked, (printed, printed_call, printed_unchecked)
    print(f"inline/unchecked {inline / unchecked:.2f}  call/unchecked {call / unchecked:.2f}")


if __name__ == "__main__":
    main()
