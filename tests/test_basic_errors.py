"""Every run-time and syntax error stops the run with one line naming its line."""

import pytest

from test_basic_helpers import error_of


@pytest.mark.parametrize("program, message", [
    ("4070 A=1\n4080 GOSUB PROG 2: LPRINT USING \"#####.#\":QQ; W(6)", "Syntax error in 4080"),
    ("10 A=1\n20 B=A/0", "Division by zero in 20"),
    ("10 B=0^-1", "Division by zero in 10"),
    ("10 B=5 MOD 0", "Division by zero in 10"),
    ("30 L(21)=1", "Subscript out of range in 30"),
    ("30 L(-1)=1", "Subscript out of range in 30"),  # negative: the Casio's BS error (part 12)
    ("30 I=-3: L(I)=1", "Subscript out of range in 30"),
    ("10 FOR I=1 TO 2\n20 NEXT I\n60 NEXT I", "NEXT without FOR in 60"),
    ("10 FOR I=1 TO 2: NEXT J", "NEXT without FOR in 10"),
    ("20 RETURN", "RETURN without GOSUB in 20"),
    ("10 READ A\n70 READ B\n80 DATA 1", "Out of DATA in 70"),
    ("5030 GOTO 5200", "Undefined line number 5200 in 5030"),
    ("5030 GOSUB 5200", "Undefined line number 5200 in 5030"),
    ("5030 IF 1 THEN 5200", "Undefined line number 5200 in 5030"),
    ("10 A$=\"X\"\n20 B=A$", "Type mismatch in 20"),
    ("10 A=\"X\"+1", "Type mismatch in 10"),
    ("10 X=SQR(-1)", "Illegal function call in 10"),
    ("10 X=LOG(0)", "Illegal function call in 10"),
    ("10 X=(-8)^(1/3)", "Illegal function call in 10"),
    ("10 X=TAN(90)", "Illegal function call in 10"),
    ("10 X$=CHR$(300)", "Illegal function call in 10"),
    ("10 X=EXP(1000)", "Overflow in 10"),
    ("10 X=1E200\n20 Y=X*X", "Overflow in 20"),
    ("10 X=1E200\n20 PRINT X*X", "Overflow in 20"),
    ("10 X=1E308: Y=X+X", "Overflow in 10"),
    ("10 GOSUB 10", "Out of memory in 10"),
    ("10 DIM B(100000, 100)", "Out of memory in 10"),
    ("10 DEF FNA(X)=FNA(X)+1\n20 Y=FNA(1)", "Out of memory in 20"),
    ("10 A$=\"X\"\n20 A$=A$+A$: GOTO 20", "String too long in 20"),
    ("10 RESUME NEXT", "RESUME without error in 10"),
    ("10 X=1: Y=2\n20 PRINT FNQ(X)", "Undefined user function in 20"),
    ("10 FOR I=1 TO 3\n20 GOSUB 20", "Out of memory in 20"),
    ("10 DEF FNA(X)=X*2\n20 Y=FNA(\"s\")", "Type mismatch in 20"),
    ("10 DEF FNA(X)=X\n20 Y=FNA(1, 2)", "Syntax error in 20"),
    ("10 DIM M(5)\n20 DIM M(6)", "Duplicate Definition in 20"),  # (the same sizes again: passed over, DIM.md)
    ("10 INPUT A", "Input past end in 10"),
    ("10 X=VAL(\"1E999\")", "Overflow in 10"),
    ("10 PRINT TAB(257)", "Illegal function call in 10"),  # TAB.md: 0..256
    ("10 A$=MID$(\"abc\", 0)", "Illegal function call in 10"),
    ("10 CONT", "Syntax error in 10"),
])
def test_error_names_its_line(program, message):
    assert error_of(program) == message


def test_syntax_error_is_raised_only_when_the_line_runs():
    assert error_of("10 GOTO 30\n20 THIS IS NOT BASIC\n30 X=1/0") == "Division by zero in 30"


def test_deeply_nested_expression_is_an_error_of_its_own_line():
    depth = 400
    program = "9 A=1\n10 A=" + "(" * depth + "1" + ")" * depth
    assert error_of(program + "\n20 B=1/0") == "Out of memory in 10"


def test_deep_if_nesting_is_an_error_of_its_own_line():
    program = "2 X = 1\n3 " + "IF 1 THEN " * 200 + "X = 1\n4 PRINT 5\n"
    assert error_of(program) == "Out of memory in 3"


def test_long_minus_chain_fails_on_its_own_line():
    assert error_of("10 PRINT 1\n20 X = " + "-" * 5000 + "1") == "Out of memory in 20"


def test_print_shows_the_items_before_the_failing_one():
    from yaseer.basic.machine.machine import Machine
    import io

    for statement, shown in (('PRINT "a"; SQR(-1)', "a"), ('PRINT USING "##.#"; 1; SQR(-1)', " 1.0")):
        machine = Machine(screen=io.StringIO())
        machine.load("10 " + statement)
        try:
            machine.run()
        except Exception as err:  # noqa: BLE001
            assert str(err) == "Illegal function call in 10"
        assert machine.screen.stream.getvalue() == shown


def test_long_sum_compiles():
    program = "10 A=" + "+".join(["1"] * 300) + "\n20 PRINT A: X=1/0"
    assert error_of(program) == "Division by zero in 20"
