"""Where a call of PROG 2 with forces goes when a listing cycles Q(2) through 1..4 (a script,
not a test): the size of the recorded paths it runs, and what cycling them costs.

    python tests/benchmarks/prog2_footprint.py [--calls N] [--rounds R]

The cycling mix of percall.py (``Q(2)=K-4*INT(K/4)+1`` every pass) is run once, which records
and compiles its paths (yaseer.linkages.tracing).  Then, for the path of each Q(2):

* its bytecode: bytes of the compiled function (3.11's inline caches included), bytecodes
  executed by one call, the bytes of those instructions with their caches ("hot"), and the
  64-byte lines they lie on (what the interpreter loop reads as data, a line at a time);
* CPU time per call, in R interleaved rounds of N calls (medians; the machine is shared):
  the four paths called in turn (as the cycling mix calls them), one path called alone, the
  same path as four distinct code objects called in turn (same work, four times the bytecode
  to read), and the whole call through the program area (key, choice, path); each printed as
  a ratio to the one path alone measured in the same round.

The ratio of "four copies of one path" to "one path" is what the bytecode's size costs alone:
the copies do the same operations on the same values.
"""

from __future__ import annotations

import argparse
import dis
import statistics
import sys
import time
import types
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

import percall  # noqa: E402

from yaseer import binding  # noqa: E402

LINE = 64  # bytes of a cache line


def recorded_paths():
    """A machine set up as percall's cycling mix, after a run of it, and its path for each Q(2)."""
    machine = percall.machine_for(2)
    machine.load(percall.mix_listing("Q(2) cycling 1..4", 400, True))
    machine.run()
    recordings = binding._recordings[(2, None)]
    choices = machine.array("Q")
    paths = {}
    for q in (1, 2, 3, 4):
        choices[2] = float(q)
        paths[q] = recordings._chosen.get(recordings._pick(machine))
    return machine, paths


def executed_offsets(function, machine) -> set[int]:
    """The offsets of the bytecodes one call of ``function(machine)`` executes."""
    code, offsets = function.__code__, set()

    def trace(frame, event, arg):
        if frame.f_code is not code:
            return None
        frame.f_trace_opcodes = True
        if event == "opcode":
            offsets.add(frame.f_lasti)
        return trace

    sys.settrace(trace)
    try:
        function(machine)
    finally:
        sys.settrace(None)
    return offsets


def footprint(function, machine) -> tuple[int, int, int, int]:
    """(bytes of the code, bytecodes executed, hot bytes, 64-byte lines of the hot bytes)."""
    code = function.__code__
    size = len(code.co_code)
    starts = [i.offset for i in dis.get_instructions(code, show_caches=True) if i.opname != "CACHE"]
    ends = dict(zip(starts, starts[1:] + [size]))
    executed = executed_offsets(function, machine)
    hot = {byte for offset in executed for byte in range(offset, ends[offset])}
    return size, len(executed), len(hot), len({byte // LINE for byte in hot})


def copy_of(function):
    """``function`` with a code object of its own (its own bytecode and inline caches)."""
    code = function.__code__
    code = code.replace(co_code=bytes(bytearray(code.co_code)))
    return types.FunctionType(code, function.__globals__, function.__name__)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--calls", type=int, default=3000)
    parser.add_argument("--rounds", type=int, default=11)
    args = parser.parse_args(argv)
    machine, paths = recorded_paths()
    choices, angles = machine.array("Q"), machine.array("T")

    print(f"{'Q(2)':5s} {'code bytes':>10s} {'executed':>9s} {'hot bytes':>10s} {'lines':>6s}")
    lines = 0
    for q, path in paths.items():
        choices[2] = float(q)
        size, executed, hot, touched = footprint(path, machine)
        lines += touched
        print(f"{q:<5d} {size:10d} {executed:9d} {hot:10d} {touched:6d}")
    print(f"the four paths: {lines} lines, {lines * LINE} bytes of bytecode read a cycle")

    area = machine.python_areas[2]
    one = paths[2]
    copies = [one] + [copy_of(one) for _ in range(3)]

    def timed(case) -> float:
        cycling, call_for = case
        start = time.process_time()
        for k in range(args.calls):
            angles[12] = k / 10
            q = k % 4 + 1 if cycling else 2
            choices[2] = float(q)
            call_for(k, q)(machine)
        return (time.process_time() - start) / args.calls

    cases = {  # (whether Q(2) cycles, the function called)
        "four paths in turn": (True, lambda k, q: paths[q]),
        "one path alone": (False, lambda k, q: one),
        "four copies of one path": (False, lambda k, q: copies[k % 4]),
        "program area (cycling)": (True, lambda k, q: area),
    }
    for case in cases.values():  # every copy specialised, every key met
        timed(case)
    times: dict[str, list[float]] = {name: [] for name in cases}
    for _ in range(args.rounds):
        for name, case in cases.items():
            times[name].append(timed(case))
    reference = statistics.median(times["one path alone"])
    print(f"\nCPU us a call, medians of {args.rounds} interleaved rounds of {args.calls} calls; "
          f"ratio to one path alone")
    for name, values in times.items():
        median = statistics.median(values)
        print(f"{name:26s} {1e6 * median:8.2f} {median / reference:7.2f}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
