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
from typing import Callable

BANNER = (
    "yaseer - the Al-Yaseer pocket computer. PROG 1, 2, 3 and 5 hold the library programs.\n"
    "Type numbered lines to store them; LIST, RUN, CONT, NEW, DELETE, RENUM, EDIT, LOAD, SAVE, PROG n;\n"
    "HELP lists the commands; SYSTEM (or Ctrl-D) leaves.\n"
)

Reader = Callable[[str, str], str]  # (prompt, text put up for editing) -> the line typed


def add_arguments(parser) -> None:
    """``yaseer`` alone (or ``yaseer --dialect gw``) starts the session: ``--dialect``."""
    from yaseer.commands.options import add_dialect_argument

    add_dialect_argument(parser)


def main(args=None) -> int:
    """Run the session on this terminal until SYSTEM or end of input."""
    from yaseer.session import MachineEngine, Session

    write = _writer(sys.stdout)
    dialect = getattr(args, "dialect", None) or "casio"
    session = Session(write=write, engine=MachineEngine(write, dialect=dialect))
    read = prompt_toolkit_reader() if _is_terminal() else plain_reader(sys.stdin, write)
    write(BANNER)
    return run_loop(session, read, write)


def run_loop(session, read: Reader, write: Callable[[str], object]) -> int:
    """Prompt, read, handle, until the session finishes or input ends."""
    while not session.finished:
        try:
            text = read(session.prompt, session.edit_text or "")
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
        return prompt_session.prompt(prompt, default=default)

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
