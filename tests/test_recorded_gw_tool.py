"""tools/recorded_gw.py on a corpus made here: a recording reproduced, one not, one not runnable."""

from __future__ import annotations

import importlib.util
from pathlib import Path

TOOL = Path(__file__).resolve().parents[1] / "tools" / "recorded_gw.py"
RUN_AND_QUIT = "[pcbasic]\nrun=TEST.BAS\nquit=True\n"


def load_tool():
    spec = importlib.util.spec_from_file_location("recorded_gw", TOOL)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def make_test(group: Path, name: str, program: str, model: bytes, ini: str = RUN_AND_QUIT) -> None:
    folder = group / name
    (folder / "model").mkdir(parents=True)
    (folder / "TEST.BAS").write_text(program)
    (folder / "PCBASIC.INI").write_text(ini)
    (folder / "model" / "OUTPUT.TXT").write_bytes(model)


def test_counts_a_match_a_difference_and_leaves_out_a_typed_test(tmp_path, capsys):
    group = tmp_path / "corpus" / "unsorted"
    writes_seven = '10 OPEN "output.txt" FOR OUTPUT AS 1\n20 PRINT #1, 3+4\n30 CLOSE\n'
    # GW closes a sequential output file with a ^Z (GIODSK.ASM), as the recordings end
    make_test(group, "SAME", writes_seven, b" 7 \r\n\x1a")
    make_test(group, "OTHER", writes_seven, b" 8 \r\n\x1a")
    make_test(group, "TYPED", writes_seven, b" 7 \r\n\x1a", ini=RUN_AND_QUIT + "keys=abc\n")
    tool = load_tool()
    assert tool.main([str(tmp_path / "corpus"), "--list", "all"]) == 0
    out = capsys.readouterr().out
    assert "pass unsorted/SAME" in out
    assert "FAIL unsorted/OTHER: OUTPUT.TXT differs" in out
    assert "unsorted: 1 of 2 reproduced (1 other tests not run)" in out

    assert tool.main([str(tmp_path / "corpus"), "--tests", "OTHER", "--list", "all"]) == 0
    out = capsys.readouterr().out
    assert "SAME" not in out and "FAIL unsorted/OTHER" in out
    assert "all: 0 of 1 reproduced" in out


def test_the_settings_file_is_there_where_the_model_holds_it(tmp_path, capsys):
    """A test whose model/ holds PCBASIC.INI ran with it in its directory (LockFiles): the
    run has it too; elsewhere it stays out of the program's directory."""
    group = tmp_path / "corpus" / "unsorted"
    lists_ini = '10 OPEN "output.txt" FOR OUTPUT AS 1\n20 PRINT #1, 3+4\n30 CLOSE\n'
    make_test(group, "WITHINI", lists_ini, b" 7 \r\n\x1a")
    (group / "WITHINI" / "model" / "PCBASIC.INI").write_text(RUN_AND_QUIT)
    make_test(group, "WITHOUT", '10 OPEN "I", 1, "PCBASIC.INI"\n', b"")
    tool = load_tool()
    assert tool.main([str(tmp_path / "corpus"), "--list", "all"]) == 0
    out = capsys.readouterr().out
    assert "pass unsorted/WITHINI" in out
    assert "FAIL unsorted/WITHOUT: File not found" in out
