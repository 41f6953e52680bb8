"""gw's LOG memo (gw_transcendental._LOG_RATIOS) against no memo, on BM8 (a script, not a test).

    python tests/benchmarks/gw_log_memo.py [--repeat N] [--scales 1 20 100]

BM8 (tests/benchmarks/classic/bm8.bas: K^2, LOG(K), SIN(K) for K = 1..1000, the count
multiplied by each scale) runs in process in gw three ways, in turn within each repeat:
the memo emptied before the run (what a fresh process sees: ``cold``), the memo kept from
the runs before (a session or a notebook that runs it again: ``warm``), and no memo (a dict
that keeps nothing: ``none``; its one Python-level ``__setitem__`` a call is the only cost
it adds, well under a hundredth of a LOG).  Printed: CPU seconds, best of N each, and the
ratios none/cold and none/warm (above 1: the memo pays).  The screen output of every run is
compared: the memo must not change a digit.
"""

from __future__ import annotations

import argparse
import io
import resource
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from classic_workloads import in_repo, scaled  # noqa: E402
from yaseer.basic.arithmetic import gw_transcendental  # noqa: E402
from yaseer.basic.machine.machine import Machine  # noqa: E402


class Forgetful(dict):
    """A memo that keeps nothing: every LOG computes its ratio."""

    def __setitem__(self, key, value) -> None:
        pass


def cpu_seconds() -> float:
    me = resource.getrusage(resource.RUSAGE_SELF)
    return me.ru_utime + me.ru_stime


def run(program: str) -> tuple[float, str]:
    screen = io.StringIO()
    machine = Machine(screen=screen, printer=io.StringIO(), dialect="gw")
    start = cpu_seconds()
    machine.load(program)
    machine.run()
    return cpu_seconds() - start, screen.getvalue()


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=7, help="best of N runs of each way")
    parser.add_argument("--scales", type=float, nargs="*", default=[1.0, 20.0, 100.0],
                        help="BM8's loop count factors (K up to 1000 times each)")
    args = parser.parse_args()
    bm8 = next(w for w in in_repo() if w.name == "bm8")
    memo = gw_transcendental._LOG_RATIOS
    print(f"gw BM8 in process, LOG memo of {gw_transcendental._LOG_MEMO_SIZE} ratios against none (CPU s, best of {args.repeat})")
    print(f"{'K up to':>9} {'cold':>8} {'warm':>8} {'none':>8} {'none/cold':>10} {'none/warm':>10}")
    for factor in args.scales:
        program = scaled(bm8.text, factor)
        best = {"cold": float("inf"), "warm": float("inf"), "none": float("inf")}
        outputs = set()
        for _ in range(args.repeat):
            for way in best:
                gw_transcendental._LOG_RATIOS = Forgetful() if way == "none" else memo
                if way == "cold":
                    memo.clear()
                seconds, output = run(program)
                best[way] = min(best[way], seconds)
                outputs.add(output)
        gw_transcendental._LOG_RATIOS = memo
        if len(outputs) != 1:
            print("the outputs differ:", outputs)
            return 1
        print(f"{round(1000 * factor):>9} {best['cold']:8.4f} {best['warm']:8.4f} {best['none']:8.4f} "
              f"{best['none'] / best['cold']:10.2f} {best['none'] / best['warm']:10.2f}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
