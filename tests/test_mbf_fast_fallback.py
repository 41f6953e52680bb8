"""The choice between gw's C routines (yaseer/basic/arithmetic/_mbf_fast.c, when built) and
the Python functions of gw_transcendental.py, and the pure-Python path itself: a gw program
prints the same with and without the accelerator (YASEER_PURE_PYTHON=1), and as PC-BASIC
2.0.8 prints it where PC-BASIC computes the same singles.  These run whether or not the
module is built (tests/test_mbf_fast.py compares the routines bit for bit)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

from yaseer.basic.arithmetic import arith_policy, gw_transcendental as gw

try:
    from yaseer.basic.arithmetic import _mbf_fast
except ImportError:  # not built: the Python functions alone
    _mbf_fast = None


def test_the_table_is_the_c_routines_unless_pure_python_is_asked(monkeypatch):
    """arith_policy.gw_routines: the C routines when the module is built, the Python functions
    under YASEER_PURE_PYTHON=1 (or when it is not built); "0" and "" keep the C ones."""
    monkeypatch.setenv(arith_policy.PURE_PYTHON, "1")
    assert arith_policy.gw_routines() == {name: getattr(gw, name) for name in arith_policy.GW_ROUTINES}
    for setting in ("0", ""):
        monkeypatch.setenv(arith_policy.PURE_PYTHON, setting)
        routines = arith_policy.gw_routines()
        for name, routine in routines.items():
            assert (routine.__self__ is getattr(gw, name)) if _mbf_fast else routine is getattr(gw, name)


PROGRAM = """\
10 PRINT 4*ATN(1); TAN(1.5); ATN(-256); EXP(1.5); 2^.5; LOG(1)
20 PRINT EXP(100)
30 PRINT TAN(1.5707963#)
40 ON ERROR GOTO 70: PRINT LOG(0)
50 S=0: FOR K=1 TO 300: S=S+LOG(K)*SIN(K)+COS(K)/ATN(K)+EXP(-K/50)+K^1.5: NEXT: PRINT S
60 END
70 PRINT "ERROR"; ERR: RESUME 50
"""
"""Every routine, an overflow (EXP), a huge TAN and an error (LOG(0)) trapped.  Lines 10-40 print
what PC-BASIC 2.0.8 prints (values whose last digit its own functions get as the source
does); line 50's sum is the source's (PC-BASIC's SIN and LOG differ from it in the last
bit, so it prints another sum)."""


def run_process(program: Path, pure: str | None) -> str:
    env = dict(os.environ)
    env.pop(arith_policy.PURE_PYTHON, None)
    if pure is not None:
        env[arith_policy.PURE_PYTHON] = pure
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", "--dialect", "gw", str(program)],
                          capture_output=True, text=True, env=env, check=True)
    return done.stdout


def test_a_program_prints_the_same_with_and_without_the_accelerator(tmp_path):
    """:data:`PROGRAM` as whole processes: accelerated (when built) and with
    YASEER_PURE_PYTHON=1 the same output, whose lines before the sum are PC-BASIC's."""
    program = tmp_path / "functions.bas"
    program.write_text(PROGRAM)
    accelerated = run_process(program, None)
    assert accelerated == run_process(program, "1")
    from test_differential_support import PcBasic

    pc = PcBasic()
    try:
        theirs = pc.program(PROGRAM.replace("50 S=0", "50 END: S=0"))
    finally:
        pc.close()
    assert theirs == (" 3.141593  14.10142 -1.56689  4.481689  1.414213  0 \nOverflow\n 1.701412E+38 \n"
                      " 1.32454E+07 \nERROR 5 \n")
    lines = accelerated.splitlines(keepends=True)
    assert "".join(lines[:5]) == theirs and len(lines) == 6


def test_the_pure_python_process_uses_the_python_functions():
    """YASEER_PURE_PYTHON=1 keeps the C routines out of a process (and its start-up imports no
    _mbf_fast); without it the table holds them when built."""
    probe = ("import sys\nfrom yaseer.basic.arithmetic import arith_policy\n"
             "routines = arith_policy.gw_routines()\n"
             "print(type(routines['sin']).__name__, 'yaseer.basic.arithmetic._mbf_fast' in sys.modules)")
    env = dict(os.environ, **{arith_policy.PURE_PYTHON: "1"})
    pure = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=env, check=True)
    assert pure.stdout.split() == ["function", "False"]
    env.pop(arith_policy.PURE_PYTHON)
    default = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, env=env, check=True)
    expected = ["builtin_function_or_method", "True"] if _mbf_fast else ["function", "False"]
    assert default.stdout.split() == expected
