"""The BASIC machine's input and output: PRINT and LPRINT (comma zones, TAB, SPC,
csv rows, the line hooks), PRINT USING, WRITE, INPUT and LINE INPUT, INPUT$, the
screen's settings (CLS, WIDTH, TRON's mark) and the file statements' I/O
(PRINT #n, INPUT #n, FILES; the files themselves: files.py).  The
:class:`InputOutput` mixin of :class:`yaseer.basic.machine.machine.Machine`."""

from __future__ import annotations

import sys

from yaseer.basic.arithmetic import formatting, mbf_digits, values

from yaseer.basic.machine import gwfunctions, runtime
from yaseer.basic.machine.random_files import FieldedVariables
from yaseer.basic.errors import (
    BasicError, BAD_FILE_NAME, FILE_NOT_FOUND, ILLEGAL_FUNCTION_CALL, INPUT_PAST_END, SYNTAX_ERROR,
)
from yaseer.basic.machine.console import end_of_keys
from yaseer.basic.machine.signals import BreakPoint
from yaseer.basic.machine.screen import DEVICE_WIDTHS, SCREEN_WIDTHS, OutputStream
from yaseer.patterns import Pattern


class Tab:
    __slots__ = ("column",)

    def __init__(self, column):
        self.column = column


class Spc:
    __slots__ = ("count",)

    def __init__(self, count):
        self.count = count


COMMA = object()
NUMBER_THEN_COMMA = object()  # marks a PRINT number a comma follows (GW's blank rule)


class InputOutput:
    """PRINT, INPUT and the file statements' I/O on the machine's streams (``screen``,
    ``printer``, ``input_stream``, ``files``).  A mixin of ``Machine``, on its state."""

    def trace_line(self, number: int, area="P0") -> None:
        """TRON's mark as line ``number`` of program area ``area`` (its name) starts: the
        dialect's ``trace_mark`` on the screen (GW: ``[n]``, like PRINT without a newline).

        Where the trace halts (casio, TRON.md: ``P0-10`` and execution suspended until EXE),
        the mark takes a row of its own; the run waits for Enter only when the keys come
        from a person at a terminal.  From ``--input`` or a pipe no key is taken: a key
        script written for the program's INPUTs then answers the same ones with TRON on,
        and the transcript lists every line run (docs/compatibility.md, TRON)."""
        rules = self.dialect.screen
        screen = self.screen
        mark = rules.trace_mark.format(area=area, line=number)
        if not rules.trace_halts:
            screen.write(mark)
            return
        if screen.column:
            screen.new_row()
        screen.write(mark)
        if self.input_stream is not None or not sys.stdin.isatty():
            screen.new_row()
            return
        self._reading_input = True  # a Ctrl-C (BRK) while it waits breaks at once
        try:
            self.show_screen()
            screen.flush()
            sys.stdin.readline()  # EXE: the terminal's echo of Enter ends the mark's row
        finally:
            self._reading_input = False
        screen.column = 0
        if self.display is not None and self.display.drawn:
            self.display.new_line()

    def set_width(self, columns, printer: bool = False) -> None:
        """WIDTH n: the screen's width, 40 or 80 columns as GW-BASIC's text screen has
        (any other n is Illegal function call); PRINT wraps there from now on.
        WIDTH LPRINT n: the printer's, 0..255 (0 acts as 1, 255 never wraps, as
        PC-BASIC 2.0.8 has it), on a ``--printer`` file or, where the dialect's printer has a
        width (GW's LPT1:), on the output beside the screen; nothing changes otherwise."""
        n = runtime.cint(columns)
        if printer:
            if not 0 <= n <= 255:
                raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
            if self.own_printer or (self.printer is not self.screen and self.dialect.printer_width):
                self.printer.width = None if n == 255 else max(n, 1)
            return
        if n not in SCREEN_WIDTHS:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        if self.display is not None and n != self.display.columns:  # a new width clears the screen
            self.screen.catch_up()
            self.display.resize(n)
            self.screen.column = 0
        self.screen.width = n

    @staticmethod
    def set_file_width(file, columns) -> None:
        """WIDTH #n, w: the width PRINT # wraps ``file``'s lines at (the open file n: the
        compiled code finds it before it reads w, as GIO86.ASM FILWID does), 0..255 (more
        than 255 Illegal function call; 255 never wraps, the disk's own width; GIO86.ASM
        WIDTHS, FILWID).  0 acts as 1: GIO86.ASM GETWDT refuses it, but a real GW-BASIC 3.23
        took it (the recorded WIDTH test: each PRINT # item on a line of its own after it,
        as PC-BASIC 2.0.8 prints).  (PC-BASIC 2.0.8 refuses 255.)"""
        n = runtime.cint(columns)
        if not 0 <= n <= 255:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        file.set_width(None if n == 255 else max(n, 1))

    def set_device_width(self, device: str, columns) -> None:
        """WIDTH "dev", n: ``LPT1:`` is WIDTH LPRINT n (GW-BASIC's source, GIOLPT.ASM
        ``LPTSWD``, sets the width LPRINT wraps at), ``SCRN:`` WIDTH n; the other devices
        GW-BASIC has take 0..255 and change nothing yaseer shows (``KYBD:`` refuses it,
        Illegal function call); any other text is ``Bad file name``."""
        action = DEVICE_WIDTHS.get(device.upper())
        if action is None:
            raise BasicError("Bad file name", BAD_FILE_NAME)
        if action == "screen":
            self.set_width(columns)
        elif action == "printer":
            self.set_width(columns, printer=True)
        elif action == "refused" or not 0 <= runtime.cint(columns) <= 255:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)

    def print_items(self, device: int, items: tuple, newline: bool, end: bool = True) -> None:
        """PRINT / LPRINT: values, comma zones, TAB and SPC; ``newline`` ends the line.

        A statement may print in several calls; ``end`` marks its last.  In csv
        output a row is a printed line: the values of every PRINT up to the one
        that ends the line (so rows of one kind have one length).
        """
        stream = self.streams[device]
        if self.line_hooks:
            self._note_values(device, [_printed_value(v) for v in items if not isinstance(v, (Tab, Spc))
                                       and v is not COMMA and v is not NUMBER_THEN_COMMA], newline)
        if self.csv:
            for v in items:
                if type(v) is not float and type(v) is not str:
                    v = _as_number(v)
                if type(v) is float:
                    if v - v:
                        runtime.overflow()
                    stream.row.append(repr(v))
                elif type(v) is str:
                    stream.row.append(v)
            if end and newline:
                self._csv_row(stream)
            return
        self._lay_out(stream, items, newline)
        if device == 0 and self.print_echo and self.own_printer:
            self._lay_out(self.printer, items, newline)  # MODE 7: PRINT on the printer too

    def _lay_out(self, stream: OutputStream, items: tuple, newline: bool) -> None:
        """PRINT's items as text on ``stream`` (the screen, the printer or a file)."""
        comma_follows = False
        for item in items:
            kind = type(item)
            if kind is not float and kind is not str and isinstance(item, (int, float)):
                # casio: e.g. a numpy float a Python area stored; gw: an integer or a double
                item, kind = self._printed_number(item), float
            if kind is float:
                if item - item:
                    item = self.arith.overflowed(item, "#" if isinstance(item, values.Double) else "!")
                text = self._number_text(item)
                if comma_follows:
                    text = self._blank_before_comma(stream, text)
                    comma_follows = False
                stream.item(text)
            elif kind is str:
                stream.item(item)
            elif item is COMMA:
                stream.comma(self.dialect.zone)
            elif item is NUMBER_THEN_COMMA:
                comma_follows = self.dialect.comma_trims_number
            elif kind is Tab:
                words = self.dialect.words
                if words is not None and words.tab_from_zero:  # TAB.md: truncated, counted from 0
                    column = int(item.column)
                    if not 0 <= column <= 256:
                        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
                    stream.tab(column + 1)  # (the stream counts columns from 1)
                    continue
                column = runtime.cint(item.column)
                if column > 255 and stream.width is None:
                    raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
                stream.tab(column)
            elif kind is Spc:
                count = runtime.cint(item.count)
                if (count < 0 or count > 255) and stream.width is None:
                    raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
                stream.spc(count)
        if newline:
            stream.end_line()

    def _blank_before_comma(self, stream: OutputStream, text: str) -> str:
        """A number a comma follows loses its trailing blank when it would end just
        before a zone (so the comma moves one column, not a whole zone): GW-BASIC's
        PRINT code, GIO86.ASM ``MODCOM``; PC-BASIC 2.0.8 keeps the blank."""
        zone, width = self.dialect.zone, stream.width
        end = stream.column + len(text) - 1  # the column after the number without its blank
        if width is not None and width >= zone and end >= zone * (width // zone - 1):
            return text
        return text[:-1] if (end + 1) % zone == 0 else text

    def _using_values(self, items) -> list:
        """PRINT USING's values as floats and strings (a typed single as its 7 digits)."""
        singles = self.dialect.typed_numbers
        return [(_single_decimal(v) if singles and v == v and v - v == 0 else v) if type(v) is float
                else v if type(v) is str else _double_decimal(v) if isinstance(v, values.Double) and v - v == 0
                else _as_number(v) for v in items]

    def print_using(self, device: int, fmt: str, values: tuple, newline: bool) -> None:
        """PRINT USING fmt; values (the format rules live in ``formatting.using``)."""
        stream = self.streams[device]
        values = self._using_values(values)
        for v in values:
            if type(v) is float and v - v:
                runtime.overflow()
        if self.line_hooks:
            self._note_values(device, values, newline)
        if self.csv:
            stream.row.extend(repr(v) if type(v) is float else v for v in values)
            if newline:
                self._csv_row(stream)
            return
        most = self.dialect.using_digits
        text = _formatted(fmt, values, stream, most)
        if stream.width is None or stream.column + len(text) <= stream.width:
            stream.write(text)
        else:  # a field that does not fit the row starts the next one, as a PRINT item does
            for text, field in _formatted(fmt, values, stream, most, pieces=True):
                if field:
                    stream.item(text)
                else:
                    stream.write(text)
        if newline:
            stream.end_line()

    def using_line(self, device: int, fmt: str) -> UsingLine:
        """PRINT USING fmt; v1; v2 ... with each value evaluated when its field is reached
        (``Dialect.using_each_value``): the text before the first field is printed now."""
        return UsingLine(self, self.streams[device], fmt, device)

    def using_line_to(self, stream, fmt: str) -> UsingLine:
        """PRINT #n, USING, value by value (see :meth:`using_line`)."""
        return UsingLine(self, stream, fmt)

    def _note_values(self, device: int, values: list, newline) -> None:
        """Collect a printed line's values; at its end hand them to the line hooks."""
        line = self._line_values[device]
        line.extend(values)
        if newline:
            printed = line.copy()
            line.clear()
            for hook in self.line_hooks:
                hook(device, printed)

    def _csv_row(self, stream: OutputStream) -> None:
        """Write the csv row of the line ``stream`` was printing (its values so far)."""
        import csv  # here: only --format csv and INPUT need it (start-up)

        writer = csv.writer(stream.stream, lineterminator="\n")
        writer.writerow(stream.row)
        stream.row = []
        stream.column = 0

    def input_values(self, prompt, question_mark: bool, kinds: str, again: tuple | None = None,
                     limit: int | None = None, keeps_row: bool = False) -> list:
        """INPUT: prompt, read one line, split at commas; wrong values ask again.

        ``again``: (the block of area 0 this INPUT starts, its line); see :meth:`_read_line`.
        ``limit``: the most characters the answer takes (the library's ``INPUT @n;``: the
        keys past the field are not taken, as a field of n columns would refuse them).
        ``keeps_row``: ``INPUT;`` (see :meth:`_read_line`).
        """
        while True:
            line = self._read_line(_question(prompt, question_mark), again, keeps_row)
            if limit is not None:
                line = line[:limit]
            if not line and len(kinds) == 1 and self.dialect.empty_input_keeps:
                return [None if kind == "n" else "" for kind in kinds]
            values = parse_input(line, kinds, self.dialect.number_reading, self.dialect.string_length)
            if values is None and kinds == "n" and self.dialect.words is not None and self.dialect.words.input_expressions:
                values = self.input_expression(line)  # casio: a numeric expression (casio_words.py)
            if values is not None:
                return values
            self.screen.write("?Redo from start\n")

    def input_names_cut(self, prompt, question_mark: bool, keeps_row: bool) -> None:
        """INPUT whose names are missing or end in a comma (``Dialect.input_answer_first``):
        GW-BASIC shows the question and reads the answer before it reads the names
        (GWMAIN.ASM INPUT: SINLIN, then PTRGTN finds no name), so both come before the
        Syntax error; the answer is not looked at.  ``keeps_row``: ``INPUT;``."""
        self._read_line(_question(prompt, question_mark), keeps_row=keeps_row)
        raise BasicError("Syntax error", SYNTAX_ERROR)

    def line_input(self, prompt, again: tuple | None = None, keeps_row: bool = False) -> str:
        """LINE INPUT ["prompt";] a$: the whole line, commas and quotes included (its
        trailing blanks dropped, as GW-BASIC's screen editor drops them); ``again``
        and ``keeps_row`` as for INPUT (see :meth:`_read_line`); a line over the dialect's
        string length is String too long."""
        line = self._read_line(prompt or "", again, keeps_row)
        return runtime.limited(line.rstrip(" "), self.dialect.string_length)

    def _read_line(self, prompt: str, again: tuple | None = None, keeps_row: bool = False) -> str:
        """Show ``prompt``, read one line of input (without its line end); the end of
        the input is ``Input past end``.  ``keeps_row`` (GW's ``INPUT;``): an answer from
        ``--input`` is not followed by a new row, the cursor stays after it (at a terminal
        its echo of Enter has already moved the cursor: the column starts again at 0).

        ``again``: (a block of area 0 that starts with this statement, its line); with
        ``resumable_breaks`` a Ctrl-C while the line is awaited (or one that came just
        before) is a break that CONT resumes by running that block: asking again, as
        GW-BASIC does.  Otherwise a Ctrl-C here breaks at once.
        """
        stream = self.input_stream if self.input_stream is not None else sys.stdin
        self._reading_input = True  # a Ctrl-C now breaks at once
        try:
            if self._break_armed is not None and again is not None:
                raise KeyboardInterrupt  # a Ctrl-C came just before: the break lands here
            self.screen.write(prompt)
            under = self._text_under_cursor()
            self.show_screen()
            self.screen.flush()
            line = stream.readline()
        except KeyboardInterrupt:
            if again is None or not self.resumable_breaks:
                raise
            raise BreakPoint(0, again[0], again[1], (), self.area_depth) from None
        finally:
            self._reading_input = False
        if not line:
            raise end_of_keys()
        line = self.dialect.charset.codes(line)  # keys typed as symbols: the machine's codes
        self.last_input_key = 13  # EXE (PEEK: console.LAST_INPUT_KEY)
        self._looked = False  # keys were taken: INKEY$ finds the next one only when it looks again
        typed = line.rstrip("\r\n")
        display = self.display if self.display is not None and self.display.drawn else None
        if self.input_stream is not None:
            self.screen.write(typed)
        elif display is not None:  # the keys typed show on the LCD too
            display.write(typed)
        if under and display is not None:
            display.to_end_of_logical_line()  # EXE took the logical line: the next row is after it
        if self.input_stream is not None:
            if not keeps_row:
                self.screen.write("\n")
        else:
            self.screen.column = 0
            if display is not None:
                display.write("\n")
        line = typed
        return (line + under[len(line):]).rstrip(" ") if under else line

    def _text_under_cursor(self) -> str:
        """What the screen holds from the cursor to the end of its logical line, where the
        dialect's INPUT takes it with the keys typed over it (``input_reads_screen``; only on
        a drawn display: streamed text has nothing placed after the cursor)."""
        display = self.display
        if display is None or not display.drawn or not display.rules.input_reads_screen:
            return ""
        return display.logical_line_from(display.column(), display.row()).rstrip(" ")

    def end_line(self) -> None:
        """Finish a partly printed line (before an error message, as MS-BASIC does; csv: its row)."""
        if self.csv:
            for stream in dict.fromkeys(self.streams):
                if stream.row:
                    self._csv_row(stream)
        elif self.screen.column:
            self.screen.new_row()

    def flush(self) -> None:
        for stream in self.streams:
            try:
                stream.flush()
            except (OSError, ValueError):
                pass

    # ------------------------------------------------------------ files (files.py)
    def print_to(self, stream, items: tuple, newline: bool, end: bool = True) -> None:
        """PRINT #n: the items laid out on the file's stream as on the screen (no csv, no hooks)."""
        try:
            self._lay_out(stream, items, newline)
        finally:
            self._fields_follow(stream)

    def print_using_to(self, stream, fmt: str, values: tuple, newline: bool) -> None:
        """PRINT #n, USING."""
        try:
            stream.write(_formatted(fmt, self._using_values(values), stream, self.dialect.using_digits))
            if newline:
                stream.end_line()
        finally:
            self._fields_follow(stream)

    def write_to(self, stream, pieces: tuple, cut: str | None = None) -> None:
        """WRITE #n (``cut``: see write_values)."""
        try:
            if cut is not None:
                stream.write(",".join(pieces) + cut)
                return
            stream.write(",".join(pieces))
            stream.before_write_end()
            stream.end_line()
        finally:
            self._fields_follow(stream)

    def _fields_follow(self, stream) -> None:
        """After PRINT # or WRITE # into a random file's record buffer (``stream.file``): its
        fielded variables show what is there now (GW-BASIC's point into the buffer)."""
        file = getattr(stream, "file", None)
        if file is not None:
            self._fields_poked(file)

    def _fields_poked(self, file) -> None:
        """After something wrote into random file ``file``'s buffer (PRINT #, a POKE): its
        fielded variables show what is there now."""
        variables = self.fielded()
        variables.update(file.refreshed(variables))

    def file_number(self, file) -> float:
        """INPUT #n into a numeric variable: one field of ``file``, read as GW-BASIC reads numbers."""
        return gwfunctions.val(file.read_field(True, self.dialect.string_length), self.dialect.number_reading)

    def input_chars(self, count, n=None) -> str:
        """INPUT$(count[, #n]): ``count`` characters of the file (or of the input)."""
        k = runtime.cint(count)
        if not 1 <= k <= 255:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        if n is not None:
            return self.files.opened(n).read_chars(k)
        return self.input_keys(k)

    def fielded(self) -> FieldedVariables:
        """The variables a FIELD may name, scalars and array elements, by key."""
        return FieldedVariables(self.scalars, self.arrays)

    def field_element(self, key):
        """The value of a FIELD or LSET variable ``key``; an element's array is made with its
        default size if there is none (GW's PTRGET), a subscript beyond it ``Subscript out
        of range`` (an IndexError)."""
        if type(key) is str:
            return self.scalars.get(key)
        name, subscripts = key
        values = self.array_nd(name, len(subscripts))
        for k in subscripts:
            values = values[k]
        return values

    def get_record(self, file, record=None) -> None:
        """GET #n[, record] of random ``file`` (found first: files.FileTable.opened): read the
        record; its fielded variables take their slices."""
        variables = self.fielded()
        variables.update(file.get(variables, record))

    def set_field(self, key, value: str, current, right: bool) -> None:
        """LSET / RSET (files.justify): the variable, and the others fielded over its bytes;
        ``current``: a scalar's value (an element's is read here)."""
        if type(key) is not str:
            current = self.field_element(key)
        variables = self.fielded()
        changed = self.files.justify(key, value, current, right, variables)
        space = self.string_space
        if self.dialect.free_memory is not None and len(changed) == 1:
            # LSET writes into the variable's own string, never into a literal (the result is
            # a string of its own even where Python gave the literal back); a variable pointing
            # at a literal of the program text gets a copy in the string space first
            # (DSKCOM.ASM LSET: GETSPA when the string lies below VARTAB)
            new = changed[key]
            if len(new) > 1 and id(new) in space.text:
                changed[key] = new[:1] + new[1:]
            if len(current) > 1 and id(current) in space.text:
                space.take_room(changed[key])
            elif space.places[0] is not None and id(current) in space.places[0]:  # (written in place)
                space.places[0][id(changed[key])] = (changed[key], space.places[0][id(current)][1])
        variables.update(changed)

    def swap_fields(self, first, second, now_first: str, now_second: str) -> None:
        """SWAP of string variables ``first`` and ``second`` (keys as FIELD's), which now hold
        ``now_first`` (what ``second`` held) and ``now_second``: the fields go with the
        values (files.FileTable.swap_fields)."""
        self.files.swap_fields(first, second, now_first, now_second)

    def field_variable(self, file, offset: int, width, key) -> int:
        """One ``width AS variable`` of FIELD #n on random ``file`` (random_files.RandomFile.field):
        the variable holds its slice of the buffer at once; the next one's offset."""
        offset, value = file.field(offset, width, key, self.field_element)
        if key is not None:
            self.fielded().update({key: value})
        return offset

    def list_files(self, pattern) -> None:
        """FILES [pattern]: GW-BASIC's listing: the directory (``C:\\``, the sandbox as
        a drive's root, and CHDIR's folders), the matching entries in as many columns of 18 as the width
        has 20s, the disk's bytes free, an empty line; nothing matching is ``File not
        found`` after the directory line (as PC-BASIC 2.0.8 prints it)."""
        sandbox = self.files.sandbox
        entries = sandbox.directory(pattern)
        self.print_items(0, ("C:" + sandbox.current_path(),), True)
        if not entries:
            raise BasicError("File not found", FILE_NOT_FOUND)
        columns = max(1, (self.screen.width or 80) // 20)
        for k in range(0, len(entries), columns):
            self.print_items(0, (" ".join(entries[k:k + columns]),), True)
        self.print_items(0, (f" {sandbox.free_bytes()} Bytes free",), True)
        self.print_items(0, (), True)

    def write_values(self, device: int, pieces: tuple, cut: str | None = None) -> None:
        """WRITE: the items (already as text: strings quoted, numbers without blanks)
        separated by commas, then the line end; ``cut``: the items of a WRITE that fails
        part way, followed by ``cut`` (the comma after the last, or nothing) and no line end
        (FIVEO.ASM WRITE prints each item, reads its separator, prints its comma, then
        reads the next)."""
        if cut is not None:
            self.print_items(device, (",".join(pieces) + cut,), False)
            return
        self.print_items(device, (",".join(pieces),), True)


class UsingLine:
    """One PRINT [#n,] USING statement printed field by field, as GW-BASIC's BIPRTU.ASM
    prints it: the compiled statement evaluates a value, hands it to :meth:`put`, which
    prints it in its field and the literal text up to the next field, then evaluates the
    next value.  So a value's error or message comes after the fields before it, and
    ``POS(0)`` sees them.  What is printed stays when an error stops the statement (an
    ON ERROR handler goes on from that column).  ``device``: the screen's or printer's
    number (csv rows and line hooks, as ``print_using``); None for a file's stream."""

    __slots__ = ("machine", "stream", "device", "cursor")

    def __init__(self, machine, stream, fmt: str, device: int | None = None):
        self.machine, self.stream, self.device, self.cursor = machine, stream, device, None
        if device is not None and machine.csv:  # a csv row takes the values, not the format
            return
        try:
            self.cursor = formatting.UsingCursor(fmt, machine.dialect.using_digits)
        except BasicError as error:  # a format without a field: its text, then the error
            stream.write(error.printed)
            raise
        text = self.cursor.literals(True)
        if text:
            stream.write(text)
            self._fields_follow()

    def _fields_follow(self) -> None:
        """A file's stream that is a random file's record buffer: its fielded variables
        show what was written (after each write, so also when a later value stops it)."""
        if self.device is None:
            self.machine._fields_follow(self.stream)

    def put(self, value, more: bool) -> None:
        """``value`` in its field, then the literal text up to the next field (``more``:
        another value follows, so the format is read again from its start at its end)."""
        machine, stream, device = self.machine, self.stream, self.device
        value = machine._using_values((value,))[0]
        if type(value) is float and value - value:
            runtime.overflow()
        if device is not None and machine.line_hooks:
            machine._note_values(device, [value], False)
        if self.cursor is None:
            stream.row.append(repr(value) if type(value) is float else value)
            return
        text = self.cursor.field(value)
        after = self.cursor.literals(more)
        if device is None or stream.width is None or stream.column + len(text) <= stream.width:
            stream.write(text + after)  # (one write: this is a loop's path)
        else:  # a field that does not fit the row starts the next one, as a PRINT item does
            stream.item(text)
            stream.write(after)
        self._fields_follow()

    def end(self, newline: bool) -> None:
        """The statement's end: the line ends unless a ``;`` or ``,`` ended the list."""
        machine, stream, device = self.machine, self.stream, self.device
        if device is not None and machine.line_hooks:
            machine._note_values(device, [], newline)
        if self.cursor is None:
            if newline:
                machine._csv_row(stream)
        elif newline:
            stream.end_line()
            self._fields_follow()


def _printed_value(value):
    """A printed item as a line hook sees it: str stays, any number becomes a float."""
    return value if type(value) is str else float(value)


def _same(value):
    return value


def _formatted(fmt: str, values: list, stream, most_digits: int | None, pieces: bool = False):
    """``formatting.using`` (``most_digits``: the dialect's ``using_digits``); on an error the
    text before it is written to ``stream`` first."""
    try:
        return formatting.using(fmt, values, pieces, most_digits)
    except BasicError as error:
        stream.write(getattr(error, "printed", ""))
        raise


# MATH2.ASM $PUF prints a number from 10**16 up in free format (formatting.Single's free): a
# double compared with $DP16 (10**16, exact), a single with its top four bytes (10**16
# cut to 24 bits, 9999999198822400)
_PUF_SINGLE_LIMIT = 9999999198822400.0
_PUF_DOUBLE_LIMIT = values.double_parts(1e16)[1:]


def _single_decimal(x: float) -> float:
    """A nonzero single as the decimal of its 7 digits (what PRINT shows), carrying
    ``$FOTNV``'s bracket of its binary value, from which a field finds its digits
    (formatting.Single); from ``$PUF``'s limit up marked with its free-format text."""
    if not x:
        return x
    y, power = mbf_digits.bracket(x)
    n = mbf_digits.rounded_whole(y)
    shown = formatting.Single(f"-{n}e{power}" if x < 0 else f"{n}e{power}")
    shown.bracket = y, power
    shown.free = values.unsigned_text(x, values.SINGLE_DIGITS, "E") \
        if not -_PUF_SINGLE_LIMIT < x < _PUF_SINGLE_LIMIT else None
    return shown


def _double_decimal(x) -> float:
    """A gw double with its exact 56-bit value, whose digits PRINT USING finds as
    MATH1.ASM's PUFOUT does (formatting.Shown): ``2#/3`` with sixteen places is
    .6666666666666667 (the nearest IEEE double's digits gave ...666), as PC-BASIC 2.0.8
    prints; from 10**16 up with its free-format text (``$PUF``)."""
    shown = formatting.Shown(x)
    shown.parts = parts = values.double_parts(x)
    if parts[1:] >= _PUF_DOUBLE_LIMIT:
        shown.free = values.unsigned_text(x, values.DOUBLE_DIGITS, "D")
    return shown


def _as_number(value):
    """A number some Python area stored (int, numpy float) as a Python float; else as is."""
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return float(value)
    return value


def parse_input(text: str, kinds: str, reading, longest: int):
    """The values of one INPUT line for targets of ``kinds`` ("n"/"s"), or None to redo
    (``reading``: see gwfunctions.read_number); a string over ``longest`` characters is
    String too long."""
    import csv

    reader = csv.reader([text], skipinitialspace=True)
    fields = next(reader, None) or [""]  # an empty answer is one empty value: 0 or ""
    if len(fields) != len(kinds):
        return None
    values = []
    for field_text, kind in zip(fields, kinds):
        if kind == "s":
            values.append(runtime.limited(field_text, longest))
            continue
        try:
            value = gwfunctions.number_field(field_text, reading)
        except BasicError:  # beyond the double range
            return None
        if value is None:
            if not _NUMBER_WITHOUT_DIGITS.fullmatch("".join(field_text.split()).upper()):
                return None
            value = 0.0
        values.append(value)
    return values


# An answer the number reader ($FIN, MATH1.ASM) reads whole although it has no digit:
# a sign, a point, an exponent letter (D or E, with its sign and digits) make a number
# of value 0 (``D``, ``-D``, ``.``, ``E+``, ``D5``)
_NUMBER_WITHOUT_DIGITS = Pattern(r"[+-]?\.?(?:[DE][+-]?\d*)?")


def _question(prompt: str | None, question_mark: bool) -> str:
    """What INPUT shows before the answer: its prompt, then ``? `` unless a comma followed it."""
    return (prompt or "") + ("? " if question_mark or prompt is None else "")
