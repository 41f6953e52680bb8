"""The parser's tables (yaseer/basic/source/parse_tables.py) and what a cold start may read.

The tables are written by tools/make_parse_tables.py from grammar.lark with lark: regenerating
them gives the committed file, so the two cannot drift.  The interpreter itself never imports
lark and never unpickles anything: a pickle planted where lark's ``cache=True`` used to look
(a predictable name in the shared temp directory, which another user can write) runs nothing.
"""

from __future__ import annotations

import getpass
import hashlib
import os
import pickle
import subprocess
import sys
from pathlib import Path

import yaseer

ROOT = Path(__file__).resolve().parents[1]
PACKAGE_PARENT = str(Path(yaseer.__file__).resolve().parents[1])
TOOL = ROOT / "tools" / "make_parse_tables.py"


def test_regenerating_the_tables_from_the_grammar_gives_the_committed_module():
    done = subprocess.run([sys.executable, str(TOOL), "--check"], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


def test_the_check_notices_a_table_that_does_not_follow_the_grammar(tmp_path):
    """The comparison is real: a grammar with one more statement gives other tables."""
    sys.path.insert(0, str(TOOL.parent))
    try:
        import make_parse_tables
    finally:
        sys.path.remove(str(TOOL.parent))
    grammar = (ROOT / "yaseer" / "basic" / "source" / "grammar.lark").read_text()
    edited = grammar.replace("reset_stmt: RESET\n", "reset_stmt: RESET expr?\n")
    assert edited != grammar
    committed = (ROOT / "yaseer" / "basic" / "source" / "parse_tables.py").read_text()
    assert make_parse_tables.generate(grammar) == committed
    assert make_parse_tables.generate(edited) != committed


def old_lark_cache_names(grammar: str) -> list[str]:
    """The names lark 1.3.1's ``cache=True`` gave yaseer's parser tables in the temp directory:
    a hash of the grammar, the options as lark spells them, its version and Python's."""
    names = []
    for module in ("yaseer.basic.parser", "yaseer.basic.source.parser"):
        options = f"cacheTrueparserlalrlexer<class '{module}._TokenListLexer'>maybe_placeholdersFalse"
        digest = hashlib.sha256((grammar + options + "1.3.1" + str(sys.version_info[:2])).encode()).hexdigest()
        names.append(".lark_cache_%s_%s_%s_%s.tmp" % (getpass.getuser(), digest, *sys.version_info[:2]))
    return names


class _Planted:
    """Unpickling it writes the file ``marker`` (what an attacker's pickle would run instead)."""

    def __init__(self, marker: str):
        self.marker = marker

    def __reduce__(self):
        return (exec, (f"open({self.marker!r}, 'w').write('ran')",))


def test_a_pickle_planted_in_the_temp_directory_runs_nothing(tmp_path):
    shared, marker = tmp_path / "tmp", tmp_path / "ran.txt"
    shared.mkdir()
    grammar = (ROOT / "yaseer" / "basic" / "source" / "grammar.lark").read_text()
    payload = pickle.dumps(_Planted(str(marker)))
    for name in old_lark_cache_names(grammar):
        (shared / name).write_bytes(b"planted\n" + payload + payload)
    listing = tmp_path / "print.bas"
    listing.write_text("10 PRINT 1\n")
    env = dict(os.environ, TMPDIR=str(shared), YASEER_CACHE_DIR=str(tmp_path / "cache"))
    # Audit events: every file opened under the temp directory and every unpickled global.
    probe = (f"import sys; sys.path.insert(0, {PACKAGE_PARENT!r})\n"
             "seen = []\n"
             "def hook(event, args):\n"
             "    if event == 'open' and isinstance(args[0], str) and args[0].startswith(sys.argv[2]):\n"
             "        seen.append(args[0])\n"
             "    elif event.startswith('pickle.'):\n"
             "        seen.append(event)\n"
             "sys.addaudithook(hook)\n"
             "from yaseer.cli import main\n"
             "status = main(['run', sys.argv[1]])\n"
             "print(seen, status)")
    done = subprocess.run([sys.executable, "-c", probe, str(listing), str(shared)], capture_output=True,
                          text=True, env=env)
    assert done.stdout == " 1 \n[] 0\n", done.stderr
    assert not marker.exists()
    # The same through the command a user types (a fresh compiled cache: the parser runs).
    env["YASEER_CACHE_DIR"] = str(tmp_path / "cache2")
    done = subprocess.run([sys.executable, "-m", "yaseer", "run", str(listing)], capture_output=True,
                          text=True, env=env)
    assert (done.stdout, done.returncode) == (" 1 \n", 0), done.stderr
    assert not marker.exists()


def _old_lexer_class(module: str):
    """A stand-in for the lexer class the old parser in ``module`` passed lark, shown by ``str`` as
    that class was (lark hashes the option's text) and pickled as what it is (lark saves its
    tables by pickling)."""
    from lark.lexer import Lexer

    class Shown(type(Lexer)):
        def __repr__(cls):
            return f"<class '{module}._TokenListLexer'>"

    class TokenListLexer(Lexer, metaclass=Shown):
        def __init__(self, conf):
            pass

        def lex(self, data, *_):
            return iter(data)

    TokenListLexer.__qualname__ = "OLD_LEXER"
    return TokenListLexer


def test_the_planted_names_are_those_lark_used(tmp_path, monkeypatch):
    """The names above are lark's: lark itself, asked to cache the grammar with those options,
    writes its file under those names."""
    import tempfile

    import lark

    assert lark.__version__ == "1.3.1"  # the version the names were taken from (pinned by the test extra)
    global OLD_LEXER
    monkeypatch.setattr(tempfile, "tempdir", str(tmp_path))  # lark asks tempfile for the temp directory
    grammar = (ROOT / "yaseer" / "basic" / "source" / "grammar.lark").read_text()
    for module in ("yaseer.basic.parser", "yaseer.basic.source.parser"):
        OLD_LEXER = _old_lexer_class(module)
        lark.Lark(grammar, cache=True, parser="lalr", lexer=OLD_LEXER, maybe_placeholders=False)
    written = sorted(p.name for p in tmp_path.glob(".lark_cache_*"))
    assert written == sorted(old_lark_cache_names(grammar))


def test_importing_the_tables_builds_no_state_and_a_parse_makes_only_the_states_it_reaches():
    """The tables are constant tuples (no dict is built when the module is imported, a cold
    start's cost); the parser makes a state's actions the first time it reaches the state, the
    same actions as the tables list, and a rule's reduction the first time it reduces by it
    (every rule has one)."""
    probe = (f"import sys; sys.path.insert(0, {PACKAGE_PARENT!r})\n"
             "from yaseer.basic.source import parse_tables\n"
             "print(all(type(row) is tuple and len(row) == 2 for row in parse_tables.ACTIONS))\n"
             "from yaseer.basic.source import parser\n"
             "print(parser.parse_line(10, 'PRINT 1').statements)\n"
             "made = [state for state, row in enumerate(parser._ROWS) if row is not None]\n"
             "print(0 < len(made) < len(parse_tables.ACTIONS) // 10,\n"
             "      all(parser._ROWS[s] == dict(zip(*parse_tables.ACTIONS[s])) for s in made))\n"
             "reduced = [rule for rule, entry in enumerate(parser._REDUCTIONS) if entry is not None]\n"
             "print(0 < len(reduced) < len(parse_tables.RULES) // 10,\n"
             "      all(callable(parser._reduction_of(rule)[2]) for rule in range(len(parse_tables.RULES))))\n")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    tuples, statements, made, reduced = done.stdout.splitlines()
    assert tuples == "True" and "Print(" in statements and made == "True True" and reduced == "True True"
