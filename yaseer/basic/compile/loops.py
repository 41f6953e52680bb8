"""FOR ... NEXT -> Python: the loop half of the area compiler (``AreaCompiler`` in
compiler.py mixes it in).

A FOR whose NEXT the plan (blocks.py) finds with no jump into or out of the body
becomes a native Python loop (:meth:`LoopCompiler.native_loop`), run in the way
:meth:`LoopCompiler.loop_mode` picks; any other FOR pushes a frame on the FOR stack
and its NEXT steps through it (``stmt_For``, ``stmt_Next``).
"""

from __future__ import annotations

from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.compile.blocks import nodes, walk_statements
from yaseer.basic.compile.expressions import BlockScope, CompileError, constant_value, syntax_error, type_mismatch
from yaseer.basic.compile.markers import LOAD_LOCALS, STORE_LOCALS, PassTop
from yaseer.basic.compile.number_models import local_name
from yaseer.basic.errors import FOR_WITHOUT_NEXT, NEXT_WITHOUT_FOR, BasicError


class LoopSplit(str):
    """A native loop's first line in a block's code that may run in two loops
    (LoopCompiler.unchecked_passes): its text, as any line of the code for what reads it
    (sizes, searches), and its parts, from which compiler._passes writes the two loops
    without reading the text back.  ``key``: ``<block>_<n>``, its flag ``_f<key>``; ``n``
    its temporaries' number; ``arrays`` those its body makes (bound again between the
    loops); ``target`` and ``items`` of ``for target in items:``, or ``target`` None and
    ``items`` the test of ``while items:``."""

    def __new__(cls, text: str, key: str, n: str, arrays: tuple, target: str | None, items: str):
        line = super().__new__(cls, text)
        line.key, line.n, line.arrays, line.target, line.items = key, n, arrays, target, items
        return line


class LoopCompiler:
    """The FOR / NEXT methods of ``AreaCompiler`` (they use its blocks, ``walk`` and
    ``continuation``)."""

    def loop_key(self, var) -> str:
        """The FOR-stack key of a control variable: ``I``, or ``A()`` for an element
        (gw: with its type character, ``I!``)."""
        name = self.numbers.name(var.name)
        return name if isinstance(var, ast.Var) else name + "()"

    def loop_var(self, var, scope) -> tuple[str, str]:
        """(Python target for the control variable, FOR-stack key)."""
        if self.kind_of(var) == "s":
            raise type_mismatch()
        if isinstance(var, ast.Var):
            return scope.scalar(var.name, write=True), self.loop_key(var)
        return self.element(var, scope), self.loop_key(var)

    def stepping(self, var_node, var: str, step: str) -> str:
        """The code of ``var + step`` for a FOR variable (rounded to its type)."""
        return self.numbers.stepped(self.kind_of(var_node), var, step)

    def stmt_For(self, stmt, scope, native_next: int | None = None):
        if isinstance(stmt.var, ast.Elem) and stmt.var.indices and not self.for_array_elements:
            raise syntax_error()
        kind = self.kind_of(stmt.var)
        if kind not in self.numbers.loop_types:
            raise type_mismatch()
        self.made(stmt.var)  # FOR's PTRGET makes the variable, whether or not its NEXT is found
        convert = self.numbers.convert
        start = convert(*self.typed(stmt.start, scope), kind)
        limit = convert(*self.typed(stmt.stop, scope), kind)
        one = self.numbers.one()
        step = one if stmt.step is None else convert(*self.typed(stmt.step, scope), kind)
        var, key = self.loop_var(stmt.var, scope)
        n = self.new_temp()
        self.emit(f"_v{n} = {start}; _l{n} = {limit}; _s{n} = {step}")
        if isinstance(stmt.var, ast.Elem) and stmt.var.indices and not all(
                isinstance(i, ast.Num) for i in stmt.var.indices):
            raise syntax_error()  # a computed subscript would be re-evaluated each pass
        bound = self.bound_next(stmt)
        if bound is None or bound[2] is not True:
            # GW-BASIC's FOR keeps the start value aside until its scan has found the NEXT
            # (GWMAIN.ASM FOR, NXTSCN): no NEXT, or one of another loop, leaves the variable as it was
            self.emit(f"_M.bound_next({bound!r})")
        self.emit(f"{var} = _v{n}")
        if native_next is not None:
            step_value = stmt.step.value if isinstance(stmt.step, ast.Num) else (
                1.0 if stmt.step is None else None)
            if step_value is not None and step_value > 0:
                test = f"{var} <= _l{n}"
            elif step_value is not None and step_value < 0:
                test = f"{var} >= _l{n}"
            else:
                test = f"({var} <= _l{n} if _s{n} >= 0.0 else {var} >= _l{n})"
            mode = self.loop_mode(stmt) if self.numbers.may_iterate(stmt, kind) else "while"
            if mode == "count":
                # the body neither reads nor changes the variable: count the passes
                self.emit(f"if {test}:")
                self.indent += 1
                self.emit(f"_it{n} = _fcount(_v{n}, _l{n}, _s{n})")
                if self.idle_body:  # an empty body: the passes are counted in C, in chunks
                    self.emit(f"_i{n} = 0")
                self.emit("try:")
                self.indent += 1
                self.loop_header(f"_i{n}", f"_fidle(_it{n})" if self.idle_body else f"_it{n}")
                return n, var, step_value, mode
            if mode == "constant":
                values, _ = self.constant_passes(stmt)
                self.emit(f"if {test}:")
                self.indent += 1
                first, last = self.loop_range
                indexing = any(isinstance(node, ast.Elem) and stmt.var in node.indices
                               for node in nodes([self.flat[k][1] for k in range(first + 1, last)]))
                if indexing and not self.plan.option_base and all(v == int(v) and 0 <= v < 2.0 ** 52 for v in values):
                    # the subscript of each value too: the body indexes arrays with it
                    self.whole_index[stmt.var.name] = f"_k{n}"
                    pairs = "".join(f"({int(v)}, {v!r}), " for v in values)
                    self.loop_header(f"_k{n}, {var}", f"({pairs})")
                else:
                    self.loop_header(var, f"({''.join(f'{v!r}, ' for v in values)})")
                return n, var, step_value, mode
            if mode == "values":
                # the body never changes the variable: iterate over its values
                self.emit(f"if {test}:")
                self.indent += 1
                self.loop_header(var, f"{self.numbers.loop_helpers(kind)[0]}(_v{n}, _l{n}, _s{n})")
                return n, var, step_value, mode
            self.emit(f"if {test}:")
            self.indent += 1
            self.loop_header(None, test)
            return n, var, step_value, mode
        body = self.entry_block.get(self.index + 1) if self.depth == 0 else None
        skip_index = self.plan.for_next.get(self.index) if self.depth == 0 else None
        if skip_index is None:
            skip_index = self.plan.branch_for_next.get(id(stmt))
        block, indent = self.cur, self.indent
        self.emit(f"if _v{n} <= _l{n} if _s{n} >= 0.0 else _v{n} >= _l{n}:")
        if body is None:
            body_block = self.continuation()
        else:
            body_block = body
            self.cur = None
        block.code.append((indent + 1, f"_for({key!r}, _l{n}, _s{n}, {body_block}, {self.bound_next(stmt)!r})"))
        block.code.append((indent + 1, f"return {body_block}"))
        # a loop that never runs leaves its variable at the start value (GW-BASIC's
        # source: FOR hands over to NEXTS in NEXT86.ASM with NXTFLG = 0; see compatibility.md)
        bound = self.bound_next(stmt)
        if bound:  # GW-BASIC: no NEXT, or one naming another loop, is an error; else go on after it
            block.code.append((indent, f"_M.bound_next({bound!r})"))
            found = self.scanned_next(stmt)[1]
            if not any(s is found for s in walk_statements(self.flat[bound[0]][1])):
                found = self.flat[bound[0]][1]  # a NEXT in text an unowned ELSE skips: on after its statement
            after = self.after(bound[0], found).number
            block.code.append((indent, f"if _M.dialect.for_binds_next: return {after}"))
        elif bound is None:
            block.code.append((indent, "_M.bound_next(None)"))
        if skip_index is None:
            block.code.append((indent, f"raise _err('FOR without NEXT', {FOR_WITHOUT_NEXT})"))
        else:
            block.code.append((indent, f"return {self.entry_block[skip_index + 1]}"))
        return None

    def bound_next(self, stmt):
        """What GW-BASIC's FOR finds scanning for its NEXT (``Machine.for_push``):
        ``(statement index, line, names this loop?, the NEXT's place)``, None for no NEXT;
        "names this loop?" is ``(message, code)`` for a NEXT whose name does not read.
        The place (:meth:`next_place`) is the loop's NEXT: GW-BASIC's FOR entry keeps the
        text pointer of the NEXT it found, and a NEXT elsewhere does not step the loop
        (NEXT86.ASM NEXTC compares it with its own).  A FOR inside an IF branch scans on
        from itself through the rest of its IF statement."""
        found = self.scanned_next(stmt)
        if found is None:
            return None
        k, next_stmt = found
        if isinstance(next_stmt.var, BasicError):  # a NEXT whose name does not read: its error
            return (k, self.flat[k][0], (next_stmt.var.message, next_stmt.var.code), self.next_place(next_stmt))
        return (k, self.flat[k][0], next_stmt.var is None or next_stmt.var == stmt.var, self.next_place(next_stmt))

    def next_place(self, stmt) -> int:
        """Where the NEXT ``stmt`` is in the program's text: its place among the statements
        and IF branches in text order (``NEXT J, I`` is two places), as the FOR stack's
        frames name the NEXT they are bound to."""
        return self.plan.next_scan.position[id(stmt)]

    def scanned_next(self, stmt):
        """``(statement index, NEXT)`` that the FOR ``stmt``'s scan finds, or None."""
        return self.plan.next_scan.find(self.index + 1, stmt if self.depth else None)

    def zero_trip_target(self, stmt) -> bool:
        """Does ``stmt`` hold, in an IF branch, a NEXT that a zero-trip FOR goes on after?"""
        return any(id(s) in self.plan.branch_nexts for s in walk_statements(stmt, unreachable=False))

    def stmt_Next(self, stmt, scope):
        var = stmt.var
        if isinstance(var, BasicError):  # a name that does not read (parser._next_read_as_far)
            self.emit(f"raise _err({var.message!r}, {var.code})")
            return
        if var is not None and self.for_binds_next and self.kind_of(var) == "s":
            # no FOR entry is a string's (FOR A$ is Type mismatch): NEXT86.ASM FNDFOR finds none
            self.emit(f"raise _err('NEXT without FOR', {NEXT_WITHOUT_FOR})")
            return
        if var is None and self.depth == 0 and self.index in self.plan.next_for:
            var = self.flat[self.plan.next_for[self.index]][1].var
        if var is None:
            self.emit(STORE_LOCALS)
            self.emit(f"if _next_any({self.next_place(stmt)}): return _M.frame_body")
            self.emit(LOAD_LOCALS)
        else:
            target, key = self.loop_var(var, scope)
            self.emit(f"_f = _next({key!r}, {self.next_place(stmt)})")
            self.emit(f"{target} = {self.stepping(var, target, '_f.step')}")
            self.emit(f"if {target} <= _f.limit if _f.step >= 0.0 else {target} >= _f.limit: return _f.body")
            self.emit("_pop()")
        if id(stmt) in self.plan.branch_nexts:  # a zero-trip FOR goes on here, inside the branch
            self.continue_after(stmt, fall_through=True)

    def loop_mode(self, stmt) -> str:
        """How to run the native loop now being compiled.

        ``"while"``: test and add the step each pass (always right; used for a
        short loop with constant bounds, or when the body may change the variable);
        ``"constant"``: such a short loop in plain doubles iterates over a tuple of
        its values made at compile time (:meth:`constant_passes`), with each value's
        subscript beside it when all are whole numbers >= 0 and the body indexes
        an array with the variable;
        ``"values"``: ``for var in _frange(...)`` when nothing in the body can
        change the variable; ``"count"``: ``for _ in range(n)`` when the body does
        not even read it (the variable's value is set after the loop, or on an error).
        """
        if not self.iterable_loop(stmt.var):
            return "while"
        start, stop = constant_value(stmt.start), constant_value(stmt.stop)
        step = 1.0 if stmt.step is None else constant_value(stmt.step)
        if start is not None and stop is not None and step and 0 <= (stop - start) / step < 16:
            return "constant" if self.constant_passes(stmt) else "while"
        first, last = self.loop_range
        body = [self.flat[k][1] for k in range(first + 1, last)]
        if any(isinstance(node, ast.FnCall) or node == stmt.var for node in nodes(body)):
            return "values"
        return "count"

    def counts_up_from_zero(self, stmt) -> bool:
        """Does the loop's variable stay >= 0 in its body (constant start >= 0, step > 0,
        never assigned there)?  Then it can index arrays without the subscript check."""
        start_ok = isinstance(stmt.start, ast.Num) and stmt.start.value >= 0
        step_ok = stmt.step is None or (isinstance(stmt.step, ast.Num) and stmt.step.value > 0)
        return start_ok and step_ok and self.iterable_loop(stmt.var)

    def counts_whole_numbers(self, stmt) -> bool:
        """Does the loop's variable hold whole numbers in its body (constant whole start and
        step, never assigned there)?  A sum of whole numbers is whole in any type (a double
        or single that rounds it is past 2**53 or 2**24, where every number is whole)."""
        def whole(node) -> bool:
            value = 1.0 if node is None else constant_value(node)
            return value is not None and value == int(value)
        return whole(stmt.start) and whole(stmt.step) and self.iterable_loop(stmt.var)

    def iterable_loop(self, var) -> bool:
        """May the native loop now being compiled iterate instead of testing?

        Only when nothing in its body can change the control variable: it is a
        scalar, no statement assigns it, and nothing outside the block (an area,
        CLEAR) runs inside the loop.
        """
        if not isinstance(var, ast.Var):
            return False
        first, last = self.loop_range
        for k in range(first + 1, last):
            for s in walk_statements(self.flat[k][1]):
                if isinstance(s, (ast.GosubProg, ast.Clear)):
                    return False
                targets = []
                if isinstance(s, (ast.Let,)):
                    targets = [s.target]
                elif isinstance(s, (ast.Read, ast.Input)):
                    targets = s.targets
                elif isinstance(s, ast.For):
                    targets = [s.var]
                if var in targets:
                    return False
        return True

    def constant_passes(self, stmt) -> tuple[list, float] | None:
        """A short loop known at compile time: (the values of the variable, one per pass;
        its value after the loop), found by adding the step as the loop does.

        Only for a scalar FOR with constant bounds and fewer than 16 passes (the short
        loops :meth:`loop_mode` would run as ``while``, and those that never run) whose numbers are plain doubles
        stepped by a plain ``+`` (the casio dialect's), or whose values are all whole numbers below the
        model's ``whole_steps_below`` (gw singles: 2**24; decimal: 1E+12, exact in both arithmetics);
        None for any other loop.
        """
        whole_below = self.numbers.whole_steps_below
        if self.numbers.typed and self.kind_of(stmt.var) != "!":
            return None
        if not isinstance(stmt.var, ast.Var) or self.kind_of(stmt.var) == "s":
            return None
        value, limit = constant_value(stmt.start), constant_value(stmt.stop)
        step = 1.0 if stmt.step is None else constant_value(stmt.step)
        if value is None or limit is None or step is None or not step or not (limit - value) / step < 16:  # (a loop that never runs is one too)
            return None
        values = []
        while (value <= limit) if step > 0 else (value >= limit):
            values.append(value)
            value = value + step
        if whole_below is not None and not all(v == int(v) and abs(v) < whole_below for v in values + [value]):
            return None  # (a sum of whole numbers below it is exact: the arithmetic's sum is the double's)
        return values, value

    def loop_header(self, target: str | None, items: str) -> None:
        """Emit a native loop's first line, ``for target in items:`` (``target`` None: ``while
        items:``), and keep its parts for :meth:`unchecked_passes` (``header_parts``)."""
        self.header_parts = (target, items)
        self.emit(f"while {items}:" if target is None else f"for {target} in {items}:")

    def unchecked_passes(self, block, header: int, n: str, makings: set, parts: tuple) -> None:
        """Mark the native loop whose first line is ``block.code[header]`` (the rest of the
        block's code its passes; ``parts`` that line's, :meth:`loop_header`) to run in two
        loops where its body makes variables (``makings``, compiler.made): the passes with
        the tests of their makings while one is not made (the loop's own flag
        ``_f<block>_<n>``, kept as a block's: CompiledArea.makings), then the rest without
        (compiler._passes), so that the passes after the first pay nothing for the makings.
        The line becomes a :class:`LoopSplit`; whether the loop is copied is decided with
        the area's other copies (compiler._copies).  Not where the body can unmake a name
        (CLEAR, ERASE) or leaves the block."""
        if not makings or self.cur is not block or any(
                "_clear(" in text or "_erase(" in text for _, text in block.code[header + 1:]):
            return
        key = f"{block.number}_{n}"
        block.loop_makes[key] = set(makings)
        arrays = tuple(sorted(name[:-2] for name in makings if name.endswith(")")))
        indent, text = block.code[header]
        block.code[header] = (indent, LoopSplit(text, key, n, arrays, *parts))

    def native_loop(self, i: int) -> int:
        """Emit FOR at ``i`` ... its NEXT as a Python while loop; the index after NEXT."""
        j = self.plan.native[i]
        stmt = self.flat[i][1]
        scope = BlockScope(self)
        levels = self.words.for_levels
        if levels is not None:
            # a dialect's FOR levels (casio: FOR_NEXT_STEP.md item 4): the loops open on the
            # stack and the native loops around this one leave room for it, or OM
            room = levels - len(self.open_loops)
            self.emit(f"if len(_stk) >= {room} and _loops() >= {room}: _oom()")
        # nothing between FOR and NEXT (and no TRON line marks): a delay loop
        self.idle_body = j == i + 1 and not self.trace
        passes = self.constant_passes(stmt) if self.idle_body else None
        if passes is not None:  # a short delay loop: its variable's final value
            self.made(stmt.var)
            self.emit(f"{scope.scalar(stmt.var.name, write=True)} = {passes[1]!r}")
            self.line = None
            self.set_line(self.flat[j][0])
            return j + 1
        block, mark = self.cur, len(self.cur.code)
        self.loop_range = (i, j)
        try:
            n, var, step_value, mode = self.stmt_For(stmt, scope, native_next=j)
        except CompileError as err:
            del block.code[mark:]
            self.emit(f"raise _err({err.message!r}, {err.code})")
            return i + 1
        counting = self.counts_up_from_zero(stmt)
        if counting:
            self.counting_vars.add(stmt.var.name)
        whole = self.counts_whole_numbers(stmt)
        if whole:
            self.whole_vars.add(stmt.var.name)
        header = len(block.code) - 1  # the loop's "for ... in ...:" or "while ...:" line
        parts = self.header_parts  # (before the body's loops emit theirs)
        self.indent += 1
        # The top of a pass is where a Ctrl-C may stop the loop so that CONT resumes it:
        # its line is the atomic ``_ln = n`` (nothing in it can be interrupted half-way).
        self.open_loops.append((i, self.loop_key(stmt.var), n, mode,
                                local_name(self.numbers.name(stmt.var.name)) if isinstance(stmt.var, ast.Var)
                                else None))
        self.emit(PassTop(len(self.break_infos)))
        self.break_infos.append((self.flat[i + 1][0], tuple(self.open_loops)))
        self.line = None
        # (the line of the body's first statement, where a break lands; the FOR's for an empty body)
        self.set_line(self.flat[i + 1][0] if j > i + 1 else self.flat[i][0])
        body_mark = len(self.cur.code)
        self.loop_makings.append(set())
        self.walk(i + 1, j)
        self.trace_line(j)  # a NEXT that starts its line
        self.open_loops.pop()
        makings = self.loop_makings.pop()
        if len(self.cur.code) == body_mark:
            self.emit("pass")  # an empty body (a delay loop)
        if counting:
            self.counting_vars.discard(stmt.var.name)
        if whole:
            self.whole_vars.discard(stmt.var.name)
        self.index = j  # (stepping cannot fail, so NEXT's line needs no marker in the loop)
        increment = repr(step_value) if step_value is not None and not self.numbers.typed else f"_s{n}"
        increment = self.stepping(stmt.var, var, increment)
        if mode != "while":
            self.unchecked_passes(block, header, n, makings, parts)
        if mode == "count":
            self.indent -= 2
            self.emit("except BaseException:")
            self.emit(f"    {var} = _fvalue(_it{n}, _v{n}, _s{n}, _i{n})")
            self.emit("    raise")
            self.emit(f"{var} = _fafter(_it{n}, _v{n}, _s{n})")
        elif mode == "values":
            self.indent -= 1
            self.emit(f"{var} = {increment}")
        elif mode == "constant":
            self.indent -= 1
            self.emit(f"{var} = {self.constant_passes(stmt)[1]!r}")
            self.whole_index.pop(stmt.var.name, None)
        else:
            self.emit(f"{var} = {increment}")
            self.unchecked_passes(block, header, n, makings, parts)
            self.indent -= 1
        self.indent -= 1
        # a loop that never runs leaves its variable at the start value (see stmt_For)
        self.line = None
        self.set_line(self.flat[j][0])
        return j + 1
