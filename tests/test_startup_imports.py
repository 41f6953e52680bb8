"""Start-up (issue 15): which modules a warm ``yaseer run`` imports.

A run whose compiled program is in the cache must not load what it does not
use: the parser and lark, numpy, and the standard modules that only some paths
need (pathlib for files and --out, decimal for PRINT USING's ^^^^ fields and doubles, csv for
--format csv and INPUT, hashlib for the cache key, random for RND), nor dataclasses (with
inspect) at all, not even when a library program is called.  Each probe is a fresh
process started with ``-S`` (no site: an editable install's import hook would
load pathlib before yaseer does) that runs ``yaseer run`` as the console script
does and prints which of the watched modules are in ``sys.modules`` at the end.
(Speed itself is measured by tests/benchmarks/startup.py, never asserted.)
"""

from __future__ import annotations

import ast
import os
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import given, settings, strategies as st

import yaseer

ROOT = Path(__file__).resolve().parents[1]
PACKAGE_PARENT = str(Path(yaseer.__file__).resolve().parents[1])

NEVER_WARM = ("lark", "numpy", "yaseer.basic.source.parser", "yaseer.basic.source.syntax_tree", "yaseer.basic.compile.compiler", "yaseer.basic.compile.expressions",
              "yaseer.basic.compile.statements_io", "yaseer.basic.compile.loops", "yaseer.animation",
              "pathlib", "decimal", "csv", "hashlib", "random", "dataclasses", "inspect")
"""Imported by no warm run of a listing that prints numbers (they serve other paths)."""

NOT_WITHOUT_PROG = ("yaseer.linkages",)
"""Imported only when a listing calls a library program.  (Its results are named tuples and
plain classes, not dataclasses: dataclasses imports inspect, ast, dis and tokenize, several ms.)"""

WATCHED = NEVER_WARM + NOT_WITHOUT_PROG


def warm_run(listing: Path, cache: Path, watched: tuple[str, ...] = WATCHED,
             options: tuple[str, ...] = ()) -> tuple[str, set[str]]:
    """Run ``yaseer run [OPTIONS] LISTING`` twice (the first fills the cache); the second's output
    and which ``watched`` modules it imported."""
    env = dict(os.environ, YASEER_CACHE_DIR=str(cache))
    cold = subprocess.run([sys.executable, "-m", "yaseer", "run", *options, str(listing)], capture_output=True,
                          text=True, env=env, check=True)
    probe = (f"import sys; sys.path.insert(0, {PACKAGE_PARENT!r})\n"
             "from yaseer.cli import main\n"
             f"status = main(['run', *{list(options)!r}, sys.argv[1]])\n"
             f"print(sorted(m for m in {watched!r} if m in sys.modules), status)")
    done = subprocess.run([sys.executable, "-S", "-c", probe, str(listing)], capture_output=True, text=True,
                          env=env, check=True)
    *output, last = done.stdout.splitlines()
    modules, status = last.rsplit(" ", 1)
    assert status == "0", done.stderr
    assert "\n".join(output) + "\n" == cold.stdout  # the cached program prints what the compiled one did
    return cold.stdout, set(ast.literal_eval(modules))


@pytest.fixture
def cache(tmp_path) -> Path:
    return tmp_path / "cache"


def test_a_warm_basic_only_run_imports_only_the_machine(cache):
    listing = cache.parent / "print.bas"
    listing.write_text("10 PRINT 1\n")
    output, imported = warm_run(listing, cache)
    assert output == " 1 \n"
    assert imported == set()


def test_a_warm_run_calling_the_programs_loads_their_formulas_only(cache):
    output, imported = warm_run(ROOT / "listings" / "example1.bas", cache)
    assert output == (ROOT / "tests" / "golden" / "example1.txt").read_text()
    assert imported == set(NOT_WITHOUT_PROG)  # its PRINT USING's fixed fields round without decimal


FORMULAS = ("yaseer.linkages.planar", "yaseer.linkages.kinetostatics", "yaseer.linkages.fourbar",
            "yaseer.linkages.slider_crank", "yaseer.linkages.inverted_slider_crank", "yaseer.linkages.virtual_link")
"""The linkage formulas: a warm run whose library calls all take paths kept on disk runs none of them."""


@pytest.mark.parametrize("example", ["example1", "example5"])
def test_a_warm_run_of_kept_paths_imports_no_formula(cache, example):
    output, imported = warm_run(ROOT / "listings" / f"{example}.bas", cache, WATCHED + FORMULAS)
    assert output == (ROOT / "tests" / "golden" / f"{example}.txt").read_text()
    assert "yaseer.linkages" in imported and not imported & set(FORMULAS)


def test_the_formulas_are_the_package_names_at_first_use():
    """The package's names are imported when first used; a function named as its module stays
    the function when that module is imported (as the import system binds it in the package)."""
    probe = ("import yaseer.linkages as L, sys\n"
             "before = sorted(m for m in sys.modules if m.startswith('yaseer.linkages.'))\n"
             "import yaseer.linkages.fourbar, yaseer.linkages.virtual_link\n"
             "print(before, callable(L.fourbar), L.fourbar.__module__, L.virtual_link.__name__,\n"
             "      L.MassProps.__module__, 'slider_crank' in dir(L), L.CROSSED != L.UNCROSSED)")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True,
                          env=dict(os.environ, PYTHONPATH=PACKAGE_PARENT))
    assert done.stdout.split() == ["[]", "True", "yaseer.linkages.fourbar", "virtual_link",
                                   "yaseer.linkages.kinetostatics", "True", "True"]
    from yaseer.linkages.registry import default_method, method_names

    assert "paper" in method_names("virtual_link") and default_method("virtual_link") == "polar"
    with pytest.raises(AttributeError):
        import yaseer.linkages

        yaseer.linkages.no_such_name  # noqa: B018


def test_the_watched_modules_are_those_the_other_paths_need(cache):
    """The probe can see them: PRINT USING with an exponent, INPUT and a file do load them (no -S needed here)."""
    listing = cache.parent / "other.bas"
    listing.write_text('10 PRINT USING "##.##^^^^"; 1.234\n20 OPEN "O", 1, "F.TXT": PRINT #1, 1: CLOSE 1\n30 INPUT A\n')
    (cache.parent / "answers.txt").write_text("5\n")
    env = dict(os.environ, YASEER_CACHE_DIR=str(cache))
    probe = (f"import sys, os; sys.path.insert(0, {PACKAGE_PARENT!r}); os.chdir(sys.argv[2])\n"
             "from yaseer.cli import main\n"
             "status = main(['run', '--dialect', 'gw', '--input', 'answers.txt', sys.argv[1]])\n"
             "print(sorted(m for m in ('pathlib', 'decimal', 'csv') if m in sys.modules))")
    done = subprocess.run([sys.executable, "-c", probe, str(listing), str(cache.parent)],
                          capture_output=True, text=True, env=env, check=True)
    assert done.stdout.splitlines()[-1] == "['csv', 'decimal', 'pathlib']", done.stderr


def test_the_plain_classes_behave_as_the_dataclasses_they_replace():
    """Result compares and shows itself by its fields (not lines), with a list of its own;
    a Dialect is immutable and makes variants."""
    from yaseer.api import Result
    from yaseer.basic.dialects.dialect import CASIO

    a, b = Result("10 PRINT 1", text=" 1 \n"), Result("10 PRINT 1", text=" 1 \n")
    assert a == b and a != Result("10 PRINT 1") and a != "10 PRINT 1"
    assert repr(a) == ("Result(listing='10 PRINT 1', name=None, text=' 1 \\n', error=None, status='end', "
                       "line=None, exception=None, frames=[])")
    a.lines.append([1.0])
    assert a != b and b.lines == [] and a.frames is not b.frames
    with pytest.raises(AttributeError):
        CASIO.width = 80
    assert CASIO._replace(width=80).width == 80 and CASIO.width is None
    assert CASIO.with_program_areas() is CASIO and hash(CASIO) == hash(CASIO._replace())


def test_the_linkage_results_behave_as_the_frozen_dataclasses_they_replace():
    """Kinematics results: made from their fields in order, immutable, compared, hashed
    and shown by their fields; the force records are named tuples of the same fields."""
    from yaseer.linkages import MassProps, slider_crank, virtual_link

    a, b = slider_crank(0.0, 1.0, 3.0, 30.0, 2.0, 0.0), slider_crank(0.0, 1.0, 3.0, 30.0, 2.0, 0.0)
    assert a == b and hash(a) == hash(b) and a != slider_crank(0.0, 1.0, 3.0, 31.0, 2.0, 0.0) and a != a.crank
    assert repr(a).startswith("SliderCrank(crank=Rotation(angle=") and repr(a).endswith(", moving=True)")
    assert type(a)(*(getattr(a, name) for name in a.FIELDS)) == a
    a.rod_point(1.0, 0.0)  # keeps its unit vectors, still equal
    assert a == b
    with pytest.raises(AttributeError):
        a.rod = a.crank
    with pytest.raises(TypeError):
        type(a)(a.crank)
    assert MassProps(2.0) == MassProps(mass=2.0, inertia=0.0) and MassProps().offset_deg == 0.0
    with pytest.raises(AttributeError):
        MassProps().mass = 1.0
    assert virtual_link(3.0, 4.0, 0.0, 0.0, 0.0, 0.0).length == 5.0


@pytest.mark.parametrize("command", ["run", "diff", "plot", "animate", "bench", "stability", "centrode", "report"])
def test_a_command_parser_alone_is_the_sub_parser_of_the_whole_parser(command, monkeypatch):
    """``yaseer COMMAND ...`` is parsed by the command's parser alone (the main parser and
    the other sub-parsers are not built): the same help, usage, options and defaults."""
    from yaseer.cli import build_parser, command_parser

    monkeypatch.setenv("COLUMNS", "100")
    alone, sub = command_parser(command), build_parser(command)[1]
    assert alone.prog == sub.prog == f"yaseer {command}"
    assert alone.format_help() == sub.format_help()
    assert [(a.dest, a.default) for a in alone._actions] == [(a.dest, a.default) for a in sub._actions]


def test_a_warm_run_builds_no_other_commands_parser(cache):
    listing = cache.parent / "print.bas"
    listing.write_text("10 PRINT 1\n")
    env = dict(os.environ, YASEER_CACHE_DIR=str(cache))
    subprocess.run([sys.executable, "-m", "yaseer", "run", str(listing)], capture_output=True, env=env, check=True)
    probe = (f"import sys; sys.path.insert(0, {PACKAGE_PARENT!r})\n"
             "from yaseer.cli import main\n"
             "assert main(['run', sys.argv[1]]) == 0\n"
             "print(sorted(m for m in sys.modules if m.startswith('yaseer.commands.')))")
    done = subprocess.run([sys.executable, "-S", "-c", probe, str(listing)], capture_output=True, text=True,
                          env=env, check=True)
    assert done.stdout.splitlines()[-1] == "['yaseer.commands.options', 'yaseer.commands.output', 'yaseer.commands.run']"


NOT_FOR_A_PLAIN_RUN = ("argparse", "typing", "gettext", "locale", "shutil", "importlib", "yaseer.commands.parsers")
"""Not imported by a warm ``yaseer run FILE [options]``: the command line is read from the run
command's table without argparse (with gettext, locale and shutil for its help width), no named
tuple of the machine or the linkages is a ``typing.NamedTuple``, and the command's module and the
linkages' default methods are found without importlib."""


@pytest.mark.parametrize("options", [(), ("--dialect", "gw", "--format=csv", "--angle", "deg", "--arith=binary")])
def test_a_plain_run_command_line_imports_no_argparse_and_no_typing(options, cache):
    listing = cache.parent / "print.bas"
    listing.write_text("10 PRINT 1\n")
    output, imported = warm_run(listing, cache, NOT_FOR_A_PLAIN_RUN, options)
    assert output == (" 1 \n" if not options else "1.0\n")
    assert imported == set()


def test_a_warm_run_calling_the_programs_imports_no_argparse_and_no_typing(cache):
    output, imported = warm_run(ROOT / "listings" / "example1.bas", cache, NOT_FOR_A_PLAIN_RUN)
    assert output == (ROOT / "tests" / "golden" / "example1.txt").read_text()
    assert imported == set()


def test_the_run_parser_and_the_scanner_are_built_from_one_table():
    """argparse's ``yaseer run`` parser holds exactly the table's arguments, in its order."""
    from yaseer.cli import command_parser
    from yaseer.commands.run import ARGUMENTS

    parser = command_parser("run")
    table = [option for _, group in ARGUMENTS for option in group]
    assert [(a.dest, a.option_strings, a.metavar, a.choices) for a in parser._actions if a.dest != "help"] == [
        (o.dest, [] if o.positional else [o.flag], o.metavar, o.choices) for o in table]


@pytest.mark.parametrize("argv", [
    ["x.bas"], ["-"], ["--dialect", "gw", "x.bas"], ["x.bas", "--dialect=gw", "--dialect", "casio"],
    ["--format", "csv", "--printer", "-", "x.bas"], ["--printer=", "x.bas"], ["x=y.bas", "--input", "in.txt"],
    ["--prog", "5=p.bas", "--prog=1=q.bas", "x.bas", "--method", "5=paper", "--method=2=newton"],
    ["--angle", "rad", "--arith", "decimal", "--files", "dir", "x.bas"], [""],
])
def test_the_scanner_reads_a_plain_command_line_as_argparse_does(argv):
    from yaseer.cli import command_parser
    from yaseer.commands.options import scan
    from yaseer.commands.run import ARGUMENTS

    assert vars(scan(argv, ARGUMENTS)) == vars(command_parser("run").parse_args(argv))


@pytest.mark.parametrize("argv", [
    [], ["--help"], ["-h", "x.bas"], ["x.bas", "y.bas"], ["--form", "csv", "x.bas"], ["--", "x.bas"],
    ["--dialect", "xx", "x.bas"], ["--dialect=", "x.bas"], ["--prog", "12=x.bas", "x.bas"], ["--prog", "x", "x.bas"],
    ["--method", "5=nonsense", "x.bas"], ["x.bas", "--printer"], ["x.bas", "--printer", "--format", "csv"],
    ["-5"], ["x.bas", "--version"], ["--dialect", "-", "x.bas"],
])
def test_the_scanner_leaves_every_other_command_line_to_argparse(argv):
    """Help, errors and the forms whose reading is argparse's own (abbreviations, ``--``, a
    value like an option): the scanner declines, so argparse reads them or reports them as before."""
    from yaseer.commands.options import scan
    from yaseer.commands.run import ARGUMENTS

    assert scan(argv, ARGUMENTS) is None


WORDS = ("x.bas", "y.bas", "-", "", "a b", "-5", "--", "-h", "--help", "--form", "--pr", "--dialect", "--dialect=gw",
         "--dialect=", "gw", "casio", "xx", "--format", "csv", "text", "--printer", "--printer=out.txt", "--prog",
         "--prog=5=p.bas", "5=p.bas", "12=x", "--method", "5=paper", "5=nonsense", "--angle", "deg", "--arith",
         "decimal", "--input", "--files", "dir", "--no-such", "-x", "--files=")


@settings(max_examples=300, deadline=None)
@given(st.lists(st.sampled_from(WORDS), max_size=6).flatmap(lambda words: st.permutations([*words, "x.bas"])))
def test_whatever_the_scanner_reads_argparse_reads_the_same(argv):
    """Any command line the scanner answers for (words of every kind, one file among them),
    argparse parses to the same namespace."""
    from yaseer.cli import command_parser
    from yaseer.commands.options import scan
    from yaseer.commands.run import ARGUMENTS

    scanned = scan(argv, ARGUMENTS)
    if scanned is not None:
        assert vars(scanned) == vars(command_parser("run").parse_args(argv))


def test_a_gw_run_imports_no_library_binding(cache):
    """gw has no library programs (PROG is no word): its runs leave yaseer.binding unimported."""
    listing = cache.parent / "print.bas"
    listing.write_text("10 PRINT 1\n")
    output, imported = warm_run(listing, cache, ("yaseer.binding",), ("--dialect", "gw"))
    assert output == " 1 \n"
    assert imported == set()


COLLECTOR_PROBE = (
    f"import gc, sys; sys.path.insert(0, {PACKAGE_PARENT!r})\n"
    "import yaseer.entry\n"  # the program's first code: the collector paused from here
    "from yaseer.basic.machine.machine import Machine\n"
    "from yaseer.cli import main\n"
    "seen = [gc.isenabled()]\n"
    "run = Machine.run\n"
    "def watched(self):\n"
    "    seen.append((gc.isenabled(), gc.get_freeze_count() > 0))\n"
    "    return run(self)\n"
    "Machine.run = watched\n"
    "status = main()\n"  # as the program calls it: the command line is sys.argv[1:]
    "print(seen, gc.isenabled(), status)\n")


def collector_states(*argv: str) -> str:
    """The last line of the probe above run with the command line ``argv``: whether the
    collector was on after yaseer.entry was imported, [(on, objects frozen) when each BASIC
    program started], whether it was on at the end, and the exit status."""
    done = subprocess.run([sys.executable, "-c", COLLECTOR_PROBE, *argv], capture_output=True, text=True,
                          check=True)
    return done.stdout.splitlines()[-1]


def test_the_collector_is_paused_while_a_process_starts_and_on_when_the_program_runs(tmp_path):
    """collection_pause: a `yaseer run` process collects no garbage while it imports and loads
    (none is made), freezes what the start made and runs the BASIC program with the collector on."""
    listing = tmp_path / "print.bas"
    listing.write_text("10 PRINT 1\n")
    assert collector_states("run", str(listing)) == "[False, (True, True)] True 0"
    assert collector_states("run", "--dialect", "gw", str(listing)) == "[False, (True, True)] True 0"


def test_every_other_command_switches_the_collector_on_once_its_command_line_is_read():
    assert collector_states("--version") == "[False] True 0"
    assert collector_states("run", "--no-such-option") == "[False] True 2"


def test_a_program_run_inside_another_python_never_pauses_the_collector():
    import gc

    frozen = gc.get_freeze_count()
    assert yaseer.run("10 PRINT 1").text == " 1 \n"
    assert gc.isenabled() and gc.get_freeze_count() == frozen


COMPILE_PROBE = (
    f"import gc, sys; sys.path.insert(0, {PACKAGE_PARENT!r})\n"
    "import yaseer.entry\n"
    "import yaseer.basic.compile.compiler as compiler\n"
    "from yaseer.cli import main\n"
    "seen = []\n"
    "compile_area = compiler.compile_area\n"
    "def watched(*args, **kwargs):\n"
    "    seen.append(gc.isenabled())\n"
    "    return compile_area(*args, **kwargs)\n"
    "compiler.compile_area = watched\n"
    "status = main()\n"
    "print(seen, gc.isenabled(), status)\n")


def test_a_cold_run_parses_and_compiles_with_the_collector_paused(tmp_path):
    """The first run of a listing parses and compiles it before the program starts
    (Machine.compile_areas), while the start's pause lasts: the objects that makes are no
    garbage either; the collector is on again when the program runs and at the end."""
    listing = tmp_path / "print.bas"
    listing.write_text("10 PRINT 1\n")
    env = dict(os.environ, YASEER_CACHE_DIR=str(tmp_path / "cache"))
    done = subprocess.run([sys.executable, "-c", COMPILE_PROBE, "run", str(listing)], capture_output=True,
                          text=True, env=env, check=True)
    assert done.stdout.splitlines() == [" 1 ", "[False] True 0"]
    assert collector_states("run", str(listing)) == "[False, (True, True)] True 0"  # the program still runs with it on


def test_a_program_run_inside_another_python_compiles_with_its_collector_as_it_was():
    import gc

    assert gc.isenabled()
    assert yaseer.run('10 PRINT "A"').text == "A\n"
    assert gc.isenabled()


def test_each_syntax_tree_class_is_made_once():
    """Importing the syntax tree makes one class per node (its metaclass builds it with its
    slots), not a class and then a second one with slots (a cold start's parse imports it)."""
    probe = (f"import gc, sys; sys.path.insert(0, {PACKAGE_PARENT!r}); gc.disable()\n"
             "import yaseer.basic.source.syntax_tree as ast\n"
             "made = [o for o in gc.get_objects() if isinstance(o, type) and o.__module__ == ast.__name__]\n"
             "named = [v for v in vars(ast).values() if isinstance(v, type) and v.__module__ == ast.__name__]\n"
             "print(len(made), len(named), all(type(c) is type for c in named))")
    done = subprocess.run([sys.executable, "-c", probe], capture_output=True, text=True, check=True)
    made, named, plain = done.stdout.split()
    assert made == named, "a node class made with @_node: write it as class Name(metaclass=_node)"
    assert int(named) > 80 and plain == "True"


def test_a_node_keeps_its_fields_defaults_and_slots():
    from yaseer.basic.source import syntax_tree as ast

    assert ast.Num._fields == ("value", "kind") and ast.Num.__slots__ == ("value", "kind")
    assert ast.Num(1.0) == ast.Num(1.0, "") and ast.Num(1.0).kind == ""
    assert ast.Num.__qualname__ == "Num" and ast.Num.__module__ == ast.__name__ and issubclass(ast.Num, ast.Node)
    with pytest.raises(AttributeError):
        ast.Num(1.0).other = 2
    with pytest.raises(TypeError):
        ast.Num()


NEVER_COLD = ("lark", "numpy", "re", "enum", "pathlib", "decimal", "csv", "hashlib", "random", "dataclasses",
              "inspect", "typing", "argparse")
"""Imported by no cold ``yaseer run`` of a casio listing of plain statements and whole numbers (the
first run of a new listing parses and compiles it): the scanner reads digits without a regular
expression (re imports enum), the compiler and the parser compile theirs where a line needs one."""


@pytest.mark.parametrize("text", ["10 PRINT 1\n", "10 A=12: B=A*3\n20 IF B>30 THEN PRINT B ELSE PRINT -B\n30 END\n"])
def test_a_cold_run_imports_no_regular_expressions(tmp_path, text):
    listing = tmp_path / "plain.bas"
    listing.write_text(text)
    env = dict(os.environ, YASEER_CACHE_DIR=str(tmp_path / "cache"))
    probe = (f"import sys; sys.path.insert(0, {PACKAGE_PARENT!r})\n"
             "from yaseer.cli import main\n"
             "status = main(['run', sys.argv[1]])\n"
             f"print(sorted(m for m in {NEVER_COLD!r} if m in sys.modules), status)")
    done = subprocess.run([sys.executable, "-S", "-c", probe, str(listing)], capture_output=True, text=True,
                          env=env, check=True)
    assert done.stdout.splitlines()[-1] == "[] 0", done.stderr
    assert list((tmp_path / "cache").glob("*.bin"))  # a cold run: compiled and kept


def test_a_cold_run_whose_compile_fails_switches_the_collector_back_on(tmp_path):
    listing = tmp_path / "print.bas"
    listing.write_text("10 PRINT 1\n")
    probe = (f"import gc, sys; sys.path.insert(0, {PACKAGE_PARENT!r})\n"
             "import yaseer.entry\n"
             "import yaseer.basic.compile.compiler as compiler\n"
             "from yaseer.basic.errors import BasicError\n"
             "from yaseer.cli import main\n"
             "def failing(*args, **kwargs):\n"
             "    raise BasicError('Out of memory', 7)\n"
             "compiler.compile_area = failing\n"
             "status = main()\n"
             "print(gc.isenabled(), status)\n")
    env = dict(os.environ, YASEER_CACHE_DIR=str(tmp_path / "cache"))
    done = subprocess.run([sys.executable, "-c", probe, "run", str(listing)], capture_output=True, text=True, env=env)
    assert done.stdout.splitlines()[-1] == "True 1" and "Out of memory" in done.stderr and "Traceback" not in done.stderr
