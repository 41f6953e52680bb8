"""The dialect object: lookup, the machine's start-up state, and the CLI/session options."""

from __future__ import annotations

import io

import pytest

from test_differential_support import PcBasic, run_yaseer
from yaseer.basic.dialects.dialect import CASIO, GW, Dialect, get_dialect
from yaseer.basic.machine.machine import Machine

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")


def test_lookup_by_name_any_case_and_passthrough():
    assert get_dialect("casio") is CASIO
    assert get_dialect("GW") is GW
    assert get_dialect(GW) is GW
    with pytest.raises(ValueError, match="unknown dialect 'qbasic'"):
        get_dialect("qbasic")


def test_dialect_is_frozen_data():
    with pytest.raises(Exception):
        CASIO.width = 80  # type: ignore[misc]
    assert isinstance(CASIO, Dialect) and CASIO != GW


def test_machine_keeps_its_dialect_and_defaults_to_casio():
    assert Machine(screen=io.StringIO()).dialect is CASIO
    assert Machine(screen=io.StringIO(), dialect="gw").dialect is GW


def test_casio_has_the_al_yaseer_arrays_gw_has_none():
    # N is pre-dimensioned 0..3 on the paper's machine; in GW-BASIC every
    # undimensioned array is 0..10 (PC-BASIC is the reference for gw).
    source = "10 N(10) = 5: PRINT N(10)\n20 PRINT A(53)\n"
    assert run_yaseer(source, angle=None) == "Subscript out of range in 10\n"
    pc = PcBasic()
    try:
        theirs = pc.program(source)
    finally:
        pc.close()
    assert theirs.startswith(" 5 \nSubscript out of range in 20")
    assert run_yaseer(source, angle=None, dialect="gw") == " 5 \nSubscript out of range in 20\n"


def test_start_up_angle_is_the_dialects_unless_given():
    # ATN(1) is 45 in degrees and pi/4 (< 1) in radians
    assert run_yaseer("10 PRINT ATN(1) > 1\n", angle=None) == "-1 \n"
    assert run_yaseer("10 PRINT ATN(1) > 1\n", angle=None, dialect="gw") == " 0 \n"
    assert run_yaseer("10 PRINT ATN(1) > 1\n", angle="deg", dialect="gw") == "-1 \n"


def test_run_command_takes_dialect(tmp_path, capsys):
    from yaseer.cli import main

    path = tmp_path / "p.bas"
    path.write_text("10 PRINT ATN(1) > 1\n")
    assert main(["run", "--dialect", "gw", str(path)]) == 0
    assert capsys.readouterr().out == " 0 \n"
    assert main(["run", str(path)]) == 0
    assert capsys.readouterr().out == "-1 \n"


def test_interactive_session_takes_dialect(monkeypatch, capsys):
    from yaseer.cli import main

    monkeypatch.setattr("sys.stdin", io.StringIO("PRINT ATN(1) > 1\n"))
    assert main(["--dialect", "gw"]) == 0
    assert " 0 \n" in capsys.readouterr().out
    monkeypatch.setattr("sys.stdin", io.StringIO("PRINT ATN(1) > 1\n"))
    assert main([]) == 0
    assert "-1 \n" in capsys.readouterr().out


def test_session_lists_lines_as_its_dialect_reads_them():
    from yaseer.session import MachineEngine, Session

    for dialect, listed in (("casio", "10 COS t=5"), ("gw", "10 COST=5")):  # casio names keep their case
        shown: list[str] = []
        session = Session(write=shown.append, engine=MachineEngine(shown.append, dialect=dialect), dialect=dialect)
        session.handle("10 cost=5")
        session.handle("LIST")
        assert listed in "".join(shown), (dialect, shown)
