"""CHAIN, MERGE and COMMON: a running program hands over to another program file
(the :class:`Chaining` mixin of :class:`yaseer.basic.machine.Machine`).

``CHAIN [MERGE] file [, line] [, ALL] [, DELETE first-last]`` (FIVEO.ASM ``CHAIN``):
the file (``.BAS`` added to a name without a ``.``, read from the program's directory
as LOAD reads it: yaseer.basic.program_file) replaces the program, or with MERGE is
merged into it (an ASCII file only: ``Bad file mode``), after the lines of the DELETE
range are removed (the range must end on an existing line: ``Illegal function call``).
The variables named in the program's COMMON statements (wherever they are, run or
not, at a statement's start, not right after THEN or ELSE: CHAIN scans the statements
for them and reads their lists, source/common_lists.py), or with ALL every variable, keep their
values; the others are cleared, as are DEF FN functions (unless MERGE with ALL), the
GOSUB/FOR stack and ON ERROR.  Open files stay open and OPTION BASE stays.  The new
program runs from its start or from ``line``.  ``MERGE file`` merges the file and
then stops the program (GW-BASIC returns to direct mode).

The file is read when the statement runs, so a missing file is the statement's error
(``File not found``, trappable); what follows is done by the run loop, which catches
:class:`ChainTo`.
"""

from __future__ import annotations

from collections import namedtuple

from yaseer.basic.machine import memory_model
from yaseer.basic.machine.files import read_program
from yaseer.basic.machine.sandbox import nameless
from yaseer.basic.errors import (
    BAD_FILE_MODE, BasicError, ILLEGAL_DIRECT, ILLEGAL_FUNCTION_CALL, UNDEFINED_LINE, error_for,
    password_protected,
)
from yaseer.basic.machine.signals import ProgramEnd
from yaseer.basic.source.line_ranges import deleted_lines
from yaseer.basic.source.scanner import DirectStatementInFile

TYPE_CHECKING = False
if TYPE_CHECKING:
    from yaseer.basic.source import syntax_tree


class ChainTo(ProgramEnd):
    """The program is being replaced (CHAIN) or merged into (MERGE): what to do next."""

    def __init__(self, lines: dict, merge: bool, line, everything: bool, delete, run: bool,
                 stopped: BasicError | None = None, common: tuple[set, set] | None = None):
        super().__init__()
        self.lines, self.merge, self.line = lines, merge, line
        self.everything, self.delete, self.run = everything, delete, run
        self.stopped = stopped  # the file's ``Direct statement in file``: raised once the lines are in
        self.common = common  # the COMMON scalars and arrays kept (without ALL: Chaining.common_names)


class ChainStart(namedtuple("ChainStart", "block direct_code", defaults=(None,))):
    """Where the run goes on after a CHAIN or MERGE: ``block`` of program area 0, or, where
    ``direct_code`` is given, the error handler's block for that direct line's trapped error
    (the line a RESUME goes back into): an int and a CompiledArea or None."""

    __slots__ = ()


class RunAgain(ProgramEnd):
    """RUN in a program: start again, from ``line`` (None: the start), with ``lines`` as the
    program (None: the same one); ``keep_files``: RUN "file",R and LOAD "file",R leave
    the files open."""

    def __init__(self, lines: dict | None, line: int | None, keep_files: bool):
        super().__init__()
        self.lines, self.line, self.keep_files = lines, line, keep_files


class Chaining:
    """CHAIN and MERGE on the machine's programs and variables (a mixin of ``Machine``)."""

    def _program_lines(self, name: str, merge: bool = False,
                       existing=None) -> tuple[dict[int, str | None], BasicError | None]:
        """The lines of program file ``name`` (``.BAS`` added to a name without ``.``), read
        as LOAD reads it (scanner.program_lines), and the ``Direct statement in file`` that
        stopped the reading (None if none: the lines before it are the program's); MERGE reads
        ASCII files only (``Bad file mode``).  An ASCII file's lines are entered as typed ones:
        the last is the current line (``_entered``).  ``existing``: MERGE's, the lines of the
        program the file joins (a bare number of one deletes it: None)."""
        from yaseer.basic.machine.program_file import TOKENISED, is_protected, program_text
        from yaseer.basic.source.scanner import program_lines

        data = read_program(self.files.sandbox, self._program_name(name))
        if merge and data[:1] >= bytes((TOKENISED - 1,)):
            raise error_for(BAD_FILE_MODE)  # DSKCOM.ASM OKGET2
        charset = self.dialect.charset
        text = charset.codes(program_text(data, charset))  # as shown, then in the machine's codes
        if not merge:
            self.program_protected = is_protected(data)
        lines, stopped = program_lines(text, self.dialect, from_file=True, existing=existing if merge else None)
        if not merge:  # (MERGE's lines must fit with the program they join: chained)
            lines, full = memory_model.fitting_lines({}, lines, self.dialect.free_memory)
            stopped = full or stopped
        if data[:1] < bytes((TOKENISED - 1,)):
            self._entered(lines)
        return lines, stopped

    def program_command(self, name: str, argument, option, everything: bool = False, file: str | None = None) -> None:
        """A command run by a program (GW-BASIC runs them and, but for RUN and the saves of
        the dialect's ``saves_going_on``, returns to direct mode: the run ends): RUN [line | "file"[,R]], LIST/LLIST [range], LOAD
        "file"[,R], SAVE "file"[,A|,P] (program_crunch.saved_program), NEW, SYSTEM, DELETE
        range, EDIT line (ends the run: there is no editor in a run), RENUM [new][, [old][,
        step]] (source/renumbering.py; its messages on the screen), KEY ON/OFF (the
        function-key line is the screen's: nothing where output is not a terminal).

        The Casio's (dialects/casio.py PROGRAM_COMMANDS): NEW and RUN refused (FC); LIST,
        SAVE, LOAD as GW's, and with ALL (``everything``) on every program area 0-9."""
        words = self.dialect.words
        if words is not None and name in words.refused_commands:
            raise error_for(ILLEGAL_DIRECT)
        if words is not None and self.password_set is not None and name in words.password_refuses:
            raise password_protected()  # PASS.md item 5
        if everything:
            self._every_area(name, argument)
        if name == "KEY":
            return
        if name == "AUTO":
            self._auto_mode(*argument)
        if name in ("RUN", "LOAD") and isinstance(argument, str):
            lines, stopped = self._program_lines(argument)
            if stopped is not None:  # the lines before it are the program; nothing runs
                raise ChainTo(lines, False, None, True, None, False, stopped)
            if name == "RUN" or option == "R":
                raise RunAgain(lines, None, name == "LOAD" or option == "R")
            raise ChainTo(lines, False, None, True, None, False)
        if name == "RUN":
            raise RunAgain(None, argument, False)
        program = self.programs.get(0, {})
        if self.program_protected and (name in ("LIST", "LLIST", "EDIT") or (name == "SAVE" and option != "P")):
            raise error_for(ILLEGAL_FUNCTION_CALL)  # GIODSK.ASM PROCHK: a protected program is not shown
        if name in ("LIST", "LLIST"):
            self._list_lines(program, argument, 1 if name == "LLIST" else 0, file)
        elif name == "SAVE":
            self._save(program, argument, option=option or "")
            if (option or "") in self.dialect.saves_going_on:
                return
        elif name == "NEW":
            self.program_protected = False
            raise ChainTo({}, False, None, True, None, False)
        elif name == "DELETE":  # its range must end on a line (GWLIST.ASM DELETE: source/line_ranges.py)
            doomed = deleted_lines(program, *argument, open_end=True)
            raise ChainTo({n: t for n, t in program.items() if n not in doomed}, False, None, True, None, False)
        elif name == "EDIT" and words is not None and words.edit_lists_from:
            self._list_lines(program, (argument, None), 0)  # the edit mode shows the program from there
            shown = [n for n in sorted(program) if n >= (argument or 0)]
            self.edit_request = shown[0] if shown else None  # the session puts that line up for editing
        elif name == "EDIT" and argument not in program:
            self._edited(argument)
            raise error_for(UNDEFINED_LINE)
        elif name == "EDIT":
            self._edited(argument)
        elif name == "RENUM":
            from yaseer.basic.source.renumbering import renumber  # here: only RENUM needs it

            new, old, step = argument
            renumbered, messages = renumber(program, 10 if new is None else new, old or 0,
                                            10 if step is None else step, self.dialect)
            for message in messages:
                self.print_items(0, (message,), True)
            raise ChainTo(renumbered, False, None, True, None, False)
        raise ProgramEnd()

    def _edited(self, number: int) -> None:
        """EDIT's line is the current line, whether it exists or not (SCNEDT.ASM EDIT stores
        DOT before FNDLIN looks for it)."""
        if self.dialect.current_line_listed:
            self.current_line = number

    def _auto_mode(self, start: int | None, step: int | None) -> None:
        """AUTO [start][, [step]] in a program (GWMAIN.ASM AUTO): the program stops and the
        command level numbers the lines typed next from ``start`` (10) by ``step`` (10; None:
        the step AUTO used last, AUTINC, which is 0 before any AUTO), which the session takes
        up (``auto_request``); a step of 0 is Illegal function call (``AUTO 10,`` with no AUTO
        before it: recorded in PC-BASIC's various_syntax_errors test).  Run without the
        session, the program ends there."""
        if step is None:
            step = self.auto_step
        if step == 0:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        self.auto_step = step
        self.auto_request = (10 if start is None else start, step)
        raise ProgramEnd()

    def _every_area(self, name: str, argument) -> None:
        """LIST ALL, SAVE ALL "file", LOAD ALL "file" (LIST.md item 13, SAVE_SAVE_ALL.md,
        LOAD_LOAD_ALL.md): the BASIC program areas 0-9 in order.  LIST shows each as a row
        ``P<n>`` and its lines; the ALL file is yaseer's own ASCII form of the machine's
        (whose format the manual does not give): each area's listing after a line
        ``PROG <n>``.  LOAD ALL replaces areas 1-9 by the file's (empty where it has none)
        and area 0 as LOAD does; then the run ends."""
        areas = [n for n in range(10) if self.programs.get(n)]
        if name == "LIST":
            for n in areas:
                self.print_items(0, (f"P{n}",), True)
                self._list_lines(self.programs[n], (None, None), 0)
        elif name == "SAVE":
            self._save({}, argument, {n: self.programs[n] for n in areas})
        else:
            lines = self._area_files(argument)
            for n in range(1, 10):
                if n in lines or n in self.programs:
                    self.load("\n".join(f"{k} {t}" for k, t in sorted(lines.get(n, {}).items())), n)
            raise ChainTo(lines.get(0, {}), False, None, True, None, False)
        raise ProgramEnd()

    def _area_files(self, name: str) -> dict[int, dict[int, str]]:
        """The areas of an ALL file (see ``_every_area``): area -> its lines."""
        from yaseer.basic.machine.program_file import program_text
        from yaseer.basic.source.scanner import split_lines

        charset = self.dialect.charset
        text = charset.codes(program_text(read_program(self.files.sandbox, self._program_name(name)), charset))
        areas: dict[int, list[str]] = {0: []}
        current = areas[0]
        for row in text.split("\n"):
            header = row.split()
            if len(header) == 2 and header[0].upper() == "PROG" and header[1].isdigit():
                current = areas.setdefault(int(header[1]), [])
            else:
                current.append(row)
        return {n: {k: t for k, t, _ in split_lines("\n".join(rows), self.dialect.joins_unnumbered_lines)}
                for n, rows in areas.items() if n < 10}

    def _program_name(self, name: str) -> str:
        """A program file's name as LOAD, SAVE, CHAIN read it: without the device that means
        the program's directory (the Casio's ``CAS0:``), ``.BAS`` added to a name without
        ``.`` (GIO86.ASM NAMBAS; ``GOSUB "name"`` finds it too: program_files.py).  A name
        that names nothing (sandbox.nameless) is the dialect's error for it, as OPEN's
        (Dialect.nameless_file_error): a file called ``.BAS`` would be a hidden file no user
        meant."""
        name = self.files._local_name(name)
        if nameless(name):
            raise error_for(self.dialect.nameless_file_error)
        return name if "." in name else name + ".BAS"

    def _list_lines(self, program: dict, line_range, device: int, file: str | None = None) -> None:
        """LIST / LLIST: the lines in ``line_range`` as LIST shows them; ``file``: written to
        that file instead (GWLIST.ASM LIST opens it for output as file 0), closed at the end."""
        from yaseer.basic.machine.program_crunch import listed_row

        first, last = line_range
        listing = None if file is None else self.files.listing_file(file)
        try:
            for number in sorted(program):
                if (first or 0) <= number <= (65529 if last is None else last):
                    if self.dialect.current_line_listed:
                        self.current_line = number  # GWLIST.ASM LIST keeps each line shown in DOT
                    row = listed_row(number, program[number], self.dialect, listing is not None)
                    if listing is None:
                        self.print_items(device, (row,), True)
                    else:
                        listing.output().write(row + "\r\n")
        finally:
            if listing is not None:
                listing.close()

    def _save(self, program: dict, name: str, areas: dict | None = None, option: str = "") -> None:
        """SAVE "f"[,A|,P]: the program as ``option`` asks (program_crunch.saved_program) in the
        program's directory.  ``areas``: SAVE ALL's areas (see ``_every_area``), one listing
        after another."""
        from yaseer.basic.machine.program_crunch import ascii_file, listing_text, saved_program

        if areas is None:
            data = saved_program(program, option, self.dialect)
        else:
            data = ascii_file("".join(f"PROG {n}\r\n" + listing_text(lines, self.dialect) for n, lines in areas.items()))
        sandbox = self.files.sandbox
        self.files.check_not_open(self._program_name(name))
        sandbox.write_bytes(sandbox.dos_name(self._program_name(name)), data)

    def run_again(self, again: RunAgain) -> int:
        """Carry out RUN: the program (a new one from a file), fresh variables, the files
        closed unless ``keep_files``; the block of area 0 to start from."""
        if again.lines is not None:
            self.programs[0] = dict(again.lines)
            self._invalidate(0)
            self._extra_entries.clear()
        kept = dict(self.files.open_files) if again.keep_files else {}
        for number in kept:
            del self.files.open_files[number]
        self._run_types(again.line if again.line in self.programs.get(0, {}) else None)
        self.reset()  # closes the files not kept
        self.files.open_files.update(kept)
        if again.line is None:
            return 0
        if again.line not in self.programs.get(0, {}):
            raise error_for(UNDEFINED_LINE)  # RUN has left the line it was in: none is named
        return self._line_block(again.line)

    def chain_file(self, name: str) -> None:
        """The file a CHAIN opens before it reads its options (FIVEO.ASM CHAIN: PRGFLI): its
        errors (``File not found``), nothing else."""
        read_program(self.files.sandbox, self._program_name(name))

    def chain(self, name: str, merge: bool, line, everything: bool, delete, run: bool = True) -> None:
        """CHAIN / MERGE as the statement runs: the file is read (its errors are this
        statement's) and the range checked, then :class:`ChainTo` ends the block."""
        existing = set(self.programs.get(0, {}))
        if merge and delete is not None:  # the DELETE comes first: a bare number of a deleted line deletes none
            try:
                existing -= set(deleted_lines(self.programs.get(0, {}), *delete))
            except BasicError:
                pass  # (a bad range's error comes after the file's: below)
        lines, stopped = self._program_lines(name, merge, existing)
        if line is not None:
            line = self._chain_line(line)
        if delete is not None:
            self._check_range(delete)
        common = self.common_names() if run and not everything else None  # (ALL: no scan, DNCMDA)
        raise ChainTo(lines, merge, line, everything, delete, run and stopped is None, stopped, common)

    @staticmethod
    def _chain_line(line) -> int:
        """CHAIN's line number: an unsigned 16-bit number (GWMAIN.ASM ``FRQINT``)."""
        n = round(line)
        if not -32768 <= n <= 65535:
            raise error_for(6)
        return n & 0xFFFF

    def _check_range(self, delete) -> None:
        """The DELETE range of a CHAIN: its last line must exist, its first not after it
        (FIVEO.ASM CHAIN: SCNLIN and FNDLIN as DELETE's, source/line_ranges.py)."""
        deleted_lines(self.programs.get(0, {}), *delete)

    def chained(self, chain: ChainTo) -> ChainStart | None:
        """Carry out a CHAIN or MERGE: the program and variables it leaves; where the run
        goes on (None: MERGE, which stops; a start with ``direct_code``: a direct line's
        error trapped, see :meth:`_merged_direct_line`)."""
        program = dict(self.programs.get(0, {}))
        scalars, arrays = chain.common or (None, None)  # (None: ALL, every variable)
        if chain.delete is not None:
            doomed = set(deleted_lines(program, *chain.delete))
            program = {n: t for n, t in program.items() if n not in doomed}
        stopped = chain.stopped
        room = self.dialect.free_memory
        if room is not None and chain.run:  # CHAIN keeps its variables above the lines it loads
            room = self._room_beside(scalars, arrays, chain.merge and chain.everything)
        if chain.merge or room != self.dialect.free_memory:
            # a line that does not fit: Out of memory, not trapped (the line insertion clears
            # ONELIN first: GWMAIN.ASM LEVFRE)
            program, full = memory_model.fitting_lines(program if chain.merge else {}, chain.lines, room)
            stopped = full or stopped
        else:
            program, full = dict(chain.lines), None
        self.programs[0] = program
        self._invalidate(0)
        self._extra_entries.clear()
        if stopped is not None:
            if chain.merge and full is None and not stopped.lines and isinstance(stopped, DirectStatementInFile):
                return self._merged_direct_line(stopped)
            if not chain.merge or full is not None:
                self.on_error = None  # the old program's handler went with it
            raise stopped
        if not chain.run:
            return None
        kept_scalars = {k: v for k, v in self.scalars.items() if scalars is None or k in scalars}
        kept_arrays = {k: (self.arrays[k], self.array_dims.get(k), k in self.explicit_arrays)
                       for k in self.arrays if arrays is None or k in arrays}
        functions = dict(self.fns) if chain.merge and chain.everything else {}
        base, option_seen = self.subscript_base, self.option_seen
        block = 0
        if chain.line:  # line 0: the start (FIVEO.ASM CHNRET)
            if chain.line not in program:
                raise error_for(UNDEFINED_LINE).at(self.line)
            block = self._line_block(chain.line)
        self._compiled(0)
        # the variables passed on that the first program made (it recorded COMMON's or, with
        # ALL, every making: compiler._watched_names), or that hold a value other than 0 or ""
        # (in the order they were made: the new program's variable table starts with them)
        made = [name for name in self.made if name in kept_scalars]
        made += [name for name, value in kept_scalars.items() if value and name not in self.made]
        self.clear()
        self.stack.clear()
        self.on_error = None
        self.in_handler = False
        self.pending_error = None
        self.scalars.update(kept_scalars)
        self.made.update(made)  # those passed on that exist stay made (a SWAP may ask)
        self.mark_made(made)
        for name, (values, dims, explicit) in kept_arrays.items():
            self.arrays[name] = values
            if dims is not None:
                self.array_dims[name] = dims
                self._reserve(name, dims)
            if explicit:
                self.explicit_arrays.add(name)
        self.fns.update(functions)
        self.set_subscript_base(base)
        self.option_seen = option_seen  # (FIVEO.ASM CHAIN keeps OPTFLG and OPTVAL: TOPTFG, TOPTVL)
        if self.dialect.data_segment is not None:
            self._strings_out_of_the_text(kept_scalars, program)
        return ChainStart(block)

    def _strings_out_of_the_text(self, kept: dict, program: dict) -> None:
        """The strings passed on that lay in the old program's text (a literal, a DATA item)
        are copied into the string space, below the others (FIVEO.ASM CHAIN keeps the
        variables, not the text they pointed into: the copies come after its collection).
        Where the new program reads the data segment (VARPTR), the strings' places are kept
        from here on (machine/data_segment.py), so that the copies lie below the others."""
        space = self.string_space
        copies = [name for name, value in kept.items()
                  if type(value) is str and len(value) > 1 and id(value) in space.text]
        if not copies:
            return
        if space.places[0] is None and any("VARPTR" in text.upper() for text in program.values()):
            self.data_layout()
        for name in copies:
            value = self.scalars[name]
            copy = value[:1] + value[1:]
            space.take_room(copy)  # (made before the variable holds it: a collection keeps the old)
            self.scalars[name] = copy

    def _room_beside(self, scalars: set | None, arrays: set | None, functions: bool) -> int:
        """The bytes the program text may take beside what a CHAIN keeps: the simple
        variables ``scalars`` and arrays ``arrays`` (None: every one, ALL), the DEF FN
        functions where ``functions`` (MERGE with ALL), and their strings, the garbage
        collected (FIVEO.ASM CHAIN moves what it keeps to the top of memory before it loads
        the new program's lines, whose insertion BIMISC.ASM REASON then refuses past it; a
        real GW-BASIC 3.23 stopped a CHAIN MERGE, ALL with Out of memory so: PC-BASIC's
        FULLCHN test)."""
        kept_scalars = {k: v for k, v in self.scalars.items() if scalars is None or k in scalars}
        kept_arrays = {k: v for k, v in self.arrays.items() if arrays is None or k in arrays}
        dims = {k: d for k, d in self.held_dims().items() if k in kept_arrays}
        free, _ = memory_model.free_and_strings(self.dialect.free_memory, {}, kept_scalars, kept_arrays, dims,
                                                self.fns if functions else {}, self.strings_outside(), self.made)
        return free

    def _merged_direct_line(self, stopped: BasicError) -> ChainStart:
        """MERGE of a file whose first line has no number: GW-BASIC's MERGE reads the file
        as typed lines (DSKCOM.ASM OKGETM goes to MAIN, which sets CURLIN to 65535), and
        no line has yet been entered to clear the error trap (GWMAIN.ASM FINI's RUNC,
        LEVFRE), so the program's ON ERROR GOTO traps ``Direct statement in file`` with
        ERL 65535.  Returns the handler's block to run, with the file's line compiled as a
        direct statement, which RESUME runs and RESUME NEXT skips (ERRTXT is the line GW
        crunched); raises ``stopped`` where nothing traps it.  After
        RESUME [NEXT] the merge is over: the handler's first output closes file #0 (GIO86.ASM
        FINPRT, NLONLY cleared by ERROR)."""
        code = self._compile_direct(stopped.statement)
        handler = self._trap(stopped, 0, 0, code)
        if handler is None:
            raise stopped
        return ChainStart(handler, code)

    def common_names(self) -> tuple[set[str], set[str]]:
        """The scalars and the arrays (typed names, as the machine keeps them) of the COMMON
        statements of program area 0 that begin a statement, wherever they are, in line
        order (FIVEO.ASM CHAIN scans each statement's first token; an array is a name with
        parentheses after it).  A list that does not read is the CHAIN's error, placed in
        the COMMON's line (the scan keeps each line's number in CURLIN for errors)."""
        from yaseer.basic.source.common_lists import chained_lists, common_items

        letters, typed = self.def_types, self.dialect.typed_numbers  # the DEF types as CHAIN finds them
        scalars, arrays = set(), set()
        for number, text in sorted(self.programs.get(0, {}).items()):
            for listed in chained_lists(text, self.dialect):
                items, error = common_items(listed, self.dialect)
                if error is not None:
                    raise error.at(number)
                for name, array in items:
                    (arrays if array else scalars).add(_typed(name, letters, typed))
        return scalars, arrays


def _typed(name: str, letters: dict, typed: bool) -> str:
    """A name as the machine keys it: with its type character (the DEF letter's, or ``!``)."""
    if not typed or name[-1] in "$%!#":
        return name
    return name + letters.get(name[0], "!")
