"""Start-up: the whole process, from exec to its last line of output, against
``python -c pass`` measured in the same run (a script, not a test).

    python tests/benchmarks/startup.py [--runs N] [--warmup W] [--python PYTHON]

``--python`` measures the yaseer installed in another environment (a regular
``pip install .``, whose ``python -c pass`` is not slowed by an editable
install's import hook); the default is the Python running this script.

Like hyperfine: each command is run W times untimed, then N times, the commands
interleaved so that a slow spell of the shared machine hits them alike; wall
time and CPU time (user + system of the child) per run; reported: median wall,
minimum wall, median CPU, and the ratios of the medians to ``python -c pass`` run
by the same interpreter (wall, and CPU: on a busy machine CPU time is far less
disturbed).  Goals, judged on the CPU ratio: ``10 PRINT 1`` with the cache warm
within 3x (issue 15) and cold within 5x (issue 22: the first run of a listing
parses and compiles it); every paper example (listings/example*.bas, which call
the library programs) with the cache warm within 5x.

Ways of starting: the ``yaseer`` console script installed beside this Python
(when present) and ``python -m yaseer``; the compiled-program cache warm (the
listing ran before: the usual case) and cold (a fresh empty cache directory
per run: the first run of a listing).  Bytecode is cached as after ``pip install``.
"""

from __future__ import annotations

import argparse
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PRINT_1 = "10 PRINT 1\n"
EXAMPLES = sorted((ROOT / "listings").glob("example*.bas"))


def children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def run_once(command: list[str], env: dict, cwd: Path) -> tuple[float, float]:
    """Wall and CPU seconds of one run of ``command`` started in ``cwd``."""
    cpu, start = children_cpu(), time.perf_counter()
    subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                   check=True, cwd=str(cwd), env=env)
    return time.perf_counter() - start, children_cpu() - cpu


def environment(cache: str) -> dict:
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["YASEER_CACHE_DIR"] = cache
    return env


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("--warmup", type=int, default=3)
    parser.add_argument("--python", default=sys.executable,
                        help="the Python whose installed yaseer is measured (default: this one)")
    args = parser.parse_args(argv)
    python = os.path.abspath(args.python)  # not resolved: a venv's python is a link to the base one
    work = Path(tempfile.mkdtemp(prefix="yaseer-startup-"))
    try:
        program = work / "print1.bas"
        program.write_text(PRINT_1)
        script = Path(python).with_name("yaseer")
        starters = {"python -m yaseer": [python, "-m", "yaseer"]}
        if script.exists():
            starters = {"yaseer (console script)": [str(script)], **starters}
        else:
            print(f"no console script beside {python}: only python -m yaseer measured")
        warm = str(work / "cache")
        cases = {"python -c pass": ([python, "-c", "pass"], None)}
        goals = {}
        first_name, first = next(iter(starters.items()))
        for starter, prefix in starters.items():
            cases[f"10 PRINT 1: {starter}, warm cache"] = (prefix + ["run", str(program)], warm)
            goals[f"10 PRINT 1: {starter}, warm cache"] = 3.0
        cases[f"10 PRINT 1: {first_name}, cold cache"] = (first + ["run", str(program)], "cold")
        goals[f"10 PRINT 1: {first_name}, cold cache"] = 5.0
        cases[f"10 PRINT 1: {first_name}, no cache"] = (first + ["run", str(program)], "")
        for listing in EXAMPLES:
            label = f"Example {listing.stem[len('example'):]}: {first_name}"
            cases[f"{label}, warm cache"] = (first + ["run", str(listing)], warm)
            goals[f"{label}, warm cache"] = 5.0
            cases[f"{label}, cold cache"] = (first + ["run", str(listing)], "cold")
        times: dict[str, list[tuple[float, float]]] = {name: [] for name in cases}
        for round_ in range(args.warmup + args.runs):
            for name, (command, cache) in cases.items():
                if cache == "cold":
                    cache = tempfile.mkdtemp(dir=work)
                # Started outside the checkout, so `python -m yaseer` runs the installed yaseer, not ./yaseer.
                elapsed = run_once(command, environment(cache if cache is not None else warm), work)
                if round_ >= args.warmup:
                    times[name].append(elapsed)
        base_wall = statistics.median(wall for wall, _ in times["python -c pass"])
        base_cpu = statistics.median(cpu for _, cpu in times["python -c pass"])
        print(f"whole process, {args.runs} runs each after {args.warmup} untimed "
              f"({python})")
        print(f"{'command':52s} {'wall ms':>8s} {'min':>6s} {'x pass':>7s} {'CPU ms':>7s} {'x pass':>7s}  goal (CPU)")
        for name, values in times.items():
            wall = statistics.median(wall for wall, _ in values)
            cpu = statistics.median(cpu for _, cpu in values)
            goal = goals.get(name)
            verdict = "" if goal is None else f"<= {goal:g}x: {'met' if cpu / base_cpu <= goal else 'NOT met'}"
            print(f"{name:52s} {1e3 * wall:8.1f} {1e3 * min(w for w, _ in values):6.1f} {wall / base_wall:7.2f} "
                  f"{1e3 * cpu:7.1f} {cpu / base_cpu:7.2f}  {verdict}")
    finally:
        shutil.rmtree(work, ignore_errors=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
