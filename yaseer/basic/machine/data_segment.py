"""GW-BASIC's data segment from the program up, as VARPTR and PEEK see it: laid out from
the machine's state when a program asks (yaseer keeps its values in Python; this module
is imported only then, so other programs pay nothing).

From ``DataSegmentRules.text_start`` (TXTTAB, 4718 with GW's default /F:3 /S:128; the byte
before it is 0) upwards, GW-BASIC 3.23 keeps (GWMAIN.ASM, BIPTRG.ASM, BISTRS.ASM):

* the program text (TXTTAB): each line's link, number, tokens and 0, then a 0 link
  (machine/program_crunch.py's bytes);
* the simple variables (VARTAB), in the order PTRGET made them (machine/variables.py's
  ``made``), each its type (2 an integer, 3 a string, 4 a single, 8 a double), its name's
  first two characters (0 for none), the count of the others and those others with bit 7
  set, then its value: an integer in two bytes, low first; a single or a double in
  Microsoft's binary format (MKS$, MKD$); a string's descriptor, its length and the
  address of its characters.  A DEF FN is such an entry with bit 7 of its first letter
  set (GWEVAL.ASM DEF: GETFNM), of the function's type, holding the address of the text
  after its name in the DEF statement, the rest of the value 0;
* the arrays (ARYTAB), in the order they were made: the name as a simple variable's, the
  bytes that follow (2), the dimension count (1) and each dimension's element count (2,
  the last dimension first: BIPTRG.ASM ISARY pops the subscripts it pushed), then the
  elements, the first subscript running fastest; STREND ends them;
* the strings, from ``string_top`` down (FRETOP): a string's characters lie in the
  string space, or in the program text for a literal assigned or a DATA item (GWMAIN.ASM
  LETCN6 copies neither).  The first time a program looks, the strings the variables
  hold are laid from the top down in the variables' order, as after a garbage collection
  (yaseer kept no addresses before); from then on the string space keeps where each new
  string goes and how a collection moves them (machine/string_space.py ``track``).

Below the program, the data segment holds the pointers (offsets into it, low byte first):
``&H2C`` the top of BASIC's memory, ``&H30`` TXTTAB, ``&H358`` VARTAB, ``&H35A`` ARYTAB,
``&H35C`` STREND (the addresses the recordings of the real machine read).
Units: addresses are offsets in the data segment, sizes bytes.
"""

from __future__ import annotations

from yaseer.basic.machine.gwfunctions import mkd, mks
from yaseer.basic.machine.memory_model import FN_KEY
from yaseer.basic.machine.program_crunch import tokenised_program

# where GW-BASIC keeps its pointers in the data segment (GWRAM.ASM's order; offsets)
MEMORY_TOP_AT, TEXT_AT, VARIABLES_AT, ARRAYS_AT, ARRAYS_END_AT = 0x2C, 0x30, 0x358, 0x35A, 0x35C
TYPE_BYTES = {"%": 2, "$": 3, "!": 4, "#": 8}  # a value's bytes, also its type byte (VALTYP)
FUNCTION_BIT = 0x80  # on a DEF FN's first letter
DEF, FN = 0x97, 0xD1  # the tokens of DEF and FN


def type_of(name: str) -> str:
    """A full name's type character (a name without one is a single's)."""
    return name[-1] if name[-1] in TYPE_BYTES else "!"


def name_bytes(name: str) -> bytes:
    """A variable's header: its type, two name characters, the count of the others and those."""
    letters = name.rstrip("%!#$").encode("latin-1")
    rest = bytes(c | 0x80 for c in letters[2:])
    first = letters[:2].ljust(2, b"\0")
    return bytes((TYPE_BYTES[type_of(name)],)) + first + bytes((len(rest),)) + rest


def value_bytes(kind: str, value) -> bytes:
    """A number's bytes as GW holds it (``kind`` "%", "!" or "#")."""
    if kind == "%":
        return (int(value) & 0xFFFF).to_bytes(2, "little")
    text = mks(value) if kind == "!" else mkd(value)
    return bytes(map(ord, text))


class Layout:
    """The data segment from ``text_start - 1`` up, with the strings above, as it stands
    (:meth:`byte`: the byte at an offset; a numeric array's elements are read only where a
    PEEK reads them), and where each variable's value lies (``scalars``: full name ->
    address; ``arrays``: full name -> (address of the first element, element counts in
    subscript order))."""

    def __init__(self, rules, program: dict, scalars: dict, order, arrays: dict, held_dims: dict,
                 fns: dict, literals: dict, base: int = 0, places: dict | None = None):
        self.rules = rules
        self.scalars: dict[str, int] = {}
        self.arrays: dict[str, tuple[int, tuple]] = {}
        self.places = places or {}  # id -> (string, address): where the string space's strings lie
        self.placed: dict = {}  # the same for the strings this layout put in the space
        self.string_top = min([rules.string_top] + [address for _, address in self.places.values()])
        self.text = _program_text(program, rules.text_start)
        self.literals = literals  # id -> string of the literals and DATA items (string_space.text)
        self.base = base
        self._strings = None  # address -> byte of the strings, made when a PEEK reads there
        table = bytearray()
        at = self.variables = rules.text_start + len(self.text)
        for name in order:
            if name.startswith(FN_KEY):
                name = name[len(FN_KEY):]
                if name in fns:
                    table += self._function(at + len(table), name)
                continue
            value = scalars.get(name)
            if value is None:
                continue
            head = name_bytes(name)
            self.scalars[name] = at + len(table) + len(head)
            table += head + self._value(name, value)
        self.table = bytes(table)
        at = self.array_start = self.variables + len(table)
        self.parts = []  # (start, first element, end, header, the elements' bytes or None: read when peeked, name, values)
        for name, values in arrays.items():
            counts = tuple(d + 1 for d in held_dims[name])
            size = TYPE_BYTES[type_of(name)]
            elements = 1
            for n in counts:
                elements *= n
            data = None
            if name.endswith("$"):  # (the descriptors now: their strings are placed in this order)
                data = b"".join(self._value(name, v) for v in _column_order(values, len(counts), base))
            head = name_bytes(name)
            rest = bytes((len(counts),)) + b"".join(n.to_bytes(2, "little") for n in reversed(counts))
            header = head + (len(rest) + elements * size).to_bytes(2, "little") + rest
            first = at + len(header)
            self.arrays[name] = (first, counts)
            self.parts.append((at, first, first + elements * size, header, data, name, values))
            at = first + elements * size
        self.array_end = at
        self.low: dict[int, int] = {}  # GW's pointers below the program
        for where, address in ((MEMORY_TOP_AT, rules.memory_top), (TEXT_AT, rules.text_start),
                               (VARIABLES_AT, self.variables), (ARRAYS_AT, self.array_start),
                               (ARRAYS_END_AT, self.array_end)):
            self.low[where], self.low[where + 1] = address & 0xFF, address >> 8

    def byte(self, offset: int) -> int:
        """The byte at data-segment ``offset`` (0 where nothing lies)."""
        if offset in self.low:
            return self.low[offset]
        k = offset - self.rules.text_start
        if -1 <= k < len(self.text):
            return self.text[k] if k >= 0 else 0
        if self.variables <= offset < self.array_start:
            return self.table[offset - self.variables]
        if self.array_start <= offset < self.array_end:
            for start, first, end, header, data, name, values in self.parts:
                if start <= offset < end:
                    if offset < first:
                        return header[offset - start]
                    if data is not None:
                        return data[offset - first]
                    index, k = divmod(offset - first, TYPE_BYTES[type_of(name)])
                    return self._value(name, _element(values, index, self.arrays[name][1], self.base))[k]
        if self._strings is None:
            self._strings = {}
            for text, address in list(self.places.values()) + list(self.placed.values()):
                for i, code in enumerate(text.encode("latin-1", "replace")):
                    self._strings[address + i] = code
        return self._strings.get(offset, 0)

    def _value(self, name: str, value) -> bytes:
        kind = type_of(name)
        if kind != "$":
            return value_bytes(kind, value)
        return bytes((len(value),)) + self._string_address(value).to_bytes(2, "little")

    def _string_address(self, text: str) -> int:
        """Where string ``text``'s characters lie: in the program text for a literal (its
        first place there between quotes, or as a DATA item), else the next place down the
        string space."""
        if not text:
            return 0
        place = self.places.get(id(text))
        if place is not None and place[0] is text:
            return place[1]
        if len(text) == 1 or id(text) in self.literals:  # (one character: maybe a literal)
            found = self._in_text(text)
            if found is not None:
                return found
        self.string_top -= len(text)
        if id(text) not in self.literals:  # (a literal of a program gone: CHAIN copies it later)
            self.placed[id(text)] = (text, self.string_top)
        return self.string_top

    def _in_text(self, text: str):
        data = text.encode("latin-1", "replace")
        where = self.text.find(b'"' + data + b'"')
        if where < 0:
            where = self.text.find(b'"' + data + b"\0")
        if where >= 0:
            return self.rules.text_start + where + 1
        where = self.text.find(data)
        return None if where < 0 else self.rules.text_start + where

    def _function(self, at: int, name: str) -> bytes:
        """A DEF FN's entry at ``at``: its value the address after its name in the DEF statement."""
        head = bytearray(name_bytes(name))
        head[1] |= FUNCTION_BIT
        self.scalars[FN_KEY + name] = at + len(head)
        size = TYPE_BYTES[type_of(name)]
        pointer = self._definition(name)
        return bytes(head) + (pointer.to_bytes(2, "little") + bytes(8))[:size]

    def _definition(self, name: str) -> int:
        """The address after ``FN name`` (and the blanks after it) in the program's DEF."""
        letters = name.rstrip("%!#$").encode("latin-1")
        text = self.text
        start = 0
        while True:
            i = text.find(bytes((DEF,)), start)
            if i < 0:
                return 0
            j = i + 1
            while j < len(text) and text[j] == 0x20:
                j += 1
            if text[j:j + 1] == bytes((FN,)):
                j += 1
                while j < len(text) and text[j] == 0x20:
                    j += 1
                k = j
                while k < len(text) and (chr(text[k]).isalnum() or text[k] == 0x2E):
                    k += 1
                if text[j:k] == letters:
                    if k < len(text) and chr(text[k]) in "%!#$":
                        k += 1
                    while k < len(text) and text[k] == 0x20:
                        k += 1
                    return self.rules.text_start + k
            start = i + 1

    def element(self, name: str, subscripts: tuple, base: int) -> int:
        """The address of array ``name``'s element at ``subscripts`` (checked already)."""
        first, counts = self.arrays[name]
        index, stride = 0, 1
        for subscript, count in zip(subscripts, counts):
            index += (subscript - base) * stride
            stride *= count
        return first + index * TYPE_BYTES[type_of(name)]


def _element(values, index: int, counts: tuple, base: int):
    """Element ``index`` (in GW's order, the first subscript fastest) of nested lists
    ``values`` holding ``counts`` elements a dimension (from ``base``)."""
    subscripts = []
    for count in counts:
        index, subscript = divmod(index, count)
        subscripts.append(subscript + base)
    for subscript in subscripts:
        values = values[subscript]
    return values


_TEXT: list = [None, None, b""]  # the last program laid out: (its lines, its start, its bytes)


def _program_text(program: dict, start: int) -> bytes:
    """:func:`tokenised_program`, kept for the same program (a PEEK loop lays it out again
    for every byte it reads)."""
    if _TEXT[0] != program or _TEXT[1] != start:
        _TEXT[:] = [dict(program), start, tokenised_program(program, start)]
    return _TEXT[2]


def in_layout(offset: int, rules) -> bool:
    """Does data-segment ``offset`` lie where the layout has bytes: GW's pointers to the
    tables, or from the byte before the program up?"""
    return offset >= rules.text_start - 1 or MEMORY_TOP_AT <= offset < TEXT_AT + 2 or (
        VARIABLES_AT <= offset < ARRAYS_END_AT + 2)


def _column_order(values, ndim: int, base: int):
    """The elements of nested lists ``values`` (first subscript outermost) with the first
    subscript running fastest, as GW keeps them; under OPTION BASE 1 (``base``) without
    the unused entry 0 of each dimension."""
    values = values[base:]
    if ndim == 1:
        return list(values)
    columns = [_column_order(v, ndim - 1, base) for v in values]  # each: the rest, in GW's order
    return [column[k] for k in range(len(columns[0])) for column in columns]
