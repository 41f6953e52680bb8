"""Writes ``yaseer/basic/source/parse_tables.py``: the LALR(1) tables of ``grammar.lark``, computed by lark.

    python tools/make_parse_tables.py           # rewrite the module after editing the grammar
    python tools/make_parse_tables.py --check   # exit status 1 when the module is not what the grammar gives

The interpreter does not import lark: it reads these tables, a module of plain literals compiled to
bytecode beside the package like every other module, and runs them in ``parser.py``'s small LALR
driver.  Importing lark and loading its tables cost a cold start more than everything else together,
and lark's own table cache is a pickle in the shared temp directory.  lark is needed only here (the
test extra pins its version, so the same grammar gives the same file everywhere; a test regenerates
it and compares).

What each rule keeps is lark's tree-building rule for an LALR parser without placeholders
(``lark.parse_tree_builder``): terminals whose name starts with ``_`` are dropped, the children of a
rule whose name starts with ``_`` are spliced into its parent, a ``?rule`` without an alias that is
left with one child is that child, and every other rule calls the transformer method named by its
alias or its name.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
GRAMMAR = ROOT / "yaseer" / "basic" / "source" / "grammar.lark"
TABLES = ROOT / "yaseer" / "basic" / "source" / "parse_tables.py"


def _lark_parser(grammar: str):
    from lark import Lark
    from lark.lexer import Lexer

    class _NoLexer(Lexer):  # the tables never see text: the scanner makes the tokens
        def __init__(self, conf):
            pass

        def lex(self, data, *_):
            return iter(data)

    return Lark(grammar, parser="lalr", lexer=_NoLexer, maybe_placeholders=False)


def _rule_row(rule) -> tuple:
    """``(name, size, callback, keep, single)``: the symbol the rule reduces to, how many stack
    entries it takes, the transformer method it calls (None: its children go to its parent),
    the ``(index, splice)`` pairs of the children it keeps (None: all, unspliced) and whether one
    kept child stands for the rule."""
    expansion = rule.expansion
    keep = tuple((i, not sym.is_term and sym.name.startswith("_")) for i, sym in enumerate(expansion)
                 if rule.options.keep_all_tokens or not (sym.is_term and sym.filter_out))
    if len(keep) == len(expansion) and not any(splice for _, splice in keep):
        keep = None
    name = str(rule.origin.name)
    callback = str(rule.alias or rule.options.template_source or name)
    if callback.startswith("_"):
        callback = None
    return (name, len(expansion), callback, keep, bool(rule.options.expand1 and not rule.alias))


def _canonical_numbers(table, shift) -> dict:
    """lark's state numbers -> the order a breadth-first walk from the start state meets them,
    following the symbols in sorted order (lark numbers states in an order that depends on
    the hashing of its sets, so the same grammar would give different files)."""
    start = table.start_states["start"]
    number, queue = {start: 0}, [start]
    for state in queue:
        for _, (action, arg) in sorted(table.states[state].items()):
            if action is shift and arg not in number:
                number[arg] = len(number)
                queue.append(arg)
    end = table.end_states["start"]
    if end not in number:
        number[end] = len(number)
    assert len(number) == len(table.states)
    return number


def generate(grammar: str) -> str:
    """The text of the tables module for ``grammar``."""
    import lark
    from lark.parsers.lalr_analysis import Shift

    parser = _lark_parser(grammar)
    table = parser.parser.parser.parser.parse_table
    rules = list(parser.rules)
    index = {id(rule): k for k, rule in enumerate(rules)}
    number = _canonical_numbers(table, Shift)
    lines = [
        f'"""The LALR(1) tables of grammar.lark, computed by lark {lark.__version__}: written by',
        "tools/make_parse_tables.py, never edited by hand (a test regenerates and compares).",
        "",
        "RULES[k] is (name, size, callback, keep, single) (see the tool); ACTIONS[state] is a pair",
        "(symbols, codes): the terminals and rule names the state takes, sorted, and for each a shift",
        "or goto (the next state, >= 0) or a reduction (-1 - rule).  Pairs of constant tuples, not",
        "dicts: importing the module builds nothing (the parser makes a state's dict when it first",
        "reaches the state), and equal tuples are one constant.",
        '"""',
        "",
        "START = 0",
        f"END = {number[table.end_states['start']]}",
        "",
        "RULES = (",
        *(f"    {_rule_row(rule)!r}," for rule in rules),
        ")",
        "",
        "ACTIONS = (",
    ]
    for state in sorted(number, key=number.get):
        actions = [(str(name), number[arg] if action is Shift else -1 - index[id(arg)])
                   for name, (action, arg) in sorted(table.states[state].items())]
        lines.append(f"    ({tuple(name for name, _ in actions)!r}, {tuple(code for _, code in actions)!r}),")
    lines += [")", ""]
    return "\n".join(lines)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--check", action="store_true", help="compare, do not write")
    args = parser.parse_args(argv)
    text = generate(GRAMMAR.read_text())
    if args.check:
        if TABLES.read_text() != text:
            print(f"{TABLES} is not what {GRAMMAR.name} gives: run {Path(__file__).name}", file=sys.stderr)
            return 1
        return 0
    TABLES.write_text(text)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
