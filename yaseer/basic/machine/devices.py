"""What gw's device words do on a machine without the devices (dialects/gw_words.py).

yaseer has no I/O ports, no device drivers, no DOS environment of the host's and runs no
machine code (the speaker's words, SOUND and BEEP, fill the music queue: machine/music.py).  Each word checks its arguments as GW-BASIC 3.23 does, then does
what a PC with nothing attached would do; where the real machine would hang or jump into
memory, the run ends with one line naming what is not emulated.  Nothing here reads or
writes outside the program's directory: the environment is the program's own table (the
host's is never read), and the file locks are records of this machine's open files.
"""

from __future__ import annotations

from yaseer.basic.errors import (
    BAD_RECORD_NUMBER, ILLEGAL_FUNCTION_CALL, OVERFLOW, PERMISSION_DENIED, TYPE_MISMATCH, error_for, not_emulated,
)
from yaseer.basic.machine import file_locks
from yaseer.basic.arithmetic.values import to_int
from yaseer.basic.machine.runtime import byte_argument as _byte, cint

# The ports of the PC's DMA controller (8237, 0..&H1F), on every PC: idle, they read 0, as
# the IBM PC behind PC-BASIC's recordings answered INP(0), INP(1) and INP(2).
DMA_PORTS = range(0x20)
# Any other port: no device answers, the data bus floats high (the recordings: INP(150),
# INP(256), INP(-1) are 255).
FLOATING_BUS = 255
# A record number of LOCK (PC-BASIC 2.0.8: 1 .. 2^25-2, else Bad record number).
LAST_RECORD = 2 ** 25 - 2
WHOLE_FILE = (1, LAST_RECORD)


def _port(x: float) -> int:
    """A port as FRMQNT reads it: -32768..65535 (a negative one is its 16-bit two's
    complement), else Overflow."""
    k = cint(x)
    if not -32768 <= k <= 65535:
        raise error_for(OVERFLOW)
    return k & 0xFFFF


def port_value(port: int) -> int:
    """The byte a port reads (0..65535): 0 for the DMA controller's, else the floating bus."""
    return 0 if port in DMA_PORTS else FLOATING_BUS


class Devices:
    """The device words' state: the program's environment table and its file locks.

    ``files``: the machine's FileTable (machine/files.py), whose open files LOCK and
    IOCTL address."""

    def __init__(self, files):
        self.files = files
        # ENVIRON's table, name -> value, in the order set; it starts empty: a program
        # never sees the host's environment (which may hold secrets and differs by host)
        self.table: dict[str, str] = {}

    # -- ports (GWEVAL.ASM FNINP, FNOUT, FNWAIT)
    @staticmethod
    def inp(port: float) -> float:
        """INP(port): the byte the port reads (a negative port is its two's complement)."""
        return float(port_value(_port(port)))

    # the game port and the light pen: nothing is attached, so a stick's coordinate is 0, a
    # trigger is never pressed and the pen never down, at the position (0, 0), on character
    # row and column 1 (PEN(6)..PEN(9): PC-BASIC 2.0.8; the recordings show the 0s); the
    # argument is a byte (ONESUB), then the routine's own range: STICK 0..3 (RDSTIK), STRIG
    # 0..7 (STRIGF: n/2 below the 4 triggers), PEN 0..9 (PENF)
    @staticmethod
    def stick(k: int) -> float:
        """STICK(k): a joystick's coordinate (0, 1: the first's x, y; 2, 3: the second's)."""
        if _byte(k) > 3:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        return 0.0

    @staticmethod
    def trigger(k: int) -> float:
        """STRIG(k): a trigger pressed since the last look (even k) or now (odd k)."""
        if _byte(k) >> 1 >= 4:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        return 0.0

    @staticmethod
    def pen(k: int) -> float:
        """PEN(k): the light pen's state or position (k 0..9)."""
        if _byte(k) > 9:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        return 1.0 if k >= 6 else 0.0

    @staticmethod
    def motor(k: int | None = None) -> None:
        """MOTOR [k]: the cassette's motor, on or off; there is none."""
        if k is not None:
            _byte(k)

    @staticmethod
    def out(port: float, byte: int) -> None:
        """OUT port, byte: checked (SETIO), then written to no device."""
        _port(port)
        _byte(byte)

    @staticmethod
    def wait(port: float, mask: int, flip: int = 0) -> None:
        """WAIT port, mask[, flip]: goes on once (byte XOR flip) AND mask is not 0; the ports
        never change here, so a WAIT that would not end at once would wait forever: the run
        ends naming it (GW-BASIC loops, FNWAIT's LOPINP)."""
        k = _port(port)
        _byte(mask)
        _byte(flip)
        if not (port_value(k) ^ flip) & mask:
            raise not_emulated(f"WAIT for port &H{k:X} to change (yaseer's ports never change)")

    # -- the printer
    @staticmethod
    def screen_copy(k: int = 0) -> None:
        """LCOPY [n]: n a byte (LCOPYS); GW-BASIC 3.23 for the IBM PC copies nothing."""
        _byte(k)

    # -- device drivers and DOS
    def control(self, n: int, _control: str) -> None:
        """IOCTL #n, s$: file n must be open; a disk file has no control channel."""
        self.control_file(n)
        raise error_for(ILLEGAL_FUNCTION_CALL)

    def control_file(self, n) -> None:
        """The check of IOCTL's and IOCTL$'s file: n must be an open file (Bad file number)."""
        self.files.get(n)

    def open_file_number(self, number):
        """``number`` as IOCTL$ reads its file's number: a number (else Type mismatch), a
        byte (beyond an integer Overflow, outside 0..255 Illegal function call), an open
        file (:meth:`control_file`); the number itself is returned."""
        if isinstance(number, str):
            raise error_for(TYPE_MISMATCH)
        self.control_file(_byte(to_int(number)))
        return number

    def control_string(self, n: int) -> str:
        """IOCTL$([#]n): as IOCTL, n read as :meth:`open_file_number` reads it (its answer
        would come from the device's driver)."""
        self.control(self.open_file_number(n), "")
        return ""  # (never reached)

    @staticmethod
    def extended_error(k: int) -> float:
        """EXTERR(n), n 0..3: DOS's extended error information; yaseer makes no DOS call
        that fails, so every part is 0 (as PC-BASIC 2.0.8)."""
        if not 0 <= k <= 3:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        return 0.0

    def environment(self, key) -> str:
        """ENVIRON$(name) the value of name (any case; "" if unset; name "" Illegal function
        call), ENVIRON$(n) the n-th entry ``NAME=value`` (n 1..255, "" past the last)."""
        if isinstance(key, str):
            if not key:
                raise error_for(ILLEGAL_FUNCTION_CALL)
            return self.table.get(key.upper(), "")
        k = cint(key)
        if not -32768 <= k <= 32767:
            raise error_for(OVERFLOW)
        if not 1 <= k <= 255:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        entries = list(self.table.items())
        return f"{entries[k - 1][0]}={entries[k - 1][1]}" if k <= len(entries) else ""

    def set_environment(self, entry: str) -> None:
        """ENVIRON "NAME=value": sets NAME (made upper case); an empty value removes it; no
        ``=`` or no name is Illegal function call."""
        name, equals, value = entry.partition("=")
        if not equals or not name:
            raise error_for(ILLEGAL_FUNCTION_CALL)
        name = name.upper()
        self.table.pop(name, None)
        if value:
            self.table[name] = value

    # -- machine code (CALL86.ASM)
    @staticmethod
    def call(_routine) -> None:
        """CALL/CALLS routine[(variables)]: would jump to machine code in memory."""
        raise not_emulated("CALL of a machine-code routine")

    # -- file locks (DOS's, as SHARE keeps them: machine/file_locks.py)
    def _ranges(self, n: int, start, end) -> tuple[object, tuple[int, int]]:
        """The sharing of open file n (file_locks.Sharing, whose ``ranges`` its locks are)
        and the bytes a LOCK or UNLOCK names: a sequential file is locked whole, a random
        file by records from start to end (start alone: that record; neither: the whole
        file), each record its length of bytes."""
        f = self.files.get(n)
        if f.sharing is type(f).sharing:  # a device or a file no OPEN made: a sharing of its own
            f.sharing = file_locks.Sharing(None, None, list)
        if f.mode != "R" or start is None:
            first, last = WHOLE_FILE
        else:
            first = cint(start)
            last = first if end is None else cint(end)
            if not (1 <= first <= LAST_RECORD and 1 <= last <= LAST_RECORD):
                raise error_for(BAD_RECORD_NUMBER)
        size = f.length_of_record if f.mode == "R" else 1
        return f.sharing, ((first - 1) * size, last * size)

    def lock(self, n: int, start=None, end=None) -> None:
        """LOCK [#]n[, start[ TO end]]: a range that meets one locked already, by this file
        or another opening of it, is Permission Denied (the recordings: ``LOCK 1: LOCK 1``,
        and a second OPEN of a file locked by the first, PC-BASIC's LockFiles test)."""
        sharing, wanted = self._ranges(n, start, end)
        if any(file_locks.overlap(wanted, held) for other in [sharing, *sharing.others()] for held in other.ranges):
            raise error_for(PERMISSION_DENIED)
        sharing.ranges.append(wanted)

    def unlock(self, n: int, start=None, end=None) -> None:
        """UNLOCK [#]n[, start[ TO end]]: only a range locked exactly so is unlocked, else
        Permission Denied."""
        sharing, wanted = self._ranges(n, start, end)
        if wanted not in sharing.ranges:
            raise error_for(PERMISSION_DENIED)
        sharing.ranges.remove(wanted)
