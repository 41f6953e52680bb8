"""gw doubles on their 56-bit MBF mantissas (yaseer/basic/arithmetic/mbf_double.py).

References: exact rational arithmetic (fractions) for the roundings the source makes
exact (``$FMULD`` and ``$FDIVD`` round the exact result half to even; ``$FADDD`` does
while no bit is shifted past the guard byte's sticky bit); PC-BASIC 2.0.8's own MBF
doubles (``pcbasic.basic.values.numbers.Double``), bit for bit, where they follow the
source: sums of two numbers of one sign, MKD$/CVD, PRINT's 16 digits (where PC-BASIC's
are the source's: tests/test_gw_double_using.py's reference), and whole
programs whose every operation PC-BASIC computes as the source does.  Where PC-BASIC
does not (it applies the single-precision quirks of ``$FMULS``/``$FADDS`` to doubles
and divides shifting the divisor right: a few percent of products, quotients and
differences one unit off), the source's steps are asserted.
"""

from __future__ import annotations

import random
from decimal import Decimal
from fractions import Fraction

import pytest

from test_differential_support import base_seed, case_count, run_gw
from test_differential_gw_runtime import differing
from yaseer.basic.arithmetic import mbf_double, values
from yaseer.basic.machine import gwfunctions

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")  # PC-BASIC's importlib use


def value(p) -> Fraction:
    negative, exponent, mantissa = p
    if not exponent:
        return Fraction(0)
    v = Fraction(mantissa) * Fraction(2) ** (exponent - 184)
    return -v if negative else v


def nearest(x: Fraction):
    """``x`` rounded half to even to 56 bits, as parts."""
    if not x:
        return mbf_double.ZERO
    negative, x = x < 0, abs(x)
    exponent = x.numerator.bit_length() - x.denominator.bit_length()
    while x >= Fraction(2) ** exponent:
        exponent += 1
    while x < Fraction(2) ** (exponent - 1):
        exponent -= 1
    scaled = x * Fraction(2) ** (56 - exponent)  # in [2**55, 2**56)
    whole, rest = divmod(scaled.numerator, scaled.denominator)
    if 2 * rest > scaled.denominator or (2 * rest == scaled.denominator and whole & 1):
        whole += 1
    if whole >> 56:
        whole >>= 1
        exponent += 1
    return negative, exponent + 128, whole


def random_double(rng: random.Random, low: int = 100, high: int = 160) -> bytes:
    """8 MBF bytes: a random 56-bit mantissa (sometimes with few bits) and an exponent."""
    mantissa = rng.getrandbits(56)
    if rng.random() < 0.3:
        mantissa &= ~((1 << rng.randint(0, 55)) - 1)
    return mantissa.to_bytes(7, "little") + bytes((rng.randint(low, high),))


def pairs(seed: int, count: int):
    rng = random.Random(base_seed() + seed)
    for _ in range(count):
        a, b = random_double(rng), random_double(rng)
        if rng.random() < 0.5:  # exponents close together
            b = b[:7] + bytes((a[7] + rng.randint(-3, 3),))
        yield mbf_double.from_bytes(a), mbf_double.from_bytes(b)


def test_products_and_quotients_are_the_exact_ones_rounded_half_to_even():
    for a, b in pairs(1, case_count(3000)):
        assert mbf_double.multiply(a, b) == nearest(value(a) * value(b)), (a, b)
        assert mbf_double.divide(a, b) == nearest(value(a) / value(b)), (a, b)


def test_sums_without_bits_past_the_sticky_bit_are_the_exact_ones_rounded():
    checked = 0
    for a, b in pairs(2, case_count(3000)):
        if abs(a[1] - b[1]) < 8:  # bit by bit only: every bit shifted out passes bit 5
            checked += 1
            assert mbf_double.add(a, b) == nearest(value(a) + value(b)), (a, b)
            assert mbf_double.subtract(a, b) == nearest(value(a) - value(b)), (a, b)
    assert checked > case_count(3000) // 2


def test_a_second_byte_move_loses_all_but_bit_5_of_the_dropped_byte():
    """$SHRA keeps of a guard byte it drops only its bit 5 (ST): 1 + b, b shifted 16 bits
    with a 1 in its lowest byte's bit 0, ends on a guard byte of exactly 0x80 and rounds
    to even (down), where the exact sum lies above the half."""
    one = (False, 129, 1 << 55)
    b = (False, 113, (1 << 55) | (0x80 << 8) | 0x01)
    assert mbf_double.add(one, b) == (False, 129, (1 << 55) + (1 << 39))
    assert nearest(value(one) + value(b)) == (False, 129, (1 << 55) + (1 << 39) + 1)


def test_bits_a_byte_move_brings_below_bit_5_are_lost():
    """After a byte move, the bits of the new guard byte below bit 5 are shifted out
    without passing ST: shifted 10 bits, this sum ends on a guard byte of 0x80 (a tie,
    to even: down) where the exact sum lies 0.003 units above the half (PC-BASIC, which
    keeps every lost bit, rounds up)."""
    a, b = bytes.fromhex("5df3b00739e9326b"), bytes.fromhex("036ed8f56bef4461")
    exact = value(mbf_double.from_bytes(a)) + value(mbf_double.from_bytes(b))
    ours = mbf_double.add(mbf_double.from_bytes(a), mbf_double.from_bytes(b))
    assert ours[2] + 1 == nearest(exact)[2] and ours[:2] == nearest(exact)[:2]
    assert mbf_double.to_bytes(ours) == bytes.fromhex("7869aee2741a336b")


def test_shifts_of_57_bits_or_more_leave_the_larger_operand():
    one = (False, 129, 1 << 55)
    assert mbf_double.add(one, (False, 129 - 57, (1 << 56) - 1)) == one
    assert mbf_double.add(one, (True, 129 - 56, (1 << 56) - 1)) != one


def test_overflow_and_underflow():
    largest = (False, 255, (1 << 56) - 1)
    with pytest.raises(mbf_double.Overflow) as raised:
        mbf_double.add(largest, largest)
    assert not raised.value.negative
    with pytest.raises(mbf_double.Overflow) as raised:
        mbf_double.multiply(largest, (True, 130, 1 << 55))
    assert raised.value.negative
    assert mbf_double.multiply((False, 10, 1 << 55), (False, 10, 1 << 55)) == mbf_double.ZERO
    with pytest.raises(ZeroDivisionError):
        mbf_double.divide(largest, mbf_double.ZERO)


# ---------------------------------------------------------------- against PC-BASIC's MBF doubles

class _Values:
    double_math = False
    error_handler = None


def pc_double(data: bytes):
    from pcbasic.basic.values import numbers

    return numbers.Double(bytearray(data), _Values())


def pc_result(operation: str, a: bytes, b: bytes) -> bytes | None:
    x = pc_double(a)
    try:
        getattr(x, {"+": "iadd", "-": "isub", "*": "imul", "/": "idiv"}[operation])(pc_double(b))
    except (OverflowError, ZeroDivisionError):
        return None
    return bytes(x.to_bytes())


OPERATIONS = {"+": mbf_double.add, "-": mbf_double.subtract, "*": mbf_double.multiply, "/": mbf_double.divide}


def our_result(operation: str, a: bytes, b: bytes) -> bytes | None:
    try:
        return mbf_double.to_bytes(OPERATIONS[operation](mbf_double.from_bytes(a), mbf_double.from_bytes(b)))
    except (mbf_double.Overflow, ZeroDivisionError):
        return None


def test_sums_of_one_sign_are_pcbasics_bit_for_bit():
    rng = random.Random(base_seed() + 3)
    for _ in range(case_count(3000)):
        a, b = random_double(rng), random_double(rng)
        b = b[:6] + bytes((b[6] & 0x7F | a[6] & 0x80, min(255, a[7] + rng.randint(-7, 7))))  # one sign
        assert our_result("+", a, b) == pc_result("+", a, b), (a.hex(), b.hex())


def test_mkd_and_cvd_keep_all_56_bits():
    rng = random.Random(base_seed() + 4)
    for _ in range(case_count(3000)):
        data = random_double(rng, 1, 255)
        text = "".join(map(chr, data))
        x = gwfunctions.cvd(text)
        assert gwfunctions.mkd(x) == text
        assert float(x) == pc_double(data).to_value()  # the nearest float, as PC-BASIC's value


def source_digits(data: bytes) -> tuple[int, int]:
    """The 16 digits PRINT shows of a double from its bytes, by the source's steps
    (tests/test_gw_double_using.py's reference on fractions: ``$FOFMT`` takes ``$FOTNV``'s
    bracket and ``$FOTCV``'s half added), and their power of ten."""
    from test_gw_double_using import bracket, fotcv

    magnitude = abs(value(mbf_double.from_bytes(data)))
    if not magnitude:
        return 0, 0
    b, power = bracket(magnitude)
    return fotcv(b), power


def pc_agrees_with_the_source(data: bytes) -> bool:
    """Are PC-BASIC's 16 digits of the double (its tens, rounded once) the source's?"""
    if not data[7]:
        return True
    return tuple(map(abs, pc_double(data).to_decimal(16))) == tuple(map(abs, source_digits(data)))


def test_print_shows_pcbasics_16_digits_where_they_are_the_sources():
    """PRINT's text of generated doubles is PC-BASIC's where PC-BASIC's digits are those of
    the source's steps (most), else it shows the source's digits (MATH1.ASM ``$FOFMT``)."""
    rng = random.Random(base_seed() + 5)
    differing_in_pcbasic = 0
    for _ in range(case_count(3000)):
        data = random_double(rng, 60, 200)
        x = gwfunctions.cvd("".join(map(chr, data)))
        ours = values.str_dollar(values.printed_double(x))
        if pc_agrees_with_the_source(data):
            assert ours == pc_double(data).to_str(True, False).decode(), data.hex()
        else:
            differing_in_pcbasic += 1
            n, power = source_digits(data)
            shown = ours.strip().lstrip("-").replace("D", "E")
            assert Decimal(shown) == Decimal(n).scaleb(power), data.hex()
    assert differing_in_pcbasic < 0.05 * case_count(3000)


def test_csng_rounds_the_56_bits_as_pcbasic_outside_its_ties():
    """A double made single: the top 24 bits, rounded up when the 25th is 1 (``$CSD``);
    PC-BASIC rounds the byte below them half to even, the same except for a byte of
    exactly 0x80 (there the source rounds up: tested in test_single_arith.py)."""
    rng = random.Random(base_seed() + 7)
    for _ in range(case_count(3000)):
        data = random_double(rng, 60, 200)
        if data[3] == 0x80:
            continue
        x = gwfunctions.cvd("".join(map(chr, data)))
        assert values.single_of_double(x) == pc_double(data).to_single().to_value(), data.hex()


def basic_bytes(data: bytes) -> str:
    return "+".join(f"CHR$({byte})" for byte in data)


def double_program(rng: random.Random) -> str | None:
    """Two doubles from their bytes, an operation PC-BASIC computes as the source does
    (else None), its result printed, its bytes, and comparisons, INT and FIX of it."""
    a, b = random_double(rng, 110, 150), random_double(rng, 110, 150)
    if rng.random() < 0.5:
        b = b[:7] + bytes((a[7] + rng.randint(-8, 8),))
    operation = rng.choice("+-*/")
    result = our_result(operation, a, b)
    if result != pc_result(operation, a, b):
        return None
    if not all(map(pc_agrees_with_the_source, (a, b, result))):  # PRINT's digits: see above
        return None
    return (f"10 A# = CVD({basic_bytes(a)}): B# = CVD({basic_bytes(b)})\n"
            f"20 C# = A# {operation} B#: PRINT A#; B#; C#; A# {operation} B#\n"
            "30 FOR K = 1 TO 8: PRINT ASC(MID$(MKD$(C#), K, 1));: NEXT: PRINT\n"
            "40 PRINT C# < A#; C# = A# + 0; C# > B#; INT(C#); FIX(C#); STR$(-C#)\n")


def test_programs_of_doubles_print_as_pcbasic(pc):
    rng = random.Random(base_seed() + 6)
    programs = []
    while len(programs) < case_count(300):
        program = double_program(rng)
        if program:
            programs.append(program)
    found = differing(pc, programs)
    assert not found, f"{len(found)} of {len(programs)} differ; first:\n" + "\n---\n".join(found[0])


@pytest.mark.parametrize("source, shown", [
    # 56 bits: the quotient's 16th digit (a 53-bit double shows 4115223.333333334)
    ("10 A# = 12345670# / 3: PRINT A#", " 4115223.333333333 \n"),
    ("10 A# = 1# / 3: B# = A# * 3: PRINT A#; B#; B# = 1", " .3333333333333333  1 -1 \n"),
    ("10 FOR I = 1 TO 5: S# = S# + 1# / I: NEXT: PRINT S#", " 2.283333333333333 \n"),
    # 2/3 rounded down: three times it is below 2
    ("10 A# = 2# / 3: PRINT INT(A# * 3); FIX(-A#); CINT(A# * 1000)", " 2  0  667 \n"),
    # MKD$ of a 56-bit quotient read back by CVD is the same double
    ("10 A# = CVD(MKD$(1# / 3)): PRINT A# = 1# / 3; MKD$(A#) = MKD$(1# / 3)", "-1 -1 \n"),
    ("10 A# = 1# / 7: PRINT STR$(A#); A# < 1# / 7; A# > .1428571428571428#", " .1428571428571429 0 -1 \n"),
    # $FOFMT's digits: $FOTNV's table steps (times 10**7, 10, 10**9), where PC-BASIC's
    # tens give 8.333333333333333D-02 and 8.571428571428572D-02
    ("10 PRINT 1# / 12; 3# / 35", " 8.333333333333334D-02  8.571428571428571D-02 \n"),
])
def test_double_cases(source, shown):
    assert run_gw(source + "\n") == shown


def routine_result(routine, a, b):
    """What a routine of mbf_double gives: parts, or an infinity with the overflow's sign."""
    try:
        return routine(a, b)
    except mbf_double.Overflow as overflow:
        return float("-inf") if overflow.negative else float("inf")


def operation_result(operation, x, y):
    r = operation(x, y)
    return r if r in (float("inf"), float("-inf")) else values.double_parts(r)


@pytest.mark.parametrize("name", ["add", "subtract", "multiply", "divide"])
def test_the_compiled_operations_are_the_routines_bit_for_bit(name):
    """values' double operations (``_dad _dsb _dml _ddv``: the routines written out in one
    frame, with a float path) against mbf_double's routines, on 56-bit values (Wides),
    floats, integers, zero and both ends of the range."""
    routine, operation = getattr(mbf_double, name), getattr(values, f"double_{name}")
    rng = random.Random(base_seed() + 7)
    edges = [(False, 255, (1 << 56) - 1), (True, 1, 1 << 55), mbf_double.ZERO]
    def sparse():  # a few bits set: sums land on the guard byte's ties and its sticky bit
        mantissa = (1 << 55) | sum(1 << bit for bit in rng.sample(range(55), rng.randint(0, 4)))
        return rng.random() < 0.5, rng.randint(100, 160), mantissa

    cases = [(sparse(), sparse()) for _ in range(case_count(3000))]
    for a, b in list(pairs(8, case_count(3000))) + cases + [(e, f) for e in edges for f in edges]:
        if rng.random() < 0.2:  # a float operand of 53 bits, or a 16-bit integer
            a = mbf_double.parts(float(rng.getrandbits(53)) * 2.0 ** rng.randint(-60, 10) * rng.choice((1, -1)))
        x, y = values.double_of(a), values.double_of(b)
        if rng.random() < 0.1:
            x = rng.randint(-32768, 32767)
            a = mbf_double.parts(x)
        if name == "divide" and not b[1]:
            with pytest.raises(ZeroDivisionError):
                operation(x, y)
            continue
        assert operation_result(operation, x, y) == routine_result(routine, a, b), (a, b)
