"""argparse parsers built from the commands' option tables (:mod:`yaseer.commands.options`).

Imported only when a command line needs argparse: ``--help``, a usage error, a
form the fast scanner leaves to argparse, or a command without a table (every
command but ``run``, whose parsers add the shared run options from their table).
Each :class:`~yaseer.commands.options.Option` becomes exactly one ``add_argument``
call, so the help, the usage line and every error message come from argparse.
"""

from __future__ import annotations

import argparse
import functools

from yaseer.commands.options import DIALECT, RUN_OPTIONS, Option, OptionValueError
from yaseer.run_arguments import ArgumentError

TYPE_CHECKING = False
if TYPE_CHECKING:  # annotations only
    from typing import Sequence


def add_dialect_argument(parser) -> None:
    """``--dialect`` on an argparse parser (the interactive session's)."""
    add_option(parser, DIALECT)


def add_run_options(parser) -> None:
    """:data:`~yaseer.commands.options.RUN_OPTIONS` on an argparse parser (a command other than ``run``,
    whose table holds them)."""
    add_groups(parser, (RUN_OPTIONS,))


def add_groups(parser: argparse.ArgumentParser, groups: Sequence[tuple[str | None, Sequence[Option]]]) -> None:
    """Add a table's options to ``parser``: each titled group as an argument group, untitled ones directly."""
    for title, options in groups:
        target = parser if title is None else parser.add_argument_group(title)
        for option in options:
            add_option(target, option)


def add_option(parser, option: Option) -> None:
    """``option`` as one ``add_argument`` of ``parser`` (a parser or an argument group)."""
    if callable(option.help):
        action = _ComputedHelpAppend if option.repeated else _ComputedHelpStore
    else:
        action = "append" if option.repeated else "store"
    parser.add_argument(option.flag, action=action, help=option.help, metavar=option.metavar,
                        type=_argparse_type(option.convert) if option.convert is not None else None,
                        choices=option.choices, default=[] if option.repeated else option.default)


def checked(check):
    """An argparse ``type`` converting with ``check``, one of :mod:`yaseer.run_arguments` (the checks
    the API and the magic make): a value it refuses is a usage error with its message."""
    return _argparse_type(check, ArgumentError)


def _argparse_type(convert, shown=OptionValueError):
    """``convert`` for argparse: the text of a ``shown`` error is shown as the whole message
    (argparse's ``ArgumentTypeError``); any other ValueError as argparse's ``invalid NAME value``."""

    @functools.wraps(convert)
    def converted(text: str):
        try:
            return convert(text)
        except shown as error:
            raise argparse.ArgumentTypeError(str(error)) from None

    return converted


class _ComputedHelp:
    """An action whose help is a function, called only when the help is shown (``--method``'s lists
    every program's methods, which imports the numerics; a plain ``yaseer run`` must not)."""

    @property
    def help(self) -> str:
        return self._help() if callable(self._help) else self._help

    @help.setter
    def help(self, value) -> None:
        self._help = value


class _ComputedHelpStore(_ComputedHelp, argparse._StoreAction):
    """``store`` with a computed help."""


class _ComputedHelpAppend(_ComputedHelp, argparse._AppendAction):
    """``append`` with a computed help."""
