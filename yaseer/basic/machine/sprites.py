"""GET and PUT of graphics: a rectangle of pixels kept in a numeric array as GW keeps it.

The array's bytes (each element's as MKI$, MKS$ or MKD$ makes them, from the element
named or the first) hold a 4-byte header, then the rows:

* CGA modes (1 and 2: 2 and 1 bits a pixel): the row's width in bits and the height (two
  16-bit words, low byte first), then each row's pixels packed from the highest bit, a row
  starting on a new byte;
* EGA modes (7, 8, 9: 4 planes): the width in pixels and the height, then for each row the
  bits of plane 0, 1, 2, 3 in turn, each packed so (8 pixels a byte).

(The layout of the recorded GET, GET2, GET3 and PUT tests, files written by a real GW-BASIC
3.23; PC-BASIC 2.0.8 packs them the same way.)
"""

from __future__ import annotations

from yaseer.basic.errors import BasicError, TYPE_MISMATCH
from yaseer.basic.machine import gwfunctions
from yaseer.basic.machine.runtime import illegal_function_call

_SIZES = {"%": 2, "!": 4, "#": 8}


class _Flat:
    """An array's elements in the order GW's memory holds them (the first subscript runs
    fastest), over the nested lists the machine keeps; under OPTION BASE 1 (``base``) each
    list's unused entry 0 is not one of them (as data_segment lays arrays out)."""

    def __init__(self, values: list, base: int):
        dims = []
        level = values
        while isinstance(level, list):
            dims.append(len(level) - base)
            level = level[base] if len(level) > base else None
        self.nested = values
        self.dims = dims
        self.base = base

    def __len__(self) -> int:
        count = 1
        for d in self.dims:
            count *= d
        return count

    def flat_index(self, indices: list) -> int:
        k, scale = 0, 1
        for i, d in zip(indices, self.dims):
            k += i * scale
            scale *= d
        return k

    def _place(self, k: int):
        indices = []
        for d in self.dims:
            indices.append(k % d + self.base)
            k //= d
        holder = self.nested
        for i in indices[:-1]:
            holder = holder[i]
        return holder, indices[-1]

    def __getitem__(self, k: int):
        holder, i = self._place(k)
        return holder[i]

    def __setitem__(self, k: int, value) -> None:
        holder, i = self._place(k)
        holder[i] = value


class _ArrayBytes:
    """The bytes of a numeric array from one element on (``(name, subscripts)`` as the
    compiled code passes them: subscripts None for the first element)."""

    def __init__(self, machine, reference):
        name, subscripts = reference
        if name.endswith("$"):
            raise BasicError("Type mismatch", TYPE_MISMATCH)
        arrays = machine.arrays
        if name not in arrays:
            if subscripts is None:
                raise illegal_function_call()
            machine.array_nd(name, len(subscripts))
        base = machine.subscript_base
        self.values = _Flat(arrays[name], base)
        self.size = _SIZES.get(name[-1], 4)
        self.kind = name[-1]
        if subscripts is None:
            start = 0
        else:
            indices = [int(i) - base for i in subscripts]
            if len(indices) != len(self.values.dims) or any(
                    not 0 <= i < d for i, d in zip(indices, self.values.dims)):
                raise illegal_function_call()
            start = self.values.flat_index(indices)
        self.start = start

    def capacity(self) -> int:
        return (len(self.values) - self.start) * self.size

    def _element_bytes(self, k: int) -> bytes:
        value = self.values[k]
        text = {"%": gwfunctions.mki, "!": gwfunctions.mks, "#": gwfunctions.mkd}[self.kind](value)
        return bytes(ord(c) for c in text)

    def read(self, count: int) -> bytes:
        """The first ``count`` bytes (fewer where the array ends)."""
        out = bytearray()
        k = self.start
        while len(out) < count and k < len(self.values):
            out += self._element_bytes(k)
            k += 1
        return bytes(out[:count])

    def write(self, data: bytes) -> None:
        """``data`` over the first bytes (the last element touched keeps its other bytes)."""
        size = self.size
        for n in range((len(data) + size - 1) // size):
            k = self.start + n
            chunk = data[n * size:(n + 1) * size]
            if len(chunk) < size:
                chunk = chunk + self._element_bytes(k)[len(chunk):]
            text = "".join(map(chr, chunk))
            if self.kind == "%":
                self.values[k] = int(gwfunctions.cvi(text))
            elif self.kind == "!":
                self.values[k] = gwfunctions.cvs(text)
            else:
                self.values[k] = gwfunctions.cvd(text)


def array_values(machine, reference, count: int) -> list:
    """The first ``count`` values of an integer array from the element named (PALETTE
    USING): fewer elements than ``count`` Illegal function call."""
    array = _ArrayBytes(machine, reference)
    if array.kind != "%":
        raise BasicError("Type mismatch", TYPE_MISMATCH)
    if len(array.values) - array.start < count:
        raise illegal_function_call()
    return [int(array.values[k]) for k in range(array.start, array.start + count)]


def pack(canvas, x0: int, y0: int, width: int, height: int) -> bytes:
    """The rectangle at view point (x0, y0) as GET stores it (the module docstring)."""
    bits = canvas.bits
    pixel = canvas.get_pixel
    out = bytearray()
    if bits == 4:
        out += width.to_bytes(2, "little") + height.to_bytes(2, "little")
        for y in range(y0, y0 + height):
            row = [pixel(x, y) for x in range(x0, x0 + width)]
            for plane in range(4):
                out += _packed([(p >> plane) & 1 for p in row], 1)
    else:
        out += (width * bits).to_bytes(2, "little") + height.to_bytes(2, "little")
        for y in range(y0, y0 + height):
            out += _packed([pixel(x, y) for x in range(x0, x0 + width)], bits)
    return bytes(out)


def _packed(values: list, bits: int) -> bytes:
    """``values`` of ``bits`` bits each, packed from each byte's highest bits."""
    per = 8 // bits
    out = bytearray()
    for k in range(0, len(values), per):
        byte = 0
        for j, v in enumerate(values[k:k + per]):
            byte |= (v & ((1 << bits) - 1)) << (8 - bits * (j + 1))
        out.append(byte)
    return bytes(out)


def _unpacked(data: bytes, count: int, bits: int) -> list:
    per = 8 // bits
    mask = (1 << bits) - 1
    return [(data[k // per] >> (8 - bits * (k % per + 1))) & mask for k in range(count)]


def unpack(canvas, data: bytes) -> tuple[int, int, list]:
    """(width, height, rows of attributes) of a GET's bytes."""
    bits = canvas.bits
    first, height = int.from_bytes(data[0:2], "little"), int.from_bytes(data[2:4], "little")
    at = 4
    rows = []
    if bits == 4:
        width = first
        row_bytes = (width + 7) // 8
        for _ in range(height):
            row = [0] * width
            for plane in range(4):
                for x, bit in enumerate(_unpacked(data[at:at + row_bytes], width, 1)):
                    row[x] |= bit << plane
                at += row_bytes
            rows.append(row)
    else:
        width = first // bits
        row_bytes = (width * bits + 7) // 8
        for _ in range(height):
            rows.append(_unpacked(data[at:at + row_bytes], width, bits))
            at += row_bytes
    return width, height, rows


def get_sprite(machine, canvas, first, second, reference) -> None:
    """GET: the rectangle between view points ``first`` and ``second`` (both inside the
    view, else Illegal function call) into the array (too small: Illegal function call)."""
    array = _ArrayBytes(machine, reference)
    (xa, ya), (xb, yb) = first, second
    x0, x1, y0, y1 = min(xa, xb), max(xa, xb), min(ya, yb), max(ya, yb)
    if not (canvas.inside_view(x0, y0) and canvas.inside_view(x1, y1)):
        raise illegal_function_call()
    data = pack(canvas, x0, y0, x1 - x0 + 1, y1 - y0 + 1)
    if len(data) > array.capacity():
        raise illegal_function_call()
    array.write(data)


def put_sprite(machine, canvas, point, reference, action: str) -> None:
    """PUT: the array's rectangle with its top left corner at view point ``point``, the
    whole of it inside the view (else Illegal function call), each pixel as ``action``
    says: PSET the array's, PRESET its complement, AND, OR, XOR with the screen's."""
    array = _ArrayBytes(machine, reference)
    header = array.read(4)
    if len(header) < 4:
        raise illegal_function_call()
    bits = canvas.bits
    first, height = int.from_bytes(header[0:2], "little"), int.from_bytes(header[2:4], "little")
    width = first if bits == 4 else first // bits
    row_bytes = (width + 7) // 8 * 4 if bits == 4 else (width * bits + 7) // 8
    data = array.read(4 + row_bytes * height)
    x0, y0 = point
    if not (canvas.inside_view(x0, y0) and canvas.inside_view(x0 + width - 1, y0 + height - 1)):
        raise illegal_function_call()  # (an empty array's corners too: PC-BASIC 2.0.8)
    if width == 0 or height == 0:
        return
    if len(data) < 4 + row_bytes * height:
        raise illegal_function_call()
    _, _, rows = unpack(canvas, data)
    top = canvas.colours - 1
    for dy, row in enumerate(rows):
        y = y0 + dy
        for dx, value in enumerate(row):
            x = x0 + dx
            if action == "PSET":
                new = value
            elif action == "PRESET":
                new = value ^ top
            else:
                old = canvas.get_pixel(x, y)
                new = old & value if action == "AND" else old | value if action == "OR" else old ^ value
            canvas.set_pixel(x, y, new & top)
