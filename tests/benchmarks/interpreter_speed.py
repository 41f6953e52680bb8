"""Interpreter speed: yaseer against bwbasic and plain Python (a script, not a test).

    python tests/benchmarks/interpreter_speed.py [--target SECONDS] [--repeat N]

1. The tight loop ``10 FOR I=1 TO 100000: A=A+1: NEXT``: yaseer (load + compile +
   run, in process) in each dialect (casio: doubles; gw: singles, every result
   rounded) against the same loop in plain Python (a function with float locals,
   ``while`` and ``for range`` forms), and against bwbasic.  In gw also an integer
   loop ``FOR I% = 1 TO 30000`` against the same loop over a single ``I``.
   Single-precision loop bodies (:data:`SINGLE_BODIES`: the classic programs'
   arithmetic, and bodies whose every result must be rounded) in gw against the same
   loop in casio; goal (issue 22): gw within 4x.
2. Rugg/Feldman BM1-BM8 and Ahl (the workloads of tests/benchmarks/classic/, see
   classic_workloads.py; ``--extra DIR`` adds other copies, e.g. a directory of
   ``bmN.bas`` + ``bw_bmN.bas``, skipped with one line when DIR is absent): each
   loop count is scaled so that bwbasic needs about ``--target`` seconds, then
   yaseer runs the same scaled program in casio and in gw.  Without bwbasic on PATH
   this part is skipped with one line.  Reported: seconds and the ratio bwbasic /
   yaseer, in process (yaseer's compile + run, casio) and as whole processes
   (``python -m yaseer run [--dialect gw]``, which adds Python's start-up) in each
   dialect; goal (issues 15 and 22): every whole process at least 20x faster.
   A fair measure needs bwbasic to run long enough that yaseer's start-up (the whole
   process of ``10 END``, printed first) does not dominate yaseer's time: at 20x, a
   program bwbasic runs in T seconds leaves yaseer T/20 s, so the default ``--target``
   is 5 s (start-up, about 0.05-0.07 s, then at most a third of a 20x process; each
   row prints its share).  At ``--target 1`` start-up alone makes 20x out of reach.
   ``--python`` runs the whole processes with another interpreter, e.g. one with a
   regular ``pip install .`` (an editable install's import hook, which every start of
   the development venv pays, is not what a user's start pays).
3. ``--arith decimal`` (casio's 12-digit decimal arithmetic, yaseer/basic/arithmetic/
   decimal_arith.py) against binary on the same classic programs, loop counts
   multiplied by ``--decimal-scale``, in process (compile + run); needs no bwbasic.
   Goal (issue 22): decimal at most 3x binary.
4. Start-up: whole process to the first byte of output of a paper listing (wall time).

Times are CPU seconds (user + system, best of N), which other jobs on a shared
machine disturb far less than wall time.  Every ratio is measured in this one run;
nothing is compared with stored times.
"""

from __future__ import annotations

import argparse
import atexit
import io
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
# Optional other copies of the classic programs (not part of the repository).
EXTRA_CLASSIC = Path(os.environ.get("YASEER_CLASSIC", ROOT.parent / "shared" / "bench" / "classic"))
sys.path.insert(0, str(ROOT))
sys.path.insert(0, str(Path(__file__).resolve().parent))

from classic_workloads import BWBASIC_PEER, from_directory, in_repo, scaled  # noqa: E402
from yaseer.basic.machine.machine import Machine  # noqa: E402

TIGHT_LOOP = "10 FOR I=1 TO {n}: A=A+1: NEXT\n"
BODY_LOOP = "5 B=1.5: C=1.0001\n10 FOR I=1 TO {n}: {body}: NEXT\n"
SINGLE_BODIES = (
    "A=I/I*I+I-I",  # BM3's line 50 (every result exact)
    "A=I/2*3+4-5",  # BM4-BM7's line
    "A=I^2: B=SQR(I)",  # BM8's power and Ahl's square root
    "A=I*1.1: B=B*C",  # products that need rounding
    "A=I/3: C=B/7",  # quotients that need rounding
    "A=A+.1: B=B-C/3",  # sums that need rounding
    "A=A*1.0001+B/3",  # all three
)
BODY_GOAL = 4.0  # issue 22: a single-precision loop body in gw within 4x of the same body in casio
TIGHT_LOOP_BW = "10 FOR I=1 TO {n}\n20 A=A+1\n30 NEXT I\n40 SYSTEM\n"
MAX_SCALE = 20_000
PROCESS_GOAL = 20.0  # issue 15: the whole process at least 20x faster than bwbasic
DECIMAL_GOAL = 3.0  # issue 22: --arith decimal at most 3x binary on the classic programs
BWBASIC_ONLY = set(BWBASIC_PEER.values())  # the forms written for bwbasic alone


def cpu_seconds() -> float:
    """CPU time of this process and its finished children (user + system).

    CPU time rather than wall time: the machine is shared, and CPU time is far less
    disturbed by other jobs.
    """
    me = resource.getrusage(resource.RUSAGE_SELF)
    children = resource.getrusage(resource.RUSAGE_CHILDREN)
    return me.ru_utime + me.ru_stime + children.ru_utime + children.ru_stime


def best_of(repeat: int, function) -> float:
    """The least CPU time of ``repeat`` calls of ``function``."""
    times = []
    for _ in range(repeat):
        start = cpu_seconds()
        function()
        times.append(cpu_seconds() - start)
    return min(times)


def yaseer_in_process(text: str, dialect: str = "casio") -> None:
    machine = Machine(screen=io.StringIO(), printer=io.StringIO(), dialect=dialect)
    machine.load(text)
    machine.run()


def decimal_against_binary(scale: float, repeat: int) -> None:
    """Print each classic program's time in casio with --arith decimal beside binary."""
    from yaseer.basic.dialects.dialect import CASIO

    decimal = CASIO.with_arithmetic("decimal")
    print(f"\nclassic benchmarks in casio, loop counts x{scale:g}, in process: --arith decimal against binary")
    print(f"{'program':8} {'binary s':>9} {'decimal s':>10} {'ratio':>7}  goal: at most {DECIMAL_GOAL:g}")
    for workload in in_repo():
        if workload.name in BWBASIC_ONLY:
            continue
        program = scaled(workload.text, scale)
        t_binary = best_of(repeat, lambda: yaseer_in_process(program, "casio"))
        t_decimal = best_of(repeat, lambda: yaseer_in_process(program, decimal))
        ratio = t_decimal / t_binary
        print(f"{workload.name:8} {t_binary:9.4f} {t_decimal:10.4f} {ratio:7.1f}  "
              f"{'met' if ratio <= DECIMAL_GOAL else 'NOT met'}")


def plain_python_while(n: int) -> float:
    a = 0.0
    i = 1.0
    while i <= n:
        a = a + 1.0
        i = i + 1.0
    return a


def plain_python_range(n: int) -> float:
    a = 0.0
    for _ in range(1, n + 1):
        a = a + 1.0
    return a


# Whole processes start outside the checkout: ``python -m yaseer`` started in it would import
# ./yaseer (the current directory comes first on sys.path), not the yaseer of ``--python``.
# They start in an empty directory of their own, not in the shared temporary directory: the
# first import lists the current directory (the shared /tmp held 2,451 files one evening: 10-27M
# of a 120M-instruction start, varying with what other jobs had left there).  Their compiled
# programs are kept in a cache of their own too: the shared ~/.cache/yaseer, which other jobs
# fill, dropped every entry older than three minutes that evening (a dropped entry or source
# fingerprint makes a start cold).
WORK = tempfile.mkdtemp(prefix="yaseer-bench-")
OUTSIDE = os.path.join(WORK, "run")
CACHE = os.path.join(WORK, "cache")
os.mkdir(OUTSIDE)
os.mkdir(CACHE, 0o700)
atexit.register(shutil.rmtree, WORK, True)


PROCESS_TIMEOUT = [120.0]  # seconds a whole process may take before its row is given up (--timeout)


class ProcessTimeout(Exception):
    """A measured process passed :data:`PROCESS_TIMEOUT` (a heavily loaded machine): the
    caller prints one line and goes on with the next row."""


def run_process(command: list[str]) -> None:
    # stdin closed: bwbasic falls into its interactive shell after an error
    try:
        subprocess.run(command, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                       check=False, cwd=OUTSIDE, timeout=PROCESS_TIMEOUT[0], env=installed_env())
    except subprocess.TimeoutExpired:
        raise ProcessTimeout(f"{Path(command[0]).name} passed its {PROCESS_TIMEOUT[0]:g} s timeout "
                             f"(a loaded machine?)") from None


def bwbasic_time(text: str, repeat: int) -> float:
    with tempfile.NamedTemporaryFile("w", suffix=".bas", delete=False) as handle:
        handle.write(text)
    try:
        return best_of(repeat, lambda: run_process(["bwbasic", handle.name]))
    finally:
        os.unlink(handle.name)


PROCESS_PYTHON = [sys.executable]  # the interpreter of the whole-process runs (--python)


def yaseer_process_time(text: str, repeat: int, dialect: str = "casio") -> float:
    with tempfile.NamedTemporaryFile("w", suffix=".bas", delete=False) as handle:
        handle.write(text)
    try:
        return best_of(repeat, lambda: run_process([PROCESS_PYTHON[0], "-m", "yaseer", "run", "--dialect", dialect,
                                                    handle.name]))
    finally:
        os.unlink(handle.name)


def installed_env() -> dict:
    """The environment of an installed yaseer: bytecode cached (pip compiles it on install), and
    compiled programs in this run's own cache (:data:`CACHE`)."""
    env = dict(os.environ)
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    env["PYTHONPYCACHEPREFIX"] = os.path.join(tempfile.gettempdir(), "yaseer-pycache")
    env["YASEER_CACHE_DIR"] = CACHE
    return env


def first_output_time(command: list[str]) -> float:
    """Wall seconds from starting ``command`` to its first byte of output."""
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.PIPE,
                               stderr=subprocess.DEVNULL, cwd=OUTSIDE, env=installed_env())
    process.stdout.read(1)
    elapsed = time.perf_counter() - start
    process.stdout.read()
    process.wait()
    return elapsed


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--target", type=float, default=5.0,
                        help="seconds bwbasic should need per program (long enough that start-up does not dominate)")
    parser.add_argument("--classic-only", action="store_true", help="only the classic benchmarks against bwbasic")
    parser.add_argument("--only", nargs="*", default=None, help="only these classic programs (e.g. bm8 ahl)")
    parser.add_argument("--repeat", type=int, default=3, help="best of N runs")
    parser.add_argument("--extra", type=Path, default=EXTRA_CLASSIC,
                        help="a directory of other copies of the classic programs (NAME.bas + bw_NAME.bas); "
                             "default $YASEER_CLASSIC or ../shared/bench/classic beside the checkout")
    parser.add_argument("--decimal-scale", type=float, default=10.0,
                        help="loop count factor of the classic programs for --arith decimal against binary")
    parser.add_argument("--decimal-only", action="store_true", help="only --arith decimal against binary")
    parser.add_argument("--python", default=sys.executable,
                        help="the Python of the whole-process runs (e.g. a venv with a regular pip install)")
    parser.add_argument("--timeout", type=float, default=PROCESS_TIMEOUT[0],
                        help="seconds a whole process (bwbasic or yaseer) may take; past it the row is skipped")
    args = parser.parse_args()
    PROCESS_PYTHON[0] = args.python
    PROCESS_TIMEOUT[0] = args.timeout
    if args.decimal_only:
        decimal_against_binary(args.decimal_scale, args.repeat)
        return 0
    have_bwbasic = shutil.which("bwbasic") is not None
    if not args.classic_only:
        loops_against_python_and_casio(args.repeat, have_bwbasic)
    if have_bwbasic:
        try:
            classic_against_bwbasic(args)
        except ProcessTimeout as timeout:  # (the start-up's `10 END`: every row would time out too)
            print(f"classic benchmarks: {timeout}; skipped")
    else:
        print("bwbasic not found on PATH: the classic comparisons are skipped")
    if args.classic_only:
        return 0

    decimal_against_binary(args.decimal_scale, args.repeat)

    listing = ROOT / "listings" / "example1.bas"
    if listing.exists():
        command = [sys.executable, "-m", "yaseer", "run", str(listing)]
        first_output_time(command)  # warm the compiled-program cache, the bytecode and the OS file cache
        t_first = min(first_output_time(command) for _ in range(5))
        t_python = min(first_output_time([sys.executable, "-c", "print(1)"]) for _ in range(5))
        print(f"\nstart-up to first output of {listing.relative_to(ROOT)}: {t_first:.3f} s (best of 5; "
              f"bytecode cached as after pip install; `python -c 'print(1)'` takes {t_python:.3f} s here)")
    return 0


def loops_against_python_and_casio(repeat: int, have_bwbasic: bool) -> None:
    """Part 1: the tight loop against plain Python, integer loops, gw's loop bodies against casio."""
    n = 100_000
    t_while = best_of(repeat, lambda: plain_python_while(n))
    t_range = best_of(repeat, lambda: plain_python_range(n))
    for dialect in ("casio", "gw"):
        t_yaseer = best_of(repeat, lambda: yaseer_in_process(TIGHT_LOOP.format(n=n), dialect))
        print(f"tight loop, {n} passes, --dialect {dialect}: yaseer {t_yaseer:.4f} s; plain Python while "
              f"{t_while:.4f} s (ratio {t_yaseer / t_while:.2f}), for-range {t_range:.4f} s "
              f"(ratio {t_yaseer / t_range:.2f}; goal: within 5)")
    for body in ("A=A+1", "A=A+I%*2"):
        typed = f"10 FOR I%=1 TO 30000: {body}: NEXT\n"
        untyped = typed.replace("I%", "I")
        t_int = best_of(repeat, lambda: yaseer_in_process(typed, "gw"))
        t_single = best_of(repeat, lambda: yaseer_in_process(untyped, "gw"))
        print(f"gw {typed.strip()!r}: {t_int:.4f} s; with a single I: {t_single:.4f} s "
              f"(ratio {t_int / t_single:.2f}; goal: at most 1)")
    passes = 20_000
    for body in SINGLE_BODIES:
        loop = BODY_LOOP.format(n=passes, body=body)
        t_casio = best_of(repeat, lambda: yaseer_in_process(loop, "casio"))
        t_gw = best_of(repeat, lambda: yaseer_in_process(loop, "gw"))
        ratio = t_gw / t_casio
        print(f"loop body {body!r:24} {passes} passes: casio {1e9 * t_casio / passes:6.0f} ns, gw "
              f"{1e9 * t_gw / passes:6.0f} ns a pass (ratio {ratio:4.1f}; goal: within {BODY_GOAL:g}: "
              f"{'met' if ratio <= BODY_GOAL else 'NOT met'})")
    if have_bwbasic:
        big = 1_000_000
        try:
            t_bw = bwbasic_time(TIGHT_LOOP_BW.format(n=big), 1)
        except ProcessTimeout as timeout:
            print(f"tight loop, {big} passes: {timeout}; skipped")
            return
        t_y = best_of(repeat, lambda: yaseer_in_process(TIGHT_LOOP.format(n=big)))
        print(f"tight loop, {big} passes: bwbasic {t_bw:.3f} s, yaseer {t_y:.3f} s: {t_bw / t_y:.0f}x faster")


def classic_against_bwbasic(args) -> None:
    """Part 2: the classic programs scaled to ``--target`` s of bwbasic, against yaseer in
    process and as whole processes, with start-up's share of the gw process."""
    workloads = [(w.name, w.text, w.bwbasic) for w in in_repo()]
    if args.extra.is_dir():
        workloads += [(w.name + "*", w.text, w.bwbasic) for w in from_directory(args.extra)]
        print(f"(* the copies in {args.extra})")
    else:
        print(f"extra classic copies: {args.extra} not found, skipped")
    if args.only:
        workloads = [w for w in workloads if w[0].rstrip("*") in args.only]
    yaseer_process_time("10 END\n", 1, "gw")  # warm the bytecode and the compiled-program caches
    start_casio = yaseer_process_time("10 END\n", args.repeat)
    start_gw = yaseer_process_time("10 END\n", args.repeat, "gw")
    print(f"\nclassic benchmarks, loop counts scaled so that bwbasic needs ~{args.target:g} s; yaseer's start-up "
          f"(whole process of `10 END`): casio {start_casio:.3f} s, gw {start_gw:.3f} s, "
          f"{100 * start_gw / (args.target / PROCESS_GOAL):.0f}% of the {args.target / PROCESS_GOAL:.3f} s a "
          f"{PROCESS_GOAL:g}x whole process may take")
    print(f"{'program':8} {'scale':>6} {'bwbasic s':>10} {'yaseer s':>9} {'x faster':>9} "
          f"{'process s':>10} {'x (process)':>11} {'gw s':>7} {'gw x':>6} {'gw process':>10} {'gw x':>6} {'start%':>6}"
          f"  goal: whole process >= {PROCESS_GOAL:g}x")
    for name, ms_text, bw_text in workloads:
        try:
            classic_row(args, name, ms_text, bw_text, start_gw)
        except ProcessTimeout as timeout:
            print(f"{name:8} {timeout}; row skipped", flush=True)


TARGET_TOLERANCE = 0.1  # bwbasic's time within 10% of --target (else the row says how far off it is)


def scaled_to_target(bw_text: str, target: float, repeat: int) -> tuple[float, float]:
    """(the loop count factor at which bwbasic runs ``bw_text`` in about ``target`` s, bwbasic's
    time there, best of ``repeat``).  Each estimate is measured as the row's time is (best of
    ``repeat``: a single run on a loaded machine is slower, and a factor chosen from it makes the
    row's own best-of time fall short), and refined until within :data:`TARGET_TOLERANCE`:
    the program at the listing's own count runs in a few hundredths of a second, too short to
    scale from once (bwbasic's start-up and the clock's 10 ms steps)."""
    factor = min(MAX_SCALE, max(1.0, target / max(bwbasic_time(bw_text, 1), 1e-2)))
    t_bw = bwbasic_time(scaled(bw_text, factor), repeat)
    for _ in range(6):
        if abs(t_bw - target) < TARGET_TOLERANCE * target or factor >= MAX_SCALE and t_bw < target:
            break
        factor = min(MAX_SCALE, max(1.0, factor * target / max(t_bw, 1e-2)))
        t_bw = bwbasic_time(scaled(bw_text, factor), repeat)
    return factor, t_bw


def classic_row(args, name: str, ms_text: str, bw_text: str, start_gw: float) -> None:
    """One row of :func:`classic_against_bwbasic`: ``bw_text`` scaled to ``--target`` s of
    bwbasic, ``ms_text`` scaled alike in yaseer."""
    factor, t_bw = scaled_to_target(bw_text, args.target, args.repeat)
    program = scaled(ms_text, factor)
    t_y = best_of(args.repeat, lambda: yaseer_in_process(program))
    t_p = yaseer_process_time(program, args.repeat)
    t_gw = best_of(args.repeat, lambda: yaseer_in_process(program, "gw"))
    t_gwp = yaseer_process_time(program, args.repeat, "gw")
    verdict = "met" if min(t_bw / t_p, t_bw / t_gwp) >= PROCESS_GOAL else "NOT met"
    print(f"{name:8} {factor:6.0f} {t_bw:10.3f} {t_y:9.4f} {t_bw / t_y:9.1f} {t_p:10.3f} {t_bw / t_p:11.1f} "
          f"{t_gw:7.4f} {t_bw / t_gw:6.1f} {t_gwp:10.3f} {t_bw / t_gwp:6.1f} {100 * start_gw / t_gwp:5.0f}%  "
          f"{verdict}{off_target(t_bw, args.target)}", flush=True)


def off_target(t_bw: float, target: float) -> str:
    """A note on a row whose bwbasic time missed ``target`` by more than :data:`TARGET_TOLERANCE`
    (start-up then weighs differently in its ratios)."""
    if abs(t_bw - target) < TARGET_TOLERANCE * target:
        return ""
    return f" (bwbasic ran {t_bw:.2f} s, not the {target:g} s target)"


if __name__ == "__main__":
    raise SystemExit(main())
