"""Sequential files for BASIC programs, confined to one directory.

Every name a program (or the interactive session) gives is looked up in one
directory, the *sandbox* (:mod:`yaseer.basic.machine.sandbox`): the current
directory, or ``yaseer run --files DIR``.  An absolute name, a ``..`` component,
or a name that leads out of the directory through a symbolic link is
``Path/File access error`` (75), also when another process swaps names for links
while the program runs; a FIFO or device is refused at once; nothing is ever read
or written outside it, and nothing at all is written unless the program opens a file
for OUTPUT, APPEND or RANDOM (or KILLs / NAMEs / SAVEs one).

The files are GW-BASIC's sequential files: text with CR LF line ends and a Ctrl-Z
(``chr(26)``) written at CLOSE; reading stops at the first Ctrl-Z.  Characters are
bytes (latin-1).  At most :data:`MAX_FILES` are open at once (GW-BASIC's default
``/F:3``); file numbers 1..MAX_FILES.  Errors are GW-BASIC's: ``Bad file number``
(52), ``File not found`` (53), ``Bad file mode`` (54), ``File already open`` (55),
``File already exists`` (58), ``Input past end`` (62), ``Bad file name`` (64),
``Path/File access error`` (75).
"""

from __future__ import annotations

import os

from yaseer.basic.errors import (
    BAD_FILE_MODE, BAD_FILE_NAME, BAD_FILE_NUMBER, DEVICE_IO_ERROR, FILE_ALREADY_EXISTS, FILE_ALREADY_OPEN,
    FILE_NOT_FOUND, ILLEGAL_FUNCTION_CALL, RENAME_ACROSS_DISKS, INPUT_PAST_END, PATH_FILE_ACCESS_ERROR, BasicError,
    error_for, not_emulated,
)
from yaseer.basic.machine import device_files, file_locks, item_reading, random_files
from yaseer.basic.machine.random_files import END_OF_FILE  # Ctrl-Z
from yaseer.basic.machine.runtime import cint
from yaseer.basic.machine.sandbox import Sandbox, identity_of, nameless
from yaseer.basic.machine.screen import FileStream


def _drive(name: str) -> str:
    """The drive letter a file name starts with (``C:``), in capitals, or ``""``."""
    return name[0].upper() if len(name) > 1 and name[1] == ":" and name[0].isalpha() else ""

MAX_FILES = 3
RECORD = 128  # bytes: LOC counts these
_MODES = {"I": "I", "O": "O", "A": "A", "R": "R", "INPUT": "I", "OUTPUT": "O", "APPEND": "A", "RANDOM": "R"}


def read_program(sandbox: Sandbox, name: str) -> bytes:
    """The bytes of program file ``name`` in the sandbox (CHAIN, MERGE; case as DOS)."""
    return sandbox.read_bytes(sandbox.dos_name(name))


class OpenFile:
    """One open sequential file: ``mode`` "I", "O" or "A", on ``descriptor`` (from
    :class:`Sandbox`: a regular file inside it, opened without following a link, not yet
    truncated), which it takes over; ``identity`` is its (device, inode); ``sharing`` its
    OPEN clauses (file_locks.Sharing; the file table sets it)."""

    sharing = file_locks.Sharing(None, None, list)  # no clauses (a file OPEN did not make)

    def __init__(self, descriptor: int, mode: str):
        self.identity, self.mode = identity_of(descriptor), mode
        if mode == "I":
            with os.fdopen(descriptor, "rb") as handle:
                data = handle.read().decode("latin-1")
            cut = data.find(END_OF_FILE)
            self.data = data if cut < 0 else data[:cut]
            self.size = len(data)
            self.position = 0
            self.stream = None
        else:
            if mode == "A":  # appended after the old text, without its Ctrl-Z
                old = os.pread(descriptor, os.fstat(descriptor).st_size, 0).decode("latin-1")
                cut = old.find(END_OF_FILE)
                os.ftruncate(descriptor, len(old) if cut < 0 else cut)
            else:
                os.ftruncate(descriptor, 0)
            os.lseek(descriptor, 0, os.SEEK_END)
            handle = open(descriptor, "a" if mode == "A" else "w", encoding="latin-1", newline="")
            self.stream = FileStream(handle)
            self.written = handle.tell()

    def set_width(self, width: int | None) -> None:
        """WIDTH #n: the line width of PRINT # (None: never wrap); an input file keeps it too."""
        if self.stream is not None:
            self.stream.width = width

    # -- output
    def output(self) -> FileStream:
        if self.stream is None:
            raise error_for(BAD_FILE_MODE)
        self.sharing.use("W")
        return self.stream

    def close(self) -> None:
        if self.stream is not None:
            self.stream.stream.write(END_OF_FILE)
            self.stream.stream.close()

    # -- input
    def _input(self) -> str:
        if self.stream is not None:
            raise error_for(BAD_FILE_MODE)
        self.sharing.use("R")
        return self.data

    @property
    def is_output(self) -> bool:
        """Opened for output (or append)."""
        return self.stream is not None

    def at_end(self) -> bool:
        """EOF: an output file is Bad file mode (GIODSK.ASM DSKEOF)."""
        data = self._input()
        return self.position >= len(data)

    def read_chars(self, n: int) -> str:
        data = self._input()
        if self.position + n > len(data):
            raise error_for(INPUT_PAST_END)
        text = data[self.position:self.position + n]
        self.position += n
        return text

    # the three operations item_reading.read_item asks of a source (its module docstring)
    def first(self) -> str:
        """An item's first character; the end of the file is ``Input past end``."""
        data = self._input()
        if self.position >= len(data):
            raise error_for(INPUT_PAST_END)
        self.position += 1
        return data[self.position - 1]

    def next(self) -> str | None:
        """The next character, or None at the end of the file (the first Ctrl-Z)."""
        if self.position >= len(self.data):
            return None
        self.position += 1
        return self.data[self.position - 1]

    def back(self, ch: str) -> None:
        """Give back the character just read (it is the one before the position)."""
        self.position -= 1

    def read_line(self, longest: int) -> str:
        """LINE INPUT #: DSKCOM.ASM ``DLINE``, see item_reading (PC-BASIC 2.0.8 ends a line at
        a lone LF too, where GW keeps it in the line)."""
        return item_reading.read_item(self, item_reading.LINE, longest)

    def read_field(self, numeric: bool, longest: int) -> str:
        """INPUT #: one item as DSKCOM.ASM ``INPDOR`` reads it, see item_reading."""
        return item_reading.read_item(self, item_reading.NUMBER if numeric else item_reading.TEXT, longest)

    # -- LOF, LOC
    def length(self) -> int:
        if self.stream is not None:
            self.stream.flush()
            return self.stream.stream.tell()
        return self.size

    def records(self) -> int:
        """LOC: 128-byte records written, or read into the buffer (reading starts with one)."""
        if self.stream is not None:
            return self.length() // RECORD
        return self.position // RECORD + 1


def _fcb_name(name: str) -> str:
    """The name a DOS FCB keeps of file ``name``: its last part, in capitals (no folder)."""
    return name.replace("\\", "/").rsplit("/", 1)[-1].upper()


def file_byte(n) -> int:
    """A file number as a byte: outside 0..255 ``Illegal function call`` (a CLOSE of a
    number in range that is not open does nothing)."""
    k = cint(n)
    if not 0 <= k <= 255:
        raise error_for(ILLEGAL_FUNCTION_CALL)
    return k


class FileTable:
    """The open files of a machine, by file number, all inside one :class:`Sandbox`."""

    def __init__(self, sandbox: Sandbox | None = None, devices: tuple = (), absent: dict | None = None,
                 device_files: tuple = ()):
        self.sandbox = sandbox or Sandbox()
        self.open_files: dict[int, OpenFile] = {}
        self.devices = devices  # device names that mean the sandbox ("CAS0:" on the Casio)
        self.absent = absent or {}  # device name -> what it is, for devices yaseer does not have
        self.device_files = device_files  # Dialect.device_files: the devices OPEN knows by name
        self.device_streams: dict = {}  # the machine's "screen" and "printer" streams, for those devices

    @staticmethod
    def number(n) -> int:
        """A file number: outside 0..255 ``Illegal function call``, else outside 1..MAX_FILES
        ``Bad file number`` (GW-BASIC checks the byte before the file table)."""
        k = file_byte(n)
        if not 1 <= k <= MAX_FILES:
            raise error_for(BAD_FILE_NUMBER)
        return k

    def open(self, mode: str, n, name: str, length=None, access: str | None = None, lock: str | None = None) -> None:
        """OPEN: ``mode`` "I"/"O"/"A"/"R" (or INPUT, OUTPUT, APPEND, RANDOM) as file number
        ``n``; ``length``: a random file's record length (yaseer.basic.random_files);
        ``access``, ``lock``: GW-BASIC 3.23's clauses (machine/file_locks.py)."""
        kind = _MODES.get(mode.strip().upper())
        if kind is None:
            raise error_for(BAD_FILE_MODE)
        k = self.number(n)
        if k in self.open_files:
            raise error_for(FILE_ALREADY_OPEN)
        self.open_files[k] = self._opened(kind, name, length, access, lock)

    def check_not_open(self, name: str) -> None:
        """A file SAVE writes (GIODSK.ASM opens it for output: CHKFOP): ``File already open``
        where an open file has its name (in any folder, as CHKFOP compares names; PC-BASIC's
        recorded OpenSave test)."""
        fcb_name = _fcb_name(name)
        if any(getattr(f, "fcb_name", None) == fcb_name for f in self.open_files.values()):
            raise error_for(FILE_ALREADY_OPEN)

    def listing_file(self, name: str):
        """The file LIST [range], "f" writes its lines to (GWLIST.ASM LIST: NAMSCN reads the
        name, NULOPM opens file 0 for output), as OPEN "f" FOR OUTPUT opens it but under no
        number; the caller closes it."""
        return self._opened("O", name)

    def _opened(self, kind: str, name: str, length=None, access: str | None = None, lock: str | None = None):
        """The open file (or device) OPEN makes of ``name`` in mode ``kind``, not yet numbered:
        a file open already is ``File already open`` for OUTPUT and APPEND (GIODSK.ASM DSKOPN
        calls CHKFOP for those modes only: INPUT and RANDOM may open a file open for output,
        as a real GW-BASIC 3.23 recorded it, PC-BASIC's LockFilesOutput test), and so is any
        open file of the same name in another folder (CHKFOP compares the FCBs' names, which
        hold no folder: PC-BASIC's recorded FileNameExclusion test), then the clauses
        decide (file_locks.check_opening)."""
        device = device_files.device_kind(name, self.device_files) if self.device_files else None
        if device is not None:  # never a file of the directory
            return device_files.open_device(device, kind, self.device_streams)
        size = random_files.record_length(length) if kind == "R" else None
        sandbox = self.sandbox
        name = sandbox.dos_name(self._local_name(name))
        descriptor = sandbox.open_input(name) if kind == "I" else sandbox.open_output(name, readable=kind != "O")
        identity = identity_of(descriptor)
        same = [f for f in self.open_files.values() if getattr(f, "identity", None) == identity]
        fcb_name = _fcb_name(name)
        try:
            if kind in "OA" and (same or any(getattr(f, "fcb_name", None) == fcb_name for f in self.open_files.values())):
                raise error_for(FILE_ALREADY_OPEN)  # GIODSK.ASM DSKOPN: CHKFOP for sequential output and append only
            file_locks.check_opening(access, lock, [f.sharing for f in same])
        except BasicError:
            os.close(descriptor)  # nothing truncated yet: OpenFile does that
            raise
        try:
            opened = random_files.RandomFile(descriptor, size) if size else OpenFile(descriptor, kind)
        except OSError:
            try:
                os.close(descriptor)
            except OSError:  # the file object had closed it already
                pass
            raise error_for(PATH_FILE_ACCESS_ERROR) from None
        opened.fcb_name = fcb_name
        opened.sharing = file_locks.Sharing(access, lock, lambda: [
            f.sharing for f in self.open_files.values() if f is not opened and getattr(f, "identity", None) == identity])
        return opened

    def verify(self, name: str) -> None:
        """VERIFY "file": closes every file, then reads the file through (not there: File not
        found; unreadable: Device I/O error, the Casio's RW error)."""
        self.close()
        self.sandbox.read_bytes(self.sandbox.dos_name(self._local_name(name)))

    def _local_name(self, name: str) -> str:
        """``name`` without the device that means the program's directory ("CAS0:"); a device
        yaseer does not have ends the run with one line naming it."""
        for device, what in self.absent.items():
            if name.upper().startswith(device):
                raise not_emulated(f"{device} ({what})", DEVICE_IO_ERROR)
        for device in self.devices:
            if name.upper().startswith(device):
                return name[len(device):]
        return name

    def get(self, n) -> OpenFile:
        f = self.open_files.get(self.number(n))
        if f is None:
            raise error_for(BAD_FILE_NUMBER)
        return f

    def opened(self, n) -> OpenFile:
        """Open file ``n`` as GET, PUT and INPUT$ find it: a byte (above 255 ``Illegal
        function call``), 0 ``Bad file number`` (GIO86.ASM ``POFNUM`` -> ``GETNZB``), then
        looked for among the open files, whatever the number of files: one not open is
        ``Bad file mode`` (``FDBPTR`` finds none, ``DERFNO``: GWDATA.ASM gives ``ERRFNO`` the
        code of ``ERRBFM``)."""
        k = file_byte(n)
        if k == 0:
            raise error_for(BAD_FILE_NUMBER)
        f = self.open_files.get(k)
        if f is None:
            raise error_for(BAD_FILE_MODE)
        return f

    # -- random-access files (random_files.py)
    def checked(self, n, modes: str, find=None) -> OpenFile:
        """Open file ``n`` (found by ``find``: :meth:`get` unless given) opened in one of
        ``modes`` ("I", "O", "A", "R"), else ``Bad file mode``."""
        f = (find or self.get)(n)
        if f.mode not in modes:
            raise error_for(BAD_FILE_MODE)
        return f

    def random(self, n, find=None) -> random_files.RandomFile:
        """Open file ``n`` (found by ``find``: :meth:`get` unless given), which must be a
        random one (else ``Bad file mode``)."""
        return self.checked(n, "R", find)

    def justify(self, key, value: str, current: str, right: bool, variables) -> dict:
        """LSET / RSET of variable ``key`` (a scalar's name or an element's (array,
        subscripts), now holding ``current``): the new values of the variables, ``key``'s
        and, where ``key`` is fielded on an open file, those of every variable fielded on it
        (read from ``variables``, a random_files.FieldedVariables), which see its slice of
        the buffer filled (DSKCOM.ASM FIELD points each variable into the buffer: two fields
        over the same bytes are the same bytes)."""
        for f in self.open_files.values():
            if f.mode == "R" and f.bound(key, current):
                f.store(key, value, right)
                return f.refreshed(variables, stored=key)
        return {key: random_files.justified(value, len(current), right)}

    def swap_fields(self, first, second, now_first: str, now_second: str) -> None:
        """SWAP of string variables ``first`` and ``second`` (keys), which now hold
        ``now_first`` (what ``second`` held) and ``now_second``: on every random file the
        field each was bound to goes with its value (RandomFile.swap)."""
        for f in self.open_files.values():
            if f.mode == "R":
                f.swap(first, second, now_first, now_second)

    def field_strings(self) -> dict:
        """id -> string of each string a random file's FIELD, GET, LSET or RSET gave a
        variable: GW's field variable points into the file's buffer (DSKCOM.ASM FIELD
        stores the buffer's address in its descriptor), so its characters take no string
        space (a real GW-BASIC 3.23's FRE("") after FIELD #1, 128 AS A$: PC-BASIC's
        recorded FLDGARB test).  Strings of one character are left out: Python shares
        those with every string of that character (as StringSpace.keep_text)."""
        found = {}
        for f in self.open_files.values():
            if f.mode == "R":
                found.update((id(text), text) for text in f.given.values() if len(text) > 1)
        return found

    def forget_array(self, name: str) -> None:
        """ERASE or DIM of array ``name``: its elements are no longer fields of any file."""
        for f in self.open_files.values():
            if f.mode == "R":
                f.forget_array(name)

    def close(self, numbers=()) -> None:
        """CLOSE [n, ...]: the files named (no error for one not open), or all."""
        for k in ([file_byte(n) for n in numbers] if numbers else list(self.open_files)):
            f = self.open_files.pop(k, None)
            if f is not None:
                f.close()

    def rename(self, old: str, new: str) -> None:
        """NAME old AS new (``old`` found as DOS finds it, whatever its case); a new name on
        another drive than the old one's is Rename across disks once the old file is found
        (GIODSK.ASM NAME compares the drives, no drive being 0)."""
        old = self.rename_from(old)
        if _drive(new) and _drive(new) != _drive(old):
            raise error_for(RENAME_ACROSS_DISKS)
        self.sandbox.rename(old, new)

    def rename_from(self, old: str) -> str:
        """NAME's old file, found (else File not found) before anything after it is read."""
        old = self.sandbox.dos_name(old)
        self.sandbox.identity(old)
        return old

    def kill(self, name: str) -> None:
        """KILL name: a name that names nothing is ``Bad file name`` (as a real GW-BASIC 3.23
        recorded it, PC-BASIC's DISK2 test: OPEN's is Bad file number)."""
        if nameless(name):
            raise error_for(BAD_FILE_NAME)
        name = self.sandbox.dos_name(name)
        identity = self.sandbox.identity(name)
        if any(f.identity == identity for f in self.open_files.values()):
            raise error_for(FILE_ALREADY_OPEN)
        self.sandbox.kill(name)
