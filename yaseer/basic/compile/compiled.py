"""The compiled form of one program area (what ``compiler.compile_area`` returns).

Kept apart from the compiler so that a program read back from the on-disk cache
(:mod:`yaseer.basic.compile.program_cache`) needs neither the parser nor the compiler.
"""

from __future__ import annotations

MAX_STACK = 10_000  # GOSUB returns + open FOR loops (machine.MAX_STACK)


class CompiledArea:
    """The compiled form of one program area.

    ``source`` the generated Python text; ``pieces`` [(first BASIC line or None,
    source of one function)]; ``line_blocks`` BASIC line -> block starting there;
    ``block_next`` block -> block of the statement after it (RESUME NEXT);
    ``data`` [(DATA item text, line)]; ``data_lines`` line -> index of its first
    item; ``scalars`` every scalar name used; ``blocks`` the block functions
    (filled in by the machine after it executes the source).

    Where Ctrl-C may stop a run so that CONT resumes it exactly:
    ``index_blocks`` statement index -> the block starting there;
    ``break_points`` block -> {line of its Python function: (BASIC line,
    loops)}: the ``continue`` of a block looping to its own start (loops
    ``()``: resume the block) and the top of each pass of a native FOR loop
    (loops: ``(FOR index, FOR-stack key, temporary number, mode, Python local
    of the variable or None)`` for each native loop open there, outermost
    first); ``dynamic_loops`` the FOR indices this compile was told to run
    through the FOR stack.  ``def_types`` letter -> type character after the
    area's DEFINT/DEFSNG/DEFDBL/DEFSTR (gw; direct statements start from it);
    ``dynamic_types`` those statements switch the type table as they run (the machine
    then runs the area compiled for each table it reaches: ``variants``, table -> blocks).
    ``makings`` block -> the simple variables its statements make, where the machine counts
    each making (gw: compiler.made; the block's flag ``_f<block>`` is true while one of
    them is not made).
    """

    FIELDS = ("source", "pieces", "block_count", "line_blocks", "block_next", "data", "data_lines",
              "scalars", "first_line", "index_blocks", "break_points", "dynamic_loops", "def_types",
              "dynamic_types", "makings")

    def __init__(self, source, pieces, block_count, line_blocks, block_next, data, data_lines,
                 scalars, first_line=None, index_blocks=None, break_points=None, dynamic_loops=(),
                 def_types=None, dynamic_types=False, makings=None):
        self.source, self.pieces, self.block_count = source, pieces, block_count
        self.line_blocks, self.block_next = line_blocks, block_next
        self.data, self.data_lines, self.scalars = data, data_lines, scalars
        self.first_line = first_line
        self.index_blocks = index_blocks or {}
        self.break_points = break_points or {}
        self.dynamic_loops = dynamic_loops
        self.def_types = def_types or {}
        self.dynamic_types = dynamic_types
        self.makings = makings or {}
        self.blocks: list = []
        self.variants: dict = {}

    def as_plain(self) -> tuple:
        """The fields as plain Python data (what ``marshal`` can store)."""
        return tuple(getattr(self, name) for name in self.FIELDS)

    @classmethod
    def from_plain(cls, fields: tuple) -> "CompiledArea":
        """The inverse of :meth:`as_plain`."""
        return cls(*fields)
