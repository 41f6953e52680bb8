"""The per-call path: one ``GOSUB PROG n`` with velocities, accelerations and forces,
from Python and through the interpreter (a script, not a test).

    python tests/benchmarks/percall.py [--calls N] [--repeat R]

For each of Programs 1, 2, 3 (forces: Z(n) = 2, Q(n) = 1, gravity) and 5, over
N crank positions (the crank angle changes every call, 0.1 deg apart):

* "from Python": the bound program area called directly, ``area(machine)``
  (inputs read from the machine's arrays, outputs checked and written back);
* "interpreter": a BASIC loop ``FOR K=0 TO N-1: T(..)=K/10: GOSUB PROG n: NEXT``,
  whole run, per pass; "loop only" is the same loop without the GOSUB PROG;
* the reference, measured in the same run: the library's plain scalar code
  (the recording switched off: yaseer.binding.MAX_RECORDINGS = 0), from Python.

Best of R, microseconds of CPU time per call (CPU time: the machine is shared).  Goals (issue 15), for ``GOSUB PROG 2``:
at most 20 us from Python and 40 us through the interpreter.
"""

from __future__ import annotations

import argparse
import io
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from yaseer import binding  # noqa: E402
from yaseer.basic.machine.machine import Machine  # noqa: E402

# Inputs of each program (element -> value); the crank angle element is varied.
INPUTS = {
    1: dict(L={1: 0.02, 2: 0.1, 3: 0.35}, T={4: 15.0}, W={2: -8.0}, A={2: 2.0}, D={0: 0.3}, E={0: -1.0},
            R={1: 0.07, 2: 0.04, 3: 0.12, 4: 0.2}, H={1: 25.0, 2: -10.0, 3: 8.0, 4: 170.0},
            M={2: 2.0, 3: 1.5, 4: 0.7}, I={2: 0.01, 3: 0.03}, F={0: 1.0, 1: -2.0, 7: 4.0, 9: 6.0}, P={1: 20.0}),
    2: dict(L={10: 1, 11: 1.2, 12: 0.3, 13: 1.0, 14: 0.8}, T={11: 20.0}, W={5: 4.0}, A={5: -1.0},
            D={2: 0.1}, E={2: 0.2}, R={8: 0.1, 9: 0.2, 10: 0.4, 11: 0.7, 12: 0.3, 13: 0.5},
            H={9: 30.0, 10: 5.0, 11: -20.0, 12: 10.0, 13: 40.0, 14: -15.0}, M={6: 3.0, 7: 2.0, 8: 1.0},
            I={6: 0.05, 7: 0.2, 8: 0.1}, F={29: 1.0, 30: 2.0, 32: -1.0, 33: 4.0, 37: 1.5}),
    3: dict(L={6: 0.5, 7: 0.25}, T={6: 30.0}, W={0: 6.0}, A={0: 1.0}, D={3: 0.2}, E={3: -0.5},
            R={0: 0.2, 5: 0.1, 6: 0.3, 7: 0.6}, H={23: 15.0, 7: 5.0, 6: -10.0}, M={0: 2.0, 1: 0.7, 5: 3.0},
            I={0: 0.02, 1: 0.004, 5: 0.4}, F={18: 4.0}),
    5: dict(Y={10: 1.5}, V={17: 1.0, 18: -2.0}, A={49: 0.5, 50: 0.25}),
}
CRANK = {1: ("T", 2), 2: ("T", 12), 3: ("T", 7), 5: ("X", 10)}
GOALS = {2: (20.0, 40.0)}  # us per call: from Python, through the interpreter


def machine_for(number: int) -> Machine:
    machine = Machine(screen=io.StringIO())
    binding.install(machine)
    for name, elements in INPUTS[number].items():
        for index, value in elements.items():
            machine.array(name)[index] = float(value)
    if number != 5:
        machine.array("Z")[number] = 2.0
        machine.array("Q")[number] = 1.0
        machine.set_scalar("G", 9.81)
    return machine


def from_python(number: int, calls: int) -> float:
    machine = machine_for(number)
    area = machine.python_areas[number]
    name, index = CRANK[number]
    values = machine.array(name)
    start = time.process_time()
    for k in range(calls):
        values[index] = 0.1 * k + (1.0 if number == 5 else 0.0)
        area(machine)
    return (time.process_time() - start) / calls


def listing(number: int, calls: int, call: bool) -> str:
    """The BASIC loop: the inputs set, then N passes (with or without the call)."""
    settings = [f"{name}({index})={value!r}" for name, elements in INPUTS[number].items()
                for index, value in elements.items()]
    if number != 5:
        settings += [f"Z({number})=2", f"Q({number})=1", "G=9.81"]
    name, index = CRANK[number]
    body = f"{name}({index})=K/10+{1 if number == 5 else 0}" + (f": GOSUB PROG {number}" if call else "")
    return f"10 {': '.join(settings)}\n20 FOR K=0 TO {calls - 1}: {body}: NEXT K\n30 END\n"


def interpreter(number: int, calls: int, call: bool) -> float:
    machine = machine_for(number)
    machine.load(listing(number, calls, call))
    machine.run()  # compile (and the first recording) outside the timing
    machine = machine_for(number)
    machine.load(listing(number, calls, call))
    start = time.process_time()
    machine.run()
    return (time.process_time() - start) / calls


def best(repeat: int, function, *args) -> float:
    return min(function(*args) for _ in range(repeat))


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--calls", type=int, default=3601)
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args(argv)
    print(f"{args.calls} calls, best of {args.repeat}, us per call")
    print(f"{'program':8s} {'plain lib':>10s} {'from Python':>12s} {'x faster':>9s} {'interpreter':>12s} "
          f"{'loop only':>10s}  goal")
    for number in (1, 2, 3, 5):
        saved = binding.MAX_RECORDINGS
        binding.MAX_RECORDINGS = 0
        binding._recordings.clear()
        plain = best(args.repeat, from_python, number, args.calls)
        binding.MAX_RECORDINGS = saved
        fast = best(args.repeat, from_python, number, args.calls)
        through = best(args.repeat, interpreter, number, args.calls, True)
        loop = best(args.repeat, interpreter, number, args.calls, False)
        goal = ""
        if number in GOALS:
            python_goal, interpreter_goal = GOALS[number]
            goal = (f"<= {python_goal:g} us from Python: {'met' if 1e6 * fast <= python_goal else 'NOT met'}; "
                    f"<= {interpreter_goal:g} us through the interpreter: "
                    f"{'met' if 1e6 * through <= interpreter_goal else 'NOT met'}")
        print(f"PROG {number:<3d} {1e6 * plain:10.1f} {1e6 * fast:12.1f} {plain / fast:9.1f} {1e6 * through:12.1f} "
              f"{1e6 * loop:10.2f}  {goal}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
