"""GW-BASIC's memory as PEEK and POKE reach it: the PC's 20-bit address space, as far as a
program can see it on yaseer's machine.

``PEEK(a)`` reads the byte at segment * 16 + a, ``POKE a, b`` writes one there; the segment
is the one ``DEF SEG`` set (GWEVAL.ASM DEF stores it in SAVSEG; at start and after a ``DEF
SEG`` without a number, BASIC's own data segment: ITSA86.ASM puts DS in SAVSEG).  The address
is an unsigned 16-bit number (GWMAIN.ASM PEEK and POKE read it with FRQINT: -32768..65535,
a negative one counting from 65536; beyond, Overflow); POKE's byte is GETBYT's (0..255, else
Illegal function call).  Units: addresses and segments are byte counts, segments in
paragraphs of 16 bytes.

What lies where (a colour PC, as the machine behind PC-BASIC's recordings had):

* the text screen's memory, 16 KB from the video segment (``ScreenRules.video_segment``,
  &HB800; the CGA's): the screen's pages one after another, each 4096 bytes at 80 columns
  and 2048 at 40 (the BIOS's page sizes), a cell two bytes, its character's code at the even
  offset and its colour attribute at the odd one, row by row.  Page 0 is yaseer's display
  (machine/display.py): PEEK reads its cells, POKE writes them, the key line included; the
  other pages are memory of their own, blank cells (32, 7) until POKEd, as a mode set
  leaves them (PC-BASIC 2.0.8 reads them so); the bytes past a page's cells read 0;
* BASIC's data segment (see :data:`DATA_SEGMENT`): its first bytes are those the
  recordings read (0, 0, 16, 130: PEEK(2) is 16 on the real machine; PC-BASIC 2.0.8 gives
  the four) and what POKE wrote; the files' blocks from :data:`FILE_BLOCKS` on, one for
  each file number 0..3 (GW's default /F:3 and /S:128), each a 6-byte header, the 188-byte
  file control block ``VARPTR(#n)`` points at (GIO86.ASM GETPTR: the FDB's F_MODE) and the
  128-byte FIELD buffer (FD_DAT): the addresses the recordings show (``VARPTR(#1)`` is 3757,
  file 1's buffer at 3945).  A random file's buffer bytes are its record buffer
  (machine/random_files.py): PEEK reads them, POKE writes them and the variables FIELDed
  over them see the byte, as GW's descriptors point into the buffer; the other bytes
  there, and a buffer no random file holds, read what POKE left, else 0;
* from the program up (machine/data_segment.py, laid out from the machine's state only
  when a program reads there or asks VARPTR of a variable): the program text, the simple
  variables, the arrays and the strings, and below, the pointers to them GW keeps at
  &H2C, &H30, &H358, &H35A and &H35C; ``VARPTR(v)`` is the address of v's value there
  (its descriptor for a string), ``VARPTR$(v)`` its type byte and that address as a
  3-character string (GWEVAL.ASM VARPTR); a variable not made yet is Illegal function
  call (PTRGET makes none for VARPTR), an array element's array is made as any use makes
  it, a subscript beyond it Subscript out of range.  A byte POKEd there is read back
  (the variables do not change);
* the rest of the PC's RAM (below &HA0000): what POKE wrote there, else 0 (yaseer does not
  model DOS, the BIOS's data or interrupt vectors; PC-BASIC 2.0.8 reads 0 where it models
  nothing);
* above: ROM and adapters yaseer does not have: 0, and POKE changes nothing.
"""

from __future__ import annotations

from yaseer.basic.machine import runtime
from yaseer.basic.errors import BAD_FILE_NUMBER, SUBSCRIPT_OUT_OF_RANGE, error_for

# BASIC's data segment (a paragraph number): where DEF SEG alone points, and what PEEK reads at
# start.  The real machine's, as PC-BASIC's recordings name it (its PEEK test presets a byte of
# segment 5037, &H13AD, the real run's data segment); nothing a program sees depends on the
# number itself but a DEF SEG that names it.
DATA_SEGMENT = 0x13AD
# The first bytes of the data segment (offset -> byte): what the real machine reads there.
DATA_SEGMENT_START = {0: 0, 1: 0, 2: 16, 3: 130}
# The files' blocks in the data segment (offsets; GW-BASIC 3.23's defaults /F:3, /S:128), as the
# recordings of the real machine place them: VARPTR(#0..#3) 3435, 3757, 4079, 4401.
FILE_BLOCKS = 3429  # file 0's block
FILE_HEADER = 6  # bytes before a file's control block
CONTROL_BLOCK = 188  # the control block's bytes before its FIELD buffer
BUFFER_BYTES = 128  # a FIELD buffer (/S:128)
BLOCK_BYTES = FILE_HEADER + CONTROL_BLOCK + BUFFER_BYTES  # 322
BLOCK_FILES = 4  # file 0 (the program's) and files 1..3
VIDEO_BYTES = 0x4000  # the colour adapter's 16 KB of text memory
PAGE_BYTES = {80: 4096, 40: 2048}  # a text page's size at each width (BIOS)
RAM_END = 0xA0000  # the PC's 640 KB of RAM end here; adapters and ROM above
BLANK_CELL = (32, 7)  # a cleared cell: a blank, white on black
ADDRESS_MASK = 0xFFFFF  # 20 bits: segment * 16 + offset wraps at 1 MB


class AddressSpace:
    """The memory PEEK and POKE see (module docstring).

    ``screen_model``: a callable giving the display (machine/display.py) brought up to date
    with what was printed (Console._screen_model); ``charset``: the machine's codes;
    ``video_segment``: the text screen's segment (None: no screen memory); ``files``: the
    machine's file table (machine/files.py); ``fields_changed(file)``: called after a POKE
    into random file ``file``'s buffer (the machine's FIELD variables take their slices);
    ``variables``: the machine whose variables the data segment holds (its
    ``data_layout()``, ``array_nd`` and ``subscript_base``; None: no variables there);
    ``canvas()``: the graphics mode's pixels (machine/graphics.py; None in a text mode), whose
    memory (machine/video_memory.py) comes before the text screen's."""

    def __init__(self, screen_model, charset, video_segment: int | None, files=None, fields_changed=None,
                 variables=None, canvas=None):
        self.variables = variables
        self.canvas = canvas  # a callable: the graphics mode's Canvas, None in a text mode
        self.screen_model = screen_model
        self.charset = charset
        self.files = files
        self.fields_changed = fields_changed
        self.video = None if video_segment is None else video_segment * 16
        self.segment = DATA_SEGMENT
        self.ram: dict[int, int] = {}  # 20-bit address -> the byte POKE left there

    def define_segment(self, segment: int | None) -> None:
        """DEF SEG [= s]: s (a paragraph number, 0..65535), or BASIC's data segment."""
        self.segment = DATA_SEGMENT if segment is None else segment

    def peek(self, offset: float) -> float:
        """PEEK(offset): the byte at the segment's ``offset`` (FRQINT: -32768..65535)."""
        return float(self.read(self._address(offset)))

    def poke(self, offset: float, byte: int) -> None:
        """POKE offset, byte: offset as PEEK's, then the byte 0..255 (GETBYT)."""
        where = self._address(offset)
        self.write(where, runtime.byte_argument(byte))

    def binary_save(self, name: str, offset: float, length: float) -> None:
        """BSAVE "file", offset, length: ``length`` bytes from the segment's ``offset`` (both
        FRQINT's) into the file after a 7-byte header (&HFD, the segment, the offset, the
        length: words, low byte first) and ended by &H1A (the recorded BSAVE files)."""
        start, count = runtime.unsigned_word(offset), runtime.unsigned_word(length)
        base = self.segment * 16
        data = bytes(self.read((base + start + k) & ADDRESS_MASK) for k in range(count))
        header = bytes([0xFD]) + b"".join(n.to_bytes(2, "little") for n in (self.segment, start, count))
        sandbox = self.files.sandbox
        sandbox.write_bytes(sandbox.dos_name(self.files._local_name(name)), header + data + b"\x1a")

    def binary_load(self, name: str, offset: float | None = None) -> None:
        """BLOAD "file"[, offset]: a BSAVE file's bytes back where they came from, or from
        the segment's ``offset``; a file without BSAVE's first byte Bad file mode."""
        from yaseer.basic.errors import BAD_FILE_MODE

        sandbox = self.files.sandbox
        data = sandbox.read_bytes(sandbox.dos_name(self.files._local_name(name)))
        if len(data) < 7 or data[0] != 0xFD:
            raise error_for(BAD_FILE_MODE)
        segment, start, count = (int.from_bytes(data[k:k + 2], "little") for k in (1, 3, 5))
        if offset is not None:
            segment, start = self.segment, runtime.unsigned_word(offset)
        for k, byte in enumerate(data[7:7 + count]):
            self.write((segment * 16 + start + k) & ADDRESS_MASK, byte)

    def file_pointer(self, number: float) -> float:
        """VARPTR(#n): the offset of file n's control block in the data segment, n a byte
        (GTBYTC: 0..255, else Illegal function call) naming one of the blocks (0..3, open or
        not, as the recordings show; beyond, Bad file number: GETPTR's ERFNO3)."""
        n = runtime.byte_argument(runtime.cint(number))
        if n >= BLOCK_FILES:
            raise error_for(BAD_FILE_NUMBER)
        return float(FILE_BLOCKS + n * BLOCK_BYTES + FILE_HEADER)

    def variable_pointer(self, name: str, subscripts: tuple = ()) -> float:
        """VARPTR(variable): the offset of its value in the data segment (``name`` the full
        name, ``subscripts`` an element's, not yet checked)."""
        return float(self._variable_address(name, subscripts)[0])

    def variable_pointer_string(self, name: str, subscripts: tuple = ()) -> str:
        """VARPTR$(variable): its type byte (the value's size) and its offset, low byte first."""
        address, size = self._variable_address(name, subscripts)
        return chr(size) + chr(address & 0xFF) + chr(address >> 8)

    def _variable_address(self, name: str, subscripts: tuple) -> tuple[int, int]:
        from yaseer.basic.machine.data_segment import TYPE_BYTES, type_of

        machine = self.variables
        if subscripts:
            indices = tuple(runtime.subscript_integer(x) for x in subscripts)
            machine.array_nd(name, len(indices))  # (an array used without DIM is made)
            counts = tuple(d + 1 for d in machine.held_dims()[name])
            base = machine.subscript_base
            if len(counts) != len(indices) or any(not base <= i < c + base for i, c in zip(indices, counts)):
                raise error_for(SUBSCRIPT_OUT_OF_RANGE)
            address = machine.data_layout().element(name, indices, base)
        else:
            address = machine.data_layout().scalars.get(name)
            if address is None:  # (not made: PTRGET returns no variable to VARPTR)
                raise runtime.illegal_function_call()
        return address, TYPE_BYTES[type_of(name)]

    def _address(self, offset: float) -> int:
        return (self.segment * 16 + runtime.unsigned_word(offset)) & ADDRESS_MASK

    # ------------------------------------------------------------ bytes by address
    def _graphics(self, address: int):
        """(video_memory, the Canvas, where) for an address in a graphics mode's memory (where
        None for a byte no pixel shows), else None."""
        canvas = self.canvas() if self.canvas is not None else None
        if canvas is None:
            return None
        from yaseer.basic.machine import video_memory  # (only programs that draw)

        if not video_memory.covers(canvas, address):
            return None
        return video_memory, canvas, video_memory.locate(canvas, address)

    def read(self, address: int) -> int:
        """The byte at 20-bit ``address``."""
        graphics = self._graphics(address)
        if graphics is not None:
            memory, canvas, where = graphics
            return self.ram.get(address, 0) if where is None else memory.read(canvas, where)
        video = self._video_cell(address)
        if video is not None:
            return self._read_video(address, video)
        buffer = self._field_byte(address)
        if buffer is not None:
            file, k = buffer
            return file.buffer[k]
        if address in self.ram:
            return self.ram[address]
        data = address - DATA_SEGMENT * 16
        if data in DATA_SEGMENT_START:
            return DATA_SEGMENT_START[data]
        if self.variables is not None and 0 <= data < 0x10000 and not 0 <= data - FILE_BLOCKS < BLOCK_FILES * BLOCK_BYTES:
            from yaseer.basic.machine.data_segment import in_layout

            if in_layout(data, self.variables.dialect.data_segment):
                return self.variables.data_layout().byte(data)
        return 0

    def write(self, address: int, byte: int) -> None:
        """Put ``byte`` at 20-bit ``address`` (ROM and absent adapters keep theirs)."""
        graphics = self._graphics(address)
        if graphics is not None:
            memory, canvas, where = graphics
            if where is None:  # a bank's bytes past its rows: memory no pixel shows
                self.ram[address] = byte
            else:
                memory.write(canvas, where, byte)
            return
        video = self._video_cell(address)
        buffer = None if video is not None else self._field_byte(address)
        if video is not None:
            self._write_video(address, video, byte)
        elif buffer is not None:
            file, k = buffer
            file.buffer[k] = byte
            if self.fields_changed is not None:
                self.fields_changed(file)
        elif address < RAM_END:
            self.ram[address] = byte

    # ------------------------------------------------------------ the files' FIELD buffers
    def _field_byte(self, address: int):
        """(the random file, the byte's index in its record buffer) for an address in an open
        random file's FIELD buffer; None elsewhere."""
        offset = address - DATA_SEGMENT * 16 - FILE_BLOCKS
        if self.files is None or not 0 <= offset < BLOCK_FILES * BLOCK_BYTES:
            return None
        n, k = divmod(offset, BLOCK_BYTES)
        k -= FILE_HEADER + CONTROL_BLOCK
        file = self.files.open_files.get(n)
        buffer = getattr(file, "buffer", None)  # (a random file's; a sequential file has none here)
        if buffer is None or not 0 <= k < len(buffer):
            return None
        return file, k

    # ------------------------------------------------------------ the text screen's memory
    def _video_cell(self, address: int):
        """(page, cell number, attribute byte?) for an address in the screen's memory, the
        cell None past the page's cells; None outside the screen's memory."""
        if self.video is None or not 0 <= address - self.video < VIDEO_BYTES:
            return None
        display = self.screen_model()
        size = PAGE_BYTES.get(display.columns, 4096)
        page, offset = divmod(address - self.video, size)
        cell = offset // 2 if offset < display.columns * display.rows * 2 else None
        return page, cell, offset % 2

    def _read_video(self, address: int, where) -> int:
        page, cell, odd = where
        if cell is None:
            return self.ram.get(address, 0)
        if page:
            return self.ram.get(address, BLANK_CELL[odd])
        display = self.screen_model()
        x, y = cell % display.columns, cell // display.columns
        if odd:
            return display.attr_at(x, y)
        return ord(self.charset.codes(display.char_at(x, y))[0])

    def _write_video(self, address: int, where, byte: int) -> None:
        page, cell, odd = where
        if page or cell is None:
            self.ram[address] = byte
            return
        display = self.screen_model()
        display.poke_cell(cell % display.columns, cell // display.columns, byte, odd)
