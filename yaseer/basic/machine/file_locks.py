"""OPEN's ACCESS and LOCK clauses: who may open a file that is open already, and what an
open file may do (GW-BASIC 3.23's rules for files shared on a network, as DOS's SHARE keeps
them).

The released GW-BASIC source has no ACCESS or LOCK clause (they came with 3.2's network
support); these rules are what a real GW-BASIC 3.23 did, as PC-BASIC's recorded tests show
(tests/basic/unsorted/OPEN2, LockOPEN, LockOpenShared, LockFiles, LockFilesOutput,
LockOpenAllRANDOM: each error code and line written by the real machine), and as PC-BASIC
2.0.8 reproduces them.

An open file has an ``access`` (None: not given; "R", "W" or "RW") and a ``lock`` (None: DOS's
compatibility mode, no clause; "SHARED"; "R", "W" or "RW": what it denies the others).  A
file opened with a lock but no access has "RW" for the files opened after it (the check of
its own opening saw none: the real machine's order).
"""

from __future__ import annotations

from yaseer.basic.errors import PATH_FILE_ACCESS_ERROR, PERMISSION_DENIED, error_for


class Sharing:
    """One open file's clauses, the byte ranges its LOCK statements hold (``ranges``: (first
    byte, byte after the last)), and the other open files of the same file (``others``: a
    callable giving their :class:`Sharing`)."""

    __slots__ = ("access", "lock", "others", "ranges")

    def __init__(self, access: str | None, lock: str | None, others):
        self.access = "RW" if lock is not None and access is None else access
        self.lock = lock
        self.others = others
        self.ranges: list[tuple[int, int]] = []

    def use(self, right: str, span: tuple[int, int] | None = None) -> None:
        """A read ("R": GET, INPUT #, LINE INPUT #, INPUT$) or a write ("W": PUT, PRINT #,
        WRITE #) of this file: ``Path/File access error`` where its own ACCESS leaves the
        right out or another opening of the file LOCKs it (a file opened without clauses
        shares with no file that has them: nothing to check); then, of the bytes ``span``
        (first, after the last; None or empty: none), ``Permission Denied`` where another
        opening's LOCK holds one (DOS's SHARE refuses a handle the region another handle
        locked: a real GW-BASIC 3.23's GET and PUT in PC-BASIC's LockFiles and
        LockFilesOutput tests; a GET of bytes beyond the file's end reads none of them)."""
        if self.access is not None or self.lock is not None:
            if self.access is not None and right not in self.access:
                raise error_for(PATH_FILE_ACCESS_ERROR)
            if any(other.lock not in (None, "SHARED") and right in other.lock for other in self.others()):
                raise error_for(PATH_FILE_ACCESS_ERROR)
        if span is not None and span[0] < span[1] and any(
                overlap(span, held) for other in self.others() for held in other.ranges):
            raise error_for(PERMISSION_DENIED)


def overlap(one: tuple[int, int], other: tuple[int, int]) -> bool:
    """Do the byte ranges ``one`` and ``other`` (first, after the last) share a byte?"""
    return one[0] < other[1] and other[0] < one[1]


def check_opening(access: str | None, lock: str | None, others: list[Sharing]) -> None:
    """An OPEN with ``access`` and ``lock`` of a file open already as ``others``: ``Permission
    denied`` where one refuses the other: a file opened without a clause and one opened with
    one never share; LOCK READ WRITE shares with nobody; LOCK READ or WRITE refuses a file
    open with that access, and a file open with LOCK READ or WRITE refuses an opening asking
    that access (one asking none is refused by LOCK READ WRITE only)."""
    for other in others:
        if (lock is None) != (other.lock is None) or lock == "RW":
            raise error_for(PERMISSION_DENIED)
        if lock not in (None, "SHARED") and other.access is not None and _meet(lock, other.access):
            raise error_for(PERMISSION_DENIED)
        if other.lock not in (None, "SHARED") and (_meet(other.lock, access) if access else other.lock == "RW"):
            raise error_for(PERMISSION_DENIED)


def _meet(rights: str, wanted: str) -> bool:
    """Do the rights ``rights`` and ``wanted`` ("R", "W", "RW") have one in common?"""
    return any(right in wanted for right in rights)
