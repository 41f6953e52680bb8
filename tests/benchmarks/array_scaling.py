"""The array path at scale: one call of the four-bar with positions, velocities,
accelerations and forces over N positions (a script, not a test).

    python tests/benchmarks/array_scaling.py [--max-exponent 7] [--repeat 3]

For N = 10^3 ... 10^max, each in a fresh process: one call
``fourbar(..., numpy.linspace(0, 360, N), ...).forces(...).value`` (the crank
torque at every position; linkage_speed.program_2), as a user writes it for any
N.  Above ``yaseer.linkages.chunks.CHUNK`` positions the library computes it
chunk by chunk by itself.  Printed: CPU microseconds per position (best of R;
time linear in N when this stays flat), the peak memory traced by
``tracemalloc`` from before the angles are made to the torque read (the angles
and the torque, 16 bytes a position, are part of it), and the peak resident
size of the process (Python and numpy included).  Then the time per position at
10^max against 10^3, measured in this run.  Goals (issue 22): under 200 MB at
every N up to 10^7 (traced), time per position flat from 10^3 to 10^7.  (On
machines where OPENBLAS_CORETYPE is set, unset it for this command alone: see
the README's speed section.)
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import time
import tracemalloc
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
sys.path.insert(0, str(Path(__file__).resolve().parent))

PEAK_GOAL_MB = 200.0


def child(count: int, repeat: int) -> dict:
    """Time and memory of one call over ``count`` positions, in this process."""
    import numpy as np

    from linkage_speed import program_2, settle_allocator

    settle_allocator()
    program_2(np.linspace(0.0, 360.0, 1000)).value  # warm up
    calls = max(1, 100_000 // count)
    best = float("inf")
    for _ in range(repeat):
        start = time.process_time()
        for _ in range(calls):
            torque = program_2(np.linspace(0.0, 360.0, count)).value
        best = min(best, (time.process_time() - start) / calls)
        del torque
    tracemalloc.start()
    torque = program_2(np.linspace(0.0, 360.0, count)).value
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return {"seconds": best, "traced": peak, "largest": float(np.max(np.abs(torque))),
            "rss": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--max-exponent", type=int, default=7)
    parser.add_argument("--repeat", type=int, default=3)
    parser.add_argument("--child", type=int, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child:
        print(json.dumps(child(args.child, args.repeat)))
        return 0
    from yaseer.linkages.chunks import CHUNK

    print(f"four-bar positions, velocities, accelerations, forces: one call over N positions "
          f"(chunks of {CHUNK} above {CHUNK}), each N in a fresh process")
    print(f"{'positions':>10s} {'us/pos':>8s} {'traced peak MB':>15s} {'resident peak MB':>17s}  "
          f"goal: traced < {PEAK_GOAL_MB:g} MB")
    per = {}
    for exponent in range(3, args.max_exponent + 1):
        count = 10**exponent
        out = subprocess.run([sys.executable, __file__, "--child", str(count), "--repeat", str(args.repeat)],
                             capture_output=True, text=True, check=True).stdout
        result = json.loads(out)
        per[exponent] = 1e6 * result["seconds"] / count
        traced = result["traced"] / 2**20
        print(f"{count:>10d} {per[exponent]:8.3f} {traced:15.1f} {result['rss'] / 2**20:17.1f}  "
              f"{'met' if traced < PEAK_GOAL_MB else 'NOT met'}")
    top = args.max_exponent
    print(f"time per position at 10^{top} / at 10^3: {per[top] / per[3]:.2f} (goal: flat, at most about 1)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
