"""How numbers and strings appear on the screen: PRINT, STR$ and PRINT USING.

(Placeholder implementation: the interface is final, the rules are being
completed to Microsoft BASIC semantics.)
"""

from __future__ import annotations

from typing import Sequence

SIGNIFICANT_DIGITS = 10  # a 10-digit pocket-computer display


def str_dollar(x: float) -> str:
    """STR$(x): a leading space (or minus), up to 10 significant digits, no trailing space."""
    text = f"{x:.{SIGNIFICANT_DIGITS}g}"
    if text.endswith(".0"):
        text = text[:-2]
    return text if text.startswith("-") else " " + text


def number_to_text(x: float) -> str:
    """How PRINT shows a number: STR$ form plus a trailing space."""
    return str_dollar(x) + " "


def using(fmt: str, values: Sequence[float | str]) -> str:
    """PRINT USING fmt; values — the text printed (no newline)."""
    raise NotImplementedError
