"""Helpers for the BASIC machine tests: run a program text, capture what it prints."""

from __future__ import annotations

import csv
import io

from yaseer.basic.machine.machine import Machine


def run_text(program: str, **options) -> str:
    """Run ``program`` in text mode; the screen output."""
    screen = io.StringIO()
    machine = Machine(screen=screen, **options)
    machine.load(program)
    machine.run()
    return screen.getvalue()


def run_rows(program: str, **options) -> list[list[str]]:
    """Run ``program`` in csv mode; one list of strings per PRINT statement."""
    screen = io.StringIO()
    machine = Machine(screen=screen, output_format="csv", **options)
    machine.load(program)
    machine.run()
    return list(csv.reader(io.StringIO(screen.getvalue())))


def run_values(program: str, **options) -> list[list]:
    """Like run_rows, numbers converted back to float."""
    out = []
    for row in run_rows(program, **options):
        converted = []
        for cell in row:
            try:
                converted.append(float(cell))
            except ValueError:
                converted.append(cell)
        out.append(converted)
    return out


def error_of(program: str, setup=None, **options) -> str:
    """The one-line error a program stops with."""
    from yaseer.basic.errors import BasicError

    options.setdefault("input_stream", io.StringIO(""))
    machine = Machine(screen=io.StringIO(), **options)
    machine.load(program)
    if setup:
        setup(machine)
    try:
        machine.run()
    except BasicError as err:
        return str(err)
    raise AssertionError("the program ran without an error")
