"""Start-up: the whole process, from exec to its last line of output, against
``python -c pass`` measured in the same run (a script, not a test).

    python tests/benchmarks/startup.py [--runs N] [--warmup W] [--python PYTHON] [--instructions]

``--python`` measures the yaseer installed in another environment (a regular
``pip install .``, whose ``python -c pass`` is not slowed by an editable
install's import hook); the default is the Python running this script.

Like hyperfine: each command is run W times untimed, then N times, the commands
interleaved so that a slow spell of the shared machine hits them alike; wall
time and CPU time (user + system of the child) per run; reported: median wall,
minimum wall, median CPU, and the ratios of the medians to ``python -c pass`` run
by the same interpreter (wall, and CPU: on a busy machine CPU time is far less
disturbed).  ``--instructions`` counts instead the machine instructions of one run of
each command under ``valgrind --tool=callgrind`` (``PYTHONHASHSEED=0``): a count does not
depend on the machine's load, and repeats to a few parts in a million.  Goals, judged on
the CPU (or instruction) ratio: ``10 PRINT 1`` with the cache warm within 3x (issue 15)
and cold within 5x (issue 22: the first run of a listing parses and compiles it); every
paper example (listings/example*.bas, which call the library programs) with the cache
warm within 5x.

Ways of starting: the ``yaseer`` console script installed beside this Python
(when present) and ``python -m yaseer``; the compiled-program cache

- warm: the listing ran before (the usual case);
- cold: a new listing, never run, so it is parsed and compiled and its entry written; each
  run gets a fresh cache directory holding only what yaseer keeps there for every listing,
  the fingerprint of its compiler's sources (``toolchain-*.key``, written by the first run
  after an install: :func:`yaseer.sealed_cache.source_fingerprint`), copied from the warm
  directory.  This is what a user's first run of each new listing pays;
- first run after install: a fresh empty cache directory per run, so the run also reads and
  hashes the compiler's sources (about 1.4 MB) to make that fingerprint: paid once per install;
- none (``YASEER_CACHE_DIR=``): parsed and compiled, nothing read or written.

Bytecode is cached as after ``pip install``.
"""

from __future__ import annotations

import argparse
import glob
import os
import re
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


COLLECTED = re.compile(r"Collected : (\d+)")


def count_once(command: list[str], env: dict, cwd: Path) -> int:
    """Machine instructions of one run of ``command`` started in ``cwd``, counted by callgrind."""
    done = subprocess.run(["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", *command],
                          stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                          cwd=str(cwd), env=dict(env, PYTHONHASHSEED="0"), check=True)
    return int(COLLECTED.search(done.stderr).group(1))


def environment(cache: str) -> dict:
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["YASEER_CACHE_DIR"] = cache
    return env


def fresh_cache(work: Path, warm: str, seeded: bool) -> str:
    """A new private cache directory in ``work``: empty, or (``seeded``) holding the warm
    directory's fingerprints of the compiler's sources (``toolchain-*.key``) and no entry."""
    cache = tempfile.mkdtemp(dir=work)
    if seeded:
        for key in glob.glob(os.path.join(warm, "toolchain-*.key")):
            shutil.copy(key, cache)
    return cache


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--runs", type=int, default=20)
    parser.add_argument("--warmup", type=int, default=3)
    parser.add_argument("--python", default=sys.executable,
                        help="the Python whose installed yaseer is measured (default: this one)")
    parser.add_argument("--instructions", action="store_true",
                        help="count each command's instructions once under valgrind instead of timing it")
    args = parser.parse_args(argv)
    if args.instructions and shutil.which("valgrind") is None:
        print("valgrind not found on PATH: instruction counts skipped")
        return 0
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
        for starter, prefix in starters.items():
            cases[f"10 PRINT 1: {starter}, cold cache"] = (prefix + ["run", str(program)], "cold")
            goals[f"10 PRINT 1: {starter}, cold cache"] = 5.0
        cases[f"10 PRINT 1: {first_name}, first run after install"] = (first + ["run", str(program)], "empty")
        cases[f"10 PRINT 1: {first_name}, no cache"] = (first + ["run", str(program)], "")
        for listing in EXAMPLES:
            label = f"Example {listing.stem[len('example'):]}: {first_name}"
            cases[f"{label}, warm cache"] = (first + ["run", str(listing)], warm)
            goals[f"{label}, warm cache"] = 5.0
            cases[f"{label}, cold cache"] = (first + ["run", str(listing)], "cold")
        # The warm directory filled (and its fingerprint written) before anything is measured.
        for command, cache in cases.values():
            if cache == warm:
                run_once(command, environment(warm), work)
        runs = 1 if args.instructions else args.runs
        times: dict[str, list[tuple[float, float]]] = {name: [] for name in cases}
        for round_ in range((0 if args.instructions else args.warmup) + runs):
            for name, (command, cache) in cases.items():
                if cache in ("cold", "empty"):
                    cache = fresh_cache(work, warm, cache == "cold")
                # Started outside the checkout, so `python -m yaseer` runs the installed yaseer, not ./yaseer.
                env = environment(cache if cache is not None else warm)
                if args.instructions:
                    times[name].append((count_once(command, env, work),) * 2)
                    continue
                elapsed = run_once(command, env, work)
                if round_ >= args.warmup:
                    times[name].append(elapsed)
        if args.instructions:
            return report_counts(times, goals, python)
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


def report_counts(counts: dict, goals: dict, python: str) -> int:
    base = counts["python -c pass"][0][0]
    print(f"whole process, instructions of one run each (valgrind --tool=callgrind, PYTHONHASHSEED=0; {python})")
    print(f"{'command':52s} {'instructions':>13s} {'x pass':>7s}  goal")
    for name, ((count, _),) in counts.items():
        goal = goals.get(name)
        verdict = "" if goal is None else f"<= {goal:g}x: {'met' if count / base <= goal else 'NOT met'}"
        print(f"{name:52s} {count:13,d} {count / base:7.2f}  {verdict}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
