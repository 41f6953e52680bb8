"""The casio dialect's words, each checked on its page of the FX-850P/880P owner's manual.

Every test is named after a page of the manual (urbancamo/urbancamo.github.io,
casio-basic/doc: commands/*.md, part-6-basic-programming.md, part-12-2-error-messages.md,
specifications.md) and runs a program of ours written after that page's format and
sample program; the expected values come from the manual's worked examples, from
Python's math and fractions, or from mpmath - never from yaseer.
"""

from __future__ import annotations

import io
import math
from fractions import Fraction

import mpmath
import pytest

from test_basic_helpers import error_of, run_text, run_values
from yaseer.basic.machine.machine import Machine

mpmath.mp.dps = 30


def close(value: float, reference, digits: int = 12) -> bool:
    """``value`` agrees with ``reference`` (an mpmath number) to ``digits`` significant digits."""
    reference = mpmath.mpf(reference)
    return abs(mpmath.mpf(value) - reference) <= abs(reference) * mpmath.mpf(10) ** -digits


# ------------------------------------------------------------------ functions

def test_log_ln_common_and_natural_logarithm():  # LOG_LN.md
    rows = run_values("10 N=100: PRINT LOG N; LN N\n20 PRINT LOG(2), LN(3)\n")
    assert rows[0] == [2.0, pytest.approx(float(mpmath.log(100)), rel=1e-15)]
    assert close(rows[1][0], mpmath.log10(2)) and close(rows[1][1], mpmath.log(3))
    assert error_of("10 PRINT LOG 0") == "Illegal function call in 10"  # 0 < argument
    assert error_of("10 PRINT LN(-1)") == "Illegal function call in 10"


def test_cur_cube_root():  # CUR.md: A=27 prints 3
    assert run_text('10 A=27\n20 PRINT A; ", CUBE ROOT"; CUR A\n') == " 27 , CUBE ROOT 3 \n"
    rows = run_values("10 PRINT CUR(-8), CUR 2, CUR(1E-30)\n")
    assert rows[0][0] == -2.0
    assert close(rows[0][1], mpmath.cbrt(2)) and close(rows[0][2], mpmath.mpf("1e-10"))


def test_frac_fraction_part_with_the_sign():  # FRAC.md
    rows = run_values("10 PRINT FRAC(3.14), FRAC(-2.75), FRAC 5\n")
    assert rows == [[pytest.approx(0.14, abs=1e-14), -0.75, 0.0]]


def test_int_and_fix():  # INT.md, FIX.md: INT(x) is FIX(x)-1 for a negative fraction
    assert run_values("10 A=-1.5: PRINT INT(1.3), INT A, FIX A, FIX(-1.5), INT(-2)\n") == \
        [[1.0, -2.0, -1.0, -1.0, -2.0]]


def test_fact_factorial():  # FACT.md: X=5 gives 120, 0 <= x <= 69
    assert run_text('10 X = 5\n20 Y = FACT X\n30 PRINT X;"!=";Y\n') == " 5 != 120 \n"
    assert run_values("10 PRINT FACT(69), FACT 0\n") == [[float(math.factorial(69)), 1.0]]
    assert error_of("10 PRINT FACT(70)") == "Overflow in 10"
    assert error_of("10 PRINT FACT(2.5)") == "Illegal function call in 10"  # a fraction is an error
    assert error_of("10 PRINT FACT(-1)") == "Illegal function call in 10"


def test_ncr_combinations():  # NCR.md: 8C4, and the example NCR(70, 35)
    assert run_text("10 N=8 : R=4\n20 X = NCR(N, R)\n30 PRINT X\n") == " 70 \n"
    assert run_values("10 PRINT NCR(70, 35)\n") == [[float(math.comb(70, 35))]]
    assert error_of("10 PRINT NCR(3, 4)") == "Illegal function call in 10"  # r <= n
    assert error_of("10 PRINT NCR(5.5, 2)") == "Illegal function call in 10"


def test_npr_permutations():  # NPR.md: 10P5 (the page's sample means R=5), NPR(69, 20)
    assert run_text("10 N=10 : R=5\n20 X = NPR(N, R)\n30 PRINT X\n") == " 30240 \n"
    assert run_values("10 PRINT NPR(69, 20)\n") == [[float(math.perm(69, 20))]]
    assert error_of("10 PRINT NPR(1E11, 2)") == "Illegal function call in 10"  # n < 1E10


def test_pol_rectangular_to_polar_sets_x_and_y():  # POL.md: (5, 3)
    rows = run_values("10 A=5 : B=3\n20 Z=POL(A,B)\n30 PRINT X; Y; Z\n")
    r, theta = math.hypot(5, 3), math.degrees(math.atan2(3, 5))
    assert rows == [[pytest.approx(r, rel=1e-15), pytest.approx(theta, rel=1e-15), pytest.approx(r, rel=1e-15)]]
    assert run_values("10 Z=POL(-2,0): PRINT X; Y: ANGLE 1: Z=POL(0,-3): PRINT X; Y\n") == \
        [[2.0, 180.0], [3.0, pytest.approx(-math.pi / 2, rel=1e-15)]]  # -180 < theta <= 180
    assert error_of("10 Z=POL(0,0)") == "Illegal function call in 10"  # |x| + |y| > 0


def test_rec_polar_to_rectangular_sets_x_and_y():  # REC.md: (2, 30 degrees)
    rows = run_values("10 A=2 : B=30\n20 Z=REC(A,B)\n30 PRINT X; Y\n")
    assert rows == [[pytest.approx(math.sqrt(3), rel=1e-15), pytest.approx(1.0, rel=1e-15)]]
    assert error_of("10 Z=REC(1, 1440)") == "Illegal function call in 10"  # -1440 < theta < 1440


def test_pol_and_rec_not_inside_a_def_fn():  # the Casio has no DEF FN: a body cannot set X and Y
    assert error_of("10 DEF FNR(U)=REC(U,90)\n20 Z=FNR(4)") == "Syntax error in 10"


def test_hyp_sin_cos_tan():  # HYP_SIN_COS_TAN.md: both spellings, |x| <= 230.2585092
    rows = run_values("10 N=1.5\n20 PRINT HYPSIN N; HYPCOS N; HYPTAN N; HYP SIN(N); HYP COS N\n")[0]
    for value, reference in zip(rows, [mpmath.sinh(1.5), mpmath.cosh(1.5), mpmath.tanh(1.5),
                                       mpmath.sinh(1.5), mpmath.cosh(1.5)]):
        assert close(value, reference)
    assert error_of("10 PRINT HYPSIN 231") == "Overflow in 10"


def test_hyp_asn_acs_atn():  # HYP_ASN_ACS_ATN.md
    rows = run_values("10 N=10\n20 PRINT HYPASN N; HYPACS N; HYP ATN .5\n")[0]
    for value, reference in zip(rows, [mpmath.asinh(10), mpmath.acosh(10), mpmath.atanh(0.5)]):
        assert close(value, reference)
    assert error_of("10 PRINT HYPACS .5") == "Illegal function call in 10"  # 1 <= argument
    assert error_of("10 PRINT HYPATN 1") == "Illegal function call in 10"  # -1 < argument < 1


def test_asn_acs_atn_in_radians_and_degrees():  # ASN_ACS_ATN.md: the sample in ANGLE 1
    rows = run_values("10 ANGLE 1\n20 N=.5\n30 PRINT ASN N; ACS N; ATN N\n40 ANGLE 0: PRINT ASN 1; ACS(-1); ACS 0\n")
    for value, reference in zip(rows[0], [mpmath.asin(0.5), mpmath.acos(0.5), mpmath.atan(0.5)]):
        assert close(value, reference)
    assert rows[1] == [90.0, 180.0, 90.0]
    assert error_of("10 PRINT ASN 1.5") == "Illegal function call in 10"  # -1 <= argument <= 1


def test_deg_sexagesimal_to_decimal():  # DEG.md: DEG(1, 30, 10)
    assert run_values("10 A=1: B=30: C=10\n20 D = DEG(A,B,C)\n30 PRINT D; DEG(2); DEG(2,30)\n") == \
        [[pytest.approx(float(1 + Fraction(30, 60) + Fraction(10, 3600)), rel=1e-15), 2.0, 2.5]]


def test_dms_decimal_to_sexagesimal_string():  # DMS_STRING.md: DMS$(1.52)
    # the degree sign is the Casio's code &HDF, shown as the small circle of its character set
    assert run_text('10 N=1.52\n20 PRINT "=" ; DMS$(N); ASC(MID$(DMS$(N), 2))\n') == "=1ﾟ31'12\" 223 \n"
    assert run_text('10 PRINT DMS$(-2.5); " "; DMS$(0.0001)\n') == "-2ﾟ30'0\" 0ﾟ0'0.36\"\n"
    assert run_text('10 PRINT DMS$(2E6)\n') == "2000000\n"  # from 1E6 on: no minutes, no seconds


def test_hex_four_digits():  # HEX_STRING.md: the sample's 0..16, and -1 as 65535
    text = run_text('10 FOR I=0 TO 16\n20 PRINT HEX$(I);" ";\n30 NEXT I\n40 PRINT HEX$(-1); HEX$(65535); HEX$(-32768)\n')
    assert text.split() == [format(i, "04X") for i in range(17)] + ["FFFFFFFF8000"]
    assert error_of("10 PRINT HEX$(65536)") == "Illegal function call in 10"


def test_amp_h_hexadecimal_constants():  # AMP_H.md: &HAF, &H1B7F is 7039, VAL("&H"+A$)
    assert run_values('10 A = &HAF: A$="1B7F"\n20 PRINT A; &H1B7F; VAL("&H" + A$); &HFFFF\n') == \
        [[175.0, 7039.0, 7039.0, 65535.0]]
    assert error_of("10 A = &H10000") == "Overflow in 10"  # 0 <= argument <= FFFF


def test_round_at_a_digit():  # ROUND.md: 610.5765383 rounded at -2 is 610.6
    assert run_values("10 N=610.5765383\n20 PRINT ROUND(N,-2); ROUND(N,0); ROUND(N,1); ROUND(-2.5,-1)\n") == \
        [[610.6, 610.0, 600.0, -3.0]]
    assert run_values("10 PRINT ROUND(1234.5678, -3)\n") == [[1234.57]]
    assert error_of("10 PRINT ROUND(1, 100)") == "Illegal function call in 10"  # -100 < digit < 100


def test_ran_hash():  # RAN_HASH.md
    program = "10 FOR I=1 TO 5: R=RAN#(1): S=RAN#(0): PRINT R; R=S; R>0 AND R<1: NEXT I\n"
    first, again = run_values(program), run_values(program)
    assert first == again  # RAN#(1): the same series at every run
    assert all(row[1] == -1.0 and row[2] == -1.0 for row in first)  # RAN#(0) repeats; 0 < RAN# < 1
    assert len({row[0] for row in first}) == 5
    other = run_values("10 FOR I=1 TO 200: R=RAN# * 10: IF R<=0 OR R>=10 THEN PRINT R\n20 NEXT I\n")
    assert other == []


def test_valf_evaluates_a_string():  # VALF.md: "123+456" and "EXP 2"
    assert run_text('10 X$ = "123+456"\n20 PRINT VALF(X$)\n30 PRINT VALF("EXP 2")\n') == " 579 \n 7.389056099 \n"
    assert run_values('10 x=3: PRINT VALF("x^2+1")\n') == [[10.0]]  # with the variables as they are
    assert error_of('10 PRINT VALF("VALF(1)")') == "Illegal function call in 10"  # not inside VALF
    assert error_of('10 PRINT VALF("1+")') == "Syntax error in 10"


def test_pi_constant():  # PI.md
    assert run_text('10 R=2\n20 PRINT "CIRCUMFERENCE="; 2*PI*R\n') == "CIRCUMFERENCE= 12.56637061 \n"


def test_sqr_and_sgn_and_abs():  # SQR.md, SGN.md, ABS.md
    rows = run_values("10 FOR I=0 TO 3: PRINT SQR I; SGN(I-1); ABS(1-I): NEXT I\n")
    assert [row[0] for row in rows] == [math.sqrt(i) for i in range(4)]
    assert [row[1:] for row in rows] == [[-1.0, 1.0], [0.0, 0.0], [1.0, 1.0], [1.0, 2.0]]


def test_mod_and_yen_integer_division():  # MOD.md, part 6 Arithmetic Operators: -15 ¥ 7, -15 MOD 7
    assert run_values("10 PRINT -15 MOD 7; -15 ¥ 7; -15 \\ 7; 15.9 MOD 7; -15.9 ¥ 7\n") == \
        [[-1.0, -2.0, -2.0, 1.0, -2.0]]  # fractions truncated, the remainder has the dividend's sign
    assert error_of("10 PRINT 40000 MOD 3") == "Overflow in 10"  # -32768..32767


def test_logical_operators_truncate():  # LOGICAL.md, part 6 Logical Operators: XOR's table
    assert run_values("10 PRINT 0 XOR 0; 0 XOR 1; 1 XOR 0; 1 XOR 1; 1.9 AND 1; NOT 0; 6 OR 1.5\n") == \
        [[0.0, 1.0, 1.0, 0.0, 1.0, -1.0, 7.0]]


# ------------------------------------------------------------------ statements

def test_angle_degrees_radians_grads():  # ANGLE.md: the sample's three sines of a sixth of a half turn
    text = run_text("10 ANGLE 0 'DEGREES\n20 PRINT SIN 30;\n30 ANGLE 1 'RADIAN\n40 PRINT SIN (PI/6);\n"
                    "50 ANGLE 2 'GRAD\n60 PRINT SIN(100/3)\n")
    assert text == " .5  .5  .5 \n"
    assert run_values("10 ANGLE 2: PRINT COS 100; ATN 1; TAN 50\n") == \
        [[0.0, pytest.approx(50.0, rel=1e-15), pytest.approx(1.0, rel=1e-15)]]
    assert error_of("10 ANGLE 3") == "Illegal function call in 10"  # 0 <= angle < 3


def test_beep_sounds_nothing_into_a_file():  # BEEP.md: the sample program runs and prints nothing
    assert run_text("10 BEEP 1 : BEEP 0 : BEEP 1 : BEEP 0: BEEP\n20 PRINT 1\n") == " 1 \n"


def test_clear_clears_variables():  # CLEAR.md
    assert run_values("10 A=5: A$=\"X\": CLEAR: PRINT A; A$\n") == [[0.0, ""]]


def test_defseg_and_poke():  # DEFSEG.md, POKE.md: DEFSEG = 2, POKE &H100 writes at &H120
    machine = Machine(screen=io.StringIO())
    machine.load("10 DEFSEG = 2\n20 POKE &H100, 7\n30 DEFSEG=&H0\n40 FOR I=&H7000 TO &H7002: POKE I, I-&H7000+1: NEXT I\n"
                 "50 POKE -1, 255\n")
    machine.run()
    assert machine.memory == {0x120: 7, 0x7000: 1, 0x7001: 2, 0x7002: 3, 0xFFFF: 255}
    assert error_of("10 POKE 0, 256") == "Illegal function call in 10"
    assert error_of("10 POKE 65536, 0") == "Illegal function call in 10"


def test_dim_and_the_dd_error():  # DIM.md: its sample, the same declaration again, another size
    assert run_text("10 DIM A$(5)\n20 FOR I=65 TO 70\n30 A$(I-65)=CHR$(I)\n40 PRINT A$(I-65);\n50 NEXT I\n") == \
        "ABCDEF"
    assert run_values("10 DIM B(3): B(2)=4: DIM B(3): PRINT B(2)\n") == [[4.0]]  # discarded, not cleared
    assert error_of("10 DIM B(3): DIM B(4)") == "Duplicate Definition in 10"
    assert run_values("10 DIM: ERASE Q: DIM Q(2): PRINT 1\n") == [[1.0]]  # the library's bare DIM


def test_erase():  # ERASE.md: its sample, and an array that is not there
    text = run_text('10 CLEAR\n20 DIM A$(10), B$(10)\n30 ERASE A$\n40 VARLIST\n')
    assert "B$()" in text and "A$()" not in text
    assert run_values("10 ERASE Z9: DIM Z9(1): ERASE Z9: DIM Z9(5): Z9(5)=1: PRINT Z9(5)\n") == [[1.0]]


def test_varlist_names_in_columns():  # VARLIST.md: A AB R AC$()
    text = run_text("10 A=1: AB=2: R=3: DIM AC$(1)\n20 VARLIST\n")
    assert text.splitlines()[0].split() == ["A", "AB", "R", "AC$()"]
    assert text.splitlines()[0].startswith("A       AB      R       AC$()")


def test_pass_registers_and_cancels():  # PASS.md, part-12-2: the PR error is code 21
    assert run_text('10 PASS "TEXT": PASS "TEXT": PASS "OTHER": PRINT 1\n') == " 1 \n"
    assert error_of('10 PASS "TEXT": PASS "TEST"') == "Wrong password in 10"
    assert run_values('10 ON ERROR GOTO 30\n20 PASS "ABCDEFGHI": PASS "ABCDEFGH": PASS "A": PASS "B"\n'
                      '30 PRINT ERR: END\n') == [[21.0]]  # the first 8 characters count


def test_a_registered_password_refuses_list_edit_save_and_the_data_bank(tmp_path):
    # PASS.md item 5 (LIST.md item 11, EDIT.md item 4, SAVE_SAVE_ALL.md item 6, LIST#.md
    # item 5, NEW#.md item 2, SAVE#.md item 7): the PR error, code 21 (part-12-2)
    for command in ("LIST", "LIST 10", "LLIST", "LIST ALL", "EDIT 10", "EDIT", 'SAVE "F"', "LIST#", "NEW#",
                    'SAVE# "D"'):
        assert error_of(f'10 PASS "KEY": {command}') == "Password protected in 10", command
    assert run_values('10 ON ERROR GOTO 30\n20 PASS "KEY": LIST\n30 PRINT ERR: END\n') == [[21.0]]
    # cancelled by the same password: LIST shows the program again
    assert run_text('10 PASS "KEY": PASS "KEY": LIST 10\n').startswith("10 PASS")
    assert run_values('10 WRITE# "A": PASS "K": RESTORE#: READ# A$: PRINT LEN(A$)\n') == [[1.0]]


def test_set_output_format():  # SET.md: 10/3 with two decimals, two digits, then as before
    assert run_text("10 A = 10/3\n20 SET F2\n30 PRINT A\n40 SET E2\n50 PRINT A\n60 SET N: PRINT A\n") == \
        " 3.33 \n 3.3E+00 \n 3.333333333 \n"
    assert run_text("10 SET F0: PRINT 2.5; -1234.5: SET E3: PRINT 99960; -0.000123456\n") == \
        " 3 -1235 \n 1.00E+05 -1.23E-04 \n"
    assert error_of("10 SET G2") == "Syntax error in 10"


def test_mode_angle_and_printer():  # ANGLE.md (the MODE key), part 7 (MODE 7 / MODE 8)
    assert run_values("10 MODE 5: PRINT SIN(PI/2): MODE 4: PRINT SIN 90: MODE 6: PRINT SIN 100\n") == \
        [[1.0], [1.0], [1.0]]
    screen, printer = io.StringIO(), io.StringIO()
    machine = Machine(screen=screen, printer=printer)
    machine.load('10 MODE 7: PRINT "ON": MODE 8: PRINT "OFF"\n')
    machine.run()
    assert screen.getvalue() == "ON\nOFF\n" and printer.getvalue() == "ON\n"


def test_restore_to_a_line_and_to_an_expression():  # RESTORE.md: its sample, and RESTORE (10*10)
    program = ("10 READ X\n20 IF X<> 0 THEN PRINT X;: GOTO 10\n30 RESTORE 110\n40 READ X\n"
               "50 IF X<>0 THEN PRINT X;: GOTO 40\n60 END\n100 DATA 1,2,3,4,5,6,7,8,9\n"
               "110 DATA 9,8,7,6,5,4,3,2,1\n120 DATA 0\n")
    # lines 10-20 read all three DATA lines; after RESTORE 110, lines 30-50 read the last two again
    assert run_text(program).split() == [str(k) for k in [*range(1, 10), *range(9, 0, -1), *range(9, 0, -1)]]
    assert run_values("10 RESTORE (10*10): READ A: L=110: RESTORE (L): READ B: PRINT A; B\n100 DATA 5\n110 DATA 6\n") == \
        [[5.0, 6.0]]
    assert error_of("10 RESTORE (10*5)\n100 DATA 1") == "Undefined line number 50 in 10"  # the UL error


def test_on_goto_with_empty_places():  # ON_GOTO.md: its sample; an empty place falls through
    program = '10 INPUT "1 OR 2"; A\n20 ON A GOTO 40, 50\n30 END\n40 PRINT "ONE" : END\n50 PRINT "TWO"\n'
    for answer, shown in (("1", "ONE"), ("2", "TWO"), ("3", "")):
        assert run_text(program, input_stream=io.StringIO(answer + "\n")).endswith(shown + "\n")
    assert run_text('10 ON 2 GOTO 30,,40: PRINT "NONE": END\n30 PRINT "A": END\n40 PRINT "B"\n') == "NONE\n"
    assert run_text('10 ON 3 GOSUB 30,,40: PRINT "BACK": END\n30 PRINT "A": RETURN\n40 PRINT "B": RETURN\n') == \
        "B\nBACK\n"


def test_on_goto_truncates_and_falls_through():  # ON_GOTO.md items 1-2: truncated; below 1 or past the list: on
    program = '10 FOR I=-2 TO 3: ON I+0.9 GOTO 30, 40: PRINT "ON";I;: NEXT: END\n30 PRINT "A";: NEXT: END\n40 PRINT "B";: NEXT\n'
    assert run_text(program) == "ON-2 ON-1 ON 0 ABON 3 "  # 1.9 is 1 (A), 2.9 is 2 (B)


def test_input_asks_for_each_variable():  # INPUT.md: its example YEAR=, MONTH=, DAY=; items 2-4 and 7
    program = '10 D=9: INPUT "YEAR=", Y, "MONTH="; M, D\n20 PRINT Y; M; D\n'
    text = run_text(program, input_stream=io.StringIO("1990\n5\n\n"))
    assert text.splitlines() == ["YEAR=1990", "MONTH=? 5", "? ", " 1990  5  9 "]


def test_array_subscripts_disregard_fractions():  # part 6, Arrays; DIM.md item 2: truncated
    assert run_values("10 DIM A(3.9): A(3.7)=5: A(1)=2: PRINT A(3); A(1.99); A(3)*A(1.5)\n") == [[5.0, 2.0, 10.0]]
    assert error_of("10 DIM A(3.9): A(4)=1") == "Subscript out of range in 10"
    assert error_of("10 DIM A(3): A(-1)=1") == "Subscript out of range in 10"  # part 12: the BS error


def test_asc_of_a_null_string_is_zero():  # ASC.md items 1-2
    assert run_values('10 PRINT ASC("ABC"); ASC("")\n') == [[65.0, 0.0]]


def test_fre_counts_the_variable_area_as_part_6_does():  # FRE.md (0..3), CLEAR.md, part 6 counting
    # part 6's worked example: DIM XYZ(3,3,5,2) takes (3+4)+(288x8)+4x2+1 = 2320 bytes;
    # a string takes its length + 1 in the string area; FRE 2 is CLEAR.md's 8192 (FX-880P)
    rows = run_values('10 A=FRE 0: DIM XYZ(3,3,5,2): B=FRE(0): S$="ABC": C=FRE 0\n'
                      '20 PRINT FRE 2; A-B; B-C\n')
    assert rows == [[8192.0, 2320.0, 3.0]]
    assert error_of("10 PRINT FRE 4") == "Illegal function call in 10"  # 0 <= argument <= 3
    program_area = run_values("10 PRINT FRE 3 - FRE 1\n")[0][0]
    assert program_area == (2 + 1 + len("PRINT FRE 3 - FRE 1") + 1) + 1  # "Calculating Program Length"


def test_an_array_beyond_the_variable_area_is_the_om_error():  # CLEAR.md 8192 bytes; part 6; OM error
    # a numeric array: (name + 4) + 8 an element + (dimensions x 2 + 1): B(1022) takes
    # 5 + 8184 + 3 = 8192 bytes, all of the area; B(1023) 8 more
    assert run_values("10 DIM B(1022): PRINT FRE 0") == [[0.0]]
    assert error_of("10 DIM B(1023)") == "Out of memory in 10"
    # two arrays that fit alone but not together; the OM error leaves no half-made array
    program = "10 ON ERROR GOTO 90\n20 DIM C(500): DIM D(600)\n30 PRINT FRE 0: END\n90 PRINT ERR: RESUME NEXT"
    assert run_values(program) == [[1.0], [8192.0 - (1 + 4 + 8 * 501 + 2 + 1)]]  # ERR 1: OM


def test_a_string_growing_beyond_the_variable_area_is_the_om_error():  # CLEAR.md 8192; part 6; OM
    # part 6: a string variable takes (name + 4) + (length + 1) bytes, a number name + 12, the
    # array B(1000) 5 + 8008 + 3: with A$ and I that leaves 8192 - 8016 - 7 - 13 = 156
    # characters for A$; the 157th append is OM (ERR 1) and A$ keeps its 156
    program = ('5 ON ERROR GOTO 100\n10 DIM B(1000): A$="": FOR I=1 TO 200: A$=A$+"X": NEXT\n'
               '20 PRINT "NO": END\n100 PRINT LEN(A$); I; ERR; FRE 0: END')
    assert run_values(program) == [[156.0, 157.0, 1.0, 0.0]]
    # an element of a string array, INPUT and READ store strings the same way
    program = ('5 ON ERROR GOTO 100\n10 DIM B(1000), C$(1): READ C$(0): INPUT C$(1)\n20 PRINT "NO": END\n'
               '100 PRINT ERL; ERR; LEN(C$(0)); LEN(C$(1)): END\n200 DATA ' + "Y" * 150)
    # C$(1): 2 + 4 + 2 elements + 2 = 10 bytes and its strings' lengths; I gone: 8192 - 8016 - 10 = 166
    assert run_values(program, input_stream=io.StringIO("Z" * 20 + "\n"))[-1] == [10.0, 1.0, 150.0, 0.0]
    # a shorter string in its place frees its bytes
    assert run_values('10 DIM B(1000): A$=STR$(1E99): A$="": FOR I=1 TO 150: A$=A$+"X": NEXT: PRINT LEN(A$)') \
        == [[150.0]]


def test_verify_reads_a_saved_file_through(tmp_path):  # VERIFY.md: VERIFY "CAS0:TEST"
    program = '10 OPEN "CAS0:TEST" FOR OUTPUT AS #1: PRINT #1, "ABC": CLOSE\n20 VERIFY "CAS0:TEST": PRINT "OK"\n'
    assert run_text(program, files=tmp_path) == "OK\n"
    assert error_of('10 VERIFY "CAS0:NONE"', files=tmp_path) == "File not found in 10"


def test_calc_dollar_holds_a_formula():  # the library's CALC$ (LIB1000: VALF(CALC$); LIB5950: CALC$=s$)
    assert run_values('10 CALC$="2*X+1": X=4: PRINT VALF(CALC$); LEN(CALC$)\n') == [[9.0, 5.0]]
    assert run_values('10 PRINT VALF("Q+1")\n') == [[1.0]]  # a variable the program never named is 0


@pytest.mark.parametrize("statement, message", [
    ("MODE 30(32,1024,223)", "MODE 30(...): a machine-code routine of the ROM is not emulated"),
    ('OPEN "COM0:5,E,8,2" AS #1', "COM0: (the RS-232C port) is not emulated"),
    ('PBLOAD "CAS0:P"', "PBLOAD/PBGET: reading PB-100 series tapes is not emulated"),
    ("DEFM 5", "DEFM: the PB-100 series' memory declaration is not emulated"),
])
def test_what_yaseer_lacks_ends_the_run_with_one_line(statement, message):
    # PBLOAD_PBGET.md, OPEN.md (COM0:), DEFM.md (an empty page); MODE n(...) from the
    # library: no ON ERROR handler can make them work, so none catches them
    assert error_of(f"5 ON ERROR GOTO 20\n10 {statement}\n20 END") == f"{message} in 10"


def test_if_then_else_chains():  # IF_THEN_ELSE.md: a statement after THEN, ELSE IF, nesting
    program = ('10 FOR A=1 TO 4\n20 IF A=1 THEN PRINT "ONE" ELSE IF A=2 THEN PRINT "TWO" ELSE IF A=3 THEN 40 '
               'ELSE PRINT "MANY"\n30 NEXT A: END\n40 PRINT "THREE": GOTO 30\n')
    assert run_text(program) == "ONE\nTWO\nTHREE\nMANY\n"
    assert run_text('10 A=5: IF (0<A) AND (A<10) THEN PRINT "GOOD!" ELSE 10\n') == "GOOD!\n"


def test_relational_operators_both_spellings():  # part 6, Relational Operators: =< and =>, ><
    assert run_values("10 PRINT 1=<1; 2=>3; 1><2; 10>3; 7<1; \"ABC\" = \"XYZ\"\n") == \
        [[-1.0, 0.0, -1.0, -1.0, 0.0, 0.0]]


def test_functions_without_parentheses():  # the library's SQRd, FRACx, LOG(ABSx)
    assert run_values("10 d=16: x=2.5: PRINT SQRd; FRACx; LOG(ABSx)\n") == \
        [[4.0, 0.5, pytest.approx(math.log10(2.5), rel=1e-15)]]


def test_on_error_goto_and_resume():  # ON_ERROR_GOTO.md, RESUME.md: reciprocals, 0 is illegal
    program = ('10 ON ERROR GOTO 1000\n20 INPUT A: IF A<0 THEN END\n30 D = 1/A\n40 PRINT "1/"; A; "=";D\n50 GOTO 20\n'
               '1000 PRINT "0 IS ILLEGAL"\n1010 RESUME 20\n')
    text = run_text(program, input_stream=io.StringIO("4\n0\n-1\n"))
    assert "1/ 4 = .25" in text and "0 IS ILLEGAL" in text


def test_trace_on_and_off():  # TRON.md, TROFF.md: the lines run are shown, then no more
    # the area and line of each line run ("P0-10", the page's sample), then no more after TROFF;
    # the keys are not a person's at a terminal here, so no EXE is awaited (compatibility.md)
    text = run_text("10 TRON\n20 A=1\n30 TROFF\n40 A=2\n")
    assert text == "P0-20\nP0-30\n"
    keys = io.StringIO("5\n")  # a key script is not consumed by the halts: INPUT still gets 5
    assert run_text("10 TRON\n20 INPUT A\n30 PRINT A*2", input_stream=keys) == "P0-20\n? 5\nP0-30\n 10 \n"


# ------------------------------------------------------------------ error codes

@pytest.mark.parametrize("statement, code", [
    ("X=1/0", 14),  # MA: division by zero
    ("X=SQR(-1)", 14),  # MA: argument outside the range
    ("X=FACT(70)", 13),  # OV
    ('X=1+"A"', 19),  # TM
    ("DIM Q(2): X=Q(5)", 16),  # BS
    ("DIM Q(2): DIM Q(3)", 15),  # DD
    ("GOTO 999", 18),  # UL
    ("READ Z", 22),  # DA
    ("RETURN", 25),  # GS
    ("NEXT", 23),  # FO
    ('X$="A": FOR I=1 TO 8: X$=X$+X$: NEXT I', 3),  # ST: more than 255 characters
])
def test_err_is_the_manuals_error_code(statement, code):  # part-12-2-error-messages.md
    program = f"10 ON ERROR GOTO 100\n20 {statement}\n30 END\n100 PRINT ERR; ERL: END\n"
    assert run_values(program) == [[float(code), 20.0]]


# ------------------------------------------------------------------ names and numbers

def test_names_keep_their_case_up_to_15_characters():  # part 6, Variables: A, a, NUMBER
    assert run_values("10 A=1: a=2: NUMBER=3: number=4: XYZWXYZWXYZWXYZ=5\n20 PRINT A; a; NUMBER; number; XYZWXYZWXYZWXYZ\n") \
        == [[1.0, 2.0, 3.0, 4.0, 5.0]]
    assert error_of("10 XYZWXYZWXYZWXYZW=1") == "Syntax error in 10"  # 16 characters
    assert run_values('10 ab$="x": AB$="y": PRINT ab$; AB$\n') == [["x", "y"]]


@pytest.mark.parametrize("word", ["CSR", "KEY", "MID", "VAC", "VAR", "AS", "OUT", "PUT", "CALC"])
def test_reserved_words_without_a_page_are_no_names(word):  # part 12 reserved-word list; PBLOAD_PBGET.md
    # the PB-100's words (and ALL of the direct commands): a PB-100 program using them is an SN error
    assert error_of(f"10 {word}=1") == f"Unsupported word {word} in 10"
    assert error_of(f"10 Z{word.lower()}1=1") == f"Unsupported word {word} in 10"  # read keyword-first
    assert run_values(f'10 A=1: PRINT A: END\n20 {word}\n') == [[1.0]]  # an error only when its line runs


def test_open_reads_output_and_as_though_they_are_reserved(tmp_path):
    # OPEN.md's format and sample 1/2: FOR OUTPUT AS #1, FOR INPUT AS #1 (OUTPUT read as OUT PUT)
    from yaseer.basic.source.scanner import detokenize

    program = ('10 open "CAS0:TEST" for output as #1: print #1,"WRITE TEST": close\n'
               '20 OPEN "CAS0:TEST" FOR INPUT AS 1: INPUT #1,A$: CLOSE: PRINT A$\n')
    assert run_text(program, files=tmp_path) == "WRITE TEST\n"
    assert detokenize('open "T" for output as #1') == 'OPEN "T" FOR OUTPUT AS #1'
    assert detokenize("ask=1") == "AS k=1"  # LIST shows how the machine read it


@pytest.mark.parametrize("statement", ["NEW", "NEW ALL", "RUN", "RUN 10"])
def test_new_and_run_cannot_be_in_a_program(statement):  # NEW.md item 7, RUN.md item 5: the FC error
    assert error_of(f'10 PRINT 1\n20 {statement}') == "Illegal direct in 20"
    assert run_values(f"10 ON ERROR GOTO 90\n20 {statement}\n30 END\n90 PRINT ERR: END") == [[17.0]]  # FC: 17


def test_list_in_a_program_lists_its_range_then_stands_by():  # LIST.md items 3, 10
    program = "10 LIST 20-30\n20 a=1: print a\n30 goto 40\n40 PRINT 9"
    assert run_text(program) == "20 a=1:PRINT a\n30 GOTO 40\n"  # nothing runs after it
    assert run_text("10 LIST -10\n20 END") == "10 LIST -10\n"


def test_list_period_in_a_program_lists_the_line_it_runs():  # LIST.md item 4: the line executed last
    assert run_text('10 PRINT 1\n20 PRINT 2: LIST .: PRINT 3\n30 PRINT 4') == " 1 \n 2 \n20 PRINT 2:LIST .:PRINT 3\n"
    assert run_text('10 LLIST .\n20 END') == "10 LLIST .\n"  # no --printer: beside the screen


def test_edit_in_a_program_shows_the_program_from_its_line():  # EDIT.md items 1-3
    # the edit mode displays the program from the line (or the first line above it), then
    # waits for keys: the run ends there
    program = "10 PRINT 1\n20 EDIT 25\n30 PRINT 3\n40 END"
    assert run_text(program) == " 1 \n30 PRINT 3\n40 END\n"
    assert run_text("10 EDIT .\n20 END") == "10 EDIT .\n20 END\n"  # the line running
    assert run_text("10 PRINT 1\n20 EDIT\n30 END") == " 1 \n10 PRINT 1\n20 EDIT\n30 END\n"  # from the first line
    assert error_of("10 EDIT", dialect="gw") == "Syntax error in 10"  # GW-BASIC's EDIT needs its line


def test_save_and_load_in_a_program_then_stand_by(tmp_path):  # SAVE_SAVE_ALL.md, LOAD_LOAD_ALL.md
    # the manual's sample file names: SAVE "CAS0:TEST"; LOAD "DEMO1"; ,A the ASCII format
    assert run_text('10 PRINT "SAVED"\n20 SAVE "CAS0:TEST",A\n30 PRINT "NOT REACHED"', files=tmp_path) == "SAVED\n"
    machine = Machine(screen=io.StringIO(), files=tmp_path)
    machine.load('10 LOAD "TEST"\n20 PRINT "NOT REACHED"')
    machine.run()
    assert machine.programs[0] == {10: 'PRINT "SAVED"', 20: 'SAVE "CAS0:TEST",A', 30: 'PRINT "NOT REACHED"'}
    assert machine.screen.stream.getvalue() == ""
    assert run_text('10 GOSUB "TEST"', files=tmp_path) == "SAVED\n"  # the same file GOSUB "name" runs
    assert error_of('10 LOAD "NONE"', files=tmp_path) == "File not found in 10"
    assert error_of('10 LOAD "TEST",R', files=tmp_path) == "Syntax error in 10"  # ,A only (LOAD's format)


def test_save_all_and_load_all_carry_every_program_area(tmp_path):  # SAVE ALL: P0-P9; LOAD ALL
    machine = Machine(screen=io.StringIO(), files=tmp_path)
    machine.set_area(4, "10 PRINT 4: RETURN")
    machine.set_area(7, "10 PRINT 7: RETURN")
    machine.load('10 SAVE ALL "CAS0:EVERY"')
    machine.run()
    other = Machine(screen=io.StringIO(), files=tmp_path)
    other.set_area(4, "10 PRINT 44: RETURN")
    other.set_area(8, "10 PRINT 8: RETURN")  # an area the file does not hold is emptied
    other.load('10 LOAD ALL "EVERY"')
    other.run()
    assert other.programs[0] == {10: 'SAVE ALL "CAS0:EVERY"'}
    assert other.programs[4] == {10: "PRINT 4:RETURN"} and other.programs[7] == {10: "PRINT 7:RETURN"}  # as listed
    assert not other.programs.get(8)
    screen = io.StringIO()
    lister = Machine(screen=screen)
    lister.set_area(2, "10 BEEP")
    lister.load("10 LIST ALL\n20 PRINT 1")
    lister.run()
    assert screen.getvalue() == "P0\n10 LIST ALL\n20 PRINT 1\nP2\n10 BEEP\n"  # LIST.md item 13


def test_calc_string_is_one_variable_in_any_case():  # reserved-word list: CALC; the library's CALC$=s$
    assert run_values('10 calc$="X+1": PRINT CALC$; Calc$\n') == [["X+1", "X+1"]]


def test_a_name_cannot_begin_with_a_reserved_word():  # part 6, Variable Names: RUNON, LIST1$
    # keyword-first reading: LN at the start of LNX is the function LN of X
    assert run_values("10 X=1: PRINT LNX; FACTX\n") == [[0.0, 1.0]]


def test_display_shows_ten_digits_of_twelve():  # part 6, Numeric Value Precision; PI.md
    assert run_text("10 PRINT PI; 1/3; 2/3; 1E10; 12345678901\n", dialect="casio") == \
        " 3.141592654  .3333333333  .6666666667  1E+10  1.23456789E+10 \n"
