"""The arguments of a run, checked once: by :func:`yaseer.run`, the ``%%basic`` magic and the command line.

Each check takes the value as a caller gives it and returns it ready to use,
or raises :class:`ArgumentError` (a ``ValueError``) whose text is the whole
one-line message.  The command line shows that message as a usage error
(``--prog``, ``--method``) or an error naming the file (an area's text); the
API raises it; the magic shows it as one line.  Nothing is imported here
beyond ``os`` and ``math`` (every ``yaseer run`` imports this module).
"""

from __future__ import annotations

import math
import os
from yaseer.patterns import Pattern

AREAS = range(1, 10)  # program areas a listing may fill (area 0 is the listing itself)
DIALECTS = ("casio", "gw")
ANGLES = ("deg", "rad")
OUTPUT_FORMATS = ("text", "csv")
MIN_FRAME_SIZE, MAX_FRAME_SIZE = (160, 120), (7680, 4320)  # pixels: a thumbnail to 8K


class ArgumentError(ValueError):
    """An argument of a run that is refused; its text is the whole message."""


def area_number(value: object, shown: object = None) -> int:
    """Program area ``value`` (an int, or its digits) as an int in 1-9.

    ``shown`` is how the caller wrote it, for the message (default: ``value``).
    """
    shown = value if shown is None else shown
    if isinstance(value, str) and value.strip().isdigit():
        value = int(value)
    if not isinstance(value, int) or isinstance(value, bool):
        raise ArgumentError(f"program areas are the numbers 1-9, got {shown!r}")
    if value == 0:
        raise ArgumentError(f"area 0 is the listing itself; program areas are 1-9, got {shown!r}")
    if value not in AREAS:
        raise ArgumentError(f"program areas are 1-9, got {shown!r}")
    return value


_STRINGS = Pattern(r'"[^"]*("|$)')


def area_text(number: int, text: str) -> str:
    """The BASIC text of program area ``number``, refused when it holds no numbered line or no
    RETURN (``GOSUB PROG n`` could never come back); the message does not name the area."""
    from yaseer.basic.errors import BasicError
    from yaseer.basic.source.scanner import split_lines

    try:
        lines = [statement for _, statement, _ in split_lines(text) if statement]
    except BasicError as error:
        raise ArgumentError(str(error)) from None
    if not lines:
        raise ArgumentError("the file holds no numbered program lines")
    if not any("RETURN" in _STRINGS.sub("", line).upper() for line in lines):
        raise ArgumentError(f"no RETURN, so GOSUB PROG {number} could never come back")
    return text


def method_choice(number: object, name: object) -> tuple[int, str]:
    """``(program, method name)`` checked against the method registry."""
    if isinstance(number, str) and number.strip().isdigit():
        number = int(number)
    known = method_choices()
    if not isinstance(number, int) or isinstance(number, bool) or number not in known:
        raise ArgumentError(
            f"no library program {number!r} to choose a method for (programs: {', '.join(map(str, known))})")
    if not isinstance(name, str) or name.strip() not in known[number]:
        raise ArgumentError(f"unknown method {name!r} for PROG {number} (known: {', '.join(known[number])})")
    return number, name.strip()


def method_choices() -> dict[int, list[str]]:
    """Program number -> its method names, the default first (from ``yaseer.linkages.registry``)."""
    from yaseer.binding import LINKAGES
    from yaseer.linkages.registry import default_method, method_names

    choices = {}
    for number, linkage in LINKAGES.items():
        names = method_names(linkage)
        default = default_method(linkage)
        choices[number] = [default] + [n for n in names if n != default]
    return choices


def dialect_choice(value: object) -> object:
    """A dialect name (``"casio"`` when None) or a ``Dialect`` object, as given."""
    if value is None:
        return "casio"
    if isinstance(value, str):
        if value.lower() not in DIALECTS:
            raise ArgumentError(f"unknown dialect {value!r} (choose from {', '.join(DIALECTS)})")
        return value
    from yaseer.basic.dialects.dialect import Dialect

    if isinstance(value, Dialect):
        return value
    raise ArgumentError(f"a dialect is one of {', '.join(DIALECTS)}, not {value!r}")


def choice(what: str, value: object, choices: tuple, none_allowed: bool = True) -> object:
    """``value`` if it is one of ``choices`` (or None when allowed); the message names ``what``."""
    if (value is None and none_allowed) or (isinstance(value, str) and value in choices):
        return value
    raise ArgumentError(f"{what} is one of {', '.join(choices)}, not {value!r}")


def angle_choice(value: object) -> str | None:
    """``"deg"``, ``"rad"`` or None (the dialect's unit)."""
    return choice("angle", value, ANGLES)


def output_format_choice(value: object) -> str:
    """``"text"`` or ``"csv"``."""
    return choice("output_format", value, OUTPUT_FORMATS, none_allowed=False)


def files_directory(value: object) -> str | None:
    """The directory of the program's files (None: the current one); it must exist."""
    if value is None:
        return None
    if not isinstance(value, (str, os.PathLike)):
        raise ArgumentError(f"files is the path of a directory, not {type(value).__name__} {value!r}")
    path = os.fspath(value)
    if not isinstance(path, str):
        raise ArgumentError(f"files is the path of a directory, not {value!r}")
    if not os.path.isdir(path):
        raise ArgumentError(f"{path}: no such directory" if not os.path.exists(path)
                            else f"{path}: not a directory")
    return path


def typed_line(value: object) -> str:
    """The line typed at the prompt that started the program: one line of text."""
    if not isinstance(value, str) or "\n" in value or "\r" in value:
        raise ArgumentError(f"typed is one line of text, not {value!r}")
    return value


def frames_per_second(value: object) -> float:
    """Frames a second of an animation: a finite positive number."""
    try:
        fps = float(value)
    except (TypeError, ValueError):
        raise ArgumentError(f"Frames per second must be a positive number, not {value!r}") from None
    if not (math.isfinite(fps) and fps > 0):
        raise ArgumentError(f"Frames per second must be a positive number, not {value!r}")
    return fps


def frame_size(value: object) -> tuple[int, int]:
    """A frame size in pixels, ``"WxH"`` or ``(W, H)``, from 160x120 to 7680x4320."""
    if isinstance(value, str):
        width, _, height = value.lower().partition("x")
        if not (width.strip().isdigit() and height.strip().isdigit()):
            raise ArgumentError(f"expected WIDTHxHEIGHT in pixels, got {value!r}")
        width, height = int(width), int(height)
    elif isinstance(value, tuple) and len(value) == 2 and all(isinstance(v, int) for v in value):
        width, height = value
    else:
        raise ArgumentError(f"a frame size is WIDTHxHEIGHT in pixels, not {value!r}")
    if not (MIN_FRAME_SIZE[0] <= width <= MAX_FRAME_SIZE[0] and MIN_FRAME_SIZE[1] <= height <= MAX_FRAME_SIZE[1]):
        raise ArgumentError(f"A frame size must be from {MIN_FRAME_SIZE[0]}x{MIN_FRAME_SIZE[1]} to "
                            f"{MAX_FRAME_SIZE[0]}x{MAX_FRAME_SIZE[1]} pixels, not {width}x{height}")
    return width, height


def max_frames(value: object) -> int:
    """How many frames an animation shows at most: an int (or its digits) of at least 2."""
    if isinstance(value, str) and value.strip().isdigit():
        value = int(value)
    if not isinstance(value, int) or isinstance(value, bool) or value < 2:
        raise ArgumentError(f"an animation shows at least 2 frames, not {value!r}")
    return value
