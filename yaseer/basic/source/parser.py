"""Tokens -> AST: an LALR(1) parser over ``grammar.lark``.

The tables are ``parse_tables.py``, computed from the grammar by lark when the grammar
changes (tools/make_parse_tables.py), so no run imports lark or reads a table cache;
the driver here shifts the scanner's tokens and, at each reduction, calls the method
of :class:`_ToAst` that builds the ``syntax_tree`` node.  :func:`parse_line` is the one entry point: it returns a
:class:`~yaseer.basic.source.syntax_tree.Line` whose ``error`` holds the
``BasicError`` when the text is not a valid line (the machine raises it when
the line is reached, as the period interpreters did).
"""

from __future__ import annotations

from itertools import chain


from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.dialects.dialect import CASIO, Dialect
from yaseer.basic.errors import MESSAGES, BasicError, INTERNAL_ERROR, MISSING_OPERAND, NEXT_WITHOUT_FOR, SYNTAX_ERROR
from yaseer.basic.source.parse_tables import ACTIONS, END, RULES, START
from yaseer.basic.dialects.reserved import UNSUPPORTED, mark_unsupported, unsupported_message
from yaseer.basic.source.byte_lists import mark_literal_widths, read_byte_list
from yaseer.basic.source.graphics_syntax import mark_graphics
from yaseer.basic.source.event_tokens import mark_events
from yaseer.basic.source.scanner import UNSCANNED, Token, tokenize, tokenize_statements


def _number_value(token: Token):
    """A NUMBER token's value (typed scanners give ``(value, type)``)."""
    value = token.value
    return value[0] if type(value) is tuple else value


def _line_number(token: Token) -> int:
    if token.value == ast.CURRENT_LINE:  # "." where only a number may stand (RENUM's step)
        raise BasicError("Syntax error", SYNTAX_ERROR)
    value = _number_value(token)
    if value != int(value) or value < 0:
        raise BasicError("Syntax error", SYNTAX_ERROR)
    return int(value)


# A "." the scanner marked after a line word, read back as an expression: the number 0, but no
# line constant (GWMAIN.ASM CRUNCH stores it as a plain character), so RUN . is RUN's file name
# expression (DSKCOM.ASM LRUN), not RUN 0
_DOT_ZERO = ast.Num(0.0, "!")


def _line_spec(token: Token):
    """A line number where GWMAIN.ASM LINSPC reads one: the scanner's "." (the current line,
    :data:`ast.CURRENT_LINE`, resolved as the statement runs) or a number."""
    return ast.CURRENT_LINE if token.value == ast.CURRENT_LINE else _line_number(token)


_OPERATOR_NAMES = {
    "PLUS": "+", "MINUS": "-", "STAR": "*", "SLASH": "/", "BSLASH": "\\", "CARET": "^",
    "MOD": "MOD", "AND": "AND", "OR": "OR", "XOR": "XOR", "EQV": "EQV", "IMP": "IMP",
    "EQ": "=", "LT": "<", "GT": ">", "LE": "<=", "GE": ">=", "NE": "<>",
}


def _without_commas(children) -> list:
    return [c for c in children if not (isinstance(c, Token) and c.type == "COMMA")]


def _is_token(child, kind: str) -> bool:
    """True when ``child`` is a token of type ``kind`` (not a subtree)."""
    return isinstance(child, Token) and child.type == kind


def _usr_number(children) -> None:
    """USR's number, if any: one digit 0..9, as the cruncher stores it in one byte (GWEVAL.ASM
    SCNUSR; a longer number is read as what follows a plain USR: Syntax error)."""
    if children and _number_value(children[0]) not in range(10):
        raise BasicError("Syntax error", SYNTAX_ERROR)


# the punctuation of a word statement, kept as WordStatement.marks
_WORD_MARKS = {"EQ": "=", "HASH": "#", "COMMA": ",", "TO": "T"}


def _values(children) -> list:
    """The children that are not punctuation tokens."""
    return [c for c in children if not (isinstance(c, Token) and c.type in ("COMMA", "SEMI", "EQ"))]


class _LineThenRest:
    """A branch ``n: statements``: a jump, then statements that can never run."""

    def __init__(self, line: int, rest: list):
        self.line, self.rest = line, rest


def _if(condition, then, otherwise) -> ast.If:
    unreachable = []
    if isinstance(then, _LineThenRest):
        then, unreachable = then.line, unreachable + then.rest
    if isinstance(otherwise, _LineThenRest):
        otherwise, unreachable = otherwise.line, unreachable + otherwise.rest
    return ast.If(condition, then, otherwise, unreachable)


class _ToAst:
    """A rule's kept children -> its syntax_tree node (called bottom-up, at each reduction)."""

    # -- structure
    def start(self, c):
        return c[0]

    def seq(self, c):
        out = []
        for s in c:
            if s is None:
                continue
            if isinstance(s, list):
                out.extend(s)
            else:
                out.append(s)
        return out

    def item(self, c):
        return c[0] if c else None

    def branch_line(self, c):
        return _line_number(c[0])

    def branch_line_rest(self, c):
        return _LineThenRest(_line_number(c[0]), c[1])

    def branch_seq(self, c):
        return c[0]

    def branch_end(self, c):  # THEN *: where Becker's library stops after a break (casio; see compatibility.md)
        return [ast.EndMark()]

    def if_stmt(self, c):
        c = _without_commas(c)  # IF x, THEN: GW-BASIC's IF skips a comma after its condition
        return _if(c[1], c[3], c[5] if len(c) > 5 else None)

    def if_goto(self, c):
        c = _without_commas(c)
        return _if(c[1], _line_number(c[3]), c[5] if len(c) > 5 else None)

    # -- statements
    def let_stmt(self, c):
        target, value = _values(c)[-2:]
        return ast.Let(target, value)

    def var(self, c):
        return ast.Var(c[0].value)

    def elem(self, c):
        return ast.Elem(c[0].value, tuple(c[1]))

    def args(self, c):
        return _values(c)

    def print_stmt(self, c):
        return ast.Print(c[0].type == "LPRINT", [i for i in c[1:]])

    def print_using(self, c):
        if not any(item not in (",", ";") for item in c[4:]):
            raise BasicError("Missing operand", MISSING_OPERAND)  # USING needs a value (GW-BASIC)
        return ast.Print(c[0].type == "LPRINT", list(c[4:]), using=c[2])

    def print_items_using(self, c):
        """``PRINT "X="; USING f; v``: the items before USING print first (GW-BASIC)."""
        at = next(k for k, x in enumerate(c) if isinstance(x, Token) and x.type == "USING")
        using = self.print_using([c[0]] + list(c[at:]))
        using.lead = list(c[1:at])
        return using

    def print_item(self, c):
        item = c[0]
        if isinstance(item, Token) and item.type in ("COMMA", "SEMI"):
            return "," if item.type == "COMMA" else ";"
        return item

    def tab_item(self, c):
        return ast.Tab(c[1])

    def spc_item(self, c):
        return ast.Spc(c[1])

    def for_stmt(self, c):
        v = _values(c)
        step = v[6] if len(v) > 6 else None
        return ast.For(v[1], v[2], v[4], step)

    def next_stmt(self, c):
        names = _values(c)[1:]
        if not names:
            return ast.Next(None)
        return [ast.Next(n) for n in names]  # NEXT J, I is NEXT J: NEXT I

    def goto_stmt(self, c):
        return ast.Goto(_line_number(c[1]))

    def gosub_stmt(self, c):
        return ast.Gosub(_line_number(c[1]))

    def gosub_prog(self, c):
        return ast.GosubProg(_line_number(c[2]))

    def goto_area(self, c):  # GOTO #n: the FX-850P's program areas
        return ast.GotoArea(_line_number(c[2]))

    def gosub_area(self, c):  # GOSUB #n
        return ast.GosubArea(_line_number(c[2]))

    def goto_file(self, c):  # GOTO "file:label" / GOTO r$
        return ast.GotoFile(self.atom_of(c[1]))

    def gosub_file(self, c):
        return ast.GosubFile(self.atom_of(c[1]))

    @staticmethod
    def atom_of(token):
        return ast.Str(token.value) if token.type == "STRING" else ast.Var(token.value)

    def return_stmt(self, c):
        """RETURN [line]: GW-BASIC reads the digits that follow as the line (GWMAIN.ASM RETURN
        goes on at GOTO, whose LINGET stops at the first non-digit: ``RETURN 1+1`` is line 1);
        without digits, a plain RETURN (``RETURN "1"``, ``RETURN X``: PC-BASIC 2.0.8)."""
        if len(c) == 1:
            return ast.Return()
        first = c[1]
        while isinstance(first, ast.Binary):
            first = first.left
        if isinstance(first, ast.Num) and not isinstance(first.value, str) and first.value >= 0:
            return ast.ReturnTo(int(first.value))
        return ast.Return()

    def on_jump(self, c):
        targets: list = [None]  # ON x GOTO a,,b: None where a place is empty
        for token in c[3:]:
            if token.type == "COMMA":
                targets.append(None)
            else:
                targets[-1] = _line_number(token)
        return ast.OnJump(c[1], targets, c[2].type == "GOSUB")

    def on_error(self, c):
        return ast.OnError(_line_number(c[3]))

    def on_event(self, c):
        index = c[2] if len(c) == 5 else None
        return ast.EventTrap(c[1].value, index, _line_number(c[-1]))

    def event_switch(self, c):
        return ast.EventSwitch(c[0].value, c[1] if len(c) == 3 else None, c[-1].type)

    def end_stmt(self, c):
        return ast.End()

    def stop_stmt(self, c):
        return ast.Stop()

    def rem_stmt(self, c):
        return ast.Rem(c[0].value, list(getattr(c[0].value, "skipped", ())))

    def dim_stmt(self, c):
        return ast.Dim(_values(c)[1:])

    def dim_item(self, c):
        return (c[0].value, tuple(c[1]))

    def dim_scalar(self, c):
        return (c[0].value, None)  # (compiler: the dialect's Dialect.dim_name_alone_scalar)

    def clear_stmt(self, c):
        places = [None] if len(c) > 1 else []  # each comma opens a place; None: left empty
        for x in c[1:]:
            if _is_token(x, "COMMA"):
                places.append(None)
            else:
                places[-1] = x
        return ast.Clear(places)

    # -- GW-BASIC statements
    def while_stmt(self, c):
        return ast.While(c[1])

    def wend_stmt(self, c):
        return ast.Wend()

    def swap_stmt(self, c):
        return ast.Swap(c[1], c[3])

    def mid_stmt(self, c):
        if c[0].value != "MID$":
            raise BasicError("Syntax error", SYNTAX_ERROR)
        v = _values(c)
        count = v[3] if len(v) > 4 else None
        return ast.MidAssign(v[1], v[2], count, v[-1])

    def erase_stmt(self, c):
        return ast.Erase([t.value for t in _values(c)[1:]])

    def option_base(self, c):
        base = _line_number(c[2])
        if c[1].value != "BASE" or base not in (0, 1):
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return ast.OptionBase(base)

    def line_input(self, c):
        rest = c[2:]
        keeps_row = _is_token(rest[0], "SEMI")
        rest = rest[keeps_row:]
        prompt = None
        if _is_token(rest[0], "STRING"):
            prompt, rest = rest[0].value, rest[2:]
        return ast.LineInput(prompt, rest[0], keeps_row=keeps_row)

    def write_stmt(self, c):
        return ast.Write(_values(c)[1:])

    # -- sequential files
    def open_short(self, c):
        v = [x for x in c[1:] if not (isinstance(x, Token) and x.type in ("COMMA", "HASH"))]
        return ast.Open(v[0], v[1], v[2], v[3] if len(v) > 3 else None)

    def open_long(self, c):
        mode = c[3]
        if mode.type == "NAME" and mode.value not in ("OUTPUT", "RANDOM"):
            raise BasicError("Syntax error", SYNTAX_ERROR)
        clauses = [x.value for x in c[4:] if isinstance(x, Token) and x.type == "OPENCLAUSE"]
        words = [word for word, _ in clauses]
        if words not in ([], ["ACCESS"], ["LOCK"], ["ACCESS", "LOCK"]):
            raise BasicError("Syntax error", SYNTAX_ERROR)
        rights = dict(clauses)
        node = self._open_as(ast.Str(mode.value), c[1], c[4 + len(clauses):])
        node.access, node.lock = rights.get("ACCESS"), rights.get("LOCK")
        return node

    def open_as(self, c):
        return self._open_as(ast.Str("R"), c[1], c[2:])  # no FOR: a random file (GW-BASIC)

    @staticmethod
    def _open_as(mode, name, rest):
        """OPEN ... AS [#]n [LEN = length]: ``rest`` from the AS on."""
        if rest[0].value not in ("AS", "AS#"):
            raise BasicError("Syntax error", SYNTAX_ERROR)
        rest = [x for x in rest[1:] if not (isinstance(x, Token) and x.type == "HASH")]
        if len(rest) > 1 and rest[1].value != "LEN":
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return ast.Open(mode, rest[0], name, rest[3] if len(rest) > 1 else None)

    # -- random-access files
    def field_stmt(self, c):
        v = [x for x in c[1:] if not (isinstance(x, Token) and x.type in ("COMMA", "HASH"))]
        if any(word.value != "AS" for word in v[2::3]):
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return ast.Field(v[0], list(zip(v[1::3], v[3::3])))

    def get_put(self, c):
        v = [x for x in c[1:] if not (isinstance(x, Token) and x.type in ("COMMA", "HASH"))]
        return ast.GetPut(c[0].type == "PUT", v[0], v[1] if len(v) > 1 else None)

    def lset_stmt(self, c):
        return ast.LSet(c[0].value == "RSET", c[1], c[3])

    def reset_stmt(self, c):
        return ast.Close([])

    # -- CHAIN, COMMON, MERGE
    def chain_stmt(self, c):
        merge = isinstance(c[1], Token) and c[1].type == "MERGE"
        options = c[2 + merge:]
        values = [o for o in options if o[0] == "value"]
        deletes = [o[1] for o in options if o[0] == "delete"]
        # [, line] [, ALL] [, DELETE range] (FIVEO.ASM CHAIN): at most two values, the second
        # ALL; DELETE last, after a line or its comma (a first ALL is a variable: the line)
        if len(values) > 2 or len(deletes) > 1 or (deletes and (options[-1][0] != "delete" or not values)):
            raise BasicError("Syntax error", SYNTAX_ERROR)
        line = values[0][1] if values else None
        everything = len(values) > 1 and isinstance(values[1][1], ast.Var) and values[1][1].name == "ALL"
        if len(values) > 1 and not everything:
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return ast.Chain(merge, c[1 + merge], line, everything, deletes[0] if deletes else None)

    def chain_value(self, c):
        return ("value", c[1] if len(c) > 1 else None)

    def chain_delete(self, c):
        return ("delete", c[2])

    def line_range(self, c):
        numbers = [_line_spec(t) if t.type == "NUMBER" else t.type for t in c]
        first = numbers[0] if numbers[0] != "MINUS" else None
        last = numbers[-1] if numbers[-1] != "MINUS" else None
        return (first, last)

    def line_range_one(self, c):
        return (_line_spec(c[0]),) * 2

    def common_stmt(self, c):
        return ast.Common(c[1].value)

    # -- commands a program runs (chaining.py)
    @staticmethod
    def _option(c, letters: str):
        """The letter after a comma (``,R``), which must be one of ``letters``."""
        if len(c) < 4:
            return None
        word = c[3].value
        if word not in tuple(letters):
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return word

    def run_stmt(self, c):
        if len(c) == 2 and isinstance(c[1], ast.Num) and c[1] is not _DOT_ZERO:  # RUN n: a line number
            if c[1].value != int(c[1].value) or c[1].value < 0:
                raise BasicError("Syntax error", SYNTAX_ERROR)
            return ast.Command("RUN", int(c[1].value))
        return ast.Command("RUN", c[1] if len(c) > 1 else None, self._option(c, "R"))

    def list_stmt(self, c):
        c, everything = _without_all(c)
        file = None
        if len(c) > 2 and isinstance(c[-2], Token) and c[-2].type == "COMMA":  # LIST [range], "f"
            c, file = c[:-2], c[-1]
        if len(c) > 1 and isinstance(c[1], Token):  # LIST . (the Casio's PERIOD)
            return ast.Command(c[0].value, ast.CURRENT_LINE, file=file)
        return ast.Command(c[0].value, c[1] if len(c) > 1 else (None, None), everything=everything, file=file)

    def load_stmt(self, c):
        c, everything = _without_all(c)
        return ast.Command("LOAD", c[1], self._option(c, "RA"), everything)

    def save_stmt(self, c):
        c, everything = _without_all(c)
        return ast.Command("SAVE", c[1], self._option(c, "AP"), everything)

    def new_stmt(self, c):
        c, everything = _without_all(c)
        return ast.Command(c[0].value, everything=everything)

    def delete_stmt(self, c):
        return ast.Command("DELETE", c[1] if len(c) > 1 else (None, None))  # alone: the whole range

    def edit_stmt(self, c):
        if len(c) == 1:  # EDIT alone: from the first line (the Casio's; the compiler refuses it elsewhere)
            return ast.Command("EDIT", None)
        return ast.Command("EDIT", ast.CURRENT_LINE if c[1].type == "PERIOD" else _line_spec(c[1]))

    def renum_stmt(self, c):
        """RENUM [new][, [old][, step]]: (new, old, step), None where left out."""
        values, place = [None, None, None], 0
        for token in c[1:]:
            if token.type == "COMMA":
                place += 1
            else:
                values[place] = _line_spec(token) if place < 2 else _line_number(token)
        if place == 2 and values[2] is None:  # RESEQ's LINGET reads no digits as 0, an increment it refuses
            values[2] = 0
        return ast.Command("RENUM", tuple(values))

    def auto_stmt(self, c):
        """AUTO [start | .][, [step]]: (start, step); start None: 10; step 10 without a comma,
        None after a comma alone (the step AUTO used last)."""
        start, step = None, 10
        for k, token in enumerate(c[1:]):
            if token.type == "PERIOD":
                start = ast.CURRENT_LINE
            elif token.type == "COMMA":
                step = None
            elif k == 0:
                start = _line_spec(token)
            else:
                step = _line_number(token)
        return ast.Command("AUTO", (start, step))

    def key_stmt(self, c):
        return ast.Key(c[1].type)

    def key_trap(self, c):  # KEY (n) ON/OFF/STOP: no key is ever pressed to trap (the number still read)
        return ast.Key("TRAP", c[1])

    def key_paren_define(self, c):  # KEY (n), text: the ( makes it KEY(n)'s form (GWSTS.ASM KEYS), no comma there
        raise BasicError("Syntax error", SYNTAX_ERROR)

    def key_define(self, c):
        return ast.Key("DEFINE", c[1], c[3])

    def optargs(self, c):
        args: list = [None]  # None where an argument is left out
        for x in c:
            if isinstance(x, Token) and x.type == "COMMA":
                args.append(None)
            else:
                args[-1] = x
        return args if c else []

    def color_stmt(self, c):
        return ast.ScreenStatement("COLOR", c[1])

    def screen_stmt(self, c):
        return ast.ScreenStatement("SCREEN", c[1])

    def graphics_stmt(self, c):
        return c[0].value

    def view_alone(self, c):
        return ast.ScreenStatement("VIEW", [])

    def view_print(self, c):
        return ast.ViewPrint(c[2], c[4]) if len(c) > 2 else ast.ViewPrint()

    def screen_fn(self, c):
        return ast.Call("SCREEN", tuple(c[1]))

    def merge_stmt(self, c):
        return ast.Chain(True, c[1], None, True, None, run=False)

    def close_stmt(self, c):
        return ast.Close([x for x in c[1:] if not isinstance(x, Token)])

    def kill_stmt(self, c):
        return ast.Kill(c[1])

    def name_stmt(self, c):
        if c[2].value != "AS":
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return ast.Rename(c[1], c[3])

    def files_stmt(self, c):
        return ast.Files(c[1] if len(c) > 1 else None)

    def print_file(self, c):
        return ast.Print(False, list(c[4:]), channel=c[2])

    def print_file_using(self, c):
        return ast.Print(False, list(c[7:]), using=c[5], channel=c[2])

    def write_file(self, c):
        return ast.Write(_values(c)[3:], channel=c[2])

    def input_file(self, c):
        return ast.Input(None, False, _values(c)[3:], channel=c[2])

    def line_input_file(self, c):
        return ast.LineInput(None, c[5], channel=c[3])

    def data_stmt(self, c):
        return ast.Data(c[0].value)

    def read_stmt(self, c):
        return ast.Read(_values(c)[1:])

    def restore_stmt(self, c):
        if len(c) == 1:
            return ast.Restore(None)
        target = c[1]
        if isinstance(target, ast.Num):
            return ast.Restore(_line_number(Token("NUMBER", target.value)))
        return ast.Restore(target)

    def word_stmt(self, c):
        marks = "".join(_WORD_MARKS[t.type] for t in c[1:] if isinstance(t, Token) and t.type in _WORD_MARKS)
        return ast.WordStatement(c[0].value, [a for a in c[1:] if not (isinstance(a, Token) and a.type in _WORD_MARKS)],
                                 marks)

    def word_call(self, c):  # MODE 33(a, b, c): the word's number n with arguments (a ROM routine's call)
        return ast.WordStatement(c[0].value + "()", [ast.Num(_number_value(c[1]))] + _values(c[2:]))

    def input_stmt(self, c):
        # each variable with the message before it (the Casio's INPUT "YEAR=",Y,"MONTH=",M)
        asks, targets, message = [], [], None
        rest = c[1:]
        keeps_row = bool(rest) and _is_token(rest[0], "SEMI")  # INPUT; A
        rest = rest[keeps_row:]
        names_cut = not rest or _is_token(rest[-1], "COMMA") or _is_token(rest[-1], "SEMI")
        items = iter(rest)
        for item in items:
            if _is_token(item, "STRING"):
                message = (item.value, next(items).type == "SEMI")
            elif not isinstance(item, Token):
                targets.append(item)
                asks.append(message)
                message = None
        prompt, question = (asks[0] if asks else message) or (None, True)
        return ast.Input(prompt, question, targets, asks=asks if any(asks[1:]) else None,
                         keeps_row=keeps_row, names_cut=names_cut)

    def def_stmt(self, c):
        name = c[2].value
        params = c[3] if isinstance(c[3], list) else []
        return ast.DefFn(name, params, c[-1])

    def def_seg(self, c):  # DEF SEG [= s]: the word is read letter by letter (GWEVAL.ASM DEF)
        if c[1].value != "SEG":
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return ast.DefMachine("SEG", c[3] if len(c) > 2 else None)

    def def_usr(self, c):  # DEF USR[n] = a
        _usr_number(c[2:-2])
        return ast.DefMachine("USR", c[-1])

    def usr_call(self, c):  # USR[n](x): the function's number one digit (GWEVAL.ASM SCNUSR)
        _usr_number(c[1:-1])
        return ast.Call("USR", (c[-1],))

    def params(self, c):
        return [t.value for t in _values(c)]

    def resume_stmt(self, c):
        if len(c) == 1:
            return ast.Resume("retry")
        if c[1].type == "NEXT":
            return ast.Resume("next")
        target = _line_number(c[1])
        return ast.Resume("retry") if target == 0 else ast.Resume("line", target)

    def error_stmt(self, c):
        return ast.Error(c[1])

    def randomize_stmt(self, c):
        return ast.Randomize(c[1] if len(c) > 1 else None)

    def angle_stmt(self, c):
        return ast.Angle(c[0].type)

    def trace_stmt(self, c):
        return ast.Trace(c[0].type == "TRON")

    def cls_stmt(self, c):
        return ast.Cls(c[1] if len(c) > 1 else None)

    def bank_stmt(self, c):
        return ast.Bank(c[0].value, _values(c[1:]))

    def defchr_stmt(self, c):  # DEFCHR$(n) = "hex digits": a user-defined character's dots
        if c[1].value != "CHR$":
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return ast.DefChr(c[2], c[4])

    def locate_stmt(self, c):
        return ast.Locate(c[1])

    def input_at(self, c):  # INPUT @n; v: the library's form; no "?" of its own
        return ast.Input("", False, _values(c[4:]), at=int(_number_value(c[2])))

    def width_stmt(self, c):
        return ast.Width(c[-1], len(c) == 3)  # WIDTH LPRINT n: the printer's

    def width_device(self, c):
        return ast.Width(c[-1], device=c[1])  # WIDTH "LPT1:", n

    def width_file(self, c):
        return ast.Width(c[-1], file=c[2])  # WIDTH #n, w

    def deftype_stmt(self, c):
        return ast.DefType(c[0].value[3:], _values(c)[1:])

    def letters(self, c):
        first, last = c[0].value, c[-1].value
        if len(first) != 1 or len(last) != 1 or not first.isalpha() or not last.isalpha() or last < first:
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return first + last

    # -- expressions
    def binop(self, c):
        left, op, right = c
        return ast.Binary(_OPERATOR_NAMES[op.type], left, right)

    def binop_not(self, c):  # 13*NOT 7: parse_statements refuses it where the dialect has no such NOT
        left, op, right = c
        return ast.Binary(_OPERATOR_NAMES[op.type], left, right, bare_not=True)

    def unop(self, c):
        return ast.Unary(_OPERATOR_NAMES.get(c[0].type, c[0].type), c[1])

    def _call(self, c):
        name = c[0].value
        if len(c) == 1:
            return ast.Call(name, ())
        if len(c) > 2:  # INPUT$(n, #f)
            return ast.Call(name, (c[1], c[4]))
        arg = c[1]
        return ast.Call(name, tuple(arg) if isinstance(arg, list) else (arg,))

    def call_keys(self, c):  # INPUT$(n, @): n keys
        return ast.Call(c[0].value, (c[1],))

    def file_pointer(self, c):  # VARPTR(#n): a file's block (a function without it: compiler's Syntax error)
        return ast.FilePointer(c[0].value, c[2])

    def fn_call(self, c):
        args = tuple(c[2]) if len(c) > 2 else ()
        return ast.FnCall(c[1].value, args)

    def number(self, c):
        value = c[0].value
        if value == ast.CURRENT_LINE:  # "." read as a line after a line word, in an expression: 0
            return _DOT_ZERO
        if type(value) is tuple:
            return ast.Num(value[0], value[1])
        return ast.Num(value)

    def string(self, c):
        return ast.Str(c[0].value)

    def clock_stmt(self, c):
        if c[0].value not in ("DATE$", "TIME$"):  # ERR = 1, CSRLIN = 2: no statement
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return ast.SetClock(c[0].value, c[2])

    def partial(self, c):
        return c[0].value  # the CutCall or CutExpression the token carries

    def call(self, c):
        name = c[0].value
        if len(c) > 2 and name == "POINT":  # POINT(x, #: its reading meets the # where y starts
            return ast.CutCall(name, (c[1],), True, BasicError("Syntax error", SYNTAX_ERROR))
        if len(c) > 2 and name != "INPUT$":  # (c, #f): only INPUT$ reads a file number there
            raise BasicError("Syntax error", SYNTAX_ERROR)
        return self._call(c)

    def sysvar(self, c):
        return ast.SysVar(c[0].value)




class GrammarError(Exception):
    """The grammar refuses ``token`` (type ``$END``: the statements ended early);
    ``expected``: the terminals it would have taken there."""

    def __init__(self, token: Token, expected: frozenset):
        super().__init__(f"unexpected {token.type}")
        self.token, self.expected = token, expected


def _reduction(size: int, method, keep, single):
    """The function that turns a rule's ``size`` stack values into its value: the kept
    children (``keep``: ``(index, splice)`` pairs, None for all), one child standing for a
    ``?rule`` (``single``), else ``method(children)`` (None: the list, for the parent to splice)."""
    if keep is None and not single:
        return method or list
    method = method or (lambda children: children)

    def reduce(children: list):
        if keep is not None:
            kept: list = []
            for i, splice in keep:
                if not splice:
                    kept.append(children[i])
                elif kept:
                    kept += children[i]
                else:  # left recursion: the spliced list is fresh, so it becomes the kept list
                    kept = children[i]
            children = kept
        if single and len(children) == 1:
            return children[0]
        return method(children)

    return reduce


def _missing(rule: str):
    def missing(children: list):
        raise AssertionError(f"grammar rule {rule} has no _ToAst method")
    return missing


_BUILDER = _ToAst()
_REDUCTIONS: list = [None] * len(RULES)
"""``(name, size, reduce)`` of each grammar rule, made when the parser first reduces by it."""


def _reduction_of(rule: int) -> tuple:
    """Rule ``rule``'s ``(name, size, reduce)``, its method bound to the one _ToAst (a ``?rule``
    needs one only where it can keep more than one child); made when first needed, as a cold
    start's parse reduces by few of the rules."""
    name, size, callback, keep, single = RULES[rule]
    method = callback and getattr(_BUILDER, callback, None) or (callback and _missing(callback))
    entry = _REDUCTIONS[rule] = (name, size, _reduction(size, method, keep, single))
    return entry
_END_OF_LINE = Token("$END", "")


_ROWS: list = [None] * len(ACTIONS)
"""Each state's actions (symbol -> code), made from its table row when the parser first reaches it."""


def _row(state: int) -> dict:
    """State ``state``'s actions, made from ACTIONS[state] (a cold start's parse reaches few of the states)."""
    symbols, codes = ACTIONS[state]
    row = _ROWS[state] = dict(zip(symbols, codes))
    return row


def _parse(tokens: list) -> list:
    """The statements of a token list (LALR(1): shift, or reduce and go to), or GrammarError."""
    rows, reductions = _ROWS, _REDUCTIONS
    states: list = [START]
    values: list = []
    for token in chain(tokens, (_END_OF_LINE,)):
        kind = token.type
        while True:
            row = rows[states[-1]] or _row(states[-1])
            code = row.get(kind)
            if code is None:
                raise GrammarError(token, frozenset(s for s in row if s.isupper()))
            if code >= 0:
                states.append(code)
                values.append(token)
                break
            name, size, reduce = reductions[-1 - code] or _reduction_of(-1 - code)
            if size:
                children = values[-size:]
                del states[-size:], values[-size:]
            else:
                children = []
            values.append(reduce(children))
            state = (rows[states[-1]] or _row(states[-1]))[name]
            states.append(state)
            if state == END:
                return values[-1]
    raise AssertionError("the end of the line was shifted")  # the tables never shift $END


def _without_all(c: list) -> tuple[list, bool]:
    """A command's children without the ``ALL`` after its keyword (the Casio's NEW ALL, LIST
    ALL, SAVE ALL, LOAD ALL: every program area), and whether it was there."""
    if len(c) > 1 and isinstance(c[1], Token) and c[1].type == "ALL":
        return [c[0], *c[2:]], True
    return c, False


def _else_alone(tokens: list, dialect: Dialect) -> list:
    """``tokens`` up to an ELSE that no IF before it owns, which then ends them as a
    remark does (see ``Dialect.else_alone_skips``); ``tokens`` where there is none."""
    if not dialect.else_alone_skips:
        return tokens
    for k, token in enumerate(tokens):
        if token.type == "IF":
            return tokens
        if token.type == "ELSE":
            colon = [Token("_COLON", ":")] if k and tokens[k - 1].type != "_COLON" else []
            return tokens[:k] + colon + [Token("REMARK", _SkippedText(tokens[k + 1:]))]
    return tokens


class _SkippedText(str):
    """The remark an unowned ELSE makes of the rest of its line (an empty text), with the
    statements that rest holds (``skipped``): they never run, but GW-BASIC's FOR scans the
    text for its NEXT through them (GWMAIN.ASM NXTSCN takes the word after an ELSE as a
    statement's start).  As far as each piece between ELSEs reads."""

    def __new__(cls, tokens: list):
        text = super().__new__(cls, "")
        text.skipped = []
        piece: list = []
        for token in tokens + [Token("ELSE", "ELSE")]:
            if token.type != "ELSE":
                piece.append(token)
                continue
            if piece:
                try:
                    text.skipped.extend(_parse(piece))
                except (BasicError, GrammarError):
                    text.skipped.extend(_statements_before_error(piece)[0])
            piece = []
        return text


def _read_as_statements(tokens: list, dialect: Dialect) -> list:
    """A line's tokens as its statements read them: event words as events (gw), reserved words
    the dialect lacks as unsupported, an ELSE no IF owns as the end of the line."""
    words = dialect.device_words
    tokens = mark_graphics(mark_literal_widths(tokens, dialect), dialect, parse_expression)
    marked = mark_events(tokens, words.events, words.statements) if words else tokens
    return _else_alone(mark_unsupported(marked), dialect)


def parse_statements(text: str, dialect: Dialect = CASIO) -> list:
    """The statements of one line's text as ``dialect`` reads it; raises ``BasicError`` (Syntax error)."""
    tokens = _read_as_statements(tokenize(text, dialect), dialect)
    if not tokens:
        return []
    _check_nesting(tokens)
    try:
        statements = _parse(tokens)
    except GrammarError as exc:
        raise _grammar_error(exc, dialect) from None
    if not dialect.not_after_operator and any(token.type == "NOT" for token in tokens) and _bare_not(statements):
        raise BasicError("Syntax error", SYNTAX_ERROR)
    return statements


def _bare_not(node) -> bool:
    """Whether ``node`` (a statement, an expression, a list of them) holds a NOT that is a
    binary operator's right side (``13*NOT 7``), which a dialect without
    ``Dialect.not_after_operator`` refuses."""
    if isinstance(node, list):
        return any(map(_bare_not, node))
    if isinstance(node, ast.Binary) and node.bare_not:
        return True
    return isinstance(node, ast.Node) and any(_bare_not(getattr(node, name)) for name in node._fields)


# Terminals only an expression starts with: one expected here and the statement ended
# instead is GW-BASIC's "Missing operand" (``X =``, ``PRINT 1 +``: GWEVAL.ASM EVAL raises
# MOERR); where only a name or a line number may come (``FOR``, ``DIM``, ``GOTO``) the
# statement's own scan finds nothing: "Syntax error".  An expression may always start with
# a variable's name: where none is expected no expression starts (``GOTO`` wants a line,
# ``DEF`` the word FN, SEG or USR: GWEVAL.ASM DEF's SYNCHR), whatever else may follow.
_OPERAND_STARTS = frozenset(("FUNCN", "MINUS", "NOT"))  # (not FUNC: the Casio's DEFCHR$ follows DEF)
_STATEMENT_ENDS = frozenset(("$END", "_COLON", "ELSE"))


def _grammar_error(exc: GrammarError, dialect: Dialect) -> BasicError:
    """The BASIC error for a token list the grammar refuses (``Missing operand`` only
    where the dialect reports errors when reached, as GW-BASIC)."""
    kind = exc.token.type
    if kind == UNSUPPORTED:
        return BasicError(unsupported_message(exc.token.value), SYNTAX_ERROR)
    if kind == UNSCANNED:
        return exc.token.value  # the scanner's own error for the statement
    operand = exc.expected & _OPERAND_STARTS and "NAME" in exc.expected
    if dialect.errors_when_reached and kind in _STATEMENT_ENDS and operand:
        return BasicError("Missing operand", MISSING_OPERAND)
    return BasicError("Syntax error", SYNTAX_ERROR)


def _statements_before_error(tokens: list) -> tuple[list, int]:
    """The statements of the longest run of whole statements at the start of a bad line,
    and the index of the token where the bad statement starts.

    GW-BASIC runs a line statement by statement and finds a bad token only when it
    gets there, so the statements before it run first (``10 PRINT 50: X`` prints 50).
    """
    colons = [k for k, t in enumerate(tokens) if t.type == "_COLON"]
    best: list = []
    bad_start = 0
    for k in colons:
        try:
            best = _parse(tokens[:k])
        except (BasicError, GrammarError):
            break
        bad_start = k + 1
    return best, bad_start


def _statements_after_error(tokens: list, bad_start: int, dialect: Dialect) -> list:
    """The statements after the bad one (from the colon that ends it), each bad one
    again its error: ``RESUME NEXT`` goes on with them (GW-BASIC).  None follow a bad
    statement that holds an IF (the rest of the line is its branch)."""
    for k in range(bad_start, len(tokens)):
        kind = tokens[k].type
        if kind == "IF":
            return []
        if kind == "_COLON":
            rest = tokens[k + 1:]
            if not rest:
                return []
            try:
                return _parse(rest)
            except GrammarError as exc:
                err = _grammar_error(exc, dialect)
            except BasicError as exc:
                err = exc
            return _recover_tokens(rest, err, dialect) or [err]
    return []


def _place_error(statements: list, rest: list) -> list:
    """``statements`` followed by ``rest`` (the error, raised when reached, then the statements
    RESUME NEXT goes on with); after an IF whose last branch runs to the end of the line
    they belong to that branch."""
    if statements and isinstance(statements[-1], ast.If):
        last = statements[-1]
        for field in ("otherwise", "then"):
            branch = getattr(last, field)
            if isinstance(branch, list) and branch:
                setattr(last, field, _place_error(list(branch), rest))
                return statements
            if branch is not None:  # a line number: the rest of the line never runs
                last.unreachable = list(last.unreachable) + rest
                return statements
    return statements + rest


def _recover(text: str, err: BasicError, dialect: Dialect):
    """The statements of a bad line with ``err`` in place of its first bad statement
    (see :func:`_recover_tokens`); a statement the scanner cannot read is bad in its turn."""
    tokens = _read_as_statements(tokenize_statements(text, dialect), dialect)
    if any(token.type == UNSCANNED for token in tokens):
        try:  # err was the scanner's; an earlier statement may be bad in another way (``PRINT 1+``)
            _parse(tokens)
        except GrammarError as exc:
            err = _grammar_error(exc, dialect)
        except BasicError as exc:
            err = exc
    return _recover_tokens(tokens, err, dialect)


def _recover_tokens(tokens: list, err: BasicError, dialect: Dialect) -> list:
    """The statements before the first bad one, ``err``, then the statements after it
    (inside the branch of an IF those before it end with, where the bad one belongs)."""
    good, bad_start = _statements_before_error(tokens)
    return _place_error(good, _bad_and_after(tokens, bad_start, err, dialect))


def _bad_and_after(tokens: list, bad_start: int, err: BasicError, dialect: Dialect) -> list:
    """The bad statement that starts at ``bad_start`` as it runs (see :func:`_recover_tokens`),
    then the statements after it."""
    as_then = _goto_as_then(tokens, bad_start)
    if as_then is not None:
        try:
            return _parse(as_then)
        except (BasicError, GrammarError):
            return _recover_tokens(as_then, err, dialect)
    guarded = _guarding_if(tokens, bad_start, err, dialect)
    if guarded is not None:
        return [guarded]
    defined = _deferred_definition(tokens, bad_start, err, dialect)
    if defined is not None:
        return [defined] + _statements_after_error(tokens, bad_start, dialect)
    read = read_byte_list(tokens, bad_start, dialect, parse_expression)
    if read is not None:
        return [read] + _statements_after_error(tokens, bad_start, dialect)
    checked_first = _checked_first(tokens, bad_start, err)
    if checked_first is not None:
        return [checked_first] + _statements_after_error(tokens, bad_start, dialect)
    edit_tail = _edit_tail_error(tokens, bad_start, dialect)
    if edit_tail is not None:
        return [edit_tail] + _statements_after_error(tokens, bad_start, dialect)
    found = (_mid_read_as_far(tokens, bad_start, err) or _input_file_first(tokens, bad_start, err)
             or _chain_file_first(tokens, bad_start, err) or _run_before_leftover(tokens, bad_start, err, dialect))
    if found is not None:
        return [found] + _statements_after_error(tokens, bad_start, dialect)
    nexts = _next_read_as_far(tokens, bad_start, err)
    if nexts is not None:
        return nexts + _statements_after_error(tokens, bad_start, dialect)
    jump = _jump_read_as_needed(tokens, bad_start)
    if jump is not None:
        return [jump] + _statements_after_error(tokens, bad_start, dialect)
    cut = _cut_expression(tokens, bad_start, err, dialect)
    if cut is not None:
        return cut + _statements_after_error(tokens, bad_start, dialect)
    first = _first_value_checked(tokens, bad_start, err)
    if first is not None:
        return [first] + _statements_after_error(tokens, bad_start, dialect)
    word = _word_read_as_far(tokens, bad_start, err, dialect)
    if word is not None:
        return [word] + _statements_after_error(tokens, bad_start, dialect)
    touched = _touched_element(tokens, bad_start, err)
    if touched is not None:
        return [touched] + _statements_after_error(tokens, bad_start, dialect)
    printed = (_printed_before_error(tokens, bad_start) or _written_before_error(tokens, bad_start)
               or _assigned_before_error(tokens, bad_start) or _arrays_before_error(tokens, bad_start))
    file_first = None if printed else _file_checked_first(tokens, bad_start, err)
    if file_first is not None:
        return [file_first] + _statements_after_error(tokens, bad_start, dialect)
    if printed:
        return [ast.CutShort(printed[0], err)] + _statements_after_error(tokens, bad_start, dialect)
    return [err] + _statements_after_error(tokens, bad_start, dialect)


def _word_read_as_far(tokens: list, start: int, err: BasicError, dialect: Dialect):
    """A bad device-word statement that reads its arguments before it looks at what follows
    them (``Dialect.device_words.reads_before_end``: IOCTL) whose text, up to where it goes
    wrong after an argument, reads as the statement: that statement, which checks its
    arguments and runs, then ``err`` for the rest (the recorded IOCTL test: ``IOCTL #1, "" X``
    is the disk file's Illegal function call, ``IOCTL "A" X`` the file number's Type
    mismatch).  None where the text goes wrong inside an expression or where the next
    argument should start (an operator, ``(``, ``,`` or TO comes next, or the text stops
    after the word, a ``#`` or a separator: the statement's own error), or for any other
    statement."""
    words = dialect.device_words
    if tokens[start].type != "WORDSTMT" or words is None or tokens[start].value not in words.reads_before_end:
        return None
    end = next((k for k in range(start + 1, len(tokens)) if tokens[k].type in _STATEMENT_ENDS), len(tokens))
    for k in range(end - 1, start, -1):
        try:
            found = _parse(tokens[start:k])
        except (BasicError, GrammarError):
            continue
        if tokens[k].type in _BINARY_OPERATORS or tokens[k].type in ("_LPAR", "COMMA", "TO") \
                or tokens[k - 1].type in ("WORDSTMT", "HASH", "EQ", "COMMA", "TO"):
            return None  # the statement reads on there (an operand, the next argument): its own error
        if len(found) == 1 and isinstance(found[0], ast.WordStatement):
            return ast.CutShort(found[0], err)
        return None
    return None


def _goto_as_then(tokens: list, start: int) -> list | None:
    """``IF c GOTO`` with no line number after GOTO: the tokens from ``start`` with that GOTO
    read as THEN (GWMAIN.ASM IFS takes GOTO where THEN may stand, and DOCOND runs a statement
    where no line number follows: ``IF 1 GOTO PRINT 2`` prints 2).  None for any other bad
    statement."""
    if tokens[start].type != "IF":
        return None
    word = next((k for k in range(start + 1, len(tokens)) if tokens[k].type in ("GOTO", "THEN", "_COLON")), None)
    if word is None or tokens[word].type != "GOTO" or (word + 1 < len(tokens) and tokens[word + 1].type == "NUMBER"):
        return None
    return tokens[start:word] + [Token("THEN", "THEN")] + tokens[word + 1:]


def _guarding_if(tokens: list, start: int, err: BasicError, dialect: Dialect):
    """A bad IF whose condition reads: the IF, each branch that does not read being ``err``.
    GW-BASIC reads a branch only when it runs (``10 IF 1 > 2 THEN EXIT FOR`` runs: GWMAIN.ASM
    IF skips to the ELSE or the end of the line).  None when the condition does not read."""
    if start >= len(tokens) or tokens[start].type != "IF":
        return None
    then = next((k for k in range(start + 1, len(tokens)) if tokens[k].type == "THEN"), None)
    if then is None:
        return None
    otherwise = next((k for k in range(then + 1, len(tokens)) if tokens[k].type == "ELSE"), None)
    end = len(tokens) if otherwise is None else otherwise
    head = tokens[start:then + 1]
    node = _branch_if(head + [Token("REMARK", "")])
    if node is None:
        return None
    node.then = _branch(head, tokens[then + 1:end], err, dialect)
    if otherwise is not None:
        node.otherwise = _branch(head, tokens[otherwise + 1:], err, dialect)
    return node


def _branch(head: list, part: list, err: BasicError, dialect: Dialect):
    """A branch's statements (or line number); one that does not read: the statements
    before its error, the error, those after it."""
    node = _branch_if(head + part) if part else None
    if node is not None:
        return node.then
    return (_recover_tokens(part, err, dialect) if part else None) or [err]


def _deferred_definition(tokens: list, start: int, err: BasicError, dialect: Dialect):
    """A DEF FN whose name and parameters read but whose body does not: the function, its
    body the error raised when it is called (GWEVAL.ASM DEF reads the name and the
    parameters in parentheses, if a ``(`` follows, then skips the rest of the statement as
    DATA does): after ``=`` the body's own error ``err``, with no ``=`` (``DEF FNA``)
    ``Syntax error`` (FNDOER's SYNCHR for the ``=``).  None when the name or the
    parameters do not read."""
    if start + 2 >= len(tokens) or tokens[start].type != "DEF" or tokens[start + 1].type != "FN":
        return None
    after = start + 3  # past DEF FN name
    if after < len(tokens) and tokens[after].type == "_LPAR":
        after = next((k + 1 for k in range(after, len(tokens)) if tokens[k].type in ("_RPAR", "_COLON")), len(tokens))
    try:
        found = _parse(tokens[start:after] + [Token("EQ", "="), Token("NUMBER", 0.0)])
    except (BasicError, GrammarError):
        return None
    if len(found) != 1 or not isinstance(found[0], ast.DefFn):
        return None
    equals = after < len(tokens) and tokens[after].type == "EQ"
    found[0].body = err if equals else BasicError("Syntax error", SYNTAX_ERROR)
    if equals:  # what the body reads before its bad text is evaluated first (FNA(X) + PRINT: FNA's error)
        end = next((k for k in range(after, len(tokens)) if tokens[k].type == "_COLON"), len(tokens))
        cut = _cut_expression([Token("NAME", "X")] + tokens[after:end], 0, err, dialect)
        if cut is not None and isinstance(cut[0], ast.Let):
            found[0].body = cut[0].value
    return found[0]


def _edit_tail_error(tokens: list, start: int, dialect: Dialect):
    """An EDIT whose line number (or ``.``) reads but is followed by more of the statement:
    ``dialect.edit_tail_error`` (SCNEDT.ASM EDIT reads the line with LINSPC, then refuses a
    statement that goes on with EFCERR).  None for any other bad statement."""
    code = dialect.edit_tail_error
    if code is None or tokens[start].type != "EDIT" or start + 2 >= len(tokens):
        return None
    line = tokens[start + 1]
    if line.type != "PERIOD" and not (line.type == "NUMBER" and (line.value == ast.CURRENT_LINE or _is_line_number(line))):
        return None
    if tokens[start + 2].type == "_COLON":
        return None
    return BasicError(MESSAGES[code], code)


def _checked_first(tokens: list, start: int, err: BasicError):
    """A bad RESUME or WHILE: the statement with ``err`` in place of what does not read, for
    the check it makes before reading it to come first (GWMAIN.ASM RESUME: not in a handler,
    ``RESUME without error``; FIVEO.ASM WHILE looks for its WEND, ``WHILE without WEND``,
    before it evaluates its condition).  None for any other bad statement."""
    kind = tokens[start].type
    if kind == "RESUME":
        return ast.Resume("bad", error=err)
    if kind == "WHILE":
        return _while_read_first(tokens, start, err)
    if kind == "WEND":
        return ast.Wend(err)  # FIVEO.ASM WEND: Syntax error before it looks at the stack
    if kind == "RETURN":
        return _return_read_first(tokens, start)
    if kind == "RESTORE":
        return _restore_read_first(tokens, start, err)
    return None


def _restore_read_first(tokens: list, start: int, err: BasicError):
    """A bad RESTORE: BIMISC.ASM RESTORE reads the digits that follow as a line (none: line
    0), which must exist (Undefined line number), sets the DATA pointer there, and only then
    is the rest of the statement ``err`` (``RESTORE 10 X`` restores, then Syntax error)."""
    line = 0
    if start + 1 < len(tokens) and tokens[start + 1].type == "NUMBER" and tokens[start + 1].value != ast.CURRENT_LINE:
        value = _number_value(tokens[start + 1])
        if not 0 <= value < 65530:
            return None
        line = int(value)  # (LINGET's digits: 1.5 is line 1)
    return ast.CutShort(ast.Restore(line), err)


def _while_read_first(tokens: list, start: int, err: BasicError):
    """A bad WHILE: FIVEO.ASM WHILE scans for its WEND, then evaluates its condition; a false
    one goes on after the WEND, a true one makes the loop's entry, and only then does NEWSTT
    meet what follows the condition: ``err`` (``WHILE A < 9 PRINT`` runs the loop, each pass
    starting with the Syntax error).  A condition that does not read is itself ``err``."""
    end = next((k for k in range(start + 1, len(tokens)) if tokens[k].type in _STATEMENT_ENDS), len(tokens))
    for k in range(end - 1, start + 1, -1):
        if tokens[k].type in _OPERATORS:
            continue
        try:
            found = _parse(tokens[start:k])
        except (BasicError, GrammarError):
            continue
        if len(found) == 1 and isinstance(found[0], ast.While):
            found[0].rest_error = err
            return found[0]
    return ast.While(err)


def _return_read_first(tokens: list, start: int):
    """A bad RETURN: GWMAIN.ASM RETURN takes its GOSUB off the stack first (RETURN without
    GOSUB when there is none), then goes on at GOTO, whose LINGET reads the digits and jumps
    without reading what follows them (``RETURN 40,`` goes to 40); with no digits, a plain
    RETURN, as ``return_stmt`` reads ``RETURN X`` (PC-BASIC 2.0.8)."""
    if start + 1 < len(tokens) and tokens[start + 1].type == "NUMBER" and _is_line_number(tokens[start + 1]):
        return ast.ReturnTo(_line_number(tokens[start + 1]))
    return ast.Return()


# The file statements that find their file before they read on: the modes it must be open
# in, whether the # may be left out, and whether it is found as GET and PUT find it (a file
# not open Bad file mode: files.FileTable.opened) (GIO86.ASM FILGET for PRINT #, WRITE #,
# INPUT #, LINE INPUT #; FILWID for WIDTH #; DSKCOM.ASM FIELD: FILSCN; DPUTG for GET, PUT).
_FILE_FIRST = {
    "PRINT": ("OAR", False, False), "WRITE": ("OAR", False, False), "INPUT": ("IR", False, False),
    "WIDTH": ("IOAR", False, False), "FIELD": ("R", True, False), "GET": ("R", True, True), "PUT": ("R", True, True),
}


def _file_checked_first(tokens: list, start: int, err: BasicError):
    """A bad file statement whose file number reads: the file's checks, then ``err``
    (``PRINT #1`` with file 1 not open is ``Bad file number``, not ``Syntax error``).
    None for any other bad statement."""
    k = start + (start + 1 < len(tokens) and tokens[start].type == "LINE" and tokens[start + 1].type == "INPUT")
    rule = _FILE_FIRST.get(tokens[k].type) if k < len(tokens) else None
    if rule is None or (k > start and tokens[k].type != "INPUT"):
        return None
    modes, optional, opened = rule
    k += 1
    if k < len(tokens) and tokens[k].type == "HASH":
        k += 1
    elif not optional:
        return None
    end = argument_end(tokens, k)
    number = parse_expression(tokens[k:end])
    return None if number is None else ast.FileFirst(number, modes, opened, err)


def argument_end(tokens: list, k: int, stops=("COMMA",)) -> int:
    """Where the argument that starts at ``k`` ends: at a token of ``stops`` or the
    statement's end outside parentheses (or the end of ``tokens``)."""
    depth = 0
    while k < len(tokens) and not (depth == 0 and (tokens[k].type in stops or tokens[k].type in _STATEMENT_ENDS)):
        depth += {"_LPAR": 1, "_RPAR": -1}.get(tokens[k].type, 0)
        k += 1
    return k


def _chain_file_first(tokens: list, start: int, err: BasicError):
    """A bad CHAIN whose file name reads: the file found first, then ``err`` (FIVEO.ASM
    CHAIN opens its file, PRGFLI, before it reads the options: ``CHAIN "B", 10,`` without a
    file B is File not found).  None for any other bad statement."""
    if tokens[start].type != "CHAIN":
        return None
    merge = start + 1 < len(tokens) and tokens[start + 1].type == "MERGE"
    k = start + 1 + merge
    for end in range(argument_end(tokens, k), k, -1):  # FRMEVL reads the longest expression
        name = parse_expression(tokens[k:end])
        if name is not None:
            return ast.Chain(merge, name, None, False, None, error=err)
    return None


def _run_before_leftover(tokens: list, start: int, err: BasicError, dialect: Dialect):
    """A KILL or a device word's statement (CHDIR, MKDIR, RMDIR, OUT, LOCK ...) whose text
    reads up to where the grammar stops: the statement as far as it reads, run, then
    ``err`` (GIODSK.ASM KILL reads its name with NAMFIL and deletes the file before NEWSTT
    meets what follows; the device words act, then GWMAIN.ASM GONZER finds the leftover:
    ``CHDIR "" LPRINT`` is Bad file name, as a real GW-BASIC 3.23 recorded it, PC-BASIC's
    DISK2 test).  None for any other statement, for SOUND (it checks its end first,
    gw_words.ENDS_FIRST), where the part before the stop does not read whole or ends
    where an argument should follow (``CHDIR MKDIR``: the expression's Syntax error), and
    where the word reads fewer arguments than it may take (``LOCK #1 LPRINT`` is Syntax
    error and locks nothing, ``LOCK #1, 1 TO 2 TO 3`` locks first: the LOCK test)."""
    kind, words = tokens[start].type, dialect.device_words
    if not (kind == "KILL" or (kind == "WORDSTMT" and words is not None and tokens[start].value in words.statements
                                and tokens[start].value not in words.ends_first)):
        return None
    end = next((k for k in range(start, len(tokens)) if tokens[k].type in _STATEMENT_ENDS), len(tokens))
    at = _grammar_stop(tokens, start, end)
    if at is None or at in (start, end) or tokens[at - 1].type in ("WORDSTMT", "KILL", "HASH", "COMMA", "TO", "EQ"):
        return None  # (no argument read: the stop is the expression's own Syntax error)
    try:
        found = _parse(tokens[start:at])
    except (BasicError, GrammarError):
        return None
    if len(found) != 1:
        return None
    node = found[0]
    if isinstance(node, ast.WordStatement) and len(node.args) < len(words.statements[node.word][0]):
        return None  # an optional argument's comma could come there: the word's own Syntax error first
    return ast.CutShort(node, err)


def _mid_read_as_far(tokens: list, start: int, err: BasicError):
    """A bad MID$ statement whose target and start read: the statement up to its start and
    count (where that reads), then ``err``: BISTRS.ASM LHSMID reads the start and the count
    as bytes and checks each as it reads it (GETBYT; a start of 0 Illegal function call),
    so ``MID$(A$,0`` is Illegal function call, not Syntax error.  None for any other bad
    statement."""
    if start + 1 >= len(tokens) or (tokens[start].type, tokens[start].value, tokens[start + 1].type) != (
            "FUNCN", "MID$", "_LPAR"):
        return None
    pieces, k = [], start + 2
    while len(pieces) < 3:
        end = argument_end(tokens, k, ("COMMA", "_RPAR"))
        piece = parse_expression(tokens[k:end])
        if piece is None:
            break
        pieces.append(piece)
        if end == len(tokens) or tokens[end].type != "COMMA":
            break
        k = end + 1
    if len(pieces) < 2 or not isinstance(pieces[0], (ast.Var, ast.Elem)):
        return None
    return ast.MidAssign(pieces[0], pieces[1], pieces[2] if len(pieces) > 2 else None, None, err)


def _input_file_first(tokens: list, start: int, err: BasicError):
    """A bad statement that ends inside the file number of ``INPUT$(n, #f``: its count and
    its file checked, then ``err`` (DSKCOM.ASM FIXINP reads the count with GETBYT and finds
    the file, FILSCN, before its SYNCHR for the ``)``).  None for any other bad statement."""
    end = argument_end(tokens, start, ())
    for k in range(end - 2, start - 1, -1):
        if (tokens[k].type, tokens[k].value, tokens[k + 1].type) != ("FUNCN", "INPUT$", "_LPAR"):
            continue
        comma = argument_end(tokens, k + 2)
        count = parse_expression(tokens[k + 2:comma])
        if count is None or comma == end:
            return None
        first = comma + 1 + (comma + 1 < end and tokens[comma + 1].type == "HASH")
        number = parse_expression(tokens[first:end])
        return None if number is None else ast.FileFirst(number, "IR", True, err, count)
    return None


def parse_expression(tokens: list):
    """The expression ``tokens`` are, or None where they are none (read as ``X = ...``)."""
    if not tokens:
        return None
    try:
        found = _parse([Token("NAME", "X"), Token("EQ", "="), *tokens])
    except (BasicError, GrammarError):
        return None
    return found[0].value if len(found) == 1 and isinstance(found[0], ast.Let) else None


def _next_read_as_far(tokens: list, start: int, err: BasicError):
    """A bad NEXT: the NEXTs of the names that read, then ``err``, raised once the last of
    them lets its loop end (NEXT86.ASM NEXT reads one name at a time, LOOPDN the comma after
    it; ``NEXT J, I PRINT`` runs both loops, then Syntax error).  When not even the first
    name reads (``NEXT "A"``), a NEXT whose name is ``err``: still a NEXT that a FOR's scan
    finds (GWMAIN.ASM NXTSCN stops at the word), the error raised by that FOR's first test
    (NEXTS's PTRGET) and by the NEXT when reached.  None for any other bad statement."""
    if tokens[start].type != "NEXT":
        return None
    end = next((k for k in range(start + 1, len(tokens)) if tokens[k].type in _STATEMENT_ENDS), len(tokens))
    for k in range(end, start + 1, -1):
        try:
            found = _parse(tokens[start:k])
        except (BasicError, GrammarError):
            continue
        if found and all(isinstance(node, ast.Next) and node.var is not None for node in found):
            if tokens[k].type != "COMMA":
                return found + [err]
            # after a comma another NEXT: the name that does not read, or none (LOOPD1 calls
            # NEXTC with a variable pointer no FOR entry has: NEXT without FOR)
            last = err if k + 1 < end else BasicError("NEXT without FOR", NEXT_WITHOUT_FOR)
            return found + [ast.Next(last)]
    return [ast.Next(err)]


def _jump_read_as_needed(tokens: list, start: int):
    """A bad ``ON x GOTO``/``GOSUB`` whose selector reads: the jump to the line numbers its
    text starts with, what follows them its ``rest_error``.  GW-BASIC skips only as many
    line numbers as the selector needs and jumps (``ON 1 GOTO 20,`` and ``ON 1 GOTO 20 X``
    go to 20); a selector that picks none reads them all and then the statement must end
    (GWMAIN.ASM NTONGS, LOOPON; GOTO's LINGET).  None for any other bad statement."""
    if tokens[start].type != "ON":
        return None
    jump = next((k for k in range(start + 1, len(tokens)) if tokens[k].type in ("GOTO", "GOSUB", "_COLON")), None)
    if jump is None or tokens[jump].type == "_COLON":
        return _selector_read_first(tokens, start, len(tokens) if jump is None else jump)
    try:
        found = _parse(tokens[start:jump + 1])
    except (BasicError, GrammarError):
        return None
    if len(found) != 1 or not isinstance(found[0], ast.OnJump):
        return None
    targets: list = [None]
    k = jump + 1
    while k < len(tokens):
        kind = tokens[k].type
        if kind == "NUMBER" and targets[-1] is None and _is_line_number(tokens[k]):
            targets[-1] = _line_number(tokens[k])
        elif kind == "COMMA":
            targets.append(None)
        else:
            break
        k += 1
    found[0].targets = targets
    if k < len(tokens) and tokens[k].type not in _STATEMENT_ENDS:
        found[0].rest_error = BasicError("Syntax error", SYNTAX_ERROR)  # NEWSTT finds no statement's end
    return found[0]


# Binary operators: a cut after one leaves the operand before it read (FRMEVL evaluated it).
_BINARY_OPERATORS = frozenset(("PLUS", "MINUS", "STAR", "SLASH", "BSLASH", "CARET", "EQ", "LT", "GT", "LE", "GE",
                               "NE", "AND", "OR", "XOR", "EQV", "IMP", "MOD"))


def _grammar_stop(tokens: list, start: int, end: int) -> int | None:
    """Where in ``tokens[start:end]`` the grammar stops reading (``end``: the text ended
    early); None when it reads whole or the scanner's error comes first."""
    try:
        _parse(tokens[start:end])
        return None
    except GrammarError as exc:
        return next((k for k in range(start, end) if tokens[k] is exc.token), end)
    except BasicError:
        return None


def _cut_expression(tokens: list, start: int, err: BasicError, dialect: Dialect):
    """A bad statement whose text goes wrong inside a function call's arguments or after an
    operator: the statement with what was read standing in for the rest (a
    :class:`ast.CutCall` or :class:`ast.CutExpression`), so that what GW-BASIC evaluated
    before it met the bad text runs first, in order (``PRINT "A"; INSTR(-1`` prints A, then
    INSTR's start is Illegal function call; ``X = FNA(1) +`` calls FNA first).  None where
    the dialect does not read so (``Dialect.argument_readings``) or nothing fits."""
    if not dialect.argument_readings or tokens[start].type == "WRITE":  # (WRITE: _written_before_error)
        return None
    end = next((k for k in range(start, len(tokens)) if tokens[k].type == "_COLON"), len(tokens))
    at = _grammar_stop(tokens, start, end)
    if at is None:
        return None
    opens: list = []
    for k in range(start, at):
        if tokens[k].type == "_LPAR":
            opens.append(k)
        elif tokens[k].type == "_RPAR" and opens:
            opens.pop()
    calls = [k for k in opens if k > start and (tokens[k - 1].type in ("FUNCN", "SCREEN") or tokens[k - 1].type == "FUNC" and (
        k + 1 < len(tokens) and tokens[k + 1].type == "HASH" or tokens[k - 1].value in dialect.argument_readings))]
    if calls:
        paren = calls[-1]
        node = _cut_call(tokens, paren, at, err)
        if node is None:
            return None
        return _with_partial(tokens, start, paren - 1, node, [k for k in opens if k < paren])
    if at == start or tokens[at - 1].type not in _BINARY_OPERATORS or at - 1 <= start:
        return None
    for k in range(start + 1, at - 1):  # the longest operand before the operator that fits
        read = parse_expression(tokens[k:at - 1])
        if read is None:
            continue
        found = _with_partial(tokens, start, k, ast.CutExpression(read, err), [j for j in opens if j < k])
        if found is not None:
            return found
    return None


def _cut_call(tokens: list, paren: int, at: int, err: BasicError):
    """The call whose ``(`` is at ``paren``, its text cut at ``at``: the arguments that read
    whole, and whether the cut comes where an argument starts."""
    if paren + 1 < at and tokens[paren + 1].type == "HASH":  # WORD(#n: the file's checks, then the ")"
        number = parse_expression(tokens[paren + 2:at])
        return None if number is None else ast.CutFileCall(tokens[paren - 1].value, number,
                                                           BasicError("Syntax error", SYNTAX_ERROR))
    pieces, depth, begin = [], 0, paren + 1
    for k in range(paren + 1, at):
        kind = tokens[k].type
        depth += {"_LPAR": 1, "_RPAR": -1}.get(kind, 0)
        if kind == "COMMA" and depth == 0:
            pieces.append(tokens[begin:k])
            begin = k + 1
    args = []
    for piece in pieces:
        arg = parse_expression(piece)
        if arg is None:
            return None
        args.append(arg)
    last = tokens[begin:at]
    whole = parse_expression(last) if last else None
    if whole is not None:
        return ast.CutCall(tokens[paren - 1].value, tuple(args + [whole]), False, BasicError("Syntax error", SYNTAX_ERROR))
    return ast.CutCall(tokens[paren - 1].value, tuple(args), True, err)


def _with_partial(tokens: list, start: int, at: int, node, opens: list):
    """The statement ``tokens[start:at]`` followed by ``node`` (and a ``)`` for each of
    ``opens``), if it reads as one statement; else None."""
    try:
        found = _parse(tokens[start:at] + [Token("PARTIAL", node)] + [Token("_RPAR", ")")] * len(opens))
    except (BasicError, GrammarError):
        return None
    return found if len(found) == 1 else None


def _first_value_checked(tokens: list, start: int, err: BasicError):
    """A bad KEY n, text or NAME old AS new whose first value reads: that value checked as the
    statement checks it before it reads on (GWSTS.ASM KEYS: GETBYT of the key's number;
    GIODSK.ASM NAME: the old file found before the AS), then ``err``.  None otherwise."""
    kind = tokens[start].type if start < len(tokens) else None
    if kind not in ("KEY", "RENAME") or start + 1 >= len(tokens) or tokens[start + 1].type in ("ON", "OFF", "LIST"):
        return None
    if _assigned_before_error(tokens, start):
        return None  # the whole statement reads, junk after it (it runs first: _bad_and_after)
    end = argument_end(tokens, start + 1, ())
    value = next((found for found in (parse_expression(tokens[start + 1:k]) for k in range(end, start + 1, -1))
                  if found is not None), None)  # the longest value that reads
    if value is None:
        return None
    return ast.Key("NUMBER", value, err) if kind == "KEY" else ast.Rename(value, None, err)


def _selector_read_first(tokens: list, start: int, end: int):
    """``ON x`` with no GOTO or GOSUB before ``end``: the selector's value is checked
    (GWMAIN.ASM NTONGS: GETBYT, Illegal function call outside 0..255), then the missing
    word is a Syntax error (SYNCHR for GOTO): a jump with no places whose ``rest_error``
    is that error.  None when no selector reads after ON, or when it stops at an operator
    (``ON A+``: the expression's own error, Missing operand)."""
    for k in range(end, start + 1, -1):
        if k < end and tokens[k].type in _OPERATORS:
            continue
        try:
            found = _parse(tokens[start:k] + [Token("GOTO", "GOTO"), Token("NUMBER", (0, "%"))])
        except (BasicError, GrammarError):
            continue
        if len(found) == 1 and isinstance(found[0], ast.OnJump):
            found[0].targets = []
            found[0].rest_error = BasicError("Syntax error", SYNTAX_ERROR)
            return found[0]
    return None


def _is_line_number(token: Token) -> bool:
    """A NUMBER token GW would have stored as a line number (digits only)."""
    try:
        _line_number(token)
    except BasicError:
        return False
    return True


def _touched_element(tokens: list, start: int, err: BasicError):
    """A bad statement that begins with an array element (``DIMA$(20)``: the name DIMA$):
    GW-BASIC's LET reads its target (PTRGET: the array made, the subscripts checked) before
    it looks for the ``=``; None for any other bad statement."""
    if start + 1 >= len(tokens) or tokens[start].type not in ("NAME", "STRNAME") or tokens[start + 1].type != "_LPAR":
        return None
    depth = 0
    for k in range(start + 1, len(tokens)):
        depth += {"_LPAR": 1, "_RPAR": -1}.get(tokens[k].type, 0)
        if depth == 0:
            break
    else:
        return None
    if k + 1 < len(tokens) and tokens[k + 1].type == "EQ":
        return None  # the assignment itself is bad: its value
    try:
        found = _parse(tokens[start:k + 1] + [Token("EQ", "="), Token("NUMBER", 0.0)])
    except (BasicError, GrammarError):
        return None
    if len(found) != 1 or not isinstance(found[0], ast.Let):
        return None
    return ast.Touch(found[0].target, err)


def _branch_if(tokens: list):
    """``tokens`` (IF x THEN branch) read as one IF, or None."""
    try:
        found = _parse(tokens)
    except (BasicError, GrammarError):
        return None
    return found[0] if len(found) == 1 and isinstance(found[0], ast.If) else None


# Tokens a ``(`` after which continues an item (a subscript, a function's arguments).
_CALLED = frozenset(("NAME", "STRNAME", "FUNC", "FUNCN", "TAB", "SPC"))


# Tokens an expression goes on with after an operand (FRMEVL reads on past them).
_OPERATORS = frozenset(_OPERATOR_NAMES)


def _written_before_error(tokens: list, start: int) -> list:
    """A bad WRITE whose items read up to a separator or to a token no expression goes on
    with: those items as FIVEO.ASM WRITE prints them, an item, then (after its ``,`` or
    ``;``) a comma before it reads the next: ``WRITE 1,`` prints ``1,``, then the next
    item's ``Missing operand``; ``WRITE 1 X`` prints ``1``, then ``Syntax error`` (its
    SYNCHR for the comma).  Neither has a line end.  Empty otherwise."""
    if start >= len(tokens) or tokens[start].type != "WRITE":
        return []
    end = argument_end(tokens, start, ())
    for k in range(end - 1, start, -1):
        after, last = tokens[k].type, tokens[k - 1].type
        separated = after in ("COMMA", "SEMI")
        if not separated and (after in _OPERATORS or (after == "_LPAR" and last in _CALLED)):
            continue  # the prefix ends inside an item (``1+``, ``A(``)
        try:
            found = _parse(tokens[start:k])
        except (BasicError, GrammarError):
            continue
        if len(found) == 1 and isinstance(found[0], ast.Write) and found[0].items:
            found[0].cut = "," if separated else ""  # (what follows: the comma, or the grammar's Syntax error)
            return found
    return []


def _printed_before_error(tokens: list, start: int) -> list:
    """A bad PRINT's longest good start, as a PRINT that leaves the line open: GW-BASIC
    prints each item as it reads it (``PRINT "a"; ERL(`` prints ``a 0``, then ``Missing
    operand``: ``(`` begins another item).  Empty for any other statement."""
    if start >= len(tokens) or tokens[start].type not in ("PRINT", "LPRINT"):
        return []
    end = next((k for k in range(start, len(tokens)) if tokens[k].type == "_COLON"), len(tokens))
    # (not inside an item: ``1+``, ``A(``, ``1 2``, which GW reads 12; before anything else the
    # item is printed: PRINT's loop then reads what follows as the next item, ``(1)%`` or
    # ``LEFT $(``, and FRMEVL finds no operand there)
    ends = []
    for k in range(end - 1, start, -1):
        after, last = tokens[k + 1].type if k + 1 < end else None, tokens[k].type
        if not (after in _EXPRESSION_GOES_ON or (after == "_LPAR" and last in _CALLED) or after == last == "NUMBER"):
            ends.append(k + 1)
    found = _first_parse(tokens, start, ends)
    if len(found) == 1 and isinstance(found[0], ast.Print) and found[0].using is None:
        printed = found[0]
        if not printed.items or printed.items[-1] not in (",", ";"):  # (``PRINT #1,`` wrote nothing)
            printed.items = list(printed.items) + [";"]
        return [printed]
    return []


def _first_parse(tokens: list, start: int, ends) -> list:
    """The statements ``tokens[start:k]`` parse as, for the first ``k`` of ``ends`` (the
    longest good start first) at which they parse at all; empty when none does."""
    for k in ends:
        try:
            return _parse(tokens[start:k])
        except (BasicError, GrammarError):
            continue
    return []


# Tokens after which an expression goes on: its operators (a ``(`` after a name or a function
# and a number after a number are handled by the caller).
_EXPRESSION_GOES_ON = frozenset(("PLUS", "MINUS", "STAR", "SLASH", "BSLASH", "CARET", "EQ", "LT", "GT", "LE", "GE",
                                 "NE", "AND", "OR", "XOR", "EQV", "IMP", "MOD", "PERIOD", "ELSE"))
# (SWAP exchanges, DATE$ = sets the date, OPTION BASE sets the base, KEY defines or lists,
# NAME renames, then the statement must end: BIMISC.ASM SWAP, GWSTS.ASM DATES and KEYS,
# GWMAIN.ASM OPTION's CHRGTR for the terminator, GIODSK.ASM NAME)
_ASSIGNMENTS = (ast.Let, ast.LSet, ast.Swap, ast.SetClock, ast.OptionBase, ast.Key, ast.Rename)


def _assigned_before_error(tokens: list, start: int) -> list:
    """A bad assignment (LET, LSET, RSET) whose value ends before its
    statement does (``A$ = "X" LPRINT``): the assignment, which GW-BASIC makes before it
    finds no end of statement there (the statement's value is read by FRMEVL, which stops
    at the first token that cannot go on with it; GWMAIN.ASM NEWSTT then wants ``:`` or the
    line's end: ``Syntax error``).  Empty for any other bad statement, or when the value
    itself is bad, or where the next token could go on with it (``A = 1 2`` is 12)."""
    end = next((k for k in range(start, len(tokens)) if tokens[k].type == "_COLON"), len(tokens))
    ends = [k + 1 for k in range(end - 2, start, -1)
            if not (tokens[k + 1].type in _EXPRESSION_GOES_ON or tokens[k + 1].type == tokens[k].type == "NUMBER"
                    or (tokens[k + 1].type == "_LPAR" and tokens[k].type in _CALLED))]
    found = _first_parse(tokens, start, ends)
    return found if len(found) == 1 and isinstance(found[0], _ASSIGNMENTS) else []


# Statements of a list that GW-BASIC handles one item at a time: the node, its list, and
# whether an item may end without a comma after it (a name or a ``)``: DIM, ERASE) or only
# at a comma (CLOSE's numbers: ``CLOSE 1 2`` is file 12)
_ITEM_LISTS = {"DIM": (ast.Dim, "arrays", True), "ERASE": (ast.Erase, "names", True),
               "CLOSE": (ast.Close, "numbers", False)}


def _arrays_before_error(tokens: list, start: int) -> list:
    """A bad DIM, ERASE or CLOSE whose first items read (``DIM A(1), B(``, ``ERASE A,``,
    ``DIM A(1) B``, ``CLOSE 1,``): the statement with those items, which GW-BASIC dimensions,
    erases or closes one by one before it looks at what follows each (BIPTRG.ASM DIM and
    DIMCON: a comma, or the statement's end; GWMAIN.ASM ERASE and GIO86.ASM CLOSE likewise),
    so a second DIM of one of them is Duplicate Definition, and an array erased or a file
    closed is gone, before the cut's error.  Empty otherwise."""
    rule = _ITEM_LISTS.get(tokens[start].type) if start < len(tokens) else None
    if rule is None:
        return []
    node, field, ends_alone = rule
    end = next((k for k in range(start, len(tokens)) if tokens[k].type in _STATEMENT_ENDS), len(tokens))
    depth, ends = 0, []  # where an item may end
    for k in range(start + 1, end):
        depth += {"_LPAR": 1, "_RPAR": -1}.get(tokens[k].type, 0)
        if depth == 0 and ends_alone and tokens[k].type in ("_RPAR", "NAME", "STRNAME"):
            ends.append(k + 1)
        elif depth == 0 and not ends_alone and tokens[k].type == "COMMA":
            ends.append(k)
    found = _first_parse(tokens, start, reversed(ends))
    return found if len(found) == 1 and isinstance(found[0], node) and getattr(found[0], field) else []


MAX_NESTING = 60  # IFs in one line, or parentheses inside each other


def _check_nesting(tokens: list) -> None:
    """Refuse absurdly deep lines before parsing: ``Out of memory`` (the period's answer)."""
    depth = deepest = ifs = 0
    for token in tokens:
        kind = token.type
        if kind == "_LPAR":
            depth += 1
            deepest = max(deepest, depth)
        elif kind == "_RPAR":
            depth -= 1
        elif kind == "IF":
            ifs += 1
    if deepest > MAX_NESTING or ifs > MAX_NESTING:
        from yaseer.basic.errors import OUT_OF_MEMORY
        raise BasicError("Out of memory", OUT_OF_MEMORY)


def _bad_else_branches(text: str, err: BasicError, dialect: Dialect) -> list | None:
    """``IF c THEN s ELSE bad`` (IFs nested in the THEN branch may have ELSEs too): the line
    before its first ELSE parsed, each ELSE branch given to the IF it belongs to, the innermost
    first (a branch that does not parse is ``err``); None when the line is no such IF."""
    import re  # only for a line that does not parse: a cold start of a good listing does not load it

    places = [m.start() for m in re.finditer("ELSE", _blank_strings(text))]
    if not places:
        return None
    try:
        statements = parse_statements(text[:places[0]], dialect)
    except BasicError:
        return None
    ifs = []  # the IFs the line ends with, outermost first: the ELSEs' owners
    inner = statements[-1] if statements else None
    while isinstance(inner, ast.If) and inner.otherwise is None:
        ifs.append(inner)
        inner = inner.then[-1] if isinstance(inner.then, list) and inner.then else None
    ends = places[1:] + [len(text)]
    if len(places) > len(ifs):
        return None
    for owner, start, end in zip(reversed(ifs), places, ends):
        branch = text[start + 4:end].strip()
        try:
            owner.otherwise = int(branch) if branch.isdigit() else parse_statements(branch, dialect)
        except BasicError:
            owner.otherwise = [err]
    return statements


def _blank_strings(text: str) -> str:
    """``text`` with every string literal blanked (same length), so a search finds only words."""
    import re

    return re.sub(r'"[^"]*"?', lambda m: " " * len(m.group()), text)


def _in_branch(text: str, err: BasicError, dialect: Dialect) -> list | None:
    """Where the dialect finds only a bad IF branch when it runs (``words.branch_errors_when_reached``):
    the line's statements with ``err`` inside the branch of the IF they end with, so the line runs
    up to that IF and the branch is the error only if the condition takes it; None when the bad
    statement is not in an IF's branch (the whole line is the error)."""
    if not getattr(dialect.words, "branch_errors_when_reached", False):
        return None
    otherwise = _bad_else_branches(text, err, dialect)
    if otherwise is not None:
        return otherwise
    statements = _recover(text, err, dialect)
    if not statements or not isinstance(statements[-1], ast.If) or any(
            isinstance(statement, BasicError) for statement in statements):
        return None
    return statements


def parse_line(number: int, text: str, dialect: Dialect = CASIO) -> ast.Line:
    """Parse one numbered line; a syntax error is stored in ``Line.error`` or, where the
    dialect finds errors when execution reaches them, after the statements before it.  A
    slip of the reader itself becomes the line's ``Internal error``, one line where the
    program stops, never a traceback."""
    try:
        return _parsed_line(number, text, dialect)
    except RecursionError:
        from yaseer.basic.errors import OUT_OF_MEMORY
        return ast.Line(number, [], text, error=BasicError("Out of memory", OUT_OF_MEMORY))
    except BasicError:
        raise
    except Exception as slip:  # (a bug of this module: the program still gets one BASIC error)
        error = BasicError(f"Internal error (reading the line: {type(slip).__name__}: {slip})", INTERNAL_ERROR)
        return ast.Line(number, [], text, error=error)


def _parsed_line(number: int, text: str, dialect: Dialect) -> ast.Line:
    try:
        statements = parse_statements(text, dialect)
    except BasicError as err:
        statements = _recover(text, err, dialect) if dialect.errors_when_reached else _in_branch(text, err, dialect)
        if statements is None or statements == [err]:
            return ast.Line(number, [], text, error=err)
        return ast.Line(number, statements, text)
    return ast.Line(number, statements, text)
