"""Start-up: the whole process, from exec to its last line of output, against
``python -c pass`` measured in the same run (a script, not a test).

    python tests/benchmarks/startup.py [--runs N] [--warmup W]

Like hyperfine: each command is run W times untimed, then N times, the commands
interleaved so that a slow spell of the shared machine hits them alike; wall
time per run; reported: median, minimum, and the ratio of medians to
``python -c pass`` run by the same interpreter.  Goals (issue 15): ``10 PRINT 1``
within 3x, Example 1 (calls PROG 1 and PROG 5) within 5x.

Ways of starting: the ``yaseer`` console script installed beside this Python
(when present) and ``python -m yaseer``; the compiled-program cache warm (the
listing ran before: the usual case) and cold (a fresh empty cache directory
per run: the first run of a listing).  Bytecode is cached as after ``pip install``.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PRINT_1 = "10 PRINT 1\n"
GOALS = {"10 PRINT 1": 3.0, "Example 1": 5.0}


def run_once(command: list[str], env: dict) -> float:
    start = time.perf_counter()
    subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   check=True, cwd=str(ROOT), env=env)
    return time.perf_counter() - start


def environment(cache: str) -> dict:
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["YASEER_CACHE_DIR"] = cache
    return env


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("--warmup", type=int, default=3)
    args = parser.parse_args(argv)
    work = Path(tempfile.mkdtemp(prefix="yaseer-startup-"))
    try:
        program = work / "print1.bas"
        program.write_text(PRINT_1)
        example1 = str(ROOT / "listings" / "example1.bas")
        script = Path(sys.executable).with_name("yaseer")
        starters = {"python -m yaseer": [sys.executable, "-m", "yaseer"]}
        if script.exists():
            starters = {"yaseer (console script)": [str(script)], **starters}
        else:
            print(f"no console script beside {sys.executable}: only python -m yaseer measured")
        warm = str(work / "cache")
        cases = {"python -c pass": ([sys.executable, "-c", "pass"], None)}
        for label, listing in (("10 PRINT 1", str(program)), ("Example 1", example1)):
            for starter, prefix in starters.items():
                cases[f"{label}: {starter}, warm cache"] = (prefix + ["run", listing], warm)
            first = next(iter(starters.values()))
            cases[f"{label}: {next(iter(starters))}, cold cache"] = (first + ["run", listing], "cold")
            cases[f"{label}: {next(iter(starters))}, no cache"] = (first + ["run", listing], "")
        times: dict[str, list[float]] = {name: [] for name in cases}
        for round_ in range(args.warmup + args.runs):
            for name, (command, cache) in cases.items():
                if cache == "cold":
                    cache = tempfile.mkdtemp(dir=work)
                elapsed = run_once(command, environment(cache if cache is not None else warm))
                if round_ >= args.warmup:
                    times[name].append(elapsed)
        base = statistics.median(times["python -c pass"])
        print(f"whole process, wall time, {args.runs} runs each after {args.warmup} untimed "
              f"({sys.executable}, Python {sys.version.split()[0]})")
        print(f"{'command':52s} {'median ms':>10s} {'min ms':>8s} {'x python -c pass':>17s}  goal")
        for name, values in times.items():
            median = statistics.median(values)
            ratio = median / base
            goal = next((limit for label, limit in GOALS.items() if name.startswith(label + ":")), None)
            verdict = "" if goal is None or "warm" not in name else (
                f"<= {goal:g}x: {'met' if ratio <= goal else 'NOT met'}")
            print(f"{name:52s} {1e3 * median:10.1f} {1e3 * min(values):8.1f} {ratio:17.2f}  {verdict}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
