"""A graphics mode's pixels as the adapter's memory holds them, for PEEK, POKE, BSAVE and
BLOAD (machine/address_space.py asks here first while a graphics mode is on).

* CGA modes 1 and 2 (&HB800, 16 KB): the even rows from offset 0, the odd rows from
  &H2000, 80 bytes a row, the pixels of a byte from its highest bits (4 of 2 bits in mode
  1, 8 of 1 bit in mode 2);
* EGA modes 7, 8 and 9 (&HA000): four planes at the same addresses, ``width / 8`` bytes a
  row, one bit a pixel from the highest, plane p holding bit p of each attribute; the
  pages one after another (8 KB, 16 KB and 32 KB each).  A read sees plane 0 and a write
  goes to all four planes (the graphics controller as the BIOS leaves it: read map 0, map
  mask 15; OUT to its ports is not emulated).

The layouts are IBM's adapters' (as PC-BASIC 2.0.8 maps them too).  Units: byte offsets.
"""

from __future__ import annotations

CGA_BASE = 0xB8000
EGA_BASE = 0xA0000
CGA_BANK = 0x2000


def _ega_page(canvas) -> int:
    """An EGA page's bytes: 8 KB in 320x200, 16 KB in 640x200, 32 KB in 640x350."""
    if canvas.width == 320:
        return 0x2000
    return 0x4000 if canvas.height == 200 else 0x8000


def covers(canvas, address: int) -> bool:
    """Whether 20-bit ``address`` is in the mode's memory (its pixels' bytes and the unused
    bytes after each CGA bank's rows, which hold what was written there)."""
    if canvas.bits == 4:
        return 0 <= address - EGA_BASE < _ega_page(canvas) * len(canvas.pages)
    return 0 <= address - CGA_BASE < 2 * CGA_BANK


def locate(canvas, address: int):
    """(page, first pixel's x, y, pixels in the byte) for 20-bit ``address`` in the mode's
    memory; None outside it (or in a bank's bytes past its rows)."""
    if canvas.bits == 4:
        size = _ega_page(canvas)
        offset = address - EGA_BASE
        if not 0 <= offset < size * len(canvas.pages):
            return None
        page, within = divmod(offset, size)
        row_bytes = canvas.width // 8
        y, column = divmod(within, row_bytes)
        if y >= canvas.height:
            return None
        return page, column * 8, y, 8
    offset = address - CGA_BASE
    if not 0 <= offset < 2 * CGA_BANK:
        return None
    bank, within = divmod(offset, CGA_BANK)
    row, column = divmod(within, 80)
    if row >= canvas.height // 2:
        return None
    per = 8 // canvas.bits
    return 0, column * per, row * 2 + bank, per


def read(canvas, where) -> int:
    """The byte at ``where`` (from :func:`locate`)."""
    page, x0, y, count = where
    pixels = canvas.pages[page]
    row = y * canvas.width
    byte = 0
    if canvas.bits == 4:
        for k in range(count):
            byte |= (pixels[row + x0 + k] & 1) << (7 - k)
        return byte
    bits = canvas.bits
    mask = (1 << bits) - 1
    for k in range(count):
        byte |= (pixels[row + x0 + k] & mask) << (8 - bits * (k + 1))
    return byte


def write(canvas, where, byte: int) -> None:
    """``byte`` written at ``where``: the pixels it covers (all four planes in EGA modes)."""
    page, x0, y, count = where
    pixels = canvas.pages[page]
    row = y * canvas.width
    if canvas.bits == 4:
        for k in range(count):
            pixels[row + x0 + k] = 15 if byte >> (7 - k) & 1 else 0
        return
    bits = canvas.bits
    mask = (1 << bits) - 1
    for k in range(count):
        pixels[row + x0 + k] = (byte >> (8 - bits * (k + 1))) & mask
