from yaseer.basic.errors import BasicError, DIVISION_BY_ZERO, ILLEGAL_FUNCTION_CALL


def test_error_line_names_line_and_area():
    assert str(BasicError("Division by zero", DIVISION_BY_ZERO).at(20, 5)) == "Division by zero in 20 (PROG 5)"
    assert str(BasicError("Syntax error", 2).at(4080)) == "Syntax error in 4080"


def test_python_area_error_gets_calling_line_once():
    err = BasicError("Mechanism cannot be assembled (PROG 2)", ILLEGAL_FUNCTION_CALL)
    err.at(4040).at(9999)
    assert str(err) == "Mechanism cannot be assembled (PROG 2) in 4040"
