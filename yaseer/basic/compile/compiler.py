"""AST -> Python: one program area becomes a set of Python functions, one per block.

A *block* is a run of statements that is entered only at its top: it starts at
a line some jump names (GOTO, GOSUB, THEN n, ON ... GOTO, RESUME n), at the
statement after a GOSUB or STOP (the return point), at the body of a FOR loop
that must be run through the FOR stack, or - in a program that uses RESUME or
RESUME NEXT - at every statement.  Each block is generated as Python source:

* scalars live in Python locals for the block's duration (loaded from the
  machine's scalar dict on entry, stored back in a ``finally``, and around every
  call out of the block: ``GOSUB PROG n``, ``FN``, ``CLEAR``);
* a FOR ... NEXT with no jump into or out of its body becomes a native
  ``while`` loop; a block that jumps back to its own start becomes
  ``while True`` with ``continue``;
* a block returns the number of the next block to run; the machine's run loop
  is ``while True: b = blocks[b]()``.

The variable ``_ln`` tracks the BASIC line for error messages.

With ``trace`` (TRON), the first statement of every line is preceded by
``_tr(n)``, which prints ``[n]``: a line is traced when execution reaches its
start (falling in from the line before, or by a jump), not when a NEXT or
RETURN comes back into its middle, as GW-BASIC traces.  The traced variant has
the same blocks as the plain one, so the machine can swap one for the other
while a program runs; the plain variant carries no cost for tracing.
"""

from __future__ import annotations

from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.compile.blocks import data_statements, flatten, nodes, plan, splits, types_fixed, walk_statements
from yaseer.basic.compile.expressions import (
    MAKING, BlockScope, CompileError, ExpressionCompiler, FnScope, calls_fn, may_overflow, syntax_error, type_mismatch,
)
from yaseer.basic.compile.statements_io import InputOutputCompiler
from yaseer.basic.compile.graphics_statements import GraphicsCompiler
from yaseer.basic.compile.device_words import device_statement, event_switch, event_trap
from yaseer.basic.compile.loops import LoopCompiler, LoopSplit
from yaseer.basic.compile.markers import (
    LOAD_LOCALS, STACK_CHECK, STORE_LOCALS, ArraysCall, Dimensioned, LoadLocals, PassTop, Refreshing, StackCheck,
    StoreLocals,
)
from yaseer.basic.dialects.dialect import CASIO
from yaseer.basic.compile.number_models import array_local, local_name, number_model, variant_function
from yaseer.basic.compile.compiled import MAX_STACK, CompiledArea  # noqa: F401  (re-exported)
from yaseer.basic.errors import (
    BasicError, ILLEGAL_FUNCTION_CALL, OUT_OF_MEMORY, SYNTAX_ERROR, UNDEFINED_LINE, WEND_WITHOUT_WHILE, WHILE_WITHOUT_WEND,
    undefined_line_message,
)


class _Block:
    def __init__(self, number: int):
        self.number = number
        self.code: list[tuple[int, str]] = []
        self.scalars: dict[str, bool] = {}  # name -> assigned in this block
        self.arrays: dict[str, int] = {}  # name -> number of dimensions
        self.makes: set[str] = set()  # the simple variables its statements make (compiler.made)
        self.loop_makes: dict[str, set] = {}  # a native loop's flag -> the names its body makes
        self.first_line = None


# What generated code calls that changes the GOSUB/FOR stack and goes on in the same block.
_STACK_CHANGES = ("_pop(", "_next_any(", "_clear(", "_call(", "_M.", "_gosub(", "_stk.")


def _too_deep(code: list) -> bool:
    """Would these generated lines pass Python's nesting limits (indents, parentheses)?"""
    for indent, text in code:
        if indent > 80:
            return True
        depth = 0
        for ch in text:
            if ch == "(":
                depth += 1
                if depth > 150:
                    return True
            elif ch == ")":
                depth -= 1
    return False


class _NoWords:
    """The tables of a dialect without words of its own (GW-BASIC): all empty."""

    functions: dict = {}
    statements: dict = {}
    routine_calls: dict = {}
    reads_variables = writes_variables = sets_x_y = empty_statements = frozenset()
    variable_area = None
    edit_lists_from = False
    password_refuses = ()
    read_mismatch = output_eof = False
    gosub_levels = for_levels = None
    computed_restore = empty_on_targets = truncates = asks_each = False
    command_options = {"LOAD": "R", "SAVE": "AP", "RUN": "R"}  # GW-BASIC's LOAD ,R; SAVE ,A ,P; RUN ,R
    list_to_file = True  # LIST [range], "f" (GWLIST.ASM LIST)


NO_WORDS = _NoWords()


def _set_format(node) -> tuple[str, int]:
    """SET's argument (SET.md): ``F`` or ``E`` and one digit, or ``N``, read as the name
    the scanner made of it (``SET F3``: the name F3)."""
    name = node.name.upper() if isinstance(node, ast.Var) else ""
    if name == "N":
        return "N", 0
    if len(name) == 2 and name[0] in "FE" and name[1].isdigit():
        return name[0], int(name[1])
    raise syntax_error()


class AreaCompiler(ExpressionCompiler, InputOutputCompiler, LoopCompiler, GraphicsCompiler):
    """Compiles the lines of one program area (see the module docstring).

    The area walk, the blocks and the statements of control flow are here; expressions
    (:mod:`~yaseer.basic.compile.expressions`), the statements that move data in and
    out (:mod:`~yaseer.basic.compile.statements_io`) and FOR/NEXT loops
    (:mod:`~yaseer.basic.compile.loops`) are compiled by the mixins."""

    def __init__(self, lines: list, area: int = 0, direct: bool = False, entry_lines=(), trace: bool = False,
                 dynamic_loops=(), dialect=CASIO, def_types=None, statement_types=False, base_one: bool = False):
        self.area = area
        self.statement_types = statement_types  # DEF types switched as they run, even where fixed would do
        self.variables_made = dialect.variables_made  # SWAP's second variable must exist (see made)
        self.dim_name_alone_scalar = dialect.dim_name_alone_scalar  # DIM A: the simple variable
        self.fields_bind = "FIELD" in dialect.own_words  # string variables may point into a file's buffer
        self.watched: frozenset = frozenset()  # the names whose making is recorded (see made)
        self.counts_made = False  # each making is counted and checked against the 64 KB (see made)
        self.checked_once: set = set()  # the blocks whose later passes run without those tests (_checks_once)
        self.read_commits = dialect.read_commits  # a READ ends with _read_end (Dialect.read_commits)
        self.list_dialect = dialect  # COMMON's lists are read by its scanner (common_variables)
        self.numbers = number_model(dialect, def_types)
        # the binade caches' names differ between the variants run in one namespace (TRON, DEF types)
        salt = "t" if trace else ""
        if def_types is not None:
            salt += "v" + variant_function("", def_types)
        self.numbers.site_salt = salt
        self.program_areas = dialect.program_areas  # GOSUB PROG n, #n, "file:label"
        self.library_forms = dialect.library_forms  # THEN *
        self.locate_arguments = dialect.screen.locate_arguments  # LOCATE's (fewest, most)
        self.byte_statements = dict(dialect.screen.byte_statements)  # read as GWSTS.ASM SCNINT (GW)
        self.late_errors = dialect.errors_when_reached  # a DEF FN body's errors when it is called
        self.reads_arguments_in_order = dialect.argument_readings  # a call that does not fit (argument_reading)
        self.using_each_value = dialect.using_each_value  # PRINT USING's values field by field
        self.input_answer_first = dialect.input_answer_first  # INPUT; and INPUT cut short (GW)
        self.def_seg_usr = dialect.def_seg_usr  # DEF SEG, DEF USR (GW)
        self.clear_readings = dialect.clear_readings  # how CLEAR reads its places (GW)
        self.for_array_elements = dialect.for_array_elements  # FOR T(2) = ... (the paper's Example 3)
        self.for_binds_next = dialect.for_binds_next  # a NEXT looks for its FOR entry by name (GW)
        # "." in LIST, EDIT ...: GW's DOT, the machine's current_line as the statement runs
        # (Dialect.current_line_listed); else (casio) the line the statement is in
        self.dot_runs = dialect.current_line_listed
        self.names_missing_line = dialect.names_missing_line
        self.words = dialect.words or NO_WORDS  # the dialect's own words (dialects/casio.py)
        # the test of a full stack before a GOSUB: the stack's length, or (a dialect that counts
        # GOSUB levels: casio, GOSUB.md item 2) its GOSUB entries once the stack is that long
        levels = self.words.gosub_levels
        self.stack_full = f"len(_stk) >= {MAX_STACK}" if levels is None else f"len(_stk) >= {levels} and _deep()"
        self.string_length = dialect.string_length  # the longest literal (characters)
        self.counts_strings = dialect.free_memory is not None  # strings take room (string_space.py)
        self.strings_in_area = self.words.variable_area is not None  # casio: a stored string takes room (_sroom)
        self.own_functions = dict(self.words.functions, DEG=self.words.deg_function) if dialect.words else {}
        self.device_words = dialect.device_words  # gw's INP, OUT, LOCK ... (dialects/gw_words.py)
        if self.device_words:
            self.own_functions.update(self.device_words.functions)
        self.direct = direct
        self.trace = trace and not direct
        self.dynamic_loops = set(dynamic_loops)
        self.flat = flatten(lines)
        # A direct line's error may be RESUMEd NEXT by the program's handler where the dialect
        # traps it (GW), so each of its statements is a place to come back to.
        self.plan = plan(self.flat, entry_lines, self.dynamic_loops,
                         resumable=direct and dialect.direct_line_number is not None)
        # under an OPTION BASE 1 in force when the code is made (a CHAIN keeps the first
        # program's) subscripts go through the check as if the area held the statement
        self.plan.option_base = self.plan.option_base or base_one
        self.line_first = {}
        for i, (number, _) in enumerate(self.flat):
            self.line_first.setdefault(number, i)
        self.entry_block = {idx: b for b, idx in enumerate(self.plan.entries)}
        self.blocks: list[_Block] = [_Block(b) for b in range(len(self.plan.entries))]
        self.block_next: dict[int, int] = {}
        self.while_block: dict[int, int] = {}  # id(WHILE in an IF branch) -> its block
        self.while_numbers: dict | None = None  # id(WHILE) -> its number in the text (while_key)
        self.branch_after: dict[int, _Block] = {}  # id(WEND or NEXT in an IF branch) -> the block after it
        self.prelude: list[str] = []
        self.scalars: set[str] = set()
        self.cur: _Block | None = None
        self.indent = 0
        self.depth = 0  # IF nesting
        self.index = 0  # current top-level statement
        self.line = None
        self.temp = 0
        self.dynamic_types = False  # DEF types switched as they run (see stmt_DefType)
        self.fn_count = 0
        self.data: list = []
        self.data_lines: dict = {}
        self.scope = BlockScope(self)
        self.counting_vars: set[str] = set()  # native loop variables that stay >= 0
        self.whole_vars: set[str] = set()  # native loop variables that stay whole numbers
        self.idle_body = False  # the native loop being compiled has an empty body
        self.whole_index: dict[str, str] = {}  # constant loop variable -> local of its subscript
        self.open_loops: list[tuple] = []  # the native loops around the code being emitted
        self.loop_makings: list[set] = []  # the names each of those loops' bodies makes (note_making)
        self.header_parts: tuple = ()  # the last native loop's first line (loops.loop_header)
        self.split_loops: set = set()  # the native loops run in two (loops.unchecked_passes, _copies)
        self.break_infos: list[tuple] = []  # markers.PassTop's: (BASIC line, open loops)
        self.break_points: dict[int, dict] = {}  # block -> {Python line: (BASIC line, open loops)}
        self.fn_params: dict[str, list] = {}  # DEF FN name -> parameter names
        # under OPTION BASE 1 a constant subscript 0 must go through the check
        self.lowest_fast_subscript = 1 if self.plan.option_base else 0

    # -- emission primitives
    def emit(self, text: str) -> None:
        self.cur.code.append((self.indent, text))

    def new_temp(self) -> str:
        self.temp += 1
        return f"_t{self.temp}"

    def new_block(self) -> _Block:
        block = _Block(len(self.blocks))
        self.blocks.append(block)
        return block

    def block_of_line(self, line: int) -> int | None:
        index = self.line_first.get(line)
        return None if index is None else self.entry_block[index]

    def jump(self, line: int) -> str:
        block = self.block_of_line(line)
        if block is None:
            if self.direct:
                return f"raise _DirectJump({line})"
            return f"raise _err({undefined_line_message(line, self.names_missing_line)!r}, {UNDEFINED_LINE})"
        return f"return {block}"

    # -- statements
    def statement(self, stmt) -> None:
        """Emit one statement; a compile error becomes a run-time raise of its line."""
        if isinstance(stmt, BasicError):
            self.emit(f"raise _err({stmt.message!r}, {stmt.code})")
            return
        mark = len(self.cur.code)
        block = self.cur
        scope = BlockScope(self)
        try:
            getattr(self, "stmt_" + type(stmt).__name__)(stmt, scope)
        except (CompileError, RecursionError) as exc:
            err = exc if isinstance(exc, CompileError) else CompileError("Out of memory", OUT_OF_MEMORY)
            if self.cur is block:
                del block.code[mark:]
            self.emit(f"raise _err({err.message!r}, {err.code})")
            return
        if self.cur is block and _too_deep(block.code[mark:]):
            del block.code[mark:]  # Python could not compile it: the statement's own error
            if self.numbers.tests_inline:  # unless the plain helper calls, which nest least, fit
                self.numbers.tests_inline = False
                try:
                    return self.statement(stmt)
                finally:
                    self.numbers.tests_inline = True
            self.emit(f"raise _err('Out of memory', {OUT_OF_MEMORY})")
            return
        if scope.uses_fn:
            block.code.insert(mark, (self.indent, STORE_LOCALS))

    def assign(self, target, value_code: str, value_kind: str, scope, check: bool) -> None:
        """Store ``value_code`` in a variable or element; ``check`` adds the Overflow test.

        A number is converted to the target's numeric type (GW-BASIC's types)."""
        target_kind = self.kind_of(target)
        if (target_kind == "s") != (value_kind == "s"):
            raise type_mismatch()
        if value_kind != "s":
            value_code = self.numbers.stored(value_code, value_kind, target_kind)
        elif self.strings_in_area:  # the string must fit in the variable area (an element: counted whole)
            if isinstance(target, ast.Var):  # no longer than the old text: nothing to count (no call)
                old = scope.scalar(target.name, write=True)
                value_code = f"(_sv if len(_sv := {value_code}) <= len({old}) else _sroom(_sv, {old}))"
            else:
                value_code = f"_sroom({value_code}, '')"
        if isinstance(target, ast.Var):
            name = scope.scalar(target.name, write=True)
            self.made(target)  # LET's PTRGET makes the variable before its value is worked out
            if check:  # checked before the store: a trapped Overflow leaves the variable as it was
                self.emit(f"_t = {value_code}")
                self.emit(f"if _t - _t: _t = _ovf(_t, {target_kind!r})")
                value_code = "_t"
            self.emit(f"{name} = {value_code}")
            return
        element = self.element(target, scope, made=self.counts_made)
        if self.counts_made:  # LET's PTRGET makes an array used without DIM before the value is worked out
            name = self.numbers.name(target.name)
            local = array_local(name)
            self.note_making(name + "()")
            self.emit(Refreshing(f"{MAKING}{local} is None: {local} = _arr({name!r}, {len(target.indices)})"))
        if check:
            self.emit(f"_t = {value_code}")
            self.emit(f"if _t - _t: _t = _ovf(_t, {target_kind!r})")
            value_code = "_t"
        self.emit(f"{element} = {value_code}")

    def stmt_Let(self, stmt, scope):
        code, kind = self.expr(stmt.value, scope)
        if isinstance(stmt.value, (ast.CutCall, ast.CutExpression)):
            self.emit(code)  # a value the text cuts short raises as it is read: no assignment, no type to match
            return
        if kind == "s" and self.counts_strings and isinstance(stmt.value, (ast.Var, ast.Elem)):
            code = f"_scopy({code})"  # another variable's string is copied (machine/string_space.py)
        check = kind != "s" and may_overflow(stmt.value, self.numbers.typed) and self.kind_of(stmt.target) != "%"
        if check and kind in self.numbers.kinds_in_range and not calls_fn(stmt.value):
            check = False  # every operation of its type gave a value in the range or the policy's
        self.assign(stmt.target, code, kind, scope, check)

    def stmt_Rem(self, stmt, scope):
        pass

    def stmt_Data(self, stmt, scope):
        pass

    def stmt_Goto(self, stmt, scope):
        self.emit(self.jump(stmt.target))

    def continuation(self) -> int:
        """The block where code after the current statement goes (a return point)."""
        if self.depth == 0:
            block = self.entry_block[self.index + 1]
            self.cur = None
            return block
        block = self.new_block()
        self.cur = block
        self.indent = 1
        self.emit(f"_ln = {self.line}")
        return block.number

    def stmt_Gosub(self, stmt, scope):
        if stmt.target in self.plan.bare_returns:
            # a subroutine that is a plain RETURN: push and pop in place (a full stack
            # is still Out of memory at the GOSUB; TRON still shows the RETURN's line)
            self.emit(STACK_CHECK)
            if self.trace:
                self.emit(f"_tr({stmt.target})")
            return
        target = self.jump(stmt.target)
        if target.startswith("raise _err("):
            # GWMAIN.ASM GOSUB: GETSTK's room first, then the line; a trapped error's SAVSTK
            # drops what was pushed, so RETURN never comes back here
            self.emit(f"if {self.stack_full}: _oom()")
            self.emit(target)
            return
        block, indent = self.cur, self.indent
        ret = self.continuation()
        block.code.append((indent, f"if {self.stack_full}: _oom()"))
        block.code.append((indent, f"_stk.append({ret})"))
        block.code.append((indent, target))

    def stmt_GosubProg(self, stmt, scope):
        self.emit(STORE_LOCALS)
        self.emit(ArraysCall(f"_call({stmt.area}, _ln)"))

    def stmt_GosubArea(self, stmt, scope):
        self._call_program(f"_call({stmt.area}, _ln)")

    def stmt_GotoArea(self, stmt, scope):
        self._call_program(f"_call({stmt.area}, _ln)")
        self.emit("raise _END")

    def stmt_GosubFile(self, stmt, scope):
        self._call_program(f"_call_file({self.string(stmt.name, scope)}, _ln)")

    def stmt_GotoFile(self, stmt, scope):
        self._call_program(f"_call_file({self.string(stmt.name, scope)}, _ln)")
        self.emit("raise _END")

    def _call_program(self, call: str) -> None:
        """Run another program (area or file) where the dialect has them; else Syntax error."""
        if not self.program_areas:
            raise syntax_error()
        self.emit(STORE_LOCALS)
        self.emit(call)
        self.emit(LOAD_LOCALS)

    def stmt_Return(self, stmt, scope):
        # the common case inline: a GOSUB's return block on top of the stack
        self.emit("if _stk and type(_stk[-1]) is int: return _stk.pop()")
        self.emit("return _return()")

    def stmt_OnJump(self, stmt, scope):
        selector = self.integer(stmt.selector, scope)
        k = self.new_temp()
        self.emit(f"{k} = _on({selector}, {len(stmt.targets)})")
        empty_places = not self.words.empty_on_targets and self.late_errors
        if None in stmt.targets and not self.words.empty_on_targets and not self.late_errors:
            raise syntax_error()
        jumps = {n: self.jump(t) for n, t in enumerate(stmt.targets, 1) if t is not None}
        for n in (n for n, t in enumerate(stmt.targets, 1) if t is None):
            if empty_places:  # GOTO finds no line number there (GWMAIN.ASM GOTO2: SNERR)
                self.emit(f"if {k} == {n}: raise _err('Syntax error', {SYNTAX_ERROR})")
            else:
                self.emit(f"if {k} == {n}: {k} = 0")  # an empty place: no branch
        if stmt.rest_error is not None:  # no place picked: the text after the places is read
            self.emit(f"if not {k}: raise _err({stmt.rest_error.message!r}, {stmt.rest_error.code})")
        if not stmt.gosub:
            for n, jump in jumps.items():
                self.emit(f"if {k} == {n}: {jump}")
            return
        block, indent = self.cur, self.indent
        self.emit(f"if {k}:")
        ret = self.continuation()
        # a line that does not exist is found missing before the return is pushed (GWMAIN.ASM
        # GOSUB: a trapped error's SAVSTK drops what the statement pushed)
        missing = {n: jump for n, jump in jumps.items() if jump.startswith("raise _err(")}
        for n, jump in missing.items():
            block.code.append((indent + 1, f"if {k} == {n}: _oom() if {self.stack_full} else None; {jump}"))
        block.code.append((indent + 1, f"_gosub({ret})"))
        for n, jump in jumps.items():
            if n not in missing:
                block.code.append((indent + 1, f"if {k} == {n}: {jump}"))
        block.code.append((indent, f"return {ret}"))

    def stmt_OnError(self, stmt, scope):
        if stmt.target == 0:
            self.emit("_error_off()")
            return
        block = self.block_of_line(stmt.target)
        if block is None:
            self.emit(self.jump(stmt.target))
            return
        self.emit(f"_M.on_error = ({self.area}, {block})")

    def stmt_EventTrap(self, stmt, scope):
        event_trap(self, stmt, self.device_words.events, scope)

    def stmt_EventSwitch(self, stmt, scope):
        event_switch(self, stmt, self.device_words.events, scope)

    def stmt_EndMark(self, stmt, scope):
        if not self.library_forms:
            raise syntax_error()
        self.emit("raise _END")

    def stmt_End(self, stmt, scope):
        self.emit("raise _END")

    def stmt_Stop(self, stmt, scope):
        block, indent = self.cur, self.indent
        ret = self.continuation()
        block.code.append((indent, f"_stop({ret})"))

    def hand_over(self, call: str | None = None) -> None:
        """End the current block, after ``call`` (a machine call that swaps in another compiled
        variant of the area: TRON, a DEF type table) where one is given, by returning the next
        block's number: the machine looks that block up in the variant running then."""
        block, indent = self.cur, self.indent
        ret = self.continuation()
        if call is not None:
            block.code.append((indent, call))
        block.code.append((indent, f"return {ret}"))

    def stmt_Trace(self, stmt, scope):
        """TRON / TROFF: the machine swaps in the other variant; the next block is its."""
        self.hand_over(f"_M.set_trace({stmt.on})")

    def stmt_Cls(self, stmt, scope):
        if "CLS" in self.byte_statements:
            self.byte_statement("CLS", [] if stmt.mode is None else [stmt.mode], None, scope)
            return
        mode = "None" if stmt.mode is None else self.numeric(stmt.mode, scope)
        self.emit(f"_M.clear_screen({mode})")

    def stmt_DefChr(self, stmt, scope):
        if not self.library_forms:
            raise syntax_error()
        self.emit(f"_M.define_character({self.numeric(stmt.code, scope)}, {self.string(stmt.pattern, scope)})")

    def stmt_Locate(self, stmt, scope):
        if "LOCATE" in self.byte_statements:
            self.byte_statement("LOCATE", stmt.args, None, scope)
            return
        fewest, most = self.locate_arguments
        if not fewest <= len(stmt.args) <= most or None in stmt.args[:fewest]:
            raise syntax_error()
        self.emit(f"_locate({self.optional_numbers(stmt.args, scope)})")

    def stmt_Width(self, stmt, scope):
        if stmt.file is not None:
            # the file first, then the width (GIO86.ASM FILWID: PRFNUM, FDBPTR, then GETWDT)
            file = f"_M.files.get({self.integer(stmt.file, scope)})"
            width = self.when_reached(lambda: self.integer(stmt.columns, scope))
            self.emit(f"_M.set_file_width({file}, {width})")
            return
        if stmt.device is not None:
            if self.kind_of(stmt.device) != "s" and "WIDTH" in self.byte_statements:
                self.byte_statement("WIDTH", [stmt.device, stmt.columns], None, scope)
                return
            if self.kind_of(stmt.device) != "s":  # WIDTH columns, rows: the screen's size
                self.emit(f"_M.set_screen_size({self.integer(stmt.device, scope)}, {self.integer(stmt.columns, scope)})")
                return
            device = self.string(stmt.device, scope)
            self.emit(f"_M.set_device_width({device}, {self.integer(stmt.columns, scope)})")
            return
        if self.kind_of(stmt.columns) == "s":
            raise syntax_error()  # WIDTH "LPT1:" without its width
        if not stmt.printer and "WIDTH" in self.byte_statements:
            self.byte_statement("WIDTH", [stmt.columns], None, scope)
            return
        self.emit(f"_M.set_width({self.integer(stmt.columns, scope)}, {stmt.printer})")

    def stmt_Dim(self, stmt, scope):
        if not stmt.arrays and "DIM" not in self.words.empty_statements:
            raise syntax_error()
        for name, sizes in stmt.arrays:
            name = self.numbers.name(name)
            if sizes is None:  # a name alone
                if self.dim_name_alone_scalar:
                    self.made_name(name, counted=True)
                    continue
                sizes = (ast.Num(10.0),)
            codes = ", ".join(self.integer(s, scope) for s in sizes)
            self.emit(f"_dim({name!r}, ({codes},))")
            self.emit(Dimensioned(name))

    def stmt_Clear(self, stmt, scope):
        readings = self.clear_readings
        if readings:
            self._clear_arguments(stmt.args, readings, scope)
        elif any(a is not None for a in stmt.args):
            sizes = ", ".join(self.numeric(a, scope) for a in stmt.args if a is not None)
            self.emit(f"_clear_args({sizes})")
        self.emit("_clear()")
        self.emit(LOAD_LOCALS)
        if self.dynamic_types:  # the type table is single again: on in that variant (stmt_DefType)
            self.hand_over()

    def _clear_arguments(self, args: list, readings: tuple, scope) -> None:
        """CLEAR's places (None: left empty) read one by one as ``readings`` say, each checked
        before the next is read; more places than readings, or an empty last place after a
        comma, is a Syntax error where it is met (Dialect.clear_readings)."""
        if not args:
            return
        codes = [None if a is None else f"_clear_arg({reading!r}, {self.numeric(a, scope)})"
                 for a, reading in zip(args, readings)]
        if len(args) > len(readings) or len(args) > 1 and args[-1] is None:
            codes.append(f"_fail('Syntax error', {SYNTAX_ERROR})")
        self.emit(f"_clear_sizes({', '.join(c or 'None' for c in codes)})")

    # -- GW-BASIC's statements
    def stmt_While(self, stmt, scope):
        found = self.plan.while_wend.get(id(stmt))
        if found is None:
            raise CompileError("WHILE without WEND", WHILE_WITHOUT_WEND)
        if self.depth:  # inside an IF branch: a block starts here, for WEND to come back to
            block, indent = self.cur, self.indent
            self.while_block[id(stmt)] = start = self.continuation()
            block.code.append((indent, f"return {start}"))
        if isinstance(stmt.condition, BasicError):  # its WEND found, the condition does not read
            self.emit(f"raise _err({stmt.condition.message!r}, {stmt.condition.code})")
            return
        # the loops running (GW's stack of WHILE entries): a WEND reached by a GOTO into a loop
        # that is not running is WEND without WHILE (GWMAIN.ASM WEND searches the stack)
        condition, after = self.condition(stmt.condition, scope), self.after(*found).number
        rest = stmt.rest_error  # (the loop's entry made: FIVEO.ASM FNWEND, then NEWSTT reads on)
        if not self.entered_inside(self.index, found[0]):
            self.emit(f"if not ({condition}): return {after}")
        else:
            key = self.while_key(stmt)
            self.emit(f"if not ({condition}): _wh.discard({key}); return {after}")
            self.emit(f"_wh.add({key})")
        if rest is not None:
            self.emit(f"raise _err({rest.message!r}, {rest.code})")

    def entered_inside(self, start: int, end: int) -> bool:
        """Whether a block starts inside the loop from statement ``start`` to ``end`` (a GOTO
        target, a return point ...): only such a loop's WEND can be reached while the loop
        is not running, so only its WHILE and WEND keep the running-loops set."""
        return any(start < entry <= end for entry in self.plan.entries)

    def while_key(self, loop) -> int:
        """The running-loops set's key of a WHILE: its area and its number in the text, as one
        int (an int hashes at once: the set is touched every time round the loop)."""
        if self.while_numbers is None:
            self.while_numbers = {k: n for n, k in enumerate(self.plan.while_wend)}
        return self.area << 32 | self.while_numbers[id(loop)]

    def after(self, index: int, node) -> _Block:
        """The block where execution goes on after ``node`` (a WEND, or a NEXT a FOR that
        runs zero times goes on after) in statement ``index``: inside an IF branch, a
        block of its own that the rest of the branch is compiled into."""
        if node is self.flat[index][1]:
            return self.blocks[self.entry_block[index + 1]]
        block = self.branch_after.get(id(node))
        if block is None:
            block = self.branch_after[id(node)] = self.new_block()
        return block

    def continue_after(self, node, fall_through: bool) -> None:
        """Inside an IF branch: compile the rest of the branch into the block after
        ``node`` (see :meth:`after`), which the code so far enters if ``fall_through``."""
        block = self.after(self.index, node)
        if fall_through:
            self.emit(f"return {block.number}")
        # RESUME NEXT after an error in ``node`` goes on there too (not at the block numbered next)
        self.block_next.setdefault(self.cur.number, block.number)
        self.cur, self.indent = block, 1
        self.emit(f"_ln = {self.line}")

    def stmt_Wend(self, stmt, scope):
        if stmt.error is not None:  # WEND with more after it (parser._checked_first)
            self.emit(f"raise _err({stmt.error.message!r}, {stmt.error.code})")
            return
        found = self.plan.wend_while.get(id(stmt))
        start = None
        if found is not None:
            index, loop = found
            start = self.entry_block[index] if loop is self.flat[index][1] else self.while_block.get(id(loop))
        if start is None:
            raise CompileError("WEND without WHILE", WEND_WITHOUT_WHILE)
        if self.entered_inside(index, self.index):
            self.emit(f"if {self.while_key(loop)} not in _wh: raise _err('WEND without WHILE', {WEND_WITHOUT_WHILE})")
        self.emit(f"return {start}")
        if self.depth:  # the rest of the IF branch goes on in the block after the WEND
            self.continue_after(stmt, fall_through=False)

    def made(self, target) -> None:
        """Record that a statement makes simple variable ``target`` (see Dialect.variables_made).
        Where the dialect's variables take room (``counts_made``: gw) each name is made as
        GW's PTRGET makes it: counted from then on by FRE even while it holds 0 or "", and
        ``Out of memory`` where it does not fit (``_mk``: machine/variables.py).  The test
        costs a local's truth once every name the block makes is made: the block's ``_f``,
        read from the global ``_f<block>`` as it starts, which the machine keeps true while
        one of them is not (``CompiledArea.makings``), and a block that loops back to its own
        start runs its passes without the tests once they are all made (:func:`_copies`: ``checked_once``).
        Elsewhere (no room counted) the names a SWAP may ask about are
        recorded: those that stand second in a SWAP of the area, and every name in a direct line."""
        if self.variables_made and isinstance(target, ast.Var):
            self.made_name(target.name, counted=True)

    def note_making(self, name: str) -> None:
        """The code being emitted makes ``name`` (a simple variable, or an array: ``A!()``)
        and tests that it is made first (compiler.made): one of its block's names, and of
        each native loop's around it (loops.unchecked_passes)."""
        self.cur.makes.add(name)
        for names in self.loop_makings:
            names.add(name)

    def made_name(self, name: str, counted: bool = False) -> None:
        """:meth:`made` for the simple variable called ``name`` (``counted``: taking its
        bytes as a variable; a DEF FN parameter's are the function's, memory_model)."""
        name = self.numbers.name(name)
        if counted and self.counts_made:
            self.note_making(name)
            self.emit(Refreshing(f"{MAKING}{name!r} not in _made: _mk({name!r})"))
        elif self.direct or name in self.watched:
            self.emit(f"_made.add({name!r})")

    def stmt_Swap(self, stmt, scope):
        first, kind = self.expr(stmt.first, scope)
        second, other = self.expr(stmt.second, scope)
        if kind != other:
            raise type_mismatch()
        if self.variables_made and isinstance(stmt.second, ast.Var):
            self.made(stmt.first)  # the first PTRGET made it before the second fails
            self.emit(f"_swap2({self.numbers.name(stmt.second.name)!r}, {second})")
        t = self.new_temp()
        self.emit(f"{t} = {first}")
        self.assign(stmt.first, second, kind, scope, False)
        self.assign(stmt.second, t, kind, scope, False)
        if kind == "s" and self.fields_bind:
            self.swap_fields(stmt, scope)

    def stmt_MidAssign(self, stmt, scope):
        target = self.string(stmt.target, scope)
        if self.late_errors:
            # GW (BISTRS.ASM LHSMID) checks the start and the count as it reads them (GETBYT),
            # then evaluates the value, then finds it a string (FRESTR): MID$(A$,0)=5 is
            # Illegal function call, not Type mismatch; a statement read only so far stops there
            start, count = self.new_temp(), "None"
            self.emit(f"{start} = _byte({self.numeric(stmt.start, scope)}, 1)")
            if stmt.count is not None:
                count = self.new_temp()
                self.emit(f"{count} = _byte({self.numeric(stmt.count, scope)})")
            if stmt.error is not None:
                self.emit(f"raise _err({stmt.error.message!r}, {stmt.error.code})")
                return
            value = self.when_reached(lambda: self.string(stmt.value, scope))
        else:
            start, value = self.numeric(stmt.start, scope), self.string(stmt.value, scope)
            count = "None" if stmt.count is None else self.numeric(stmt.count, scope)
        # the target itself as the value: GW copies it onto itself byte by byte (overlapping)
        same = stmt.value == stmt.target and self.numbers.typed
        self.assign(stmt.target, f"_midset({target}, {start}, {count}, {value}, {same})", "s", scope, False)

    def stmt_Erase(self, stmt, scope):
        for name in stmt.names:
            self.emit(f"_erase({self.numbers.name(name)!r})")

    def stmt_OptionBase(self, stmt, scope):
        self.emit(f"_option_base({stmt.base})")

    # -- RETURN n, DEF FN, errors, RANDOMIZE, IF
    def stmt_ReturnTo(self, stmt, scope):
        jump = self.jump(stmt.target)
        self.emit("_return()")
        self.emit(jump)

    def stmt_Touch(self, stmt, scope):
        self.emit(self.expr(stmt.target, scope)[0])
        self.emit(f"raise _err({stmt.error.message!r}, {stmt.error.code})")

    def stmt_CutShort(self, stmt, scope):
        getattr(self, "stmt_" + type(stmt.statement).__name__)(stmt.statement, scope)
        self.emit(f"raise _err({stmt.error.message!r}, {stmt.error.code})")

    def stmt_DefFn(self, stmt, scope):
        self.fn_count += 1
        fname = function = f"_fn_{self.fn_count}"
        params = ", ".join("p" + local_name(self.numbers.name(p)) for p in stmt.params)
        if not self.dynamic_types:
            self.prelude.append(f"def {fname}({params}):\n    {self.fn_body(stmt, self.numbers.kind(stmt.name))}\n")
        else:
            # the parameters and the body's names typed by the DEF types when it is called
            # (each variant of the area has its own function, found by name then), its result
            # by the type its name had when the DEF ran (GWEVAL.ASM FNDOFN: the value is
            # checked against the function's variable, made by DEF): one for each such type
            function = repr(function)
            results = (stmt.name[-1],) if stmt.name[-1] in "$%!#" else ("$", "%", "!", "#")
            for result in results:
                name = variant_function(fname, self.numbers.def_types(), result)
                self.prelude.append(f"def {name}({params}):\n    {self.fn_body(stmt, 's' if result == '$' else result)}\n")
        names = tuple(self.numbers.name(p) for p in stmt.params)  # DEF's PTRGET makes each one's variable
        self.emit(f"_dfn({self.numbers.name(stmt.name)!r}, {function}, {names!r})")

    def fn_body(self, stmt, fn_kind: str) -> str:
        """The Python statement of DEF FN ``stmt``'s body giving a value of type ``fn_kind``
        (``"s"`` or a number's type character): its value converted, or its error."""
        try:
            if isinstance(stmt.body, BasicError):
                raise stmt.body
            fn_scope = FnScope(self, stmt.params)
            body, kind = self.expr(stmt.body, fn_scope)
            if (kind == "s") != (fn_kind == "s"):
                raise type_mismatch()
            if kind != "s":
                body = self.numbers.convert(body, kind, fn_kind)
            return f"return {body}"
        except BasicError as err:
            if not self.late_errors:
                raise
            # GW-BASIC's DEF only notes where the body is: its errors come when it is called
            return f"raise _err({err.message!r}, {err.code})"

    def stmt_DefType(self, stmt, scope):
        """Applied to the whole area before compiling where that gives GW's types
        (blocks.types_fixed); else a switch of the type table when it runs: the machine goes
        on in the area compiled for the new table, from the next block (as TRON does)."""
        if not self.dynamic_types:
            return
        ranges = [first + last for first, last in stmt.ranges]
        area = None if self.direct else self.area  # None: the direct line (Machine.use_def_types)
        self.hand_over(f"_M.set_def_types({area}, {stmt.kind!r}, {ranges!r})")

    def stmt_Resume(self, stmt, scope):
        if stmt.mode == "bad":
            self.emit("if not _M.in_handler: _resume(False)")  # RESUME without error, not trappable
            self.emit(f"raise _err({stmt.error.message!r}, {stmt.error.code})")
            return
        if stmt.mode == "line":
            block = self.block_of_line(stmt.target)
            if block is None:
                self.emit(self.jump(stmt.target))
                return
            self.emit(f"return _resume_at({block})")
        else:
            self.emit(f"return _resume({stmt.mode == 'next'})")

    def stmt_SetClock(self, stmt, scope):
        self.emit(f"_M.clock.set({stmt.name!r}, {self.string(stmt.value, scope)})")

    def stmt_Error(self, stmt, scope):
        self.emit(f"_error({self.integer(stmt.code, scope)})")

    def stmt_DefMachine(self, stmt, scope):
        """DEF SEG and DEF USR (``Dialect.def_seg_usr``): their number read and kept."""
        if not self.def_seg_usr:
            raise syntax_error()
        value = "None" if stmt.value is None else self.numeric(stmt.value, scope)
        self.emit(f"_M.define_machine({stmt.word!r}, {value})")

    def stmt_Randomize(self, stmt, scope):
        if stmt.seed is not None and self.kind_of(stmt.seed) == "s":
            # GW-BASIC 3.23 takes the seed as a number without FRCINT: a string is Illegal
            # function call there (PC-BASIC 2.0.8), not Type mismatch
            self.emit(f"raise _err('Illegal function call', {ILLEGAL_FUNCTION_CALL})")
            return
        seed = "None" if stmt.seed is None else self.numeric(stmt.seed, scope)
        self.emit(f"_randomize({seed}, {self.seed_kind(stmt.seed)!r})")

    def seed_kind(self, node) -> str:
        """The BASIC type RANDOMIZE sees its argument stored as (randomness.py): a
        variable's own type (``%`` ``!`` ``#``, DEF types included); an unsigned integer
        literal up to 32767 is ``%``, a double literal ``#``; any other expression ``!``
        (PC-BASIC 2.0.8 reads ``-1`` and ``0-1`` as singles here)."""
        if isinstance(node, ast.Num):
            if node.kind:  # gw: the literal's own type
                return node.kind
            return "%" if node.value == int(node.value) and 0 <= node.value <= 32767 else "!"
        if isinstance(node, (ast.Var, ast.Elem)):
            kind = self.kind_of(node)
            return kind if kind in ("%", "#") else "!"
        return "!"

    def stmt_WordStatement(self, stmt, scope):
        """A statement of the dialect's own words: its helper called with its arguments,
        each of the kind the table gives ("n", "s"; "format": SET's letter and digit)."""
        word = stmt.word
        devices = self.device_words
        if devices and word in devices.statements:
            writes = word in devices.writes_variables  # (POKE into a FIELD buffer)
            if writes:
                self.emit(STORE_LOCALS)
            device_statement(self, stmt, devices, scope)
            if writes:
                self.emit(LOAD_LOCALS)
            return
        commas = "," * max(len(stmt.args) - 1, 0)
        if not word.endswith("()") and stmt.marks not in (commas, "=" + commas):
            raise syntax_error()  # the casio words take no #, TO or comma after the last argument
        table = self.words.routine_calls if word.endswith("()") else self.words.statements
        least, most, helper, kind = table[word.removesuffix("()")]
        if not least <= len(stmt.args) <= most:
            raise syntax_error()
        if kind == "format":
            args = [repr(part) for part in _set_format(stmt.args[0])]
        elif kind == "any":
            args = [self.string(arg, scope) if self.kind_of(arg) == "s" else self.numeric(arg, scope)
                    for arg in stmt.args]
        elif kind == "s":
            args = [self.string(arg, scope) for arg in stmt.args]
        else:
            args = [self.numeric(arg, scope) for arg in stmt.args]
        writes = stmt.word in self.words.writes_variables
        if writes or stmt.word in self.words.reads_variables:
            self.emit(STORE_LOCALS)
        self.emit(f"{helper}({', '.join(args)})")
        if writes:
            self.emit(LOAD_LOCALS)  # the helper set variables: the block takes their new values

    def stmt_Angle(self, stmt, scope):
        self.emit(f"_M.set_angle({stmt.mode!r})")

    def stmt_If(self, stmt, scope):
        try:
            cond = self.condition(stmt.condition, scope)
        except CompileError as err:
            if not self.dynamic_types:
                raise
            # the error when it runs, the branches compiled all the same: each DEF type
            # table's variant of the area has the same blocks (stmt_DefType)
            cond = f"_fail({err.message!r}, {err.code})"
        branches = [b for b in (stmt.then, stmt.otherwise) if isinstance(b, list)]
        split = (self.plan.fine and bool(branches)) or any(
            splits(s, self.plan.bare_returns) or isinstance(s, (ast.While, ast.Wend)) or self.zero_trip_target(s)
            for b in branches for s in b)
        if not split:
            self.emit(f"if {cond}:")
            self.branch(stmt.then)
            if stmt.otherwise is not None:
                self.emit("else:")
                self.branch(stmt.otherwise)
            return
        if self.depth == 0:
            after = self.entry_block[self.index + 1]
            after_block = None
        else:
            after_block = self.new_block()
            after = after_block.number
        start, indent = self.cur, self.indent
        self.emit(f"if {cond}:")
        self.branch(stmt.then, after)
        self.cur, self.indent = start, indent
        self.emit("else:")
        if stmt.otherwise is not None:
            self.branch(stmt.otherwise, after)
        else:
            self.indent += 1
            self.emit(f"return {after}")
            self.indent -= 1
        self.cur, self.indent = after_block, 1
        if after_block is not None:
            self.emit(f"_ln = {self.line}")

    def branch(self, branch, after: int | None = None) -> None:
        """The statements of a THEN or ELSE, one indent deeper."""
        self.indent += 1
        self.depth += 1
        if isinstance(branch, int):
            self.emit(self.jump(branch))
        else:
            self.emit("pass")
            for stmt in branch:
                if self.plan.fine and after is not None:
                    self.statement_block()
                self.statement(stmt)
        if after is not None:
            self.block_next.setdefault(self.cur.number, after)
            self.emit(f"return {after}")
        self.depth -= 1
        self.indent -= 1

    def statement_block(self) -> None:
        """Start a new block for the branch statement that follows, where RESUME NEXT is
        used: an error in it goes on with the statement after it in the branch (GW-BASIC's
        RESUME NEXT goes to the statement after the failing one by its place in the text)."""
        block = self.new_block()
        self.block_next.setdefault(self.cur.number, block.number)
        self.emit(f"return {block.number}")
        self.cur, self.indent = block, 1
        self.emit(f"_ln = {self.line}")

    # -- the program walk
    def set_line(self, number) -> None:
        if self.cur.first_line is None:
            self.cur.first_line = number
        self.emit(f"_ln = {number}")
        self.line = number

    def walk(self, start: int, stop: int) -> None:
        """Emit top-level statements ``start``..``stop-1``."""
        i = start
        while i < stop:
            number, stmt = self.flat[i]
            self.index = i
            if i in self.entry_block:
                if self.cur is not None:
                    self.emit(f"return {self.entry_block[i]}")
                self.cur = self.blocks[self.entry_block[i]]
                self.indent = 1
                self.line = None
                if self.plan.fine:
                    self.block_next[self.cur.number] = self.entry_block.get(
                        min(e for e in self.plan.entries if e > i))
            if number != self.line:
                self.set_line(number)
            self.trace_line(i)
            if i in self.plan.native:
                i = self.native_loop(i)
                continue
            self.statement(stmt)
            i += 1

    def trace_line(self, i: int) -> None:
        """TRON: print ``[n]`` where statement ``i`` starts its line ``n``."""
        number = self.flat[i][0]
        if self.trace and self.line_first[number] == i:
            self.emit(f"_tr({number})")

    # -- the whole area
    def compile(self) -> CompiledArea:
        """Generate every block of the area (DEF types, DATA and DEF FN collected first)."""
        statements = [s for _, stmt in self.flat if not isinstance(stmt, BasicError)
                      for s in walk_statements(stmt) if isinstance(s, ast.DefType)]
        self.dynamic_types = bool(statements) and self.numbers.typed and (
            self.statement_types or not types_fixed(self.flat))
        if not self.dynamic_types:
            self.numbers.set_types(statements)
        if self.variables_made:
            self.watched = _watched_names(self.flat, self.numbers.name, self.common_variables)
            self.counts_made = self.counts_strings
        for i, (number, stmt) in enumerate(self.flat):
            for s in ([] if isinstance(stmt, BasicError) else data_statements(stmt)):
                self.data_lines.setdefault(number, len(self.data))
                self.data.extend((item, number) for item in split_data(s.text))
        for _, stmt in self.flat:
            for s in ([] if isinstance(stmt, BasicError) else walk_statements(stmt)):
                if isinstance(s, ast.DefFn):  # (a name typed by the DEF types as the DEF runs: each type)
                    typed = self.dynamic_types and s.name[-1] not in "$%!#"
                    for name in [s.name + c for c in "$%!#"] if typed else [self.numbers.name(s.name)]:
                        self.fn_params.setdefault(name, s.params)
        self.walk(0, len(self.flat))
        end = self.entry_block[len(self.flat)]
        if self.cur is not None:
            self.emit(f"return {end}")
        self.cur = self.blocks[end]
        self.indent = 1
        self.set_line(self.flat[-1][0] if self.flat else 0)
        if self.direct:  # a direct line's end is no END: a handler left running stays so (BIMISC.ASM ENDCON)
            self.emit("return -1")
        else:  # past a program's last line a handler still running is an error in GW
            self.emit("_off_end(_ln)")
            self.emit("raise _END")
        pieces = [(None, text) for text in self.prelude]
        self.checked_once, self.split_loops = _copies(self.blocks)
        pieces += [(b.first_line, self.block_source(b)) for b in self.blocks]
        if self.numbers.cache_bases:  # each cache the code uses matches nothing until its operation writes it
            pieces.insert(0, (None, self.numbers.cache_prelude("".join(text for _, text in pieces))))
        source = "\n".join(text for _, text in pieces)
        line_blocks = {number: self.entry_block[i] for number, i in self.line_first.items()
                       if i in self.entry_block}
        makings = {b.number: tuple(sorted(b.makes)) for b in self.blocks if b.makes}
        makings.update((flag, tuple(sorted(names))) for b in self.blocks for flag, names in b.loop_makes.items()
                       if flag in self.split_loops)
        return CompiledArea(
            source=source, pieces=pieces, block_count=len(self.blocks), line_blocks=line_blocks,
            block_next=self.block_next, data=self.data, data_lines=self.data_lines,
            scalars=set(self.scalars), first_line=self.flat[0][0] if self.flat else None,
            index_blocks=dict(self.entry_block), break_points=self.break_points,
            dynamic_loops=tuple(sorted(self.dynamic_loops)), def_types=self.numbers.def_types(),
            dynamic_types=self.dynamic_types, makings=makings,
        )

    def _pass_lines(self, block: _Block, out: list, points: dict, lines: dict, base: int,
                    checked: bool = True) -> None:
        """Append the lines of one pass of ``block`` to ``out`` (its break points to
        ``points``); ``lines``: the block's loads, stores and checks (block_source).
        ``checked=False``: the pass of a block whose names are all made, without the tests
        of its makings (compiler.made)."""
        load, load_arrays, store = lines["load"], lines["load_arrays"], lines["store"]
        loop_back, self_loop = lines["loop_back"], lines["self_loop"]
        pending = None  # a PassTop waiting for the line it marks
        for indent, text in _passes(block.code, self.split_loops, checked):
            pad = "    " * (indent + base)
            kind = type(text)
            if kind is not str:
                if kind is StoreLocals:
                    if store:
                        out.append(pad + store)
                    continue
                if kind is LoadLocals:
                    if load:
                        out.append(pad + load)
                    out += [pad + line for line in load_arrays]
                    continue
                if kind is ArraysCall:
                    if load_arrays:
                        out.append(pad + f"if {text.call}:")
                        out += [pad + "    " + line for line in load_arrays]
                    else:
                        out.append(pad + text.call)
                    if load:
                        out.append(pad + load)
                    continue
                if kind is Dimensioned:
                    if text.name in block.arrays:
                        out.append(pad + f"{array_local(text.name)} = _A[{text.name!r}]")  # just dimensioned
                    continue
                if kind is PassTop:
                    pending = self.break_infos[text.index]
                    continue
                if kind is StackCheck:
                    text = lines["full_check"]
                elif kind is Refreshing:
                    text = f"{text.code}; {lines['refresh']}"
            elif text[:1] == "#":
                raise AssertionError(f"a comment line in generated code: {text!r} (a marker is a markers.Marker)")
            if self_loop and (text == loop_back or text.endswith(": " + loop_back)):
                if text != loop_back:  # "if c: return b": the continue on a line of its own
                    out.append(pad + text[: -len(loop_back) - 1])
                    pad += "    "
                points[len(out) + 1] = (block.first_line, ())  # (lines count from 1: def is 1)
                text = "continue"
            if pending is not None:
                points[len(out) + 1], pending = pending, None
            out.append(pad + text)

    def block_source(self, block: _Block) -> str:
        """The Python text of one block function.

        Its break points (see :class:`CompiledArea`) go to ``self.break_points``:
        the ``continue`` lines of a block that loops back to its own start, and the
        line after each native loop's :class:`markers.PassTop`.
        """
        points: dict[int, tuple] = {}
        names = sorted(block.scalars)
        written = [n for n in names if block.scalars[n]]
        load = "; ".join(f"{local_name(n)} = _S[{n!r}]" for n in names)
        load_arrays = _array_loads(block.arrays, lazy=self.counts_made)
        refresh = f"_f = _f{block.number}"  # (compiler.made) with the arrays, which a call may have made
        refresh += "".join(f"; {array_local(a)} = _A.get({a!r})" for a in sorted(block.arrays))
        if block.makes:  # read again wherever the variables are: a call may have made or cleared them
            load = f"{load}; _f = _f{block.number}" if load else f"_f = _f{block.number}"
        store = "; ".join(f"_S[{n!r}] = {local_name(n)}" for n in written)
        loop_back = f"return {block.number}"
        self_loop = _loops_back(block) and not self.plan.polls_events
        # A GOSUB compiled in place checks for a full stack.  Every push onto the stack
        # ends its block, so unless the block pops (a NEXT through the stack), clears
        # or calls out, the stack's length cannot change while the block runs: it is
        # measured once, as the block starts.
        full_check = f"if {self.stack_full}: _oom()"
        if any(type(text) is StackCheck for _, text in block.code) and not any(
                name in text for _, text in block.code for name in _STACK_CHANGES):
            full_check = "if _full: _oom()"
        base = 2 if self_loop else 1
        out = [f"def _b{block.number}():"]
        if load:
            out.append("    " + load)
        out += ["    " + text for text in load_arrays]
        out.append("    _ln = None")
        if full_check == "if _full: _oom()":
            out.append(f"    _full = {self.stack_full}")
        out.append("    try:")
        lines = dict(load=load, load_arrays=load_arrays, store=store, refresh=refresh,
                     full_check=full_check, loop_back=loop_back, self_loop=self_loop)
        if block.number in self.checked_once:
            out.append("        while _f:")  # the passes that make a name: checked (compiler.made)
            self._pass_lines(block, out, points, lines, base)
            out.append("        while True:")  # then every pass without a test of its makings
            self._pass_lines(block, out, points, lines, base, checked=False)
        else:
            if self_loop:
                out.append("        while True:")
            self._pass_lines(block, out, points, lines, base)
        if not block.code:
            out.append("    " * (1 + base) + "pass")
        out.append("    finally:")
        if store:
            out.append("        " + store)
        out.append("        _M.line = _ln")
        if points:
            self.break_points[block.number] = points
        return "\n".join(out) + "\n"




class _EveryName:
    """Every name (a program that CHAINs with ALL passes each variable it made on)."""

    def __contains__(self, name) -> bool:
        return True


def _watched_names(flat, full_name, common_variables):
    """The simple variables whose making an area records (compiler.made): the second of a
    SWAP (it must exist), and those a CHAIN passes on made to a program whose SWAP may ask
    (COMMON's; with CHAIN ... ALL every one).  ``full_name``: a name with its type;
    ``common_variables``: a COMMON's (name, is an array) pairs."""
    statements = [s for _, stmt in flat if not isinstance(stmt, BasicError) for s in walk_statements(stmt)]
    chains = [s for s in statements if isinstance(s, ast.Chain) and s.run]
    if any(chain.everything for chain in chains):
        return _EveryName()
    names = {full_name(s.second.name) for s in statements if isinstance(s, ast.Swap) and isinstance(s.second, ast.Var)}
    if chains:
        names.update(full_name(name) for s in statements if isinstance(s, ast.Common)
                     for name, is_array in common_variables(s) if not is_array)
    return frozenset(names)


# An array made where it is first read (expressions.BlockScope.array): code that runs only
# once its names are made reads the local itself.
_LAZY_ARRAY = r"\(((?:a|b|ai|ad)_\w+) or \(\1 := _arr\('[^']+', \d+\)\)\)"


def _arrays_made(text: str) -> str:
    """``text`` with each array made where it is first read replaced by its local; re is imported
    only for a line that makes one (a cold start of a listing without one does not load it)."""
    if " := _arr(" not in text:
        return text
    import re

    return re.sub(_LAZY_ARRAY, r"\1", text)


def _passes(code: list, split: set, checked: bool = True) -> list:
    """Generated lines (indent, text) as they run: the native loops marked with a
    :class:`LoopSplit` whose key is in ``split`` (loops.unchecked_passes, :func:`_copies`)
    in two loops, the passes with the tests of their makings while the loop's flag is true,
    then the rest without (a ``for`` loop's items from one iterator both share, a ``while``
    loop's test starting with the flag; its arrays bound again between: a function may
    have made one); any other loop as it is, its passes with the tests.  ``checked=False``:
    for code that runs only once every name it makes is made, without those tests and
    with each loop as it was."""
    out = []
    k = 0
    while k < len(code):
        indent, text = code[k]
        if checked and type(text) is LoopSplit and text.key in split:
            end = k + 1
            while end < len(code) and code[end][0] > indent:
                end += 1
            body = code[k + 1:end]
            k = end
            flag, n, target, items = f"_f{text.key}", text.n, text.target, text.items
            rebind = [(indent, f"{array_local(a)} = _A.get({a!r})") for a in text.arrays]
            if target is None:
                out += [(indent, f"while {flag} and {items}:"), *_passes(body, split), *rebind,
                        (indent, f"while {items}:")]
            else:
                out += [(indent, f"_j{n} = iter({items})"), (indent, f"if {flag}:"),
                        (indent + 1, f"for {target} in _j{n}:"), *((j + 1, line) for j, line in _passes(body, split)),
                        (indent + 2, f"if not {flag}: break"), *rebind, (indent, f"for {target} in _j{n}:")]
            out += _passes(body, split, False)
            continue
        k += 1
        if not checked:
            if text.startswith(MAKING):  # (a "pass" where the making stood alone in its suite)
                if k < len(code) and code[k][0] == indent:
                    continue
                text = "pass"
            if type(text) is str:  # (a marker keeps its type)
                text = _arrays_made(text)
        out.append((indent, text))
    return out


def _loops_back(block: _Block) -> bool:
    """Does ``block`` jump back to its own start (its passes run in a ``while`` loop)?"""
    loop_back = f"return {block.number}"
    return any(text == loop_back or text.endswith(": " + loop_back) for _, text in block.code)


# The copies of code the makings' tests cost (compiler.made, :func:`_copies`): at most a
# quarter of the area's code, or this many characters
COPIES_SHARE = 4
COPIES_LEAST = 16_000


def _source_size(lines, levels: int) -> int:
    """Characters ``lines`` ((indent, text) of a block's code) take in the Python source,
    each indented ``levels`` more than its own indent (4 characters a level), with its line end."""
    return sum(4 * (indent + levels) + len(text) + 1 for indent, text in lines)


def _copies(blocks: list) -> tuple[set, set]:
    """The code copied so that later passes run without the tests of their makings
    (compiler.made): the blocks that loop back to their own start and test their makings
    only while one is not made (their passes run in two loops, with the tests while the
    block's ``_f`` is true, without them from the first pass that starts with every name
    made; not a block that can unmake a name, CLEAR or ERASE, and go on), and the native
    FOR loops run in two (loops.unchecked_passes: a :class:`LoopSplit`'s key).  Each is a
    second copy of its code to compile: the smallest first, of both kinds together, while
    the copies add at most a quarter of the area's code (or 16,000 characters): a test
    weighs most in a small loop's pass (in a long one it is a few per cent at most).

    Sizes are characters of the source: the area's at least (each line a block function's
    level in), a copy's at most (a block's pass two levels in, a loop's checked passes one
    more and one for each loop copied around it, its extra first lines and arrays bound
    again), so the copies stay within the budget.  Returns (the block numbers, the loops' keys)."""
    budget = max(COPIES_LEAST, sum(_source_size(b.code, 1) for b in blocks) // COPIES_SHARE)
    candidates = []
    for block in blocks:
        code = block.code
        if block.makes and _loops_back(block) and not any("_clear(" in text or "_erase(" in text for _, text in code):
            candidates.append((_source_size(code, 2) + 40, 0, block.number))  # (and its "while True:")
        around: list[int] = []  # the indents of the loops marked around a line
        for k, (indent, text) in enumerate(code):
            while around and around[-1] >= indent:
                around.pop()
            if type(text) is not LoopSplit:
                continue
            end = k + 1
            while end < len(code) and code[end][0] > indent:
                end += 1
            levels = 3 + len(around)
            size = _source_size(code[k + 1:end], levels) + 3 * _source_size([(indent, text)], levels)
            candidates.append((size + 60 * (1 + len(text.arrays)), 1, text.key))
            around.append(indent)
    chosen: tuple[set, set] = (set(), set())
    for size, kind, key in sorted(candidates, key=lambda c: c[0]):
        budget -= size
        if budget < 0:
            break
        chosen[kind].add(key)
    return chosen


def _array_loads(arrays: dict[str, int], lazy: bool = False) -> list[str]:
    """The lines binding a block's arrays (name -> dimensions) to its locals: subscripts of the
    dictionary of arrays where all exist (a method call each cost a GOSUB PROG, which reloads
    them after the call, a few microseconds), else each made as the block starts as ``_arr``
    does.  ``lazy`` (an area that counts its makings: compiler.made): None for one not made
    yet, which the block makes where it first uses it (expressions.BlockScope.array)."""
    if not arrays:
        return []
    names = sorted(arrays)
    if lazy:
        return ["; ".join(f"{array_local(a)} = _A.get({a!r})" for a in names)]
    return [f"try: {'; '.join(f'{array_local(a)} = _A[{a!r}]' for a in names)}",
            f"except KeyError: {'; '.join(f'{array_local(a)} = _A.get({a!r}) or _arr({a!r}, {arrays[a]})' for a in names)}"]


def split_data(text: str) -> list[str]:
    """The items of a DATA statement's text: commas outside quotes separate them."""
    items, current, quoted = [], [], False
    for ch in text:
        if ch == '"':
            quoted = not quoted
            current.append(ch)
        elif ch == "," and not quoted:
            items.append("".join(current).strip())
            current = []
        else:
            current.append(ch)
    items.append("".join(current).strip())
    return items


def compile_area(lines: list, area: int = 0, direct: bool = False, entry_lines=(),
                 trace: bool = False, dynamic_loops=(), dialect=CASIO, def_types=None,
                 statement_types: bool = False, base_one: bool = False) -> CompiledArea:
    """Compile an area's parsed lines (``syntax_tree.Line`` in line order) for ``dialect``.

    ``entry_lines`` are lines that must start a block although no jump names
    them (RUN n, or a GOTO typed in direct mode); ``trace`` compiles the TRON
    variant (see the module docstring); ``dynamic_loops`` are the statement
    indices of FOR loops to run through the FOR stack even where they could be
    native (CONT resumes a native loop broken by Ctrl-C that way); ``statement_types``
    compiles DEFINT ... as switches of the type table where they run even where
    applying them first would do (a RUN n typed in direct mode skips those before n);
    ``base_one``: OPTION BASE 1 is in force as the code is made (no subscript 0 read
    unchecked, whether or not the area holds an OPTION BASE).
    """
    compiler = AreaCompiler(lines, area, direct, entry_lines, trace, dynamic_loops, dialect, def_types,
                            statement_types, base_one)
    compiled = compiler.compile()
    if compiler.numbers.cache_bases and sum(len(text) for _, text in compiled.pieces) > CACHED_CODE_LIMIT:
        compiler = AreaCompiler(lines, area, direct, entry_lines, trace, dynamic_loops, dialect, def_types,
                                statement_types, base_one)
        compiler.numbers.caching = False  # the code without them (the machine's limit is 4 MB)
        compiled = compiler.compile()
    return compiled


# Python characters of an area beyond which its single operations go without their binade
# caches (number_models: they add about a third to the code of a program of arithmetic)
CACHED_CODE_LIMIT = 3 * 1024 * 1024
