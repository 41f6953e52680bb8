"""The marker lines of a block's generated code (yaseer/basic/compile/markers.py).

A marker is text to every reader of the code (sizes, searches) and is replaced by
``block_source``; a plain comment line there would be a marker written as text by
mistake, which would silently do nothing, so the compiler refuses it."""

import pytest

from yaseer.basic.compile import compiler as compiler_module
from yaseer.basic.compile.markers import (
    LOAD_LOCALS, STACK_CHECK, STORE_LOCALS, ArraysCall, Dimensioned, PassTop, Refreshing,
)
from yaseer.basic.dialects.dialect import GW
from yaseer.basic.machine.machine import _parse_cached


def _compile(source: dict):
    lines = [_parse_cached(number, text, GW) for number, text in sorted(source.items())]
    return compiler_module.compile_area(lines, 0, dialect=GW)


def test_markers_are_text_with_their_parts():
    assert ArraysCall("_call(1, _ln)").call == "_call(1, _ln)"
    assert "_call(" in ArraysCall("_call(1, _ln)")  # found by the searches for stack changes
    assert Dimensioned("A").name == "A" and PassTop(3).index == 3
    assert Refreshing("if _f and x: y").code == "if _f and x: y"
    for marker in (STORE_LOCALS, LOAD_LOCALS, STACK_CHECK, ArraysCall("f()"), Dimensioned("A"), PassTop(0)):
        assert marker.startswith("#")


def test_no_marker_is_left_in_the_generated_source():
    source = {10: "DEF FNA(X) = X * 2", 20: "FOR I = 1 TO 3: A(I) = FNA(I): GOSUB 100: NEXT I",
              30: "DIM C(5): C(1) = 2: CLEAR: PRINT A(2)", 40: "END", 100: "RETURN"}
    text = _compile(source).source
    assert not [line for line in text.splitlines() if line.strip().startswith("#")]
    assert "_mk(" in text and "_S[" in text  # the makings' and the stores' lines were written


def test_a_marker_written_as_plain_text_is_refused(monkeypatch):
    def clear_with_text_marker(self, stmt, scope):
        self.emit("_clear()")
        self.emit("#RELOAD#")

    monkeypatch.setattr(compiler_module.AreaCompiler, "stmt_Clear", clear_with_text_marker)
    with pytest.raises(AssertionError, match="comment line"):
        _compile({10: "A = 1: CLEAR: PRINT A"})
