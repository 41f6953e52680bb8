"""Semantics of the BASIC machine, checked against values computed independently in Python."""

import io
import math

import pytest

from alarm_support import stop_alarm
from test_basic_helpers import error_of, run_rows, run_text, run_values
from yaseer.basic.errors import BasicError, ILLEGAL_FUNCTION_CALL
from yaseer.basic.machine.machine import Machine


def values(program, **options):
    return [row for row in run_values(program, **options)]


# ---------------------------------------------------------------- arithmetic


def test_arithmetic_and_precedence():
    rows = values("10 PRINT -2^2, 2^3^2, 2+3*4, 7/2, (1+2)*3, 2^-1, 7 MOD 3, -7 MOD 3, 7\\2, -7\\2")
    assert rows == [[-4.0, 64.0, 14.0, 3.5, 9.0, 0.5, 1.0, -1.0, 3.0, -3.0]]


def test_relations_give_minus_one_and_zero():
    assert values('10 PRINT 1<2, 1>2, 2=2, 2<>2, 1<=1, 3>=4, "A"<"B"') == [[-1.0, 0.0, -1.0, 0.0, -1.0, 0.0, -1.0]]


def test_logical_operators_are_bitwise_on_integers():
    assert values("10 PRINT 5 AND 3, 5 OR 3, NOT 0, NOT -1, (1<2) AND (2<3)") == [[1.0, 7.0, -1.0, 0.0, -1.0]]


def test_degree_trig_by_default():
    rows = values("10 PRINT SIN 30, COS 60, TAN 45, ATN 1, COS 90, SIN 180, COS(-90.1)")
    expected = [math.sin(math.radians(30)), math.cos(math.radians(60)), math.tan(math.radians(45)),
                45.0, 0.0, 0.0, math.cos(math.radians(269.9))]
    assert rows[0] == pytest.approx(expected, rel=1e-15, abs=1e-15)
    assert rows[0][4] == 0.0  # exactly, as the pocket computer shows it


def test_rad_statement_and_angle_option():
    assert values("10 RAD: PRINT SIN 1, ATN 1: DEG: PRINT ATN 1") == [[math.sin(1), math.atan(1)], [45.0]]
    assert values("10 PRINT COS 1", angle="rad") == [[math.cos(1)]]


def test_functions():
    rows = values("10 PRINT SQR 16, ABS(-3), INT(-2.5), FIX(-2.5), SGN(-4), SGN 0, EXP 1, LN 10, LEN \"ABC\"")
    assert rows == [[4.0, 3.0, -3.0, -2.0, -1.0, 0.0, math.e, math.log(10), 3.0]]  # LN: casio's natural log


def test_function_of_a_function_without_parentheses():
    assert values("10 T=60: PRINT SQR ABS(-16), COST*2") == [[4.0, 2 * math.cos(math.radians(60))]]


def test_string_functions():
    rows = run_rows('10 A$="HELLO": PRINT LEFT$(A$,2); RIGHT$(A$,3); MID$(A$,2,3); MID$(A$,4); '
                    'CHR$(65); ASC("a"); VAL(" 12.5xyz"); STR$(-3); A$+"!"; LEN(A$)')
    assert rows == [["HE", "LLO", "ELL", "LO", "A", "97.0", "12.5", "-3", "HELLO!", "5.0"]]


def test_scalars_and_arrays_are_separate():
    assert values("10 L=5: L(2)=7: PRINT L, L(2)") == [[5.0, 7.0]]


# ---------------------------------------------------------------- FOR / NEXT


def test_for_array_element_control_variable_ends_one_step_past():
    rows = values("10 FOR T(2) = .1 TO 360.1 STEP 20: PRINT T(2): NEXT T(2): PRINT T(2)")
    expected, x = [], 0.1
    while x <= 360.1:
        expected.append(x)
        x += 20
    assert [r[0] for r in rows[:-1]] == expected
    assert rows[-1] == [x]


def test_negative_step_and_no_name_next():
    rows = values("10 FOR QQ = 360.1 TO .1 STEP -20: PRINT QQ: NEXT: PRINT QQ")
    expected, x = [], 360.1
    while x >= 0.1:
        expected.append(x)
        x -= 20
    assert [r[0] for r in rows] == expected + [x]


def test_loop_test_comes_before_the_first_pass():
    # a loop that never runs leaves its variable at the start value: GW-BASIC's source
    # (FOR hands over to NEXTS in NEXT86.ASM with NXTFLG = 0, which stores the start
    # value before the exit test); PC-BASIC 2.0.8 gives start + STEP (6, 4.5)
    assert values("10 FOR I=5 TO 1: PRINT I: NEXT I: PRINT I") == [[5.0]]
    assert values("10 FOR J=3 TO -.5 STEP 1.5: PRINT J: NEXT: PRINT J") == [[3.0]]
    # the same through the FOR stack (a GOSUB in the body)
    assert values("10 FOR I=5 TO 1: GOSUB 50: NEXT I\n20 PRINT I: END\n50 PRINT 99: RETURN") == [[5.0]]


def test_next_j_i_closes_two_loops():
    rows = values("10 FOR I=1 TO 2: FOR J=1 TO 3: S=S+I*J: NEXT J, I: PRINT S, I, J")
    assert rows == [[sum(i * j for i in (1, 2) for j in (1, 2, 3)), 3.0, 4.0]]


def test_dynamic_loop_over_several_lines_with_gosub():
    program = "10 FOR K=1 TO 3\n20 GOSUB 100\n30 NEXT K\n40 PRINT S: END\n100 S=S+K*K: RETURN\n"
    assert values(program) == [[14.0]]


def test_jump_back_loop():
    assert values("10 K=0\n20 K=K+1: IF K<1000 THEN 20\n30 PRINT K") == [[1000.0]]


def test_gosub_inside_if_branch_returns_into_the_branch():
    program = '10 IF 1 THEN GOSUB 100: PRINT "then" ELSE PRINT "else"\n20 PRINT "next": END\n100 PRINT "sub": RETURN'
    assert run_rows(program) == [["sub"], ["then"], ["next"]]


# ---------------------------------------------------------------- jumps


def test_on_goto_and_on_gosub():
    program = ("10 FOR I=0 TO 3: ON I GOSUB 100, 200: NEXT: ON 2 GOTO 30, 40\n"
               "30 PRINT 30: END\n40 PRINT 40: END\n100 PRINT 100: RETURN\n200 PRINT 200: RETURN\n")
    assert values(program) == [[100.0], [200.0], [40.0]]


def test_if_then_else_and_nested_if_in_else():
    program = ('10 FOR X=1 TO 3: IF X=1 THEN PRINT "one" ELSE IF X=2 THEN PRINT "two" ELSE PRINT "many"\n'
               '20 NEXT X')
    assert run_rows(program) == [["one"], ["two"], ["many"]]


def test_then_line_and_else_line():
    program = "10 A=2: IF A>1 THEN 30 ELSE 40\n30 PRINT 30: END\n40 PRINT 40"
    assert values(program) == [[30.0]]
    assert values(program.replace("A=2", "A=0")) == [[40.0]]


def test_nested_gosub():
    program = "10 GOSUB 100: PRINT 3: END\n100 GOSUB 200: PRINT 2: RETURN\n200 PRINT 1: RETURN"
    assert values(program) == [[1.0], [2.0], [3.0]]


# ---------------------------------------------------------------- arrays


def test_al_yaseer_implicit_dimensions():
    assert values("10 F(46)=1: A(53)=2: P(4)=3: QZ(10)=4: PRINT F(46)+A(53)+P(4)+QZ(10)") == [[10.0]]
    assert error_of("10 Z(6)=1") == "Subscript out of range in 10"
    assert error_of("10 B(11)=1") == "Subscript out of range in 10"


def test_own_dim_replaces_an_implicit_dimension():
    assert values("10 DIM M(5): M(5)=1: PRINT M(5)") == [[1.0]]
    assert error_of("10 DIM M(5): M(6)=1") == "Subscript out of range in 10"
    assert values("10 DIM F(100): F(100)=3: PRINT F(100)") == [[3.0]]


def test_paper_universal_line_runs():
    program = ("2 CLEAR: DIM F(46), M(11), R(19), H(24), A(53), L(20), T(25), W(10),\n"
               "Z(5), C(14), U(4), D(6), E(6), X(11), Y(11), V(21), Q(4), N(3), I(11), P(4)\n"
               "10 L(20)=1: PRINT L(20)")
    assert values(program) == [[1.0]]


def test_multidimensional_arrays():
    assert values("10 DIM B(2,3): B(2,3)=5: B(1,0)=2: PRINT B(2,3)*B(1,0)") == [[10.0]]
    assert error_of("10 DIM B(2,3): B(3,1)=1") == "Subscript out of range in 10"


def test_second_dim_is_a_duplicate_definition():
    assert error_of("10 DIM M(5): DIM M(6)") == "Duplicate Definition in 10"


def test_subscripts_drop_their_fraction_on_the_casio():
    # part 6, Arrays: "Fractions are disregarded" (GW-BASIC rounds: test_gw_language)
    assert values("10 L(2)=7: L(1)=3: PRINT L(1.6), L(2.4), L(2.99)") == [[3.0, 7.0, 7.0]]
    assert values("10 DIM Q(2.9): Q(2)=4: PRINT Q(2.5)") == [[4.0]]  # DIM.md: the size truncated
    assert error_of("10 PRINT L(-1)") == "Subscript out of range in 10"


# ---------------------------------------------------------------- data, input, functions


def test_data_read_restore():
    program = '10 READ A, B$, C: PRINT A; B$; C: RESTORE 40: READ D: PRINT D\n30 DATA 1, "x, y"\n40 DATA 3'
    assert run_rows(program) == [["1.0", "x, y", "3.0"], ["3.0"]]


def test_input_from_a_stream():
    machine = Machine(screen=io.StringIO(), output_format="csv", input_stream=io.StringIO("3\nabc\n"))  # one answer a variable (INPUT.md)
    machine.load('10 INPUT "N"; N, A$: PRINT N*2, A$')
    machine.run()
    assert machine.screen.stream.getvalue().splitlines()[-1] == "6.0,abc"


def test_input_redo_on_bad_number():
    machine = Machine(screen=io.StringIO(), input_stream=io.StringIO("1+\n4\n"))  # (x: a variable, INPUT.md item 9)
    machine.load("10 INPUT N: PRINT N")
    machine.run()
    assert "?Redo from start" in machine.screen.stream.getvalue()
    assert machine.scalar("N") == 4.0


def test_def_fn():
    assert values("10 DEF FNA(X)=X*X+B: B=1: PRINT FNA(3), FNA(FNA(1))") == [[10.0, 5.0]]


def test_undefined_user_function():
    assert error_of("10 PRINT FNZ(1)") == "Undefined user function in 10"


def test_rnd_is_in_unit_interval_and_rnd0_repeats():
    rows = values("10 FOR I=1 TO 50: X=RND(1): IF X<0 OR X>=1 THEN PRINT 999\n20 NEXT: Y=RND(1): PRINT Y=RND(0)")
    assert rows == [[-1.0]]


def test_randomize_reseeds_the_same_sequence():
    rows = values("10 RANDOMIZE 7: A=RND(1): RANDOMIZE 7: PRINT A=RND(1)")
    assert rows == [[-1.0]]


# ---------------------------------------------------------------- printing


def test_print_zones_semicolons_tab_spc():
    out = run_text('10 PRINT "A","B";"C": PRINT TAB(5);"X";SPC(2);"Y": PRINT "P";\n20 PRINT "Q"', dialect="gw")
    assert out == "A" + " " * 13 + "BC\n" + "    X  Y\nPQ\n"
    # casio: TAB counts from column 0 (TAB.md), so TAB(5) leaves five blanks
    out = run_text('10 PRINT "A","B";"C": PRINT TAB(5);"X";SPC(2);"Y": PRINT "P";\n20 PRINT "Q"')
    assert out == "A" + " " * 13 + "BC\n" + "     X  Y\nPQ\n"


# PC-BASIC 2.0.8 prints these (gw; casio's TAB counts from 0, TAB.md):
#   10 PRINT "A";TAB(0);"B"  ->  A / B            (TAB below 1 is column 1, here on a new line)
#   PRINT "XYZ";CHR$(13);"Q";TAB(3);"R"  ->  XYZ / Q R   (CR ends the line, the column is 0)
#   PRINT "AB";TAB(10) then PRINT "C"  ->  "AB       C"  (TAB or SPC at the end keeps the line open)


def test_tab_below_one_is_column_one():
    assert run_text('10 PRINT "A";TAB(0);"B": PRINT TAB(-7);"C": PRINT "D";TAB(-1);"E"', dialect="gw") == \
        "A\nB\nC\nD\nE\n"


def test_carriage_return_ends_the_line():
    assert run_text('10 PRINT "XYZ";CHR$(13);"Q";TAB(3);"R"', dialect="gw") == "XYZ\nQ R\n"
    assert run_text('10 PRINT "XYZ";CHR$(13);"Q";TAB(3);"R"') == "XYZ\nQ  R\n"  # casio: column 3 from 0


def test_print_ending_in_tab_or_spc_keeps_the_line_open():
    assert run_text('10 PRINT "AB";TAB(10)\n20 PRINT "C": PRINT "AB";SPC(3)\n30 PRINT "E"', dialect="gw") == \
        "AB       C\nAB   E\n"
    assert run_text('10 PRINT "AB";TAB(10)\n20 PRINT "C"') == "AB        C\n"  # casio: column 10 from 0


def test_empty_input_answer_is_zero_or_empty_string():
    machine = Machine(screen=io.StringIO(), input_stream=io.StringIO("\n\n"))
    machine.load('10 INPUT N: INPUT A$: PRINT N; "[" A$ "]"')
    machine.run()
    assert machine.screen.stream.getvalue().splitlines() == ["? ", "? ", " 0 []"]


def test_input_of_two_variables_asks_for_each_and_exe_alone_keeps_a_value():
    # INPUT.md: EXE after each answer (items 3, 4); EXE alone keeps a numeric value (item 7)
    machine = Machine(screen=io.StringIO(), input_stream=io.StringIO("\n3\n"))
    machine.load("10 C=5: INPUT C, D: PRINT C; D")
    machine.run()
    assert machine.screen.stream.getvalue().splitlines() == ["? ", "? 3", " 5  3 "]


def test_lprint_goes_to_the_printer_stream():
    screen, printer = io.StringIO(), io.StringIO()
    machine = Machine(screen=screen, printer=printer)
    machine.load('10 PRINT "S": LPRINT "P"')
    machine.run()
    assert (screen.getvalue(), printer.getvalue()) == ("S\n", "P\n")


def test_csv_rows_have_full_precision():
    assert run_rows("10 PRINT 1/3; 2: PRINT USING \"##.#\"; 2/3") == [[repr(1 / 3), "2.0"], [repr(2 / 3)]]


# ---------------------------------------------------------------- error trapping


def test_on_error_resume_next_err_erl():
    program = "10 ON ERROR GOTO 100\n20 A=1/0: PRINT 2\n30 PRINT ERR, ERL: END\n100 PRINT 1: RESUME NEXT"
    assert values(program) == [[1.0], [2.0], [0.0, 20.0]]  # RESUME clears ERR, keeps ERL


def test_resume_line_and_resume_retry():
    program = ("10 ON ERROR GOTO 100\n20 B=0\n30 A=1/B: PRINT A: END\n"
               "100 IF B=0 THEN B=4: RESUME\n110 RESUME 30")
    assert values(program) == [[0.25]]


def test_error_inside_handler_is_not_trapped():
    assert error_of("10 ON ERROR GOTO 100\n20 A=1/0\n100 B=SQR(-1)") == "Illegal function call in 100"


def test_on_error_goto_zero_switches_trapping_off():
    assert error_of("10 ON ERROR GOTO 100: ON ERROR GOTO 0\n20 A=1/0\n100 END") == "Division by zero in 20"


# ---------------------------------------------------------------- program areas


def test_python_area_reads_and_writes_shared_state():
    def area(machine):
        machine.array("X")[2] = machine.array("L")[1] * 2
        machine.set_scalar("T", machine.scalar("QQ") + 1)

    machine = Machine(screen=io.StringIO(), output_format="csv")
    machine.load("10 FOR QQ=1 TO 2: L(1)=QQ*10: GOSUB PROG 1: PRINT X(2), T: NEXT")
    machine.set_area(1, area)
    machine.run()
    assert machine.screen.stream.getvalue().split() == ["20.0,2.0", "40.0,3.0"]


def test_a_python_area_that_replaces_an_array_is_seen_after_it_unless_it_says_it_keeps_them():
    # A Python area may ERASE and make an array anew (as a BASIC area's DIM may): the calling
    # block looks its arrays up again after the call.  One marked ``keeps_arrays`` (the library
    # programs: elements only) is taken at its word, and the block keeps the arrays it holds.
    def area(machine):
        machine.arrays["X"] = [7.0] * 11

    for keeps, shown in ((False, ["7.0"]), (True, ["1.0"])):
        area.keeps_arrays = keeps
        machine = Machine(screen=io.StringIO(), output_format="csv")
        machine.load("10 X(2)=1: GOSUB PROG 1: PRINT X(2)")
        machine.set_area(1, area)
        machine.run()
        assert machine.screen.stream.getvalue().split() == shown


def test_the_library_programs_keep_the_arrays_they_are_given():
    from yaseer import binding

    machine = Machine(screen=io.StringIO(), output_format="csv")
    binding.install(machine)
    assert all(machine.python_areas[number].keeps_arrays for number in (1, 2, 3, 5))
    # what they make is made where the block did not hold it: X(4), the coupler point at A, is seen
    machine.load("10 L(11)=1.2: L(12)=0.3: L(13)=1: L(14)=0.8: GOSUB PROG 2: PRINT X(4) > 0")
    machine.run()
    assert machine.screen.stream.getvalue().split() == ["-1.0"]


def test_python_area_error_gets_the_calling_line():
    def area(machine):
        raise BasicError("Mechanism cannot be assembled (PROG 2)", ILLEGAL_FUNCTION_CALL)

    message = error_of("4030 A=1\n4040 GOSUB PROG 2", setup=lambda m: m.set_area(2, area))
    assert message == "Mechanism cannot be assembled (PROG 2) in 4040"


def test_python_area_error_can_be_trapped():
    def area(machine):
        raise BasicError("Mechanism cannot be assembled (PROG 2)", ILLEGAL_FUNCTION_CALL)

    machine = Machine(screen=io.StringIO(), output_format="csv")
    machine.load("10 ON ERROR GOTO 100\n20 GOSUB PROG 2: PRINT 1\n30 PRINT 2: END\n100 PRINT ERR, ERL: RESUME NEXT")
    machine.set_area(2, area)
    machine.run()
    # ERR is the Casio manual's code: 14, the MA error (part-12-2-error-messages.md)
    assert machine.screen.stream.getvalue().split() == ["14.0,20.0", "1.0", "2.0"]


def test_basic_area_shares_variables_and_returns():
    machine = Machine(screen=io.StringIO(), output_format="csv")
    machine.load("10 X(10)=3: GOSUB PROG 5: PRINT T, L\n20 END")
    machine.set_area(5, "1 REM area\n10 T=X(10)*2\n20 L=T+1: RETURN\n")
    machine.run()
    assert machine.screen.stream.getvalue().split() == ["6.0,7.0"]


def test_error_in_basic_area_names_the_area():
    message = error_of("10 GOSUB PROG 5", setup=lambda m: m.set_area(5, "10 X=0\n20 Y=1/X: RETURN"))
    assert message == "Division by zero in 20 (PROG 5)"


def test_unbound_area():
    assert error_of("10 A=1\n20 GOSUB PROG 5") == "Undefined program area 5 in 20"


def test_keyboard_interrupt_is_break_in_line():
    def area(machine):
        raise KeyboardInterrupt

    assert error_of("10 A=1\n20 GOSUB PROG 1", setup=lambda m: m.set_area(1, area)) == "Break in 20"


# ---------------------------------------------------------------- interactive API


def test_stop_and_cont():
    machine = Machine(screen=io.StringIO(), output_format="csv")
    machine.load("10 A=1: STOP: A=A+1: PRINT A\n20 PRINT 9")
    assert machine.run() == "stop"
    assert machine.scalar("A") == 1.0 and machine.line == 10
    machine.execute_direct("A=10")
    assert machine.cont() == "end"
    assert machine.screen.stream.getvalue().split() == ["11.0", "9.0"]


def test_cont_without_stop():
    machine = Machine(screen=io.StringIO())
    with pytest.raises(BasicError, match="Can't continue"):
        machine.cont()


def test_direct_mode_shares_variables_and_goto_runs_the_program():
    machine = Machine(screen=io.StringIO(), output_format="csv")
    machine.load("10 PRINT 1\n20 PRINT B*2")
    machine.execute_direct("B=21: PRINT B")
    machine.execute_direct("GOTO 20")
    assert machine.screen.stream.getvalue().split() == ["21.0", "42.0"]


def test_direct_mode_error_has_no_line():
    machine = Machine(screen=io.StringIO())
    with pytest.raises(BasicError) as info:
        machine.execute_direct("A=1/0")
    assert str(info.value) == "Division by zero"


# ---------------------------------------------------------------- the loop forms the compiler picks


def accumulate(start, limit, step):
    values, x = [], start
    while (x <= limit) if step >= 0 else (x >= limit):
        values.append(x)
        x += step
    return values, x


def test_body_that_changes_the_variable_steers_the_loop():
    rows = values("10 FOR I=1 TO 100: I=I*2: PRINT I: NEXT: PRINT I")
    expected, i = [], 1.0
    while i <= 100:
        i *= 2
        expected.append([i])
        i += 1
    assert rows == expected + [[i]]


def test_long_loop_reading_its_variable_with_variable_bounds():
    rows = values("10 N=1000: FOR J=3 TO N STEP 7: S=S+J: NEXT: PRINT S, J")
    seen, final = accumulate(3.0, 1000.0, 7.0)
    assert rows == [[sum(seen), final]]


def test_long_fractional_loop_not_reading_its_variable():
    rows = values("10 FOR I=.1 TO 99.7 STEP .3: K=K+1: NEXT: PRINT I, K")
    seen, final = accumulate(0.1, 99.7, 0.3)
    assert rows == [[final, float(len(seen))]]


def test_error_inside_a_counted_loop_sees_the_current_variable():
    program = "10 ON ERROR GOTO 100\n20 FOR I=1 TO 100: K=K+1: A=1/(50-K): NEXT\n30 END\n100 PRINT I, K: END"
    assert values(program) == [[50.0, 50.0]]


def test_loop_helpers_match_repeated_addition():
    import random

    from yaseer.basic.machine import runtime
    rng = random.Random(1)
    for _ in range(3000):
        start = rng.choice([rng.randint(-50, 50), rng.uniform(-50, 50), round(rng.uniform(-50, 50), 1)])
        step = rng.choice([rng.randint(-7, 7), rng.uniform(-7, 7), 0.1, -0.5]) or 1
        limit = rng.choice([rng.randint(-60, 60), rng.uniform(-60, 60)])
        if not (start <= limit if step > 0 else start >= limit):
            continue
        seen, final = accumulate(start, limit, step)
        assert list(runtime.float_range(start, limit, step)) == seen
        passes = runtime.pass_counter(start, limit, step)
        assert len(list(passes)) == len(seen)
        assert runtime.counted_final(passes, start, step) == final


def test_apostrophe_remark_after_a_statement():
    assert values("20 X = 1 ' set X\n30 PRINT X ' show it\n40 ' only a remark\n50 PRINT 2") == [[1.0], [2.0]]


def test_csv_row_of_a_statement_printed_in_parts():
    assert run_rows('10 L(1)=2: PRINT "a"; L(1); SQR(L(1)^2)') == [["a", "2.0", "2.0"]]


def _interrupted_run(program: str, after_seconds: float = 0.2) -> tuple[Machine, BasicError]:
    """Run ``program`` and send this process SIGINT (Ctrl-C) after ``after_seconds``."""
    import signal

    machine = Machine(screen=io.StringIO())
    machine.load(program)
    previous = signal.signal(signal.SIGALRM, lambda *_: signal.raise_signal(signal.SIGINT))
    signal.setitimer(signal.ITIMER_REAL, after_seconds)
    try:
        with pytest.raises(BasicError) as info:
            machine.run()
    finally:
        stop_alarm(previous)
    return machine, info.value


def test_break_of_a_jump_loop_names_the_line():
    machine, error = _interrupted_run("10 X=X+1\n20 GOTO 10\n")
    assert str(error) in ("Break in 10", "Break in 20")
    assert machine.scalar("X") > 0


def test_total_array_budget():
    from yaseer.basic.machine import machine as machine_module
    names = ", ".join(f"A{k}(1999998)" for k in range(machine_module.MAX_TOTAL_ELEMENTS // 1999999 + 1))
    assert error_of(f"10 DIM {names}") == "Out of memory in 10"


def test_empty_loops():
    assert values("10 FOR I=1 TO 1000: NEXT: PRINT I") == [[1001.0]]
    assert values("10 FOR I=1 TO 3\n20 NEXT I\n30 PRINT I") == [[4.0]]
    assert values("10 FOR X=.5 TO 99 STEP .25: NEXT: PRINT X") == [[accumulate(0.5, 99.0, 0.25)[1]]]


def test_zero_trip_loop_started_in_an_if_branch_skips_to_its_next():
    program = "10 IF 1 THEN FOR I=5 TO 1: PRINT 99\n20 PRINT 1\n30 NEXT I\n40 PRINT I"
    assert values(program) == [[5.0]]  # the start value (GW-BASIC's source; PC-BASIC: 6)


def test_string_arrays_and_string_comparison():
    out = run_text('10 DIM N$(3): FOR I=1 TO 3: READ N$(I): NEXT: FOR I=3 TO 1 STEP -1: PRINT N$(I);: NEXT: PRINT\n'
                   '20 IF N$(1) < N$(2) THEN PRINT "lt" ELSE PRINT "ge"\n30 DATA "b", a, c')
    assert out == "cab\nge\n"


def test_on_goto_out_of_range_falls_through():
    assert values("10 ON 3 GOTO 30, 40: PRINT 1: END\n30 PRINT 30\n40 PRINT 40") == [[1.0]]


def test_gosub_prog_inside_a_native_loop_sees_the_loop_variable():
    def area(machine):
        machine.array("Y")[1] = machine.scalar("I") * 10

    machine = Machine(screen=io.StringIO(), output_format="csv")
    machine.load("10 FOR I=1 TO 3: GOSUB PROG 1: PRINT Y(1): NEXT")
    machine.set_area(1, area)
    machine.run()
    assert machine.screen.stream.getvalue().split() == ["10.0", "20.0", "30.0"]


def test_numbers_a_python_area_stores_as_int_print_as_numbers():
    def area(machine):
        machine.array("X")[1] = 3  # an int, not a float

    for output_format, expected in (("csv", "3.0\n"), ("text", None)):
        screen = io.StringIO()
        machine = Machine(screen=screen, output_format=output_format)
        machine.load("10 GOSUB PROG 1: PRINT X(1)")
        machine.set_area(1, area)
        machine.run()
        if expected is not None:
            assert screen.getvalue() == expected
        else:
            assert screen.getvalue().strip() == "3"


def test_clear_resets_variables_and_arrays():
    program = "10 A=5: A$=\"x\": L(2)=7: DIM M(3): CLEAR: PRINT A; A$; L(2): DIM M(20): M(20)=1: PRINT M(20)"
    assert run_rows(program) == [["0.0", "", "0.0"], ["1.0"]]


def test_lower_case_program():
    assert values("10 for i=1 to 3: s=s+i: next i: print s") == [[6.0]]


def test_print_using_line_ending():
    # MS-BASIC: "###.##" right-aligns with two decimals; a trailing ; keeps the line open
    out = run_text('10 PRINT USING "###.##"; 3.14159;\n20 PRINT USING "###.##"; -2\n30 PRINT USING "##"; 1, 2')
    assert out == "  3.14 -2.00\n 1 2\n"


def test_area_hooks_see_every_gosub_prog():
    seen = []
    machine = Machine(screen=io.StringIO())
    machine.load("10 FOR QQ=1 TO 3: X(1)=QQ*2: GOSUB PROG 1: NEXT")
    machine.set_area(1, lambda m: None)
    machine.area_hooks.append(lambda m, n: seen.append((n, m.line, m.array("X")[1])))
    machine.run()
    assert seen == [(1, 10, 2.0), (1, 10, 4.0), (1, 10, 6.0)]


def test_statements_after_then_line_never_run():
    # as GW-BASIC (checked with PC-BASIC): they belong to the THEN branch, which jumps
    program = ('10 K=3: IF K > 2 THEN 40: PRINT "a"\n30 PRINT 30\n40 PRINT 40\n'
               '50 K=0: IF K > 2 THEN 40: PRINT "b"\n60 PRINT 60')
    assert run_rows(program) == [["40.0"], ["60.0"]]


def test_zero_trip_loop_finds_its_next_inside_an_if_branch():
    # GW-BASIC scans forward for the NEXT, also into IF branches (checked with PC-BASIC)
    program = '10 FOR N=0 TO 4 STEP -1: IF 0 THEN 20 ELSE PRINT 9: NEXT N\n20 PRINT "x"'
    assert run_rows(program) == [["x"]]
    program = "10 IF 0 THEN A=1 ELSE PRINT 1: FOR N=3 TO 1 STEP 2: NEXT N\n20 PRINT N"
    assert values(program) == [[1.0], [3.0]]  # the start value (GW-BASIC's source; PC-BASIC: 5)
    # even a NEXT after "THEN n:", which can never run, ends the scan
    program = '10 FOR J=3 TO 2: PRINT 1\n20 IF 1 THEN 30: NEXT J\n30 PRINT "y"; J'
    assert run_rows(program) == [["y", "3.0"]]  # the start value (PC-BASIC: 4)


def test_break_inside_a_long_native_loop_keeps_the_variable():
    machine, error = _interrupted_run("10 FOR I=1 TO 1E12: NEXT\n20 PRINT I")
    assert str(error) == "Break in 10"
    assert 1 < machine.scalar("I") < 1e12 and machine.scalar("I") == int(machine.scalar("I"))


# ---------------------------------------------------------------- GW-BASIC's screen width
# Rows as PC-BASIC 2.0.8 shows them (its logical lines cut into 80-column rows):
#   PRINT 70 A's;"BCDEFGHIJK"   -> fits exactly: the full row is followed by an empty one
#   PRINT 70 A's;"BCDEFGHIJKL"  -> the string does not fit: it starts the next row
#   PRINT 75 A's;12345          -> the number (" 12345 ") starts the next row
#   PRINT 56 A's,"B"            -> from the last zone (column 57) the comma starts a new row


def gw_text(program: str) -> str:
    return run_text(program, dialect="gw")


def test_gw_item_that_does_not_fit_starts_a_new_row():
    a70 = '"' + "A" * 70 + '"'
    assert gw_text(f'10 PRINT {a70};"BCDEFGHIJK"') == "A" * 70 + "BCDEFGHIJK\n\n"
    assert gw_text(f'10 PRINT {a70};"BCDEFGHIJKL"') == "A" * 70 + "\nBCDEFGHIJKL\n"
    assert gw_text('10 PRINT "' + "A" * 75 + '";12345') == "A" * 75 + "\n 12345 \n"


def test_gw_long_string_wraps_and_comma_at_the_last_zone_starts_a_row():
    assert gw_text('10 PRINT "' + "A" * 100 + '"') == "A" * 80 + "\n" + "A" * 20 + "\n"
    assert gw_text('10 PRINT "' + "A" * 56 + '","B"') == "A" * 56 + "\nB\n"
    assert gw_text("10 PRINT 1,2,3,4,5,6") == "".join(f" {k}            " for k in range(1, 5)) + " 5 \n 6 \n"


def test_gw_tab_and_spc_count_modulo_the_width():
    assert gw_text('10 PRINT TAB(90);"B": PRINT "A";SPC(85);"B"') == " " * 9 + "B\nA     B\n"


def test_width_40_and_bad_widths():
    assert gw_text('10 WIDTH 40: PRINT 1,2,3,4') == " 1             2 \n 3             4 \n"
    assert error_of("10 WIDTH 50", dialect="gw") == "Illegal function call in 10"


def test_gw_number_before_comma_keeps_its_blank_at_a_zone_end():
    """A number a comma follows that ends one column before a zone keeps its trailing blank,
    so the comma moves a whole zone, as a real GW-BASIC 3.23 recorded it (PC-BASIC's PRFLOAT
    test: the item after `` 7.369805E-02`` at column 29) and PC-BASIC 2.0.8 prints it; the
    published source's MODCOM would drop the blank (column 15)."""
    assert gw_text('10 PRINT "ABCD";12345678,5') == "ABCD 12345678" + " " * 15 + " 5 \n"
    assert run_text('10 PRINT "ABCD";12345678,5') == "ABCD 12345678" + " " * 15 + " 5 \n"


def test_casio_never_wraps():
    assert run_text('10 PRINT "' + "A" * 100 + '";12345') == "A" * 100 + " 12345 \n"
