"""The FX-850P/880P's DATA BANK: records (lines of text) a program writes, reads and searches.

The owner's manual, part 5 and the pages WRITE#, READ#, RESTORE#, LIST#, LLIST#, NEW#, SAVE#
and LOAD#: a record is one line of items separated by commas (at most 255 characters); one
pointer says where the next READ# or WRITE# goes.  ``RESTORE#`` puts it before the first
record; ``RESTORE# "text"`` on the next item, searching forward from the pointer, that
begins with the text (mode 0, the default) or holds it (mode 1).  ``WRITE# a, b`` writes
the record at the pointer (replacing it, or adding one at the end) and moves past it;
``WRITE#`` alone empties the record.  ``READ#`` reads item after item, across records,
as READ reads DATA (quotes keep commas; blanks before an item are skipped); none left is
the manual's DA error (``Out of DATA``).  ``SAVE#``/``LOAD#`` keep the records in a
file of the program's directory, one line each, in the machine's codes.
"""

from __future__ import annotations

from yaseer.basic.errors import (
    BasicError, ILLEGAL_FUNCTION_CALL, OUT_OF_DATA, STRING_TOO_LONG, TYPE_MISMATCH, password_protected,
)

RECORD_LENGTH = 255  # WRITE#.md item 6


def items_of(record: str) -> list[tuple[int, str]]:
    """(offset, text) of each item of ``record``: split at commas outside quotes."""
    items, start, quoted = [], 0, False
    for k, ch in enumerate(record):
        if ch == '"':
            quoted = not quoted
        elif ch == "," and not quoted:
            items.append((start, record[start:k]))
            start = k + 1
    items.append((start, record[start:]))
    return items


class DataBank:
    """The records and the pointer (record, item) of one machine."""

    def __init__(self):
        self.records: list[str] = []
        self.record = 0  # the pointer: this record ...
        self.item = 0  # ... and this item of it

    def restore(self) -> None:
        """RESTORE#: before the first record."""
        self.record = self.item = 0

    def find(self, text: str, mode: int = 0) -> bool:
        """RESTORE# "text"[, mode]: the pointer on the next item that begins with (0) or holds
        (1) ``text``; False (pointer kept) when there is none."""
        if mode not in (0, 1):
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        for r in range(self.record, len(self.records)):
            for i, (_, item) in enumerate(items_of(self.records[r])):
                if r == self.record and i < self.item:
                    continue
                candidate = item.lstrip(" ")
                if candidate.startswith(text) if mode == 0 else text in candidate:
                    self.record, self.item = r, i
                    return True
        return False

    def write(self, pieces: tuple) -> None:
        """WRITE# items: the record at the pointer (from its item on) becomes them."""
        if self.record >= len(self.records):
            self.records.append("")
            self.record = len(self.records) - 1
            self.item = 0
        old = self.records[self.record]
        keep = old[:items_of(old)[self.item][0]] if self.item else ""
        record = keep + ",".join(pieces)
        if len(record) > RECORD_LENGTH:
            raise BasicError("String too long", STRING_TOO_LONG)
        self.records[self.record] = record
        self.record, self.item = self.record + 1, 0

    def read(self) -> str:
        """READ#: the next item's text (quotes removed), the pointer past it."""
        while self.record < len(self.records):
            items = items_of(self.records[self.record])
            if self.item < len(items) and self.records[self.record]:
                text = items[self.item][1].strip(" ")
                self.item += 1
                if self.item >= len(items):
                    self.record, self.item = self.record + 1, 0
                return text[1:-1] if len(text) >= 2 and text[0] == text[-1] == '"' else text
            self.record, self.item = self.record + 1, 0
        raise BasicError("Out of DATA", OUT_OF_DATA)

    def clear(self, machine) -> None:
        """NEW# (refused, as LIST# and SAVE#, while ``machine`` has a password: PR)."""
        _unlocked(machine)
        self.records.clear()
        self.restore()

    def text(self) -> str:
        """The records as a file holds them (SAVE#), one line each."""
        return "".join(record + "\n" for record in self.records)

    def load(self, text: str, append: bool) -> None:
        """LOAD# (``append``: ``, M``) from a file's text."""
        records = [line.rstrip("\r") for line in text.split("\n")]
        if records and records[-1] == "":
            records.pop()
        self.records = (self.records if append else []) + records
        self.restore()

    # -- the statements on a machine (its screen, files and number reading)
    def read_number(self, machine) -> float:
        """READ# into a numeric variable: the item as a number (a text is Type mismatch, TM)."""
        from yaseer.basic.machine.gwfunctions import number_field

        value = number_field(self.read(), machine.dialect.number_reading)
        if value is None:
            raise BasicError("Type mismatch", TYPE_MISMATCH)
        return value

    def list(self, machine, device: int = 0) -> None:
        """LIST# (``device`` 0) or LLIST# (1, the printer): each record on a line of its own,
        after its record number (LIST_HASH.md item 2, LLIST_HASH.md item 2).  The pages do
        not show the form; part 5 calls the record number the DATA BANK's line number, so a
        record is shown as LIST shows a program line: the number (from 1), a blank, the data."""
        _unlocked(machine)
        for number, record in enumerate(self.records, 1):
            machine.print_items(device, (f"{number} {record}",), True)

    def save(self, machine, name: str) -> None:
        """SAVE# "name": the records into the file (its bytes are the machine's codes)."""
        _unlocked(machine)
        machine.files.sandbox.write_bytes(_file_name(machine, name), self.text().encode("latin-1"))

    def load_file(self, machine, name: str, append: bool) -> None:
        """LOAD# "name"[, M]."""
        self.load(machine.files.sandbox.read_bytes(_file_name(machine, name)).decode("latin-1"), append)


def _unlocked(machine) -> None:
    """LIST#, LLIST#, NEW# and SAVE# cannot be executed for data protected by a password
    (LIST#.md item 5, LLIST#.md item 3, NEW#.md item 2, SAVE#.md item 7; PASS.md: one password
    for the programs and the DATA BANK): the PR error."""
    if machine.password_set is not None:
        raise password_protected()


def _file_name(machine, name: str) -> str:
    """``name`` without a device that means the program's directory (``CAS0:``)."""
    for device in machine.files.devices:
        if name.upper().startswith(device):
            return name[len(device):]
    return name
