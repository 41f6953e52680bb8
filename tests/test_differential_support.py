"""The PC-BASIC 2.0.8 oracle and the seeded generators used by the differential tests.

This module holds no tests.  PC-BASIC (a GW-BASIC emulator whose expected
outputs were recorded on real GW-BASIC) runs headless in-process through
``pcbasic.Session``; one session runs many small cases, which is much faster
than a process per case.

Values given to both sides are *exact in single precision* and have at most
7 significant decimal digits, so GW-BASIC's single precision cannot decide
any printed digit.

PC-BASIC finds PRINT's 7 digits of a single by dividing by ten, where the GW-BASIC
source multiplies by its table's powers of ten (about 3% of random singles print
another 7th digit): the oracle runs PC-BASIC under
``single_digits_support.source_single_digits``, so such a single prints the digits of
the source's steps (a reference on fractions) in PC-BASIC's layout, and every other
text is PC-BASIC's own.  ``PcBasic.differing`` lists the singles it changed.

``YASEER_DIFF_CASES`` (environment) raises the number of generated cases per
test for a long run by hand; ``YASEER_DIFF_SEED`` changes the seed.
"""

from __future__ import annotations

import math
import os
import random
import re
from decimal import Decimal
from fractions import Fraction

DEFAULT_CASES = 300
STEP_LIMIT = 20_000  # program lines PC-BASIC may start before the case is cut off


def case_count(default: int = DEFAULT_CASES) -> int:
    """Cases per generated test: the default, or ``YASEER_DIFF_CASES``."""
    return int(os.environ.get("YASEER_DIFF_CASES", default))


def base_seed() -> int:
    """The seed of the generators: 2026, or ``YASEER_DIFF_SEED``."""
    return int(os.environ.get("YASEER_DIFF_SEED", 2026))


class StepLimitExceeded(Exception):
    """Raised inside PC-BASIC when a program runs too many lines."""


class PcBasic:
    """One headless PC-BASIC session running direct statements and whole programs."""

    def __init__(self, double: bool = False, source_digits: bool = True, devices: dict | None = None) -> None:
        """``double``: PC-BASIC's /D option (double-precision SIN, COS, ATN, SQR ... of double
        arguments); ``source_digits``: singles print the source's 7 digits (module docstring),
        False for PC-BASIC's own output; ``devices``: PC-BASIC's device map (``{"LPT1:":
        "FILE:path"}`` writes the printer's text to a file)."""
        import pcbasic  # test dependency, imported only when a differential test runs

        self._session = pcbasic.Session(output_streams=None, input_streams=None, double=double,
                                        devices=devices)
        self._session.start()
        self._steps = 0
        self._session.set_hook(self._count_step)
        self.differing: list = []  # (single, PC-BASIC's digits, the source's) it printed otherwise
        self._source_digits = source_digits

    def _count_step(self, _token: bytes) -> None:
        self._steps += 1
        if self._steps > STEP_LIMIT:
            raise StepLimitExceeded()

    def _run(self, text: str) -> str:
        from contextlib import nullcontext

        from single_digits_support import source_single_digits

        self._steps = 0
        try:
            with source_single_digits(self.differing) if self._source_digits else nullcontext():
                out = self._session.execute(text)
        except StepLimitExceeded:
            out = "\n<step limit>"
        return clean_output(out)

    def statement(self, text: str) -> str:
        """Output of one direct-mode statement (``PRINT USING ...``)."""
        return self._run(text)

    def program(self, source: str) -> str:
        """Output of ``NEW``, the numbered ``source`` lines, then ``RUN``."""
        self._session.execute("NEW")
        return self._run(source.rstrip("\n") + "\nRUN")

    def close(self) -> None:
        self._session.close()


def screen_rows(text: str, width: int = 80) -> str:
    """PC-BASIC's captured lines cut into screen rows of ``width`` columns.

    PC-BASIC's text holds logical lines (a row that wraps on its screen is not broken
    in the text); yaseer's gw screen writes one line per row.
    """
    rows = []
    for line in text.split("\n"):
        rows += [line[i:i + width] for i in range(0, len(line), width)] or [""]
    return "\n".join(rows)


def clean_output(text: str) -> str:
    """PC-BASIC screen text as plain lines: ``\\n`` line ends, no cursor NBSP after errors."""
    return text.replace("\r\n", "\n").replace("\xa0", "")


# ---------------------------------------------------------------------------
# Values exact in single precision
# ---------------------------------------------------------------------------

def significant_digits(value: Fraction) -> int:
    """Significant decimal digits of an exact (terminating) rational."""
    text = format(Decimal(value.numerator) / Decimal(value.denominator), "f")
    digits = text.replace("-", "").replace(".", "").lstrip("0").rstrip("0")
    return len(digits) or 1


def exact_single(rng: random.Random, max_digits: int = 7, max_abs: float = 1e7) -> float:
    """A random k / 2**m exact in single precision with at most ``max_digits`` decimal digits."""
    while True:
        shift = rng.choice([0, 0, 0, 1, 2, 3, 4, 5, 6])
        scale = rng.choice([1, 10, 100, 1000, 10_000, 100_000, 1_000_000])
        k = rng.randint(0, scale)
        if rng.random() < 0.4:
            k = -k
        value = Fraction(k, 2 ** shift)
        if abs(k) >= 2 ** 24 or abs(value) >= max_abs:
            continue
        if significant_digits(value) <= max_digits:
            return float(value)


def basic_number(x: float) -> str:
    """A literal both BASICs read exactly (no exponent, full digits)."""
    text = format(Decimal(x), "f")
    if "." in text:
        text = text.rstrip("0").rstrip(".")
    return text or "0"


# ---------------------------------------------------------------------------
# PRINT USING formats
# ---------------------------------------------------------------------------

LITERAL_CHARS = "ABXYZ =:;()/<>*?%@"


def random_literal(rng: random.Random) -> str:
    """Short literal text (no field characters next to one another)."""
    text = "".join(rng.choice(LITERAL_CHARS) for _ in range(rng.randint(1, 3)))
    # An isolated '*' or '$' is literal, but '**' or '$$' would start a field.
    return text.replace("**", "*")


def random_numeric_field(rng: random.Random) -> str:
    """A random numeric field: sign, fill, dollar, digits, commas, point, exponent."""
    exponent = rng.random() < 0.25
    lead = ""
    if rng.random() < 0.2:
        lead = "+"
    if not exponent:
        lead += rng.choice(["", "", "", "**", "$$", "**$"])
    positions = rng.randint(0 if lead == "" else 0, 7)
    whole = "#" * positions
    if not exponent and positions >= 2 and rng.random() < 0.3:
        at = rng.randint(1, positions - 1)
        whole = whole[:at] + "," + whole[at:]
    decimals = rng.randint(0, 4)
    point = rng.random() < 0.7 or (positions == 0 and not lead.strip("+"))
    field = lead + whole + ("." + "#" * decimals if point else "")
    if field.strip("+.") == "":
        field = field.replace(".", "") + "#"
    if exponent:
        field += "^^^^"
    if not lead.startswith("+") and rng.random() < 0.25:
        field += rng.choice("+-")
    return field


def random_string_field(rng: random.Random) -> str:
    """``!``, ``&`` or ``\\ n spaces \\``."""
    return rng.choice(["!", "&", "\\" + " " * rng.randint(0, 4) + "\\"])


def random_format(rng: random.Random) -> tuple[str, list[str]]:
    """A format of 1-3 fields with literals, and its fields' texts."""
    parts: list[str] = []
    fields: list[str] = []
    for _ in range(rng.randint(1, 3)):
        if rng.random() < 0.5:
            parts.append(random_literal(rng))
        field = random_numeric_field(rng) if rng.random() < 0.75 else random_string_field(rng)
        if parts and parts[-1][-1] in "*$":
            # "***$#" or "*+#" are ambiguous; PC-BASIC and yaseer split them differently
            parts[-1] = parts[-1][:-1] + "="
        parts.append(field)
        fields.append(field)
        # a literal between fields keeps them apart (two fields glued may merge)
        parts.append(random_literal(rng) if rng.random() < 0.8 else " ")
    fmt = "".join(parts)
    # PC-BASIC reads a '*' that ends the format as a numeric field (a quirk yaseer does not copy).
    if fmt.endswith("*"):
        fmt = fmt[:-1] + "="
    return fmt, fields


def random_string(rng: random.Random) -> str:
    """A short string without quotes."""
    return "".join(rng.choice("abcXYZ 019-") for _ in range(rng.randint(0, 6)))


def is_string_field(field: str) -> bool:
    """``!``, ``&`` or ``\\ \\``."""
    return field[0] in "!&\\"


def mantissa_digits(field: str) -> int:
    """Digits of a ``^^^^`` field's mantissa: one ``#`` left of the point is the sign's unless ``+``/``-`` is given."""
    whole, _, decimals = field.rstrip("+-^").lstrip("+").partition(".")
    signed = "+" in field or field.endswith("-")
    return max(whole.count("#") - (0 if signed else 1), 0) + decimals.count("#")


def in_pcbasic_rounding_quirk(x: float, field: str) -> bool:
    """Whether PC-BASIC's digit extraction would decide the output (yaseer rounds exactly).

    PC-BASIC rounds a value whose first digit falls one place right of the
    last shown decimal to zero (``PRINT USING "#.#";.0625`` gives ``0.0``),
    and in E notation loses the carry of a mantissa rounded up to the next
    power of ten (``"#.#^^^^"`` of 98.125 gives ``0.1E+02``).
    """
    value = abs(Decimal(x))
    if value == 0:
        return False
    if field.endswith(("^^^^", "^^^^+", "^^^^-")):
        digits = mantissa_digits(field)
        if digits == 0:
            return True
        quantum = Decimal(1).scaleb(value.adjusted() - digits + 1)
        return value.quantize(quantum, rounding="ROUND_HALF_UP").adjusted() > value.adjusted()
    decimals = field.partition(".")[2].count("#")
    return Decimal("0.5").scaleb(-decimals) <= value < Decimal(1).scaleb(-decimals)


def random_using_case(rng: random.Random) -> tuple[str, list[float | str]]:
    """A format and 1-5 values that fit its fields' kinds (cycling through them)."""
    fmt, fields = random_format(rng)
    values: list[float | str] = []
    for i in range(rng.randint(1, 5)):
        field = fields[i % len(fields)]
        if is_string_field(field):
            values.append(random_string(rng))
            continue
        x = exact_single(rng)
        while in_pcbasic_rounding_quirk(x, field):
            x = exact_single(rng)
        values.append(x)
    return fmt, values


def basic_value(value: float | str) -> str:
    """A value as a BASIC literal."""
    if isinstance(value, str):
        return '"' + value + '"'
    return basic_number(value)


def using_statement(fmt: str, values: list[float | str]) -> str:
    """``PRINT USING "fmt"; v1; v2 ...``"""
    return f'PRINT USING "{fmt}"; ' + "; ".join(basic_value(v) for v in values)


# ---------------------------------------------------------------------------
# Running yaseer in-process, comparing outputs
# ---------------------------------------------------------------------------

def core(dialect):
    """``dialect`` without a machine's own words: casio without the FX-850P's (its LOG is the
    common logarithm, ERR the manual's codes, MOD and HEX$ the manual's ...: checked on
    the manual's pages in tests/test_casio_words.py), so the MS-BASIC core casio shares
    with GW-BASIC can be compared with PC-BASIC.  gw passes through."""
    from yaseer.basic.dialects.dialect import get_dialect

    d = get_dialect(dialect)
    return d._replace(words=None, names_keep_case=False, name_length=None, hex_literals=False) if d.words else d


def run_yaseer(source: str, angle: str | None = "rad", dialect: str = "casio") -> str:
    """yaseer's screen output for ``source``, then its error line (as PC-BASIC shows it).

    ``dialect`` "casio" or "gw"; ``angle`` None takes the dialect's own unit.
    """
    import io

    from yaseer.basic.errors import BasicError
    from yaseer.basic.machine.machine import Machine

    screen = io.StringIO()
    machine = Machine(screen=screen, angle=angle, dialect=core(dialect))
    try:
        machine.load(source)
        outcome = machine.run()
    except BasicError as err:
        machine.end_line()
        machine.flush()
        return screen.getvalue() + str(err) + "\n"
    if outcome == "stop":  # `yaseer run` reports STOP as "Break in N" (on standard error)
        machine.end_line()
        return screen.getvalue() + f"Break in {machine.line}\n"
    return screen.getvalue()


def run_gw(source: str) -> str:
    """yaseer's screen for ``source`` in ``--dialect gw`` (the dialect's own angle unit)."""
    return run_yaseer(source, angle=None, dialect="gw")


def gw_programs_differing(pc, make, count: int, mark: str | None = None, tail: int | None = None):
    """Run ``count`` programs ``make()`` in PC-BASIC session ``pc`` and in yaseer's gw:
    ([(source, PC-BASIC's output, yaseer's)] where they differ, the outputs cut to their
    last ``tail`` characters; how many of PC-BASIC's outputs hold ``mark``)."""
    bad, marked = [], 0
    for _ in range(count):
        source = make()
        pc.statement("ON ERROR GOTO 0")
        theirs, ours = pc.program(source), run_gw(source)
        marked += mark is not None and mark in theirs
        if theirs != ours:
            bad.append((source, theirs[-tail:] if tail else theirs, ours[-tail:] if tail else ours))
    return bad, marked


def run_direct(text: str, dialect: str = "gw") -> str:
    """yaseer's output for one statement typed in direct mode, then its error line if it fails
    (as PC-BASIC shows a direct statement)."""
    import io

    from yaseer.basic.errors import BasicError
    from yaseer.basic.machine.machine import Machine

    screen = io.StringIO()
    machine = Machine(screen=screen, dialect=core(dialect))
    try:
        machine.execute_direct(text)
    except BasicError as err:
        machine.end_line()
        return screen.getvalue() + str(err) + "\n"
    return screen.getvalue()


NUMBER = re.compile(r"-?(?:\d+\.?\d*|\.\d+)(?:[ED][-+]\d+)?")  # D: GW-BASIC's double exponent


def numbers_and_text(output: str) -> tuple[list[float], str]:
    """The numbers of an output and its text with numbers replaced by ``#`` and blanks collapsed."""
    numbers = [float(m.replace("D", "E")) for m in NUMBER.findall(output)]
    text = " ".join(NUMBER.sub("#", output).split())
    return numbers, text


def outputs_agree(ours: str, theirs: str, tolerant: bool) -> bool:
    """Byte equality, or (``tolerant``) the same text and numbers within 1e-6 relative.

    The absolute floor of 1e-6 covers values that single precision cancels to
    noise in GW-BASIC (e.g. COS of an angle near 90 degrees).
    """
    if ours == theirs:
        return True
    if not tolerant:
        return False
    our_numbers, our_text = numbers_and_text(ours)
    their_numbers, their_text = numbers_and_text(theirs)
    if our_text != their_text or len(our_numbers) != len(their_numbers):
        return False
    return all(math.isclose(a, b, rel_tol=1e-6, abs_tol=1e-6) for a, b in zip(our_numbers, their_numbers))
