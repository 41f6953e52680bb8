"""The graphics statements (gw: source/graphics_syntax.py reads them into
:class:`~yaseer.basic.source.syntax_tree.Graphics` nodes) compiled into calls of the
machine's graphics (machine/graphics_words.py).

The compiled code first asks the machine whether the statement may run in the screen mode
(``_M.graphics.check``: PSET, VIEW, WINDOW, GET and PUT are Illegal function call in the
text mode, whatever their text: the recorded PSET and WINDOW tests), then evaluates
the pieces in the order GW reads them (a string where a number must be raises Type
mismatch there), then hands them and the text's error to ``_M.graphics.run``.
"""

from __future__ import annotations

from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.compile.expressions import _temporary, _used_at_once
from yaseer.basic.compile.markers import LOAD_LOCALS, STORE_LOCALS

# the words that check the screen mode before they read anything
# (LINE reads its points first: GENGRP.ASM GLINE scans them before ATRSCN asks GETFBC for the
# graphics colours, so ``LINE`` alone is Syntax error in the text mode; CIRCLE checks first: the
# recorded CIRCLE test; DRAW: ADVGRP.ASM DRAW asks PIXSIZ first; PAINT as they)
CHECKS_MODE_FIRST = frozenset(("PSET", "PRESET", "VIEW", "WINDOW", "GET", "PUT", "CIRCLE", "PAINT", "DRAW"))


class GraphicsCompiler:
    """The mixin of AreaCompiler for :class:`ast.Graphics`."""

    def stmt_Graphics(self, stmt, scope):
        if stmt.word in CHECKS_MODE_FIRST:
            self.emit(f"_M.graphics.check({stmt.word!r})")
        codes = []
        arrays = False
        for part in stmt.parts:
            kind = part[0]
            if kind == "xy":
                x = self.when_reached(lambda node=part[2]: self.numeric(node, scope))
                y = self.when_reached(lambda node=part[3]: self.numeric(node, scope))
                codes.append(f"({part[1]!r}, {x}, {y})")
            elif kind == "n":
                codes.append("None" if part[1] is None
                             else self.when_reached(lambda node=part[1]: self.numeric(node, scope)))
            elif kind == "x":  # a number or a string (PAINT's tile, DRAW's string)
                node = part[1]
                if node is None:
                    codes.append("None")
                else:
                    codes.append(self.when_reached(lambda node=node: self.either(node, scope)))
            elif kind == "w":
                codes.append(repr(part[1]))
            else:  # an array: its full name and the subscripts of an element
                arrays = True
                node = part[1]
                if not isinstance(node, (ast.Var, ast.Elem)):
                    codes.append("_fail('Type mismatch', 13)")
                    continue
                name = repr(self.numbers.name(node.name))
                if isinstance(node, ast.Elem):
                    subscripts = "(" + "".join(self.numeric(i, scope) + ", " for i in node.indices) + ")"
                else:
                    subscripts = "None"
                codes.append(f"({name}, {subscripts})")
        error = stmt.error
        fault = "None" if error is None else f"({error.message!r}, {error.code}, {stmt.after!r})"
        if arrays:
            self.emit(STORE_LOCALS)
        self.emit(f"_M.graphics.run({stmt.word!r}, ({''.join(c + ', ' for c in codes)}), {fault})")
        if arrays:
            self.emit(LOAD_LOCALS)

    def either(self, node, scope) -> str:
        """A number or a string a statement uses up (PAINT's tile, DRAW's string): a new
        string gives its bytes back at once (the recorded PAINTSTR test: FRE(0) after
        ``PAINT (x, y), "a" + "b"`` is what it was before)."""
        if self.type_of(node) != "s":
            return self.numeric(node, scope)
        code = self.string(node, scope)
        if self.counts_strings and _temporary(node, self.numbers.kind):
            code = _used_at_once(node, code)
        return code
