"""GW-BASIC's random-access files: records of a fixed length read and written through a
buffer that FIELD divides among string variables.

``OPEN "R", #n, name, length`` (or ``OPEN name [FOR RANDOM] AS #n LEN = length``) opens
or creates the file with records of ``length`` bytes (default 128, 1..32767); ``FIELD``
binds variables to slices of the record buffer (more bytes than a record is ``FIELD
overflow``, DSKCOM.ASM ``FIELD``); ``LSET``/``RSET`` store a string into a variable,
padded with blanks or cut to its length (the field's for a fielded variable, which then
writes the buffer: DSKCOM.ASM ``LSET``); ``GET #n[, r]`` reads record ``r`` (or the next)
into the buffer, and every fielded variable takes its slice; ``PUT #n[, r]`` writes the
buffer as record ``r`` (or the next).  A record beyond the end reads as zero bytes and
``EOF`` is then true; writing beyond the end extends the file with zero bytes.  ``LOC``
is the last record read or written, ``LOF`` the file's length in bytes.  GET and PUT
without a number take the record after the last one read or written (GIODSK.ASM
``DSKRND``: the logical record ``FD_LOG`` + 1), also after a GET beyond the end, where
PC-BASIC 2.0.8 writes at the end of the file instead.

PRINT #, WRITE #, INPUT #, LINE INPUT # and INPUT$ work on the record buffer at its
position (GIODSK.ASM ``DSKSOT``/``DSKSIN``: ``FD_OPS``), which GET and PUT set back to the
start; a byte beyond the record is ``FIELD overflow`` (``FOVCHK``).  The FIELD variables
then show what PRINT # wrote (the machine refreshes them after each such statement).

Characters are bytes (latin-1), as in the sequential files.  A fielded variable is
named by its key: a scalar's in the machine's scalars (``A$``), an array element's the
array's name and its subscripts (``("A$", (1,))``: DSKCOM.ASM ``FIELD`` finds each variable
with ``PTRGET``, which takes an element as well, making the array with its default size
if there is none); :class:`FieldedVariables` reads and stores both kinds.  ERASE or a new
DIM of the array detaches its elements (:meth:`RandomFile.forget_array`: the descriptors
that pointed into the buffer are gone with the array).  GW-BASIC's field variables point
into the buffer itself, so a ``LET`` to one detaches it from the buffer: GET no longer
changes it and LSET pads to its own length.  Here a fielded variable stays bound while
it holds the very string object the file last gave it (FIELD, GET, LSET give them);
any other value was stored by the program, which detaches it.  SWAP moves the string to
the other name, and the binding with it (:meth:`RandomFile.swap`), as GW-BASIC's SWAP
moves the descriptor.
"""

from __future__ import annotations

import math

from yaseer.basic.errors import (
    BAD_RECORD_NUMBER, FIELD_OVERFLOW, ILLEGAL_FUNCTION_CALL, INPUT_PAST_END, OVERFLOW, error_for,
)
from yaseer.basic.machine import file_locks, item_reading
from yaseer.basic.machine.screen import FileStream

END_OF_FILE = "\x1a"  # Ctrl-Z: ends an input item (GIODSK.ASM DSKSIN)
DEFAULT_LENGTH = 128  # bytes per record without LEN (GW-BASIC's /S default)
MAX_LENGTH = 32767
MAX_RECORD = 32767  # the largest record number (a signed 16-bit number above 0)


def record_length(length) -> int:
    """A record length given to OPEN (None: the default); outside 1..32767 ``Illegal function call``."""
    if length is None:
        return DEFAULT_LENGTH
    from yaseer.basic.machine.runtime import cint

    n = cint(length)
    if not 1 <= n <= MAX_LENGTH:
        raise error_for(ILLEGAL_FUNCTION_CALL)
    return n


class RandomFile:
    """One file open for random access: its handle, record buffer and fields; ``sharing``
    its OPEN clauses (file_locks.Sharing; the file table sets it)."""

    mode = "R"
    sharing = file_locks.Sharing(None, None, list)

    def __init__(self, descriptor: int, length: int):
        """``descriptor``: the file, opened for reading and writing by the sandbox (which it
        takes over)."""
        from yaseer.basic.machine.sandbox import identity_of

        self.identity = identity_of(descriptor)
        self.length_of_record = length
        self.handle = open(descriptor, "r+b")
        self.buffer = bytearray(length)
        self.fields: dict = {}  # variable key (str or (array, subscripts)) -> (offset, width)
        self.given: dict = {}  # variable key -> the string object it was last given
        self.last = 0  # LOC: the record last read or written
        self.past_end = False  # the last GET read beyond the end (EOF only: the buffer is still read)
        self.input_ended = False  # INPUT # met a Ctrl-Z: the end, until the next GET or PUT
        self.position = 0  # the buffer's byte PRINT # writes or INPUT # reads next (FD_OPS)
        self.given_back: str | None = None  # a character INPUT # gave back (F_BAKC)
        self.stream = RecordStream(self)

    # -- FIELD, LSET, RSET
    def field(self, offset: int, width, key, find=None) -> tuple[int, str | None]:
        """One ``width AS variable`` of FIELD, ``offset`` bytes into the buffer: the offset
        of the next one and the variable's new value (its slice of the buffer).  As
        DSKCOM.ASM FIELD takes them, one at a time: the width (GETBYT: 0..255, else
        Illegal function call), the variable (``key`` None: not a string variable, whose
        error the caller raises; ``find(key)`` makes it or fails: PTRGET), then the total
        against the record's length (``DERFOV``); a variable before the one that fails
        keeps its field."""
        from yaseer.basic.machine.runtime import cint

        width = cint(width)
        if not 0 <= width <= 255:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        if key is None:
            return offset, None
        if find is not None:
            find(key)
        if offset + width > self.length_of_record:
            raise error_for(FIELD_OVERFLOW)
        self.fields[key] = (offset, width)
        return offset + width, self._give(key)

    def _give(self, key: str, text: str | None = None) -> str:
        text = self.field_value(key) if text is None else text
        self.given[key] = text
        return text

    def forget_array(self, name: str) -> None:
        """Detach the elements of array ``name`` (ERASE, DIM: the array is made again)."""
        for key in [k for k in self.fields if type(k) is tuple and k[0] == name]:
            del self.fields[key]
            self.given.pop(key, None)

    def swap(self, first, second, now_first: str, now_second: str) -> None:
        """SWAP of variables ``first`` and ``second``, which now hold ``now_first`` (what
        ``second`` held) and ``now_second``: each one that was bound to a field (it held the
        string this file gave it) hands its field to the other, which holds that string now
        (BIMISC.ASM SWAP moves the descriptors, which point into the buffer)."""
        if first == second:
            return
        moved = {}
        for key, other, now in ((first, second, now_second), (second, first, now_first)):
            if self.bound(key, now):  # bound before the SWAP: it held what the other holds now
                moved[other] = (self.fields.pop(key), self.given.pop(key))
        for key, (field, given) in moved.items():
            self.fields[key] = field
            self.given[key] = given

    def bound(self, key, current) -> bool:
        """Whether variable ``key``, now holding ``current``, is still a field of this file
        (a field variable the program has stored another string in is not: it is unbound)."""
        if key not in self.fields:
            return False
        if self.given.get(key) is current:
            return True
        del self.fields[key]
        self.given.pop(key, None)
        return False

    def field_value(self, key: str) -> str:
        offset, width = self.fields[key]
        return self.buffer[offset:offset + width].decode("latin-1")

    def store(self, key: str, value: str, right: bool) -> str:
        """LSET (``right`` False) or RSET into fielded variable ``key``: the buffer's new
        slice, which is also the variable's new value."""
        offset, width = self.fields[key]
        text = justified(value, width, right)
        self.buffer[offset:offset + width] = text.encode("latin-1", errors="replace")
        return self._give(key, text)

    # -- GET, PUT
    def _record(self, record) -> int:
        """The record a GET or PUT names: the next one, or ``record`` read as an unsigned
        16-bit number (GIO86.ASM ``DPUTG`` -> ``ADRGET``: beyond -32768..65535 ``Overflow``)
        that GIODSK.ASM ``DSKRND`` takes as signed: above 0, so 1..32767, else ``Bad record
        number``."""
        if record is None:
            return self.last + 1
        n = math.floor(abs(record) + 0.5) * (1 if record >= 0 else -1)
        if not -32768 <= n <= 65535:
            raise error_for(OVERFLOW)
        if not 1 <= n <= MAX_RECORD:
            raise error_for(BAD_RECORD_NUMBER)
        return n

    def get(self, scalars, record=None) -> dict[str, str]:
        """GET: read a record into the buffer; the new values of the variables (read from
        ``scalars``: a :class:`FieldedVariables`) still fielded."""
        n = self._record(record)
        start = (n - 1) * self.length_of_record
        self.sharing.use("R", (start, min(start + self.length_of_record, self.length())))
        self.handle.seek(start)
        data = self.handle.read(self.length_of_record)
        self.past_end = len(data) < self.length_of_record
        self.input_ended = False
        self.position = 0  # DSKRND clears FD_OPS; the column (F_POS) stays
        self.buffer[:] = data + bytes(self.length_of_record - len(data))
        self.last = n
        return {key: self._give(key) for key in list(self.fields) if self.bound(key, scalars.get(key))}

    def put(self, record=None) -> None:
        """PUT: write the buffer as a record (a gap before it filled with zero bytes)."""
        n = self._record(record)
        start = (n - 1) * self.length_of_record
        self.sharing.use("W", (start, start + self.length_of_record))
        end = self.handle.seek(0, 2)
        if end < start:
            self.handle.write(bytes(start - end))
        self.handle.seek(start)
        self.handle.write(self.buffer)
        self.handle.flush()  # DSKRND hands the record to DOS: another opening of the file sees it
        self.last = n
        self.past_end = self.input_ended = False
        self.position = 0

    # -- PRINT #, WRITE #, INPUT #, LINE INPUT #, INPUT$ through the record buffer
    def output(self) -> "RecordStream":
        """PRINT # and WRITE #: the stream that writes into the record buffer."""
        return self.stream

    def set_width(self, width: int | None) -> None:
        """WIDTH #n: the width PRINT # wraps the buffer's lines at (GIO86.ASM FILWID sets
        any file's ``F_WID``)."""
        self.stream.width = width

    def store_bytes(self, text: str) -> str:
        """Write ``text`` into the buffer from its position; the part that fitted (each
        byte first checks the position against the record length: GIODSK.ASM ``DSKSOT``
        -> ``FOVCHK``, so the bytes before the one that does not fit are written)."""
        room = self.length_of_record - self.position
        part = text[:room]
        self.buffer[self.position:self.position + len(part)] = part.encode("latin-1", errors="replace")
        self.position += len(part)
        return part

    def refreshed(self, scalars, stored=None) -> dict:
        """The new values of the variables (read from ``scalars``: a :class:`FieldedVariables`) still fielded on this file,
        after something wrote into the buffer; ``stored``: a variable just stored through
        this file (LSET, RSET), fielded whatever ``scalars`` still holds for it."""
        return {key: self._give(key) for key in list(self.fields)
                if key == stored or self.bound(key, scalars.get(key))}

    def first(self) -> str:
        """An input item's first character (GIO86.ASM ``INCHR``): the end is ``Input past end``."""
        ch = self.next()
        if ch is None:
            raise error_for(INPUT_PAST_END)
        return ch

    def next(self) -> str | None:
        """The next character of the buffer, or None at the file's end (GIO86.ASM
        ``INCHSI``): a character given back comes first; else GIODSK.ASM ``DSKSIN``: the byte
        at the position (``FOVCHK``: at the record's end ``FIELD overflow``), and a Ctrl-Z is
        the end, from then on (``INCEOF``) until the next GET or PUT.  A GET that read beyond
        the file's end leaves zero bytes to read, not the end: a real GW-BASIC recorded
        FIELD overflow there (PC-BASIC's FLDOVFL test; PC-BASIC 2.0.8 agrees), where the
        source's ``F_ORCT`` of 0 would say Input past end."""
        if self.given_back is not None:
            ch, self.given_back = self.given_back, None
            return ch
        if self.input_ended:
            return None
        if self.position >= self.length_of_record:
            raise error_for(FIELD_OVERFLOW)
        ch = chr(self.buffer[self.position])
        self.position += 1
        if ch == END_OF_FILE:
            self.input_ended = True
            return None
        return ch

    def back(self, ch: str) -> None:
        """Give ``ch`` back to the next read (GIO86.ASM ``BAKCHR``: kept in the file's block,
        so a GET or PUT in between does not lose it)."""
        self.given_back = ch

    def read_chars(self, n: int) -> str:
        """INPUT$(n, #f): ``n`` characters (DSKCOM.ASM: each by ``INDSKC``, the end ``Input
        past end``)."""
        return "".join(self.first() for _ in range(n))

    def read_line(self, longest: int) -> str:
        return item_reading.read_item(self, item_reading.LINE, longest)

    def read_field(self, numeric: bool, longest: int) -> str:
        return item_reading.read_item(self, item_reading.NUMBER if numeric else item_reading.TEXT, longest)

    def at_end(self) -> bool:
        """EOF: the last GET read beyond the end, or an input met a Ctrl-Z; not while a
        character is given back (GIO86.ASM ``EOF`` tests ``FL_BKC`` first)."""
        return (self.past_end or self.input_ended) and self.given_back is None

    def length(self) -> int:
        self.handle.flush()
        return self.handle.seek(0, 2)

    def records(self) -> int:
        return self.last

    def close(self) -> None:
        self.handle.close()


class FieldedVariables:
    """The variables a FIELD may name, by key: a scalar's name, or an array element's
    (array name, subscripts); ``scalars`` and ``arrays`` are the machine's (an array nested
    lists, one level a dimension)."""

    def __init__(self, scalars: dict, arrays: dict):
        self.scalars = scalars
        self.arrays = arrays

    def get(self, key):
        """The variable's value; None for an element of an array that is not there (erased)."""
        if type(key) is str:
            return self.scalars.get(key)
        name, subscripts = key
        values = self.arrays.get(name)
        if values is None:
            return None
        for k in subscripts:
            values = values[k]
        return values

    def update(self, values: dict) -> None:
        """Store ``values`` (key -> string) in the variables."""
        for key, value in values.items():
            if type(key) is str:
                self.scalars[key] = value
                continue
            name, subscripts = key
            row = self.arrays[name]
            for k in subscripts[:-1]:
                row = row[k]
            row[subscripts[-1]] = value


def justified(value: str, width: int, right: bool) -> str:
    """``value`` cut to ``width`` characters (its first ones) or padded with blanks: on the
    right for LSET, on the left for RSET."""
    value = value[:width]
    return value.rjust(width) if right else value.ljust(width)


class RecordStream(FileStream):
    """PRINT # and WRITE # on a random file: the text goes into the record buffer from its
    position (GIODSK.ASM ``DSKSOT`` for a random file), a byte past the record's end is
    ``FIELD overflow``; the column counts as a sequential file's (``SOUTPS``) and neither
    GET nor PUT resets it, only a CR does."""

    def __init__(self, file: RandomFile):
        super().__init__(None)
        self.file = file

    def write(self, text: str) -> None:
        part = self.file.store_bytes(text)
        self.advance(part)
        if len(part) < len(text):
            raise error_for(FIELD_OVERFLOW)

    def new_row(self) -> None:
        self.write("\r\n")

    def before_write_end(self) -> None:
        """WRITE # fills the rest of the record but its last two bytes with blanks, so that
        its CR LF ends the record (FIVEO.ASM WRITE: WRTFIN, for a random disk file, counts
        the bytes left with CMPFBC less the two of CR LF and sends that many blanks; a real
        GW-BASIC 3.23 recorded it, PC-BASIC's RandomWidth test).  With fewer than two left
        it sends none; with exactly two its count starts at 0 and runs down through 65535,
        so the blanks meet the record's end: ``FIELD overflow``."""
        left = self.file.length_of_record - self.file.position - 2
        if left == 0:
            left = 0x10000
        if left > 0:
            self.write(" " * left)
