"""Where ``GOTO "file:label"`` and ``GOSUB "file:label"`` find the program they run.

The FX-850P/880P keeps programs in named files; Becker's library for it calls its
subprograms as ``GOSUB "LIB0:S6210"`` and its menu starts a program with
``GOTO "LIB0:5250"``: entry ``label`` of the library file ``LIB0``, which his
library keeps as one program file each, ``LIB<label>.bas`` (``LIBS6210.bas``,
``LIB5250.bas``).  yaseer finds every program file in the program's one directory
(``--files DIR``, the sandbox of OPEN and KILL):

* ``"LIB0:label"``: the file ``LIB<label>.bas``;
* ``"name"`` or ``"name:"``: the file ``name``, else ``name.bas``.

A program file is read as UTF-8, or in the machine's character codes when it is not
UTF-8 (a file saved on the machine: yaseer/basic/dialects/charset.py).
"""

from __future__ import annotations

from yaseer.basic.errors import BasicError, FILE_NOT_FOUND

LIBRARY_FILE = "LIB0"  # the library's file name in its calls
LIBRARY_PREFIX = "LIB"  # ... and the start of its program files' names


def candidates(name: str) -> list[str]:
    """The file names ``"file:label"`` may mean, in the order they are tried."""
    file, _, label = name.partition(":")
    file, label = file.strip(), label.strip()
    if file.upper() == LIBRARY_FILE and label:
        return [f"{LIBRARY_PREFIX}{label}.bas", f"{LIBRARY_PREFIX}{label}.BAS"]
    if label or not file:
        raise BasicError(f"File not found: {name}", FILE_NOT_FOUND)
    return [file, f"{file}.bas", f"{file}.BAS"]


def read_program(name: str, sandbox, charset) -> str:
    """The text of the program file ``name`` names, from ``sandbox``'s directory."""
    for candidate in candidates(name):
        try:
            return charset.program_text(sandbox.read_bytes(candidate))
        except BasicError as error:
            if error.code != FILE_NOT_FOUND:
                raise
    raise BasicError(f"File not found: {name}", FILE_NOT_FOUND)
