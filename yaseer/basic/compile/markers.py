"""Lines of a block's generated code that only the whole block can write.

While a statement is compiled its block does not yet know all its variables: which
scalars it keeps in locals, which arrays it binds, whether it must test a full GOSUB stack
each time.  A statement that needs one of those writes a marker line instead, and
``AreaCompiler.block_source`` replaces each marker with the block's own text when the
block is done.

A marker is a ``str`` (as :class:`loops.LoopSplit` is), so everything that reads a block's
code as text (sizes, searches for calls) keeps working; its text starts with ``#``, a
Python comment, and ``block_source`` refuses any plain comment line, so a marker can never
be left in the source by mistake as a silent no-op.
"""

from __future__ import annotations


class Marker(str):
    """A line ``block_source`` replaces with text of the finished block."""

    def __new__(cls, text: str):
        return super().__new__(cls, text)


class StoreLocals(Marker):
    """Store the block's written locals in the machine's scalars (before code that reads
    or changes them through the machine: a call, FIELD, CHAIN, a DEF FN)."""


class LoadLocals(Marker):
    """Read the block's locals and arrays back from the machine (after such code)."""


class StackCheck(Marker):
    """A GOSUB done in place tests for a full stack: once per block where the stack's
    length cannot change while it runs, else each time."""


class ArraysCall(Marker):
    """A call that returns whether the arrays may have changed: the block's arrays bound
    again only then, its locals read back always."""

    def __new__(cls, call: str):
        line = super().__new__(cls, "#call " + call)
        line.call = call
        return line


class Dimensioned(Marker):
    """An array just made by DIM: bound again if the block uses it."""

    def __new__(cls, name: str):
        line = super().__new__(cls, "#dim " + name)
        line.name = name
        return line


class PassTop(Marker):
    """The top of a native loop's pass, where a Ctrl-C may stop it (CONT resumes it):
    ``index`` into the compiler's ``break_infos``."""

    def __new__(cls, index: int):
        line = super().__new__(cls, f"#pass {index}")
        line.index = index
        return line


class Refreshing(str):
    """A code line (a making's test, compiler.made) after which the block reads its flag
    and arrays again: ``block_source`` appends that reading to ``code``, after ``; ``."""

    def __new__(cls, code: str):
        line = super().__new__(cls, code + "; #refresh")
        line.code = code
        return line


STORE_LOCALS = StoreLocals("#store locals")
LOAD_LOCALS = LoadLocals("#load locals")
STACK_CHECK = StackCheck("#stack check")
