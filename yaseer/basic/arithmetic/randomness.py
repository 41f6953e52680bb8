"""RND and RANDOMIZE: one generator per dialect, each with the same small interface.

``rnd(x)`` is BASIC's ``RND(x)``: x > 0 (or no argument) the next number in [0, 1),
x = 0 the last one again, x < 0 reseeds from x first; ``drawer()`` a callable that
draws the next number as fast as the generator can (RND(x) with a constant x > 0).
``randomize(value, kind)``
is ``RANDOMIZE value`` where ``kind`` is the value's BASIC type (``"%"`` integer,
``"!"`` single, ``"#"`` double), because GW-BASIC reseeds from the bytes the value
is stored in.  ``reset()`` is what RUN does.

* :class:`RepeatableRandom` (the Casio dialect): Python's Mersenne Twister, seeded
  with 0 at every RUN, so a run is repeatable.
* :class:`GwRandom` (the GW dialect): GW-BASIC 3.23's own generator, as PC-BASIC
  2.0.8 documents and reproduces it: a 24-bit linear congruential generator
  ``s = (214013 s + 2531011) mod 2**24`` whose value is ``s / 2**24`` (exact in
  single precision), starting at ``s = 0x4FC752`` at RUN.
"""

from __future__ import annotations

import math
import struct

_PERIOD = 1 << 24
_MULTIPLIER = 214013
_INCREMENT = 2531011
_START = 0x4FC752  # the state GW-BASIC starts every RUN from
_RESEED_STRIDE = 0x43FD00  # RANDOMIZE n moves the state by n times this


class RepeatableRandom:
    """The Casio dialect's RND: Mersenne Twister, seed 0 at RUN (no Casio sequence is documented).

    The compiled code draws ``RND`` and ``RND(x)`` with a constant x > 0 through
    :meth:`drawer`, the generator's own C method, which records nothing; so RND(0)
    reads the last number back from the generator's state (:func:`last_drawn`).
    """

    seed_prompt = None  # RANDOMIZE alone seeds from the system

    def __init__(self) -> None:
        self._seeded = None  # made at the first RND or RANDOMIZE: a run without them never imports random
        self.reset()

    def reset(self) -> None:
        """RUN: seed 0 again (a generator once made is kept, so :meth:`drawer`'s method stays valid)."""
        if self._seeded is not None:
            self._seeded.seed(0)
        self._mark(0.0)

    def _mark(self, last: float) -> None:
        """Note the state right after a seeding and the last number then (RND(0) before any draw)."""
        self._seed_state = None if self._seeded is None else self._seeded.getstate()
        self._seed_last = last

    @property
    def _generator(self):
        """The Mersenne Twister, seeded with 0 when first needed."""
        if self._seeded is None:
            import random
            self._seeded = random.Random(0)
            self._mark(self._seed_last)
        return self._seeded

    def drawer(self):
        """The callable that draws the next number (RND(x), x > 0)."""
        return self._generator.random

    def last(self) -> float:
        """The number RND last gave (0.0 after RUN before any; after RANDOMIZE the one before it)."""
        if self._seeded is None:
            return self._seed_last
        state = self._seeded.getstate()
        if state == self._seed_state:
            return self._seed_last
        return last_drawn(state)

    def rnd(self, x: float = 1.0) -> float:
        if x < 0:
            self._generator.seed(x)
        if x != 0:
            return self._generator.random()
        return self.last()

    def randomize(self, value, kind: str = "!") -> None:
        """RANDOMIZE value; ``None`` (RANDOMIZE alone) seeds from the system."""
        last = self.last()
        self._generator.seed(value)
        self._mark(last)


def _tempered(y: int) -> int:
    """The Mersenne Twister's tempering of one state word (its output)."""
    y ^= y >> 11
    y ^= (y << 7) & 0x9D2C5680
    y ^= (y << 15) & 0xEFC60000
    return y ^ (y >> 18)


def last_drawn(state: tuple) -> float:
    """The number ``random.Random.random`` returned last, from ``getstate()`` after it.

    CPython's ``random()`` takes two 32-bit outputs, a >> 5 and b >> 6, and returns
    (a * 2**26 + b) / 2**53; outputs are the tempered state words, taken in order
    from index 0 after each regeneration of all 624 (an even number: the two words of
    one number are never split by a regeneration, so the index is >= 2 after any draw).
    """
    words = state[1]
    index = words[-1]
    a, b = _tempered(words[index - 2]) >> 5, _tempered(words[index - 1]) >> 6
    return (a * 67108864.0 + b) * (1.0 / 9007199254740992.0)


class GwRandom:
    """GW-BASIC's RND (see the module docstring); ``state`` is the 24-bit state."""

    # RANDOMIZE alone asks for the seed (an integer) with this prompt
    seed_prompt = "Random number seed (-32768 to 32767)? "

    def __init__(self) -> None:
        self.reset()

    def reset(self) -> None:
        self.state = _START

    def _advance(self) -> None:
        self.state = (self.state * _MULTIPLIER + _INCREMENT) % _PERIOD

    def drawer(self):
        """The callable that draws the next number (RND(x), x > 0)."""
        return self.rnd

    def rnd(self, x: float = 1.0) -> float:
        if x < 0:
            # the 24-bit mantissa of x as a single (hidden bit included); the exponent is
            # ignored, so RND(-1), RND(-2) and RND(-0.5) start the same sequence
            self.state = single_mantissa(x)
        if x != 0:  # (the step of _advance, written out: this is the common path)
            self.state = (self.state * _MULTIPLIER + _INCREMENT) % _PERIOD
        return self.state / _PERIOD

    def randomize(self, value, kind: str = "!") -> None:
        """RANDOMIZE value: keep the state's low byte, step once, add n * 0x43FD00.

        n is the signed 16-bit number GW-BASIC reads from the value's stored bytes:
        an integer's two bytes; for a single or double (Microsoft Binary Format) the
        last two bytes XOR the two before them.
        """
        n = seed_word(value, kind)
        self.state &= 0xFF
        self._advance()
        self.state = (self.state + n * _RESEED_STRIDE) % _PERIOD


def single_mantissa(x: float) -> int:
    """|mantissa| of x rounded to single precision, as a 24-bit integer (2**23 .. 2**24-1)."""
    single = struct.unpack("<f", struct.pack("<f", x))[0]
    if single == 0:
        return 0
    fraction, _ = math.frexp(abs(single))  # in [0.5, 1)
    return int(fraction * _PERIOD)


def mbf_bytes(value: float, kind: str) -> bytes:
    """``value`` in Microsoft Binary Format: mantissa bytes low first, sign in the top
    mantissa bit (in place of the hidden bit), then the exponent byte (bias 128, the
    mantissa read as 0.1xxx binary); zero is all zero bytes.  ``kind``: "!" 4 bytes
    (24-bit mantissa), "#" 8 bytes (56-bit mantissa)."""
    size = 4 if kind == "!" else 8
    if kind == "!":
        value = struct.unpack("<f", struct.pack("<f", value))[0]
    if value == 0:
        return bytes(size)
    bits = 8 * (size - 1)
    fraction, exponent = math.frexp(abs(value))
    mantissa = int(fraction * (1 << bits))  # exact: the value has at most `bits` bits
    if mantissa >> bits:  # cannot happen for frexp's fraction < 1, kept for safety
        mantissa >>= 1
        exponent += 1
    mantissa &= (1 << (bits - 1)) - 1
    if value < 0:
        mantissa |= 1 << (bits - 1)
    return mantissa.to_bytes(size - 1, "little") + bytes([(exponent + 128) & 0xFF])


def seed_word(value, kind: str) -> int:
    """The signed 16-bit number RANDOMIZE reads from ``value`` stored as ``kind``."""
    if kind == "%":
        word = int(value) & 0xFFFF
    else:
        stored = mbf_bytes(float(value), kind)
        low, high = stored[-2] ^ stored[-4], stored[-1] ^ stored[-3]
        word = low | (high << 8)
    return word - 0x10000 if word & 0x8000 else word
