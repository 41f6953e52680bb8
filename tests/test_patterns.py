"""yaseer.patterns.Pattern: a regular expression compiled on first use, answering as the
compiled pattern does; and the modules a run imports compile none at import."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

from yaseer.patterns import Pattern

PACKAGE_PARENT = str(Path(__file__).resolve().parents[1])

CASES = [
    (r"\s*(\d+)(?=[\sA-Za-z'?]|$)\s?", ["10 PRINT 1", "  20", "30X", "4.5", "", "٣٤ REM"]),
    (r"\r\n|\n|\r", ["a\r\nb\nc\rd", "", "\n\n"]),
    (r"([+-]?)(\d*)(?:\.([\d.]*))?", ["-12.5.6", "+.", "abc"]),
    ("[\x00-\x1f]", ["plain", "bell\x07", "\x1f"]),
]


def _shown(match) -> tuple | None:
    return match and (match.span(), match.groups())


@pytest.mark.parametrize("source, texts", CASES)
def test_each_method_answers_as_the_compiled_pattern(source, texts):
    compiled = re.compile(source)
    for text in texts:
        lazy = Pattern(source)  # a fresh one per text: the first call made is the one compiling
        assert _shown(lazy.search(text)) == _shown(compiled.search(text))
        assert _shown(lazy.match(text)) == _shown(compiled.match(text))
        assert _shown(lazy.match(text, 1)) == _shown(compiled.match(text, 1))
        assert _shown(lazy.fullmatch(text)) == _shown(compiled.fullmatch(text))
        assert lazy.split(text) == compiled.split(text)
        assert lazy.findall(text) == compiled.findall(text)
        assert [_shown(m) for m in lazy.finditer(text)] == [_shown(m) for m in compiled.finditer(text)]
        assert lazy.sub("#", text) == compiled.sub("#", text) and lazy.subn("#", text) == compiled.subn("#", text)


def test_nothing_is_compiled_before_first_use_and_a_bad_pattern_fails_then():
    lazy = Pattern("(unclosed")
    with pytest.raises(AttributeError):
        object.__getattribute__(lazy, "search")  # the slot is empty: nothing compiled yet
    with pytest.raises(re.error):
        lazy.search("x")
    with pytest.raises(AttributeError):
        lazy.no_such_method  # noqa: B018


def test_the_modules_a_run_imports_compile_no_pattern_at_import():
    """Importing the command line, the API, the machine and the binding leaves re unimported:
    no module-level re.compile is left on the way to a run."""
    probe = ("import sys; sys.path.insert(0, sys.argv[1])\n"
             "import yaseer.cli, yaseer.commands.run, yaseer.commands.options, yaseer.api, yaseer.binding\n"
             "import yaseer.basic.machine.machine, yaseer.basic.machine.program_file\n"
             "print('re' in sys.modules)")
    done = subprocess.run([sys.executable, "-S", "-c", probe, PACKAGE_PARENT], capture_output=True, text=True,
                          check=True)
    assert done.stdout.strip() == "False", done.stderr


@pytest.mark.parametrize("dialect", ["casio", "gw"])
def test_a_warm_run_of_a_basic_program_imports_no_re(tmp_path, dialect):
    """A listing with numbers of each kind, strings, an array and a subroutine, run from the
    compiled-program cache (lines read, entry messages looked for, gw's memory counted):
    nothing on that path needs a regular expression (re with enum is a fifth of a start-up
    of ``python -m yaseer``)."""
    import os

    listing = tmp_path / "p.bas"
    typed = "; 1.5D0; 123456789012#; 32767%; &H1F; .5!" if dialect == "gw" else ""
    listing.write_text(f'10 DIM M(5): A$ = "X" + STR$(2.5E+3)\n20 FOR I = 1 TO 5: M(I) = I * 1.5: GOSUB 50: NEXT\n'
                       f'30 PRINT A$; M(5); 1E-30{typed}\n40 END\n50 A$ = LEFT$(A$ + "Y", 9): RETURN\n')
    env = dict(os.environ, YASEER_CACHE_DIR=str(tmp_path / "cache"))
    run = [sys.executable, "-m", "yaseer", "run", "--dialect", dialect, str(listing)]
    first = subprocess.run(run, capture_output=True, text=True, env=env, check=True)
    probe = ("import sys; sys.path.insert(0, sys.argv[1])\n"
             "from yaseer.cli import main\n"
             "status = main(['run', '--dialect', sys.argv[2], sys.argv[3]])\n"
             "print(status, 're' in sys.modules)")
    done = subprocess.run([sys.executable, "-S", "-c", probe, PACKAGE_PARENT, dialect, str(listing)],
                          capture_output=True, text=True, env=env, check=True)
    *output, last = done.stdout.splitlines()
    assert "\n".join(output) + "\n" == first.stdout and last == "0 False", done.stderr
