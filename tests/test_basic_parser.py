"""The LALR grammar: statement and expression shapes."""

import pytest

from yaseer.basic.errors import BasicError
from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.dialects.dialect import GW
from yaseer.basic.source.parser import parse_line, parse_statements


def one(text):
    statements = parse_statements(text)
    assert len(statements) == 1
    return statements[0]


def test_power_binds_tighter_than_unary_minus():
    let = one("A=-2^2")
    assert let.value == ast.Unary("-", ast.Binary("^", ast.Num(2.0), ast.Num(2.0)))


def test_function_without_parentheses_takes_the_next_primary():
    let = one("X=COS T*2")
    assert let.value == ast.Binary("*", ast.Call("COS", (ast.Var("T"),)), ast.Num(2.0))


def test_let_is_optional_and_array_element_target():
    assert one("LET T(2) = QQ") == one("T(2)=QQ") == ast.Let(ast.Elem("T", (ast.Num(2.0),)), ast.Var("QQ"))


def test_statements_after_then_belong_to_then():
    stmt = one("IF A THEN B=1: C=2 ELSE D=3: E=4")
    assert [s.target.name for s in stmt.then] == ["B", "C"]
    assert [s.target.name for s in stmt.otherwise] == ["D", "E"]


def test_else_binds_to_the_nearest_if():
    stmt = one("IF A THEN IF B THEN 10 ELSE 20")
    assert stmt.otherwise is None
    assert stmt.then[0] == ast.If(ast.Var("B"), 10, 20)


def test_then_and_goto_take_line_numbers():
    assert one("IF X THEN 500") == ast.If(ast.Var("X"), 500, None)
    assert one("IF X GOTO 500 ELSE 600") == ast.If(ast.Var("X"), 500, 600)


def test_next_with_two_names_is_two_nexts():
    assert parse_statements("NEXT J, I") == [ast.Next(ast.Var("J")), ast.Next(ast.Var("I"))]


def test_gosub_prog():
    assert one("GOSUB PROG 5") == ast.GosubProg(5)


def test_print_using_items():
    stmt = one('PRINT USING "###.#"; QQ; U(1)')
    assert stmt.using == ast.Str("###.#")
    assert stmt.items == [ast.Var("QQ"), ";", ast.Elem("U", (ast.Num(1.0),))]


def test_for_with_negative_step():
    stmt = one("FOR QQ = 360.1 TO .1 STEP - 20")
    assert stmt.step == ast.Unary("-", ast.Num(20.0))


def test_syntax_error_is_kept_on_the_line():
    line = parse_line(5070, "U(2): X=1")
    assert line.statements == [] and str(line.error.at(5070)) == "Syntax error in 5070"


def test_statements_before_a_bad_one_are_kept_in_gw():
    """GW-BASIC finds a bad token when it gets there: the statements before it run."""
    line = parse_line(5070, "PRINT 1: U(2): X=1", GW)
    assert line.error is None and line.statements[0] == ast.Print(False, [ast.Num(1, "%")])
    # U(2) without "=": the element is read first (LET's PTRGET), then the Syntax error
    touched = line.statements[1]
    assert touched.target == ast.Elem("U", (ast.Num(2, "%"),)) and str(touched.error) == "Syntax error"
    assert str(parse_line(5070, "PRINT 1: 3: X=1", GW).statements[1]) == "Syntax error"


def test_error_after_then_belongs_to_the_branch():
    (stmt,) = parse_line(10, "IF A THEN PRINT 1: X", GW).statements
    assert stmt.then[0] == ast.Print(False, [ast.Num(1, "%")]) and str(stmt.then[1]) == "Syntax error"


@pytest.mark.parametrize("text, message", [
    ("X =", "Missing operand"), ("PRINT 1 +", "Missing operand"), ("FOR I = 1 TO", "Missing operand"),
    ("X = (", "Missing operand"), ("GOTO", "Syntax error"), ("PRINT (1", "Syntax error"),
    ("X = Y + * 2", "Syntax error"), ("SHELL \"DIR\"", "Unsupported word SHELL"),
])
def test_kind_of_grammar_error_in_gw(text, message):
    """As PC-BASIC 2.0.8 reports each (an operand expected where the statement ends); where
    what was read runs first (``PRINT 1 +``: an expression cut short) the error is its cut's."""
    line = parse_line(10, text, GW)
    assert str(line.error or _cut_error(line.statements)) == message


def _cut_error(node):
    """The error of the first cut (a BasicError, a CutShort's or CutExpression's) inside ``node``."""
    if isinstance(node, list):
        return next((found for found in map(_cut_error, node) if found is not None), None)
    if isinstance(node, (ast.CutExpression, ast.CutCall, ast.CutShort)):
        return node.error
    if isinstance(node, ast.Node):
        return _cut_error([getattr(node, name) for name in node._fields])
    return node if isinstance(node, BasicError) else None


def test_casio_reports_the_whole_line():
    assert str(parse_line(10, "X =").error) == "Syntax error"
    assert parse_line(10, "PRINT 1: X").statements == []
    assert str(parse_line(10, "PRINT VARPTR(7)").error) == "Unsupported word VARPTR"  # INKEY$ is a casio word


def test_line_number_must_be_whole():
    assert parse_line(10, "GOTO 1.5").error is not None


def test_precedence_of_relations_and_logic():
    stmt = one("A = 1 < 2 AND NOT 3 = 4 OR 0")
    assert stmt.value.op == "OR"
    assert stmt.value.left.op == "AND"


def test_a_gw_statement_the_scanner_cannot_read_is_bad_when_reached():
    # NAME is a reserved word, then a "$" no token starts with: the PRINT before it stays
    line = parse_line(10, 'PRINT "A": NAME$="": PRINT "B"', GW)
    assert line.error is None
    assert [type(s).__name__ for s in line.statements] == ["Print", "BasicError", "Print"]
    assert str(line.statements[1]) == "Syntax error"
    # casio keeps reporting the whole line (its errors are found before the line runs)
    assert str(parse_line(10, 'PRINT "A": X=1@').error) == "Syntax error"
