"""The words GW-BASIC 3.23 reserves: the one table that says which names are not names.

In both dialects a word of this table is never read as a variable or an array.
A word the dialect implements is a keyword of its scanner and never reaches this
module; one it does not implement yet reaches the parser as a name, and
:func:`mark_unsupported` turns it into an ``UNSUPPORTED`` token, so the statement
holding it stops with ``Unsupported word HEX$ in 10`` when it runs (instead of
``HEX$(10)`` silently reading an array).  Implementing a word (adding it to the
scanner's keywords) is all it takes to lift it from this check.

The list is the reserved-word appendix of the GW-BASIC 3.23 user's guide, the
keywords of Microsoft's tokeniser tables (GWDATA.ASM / IBMRES.ASM), cross-checked
against PC-BASIC 2.0.8's keyword table in tests/test_reserved.py.  ``TAB(`` and
``SPC(`` are listed without the parenthesis; ``$`` words that GW tokenises as a
keyword followed by ``$`` (``INPUT$``, ``ENVIRON$`` ...) are listed whole because a
name is read with its ``$``.
"""

from __future__ import annotations

GW_RESERVED_WORDS = frozenset("""
ABS AND ASC ATN AUTO BEEP BLOAD BSAVE CALL CALLS CDBL CHAIN CHDIR CHR$ CINT CIRCLE CLEAR
CLOSE CLS COLOR COM COMMON CONT COS CSNG CSRLIN CVD CVI CVS DATA DATE$ DEF DEFDBL
DEFINT DEFSNG DEFSTR DELETE DIM DRAW EDIT ELSE END ENVIRON ENVIRON$ EOF EQV ERASE
ERDEV ERDEV$ ERL ERR ERROR EXP EXTERR FIELD FILES FIX FN FOR FRE GET GOSUB GOTO HEX$
IF IMP INKEY$ INP INPUT INPUT$ INSTR INT IOCTL IOCTL$ KEY KILL LCOPY LEFT$ LEN LET
LINE LIST LLIST LOAD LOC LOCATE LOCK LOF LOG LPOS LPRINT LSET MERGE MID$ MKD$ MKDIR
MKI$ MKS$ MOD MOTOR NAME NEW NEXT NOT OCT$ OFF ON OPEN OPTION OR OUT PAINT PALETTE
PCOPY PEEK PEN PLAY PMAP POINT POKE POS PRESET PRINT PSET PUT RANDOMIZE READ REM
RENUM RESET RESTORE RESUME RETURN RIGHT$ RMDIR RND RSET RUN SAVE SCREEN SGN SHELL SIN
SOUND SPACE$ SPC SQR STEP STICK STOP STR$ STRIG STRING$ SWAP SYSTEM TAB TAN THEN
TIME$ TIMER TO TROFF TRON UNLOCK USING USR VAL VARPTR VARPTR$ VIEW WAIT WEND WHILE
WIDTH WINDOW WRITE XOR
""".split())

UNSUPPORTED = "UNSUPPORTED"  # token type: a reserved word the dialect does not implement
_NAME_TOKENS = ("NAME", "STRNAME")


class StoredName(str):
    """A name a tokenised program file holds as letters that spell a reserved word
    (``PRINT=1``: scanner.STORED_NAME): a variable, never an unsupported word."""

    __slots__ = ()


def mark_unsupported(tokens: list) -> list:
    """``tokens`` with every name that is a reserved word as an ``UNSUPPORTED`` token.

    (The scanner has already read every implemented keyword as a keyword, so a
    reserved word still read as a name is one the dialect does not have; a
    :class:`StoredName` is a file's variable.)
    """
    if not any(t.type in _NAME_TOKENS and t.value in GW_RESERVED_WORDS for t in tokens):
        return tokens
    return [t.update(type=UNSUPPORTED) if t.type in _NAME_TOKENS and t.value in GW_RESERVED_WORDS
            and type(t.value) is not StoredName else t for t in tokens]


def unsupported_message(word: str) -> str:
    """The error text for a reserved word the dialect does not implement."""
    return f"Unsupported word {word}"
