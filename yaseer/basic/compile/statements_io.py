"""PRINT, WRITE, INPUT, READ and the file statements -> Python: the statements that
move data in and out, one half of the area compiler (``AreaCompiler`` in compiler.py
mixes it in).  The machine's helpers they call are in runtime.py and files.py.
"""

from __future__ import annotations

from contextlib import contextmanager

from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.compile.expressions import CompileError, syntax_error, type_mismatch
from yaseer.basic.compile.markers import LOAD_LOCALS, STORE_LOCALS
from yaseer.basic.errors import (
    BasicError, ILLEGAL_FUNCTION_CALL, MISSING_OPERAND, OUT_OF_DATA, PATH_FILE_ACCESS_ERROR, SYNTAX_ERROR, UNDEFINED_LINE,
    error_message, undefined_line_message,
)


def _is_safe_item(item) -> bool:
    """A PRINT item whose evaluation cannot fail (so items may be evaluated together)."""
    return isinstance(item, (str, ast.Num, ast.Str, ast.Var))


def _print_chunks(parts: list) -> list:
    """PRINT items split so that each chunk holds one thing to evaluate (a value with the
    ``_NUMCOMMA`` mark before it, TAB or SPC) and the commas after it: each comma moves
    the cursor before the next item is evaluated, so a message that item prints
    (``Overflow``) lands where GW-BASIC prints it.  Leading commas are a chunk of their own."""
    chunks, current, evaluated = [], [], False
    for part in parts:
        if part != "_COMMA":
            if evaluated or (current and current[-1] == "_COMMA"):
                chunks.append(current)
                current, evaluated = [], False
            evaluated = part != "_NUMCOMMA"
        current.append(part)
    if current or not chunks:
        chunks.append(current)
    return chunks


# The one ACCESS each sequential mode allows (GW-BASIC 3.23 as recorded, see stmt_Open)
_ACCESS_OF_MODE = {"I": "R", "O": "W", "A": "RW"}


class InputOutputCompiler:
    """The input and output statements of ``AreaCompiler`` (they use its ``emit``,
    ``assign`` and expression methods)."""

    def print_items(self, items, scope) -> tuple[list, bool]:
        """The Python parts of PRINT items (values, _COMMA, _Tab, _Spc) and whether a newline ends it."""
        parts = []
        for k, item in enumerate(items):
            if item == ",":
                parts.append("_COMMA")
            elif item == ";":
                continue
            elif isinstance(item, ast.Tab):
                parts.append(f"_Tab({self.numeric(item.column, scope)})")
            elif isinstance(item, ast.Spc):
                parts.append(f"_Spc({self.numeric(item.count, scope)})")
            else:
                try:
                    code, kind = self.expr(item, scope)
                except CompileError as err:  # e.g. Type mismatch: the items before it still print
                    parts.append(f"_fail({err.message!r}, {err.code})")
                    return parts, False
                if kind != "s" and items[k + 1:k + 2] == [","]:
                    parts.append("_NUMCOMMA")  # a number a comma follows (see Machine._blank_before_comma)
                codes = [code]
                self.held([item], codes, used_up=True)  # a new string printed gives its bytes back (STRPRT)
                parts.append(self.numbers.printable(codes[0], kind))
        # a PRINT ending in a separator, TAB(n) or SPC(n) keeps the line open
        newline = not items or not (items[-1] in (",", ";") or isinstance(items[-1], (ast.Tab, ast.Spc)))
        return parts, newline

    def stmt_Print(self, stmt, scope):
        """PRINT / LPRINT [USING]: items are printed as they are evaluated, so an item
        that fails leaves the ones before it on the screen (as GW-BASIC does)."""
        if stmt.lead:  # PRINT items USING ...: the items first, the line left open
            lead = list(stmt.lead) + ([] if stmt.lead[-1] in (",", ";") else [";"])
            self.stmt_Print(ast.Print(stmt.printer, lead, channel=stmt.channel), scope)
            stmt = ast.Print(stmt.printer, stmt.items, using=stmt.using, channel=stmt.channel)
        device, pr, pru = 1 if stmt.printer else 0, "_pr", "_pru"
        if stmt.channel is not None:  # PRINT #n: the file's stream, found once
            device = self.new_temp()
            self.emit(f"{device} = _fout({self.numeric(stmt.channel, scope)})")
            with self.record_buffer(device):
                self._print_list(stmt, scope, device, "_prf", "_pruf")
            return
        self._print_list(stmt, scope, device, pr, pru)

    def _print_list(self, stmt, scope, device, pr, pru):
        """The items of a PRINT [USING] on ``device`` (a number, or the temporary holding a
        file's stream) by the machine's functions ``pr`` and ``pru``."""
        parts, newline = self.print_items(stmt.items, scope)
        safe = all(_is_safe_item(item) for item in stmt.items)
        if stmt.using is None:
            chunks = _print_chunks(parts) if not safe else [parts]
            for k, chunk in enumerate(chunks):
                last = k == len(chunks) - 1
                values = "(" + "".join(p + ", " for p in chunk) + ")"
                self.emit(f"{pr}({device}, {values}, {newline and last}, {last})")
            return
        fmt = self.string(stmt.using, scope)
        parts = [p for p in parts if p not in ("_COMMA", "_NUMCOMMA") and not p.startswith(("_Tab(", "_Spc("))]
        if safe:  # nothing to evaluate can fail or be seen: all at once (the loops' fast path)
            values = "(" + "".join(p + ", " for p in parts) + ")"
            self.emit(f"{pru}({device}, {fmt}, {values}, {newline})")
            return
        if self.using_each_value:  # each value when its field is reached (Machine.using_line)
            line = self.new_temp()
            self.emit(f"{line} = {'_puo' if stmt.channel is None else '_puof'}({device}, {fmt})")
            for k, part in enumerate(parts):
                self.emit(f"{line}.put({part}, {k < len(parts) - 1})")
            self.emit(f"{line}.end({newline})")
            return
        self.emit("_u = []")
        self.emit("try:")
        for part in parts:
            self.emit(f"    _u.append({part})")
        self.emit("except BaseException:")
        self.emit(f"    {pru}({device}, {fmt}, _u, False)")
        self.emit("    raise")
        self.emit(f"{pru}({device}, {fmt}, _u, {newline})")

    def stmt_Write(self, stmt, scope):
        if stmt.channel is not None:
            stream = self.new_temp()
            self.emit(f"{stream} = _fout({self.numeric(stmt.channel, scope)})")
            with self.record_buffer(stream):
                self.emit(f"_writef({stream}, ({self.written_items(stmt.items, scope)}), {stmt.cut!r})")
            return
        self.emit(f"_write(0, ({self.written_items(stmt.items, scope)}), {stmt.cut!r})")

    @contextmanager
    def record_buffer(self, stream: str):
        """Around PRINT # or WRITE # code on ``stream``: where it is a random file's record
        buffer (its ``file`` set), the variables are the machine's while it writes (FIELD's
        variables show the buffer, random_files.RecordStream), also when it stops with an
        error part way."""
        self.emit(f"if {stream}.file is not None:")
        self.emit("    pass")
        self.indent += 1
        self.emit(STORE_LOCALS)
        self.indent -= 1
        self.emit("try:")
        self.indent += 1
        yield
        self.indent -= 1
        self.emit("finally:")
        self.emit(f"    if {stream}.file is not None:")
        self.emit("        pass")
        self.indent += 2
        self.emit(LOAD_LOCALS)
        self.indent -= 2

    def written_items(self, items, scope) -> str:
        """WRITE's items as Python text pieces: strings in quotes, numbers as STR$ gives
        them without the blank (the caller joins them with commas)."""
        pieces = []
        for item in items:
            code, kind = self.expr(item, scope)
            if kind == "s":
                pieces.append(f"'\"' + {code} + '\"'")
            else:
                pieces.append(f"_strs({self.numbers.printable(code, kind)}).strip()")
        return "".join(piece + ", " for piece in pieces)

    def stmt_Input(self, stmt, scope):
        if stmt.channel is not None:  # INPUT #n: one field for each variable, stored at once
            file = self.input_file(stmt.channel, scope)
            for target in stmt.targets:
                kind = self.kind_of(target)
                reader = "_fin_s" if kind == "s" else "_fin_n"
                try:
                    self.assign(target, f"{reader}({file})", "s" if kind == "s" else self.numbers.widest,
                                scope, self.numbers.typed and kind != "s")
                except CompileError as err:  # a bad subscript: after the file and the items before it
                    self.emit(f"_fail({err.message!r}, {err.code})")
                    break
            return
        if (stmt.names_cut or stmt.keeps_row) and not self.input_answer_first:
            raise syntax_error()  # INPUT; and a list cut short: GW's forms only
        if stmt.names_cut:  # asked and answered, then the missing name refused
            self.emit(f"_input_cut({stmt.prompt!r}, {stmt.question_mark}, {stmt.keeps_row})")
            return
        if stmt.asks is not None and not self.words.asks_each:
            raise syntax_error()  # a message before a later variable: the Casio's form only
        if self.words.asks_each and len(stmt.targets) > 1:  # one answer, one EXE, for each variable
            asks = stmt.asks or [(stmt.prompt, stmt.question_mark)] + [None] * (len(stmt.targets) - 1)
            for target, ask in zip(stmt.targets, asks):
                prompt, question = ask or (None, True)
                self._input_into([target], prompt, question, stmt.at, scope)
            return
        self._input_into(stmt.targets, stmt.prompt, stmt.question_mark, stmt.at, scope, stmt.keeps_row)

    def _input_into(self, targets, prompt, question_mark, at, scope, keeps_row=False):
        """One INPUT's question: ``prompt`` (and "?"), then one line of answers for ``targets``."""
        kinds = "".join("s" if self.kind_of(t) == "s" else "n" for t in targets)
        values = self.new_temp()
        limit = f", {at}" if at is not None else ""  # INPUT @n;: at most n characters
        limit += ", keeps_row=True" if keeps_row else ""
        self.emit(f"{values} = _input({prompt!r}, {question_mark}, {kinds!r}, {self.asking_again()}{limit})")
        for n, target in enumerate(targets):
            value = f"{values}[{n}]"
            if kinds[n] == "n" and not self.numbers.typed:  # None: an empty answer keeps the value
                value = f"({value} if {value} is not None else {self.expr(target, scope)[0]})"
            elif kinds[n] == "s" and self.counts_strings:  # copied out of the keyboard buffer (LETCN6)
                value = f"_scopy({value})"
            self.assign(target, value, "s" if kinds[n] == "s" else self.numbers.widest,
                        scope, self.numbers.typed and kinds[n] != "s")

    def stmt_Bank(self, stmt, scope):
        """The DATA BANK's statements (yaseer/basic/machine/databank.py), casio only."""
        word, args = stmt.word, stmt.args
        if word == "WRITE#":
            pieces = "".join((self.string(a, scope) if self.kind_of(a) == "s" else
                              f"_strs({self.numeric(a, scope)})") + ", " for a in args)
            self.emit(f"_bank().write(({pieces}))")
        elif word == "READ#":
            if not args or not all(isinstance(a, (ast.Var, ast.Elem)) for a in args):
                raise syntax_error()
            for target in args:
                text = self.kind_of(target) == "s"
                self.assign(target, "_bank().read()" if text else "_bank().read_number(_M)",
                            "s" if text else self.numbers.widest, scope, False)
        elif word == "RESTORE#":
            self._bank_restore(args, scope)
        elif word in ("LIST#", "LLIST#", "NEW#") and not args:
            self.emit("_bank().clear(_M)" if word == "NEW#" else f"_bank().list(_M, {int(word == 'LLIST#')})")
        elif word == "SAVE#" and len(args) == 1:
            self.emit(f"_bank().save(_M, {self.string(args[0], scope)})")
        elif word == "LOAD#" and len(args) in (1, 2):
            if len(args) == 2 and not (isinstance(args[1], ast.Var) and args[1].name == "M"):
                raise syntax_error()  # LOAD# "file", M: append
            self.emit(f"_bank().load_file(_M, {self.string(args[0], scope)}, {len(args) == 2})")
        else:
            raise syntax_error()

    def _bank_restore(self, args, scope) -> None:
        """RESTORE#; RESTORE# "text"[, mode][, line]: not found is Out of DATA, or a jump to line."""
        if not args:
            self.emit("_bank().restore()")
            return
        if len(args) > 3:
            raise syntax_error()
        mode = f"int({self.numeric(args[1], scope)})" if len(args) >= 2 else "0"
        found = f"_bank().find({self.string(args[0], scope)}, {mode})"
        if len(args) == 3:
            if not isinstance(args[2], ast.Num):
                raise syntax_error()
            self.emit(f"if not {found}: {self.jump(int(args[2].value))}")
            return
        self.emit(f"if not {found}: raise _err('Out of DATA', {OUT_OF_DATA})")

    def input_file(self, channel, scope) -> str:
        """A temporary holding the file INPUT # or LINE INPUT # reads, found (open for input or
        random, else ``Bad file mode``) once and before any variable's subscripts are read
        (GWMAIN.ASM FILSTI and DSKCOM.ASM DLINE call FILINP, GIO86.ASM FILGET, first)."""
        file = self.new_temp()
        self.emit(f"{file} = _M.files.checked({self.integer(channel, scope)}, 'IR')")
        return file

    def stmt_LineInput(self, stmt, scope):
        if stmt.channel is not None:
            file = self.input_file(stmt.channel, scope)
            try:
                self.assign(stmt.target, f"_fline({file})", "s", scope, False)
            except CompileError as err:  # a bad subscript: after the file
                self.emit(f"_fail({err.message!r}, {err.code})")
            return
        if stmt.keeps_row and not self.input_answer_first:
            raise syntax_error()  # LINE INPUT; : GW's form only
        keeps_row = ", True" if stmt.keeps_row else ""
        self.assign(stmt.target, f"_line_input({stmt.prompt!r}, {self.asking_again()}{keeps_row})", "s", scope, False)

    def asking_again(self) -> tuple | None:
        """For an INPUT or LINE INPUT that starts its block of area 0 (a top-level one):
        (that block, its line), where CONT after a Ctrl-C while it waits goes on, asking
        again (GW-BASIC); None for one inside an IF branch or another area."""
        if self.depth == 0 and self.index in self.entry_block and self.area == 0 and not self.direct:
            return self.cur.number, self.line
        return None

    def stmt_Read(self, stmt, scope):
        for target in stmt.targets:
            kind = "s" if self.kind_of(target) == "s" else self.numbers.widest
            self.assign(target, "_read_s()" if kind == "s" else "_read_n()", kind, scope,
                        self.numbers.typed and kind != "s")  # beyond the range: Overflow's policy
        if self.read_commits:
            self.emit("_read_end()")

    def stmt_Restore(self, stmt, scope):
        if stmt.target is not None and not isinstance(stmt.target, int):  # RESTORE (expression)
            if not self.words.computed_restore:
                # BIMISC.ASM RESTORE: LINGET reads no digits, line 0, then the rest is no statement's end
                self.stmt_Restore(ast.Restore(0), scope)
                self.emit(f"raise _err('Syntax error', {SYNTAX_ERROR})")
                return
            self.emit(f"_restore_at({self.numeric(stmt.target, scope)})")
            return
        if stmt.target is not None and stmt.target not in self.line_first:
            message = undefined_line_message(stmt.target, self.names_missing_line)
            self.emit(f"raise _err({message!r}, {UNDEFINED_LINE})")
            return
        self.emit(f"_restore({stmt.target!r})")

    def stmt_Open(self, stmt, scope):
        """OPEN; GW-BASIC 3.23's ACCESS clause must suit the FOR mode (as a real GW-BASIC 3.23
        recorded it, PC-BASIC's OPEN2 test: INPUT only ACCESS READ, OUTPUT only ACCESS WRITE,
        APPEND ACCESS READ WRITE, and ACCESS WRITE Path/File access error when it runs;
        RANDOM any), else Syntax error; the clauses go to the file table
        (machine/file_locks.py)."""
        length = "None" if stmt.length is None else self.integer(stmt.length, scope)
        clauses = ""
        if stmt.access is not None or stmt.lock is not None:
            mode = stmt.mode.value[:1].upper()
            if stmt.access is not None and mode != "R" and stmt.access != _ACCESS_OF_MODE.get(mode, stmt.access):
                if (mode, stmt.access) == ("A", "W"):
                    self.emit(f"raise _err({error_message(PATH_FILE_ACCESS_ERROR)!r}, {PATH_FILE_ACCESS_ERROR})")
                    return
                raise syntax_error()
            clauses = f", {stmt.access!r}, {stmt.lock!r}"
        self.emit(f"_open({self.string(stmt.mode, scope)}, {self.integer(stmt.number, scope)}, "
                  f"{self.string(stmt.name, scope)}, {length}{clauses})")

    # -- random-access files (random_files.py): a fielded variable is named by its key
    def field_key(self, target, scope, made: bool = True) -> str:
        """Python code for the key of a FIELD or LSET variable (a string variable, DSKCOM.ASM
        ``PTRGET`` then ``FRCSTR``): a scalar's name, or an array element's (array name,
        subscripts), the machine making the array if there is none (``made`` False: the
        array is there, SWAP having read the element)."""
        if self.kind_of(target) != "s":
            raise type_mismatch()
        name = self.numbers.name(target.name)
        if isinstance(target, ast.Var):
            return repr(name)
        subscripts = self.subscripts(target, scope)
        if made:
            scope.array(target.name, len(subscripts), made=True)  # its local reloaded after the call
        return f"({name!r}, ({''.join(code + ', ' for code in subscripts)}))"

    def swap_fields(self, stmt, scope) -> None:
        """After SWAP of two strings, where FIELD is a word: a variable fielded on an open
        file goes on pointing into its buffer under the other name (BIMISC.ASM SWAP
        exchanges the two descriptors with VMOVE, and a fielded one points into the
        record buffer: DSKCOM.ASM FIELD).  ``stmt.first`` now holds what ``stmt.second``
        held and the reverse (machine.swap_fields sees which of them a file gave)."""
        first, second = self.field_key(stmt.first, scope, False), self.field_key(stmt.second, scope, False)
        now_first, now_second = self.string(stmt.first, scope), self.string(stmt.second, scope)
        self.emit(f"if _M.files.open_files: _swapf({first}, {second}, {now_first}, {now_second})")

    def stmt_Field(self, stmt, scope):
        """FIELD #n, w AS v, ...: the file first (a random one), then each width and its
        variable in turn (DSKCOM.ASM FIELD: FILSCN, then GTBYTC and PTRGET for each)."""
        file, offset = self.new_temp(), self.new_temp()
        self.emit(f"{file} = _M.files.random({self.integer(stmt.number, scope)})")
        for _, target in stmt.fields:
            if isinstance(target, ast.Var):
                scope.scalar(target.name)  # known to the machine from the start
                self.made(target)  # FIELD's PTRGET makes it (a SWAP may ask: compiler.made)
        self.emit(f"{offset} = 0")
        self.emit(STORE_LOCALS)  # FIELD stores the variables' slices in the machine's scalars
        self.emit("try:")
        for node, target in stmt.fields:
            width = self.when_reached(lambda: self.integer(node, scope))
            try:
                key = self.field_key(target, scope)
            except CompileError as err:  # after the width is read (GETBYT before PTRGET)
                self.emit(f"    _field({file}, {offset}, {width}, None)")
                self.emit(f"    _fail({err.message!r}, {err.code})")
                break
            self.emit(f"    {offset} = _field({file}, {offset}, {width}, {key})")
        self.emit("finally:")  # those fielded before an error keep their values
        self.indent += 1
        self.emit("pass")
        self.emit(LOAD_LOCALS)
        self.indent -= 1

    def stmt_FileFirst(self, stmt, scope):
        """A file statement cut after its file number: the file's checks, then its error
        (INPUT$'s: its count read as a byte first)."""
        if stmt.count is not None:
            self.emit(f"_byte({self.numeric(stmt.count, scope)})")
        find = "_M.files.opened" if stmt.opened else "None"
        self.emit(f"_M.files.checked({self.integer(stmt.number, scope)}, {stmt.modes!r}, {find})")
        self.emit(f"raise _err({stmt.error.message!r}, {stmt.error.code})")

    def stmt_GetPut(self, stmt, scope):
        # the file first, found and its mode checked, then the record number (GIO86.ASM
        # DPUTG: POFNUM's GETBYT, FDBPTR, the MD_RND check, then ADRGET)
        file = self.new_temp()
        self.emit(f"{file} = _M.files.random({self.integer(stmt.number, scope)}, _M.files.opened)")
        record = "None" if stmt.record is None else self.when_reached(lambda: self.numeric(stmt.record, scope))
        if stmt.put:
            self.emit(f"{file}.put({record})")
            return
        number = self.new_temp()
        self.emit(f"{number} = {record}")
        self.emit(STORE_LOCALS)  # GET stores the fielded variables in the machine's scalars
        self.emit(f"_get({file}, {number})")
        self.emit(LOAD_LOCALS)

    # -- CHAIN, MERGE (chaining.py): the machine reads the file here (an error is this
    # statement's, trappable), then ends the block with the program to go on with
    def stmt_Chain(self, stmt, scope):
        if stmt.error is not None:  # its file first (FIVEO.ASM CHAIN: PRGFLI), then the options' error
            self.emit(f"_M.chain_file({self.string(stmt.file, scope)})")
            self.emit(f"raise _err({stmt.error.message!r}, {stmt.error.code})")
            return
        line = "None" if stmt.line is None else self.numeric(stmt.line, scope)
        self.emit(STORE_LOCALS)  # the variables a CHAIN keeps are the machine's
        self.emit(f"_chain({self.string(stmt.file, scope)}, {stmt.merge}, {line}, {stmt.everything}, "
                  f"{line_specs(stmt.delete)}, {stmt.run})")

    def stmt_Command(self, stmt, scope):
        """RUN, LIST, LOAD, SAVE ... in a program: the machine's ``program_command``; the
        letter after a comma must be one the dialect's command takes."""
        options = self.words.command_options
        if stmt.option is not None and stmt.name in options and stmt.option not in options[stmt.name]:
            raise syntax_error()
        argument = stmt.argument
        if stmt.file is not None and not self.words.list_to_file:
            raise syntax_error()
        if stmt.name == "EDIT" and argument is None and not self.words.edit_lists_from:
            raise syntax_error()  # GW-BASIC's EDIT needs its line
        if argument == ast.CURRENT_LINE and not self.dot_runs:  # casio's LIST . / EDIT .: its own line
            argument = self.line if stmt.name == "EDIT" else (self.line, self.line)
        if argument is not None and not isinstance(argument, (int, tuple)):
            argument = self.string(argument, scope)
        else:
            argument = line_specs(argument)
        file = "" if stmt.file is None else f", {self.string(stmt.file, scope)}"
        self.emit(STORE_LOCALS)
        self.emit(f"_command({stmt.name!r}, {argument}, {stmt.option!r}, {stmt.everything}{file})")
        self.emit(LOAD_LOCALS)

    # -- the text screen (machine/console.py)
    def optional_numbers(self, args: list, scope) -> str:
        """A Python tuple of integer arguments (``integer``: GW's GETBYT makes each one with
        FRCINT first), None where one was left out."""
        return "(" + "".join(("None" if a is None else self.integer(a, scope)) + ", " for a in args) + ")"

    def byte_statement(self, word: str, args: list, error, scope) -> None:
        """A screen statement whose arguments are read one small number at a time
        (``Dialect.screen.byte_statements``: GWSTS.ASM SCNINT): its arguments as far as its
        count (past it, anything but one comma is EOSCHK's Syntax error, raised once they
        are read), each checked by the machine as GETBYT reads it, in order, then ``error``
        (what a bad text was: source/byte_lists.py), then the statement's own checks."""
        reads = self.byte_statements[word]
        if reads is not None and len(args) > reads:
            if args[reads:] != [None] or error is not None:
                error = BasicError("Syntax error", SYNTAX_ERROR)
            args = args[:reads]
        values = "(" + "".join(("None" if a is None else self.when_reached(lambda a=a: self.numeric(a, scope))) + ", "
                               for a in args) + ")"
        fault = "None" if error is None else f"({error.message!r}, {error.code})"
        self.emit(f"_M.screen_words.run({word!r}, {values}, {fault})")

    def stmt_ByteList(self, stmt, scope):
        self.byte_statement(stmt.word, stmt.args, stmt.error, scope)

    def stmt_ScreenStatement(self, stmt, scope):
        """COLOR and SCREEN: at most three and four arguments; the machine checks them.
        GWSTS.ASM reads any number of arguments, left-out ones too (GTPRMS), and leaves
        their checking to the OEM's SETCLR and SCRSTT, which the source does not hold; so
        as PC-BASIC 2.0.8: a list ending in a comma (``COLOR ,``) or an empty SCREEN is
        Missing operand, COLOR alone and more arguments than the statement has Illegal
        function call.  VIEW alone resets the graphics viewport, which text mode has not:
        Illegal function call."""
        if stmt.word in self.byte_statements:
            self.byte_statement(stmt.word, stmt.args, None, scope)
            return
        args = stmt.args
        if stmt.word == "VIEW" or (stmt.word == "COLOR" and not args):
            raise CompileError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        if not args or (len(args) > 1 and args[-1] is None):
            raise CompileError("Missing operand", MISSING_OPERAND)
        if len(args) > (3 if stmt.word == "COLOR" else 4):
            raise CompileError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self.emit(f"_M.screen_statement({stmt.word!r}, {self.optional_numbers(stmt.args, scope)})")

    def stmt_ViewPrint(self, stmt, scope):
        rows = "None" if stmt.first is None else f"({self.numeric(stmt.first, scope)}, {self.numeric(stmt.last, scope)})"
        self.emit(f"_M.view_print({rows})")

    def stmt_Key(self, stmt, scope):
        if stmt.action == "NUMBER":  # GETBYT of the key's number, then what follows it is bad
            self.emit(f"_M.key_number({self.numeric(stmt.number, scope)})")
            self.emit(f"raise _err({stmt.text.message!r}, {stmt.text.code})")
        elif stmt.action == "TRAP":
            self.emit(f"_M.key_number({self.numeric(stmt.number, scope)})")
        elif stmt.action == "DEFINE":
            self.emit(f"_M.define_key({self.integer(stmt.number, scope)}, {self.string(stmt.text, scope)})")
        else:
            self.emit(f"_M.key_line({stmt.action!r})")

    def stmt_Common(self, stmt, scope):
        for name, is_array in self.common_variables(stmt):
            if not is_array:
                scope.scalar(name)  # a COMMON scalar exists (0 or "") for the CHAIN to keep

    def common_variables(self, stmt) -> list:
        """COMMON's (name, is an array) pairs as far as its list reads (a CHAIN reports the
        rest: source/common_lists.py)."""
        from yaseer.basic.source.common_lists import common_items  # (only programs with COMMON)

        return common_items(stmt.text, self.list_dialect)[0]

    def stmt_LSet(self, stmt, scope):
        """LSET / RSET: the machine stores the value, and every variable fielded over the
        same bytes of the buffer shows it (its locals stored before the call and loaded after it)."""
        key = self.field_key(stmt.target, scope)  # (PTRGET finds the variable before the value is worked out)
        value = self.string(stmt.value, scope)
        current = scope.scalar(stmt.target.name) if isinstance(stmt.target, ast.Var) else "None"
        arguments = self.new_temp()
        self.emit(f"{arguments} = ({key}, {value}, {current}, {stmt.right})")
        self.emit(STORE_LOCALS)
        self.emit(f"_lset(*{arguments})")
        self.emit(LOAD_LOCALS)

    def stmt_Close(self, stmt, scope):
        self.emit(f"_close(({''.join(self.integer(n, scope) + ', ' for n in stmt.numbers)}))")

    def stmt_Kill(self, stmt, scope):
        self.emit(f"_kill({self.string(stmt.name, scope)})")

    def stmt_Rename(self, stmt, scope):
        old = self.string(stmt.old, scope)
        try:
            new = None if stmt.new is None else self.string(stmt.new, scope)
        except CompileError as err:  # the old file is found before the new name is read (GIODSK.ASM NAME)
            stmt = ast.Rename(stmt.old, None, err)
        if stmt.new is None:
            self.emit(f"_rename_from({old})")
            self.emit(f"raise _err({stmt.error.message!r}, {stmt.error.code})")
            return
        self.emit(f"_rename({old}, {new})")

    def stmt_Files(self, stmt, scope):
        self.emit(f"_files({'None' if stmt.pattern is None else self.string(stmt.pattern, scope)})")


def line_specs(value) -> str:
    """Python source for a command's line numbers ``value`` (a number, None, or a tuple of
    them): each :data:`ast.CURRENT_LINE` in it, GW's ``.`` (GWMAIN.ASM LINSPC), is the
    machine's current line (DOT) when the statement runs."""
    if value == ast.CURRENT_LINE:
        return "_M.current_line"
    if isinstance(value, tuple):
        return "(" + "".join(line_specs(item) + ", " for item in value) + ")"
    return repr(value)
