"""The ``%basic`` / ``%%basic`` magics in an in-process IPython shell: options, errors, the stored result.

(The notebook test runs them through a real kernel; these cover the option handling.)
"""

from pathlib import Path

import pytest

pytest.importorskip("IPython", reason="the magics need yaseer[jupyter] (IPython)")

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="module")
def shell():
    from IPython.testing.globalipapp import get_ipython, start_ipython

    ip = start_ipython() or get_ipython()  # one shell per process: another module may have started it
    ip.run_line_magic("load_ext", "yaseer")
    return ip


def test_a_cell_runs_and_its_result_is_kept_under_the_name_given(shell, capsys):
    shell.run_cell_magic("basic", "-o lesson --input 6\\n7", "10 INPUT A\n20 INPUT B\n30 PRINT A * B\n")
    assert shell.user_ns["lesson"].rows.tolist() == [[42.0]]
    assert capsys.readouterr().out == "? 6\n? 7\n 42 \n"


def test_a_file_with_a_method_and_the_default_name(shell):
    shell.run_line_magic("basic", f"{ROOT / 'listings' / 'example1.bas'} --method 5=paper")
    result = shell.user_ns["_basic"]
    assert result.error is None and result.rows.shape == (25, 4)


@pytest.mark.parametrize("line, cell, says", [
    ("", None, "%basic FILE runs a listing"),
    ("x.bas", "10 PRINT 1", "name no file"),
    ("--method 2", "10 PRINT 1", "expected N=VALUE"),
    ("--dialect pascal", "10 PRINT 1", "unknown dialect 'pascal'"),
    ("--size big", "10 PRINT 1", "expected WIDTHxHEIGHT"),
])
def test_wrong_options_are_one_usage_error(shell, line, cell, says):
    from IPython.core.error import UsageError

    with pytest.raises(UsageError, match=says):
        if cell is None:
            shell.run_line_magic("basic", line)
        else:
            shell.run_cell_magic("basic", line, cell)


def test_an_unknown_method_is_one_usage_error_as_on_the_command_line(shell):
    from IPython.core.error import UsageError

    with pytest.raises(UsageError, match="unknown method 'bogus' for PROG 2"):
        shell.run_cell_magic("basic", "--method 2=bogus", "10 PRINT 1\n")



def test_a_program_that_draws_shows_its_lcd(shell, tmp_path):
    """A program in the library's manner, saved in the machine's codes (&HE1 is <=), calling
    a subprogram file as GOSUB "LIB0:..." does (&H92 is the superscript 2): the cell shows the LCD."""
    from IPython.utils.capture import capture_output

    (tmp_path / "LIBS0001.bas").write_bytes(b"10 y=x*x:RETURN\n")
    (tmp_path / "LIB0001.bas").write_bytes(
        b'10 CLS:PRINT"Square (x\xe199)";\n'
        b'20 LOCATE0,1:PRINTCHR$(5);"x=";x;"?";:INPUT@10;x:LOCATE0,0:GOSUB"LIB0:S0001"\n'
        b'30 LOCATE0,1:PRINTCHR$(5);"x\x92 =";y;:z$=INPUT$(1,@):GOTO20\n')
    with capture_output() as shown:
        shell.run_line_magic("basic", f"{tmp_path / 'LIB0001.bas'} --files {tmp_path} --input 12\\n")
    result = shell.user_ns["_basic"]
    assert result.screens == ["Square (x≤99)\nx= 0 ?\n", "Square (x≤99)\nx² = 144\n"]
    html = shown.outputs[0].data["text/html"]
    assert "Square (x≤99)" in html and "x² = 144" in html
