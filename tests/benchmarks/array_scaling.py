"""The array path at scale: the four-bar's positions, velocities, accelerations and
forces over N positions in chunks (a script, not a test).

    python tests/benchmarks/array_scaling.py [--max-exponent 7] [--chunk 16384]

For N = 10^3 ... 10^max: CPU microseconds per position (time linear in N when
this stays flat) and the peak memory traced by ``tracemalloc`` in a second pass
(bounded when it stays flat), against one array call over all N at once where
N <= 10^5.  The chunks come from ``yaseer.linkages.chunks.angle_chunks``; each
chunk's crank torque is reduced to its largest magnitude, as a user would reduce,
store or write out each chunk.  The process's peak resident size is printed at
the end.  (On machines where OPENBLAS_CORETYPE is set, unset it for this
command alone: see the README's speed section.)
"""

from __future__ import annotations

import argparse
import resource
import sys
import time
import tracemalloc
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(Path(__file__).resolve().parent))

import numpy as np  # noqa: E402

from linkage_speed import program_2, settle_allocator  # noqa: E402
from yaseer.linkages.chunks import CHUNK, angle_chunks  # noqa: E402


def largest_torque(count: int, chunk: int) -> float:
    largest = 0.0
    for angles in angle_chunks(0.0, 360.0, count, chunk):
        largest = max(largest, float(np.max(np.abs(program_2(angles).value))))
    return largest


def cpu(function, *args) -> tuple[float, object]:
    start = time.process_time()
    result = function(*args)
    return time.process_time() - start, result


def traced_peak(function, *args) -> int:
    tracemalloc.start()
    try:
        function(*args)
        return tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-exponent", type=int, default=7)
    parser.add_argument("--chunk", type=int, default=CHUNK)
    args = parser.parse_args(argv)
    settle_allocator()
    largest_torque(10_000, args.chunk)  # warm up
    print(f"four-bar positions, velocities, accelerations, forces; chunks of {args.chunk} positions")
    print(f"{'positions':>10s} {'us/pos':>8s} {'peak MB':>8s} {'one call us/pos':>16s} {'one call peak MB':>17s}")
    first = None
    for exponent in range(3, args.max_exponent + 1):
        count = 10**exponent
        seconds, torque = cpu(largest_torque, count, args.chunk)
        peak = traced_peak(largest_torque, count, args.chunk)
        whole = ""
        if count <= 10**5:
            one_seconds, _ = cpu(program_2, np.linspace(0.0, 360.0, count))
            one_peak = traced_peak(program_2, np.linspace(0.0, 360.0, count))
            whole = f"{1e6 * one_seconds / count:16.3f} {one_peak / 2**20:17.1f}"
        per = 1e6 * seconds / count
        if exponent == min(5, args.max_exponent):
            first = per
        print(f"{count:>10d} {per:8.3f} {peak / 2**20:8.1f} {whole}")
    print(f"time per position at 10^{args.max_exponent} / at 10^5: {per / first:.2f} (1 = linear; below 10^5 "
          f"numpy's cost per call shows); "
          f"peak resident size of this process: {resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MB")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
