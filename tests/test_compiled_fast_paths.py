"""The compiler's fast paths give what the general code gives (issue 15).

Each fast path is checked against the same program with the fast path defeated:
an unreachable ``RESUME NEXT`` line makes every statement a block of its own, so
no GOSUB is compiled in place and no FOR loop is native (the general path of the
FOR stack and the GOSUB stack); or against values computed here in Python.  Each
test also checks that the fast path is really in the generated code.
"""

from __future__ import annotations

import io
import math
import random
import time

import pytest

from test_basic_cont import checked_break_points, run_with_breaks
from test_basic_helpers import error_of, run_text
from yaseer.basic.machine import runtime
from yaseer.basic.machine.machine import Machine

DEFEAT = "\n64999 END\n65000 RESUME NEXT\n"  # never reached: only makes the general code be compiled


def source_of(program: str, **options) -> str:
    """The Python the compiler makes of area 0 of ``program``."""
    machine = Machine(screen=io.StringIO(), **options)
    machine.load(program)
    machine.run()
    return machine.compiled[0].source


def same_as_general(program: str, **options) -> str:
    """The screen of ``program``, checked equal to the screen of its defeated form."""
    fast = run_text(program, **options)
    assert fast == run_text(program + DEFEAT, **options)
    return fast


# ---------------------------------------------------------------- GOSUB to a line holding RETURN

BARE_SUBROUTINES = [
    "10 K=K+1: GOSUB 100: IF K<50 THEN 10\n20 PRINT K: END\n100 RETURN",
    "10 FOR I=1 TO 30: IF I MOD 3=0 THEN GOSUB 100: C=C+1 ELSE GOSUB 100\n20 NEXT I: PRINT I;C: END\n100 RETURN",
    "10 FOR I=1 TO 20: GOSUB 100: S=S+I: NEXT: GOSUB 200: PRINT S;I;T: END\n100 RETURN\n"
    "200 T=T+1: GOSUB 100: RETURN",
    "10 GOSUB 100: PRINT 1: GOSUB 100: PRINT 2: END\n100 RETURN: PRINT 3",
]


@pytest.mark.parametrize("dialect", ["casio", "gw"])
@pytest.mark.parametrize("program", BARE_SUBROUTINES)
def test_gosub_to_a_bare_return_is_compiled_in_place(program, dialect):
    same_as_general(program, dialect=dialect)
    # only the GOSUB 200 (a subroutine that does something) pushes a return point
    assert source_of(program, dialect=dialect).count("_stk.append") == program.count("GOSUB 200")


@pytest.mark.parametrize("dialect, depth", [("casio", 96)])
def test_gosub_to_a_bare_return_still_fills_the_stack(dialect, depth):
    # line 10 recurses through GOSUB 10 until the stack is full: the next GOSUB 100
    # (compiled in place) is the one that finds it full, at line 10, with N the depth
    # (the Casio's 96 levels, GOSUB.md item 2; it was MAX_STACK's 10,000 before they were counted)
    program = "10 GOSUB 100: N=N+1: GOSUB 10\n100 RETURN"
    general = program.replace("100 RETURN", "100 REM\n110 RETURN")  # line 100 no longer a bare RETURN
    machine = Machine(screen=io.StringIO(), dialect=dialect)
    machine.load(program)
    with pytest.raises(Exception) as fast:
        machine.run()
    assert str(fast.value) == error_of(general, dialect=dialect) == "Out of memory in 10"
    assert machine.scalar("N") == depth


def test_gosub_to_a_bare_return_in_a_block_that_keeps_the_stack_measures_it_once():
    # each pass pushes one return point at line 10 (never returned) and enters line 30's
    # block, which neither pushes nor pops: it measures the stack once as it starts
    program = "10 GOSUB 30\n30 GOSUB 100: N=N+1: GOTO 10\n100 RETURN"
    general = program.replace("100 RETURN", "100 REM\n110 RETURN")
    assert "if _full: _oom()" in source_of(program.replace("GOTO 10", "END"))
    machine = Machine(screen=io.StringIO())
    machine.load(program)
    with pytest.raises(Exception) as fast:
        machine.run()
    assert str(fast.value) == error_of(general) == "Out of memory in 30"
    assert machine.scalar("N") == 96 - 1  # the 96th return point filled the Casio's GOSUB levels (GOSUB.md item 2)


def test_gosub_to_a_bare_return_measures_the_stack_each_time_where_a_next_pops_it():
    # GOSUB 300 makes the loop run through the FOR stack: its NEXT pops, then GOSUB 100
    program = ("10 FOR I=1 TO 3: GOSUB 300: GOSUB 100\n20 NEXT I: GOSUB 100: PRINT I;X: END\n"
               "100 RETURN\n300 X=X+1: RETURN")
    popping = [f for f in source_of(program).split("def ") if "_pop()" in f]
    # (the test of a full stack: the Casio counts its 96 GOSUB levels once the stack is that long)
    assert len(popping) == 1 and "if _full" not in popping[0] and "if len(_stk) >= 96 and _deep(): _oom()" in popping[0]
    assert same_as_general(program) == " 4  3 \n"


def test_gosub_to_a_bare_return_is_traced_as_the_return_line():
    # TRON shows the RETURN's line once per call, as the general code does
    program = "10 TRON: GOSUB 100: PRINT: GOSUB 100: END\n100 RETURN"
    traced = run_text(program)
    # (casio's mark, TRON.md: area and line)
    assert traced == run_text(program + DEFEAT) and traced.count("P0-100\n") == 2


def test_gosub_returns_into_a_native_loop_without_ending_it():
    program = "10 FOR I=1 TO 5: GOSUB 100: S=S+I: NEXT I: PRINT S;I: END\n100 RETURN"
    assert same_as_general(program) == " 15  6 \n"
    source = source_of(program)
    assert "n_I in (" in source and "_stk.append" not in source  # one native loop


# ---------------------------------------------------------------- empty loops (delay loops)

@pytest.mark.parametrize("start, stop, step", [
    (1, 3 * runtime.IDLE_CHUNK + 5, 1), (1, runtime.IDLE_CHUNK, 1), (2, runtime.IDLE_CHUNK + 1, 1),
    (4_000_000, -1_000_000, -3), (5, 1, 1), (0, 1000, 0.5)])
def test_an_empty_loop_counts_its_passes_in_chunks(start, stop, step):
    program = f"10 FOR I={start} TO {stop} STEP {step}: NEXT I\n20 PRINT I"
    value = float(start)  # the variable after the loop, by repeated + STEP
    if (stop - start) / step >= 0:
        passes = int((stop - start) // step) + 1
        value = start + passes * step
    machine = Machine(screen=io.StringIO())
    machine.load(program)
    machine.run()
    assert machine.scalar("I") == value
    if step == 1 and stop > 100:
        assert "_fidle(" in machine.compiled[0].source


@pytest.mark.parametrize("loop, final", [
    ("FOR L=1 TO 5", 6.0), ("FOR L=3 TO 1", 3.0), ("FOR L=5 TO 1 STEP -1.5", 0.5),
    ("FOR L=0 TO 1 STEP 0.1", None), ("FOR L=1 TO 15", 16.0)])
def test_a_short_empty_loop_is_its_final_value(loop, final):
    program = f"10 {loop}\n20 NEXT L\n30 PRINT L;L*1E15"
    if final is None:  # 0.1 added eleven times, as the loop adds it
        final = 0.0
        while final <= 1:
            final += 0.1
    assert same_as_general(program) == run_text(f"10 L={final!r}\n30 PRINT L;L*1E15")
    assert "while" not in source_of(program) and "for " not in source_of(program)


# ---------------------------------------------------------------- short loops with constant bounds

@pytest.mark.parametrize("program", [
    "10 DIM M(5): FOR K=1 TO 3: FOR L=1 TO 5: M(L)=M(L)+L*K: NEXT L: NEXT K\n20 PRINT M(1);M(5);L;K",
    "10 FOR L=0 TO 1 STEP .25: S=S+L: PRINT L;: NEXT\n20 PRINT S;L",
    "10 FOR L=5 TO 0 STEP -1: A(L)=L: S=S+A(L): NEXT: PRINT S;L",
])
def test_a_short_constant_loop_iterates_over_its_values(program):
    same_as_general(program)
    assert "n_L in (" in source_of(program)  # the tuple of values made at compile time


def test_a_short_constant_loop_indexes_arrays_with_its_whole_values():
    program = "10 DIM M(5): FOR L=1 TO 5: M(L)=L*L: NEXT L\n20 PRINT M(1);M(3);M(5);L"
    assert same_as_general(program) == " 1  9  25  6 \n"
    assert "a_M[_k" in source_of(program)


def test_an_error_in_a_short_constant_loop_names_its_line_and_keeps_the_variable():
    program = "10 DIM M(2)\n20 FOR L=1 TO 5\n30 M(L)=L\n40 NEXT L"
    assert error_of(program) == error_of(program + DEFEAT) == "Subscript out of range in 30"
    machine = Machine(screen=io.StringIO())
    machine.load("10 ON ERROR GOTO 100\n20 DIM M(2): FOR L=1 TO 5: M(L)=L: NEXT L\n30 END\n100 PRINT L;ERL: END")
    machine.run()
    assert machine.scalar("L") == 3.0


# ---------------------------------------------------------------- Ctrl-C and CONT on the fast paths

BROKEN = {
    "delay loops": "10 FOR J=1 TO 100: FOR I=1 TO 40000: NEXT I: S=S+J: NEXT J\n20 PRINT S;I;J",
    "a short constant loop": ("10 DIM M(5): FOR J=1 TO 60000: FOR L=1 TO 5: M(L)=M(L)+L*J: NEXT L: NEXT J\n"
                              "20 PRINT M(1);M(5);L;J"),
    "a GOSUB in place": "10 K=K+1: GOSUB 100: S=S+K: IF K<150000 THEN 10\n20 PRINT K;S: END\n100 RETURN",
}


@pytest.mark.parametrize("name", list(BROKEN))
def test_fast_paths_broken_and_continued_print_what_they_print_unbroken(name):
    program = BROKEN[name]
    started = time.perf_counter()
    reference, _ = run_with_breaks(program, None)
    every = max(0.002, (time.perf_counter() - started) / 6)
    output, breaks = run_with_breaks(program, every)
    assert breaks >= 1
    assert output == reference == run_text(program + DEFEAT)


def test_fast_paths_break_only_on_lines_nothing_can_interrupt_half_way():
    assert checked_break_points(BROKEN.values()) >= 4


# ---------------------------------------------------------------- RND with a constant argument

@pytest.mark.parametrize("dialect", ["casio", "gw"])
def test_rnd_with_a_constant_argument_draws_what_rnd_of_a_variable_draws(dialect):
    fast = "10 FOR I=1 TO 400: S=S+RND(1)+RND: NEXT: PRINT S;RND(1);RND(0);RND(.5)"
    general = "5 P=1\n" + fast.replace("RND(1)", "RND(P)").replace("RND:", "RND(P):").replace("RND(.5)", "RND(P/2)")
    assert run_text(fast, dialect=dialect) == run_text(general, dialect=dialect)
    assert "_rndf()" in source_of(fast, dialect=dialect) and "_rndf" not in source_of(general, dialect=dialect)


def test_rnd_zero_in_a_direct_statement_repeats_the_last_number_of_the_run():
    import random

    reference = random.Random(0)  # the casio generator: seed 0 at RUN
    expected = [reference.random() for _ in range(333)][-1]
    screen = io.StringIO()
    machine = Machine(screen=screen)
    machine.load("10 FOR I=1 TO 333: X=RND(1): NEXT")
    machine.run()
    assert machine.scalar("X") == expected
    machine.execute_direct("PRINT RND(0)=X; RND(0)-X")
    assert screen.getvalue() == "-1  0 \n"


# ---------------------------------------------------------------- SIN and COS in degrees

def test_degree_sine_and_cosine_test_for_multiples_of_90_first():
    import math

    def reference(function, exact, x):
        """The angle reduced to [0, 360), exact at 0, 90, 180 and 270, else the radian function."""
        r = math.fmod(x, 360.0)
        r = r + 360.0 if r < 0 else r
        return exact[r] if r in exact else function(math.radians(r))

    sines, cosines = {0.0: 0.0, 90.0: 1.0, 180.0: 0.0, 270.0: -1.0}, {0.0: 1.0, 90.0: 0.0, 180.0: -1.0, 270.0: 0.0}
    angles = [k * 7.5 for k in range(-200, 200)] + [33.0, 1e6 + 0.25, -1e-20, 359.999999, 45.5, -90.0, 450.0]
    for x in angles:
        assert runtime.sin_degrees(x) == reference(math.sin, sines, x), x
        assert runtime.cos_degrees(x) == reference(math.cos, cosines, x), x


# ---------------------------------------------------------------- sums that cannot overflow

def test_adding_a_bounded_function_needs_no_overflow_check():
    # RND, SIN, COS and SGN are at most 1 in size: added to a finite double, no infinity
    assert "_ovf" not in source_of("10 R=R+RND(1)-SIN(R)+COS(30)+SGN(R)")
    assert "_ovf" in source_of("10 R=R+X")  # two variables may overflow
    program = "10 R=1.79E308: R=R+RND(1)+SIN(30)+COS(60)+SGN(R): PRINT R=1.79E308; R-1.79E308"
    assert run_text(program) == "-1  0 \n"  # the largest doubles absorb the small terms


# ---------------------------------------------------------------- gw singles

def gw_machine(program: str) -> Machine:
    machine = Machine(screen=io.StringIO(), dialect="gw")
    machine.load(program)
    machine.run()
    return machine


WHOLE_LOOPS = ["1 TO 300", "4000 TO 4300", "-5000 TO 5000 STEP 37", "16770000 TO 16777200 STEP 25",
               "1E12 TO 3E12 STEP 7E9", "1.2E19 TO 1.4E19 STEP 1E17"]


@pytest.mark.parametrize("loop", WHOLE_LOOPS)
def test_the_square_of_a_whole_loop_variable_is_the_products(loop):
    """``I^2`` of a FOR variable with a whole start and step: a whole square up to 2**24 is
    exact, a larger one is rounded inline as ``$FMULS`` rounds (single_arith.product), one
    beyond the range overflows through the policy; as the general code gives it."""
    from yaseer.basic.arithmetic import single_arith as sa
    from yaseer.basic.arithmetic.values import SINGLE_LARGEST

    program = f"10 DIM R(400), V(400)\n20 FOR I={loop}: R(K)=I^2: V(K)=I: K=K+1: NEXT\n"
    fast = gw_machine(program)
    assert "<= 16777216.0" in fast.compiled[0].source
    general = gw_machine(program + DEFEAT)
    assert "<= 16777216.0" not in general.compiled[0].source
    count = int(fast.scalar("K!"))
    squares, values = fast.array("R!")[:count], fast.array("V!")[:count]
    assert squares == general.array("R!")[:count]
    assert squares == [min(sa.power_by_integer(v, 2), SINGLE_LARGEST) for v in values]
    assert count > 20


@pytest.mark.parametrize("loop", ["I=.5 TO 10", "I=1 TO 10 STEP .5", "I=1 TO 10: I=I+.5"])
def test_a_loop_variable_that_may_not_be_whole_has_no_whole_square(loop):
    assert "<= 16777216.0" not in gw_machine(f"10 FOR {loop}: A=I^2: NEXT\n").compiled[0].source


def test_sums_and_quotients_with_a_literal_are_the_helpers():
    """A literal operand's sign is known when compiling (the inline sum tests the other
    operand's alone), a quotient is the cut of its double, and a product or quotient by a
    literal of at least 1 in size tests one end of the range only (the other cannot be
    reached): against single_arith, overflows and underflows among them."""
    from yaseer.basic.arithmetic import single_arith as sa
    from yaseer.basic.arithmetic.values import SINGLE_LARGEST

    rng = random.Random(12)
    constants = [".1", "2.5", "1000000!", "3E+20", "1E-30", "0", "7", "8388607", "9E+29", "-1.5", "-.25", "1"]
    forms = {"A!+{c}": lambda a, c: sa.add(a, c), "A!-{c}": lambda a, c: sa.subtract(a, c),
             "{c}+A!": lambda a, c: sa.add(c, a), "{c}-A!": lambda a, c: sa.subtract(c, a),
             "A!/{c}": lambda a, c: sa.divide(a, c) if c else None, "{c}/A!": lambda a, c: sa.divide(c, a),
             "A!*{c}": lambda a, c: sa.multiply(a, c), "{c}*A!": lambda a, c: sa.multiply(c, a)}
    lines, cases = [], []
    for k in range(300):
        a = sa.nearest(rng.choice([1, -1]) * rng.uniform(0.5, 1) * 2.0 ** rng.randint(-40, 40))
        a = rng.choice([a, a, float(rng.randint(-99, 99)), sa.nearest(rng.choice([0.1, -0.1, 2.5, -2.5])),
                        sa.nearest(rng.choice([1e30, -3e37, 1e-38, -4e-39, 0.0]))])
        c = constants[k % len(constants)]
        results = ": ".join(f"R{k}X{n}!={form.format(c=c)}" for n, form in enumerate(forms) if c != "0" or "/{c}" not in form)
        lines.append(f"{10 + k} A{k}!={a!r}: C{k}!={c}: {results.replace('A!', f'A{k}!')}")
        cases.append(k)
    checked = 0
    for start in range(0, len(lines), 100):  # (300 lines and their 3000 variables do not fit in GW's 64 KB)
        machine = gw_machine("\n".join(lines[start:start + 100]) + "\n")
        source = machine.compiled[0].source
        # the quotient's cut (the general code, after its binade cache: binade_cache.py)
        assert "_sadd(" in source and "_dv(" in source and "<= (_sh := (_sc := _sv * " in source and "_zwq(" in source
        for line, k in zip(lines[start:start + 100], cases[start:start + 100]):
            a, c = machine.scalars[f"A{k}!"], machine.scalars[f"C{k}!"]  # as the literals were read
            for n, helper in enumerate(forms.values()):
                name = f"R{k}X{n}!"
                if name in machine.scalars:
                    try:
                        expected = helper(a, c)
                    except ZeroDivisionError:  # (the policy's Division by zero)
                        continue
                    if expected in (math.inf, -math.inf):  # the policy's value (arith_policy.py)
                        expected = math.copysign(SINGLE_LARGEST, expected)
                    assert machine.scalars[name] == expected, (line, list(forms)[n])
                    checked += 1
    assert checked > 1500


def test_square_root_of_zero_is_zero():
    machine = gw_machine("10 Z=0: A=SQR(Z): B=SQR(0): C=SQR(-Z)\n")
    assert [str(machine.scalar(n + "!")) for n in "ABC"] == ["0.0"] * 3  # (not -0.0)


@pytest.mark.parametrize("loop", ["1E12 TO 3E12 STEP 7E9", "16777000 TO 16777214 STEP 3",
                                  "3E9 TO 1E9 STEP -123457", "-10 TO 16777215 STEP 4194304"])
@pytest.mark.parametrize("body", ["K=K+1", "S=S+I: K=K+1"])
def test_a_single_loop_past_two_to_the_24_rounds_each_step(loop, body):
    """A native loop over whole singles iterates a ``range`` only below 2**24 (where each
    ``+ STEP`` is exact); past it each step rounds as ``$FADDS``, as the general code does."""
    fast = gw_machine(f"10 FOR I={loop}: {body}: NEXT\n")
    general = gw_machine(f"10 FOR I={loop}: {body}: NEXT\n" + DEFEAT)
    assert fast.scalars == general.scalars
    assert fast.scalars["K!"] >= 5


@pytest.mark.parametrize("body", ["K=K+1: IF K=6 THEN END", "S=S+I: K=K+1: IF K=6 THEN END",
                                  "K=K+1: IF K=6 THEN END ELSE I=I+0"])
def test_a_single_loop_down_from_two_to_the_25_stays_there(body):
    """``FOR I=33554432 TO 33554426 STEP -1`` never ends in GW: ``$FADDS`` gives 2**25 back
    for 2**25 - 1 (exponents 25 apart: the larger operand as it is; the tests' transcription
    of its registers, tests/fadds_reference.py), so each pass sees 33554432, whether the
    native loop counts its passes, iterates the values or steps a variable the body
    changes, as the general code does.  (2**24 - 1 is 16777215: exponents 24 apart keep
    the 1 in the guard byte, where PC-BASIC 2.0.8 loses it.)"""
    from fadds_reference import add

    assert add(33554432.0, -1.0) == 33554432.0 and add(16777216.0, -1.0) == 16777215.0
    fast = gw_machine(f"10 FOR I=33554432 TO 33554426 STEP -1: {body}\n20 NEXT\n")
    general = gw_machine(f"10 FOR I=33554432 TO 33554426 STEP -1: {body}\n20 NEXT\n" + DEFEAT)
    assert fast.scalars == general.scalars
    assert fast.scalars["I!"] == 33554432.0 and fast.scalars["K!"] == 6.0
    if "S=S+I" in body:
        assert fast.scalars["S!"] == add(add(add(add(add(33554432.0, 33554432.0), 33554432.0), 33554432.0),
                                             33554432.0), 33554432.0)
    assert "while" in source_of(f"10 FOR I=33554432 TO 33554426 STEP -1: {body}\n20 NEXT\n", dialect="gw")
    # the helpers of the loops whose body cannot end them (iterating values, counting passes)
    helpers = runtime.single_loop_helpers()
    values = helpers["_frange"](33554432.0, 33554426.0, -1.0)
    assert [next(values) for _ in range(8)] == [33554432.0] * 8
    passes = helpers["_fcount"](33554432.0, 33554426.0, -1.0)
    assert [n for n, _ in zip(passes, range(8))] == list(range(8)) and passes.value == 33554432.0


def test_gw_transcendental_functions_are_their_steps_without_a_rounding_test():
    """SIN COS TAN ATN LOG EXP give a single already (gw_transcendental's steps): the compiled
    code uses their value as it is, without the nearest-single test SQR's value gets; the
    values are those of the functions, with an overflow through the policy, as the helpers
    alone (the general code, tests_inline off) give them."""
    from yaseer.basic.arithmetic import gw_transcendental as gw
    from yaseer.basic.arithmetic.values import SINGLE_LARGEST
    from yaseer.basic.compile import number_models

    rng = random.Random(22)
    arguments = [0.0, -0.0, 1e-30, -3.0, 0.5, 1.0, 88.0, 89.0, -89.0, 1e6, 1e30, -1e30] + [
        float(str(rng.choice([-1, 1]) * rng.uniform(0.5, 1) * 2.0 ** rng.randint(-20, 25))[:9]) for _ in range(60)]
    functions = {"SIN": gw.sin, "COS": gw.cos, "TAN": gw.tan, "ATN": gw.atn, "EXP": gw.exp,
                 "LOG": lambda x: gw.log(abs(x)) if x else 0.0}
    lines = [f"{10 + k} X{k}!={a!r}: " + ": ".join(
        f"{name}{k}={name}({f'ABS(X{k}!)' if name == 'LOG' else f'X{k}!'})" if name != "LOG" or a else f"{name}{k}=0"
        for name in functions) for k, a in enumerate(arguments)]
    program = "\n".join(lines) + "\n"
    fast = gw_machine(program)
    assert "_sin(" in fast.compiled[0].source and "(_sv := _sin(" not in fast.compiled[0].source
    original = number_models.TypedNumbers.__init__

    def helpers_only(self, def_types=None):
        original(self, def_types)
        self.tests_inline = False

    general = pytest.MonkeyPatch()
    general.setattr(number_models.TypedNumbers, "__init__", helpers_only)
    try:
        slow = gw_machine(program + "9999 REM (another text: not the compiled cache's entry)\n")
    finally:
        general.undo()
    assert "_sfn(_sin(" in slow.compiled[0].source
    checked = 0
    for k in range(len(arguments)):
        a = fast.scalars[f"X{k}!"]  # the literal as read and stored in a single
        for name, function in functions.items():
            value = fast.scalars[f"{name}{k}!"]
            assert value == slow.scalars[f"{name}{k}!"], (name, a)
            try:
                expected = function(a)
            except ZeroDivisionError:
                continue
            if expected in (math.inf, -math.inf):
                expected = math.copysign(SINGLE_LARGEST, expected)
            assert value == expected, (name, a)
            checked += 1
    assert checked > 400


@pytest.mark.parametrize("form", ["A!+B!", "A!-B!", "B!+A!", "B!-A!", "A!+{c}", "A!-{c}", "{c}+A!", "{c}-A!"])
def test_a_power_of_two_and_half_its_unit_of_the_other_sign_is_the_power(form):
    """The inline exact sum is not taken where ``$FADDS`` leaves a power of two unchanged (the
    other operand half its unit, of the other sign: ``16777216 - 1`` is 16777216 in GW-BASIC
    and PC-BASIC); single_arith.add (the helper) gives it, as for every other pair."""
    from yaseer.basic.arithmetic import single_arith as sa

    lines, cases = [], []
    for k, (power, other) in enumerate([(16777216.0, 1.0), (1.0, 2.0 ** -24), (-4.0, 2.0 ** -22), (2.0, 1.0),
                                        (16777216.0, 2.0), (8.0, 2.0 ** -21), (0.5, 0.25)]):
        for a, b in ((power, other), (power, -other), (-power, other), (other, power), (-other, -power)):
            code = form.format(c=format(b, ".30f").rstrip("0") + "!")  # (the exact decimal, a single)
            lines.append(f"{10 + len(cases)} A!={a!r}: B!={b!r}: R{len(cases)}!={code}")
            cases.append((a, b, form))
    machine = gw_machine("\n".join(lines) + "\n")
    for n, (a, b, form) in enumerate(cases):
        operands = {"A!": a, "B!": b}
        plus = "+" in form
        left, right = form.replace("{c}", "B!").split("+" if plus else "-")
        x, y = operands[left], operands[right]
        expected = sa.add(x, y) if plus else sa.subtract(x, y)
        assert machine.scalars[f"R{n}!"] == expected, (form, a, b)
    assert 16777216.0 in [abs(machine.scalars[f"R{n}!"]) for n in range(len(cases))]  # (16777216 - 1)


def test_a_single_statement_needs_no_overflow_test_of_its_own():
    """Every single operation keeps its value in the range or gives the policy's (its inline
    path or its checked helper), so a LET of a single has no statement-level test; an
    overflow is still reported where it happens and the statement goes on with the largest
    single (a DEF FN's value keeps the test)."""
    assert "_ovf" not in gw_machine("10 A=B*C+D/E-F\n").compiled[0].source
    assert "_ovf" in gw_machine("10 DEF FNA(X)=X*X\n20 A=FNA(B)*C\n").compiled[0].source
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect="gw")
    machine.load("10 B=1E+38: C=10: A=B*C/100: PRINT A\n20 D=-B*C: PRINT D\n")
    machine.run()
    assert screen.getvalue() == "Overflow\n 1.701412E+36 \nOverflow\n-1.701412E+38 \n"


@pytest.mark.parametrize("program", ["10 A=0: B=0: C=A+B: D=A-B: E=A*-1.5: F=-A*2: G=(-A)+(-B): PRINT C;D;E;F;G\n",
                                     "10 FOR X!=0 TO 1 STEP .5: S=S+X!: T=T-X!: NEXT: PRINT S;T\n"])
def test_zero_sums_and_products_are_zero(program):
    """Sums and products that are 0 (also of -0 operands) take the helpers: 0, never -0 or a
    division of 0 by 0 in the inline tests."""
    screen = io.StringIO()
    machine = Machine(screen=screen, dialect="gw")
    machine.load(program)
    machine.run()
    assert "-0" not in screen.getvalue() and "Division" not in screen.getvalue()
    assert all(str(v) != "-0.0" for v in machine.scalars.values())
