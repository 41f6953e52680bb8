"""The BASIC dialect a machine speaks: one small frozen object of data.

A :class:`Dialect` says how the scanner reads names, which number model the
compiler and runtime use, how PRINT shows numbers and wraps lines, what an
arithmetic error does at run time, and what the machine holds when a program
starts.  The scanner, compiler, runtime and machine consult its fields; no
code asks "which dialect is this?".

Two dialects exist:

* :data:`CASIO` (``--dialect casio``, the default): the paper's pocket
  computer (Casio FX-850P family), exactly as yaseer has always run it.
* :data:`GW` (``--dialect gw``): GW-BASIC 3.23 as PC-BASIC 2.0.8 reproduces
  it; where the two disagree, Microsoft's GW-BASIC assembly source decides
  (see docs/compatibility.md).

Field names are stable: other modules build on them.  A dialect is a named tuple
(immutable; ``dialect._replace(field=value)`` makes a variant) made by
``collections.namedtuple``, not a dataclass or a ``typing.NamedTuple``: importing
dataclasses or typing costs every start milliseconds.
"""

from __future__ import annotations

from collections import namedtuple

from yaseer.basic.arithmetic.values import MBF_READING
from yaseer.basic.arithmetic.randomness import GwRandom, RepeatableRandom
from yaseer.basic.dialects.charset import CASIO as CASIO_CHARACTERS, CASIO_CONTROLS, CP437, LATIN1
from yaseer.basic.dialects import casio as casio_words
from yaseer.basic.dialects import gw_words
from yaseer.basic.dialects.screens import CASIO_SCREEN, GW_CONTROLS, GW_SCREEN

# The paper's universal line 2: these arrays exist with these sizes from the start
# (one dimension, subscripts 0..size).
AL_YASEER_DIMENSIONS = (
    ("F", 46), ("M", 11), ("R", 19), ("H", 24), ("A", 53), ("L", 20), ("T", 25), ("W", 10),
    ("Z", 5), ("C", 14), ("U", 4), ("D", 6), ("E", 6), ("X", 11), ("Y", 11), ("V", 21),
    ("Q", 4), ("N", 3), ("I", 11), ("P", 4),
)


# GW-BASIC's random-access file statements (yaseer/basic/machine/random_files.py)
RANDOM_FILE_WORDS = ("FIELD", "GET", "PUT", "LSET", "RSET", "RESET")
# ... and the statements that load other programs into a running one (yaseer/basic/machine/chaining.py)
CHAIN_WORDS = ("CHAIN", "COMMON", "MERGE", "DELETE")
# ... the commands a program may also run (LIST, SAVE, RUN "file"...) and KEY ON/OFF
COMMAND_WORDS = ("RUN", "LIST", "LLIST", "LOAD", "SAVE", "NEW", "EDIT", "RENUM", "AUTO", "KEY", "OFF", "SYSTEM")
# ... and the text screen's (yaseer/basic/machine/display.py) and keyboard's
SCREEN_WORDS = ("LOCATE", "CSRLIN", "COLOR", "SCREEN", "VIEW", "INKEY$")
# ... and the graphics statements' own words (machine/graphics.py; LINE, VIEW, GET, PUT
# are read as graphics statements where their form is: source/graphics_syntax.py)
GRAPHICS_WORDS = ("PSET", "PRESET", "WINDOW", "PALETTE", "CIRCLE", "PAINT", "DRAW")
# ... and the machine-code function USR (DEF USR sets its address)
MACHINE_WORDS = ("USR",)

# The devices GW-BASIC opens by name (machine/device_files.py): its own (GIOTBL.ASM's
# SCRN, KYBD, CONS, LPTn, CASn, COMn, with a colon) and DOS's (without)
GW_DEVICES = (
    ("SCRN:", "screen"), ("LPT1:", "printer"), ("KYBD:", "keyboard"), ("CONS:", "screen"), ("LPT2:", "absent"),
    ("LPT3:", "absent"), ("CAS1:", "absent"), ("COM1:", "absent"), ("COM2:", "absent"),
    ("CON", "screen"), ("NUL", "null"), ("PRN", "printer"), ("LPT1", "printer"), ("LPT2", "absent"),
    ("LPT3", "absent"), ("AUX", "absent"), ("COM1", "absent"), ("COM2", "absent"), ("COM3", "absent"),
    ("COM4", "absent"), ("CLOCK$", "absent"),
)

FIELDS = (
    "name",  # str: casio, gw
    "keyword_first",  # bool
    "pi_keyword",  # bool
    "own_words",  # tuple[str, ...]
    "typed_numbers",  # bool
    "print_digits",  # int
    "width",  # int | None
    "zone",  # int
    "on_division_by_zero",  # str: stop, continue
    "on_overflow",  # str: stop, continue
    "angle",  # str: DEG, RAD
    "implicit_arrays",  # tuple[tuple[str, int], ...]
    "default_dimension",  # int
    "program_areas",  # bool
    # with defaults (the Casio's):
    "random",  # type: RepeatableRandom
    "errors_when_reached",  # bool: False
    "comma_trims_number",  # bool: False
    "for_binds_next",  # bool: False
    "arithmetic",  # str: binary
    "number_reading",  # values.NumberReading | None: None
    "printer_width",  # int | None: None
    "display",  # tuple[int, int, int] | None: None
    "controls",  # tuple[tuple[int, str], ...]: ()
    "charset",  # CharacterSet: LATIN1
    "enter_key",  # str: "\n"
    "empty_input_keeps",  # bool: False
    "library_forms",  # bool: False
    "file_devices",  # tuple[str, ...]: ()
    "joins_unnumbered_lines",  # bool: True
    "names_missing_line",  # bool: True
    "spaced_relations",  # bool: False
    "bracket_subscripts",  # bool: False
    "words",  # casio.Words | None: None
    "names_keep_case",  # bool: False
    "name_length",  # int | None: None
    "hex_literals",  # bool: False
    "screen",  # ScreenRules: CASIO_SCREEN
    "string_length",  # int: 255
    "free_memory",  # int | None: None
    "variables_made",  # bool: False
    "tokenised_programs",  # bool: False
    "current_line_commands",  # tuple[str, ...]: ()
    "current_line_listed",  # bool: False
    "read_commits",  # bool: False
    "direct_line_number",  # int | None: None
    "edit_clears",  # bool: False
    "handler_must_resume",  # bool: False
    "for_array_elements",  # bool: True
    "untrapped_errors_noted",  # bool: False
    "using_digits",  # int | None: None
    "else_alone_skips",  # bool: False
    "saves_going_on",  # tuple[str, ...]: ()
    "using_each_value",  # bool: False
    "delete_needs_last_line",  # bool: False
    "eof_of_file_zero",  # bool: False
    "input_answer_first",  # bool: False
    "dim_name_alone_scalar",  # bool: False
    "dim_after_use_duplicate",  # bool: False
    "device_files",  # tuple[tuple[str, str], ...]: ()
    "nameless_file_error",  # int: 64 (Bad file name)
    "def_seg_usr",  # bool: False
    "device_words",  # gw_words.Words | None: None
    "not_after_operator",  # bool: False
    "argument_readings",  # tuple[str, ...]: ()
    "dos_program_lines",  # bool: False
    "open_clauses",  # bool: False
    "clear_readings",  # tuple[str, ...]: ()
    "line_number_digits",  # bool: False
    "data_segment",  # DataSegmentRules | None: None
    "point_after_name_is_text",  # bool: False
    "bare_line_must_exist",  # bool: False
    "line_dot_words",  # tuple[str, ...]: ()
    "edit_tail_error",  # int | None: None
)
DEFAULTS = (RepeatableRandom, False, False, False, "binary", None, None, None, (), LATIN1, "\n", False, False, (),
            True, True, False, False, None, False, None, False, CASIO_SCREEN, 255, None, False, False, (), False, False,
            None, False, False, True, False, None, False, (), False, False, False, False, False, False, (), 64, False, None, False, (),
            False, False, (), False, None, False, False, (), None)

# Where BASIC's data segment puts the program and the strings (offsets in the segment, bytes;
# machine/data_segment.py): ``text_start`` the program's first line (TXTTAB), ``string_top``
# the end of the string space (its first string ends there), ``memory_top`` the top of
# BASIC's memory as the segment's pointer at &H2C holds it.
DataSegmentRules = namedtuple("DataSegmentRules", "text_start string_top memory_top")


class Dialect(namedtuple("Dialect", FIELDS, defaults=DEFAULTS)):
    """Everything that differs between the BASICs yaseer runs (all plain data).

    Scanner rules
        ``keyword_first``: True reads keywords wherever they start inside a run
        of letters (``COST`` is ``COS T``, ``FORI=1TO3`` is ``FOR I = 1 TO 3``),
        as the pocket computers' tokenisers do; False reads a name whole, as
        GW-BASIC does (``COST`` is a variable; a keyword counts only when the
        run of letters does not continue it into a longer name).
        ``spaced_relations``: True reads two relation characters with blanks between
        them as one operator (``A = > B`` is ``A >= B``, ``< =`` is ``<=``: GW-BASIC's
        evaluator skips blanks while it collects ``<`` ``=`` ``>``, GWEVAL.ASM).
        ``bracket_subscripts``: True lets ``[`` and ``]`` stand for the parentheses of a
        subscript (``A[2]``, even ``A[2)``), but nowhere else (GW-BASIC's PTRGET).
        ``pi_keyword``: True makes ``PI`` the constant pi (a Casio keyword);
        False leaves it an ordinary variable name (GW-BASIC has no PI).
        ``own_words``: keywords only this dialect reserves, on top of the
        common ones in scanner.py (Casio: ``DEG RAD XOR EQV IMP``; GW: ``DEFINT DEFSNG
        DEFDBL DEFSTR XOR EQV IMP``).  ``PI`` and ``PROG`` are reserved by
        ``pi_keyword`` and ``program_areas``.

    Number model
        ``typed_numbers``: False is the pocket computer's one numeric type
        (every number a Python float, i.e. a double, shown to ``print_digits``);
        True is GW-BASIC's typed model: ``%`` 16-bit integers, ``!`` single
        precision (the default type of a name without suffix), ``#`` double
        precision, ``$`` strings, with DEFINT/DEFSNG/DEFDBL/DEFSTR, literal
        suffixes and ``&H``/``&O`` literals.

        ``arithmetic``: ``"binary"`` (IEEE doubles, or GW's types) or
        ``"decimal"`` (``--arith decimal``, casio only: 12-digit decimal
        arithmetic as the FX-850P family's BCD, yaseer/basic/arithmetic/decimal_arith.py).

    Print rules
        ``using_digits``: the most digit positions a PRINT USING numeric field may have
        (GW-BASIC's 24, BIPRTU.ASM: the positions before the point, ``**`` and ``$$``
        two, ``**$`` three, each comma and a leading ``+`` one, plus the point and the
        ``#`` after it; a field with more is ``Illegal function call`` when a value
        reaches it); None: no limit (casio, whose manual has no PRINT USING).
        ``using_each_value``: True evaluates each value of a PRINT USING list when its
        field is reached, after the literal text before the field is printed and the
        fields before it (GW-BASIC, BIPRTU.ASM: FRMEVL inside the loop that scans the
        format), so a value sees the cursor (``POS(0)``) and a value's message or error
        comes after the fields before it; False evaluates the whole list first (casio,
        whose manual has no PRINT USING: yaseer's way kept).
        ``print_digits``: significant digits PRINT and STR$ show for the
        default numeric type (10 on the 10-digit Casio display; 7 for
        GW-BASIC's single precision; GW doubles show 16).
        ``width``: the screen width in columns at which PRINT wraps lines
        (``None``: never wrap, the Casio behaviour as yaseer runs it; 80 for
        GW-BASIC, changed with ``WIDTH n``).
        ``zone``: columns per ``,`` print zone (14 in both).
        ``printer_width``: where LPRINT wraps (``None`` never; GW-BASIC's printer:
        80, changed with ``WIDTH LPRINT n``).
        ``comma_trims_number``: True drops the trailing blank of a number a
        ``,`` follows when the number ends one column before a zone (the published
        GW-BASIC source, GIO86.ASM ``MODCOM``), so the comma moves one column instead
        of a whole zone.  No dialect sets it: a real GW-BASIC 3.23 keeps the blank
        (PC-BASIC's recorded PRFLOAT and DATEFN tests), as PC-BASIC 2.0.8 does.

        ``random``: the class of RND's generator (yaseer/basic/arithmetic/randomness.py):
        ``RepeatableRandom`` (Python's, seed 0 at RUN) or ``GwRandom``
        (GW-BASIC's own 24-bit sequence, as PC-BASIC reproduces it).

    Program files
        ``joins_unnumbered_lines``: True (Casio, as the paper prints its listings)
        joins a line of a program file that has no line number onto the line
        before; False (GW-BASIC's LOAD, DSKCOM.ASM) stops loading there with
        ``Direct statement in file``, the lines before it loaded.
        ``dos_program_lines``: True (GW-BASIC) reads a program file's lines as its
        ASCII LOAD does (SCNEDT.ASM DSKCHI, GWMAIN.ASM MAIN and LINGET;
        scanner.dos_lines): a line ends at a CR, a LF inside it is part of it, more
        than 255 characters is ``Line buffer overflow``; a line number takes digits
        while it is at most 6552 (the rest is the line's text) and one blank after it
        is skipped unless it is 0.  False: a line ends at CR LF, CR or LF.
        ``open_clauses``: True (GW-BASIC 3.23) reads OPEN's ``ACCESS READ|WRITE|READ
        WRITE`` and ``SHARED``/``LOCK READ|WRITE|READ WRITE`` clauses after its FOR
        mode (machine/file_locks.py decides what they allow); False: they are
        Syntax errors.
        ``clear_readings``: how CLEAR reads its places, one reading each (machine/variables.py
        clear_argument; GW-BASIC: ``("whole", "top", "stack")``, BIMISC.ASM CLEAR): each checked
        as it is read, more places or an empty last place after a comma a Syntax error there
        (``CLEAR ,`` as a real GW-BASIC 3.23 recorded it in PC-BASIC's CLEARERR test, where the
        published source would clear).  Empty (casio): the sizes given are evaluated, a negative
        first one Illegal function call, any number of places.
        ``line_number_digits``: True (GW-BASIC) reads a number after a word that takes line
        numbers (scanner.LINE_NUMBER_WORDS: GOTO, THEN, ELSE, ERL, RESTORE ...), and after each
        blank, comma or operator that follows, up to another word, a name or a colon, as a line
        number: digits only, at most 65529, a ``.`` a number of its own (GWMAIN.ASM CRUNCH's
        DONUM, LINRES and LINGET), so ``ERL(1.5)`` and ``ERL(65536)`` are Syntax errors and
        ``ERL(32768)`` is ERL, then 32768 (recorded in PC-BASIC's ERL test).  False (casio):
        numbers are read alike everywhere.
        ``point_after_name_is_text``: True (GW-BASIC 3.23): a number that begins with
        ``.`` after a name and blanks (``OPEN "a" FOR OUTPUT AS .6``, ``PRINT A .5``) is a
        Syntax error where it is read: CRUNCH keeps digits and points after a name as
        text (GWMAIN.ASM, its number flag left as a name's), and EVAL reads no number
        from a ``.`` there (GWEVAL.ASM EVAL: FIN only for a digit); False: it is a number.
        ``bare_line_must_exist``: True (GW-BASIC) reads a program file's line number
        with nothing after it as the line typed so: it deletes that line, and where
        there is none loading stops with ``Undefined line number``, the lines before it
        loaded (GWMAIN.ASM EDENT: FNDLIN, then USERR); False: it deletes the line, if any.

    Messages
        ``names_missing_line``: True (Casio, as yaseer has always named it) says which
        line a jump missed (``Undefined line number 5200 in 5030``); False prints
        GW-BASIC's message as its table has it (``Undefined line number in 5030``).

    The machine's own words
        ``words``: the module of tables of the words only this dialect has
        (yaseer/basic/dialects/casio.py: the FX-850P's functions such as LN, FACT,
        ROUND, POL, its statements such as ANGLE, POKE, SET, and ERR's error codes);
        None for GW-BASIC.  The scanner reads them as keywords, the compiler finds
        their functions and statements there, the machine its ERR codes.
        ``names_keep_case``: True makes ``a`` and ``A`` two variables (the Casio
        manual lists both as names; keywords are still read in either case).
        ``name_length``: the longest name (15 on the Casio); None: no limit.
        ``device_words``: the tables of GW-BASIC's words for the PC's ports, environment,
        speaker, file locks and machine code (yaseer/basic/dialects/gw_words.py: INP, OUT,
        ENVIRON$, LOCK, CALL ...), read as keywords and run by machine/devices.py; None: no
        such words (casio).
        ``hex_literals``: True reads ``&H1F`` as a number (the Casio's ``&H``, 0..&HFFFF)
        in a dialect without typed numbers.

    Syntax errors
        ``argument_readings``: where not empty, a function call whose arguments do not fit
        the function is read as GW-BASIC's routines read it, argument by argument, each
        checked as it is read before the ``,`` or ``)`` after it is looked for (``INSTR(-1)``
        Illegal function call, ``LEFT$(1)`` Syntax error, ``INSTR(1, 1, 1, 1)`` Type mismatch:
        machine/argument_reading.py), and a call the text cuts short evaluates what it read
        first; the names are the functions with readings of their own there (BISTRS.ASM
        INSTR, STRNG$; GWEVAL.ASM ISFUN's LEFT$, RIGHT$, MID$), every function of one
        argument reads ``(``, it, ``)`` (GWEVAL.ASM PARCHK).  Empty (casio): such a call is
        the statement's error.
        ``not_after_operator``: True when NOT may stand as any operator's right operand,
        taking what follows as far as a NOT at the start would (``13*NOT 7`` is
        ``13*(NOT 7)``, ``10^NOT 0+1`` is ``10^(NOT 1)``: GWEVAL.ASM EVAL meets the NOT
        token where an operand starts and reads on at NOT's precedence); False (casio, as
        yaseer always read it): only a sign may come before NOT there, else Syntax error.
        ``errors_when_reached``: True (GW-BASIC) runs a line statement by
        statement up to a bad one, which is the error when execution reaches
        it (``10 PRINT 50: X`` prints 50, then ``Syntax error in 10``), and an
        expression cut short by the end of its statement is ``Missing
        operand``; False (Casio, as yaseer always ran the listings) makes a bad
        line a ``Syntax error`` before any of it runs.

    FOR and NEXT
        ``for_binds_next``: True (GW-BASIC, as PC-BASIC 2.0.8 runs it) binds a
        FOR, when it runs, to the NEXT it finds scanning forward (FORs and NEXTs
        met on the way counted): none is ``FOR without NEXT``, one naming another
        variable ``NEXT without FOR``, and any other NEXT of the variable is
        ``NEXT without FOR``; False (Casio, classic Microsoft BASIC) lets any NEXT
        of the variable continue the loop.

    Run-time error policy
        ``on_division_by_zero`` and ``on_overflow``: ``"stop"`` ends the run
        with the error (Casio); ``"continue"`` prints GW-BASIC's message and
        goes on with the signed largest value, unless ON ERROR traps it.
        ``number_reading``: how VAL, INPUT, READ and INPUT # read digits when the
        machine's numbers are not IEEE doubles (``None``: the double the digits name, and
        beyond 1.8E+308 an ``Overflow`` error).  GW-BASIC's (``MBF_READING``) reads them
        as ``$FIN`` does, into 56-bit Microsoft Binary Format doubles, which end where its
        singles do, at 2**127 (printed 1.701411834604692D+38); a number read beyond it
        follows ``on_overflow``.

    Display and keyboard
        ``display``: ``(columns, rows, shown)`` of the machine's screen model
        (yaseer/basic/machine/display.py): casio's 32 x 8 virtual screen with its 2-line
        LCD, gw's 80 x 25 text screen; None: no screen model (PRINT is a stream of text).
        ``controls``: ``(code, action)`` pairs, what each control code does on
        that display.  ``screen``: the display's rules (yaseer/basic/dialects/screens.py:
        when the cursor wraps, where LOCATE counts from, the function-key line).
        ``free_memory``: the bytes FRE reports with no program (GW-BASIC's 60300, less
        what the program and its variables take in GW's layout: machine/memory_model.py);
        None: FRE is what is left of yaseer's array budget.  ``charset``: the machine's character codes
        (yaseer/basic/charset.py): what CHR$ and ASC answer, how program and data
        files' bytes read.  ``enter_key``: the character INPUT$ and INKEY$ read for
        a line break of the key stream (casio: EXE, ``CHR$(13)``).
        ``empty_input_keeps``: True (casio, the INPUT page: "a numeric variable
        retains its current value") makes an empty answer to INPUT keep the
        numeric variables' values; False reads it as 0 (GW-BASIC).
        ``input_answer_first``: True (GW-BASIC) when INPUT shows its question and reads the
        answer before it reads its names (GWMAIN.ASM INPUT: QTINP and SINLIN, then PTRGTN):
        an INPUT with no names or a list ending in a comma asks, takes the answer, then is
        Syntax error; and ``INPUT;`` / ``LINE INPUT;`` (a semicolon first: SCNSEM) leave the
        cursor after the answer.  False (casio): those forms are Syntax error.
        ``def_seg_usr``: True (GW-BASIC) makes ``DEF SEG [= s]`` a statement (the segment
        PEEK, POKE, BLOAD would use: GWEVAL.ASM DEF stores SAVSEG) and ``DEF USR[n] = a``
        (the address of machine code: DEFUSR); a USR call then runs no machine code:
        ``Illegal function call``.  False (casio): Syntax error (its DEFSEG is one word).
        ``library_forms``: True (casio) accepts what Becker's library for the
        FX-850P writes and the manual does not describe: ``THEN *`` (the program
        ends there; docs/compatibility.md).
        ``file_devices``: device names a file name may start with that mean the
        program's one directory (casio: ``CAS0:``, ``CAS1:``, the cassette).
        ``device_files``: ``(name, kind)`` pairs, the devices OPEN knows by name
        (machine/device_files.py): ``NAME:`` the BASIC's own (GW-BASIC's GIOTBL.ASM table;
        another name with a colon after two or more characters is ``Bad file name``),
        ``NAME`` DOS's, whatever extension follows, and never made a file of the directory.

    Start-up environment
        ``angle``: ``"DEG"``, ``"RAD"`` (or, after ANGLE 2, ``"GRA"``), the unit of SIN COS
        TAN ATN at RUN.
        ``implicit_arrays``: ``(name, size)`` pairs of one-dimensional arrays
        that exist with those sizes before any DIM (the Al-Yaseer arrays in
        Casio; none in GW).
        ``default_dimension``: the largest subscript of an array used
        without DIM (10 in both: subscripts 0..10).
        ``variables_made``: True when a simple variable exists only once a statement
        has made it (GW-BASIC's PTRGET makes it on an assignment, INPUT, READ, FOR, a
        DEF FN parameter, SWAP, but not when an expression reads it: BIPTRG.ASM SMKVAR),
        so that SWAP's second variable must exist (BIMISC.ASM SWAP: Illegal function call).
        ``tokenised_programs``: True when the machine keeps a program as GW-BASIC's tokens
        (GWMAIN.ASM CRUNCH, machine/program_crunch.py): LIST and SAVE ,A show the tokens
        listed back (GWLIST.ASM), a plain SAVE writes them (0xFF, GIODSK.ASM BINSAV), and a
        typed line keeps its blanks but the one after its number (GWMAIN.ASM MAIN:
        "one space always printed after line #"); False: LIST shows the dialect's own
        listing (scanner.detokenize) and SAVE writes it.
        ``current_line_commands``: the session's commands that read ``.`` as the current
        line (casio's LIST, LLIST, EDIT: LIST.md item 4, EDIT.md item 2; gw's LIST, LLIST,
        DELETE, EDIT, AUTO's start and RENUM's first two numbers: GWMAIN.ASM LINSPC, called
        by SCNLIN, AUTO and RESEQ, and SCNEDT.ASM EDIT).  ``current_line_listed``: True
        (GW's DOT) when LIST and LLIST make the last line they show the current line and a
        run changes it only by an error or Break (GWLIST.ASM LIST, GWMAIN.ASM's error
        path), and ``.`` before any such line is line 0; False (casio): the line last run is
        the current one, and ``.`` before any is a Syntax error.
        ``read_commits``: True when the DATA pointer moves only as a READ ends (GWMAIN.ASM
        READ keeps it on the stack, BIMISC.ASM RESFIN stores DATPTR): a READ that fails
        leaves it where that READ started, and a numeric variable is given the number at
        the start of an item that is not one (0 if none) before the Syntax error in the
        DATA line (DOASIG assigns, STRDN2 then finds no comma: TRMNOK, DATSNE).
        ``direct_line_number``: the line number a direct statement runs under (GW's 65535:
        GWMAIN.ASM ERROR stores CURLIN in ERRLIN and traps through ONELIN whatever the line,
        so an ON ERROR GOTO left by a program catches a direct statement's error, ERL is
        65535, and RESUME [NEXT] goes back into the direct line); None (casio): a direct
        statement's error is never trapped (ON_ERROR_GOTO.md: "limited to BASIC program
        execution").
        ``edit_clears``: True when typing, replacing or DELETEing a program line in the
        session clears what RUN clears (variables, arrays, FN, DEF types, OPTION BASE, RND's
        seed, ON ERROR, open files, the stack; CONT impossible: GWMAIN.ASM FINI and GWLIST.ASM
        DELETE end in BIMISC.ASM RUNC/CLEARC); False (casio) keeps them.
        ``delete_needs_last_line``: True when the session's DELETE range must end on a line
        of the program and start before it, else ``Illegal function call`` (GWLIST.ASM
        DELETE: FNDLIN must find the upper bound, which SCNLIN makes 65530, above every
        line, when none is given; source/line_ranges.py); False (casio): any range removes
        the lines in it, a single missing line is the error.
        ``eof_of_file_zero``: True when EOF(0) is 0 rather than a file not open (a real GW-BASIC
        recorded it so in PC-BASIC's EOF test, where LOC(0) and LOF(0) are Bad file number).
        ``dim_name_alone_scalar``: True when a name without subscripts in DIM (``DIM A``) is the
        simple variable, found or made (BIPTRG.ASM DIM sets DIMFLG and calls PTRGET, which
        reads a name with no ``(`` as a simple variable; recorded on a real GW-BASIC in
        PC-BASIC's DIM test, and PC-BASIC 2.0.8 agrees); False (casio, whose DIM page knows
        only arrays): ``DIM A`` is ``DIM A(10)``.
        ``dim_after_use_duplicate``: True when DIM of an array the program has already made by
        using it (its implicit size) is ``Duplicate Definition`` (BIPTRG.ASM: PTRGET with
        DIMFLG set finds the array: "doubly dimensioned"; PC-BASIC 2.0.8 agrees); False
        (casio): DIM replaces the implicit array.
        ``nameless_file_error``: the error code of a file or program name that names nothing:
        empty, blanks before any ``.``, or starting with CHR$(0) (DOS reads the name up to a
        NUL and drops trailing blanks).  GW: 52, Bad file number, as a real GW-BASIC recorded
        ``SAVE ""`` and ``OPEN CHR$(0) ...`` in PC-BASIC's SAVE and OPEN_null tests
        (PC-BASIC 2.0.8 agrees for ``""``); casio: 64, Bad file name (the manual's nameless
        file is the cassette's, which yaseer has not).  Such a name never makes a file.
        ``handler_must_resume``: True when running off the program's last line inside an
        error handler is the error No RESUME in the last line run (GWMAIN.ASM PRGEND: ONEFLG
        still set); END leaves a handler quietly in both dialects. False (casio, whose RESUME
        page is silent): the run ends.
        ``for_array_elements``: True when a FOR's control variable may be an array element
        (the paper's Example 3: ``FOR T(2) = .1 TO 360.1``, although FOR_NEXT_STEP.md item 1
        says array variables cannot be used: the paper's listings decide); False (GW: FOR
        sets SUBFLG so PTRGET reads ``A`` alone and SYNCHR "=" meets the ``(``, GWMAIN.ASM
        FOR): such a FOR is a Syntax error, before its variable's type is looked at.
        ``line_dot_words``: the words after which a lone ``.`` is no line number (GWMAIN.ASM
        CRUNCH stores a ``.`` after a line-number word as a plain character, never a line
        constant): after GOTO, GOSUB, THEN, ELSE (GOTO2 wants a line constant, else
        Syntax error) and RESUME (LINGET reads no digits and the statement has not ended:
        Syntax error) it is a Syntax error; RUN's is no line constant, so RUN reads it as a
        file name expression (DSKCOM.ASM LRUN, GIO86.ASM NAMSCN: the number 0, Type
        mismatch).  ``()`` (casio): ``.`` there is the number it reads as.
        ``edit_tail_error``: the error code of an EDIT whose line number (or ``.``) is
        followed by more of the statement (SCNEDT.ASM EDIT: LINSPC, then EFCERR when the
        statement has not ended: 5, Illegal function call); None: the statement's Syntax error.
        ``untrapped_errors_noted``: True when an error no handler takes still sets ERR and
        ERL (65535 for a direct line) and leaves a handler that was running (GWMAIN.ASM ERROR
        stores ERRLIN and ERRFLG before NTMDCN looks for a trap; NOTRAP resets ONEFLG), so
        ``PRINT ERR; ERL`` typed after a program stopped shows its error; False (casio:
        ERR.md, "can only be changed within a program"): only a trapped error sets them.
        ``else_alone_skips``: True when an ELSE no IF before it in the line owns is a
        statement that skips the rest of the line, as REM (GW-BASIC's cruncher puts a colon
        before every ELSE and GWMAIN.ASM ELSES is REM: ``10 ELSE PRINT 1`` does nothing,
        ``PRINT 1 ELSE PRINT 2`` prints 1); False: such an ELSE is a Syntax error.
        ``saves_going_on``: the options of a SAVE in a program after which the program
        goes on with its next statement (GW-BASIC: a plain SAVE and ``,P``: GIO86.ASM BINSAV
        ends in DSKCOM.ASM PRGFIN and GIODSK.ASM PROSAV in GTMPRT, back to the statement
        after it; ``,A`` is done by LIST, which ends the run); () (casio: SAVE_SAVE_ALL.md
        item 7, command standby once SAVE is done): every SAVE ends the run.
        ``program_areas``: True when ``GOSUB PROG n`` is a statement (the
        library programs are bound at start); False in GW-BASIC, where PROG
        is no word: ``GOSUB PROG n`` is then a syntax error unless program
        areas are given explicitly (``--prog``).
    """

    __slots__ = ()

    def with_arithmetic(self, arithmetic: str) -> "Dialect":
        """This dialect computing in ``arithmetic`` ("binary" or "decimal"); decimal
        is the Casio's (ValueError for a typed dialect)."""
        if arithmetic == self.arithmetic:
            return self
        if arithmetic not in ("binary", "decimal") or self.typed_numbers:
            raise ValueError(f"--arith {arithmetic} is not for the {self.name} dialect (decimal is casio's)")
        return self._replace(arithmetic=arithmetic)

    def with_program_areas(self) -> "Dialect":
        """This dialect with ``GOSUB PROG n`` (``--prog`` gives areas in gw too)."""
        return self if self.program_areas else self._replace(program_areas=True)

    def implicit_size(self, name: str, ndim: int) -> int:
        """The largest subscript of array ``name`` with ``ndim`` dimensions used without DIM."""
        if ndim == 1:
            for array, size in self.implicit_arrays:
                if array == name:
                    return size
        return self.default_dimension


CASIO = Dialect(
    name="casio", keyword_first=True, pi_keyword=True,
    own_words=("DEG", "RAD", "XOR", "EQV", "IMP", "LOCATE", "INKEY$", "PEEK",
               "WRITE#", "READ#", "RESTORE#", "LIST#", "LLIST#", "NEW#", "SAVE#", "LOAD#")
    + casio_words.PROGRAM_COMMANDS,
    typed_numbers=False,
    print_digits=10,
    width=None, zone=14, on_division_by_zero="stop", on_overflow="stop", angle="DEG",
    implicit_arrays=AL_YASEER_DIMENSIONS, default_dimension=10, program_areas=True,
    display=(32, 8, 2), controls=tuple(sorted(CASIO_CONTROLS.items())), charset=CASIO_CHARACTERS, enter_key="\r",
    empty_input_keeps=True, library_forms=True, file_devices=("CAS0:", "CAS1:"),
    words=casio_words.WORDS, names_keep_case=True, name_length=15, hex_literals=True,
    string_length=255,  # the manual, part 6: string variables hold up to 255 characters (else ST error)
    current_line_commands=("LIST", "LLIST", "EDIT"),
)

GW = Dialect(
    name="gw", keyword_first=False, pi_keyword=False,
    own_words=("DEFINT", "DEFSNG", "DEFDBL", "DEFSTR", "XOR", "EQV", "IMP") + RANDOM_FILE_WORDS + CHAIN_WORDS
    + COMMAND_WORDS + SCREEN_WORDS + MACHINE_WORDS + GRAPHICS_WORDS,
    typed_numbers=True, print_digits=7,
    width=80, zone=14, on_division_by_zero="continue", on_overflow="continue", angle="RAD",
    implicit_arrays=(), default_dimension=10, program_areas=False, random=GwRandom,
    errors_when_reached=True, for_binds_next=True, number_reading=MBF_READING,
    printer_width=80, joins_unnumbered_lines=False, names_missing_line=False, spaced_relations=True,
    bracket_subscripts=True, display=(80, 25, 25), controls=tuple(sorted(GW_CONTROLS.items())), screen=GW_SCREEN,
    string_length=255,  # a string descriptor holds its length in one byte
    free_memory=60300, charset=CP437, tokenised_programs=True,
    current_line_commands=("LIST", "LLIST", "DELETE", "EDIT", "AUTO", "RENUM"), current_line_listed=True,
    variables_made=True,
    read_commits=True,
    direct_line_number=65535, edit_clears=True, handler_must_resume=True,
    for_array_elements=False, untrapped_errors_noted=True,
    using_digits=24, else_alone_skips=True, saves_going_on=("", "P"), using_each_value=True,
    delete_needs_last_line=True, eof_of_file_zero=True, input_answer_first=True, dim_name_alone_scalar=True,
    dim_after_use_duplicate=True, device_files=GW_DEVICES, nameless_file_error=52, def_seg_usr=True,
    device_words=gw_words.WORDS, not_after_operator=True,
    argument_readings=("INSTR", "STRING$", "LEFT$", "RIGHT$", "MID$", "PLAY", "SCREEN", "POINT", "PMAP"), dos_program_lines=True, open_clauses=True,
    clear_readings=("whole", "top", "stack"), line_number_digits=True,
    # GW-BASIC 3.23 with /F:3 /S:128, as the recordings of the real machine read it: the program
    # from 4718 (&H30), the first string ending at 65021 (PEEK of VARPTR(A$)), &H2C holding 65534
    data_segment=DataSegmentRules(text_start=4718, string_top=65021, memory_top=65534),
    point_after_name_is_text=True,
    bare_line_must_exist=True,
    line_dot_words=("GOTO", "GOSUB", "THEN", "ELSE", "RESUME", "RUN"),
    edit_tail_error=5,  # Illegal function call
)

DIALECTS = {d.name: d for d in (CASIO, GW)}


def get_dialect(name: "str | Dialect") -> Dialect:
    """The dialect called ``name`` ("casio" or "gw", any case); a Dialect passes through.

    Raises ``ValueError`` naming the choices for any other name.
    """
    if isinstance(name, Dialect):
        return name
    try:
        return DIALECTS[name.lower()]
    except KeyError:
        raise ValueError(f"unknown dialect {name!r} (choose from {', '.join(DIALECTS)})") from None
