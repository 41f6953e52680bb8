"""GW-BASIC's event words read as events where GW-BASIC reads them so.

An event word (dialects/gw_words.py EVENTS: KEY, COM, STRIG, PEN, TIMER, PLAY) is an event
right after ``ON`` (GWMAIN.ASM ONGOTO asks GWSTS.ASM ONGOTP, which takes the word's token
before any expression: ``ON TIMER GOSUB 10`` is Syntax error, not ON of TIMER's value) and
at the start of a statement followed by ``(`` or by ON, OFF or STOP (the words' statement
routines SEVSTT, PENS, STRIGS).  Elsewhere each stays what the scanner made of it: KEY ON
(the function-key line), a function (STRIG(0)), a value (TIMER), an unsupported word
(PLAY(0)).  This pass turns those tokens into ``EVENT`` tokens; the grammar's on_event
and event_switch read them.  An event word that is also a statement of the device words
(PLAY "CDE": dialects/gw_words.py STATEMENTS) and starts a statement without being an event
is that statement (a ``WORDSTMT``).
"""

from __future__ import annotations

EVENT = "EVENT"
SWITCH_STATES = frozenset(("ON", "OFF", "STOP"))
_STATEMENT_STARTS = frozenset(("_COLON", "THEN", "ELSE"))


def _word(token) -> str | None:
    value = token.value
    return value.upper() if isinstance(value, str) else None


def mark_events(tokens: list, events: dict | None, statements=()) -> list:
    """``tokens`` with each event word that reads as an event as an ``EVENT`` token
    (``events``: the dialect's table, None where it has none), and each that starts a
    statement otherwise as a ``WORDSTMT`` if it is one of ``statements``."""
    if not events:
        return tokens
    marked = None
    for k, token in enumerate(tokens):
        word = _word(token)
        if word not in events or token.type == "STRING":
            continue
        before = tokens[k - 1].type if k else "_COLON"
        after = tokens[k + 1].type if k + 1 < len(tokens) else None
        starts = before in _STATEMENT_STARTS
        if before == "ON" or starts and (after == "_LPAR" or after in SWITCH_STATES and events[word][3]):
            marked = marked or list(tokens)
            marked[k] = token.update(type=EVENT, value=word)
        elif starts and word in statements:
            marked = marked or list(tokens)
            marked[k] = token.update(type="WORDSTMT", value=word)
    return marked or tokens
