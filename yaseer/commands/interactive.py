"""``yaseer`` with no arguments: the pocket computer's interactive session.

Only terminal I/O lives here: reading lines (with prompt_toolkit's line editing
and history when stdin and stdout are a terminal, plain ``readline`` otherwise)
and handing them to :class:`yaseer.session.Session`, which does the rest.
Ctrl-C at the prompt drops the line being typed; Ctrl-C while a program runs
is ``Break in <line>`` (the machine places it) and CONT goes on; Ctrl-D or
``SYSTEM`` leaves.
"""

from __future__ import annotations

import sys

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only: typing is not imported at run time (every command loads this module)
    from typing import Callable

    Reader = Callable[[str, str], str]  # (prompt, text put up for editing) -> the line typed

BANNER = (
    "yaseer - the Al-Yaseer pocket computer. PROG 1, 2, 3 and 5 hold the library programs.\n"
    "Type numbered lines to store them (AUTO numbers them); LIST, RUN, CONT, NEW, DELETE, RENUM, EDIT,\n"
    "LOAD, SAVE, PROG n, TRON; "
    "HELP lists the commands; SYSTEM (or Ctrl-D) leaves.\n"
)


CLEAR_SCREEN = "\x1b[H\x1b[2J"  # CLS on a terminal: cursor home, erase the screen


def add_arguments(parser) -> None:
    """``yaseer`` alone (or ``yaseer --dialect gw``) starts the session: ``--dialect``, ``--printer``."""
    from yaseer.commands.parsers import add_dialect_argument

    add_dialect_argument(parser)
    parser.add_argument("--printer", metavar="FILE",
                        help="the session's printer: LPRINT and LLIST append to FILE (default: the screen)")
    parser.add_argument("--width", type=_width, metavar="N",
                        help="a screen N columns wide (16-255): longer lines go on on the next row, "
                             "as on the pocket computer's display (the FX-850P's: 32)")


def _width(text: str) -> int:
    import argparse

    if not text.isdigit() or not 16 <= int(text) <= 255:
        raise argparse.ArgumentTypeError(f"the width is a whole number of columns from 16 to 255, not {text!r}")
    return int(text)


def main(args=None) -> int:
    """Run the session on this terminal until SYSTEM or end of input."""
    from yaseer.session import FoldedScreen, MachineEngine, Session

    write = _writer(sys.stdout)
    width = getattr(args, "width", None)
    if width:
        write = FoldedScreen(write, width)
    dialect = getattr(args, "dialect", None) or "casio"
    printer = _printer(getattr(args, "printer", None))
    if printer is None and getattr(args, "printer", None):
        return 1
    terminal = _is_terminal()
    engine = MachineEngine(write, dialect=dialect, printer=printer,
                           clear_screen=(lambda: write(CLEAR_SCREEN)) if terminal else None)
    session = Session(write=write, engine=engine, printer=printer, dialect=dialect)
    read = prompt_toolkit_reader() if terminal else plain_reader(sys.stdin, write)
    write(BANNER)
    # on a terminal Enter starts a new row; from a pipe nothing is echoed and output goes on after the prompt
    return run_loop(session, read, write, line_typed=getattr(write, "line_typed", None) if terminal else None)


def _printer(path: str | None) -> Callable[[str], None] | None:
    """A writer appending to ``path`` (flushed at every write), or None (no path, or it cannot be
    opened); a write that fails (a full disk, /dev/full) is ``Device I/O error`` (57), a BASIC
    error of the statement that printed (LPRINT, LLIST), which a program may trap."""
    if not path:
        return None
    try:
        stream = open(path, "a", encoding="utf-8")  # noqa: SIM115 - open for the whole session
    except OSError as error:
        print(f"Cannot open the printer file {path}: {error.strerror}", file=sys.stderr)
        return None
    write = _writer(stream)

    def printed(text: str) -> None:
        try:
            write(text)
        except OSError:
            from yaseer.basic.errors import DEVICE_IO_ERROR, error_for

            raise error_for(DEVICE_IO_ERROR) from None

    return printed


def run_loop(session, read: Reader, write: Callable[[str], object],
             line_typed: Callable[[], object] | None = None) -> int:
    """Prompt, read, handle, until the session finishes or input ends; ``line_typed`` is
    told when a line was read (the cursor is then at the start of a row)."""
    while not session.finished:
        try:
            text = read(session.prompt, session.edit_text or "")
            if line_typed is not None:
                line_typed()
        except KeyboardInterrupt:  # Ctrl-C at the prompt: forget the line (and leave AUTO)
            session.interrupt()
            write("\n")
            continue
        except EOFError:
            write("\n")
            break
        try:
            session.handle(text)
        except KeyboardInterrupt:  # a break the machine did not place at a line
            write("Break\n")
    return 0


def _writer(stream) -> Callable[[str], None]:
    def write(text: str) -> None:
        stream.write(text)
        stream.flush()

    return write


def _is_terminal() -> bool:
    try:
        return sys.stdin.isatty() and sys.stdout.isatty()
    except (AttributeError, ValueError):
        return False


def prompt_toolkit_reader() -> Reader:
    """Line editing (cursor keys, Emacs keys) and history (up/down) from prompt_toolkit."""
    from prompt_toolkit import PromptSession
    from prompt_toolkit.history import InMemoryHistory

    prompt_session = PromptSession(history=InMemoryHistory())

    def read(prompt: str, default: str) -> str:
        # Ctrl-C typed at the prompt is a key (the terminal is in raw mode); prompt_toolkit's
        # own SIGINT handler is not wanted: a Ctrl-C pressed just after Enter would reach it
        # after the line was accepted and print a traceback instead of breaking the program.
        return prompt_session.prompt(prompt, default=default, handle_sigint=False)

    return read


def plain_reader(stream, write: Callable[[str], object]) -> Reader:
    """Lines from a pipe or file: no editing; an EDIT line is shown to be retyped."""

    def read(prompt: str, default: str) -> str:
        if default:
            write(default + "\n")
        write(prompt)
        line = stream.readline()
        if not line:
            raise EOFError
        return line.rstrip("\r\n")

    return read
