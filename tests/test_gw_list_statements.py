"""DIM, ERASE and CLOSE as GW-BASIC runs them (BIPTRG.ASM DIM: DIMFLG set, then PTRGET for each name, DIMCON
between them), each case against PC-BASIC 2.0.8, which agrees with the source and with
PC-BASIC's DIM test recorded on a real GW-BASIC:

- a name without subscripts is the simple variable (PTRGET reads no ``(``), not an array
  of ten: ``DIM A: DIM A(1)`` is no error;
- an array the program made by using it is dimensioned already: a DIM of it is Duplicate
  Definition (PTRGET with DIMFLG finds it);
- the arrays before a bad item are dimensioned before the error (``DIM A(1), B(`` makes
  A), and the error ends the whole statement for RESUME NEXT; so does ERASE (``ERASE A,``
  erases A, then Syntax error: GWMAIN.ASM ERASE, an array at a time; PC-BASIC's ERASE test
  recorded on a real GW-BASIC agrees), and CLOSE (``CLOSE 1,`` closes file 1, then Missing
  operand: GIO86.ASM CLOSE; PC-BASIC's recorded CLOSE test)."""

import pytest

from test_gw_files import both_runs, pcbasic_run, yaseer_run

pytestmark = pytest.mark.filterwarnings("ignore::DeprecationWarning")

PROGRAMS = [
    '10 DIM A\n20 DIM A(1): A = 5: PRINT A; A(1)\n30 DIM Q$: DIM Q$(3): PRINT "ok"\n',
    '10 DEFINT A: DIM A: A = 2.6: PRINT A: DIM A: DIM A(2), A: PRINT "x"\n',
    '10 PRINT A(1): DIM A(1): PRINT "no"\n',
    '10 B(3) = 4: ERASE B: DIM B(30): B(25) = 2: PRINT B(25); B(3)\n',
    '10 FOR I = 1 TO 3: C(I) = I: NEXT: CLEAR: DIM C(40): PRINT C(40)\n',
]
CUTS = ['DIM A(1), B(', 'DIM A(1),', 'DIM A(1), B(2), C', 'DIM Q(2), Q(3),', 'DIM A(1) B', 'DIM A(1),,B(2)',
        'DIM A(-1), B(', 'DIM [', 'DIM A B', 'DIM A(1) 5', 'DIM A(1), B(2) "X"', 'DIM A(B(1)) X', 'DIM A(1)) ']


@pytest.mark.parametrize("source", PROGRAMS)
def test_dim_runs_as_pcbasic(tmp_path, source):
    assert yaseer_run(source, tmp_path) == pcbasic_run(source, tmp_path)


@pytest.mark.parametrize("cut", CUTS)
def test_a_bad_dim_dimensions_the_arrays_before_its_error(tmp_path, cut):
    source = (f'10 ON ERROR GOTO 100\n20 {cut}\n30 PRINT A(1); B(2): DIM A(1): END\n'
              '100 PRINT ERR; ERL: RESUME NEXT\n')
    assert yaseer_run(source, tmp_path) == pcbasic_run(source, tmp_path)


ERASE_CUTS = ['ERASE A, B(', 'ERASE A,', 'ERASE A B', 'ERASE Q', 'ERASE A, Q,', 'ERASE A(1)', 'ERASE A, B, Q,',
              'ERASE LPRINT', 'ERASE "!"']


@pytest.mark.parametrize("cut", ERASE_CUTS)
def test_a_bad_erase_erases_the_arrays_before_its_error(tmp_path, cut):
    source = (f'10 ON ERROR GOTO 100\n15 DIM A(2), B(2)\n20 {cut}\n30 DIM A(3): DIM B(3): END\n'
              '100 PRINT ERR; ERL: RESUME NEXT\n')
    assert yaseer_run(source, tmp_path) == pcbasic_run(source, tmp_path)


CLOSE_CUTS = ['CLOSE 1,', 'CLOSE 1, 2,', 'CLOSE ,1', 'CLOSE 1 2', 'CLOSE 1,,2', 'CLOSE #1, #']


@pytest.mark.parametrize("cut", CLOSE_CUTS)
def test_a_bad_close_closes_the_files_before_its_error(tmp_path, cut):
    source = (f'10 ON ERROR GOTO 100\n15 OPEN "A" FOR OUTPUT AS 1: OPEN "B" FOR OUTPUT AS 2\n20 {cut}\n'
              '30 OPEN "C" FOR OUTPUT AS 1: OPEN "D" FOR OUTPUT AS 2: END\n100 PRINT ERR; ERL: RESUME NEXT\n')
    ours, theirs, our_files, their_files = both_runs(source, tmp_path)
    assert (ours, sorted(our_files)) == (theirs, sorted(their_files))


def test_casio_replaces_an_implicit_array_and_reads_dim_a_as_ten(tmp_path):
    assert yaseer_run("10 A(1) = 1: DIM A(20): A(20) = 2: DIM B: B(10) = 3: PRINT A(20); B(10)\n",
                      tmp_path, dialect="casio") == " 2  3 \n"
