"""A statement whose text goes wrong part-way runs its good start first, as GW-BASIC reads
and runs a statement left to right, and the whole statement is then one error.

- PRINT # cut inside its first item writes nothing to the file (GW reads the item before
  it prints anything: ``PRINT #1, ABS(`` finds the file, then Missing operand; yaseer used
  to end the file's row there, which put an empty row after every error line of PC-BASIC's
  recorded ABS test).
- An assignment whose value ends before its statement does (``A$ = "X" LPRINT``) is made,
  then Syntax error (FRMEVL stops at the first token that cannot go on with the value;
  GWMAIN.ASM NEWSTT then finds no ``:`` nor the line's end); where the next token could
  go on with the value (``A = 1 2`` is 12) there is no error.
- RESUME NEXT after an error inside such a statement goes on after the whole statement,
  not at its cut (``PRINT FNX; ABS(``: Undefined user function, then the next statement).

Each case against PC-BASIC 2.0.8, which agrees with the source here."""

import pytest

from test_gw_files import both_runs, pcbasic_run, yaseer_run

FILE_CUTS = ['PRINT #1, ABS(', 'PRINT#1, ABS(', 'PRINT #1, "A"; ABS(', 'PRINT #1, "A", ABS(', 'PRINT #1, 1 + ',
             'PRINT #1, USING "##"; ABS(', 'PRINT #1, (', 'PRINT #1, "A";: PRINT #1, ABS(']

SCREEN_CUTS = [
    'PRINT ABS(', 'PRINT FNX; ABS(', 'PRINT 1/0; ABS(', 'WRITE FNX, 1,', 'PRINT A(11); ABS(',
    'PRINT "A"; ABS(: PRINT "Q"',
    'A = 1 LPRINT', 'A$ = "X" "Y"', 'A = B C', 'A = 1 2', 'A = 2 ELSE 5', 'LSET A$ = "4" LPRINT',
    'MID$(A$, 1) = "Z" X', 'A = (1) 3', 'A = 1 +', 'LET A = 5 PRINT', 'A = FNX Y', 'A(1) = 7 8 9', 'A = -',
    'A = 1: B = 2 C', 'A = NOT 1 Q', 'A = 1E3 4', 'A = 1 .5', 'A = 1 X: PRINT "Q"', 'A% = 40000 X',
    'A = A(11) X', 'A$ = "X" + "Y" Z', 'A = 1 AND 2 3',
]


@pytest.mark.parametrize("cut", FILE_CUTS)
def test_a_cut_print_to_a_file_writes_what_pcbasic_writes(tmp_path, cut):
    source = ('10 OPEN "O.TXT" FOR OUTPUT AS 1: ON ERROR GOTO 100\n'
              f'20 {cut}\n30 PRINT #1, "B": CLOSE: END\n100 PRINT #1, ERR; ERL: RESUME NEXT\n')
    ours, theirs, our_files, their_files = both_runs(source, tmp_path)
    assert (ours, our_files) == (theirs, their_files)


@pytest.mark.parametrize("cut", SCREEN_CUTS)
def test_a_statement_cut_short_runs_its_start_then_fails_as_one(tmp_path, cut):
    source = (f'10 ON ERROR GOTO 100\n15 A$ = "AB"\n20 {cut}\n30 PRINT A; A$; B; A(1): END\n'
              '100 PRINT "E"; ERR; ERL: RESUME NEXT\n')
    assert yaseer_run(source, tmp_path) == pcbasic_run(source, tmp_path)
