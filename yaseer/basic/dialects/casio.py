"""The FX-850P/880P's own words: the tables the casio dialect adds (data only).

The source is the owner's manual (its reserved-word list, part 12, and one page per
word, commands/*.md, in the public repository urbancamo/urbancamo.github.io, folder
casio-basic/doc); docs/compatibility.md names the page behind each behaviour.  The
scanner reads these words as keywords in casio only, the compiler finds their
functions and statements here, and the machine reports ``ERR`` with the manual's
error codes.  GW-BASIC never sees these tables.
"""

from __future__ import annotations

# word -> (token type, argument forms, result, helper of the compiled code).  "FUNC":
# parentheses may be left out (``LN X``, ``FACT X``); "FUNCN": a parenthesised list.
# A form is a string of argument kinds ("n" number, "s" string; "" no argument).
FUNCTIONS = {
    "LOG": ("FUNC", ("n",), "n", "_log10"),  # LOG_LN.md: the common logarithm
    "LN": ("FUNC", ("n",), "n", "_log"),  # LOG_LN.md: the natural logarithm
    "CUR": ("FUNC", ("n",), "n", "_cur"),  # CUR.md
    "FRAC": ("FUNC", ("n",), "n", "_frac"),  # FRAC.md
    "FACT": ("FUNC", ("n",), "n", "_fact"),  # FACT.md
    "ASN": ("FUNC", ("n",), "n", "_asn"),  # ASN_ACS_ATN.md
    "ACS": ("FUNC", ("n",), "n", "_acs"),
    "HYPSIN": ("FUNC", ("n",), "n", "_sinh"),  # HYP_SIN_COS_TAN.md
    "HYPCOS": ("FUNC", ("n",), "n", "_cosh"),
    "HYPTAN": ("FUNC", ("n",), "n", "_tanh"),
    "HYPASN": ("FUNC", ("n",), "n", "_asinh"),  # HYP_ASN_ACS_ATN.md
    "HYPACS": ("FUNC", ("n",), "n", "_acosh"),
    "HYPATN": ("FUNC", ("n",), "n", "_atanh"),
    "RAN#": ("FUNC", ("", "n"), "n", "_ran"),  # RAN_HASH.md
    "FRE": ("FUNC", ("n",), "n", "_fre0"),  # FRE.md: FRE 0 .. FRE 3
    "DMS$": ("FUNC", ("n",), "s", "_dms"),  # DMS_STRING.md
    "VALF": ("FUNC", ("s",), "n", "_valf"),  # VALF.md
    "HEX$": ("FUNC", ("n",), "s", "_hex4"),  # HEX_STRING.md: four digits
    "ASC": ("FUNCN", ("s",), "n", "_asc0"),  # ASC.md: 0 for a null string
    "ROUND": ("FUNCN", ("nn",), "n", "_round"),  # ROUND.md
    "NCR": ("FUNCN", ("nn",), "n", "_ncr"),  # NCR.md
    "NPR": ("FUNCN", ("nn",), "n", "_npr"),  # NPR.md
    "POL": ("FUNCN", ("nn",), "n", "_pol"),  # POL.md: also sets X and Y
    "REC": ("FUNCN", ("nn",), "n", "_rec"),  # REC.md: also sets X and Y
}
# Functions that also assign the variables X and Y (POL.md, REC.md): the function's
# value is the first of the pair (r for POL, x for REC).
SETS_X_Y = frozenset({"POL", "REC"})

# DEG(d[, m[, s]]) (DEG.md) is a function only where a "(" follows: a bare DEG stays the
# statement that selects degrees (the PB-700 family's, which the paper's machine has).
DEG_FUNCTION = ("FUNCN", ("n", "nn", "nnn"), "n", "_degf")

# The manual writes HYP and the function apart ("HYP SIN"); the sample programs join
# them (HYPSIN): both spellings are one word.
SPELLINGS = {"HYP " + f: "HYP" + f for f in ("SIN", "COS", "TAN", "ASN", "ACS", "ATN")}

# Statements of one keyword and a list of expressions: word -> (least and most
# arguments, helper the compiled code calls with them, the arguments' kind: "n"
# numbers, "s" a string, "format" SET's letter and digit).  DEFSEG may write "=" before
# its value (DEFSEG.md: ``DEFSEG = &H1000``).
STATEMENTS = {
    "ANGLE": (1, 1, "_M.set_angle_number", "n"),  # ANGLE.md: 0 degrees, 1 radians, 2 grads
    "BEEP": (0, 1, "_M.beep", "n"),  # BEEP.md
    "DEFSEG": (1, 1, "_M.define_segment", "n"),  # DEFSEG.md
    "POKE": (2, 2, "_M.poke", "n"),  # POKE.md
    "PASS": (1, 1, "_M.password", "s"),  # PASS.md
    "MODE": (1, 1, "_M.mode", "n"),  # part 7 (MODE 7 / MODE 8: printer on, off); ANGLE.md (MODE 4 5 6)
    "VARLIST": (0, 0, "_M.variable_list", "n"),  # VARLIST.md
    "SET": (1, 1, "_M.set_format", "format"),  # SET.md: SET F n, SET E n, SET N
    # CALCJMP: leaves BASIC for the CAL mode and executes the formula CALC$ holds, as the
    # CAL mode's CALC key does (Becker's library, LIB5950-5980, after CALC$=formula; part 5's
    # data bank example shows the CALC key asking "X?" for the formula's variable)
    "CALCJMP": (0, 0, "_M.calc_jump", "n"),
    "VERIFY": (1, 1, "_M.files.verify", "s"),  # VERIFY.md: the file of the program's directory read through
    # PBLOAD_PBGET.md: PB-100 programs and data from cassette tape, converted; DEFM (its page
    # is empty): the PB-100's memory declaration.  yaseer has no PB-100 tapes: the run ends
    # there with one line saying so.
    "PBLOAD": (0, 1, "_M.pb_tape", "s"),
    "PBGET": (0, 1, "_M.pb_tape", "s"),
    "DEFM": (1, 1, "_M.pb_memory", "n"),
}
# MODE n(arguments): the library's calls of machine-code routines in the ROM (LIB0900's
# MODE 30-35, LIB1000's MODE 33(32, 1024, 223)), not described by the manual.  MODE 33 is
# emulated as LIB1000 uses it (the text typed on the cursor's line becomes CALC$, which the
# program then evaluates with VALF); the others end the run with one line naming the
# routine.  word -> as STATEMENTS ("any": each argument of its own kind), the routine's
# number first.
ROUTINE_CALLS = {"MODE": (1, 9, "_M.rom_routine", "any")}
# MODE 33: the routine that copies the cursor's line into CALC$ (see casio_words.rom_routine).
LINE_TO_CALC = 33
# The words that read the variables (the block's values are stored before they run) and
# those that also set them (stored before, taken back after: MODE 33 sets CALC$, the CAL
# mode the formula's variables).
READS_VARIABLES = frozenset({"VARLIST", "VALF", "FRE"})
WRITES_VARIABLES = frozenset({"MODE()", "CALCJMP"})

# Statements the library writes with nothing after them: a bare DIM declares nothing.
EMPTY_STATEMENTS = frozenset({"DIM"})
# TAB(n) counts the columns from 0 (TAB.md, item 2: "position 0"; its range 0..256, n
# truncated), where GW-BASIC's TAB(1) is the first column.
TAB_FROM_ZERO = True
# RESTORE (expression): the line a computed number names (RESTORE.md).
COMPUTED_RESTORE = True
# ON x GOTO a,,b: an empty place does not branch (the library writes it; ON_GOTO.md
# lets a missing destination fall through).
EMPTY_ON_TARGETS = True
# Characters that are operators on the Casio: its integer division is the yen sign
# (part 6, Arithmetic Operators: -15 ¥ 7), GW-BASIC's backslash.
OPERATORS = {"¥": "BSLASH"}
# DIM of an array again with the same sizes is passed over (DIM.md, item 5; other sizes:
# the DD error), and ERASE of an array that does not exist is no error (ERASE.md, item 2).
REDIM_SAME = True
ERASE_MISSING = True
# Subscripts, DIM's sizes and ON's selector drop their fractions (part 6, Arrays: "Fractions
# are disregarded"; DIM.md and ON_GOTO.md: "truncated to an integer"), where GW-BASIC rounds;
# and ON falls through for any selector below 1 or past its list (ON_GOTO.md, item 2).
TRUNCATES = True
# INPUT asks for each variable on its own, each with the message written before it or a
# "?" (INPUT.md, items 2-4: EXE after each answer; its example INPUT "YEAR=",Y,"MONTH=",M).
ASKS_EACH = True
# A statement's open parentheses close where it ends (``:`` or the line's end), and DATA
# runs to the end of its line (its items may hold ":").  The manual is silent on both;
# the machine's own scientific library needs them: LIB5760 (the built-in Regular
# Polyhedron program) writes ``a(0)=SQR(ABS(a(3)/b):GOTO200`` and ``DATAa:edge,r:inside``.
CLOSES_PARENTHESES = True
DATA_TO_LINE_END = True
# Devices a file name may start with that yaseer does not have: OPEN of one ends the run
# with one line naming it (OPEN.md lists COM0: for the RS-232C interface; LIB0400 tests it).
# PMT0: and PMT1: are the PB-100 series' tape, read in the positive or reverse phase: the
# device the PB commands' program (LIB0900) opens for PBLOAD [0|1] and PBGET [0|1]
# (PBLOAD_PBGET.md: "reads the specified program from tape and converts it from PB-100 series
# format"; the manual names no device nor the tape's format).
ABSENT_DEVICES = {"COM0:": "the RS-232C port", "PMT0:": "the PB-100 series' tape", "PMT1:": "the PB-100 series' tape"}
# Reserved words of the manual's list (part 12) with no page and no use in a program: the
# PB-100 series' CSR, KEY, MID, VAC, VAR (PBLOAD_PBGET.md: such words of a PB-100 program are
# an SN error when run).
# AS, OUT and PUT have no page either: their one use is OPEN's ``FOR OUTPUT AS`` (OUTPUT read
# as OUT PUT, the reason both are reserved), which the scanner gives the grammar as the words
# OPEN reads (scanner._open_words).  CALC is the CAL mode's key (part 5, "CALC: executes
# formula stored in memory"), not a statement; CALC$ (the formula, below) and CALCJMP are
# longer words of their own.  The scanner reads them keyword-first, so no name holds them
# (part 6, Variables: reserved words cannot lead a name; ``ASK`` is ``AS K``), and a
# statement using one stops with ``Unsupported word CSR``.
RESERVED_ONLY = ("CSR", "KEY", "MID", "VAC", "VAR", "AS", "OUT", "PUT", "CALC")
# The commands a program may hold (read as keywords): LIST [ALL] and LLIST list (LIST.md
# item 10: then "stands by for command input": the run ends), SAVE [ALL] "file"[,A] and
# LOAD [ALL] "file"[,A] save or load (SAVE_SAVE_ALL.md item 7, LOAD_LOAD_ALL.md item 4: the
# files closed, then command standby: the run ends); NEW [ALL] and RUN are refused with
# the FC error (NEW.md item 7, RUN.md item 5: "cannot be used within a program"; the FC
# error's meaning 2, "illegal command used in ... program mode").  ALL: every program area.
PROGRAM_COMMANDS = ("LIST", "LLIST", "SAVE", "LOAD", "NEW", "RUN", "ALL", "EDIT")
# LIST ., LLIST . and EDIT .: a period for the line most recently handled (LIST.md item 4,
# EDIT.md item 2).  EDIT [n] in a program (EDIT.md: the edit mode "displays the program from the
# specified line number", or the first line above it; without one from the first line) shows
# the lines from there as LIST does, then the run ends (the edit mode waits for keys; BRK
# leaves it).
CURRENT_LINE_PERIOD = True
EDIT_LISTS_FROM = True
REFUSED_COMMANDS = ("NEW", "RUN")
# The commands a registered password refuses (PASS.md item 5; LIST.md item 11, EDIT.md
# item 4, NEW.md item 4, SAVE_SAVE_ALL.md item 6): the PR error.  SAVE in every form:
# yaseer writes the ASCII format only, which a password forbids (SAVE's binary format,
# which would carry the password, is not documented).  LOAD stays possible (LOAD.md
# item 5: yaseer's files carry no password).
PASSWORD_REFUSES = ("LIST", "LLIST", "EDIT", "NEW", "SAVE")
# A statement that does not parse in the branch of an IF (THEN or ELSE) is the SN error when
# that branch runs: the line runs up to the IF, whose condition decides (part 6, "Errors": an
# error is reported as the line executes; the library's LIB0900 guards its deliberate SN
# statements so, ``IF PEEK(m)<>4 THEN a``).  Any other bad statement makes the whole line the
# error before any of it runs, as yaseer has always run the paper's listings (Example 5's line
# 5070 prints nothing as printed).
BRANCH_ERRORS_WHEN_REACHED = True
# READ of an item that is no number into a numeric variable: the TM error of the READ's line
# (READ.md item 2), not GW-BASIC's Syntax error in the DATA line.
READ_MISMATCH = True
# GOSUB levels (GOSUB.md item 2: up to 96, beyond that the OM error); a GOSUB to a program
# area (#n, PROG n, "file:label") is a level too.
GOSUB_LEVELS = 96
# FOR ~ NEXT levels (FOR_NEXT_STEP.md item 4 and specifications.md "Number of stacks": 29).
# The manual names no error for a 30th; it is the OM error, the error of the other stack's
# overflow (GOSUB.md item 2) and of "system overflow" (part-12-2-error-messages.md, OM).
FOR_LEVELS = 29
# INPUT into a numeric variable takes a numeric expression (INPUT.md item 9: "3*4", "A+1",
# "SQR 2"), evaluated with the variables as they are, as VALF evaluates one; a string is the TM
# error (item 5).
INPUT_EXPRESSIONS = True
# EOF of a file opened FOR OUTPUT is 0 (EOF.md item 4), not GW-BASIC's Bad file mode.
OUTPUT_EOF = True
COMMAND_OPTIONS = {"LOAD": "A", "SAVE": "A", "RUN": ""}  # ,A: the ASCII format (yaseer's only one)
# The variable area's bytes (CLEAR.md: 8192 on the FX-880P and an FX-850P of 32 KB; FRE 2
# reports it): an array that does not fit with the other variables is the OM error.
VARIABLE_AREA = 8192
# Bytes of the system area a program reads with PEEK at power-on (address -> byte): the RAM's
# size in pages of 256 bytes, low byte at &H6B4 (LIB0400, the library's memory test, reads
# K = PEEK(&H6B4)/4 + PEEK(&H6B5)*64 kilobytes): the FX-880P's 32 KB (specifications.md).
# The manual documents no address; the ROM (segment &H4000 on) is not in yaseer's memory.
SYSTEM_MEMORY = {0x6B4: (32 * 1024 // 256) % 256, 0x6B5: (32 * 1024 // 256) // 256}
# The input buffer: the line last typed at the prompt and ended with EXE (a command, a
# direct statement, RUN) stays in RAM from this address on, in the machine's codes (the
# character code table, part-12-1), ended by a 0 byte.  The manual documents neither the
# address nor the buffer; the library's conversion program LIB0900 (the BASIC program behind
# PBLOAD/PBGET, PBLOAD_PBGET.md) reads the command that ran it from here.
INPUT_BUFFER = 512
# Reserved words the buffer holds as two-byte codes, not letters: the codes LIB0900 compares
# (PBLOAD 4,179; PBGET 4,180; ALL 7,187).  The codes of the other words are documented
# nowhere, so the buffer holds those as their letters.
STORED_WORDS = {"PBLOAD": (4, 179), "PBGET": (4, 180), "ALL": (7, 187)}
# ... and the names OPEN's grammar reads them as, inside an OPEN statement (scanner._open_words)
OPEN_WORDS = {("OUT", "PUT"): "OUTPUT", ("AS",): "AS"}
# Reserved string variables: CALC$, the formula CALCJMP hands to the CAL mode (the library's
# ``CALC$=s$``); kept as the variable of that name, in capitals however it is typed.
RESERVED_VARIABLES = ("CALC$",)
# The words the scanner reads as keywords in casio only (besides the dialect's own_words).
KEYWORDS = tuple(FUNCTIONS) + tuple(STATEMENTS) + tuple(SPELLINGS)

# ERR's value: yaseer's error (GW-BASIC's code) -> the manual's error code and name
# (part-12-2-error-messages.md).  Codes without an entry keep their number.
ERROR_CODES = {
    7: (1, "OM"),  # Out of memory
    2: (2, "SN"),  # Syntax error
    15: (3, "ST"),  # String too long
    16: (4, "TC"),  # String formula too complex
    64: (8, "BF"),  # Bad file name
    52: (9, "BN"),  # Bad file number
    6: (13, "OV"),  # Overflow
    11: (14, "MA"),  # Division by zero
    5: (14, "MA"),  # Illegal function call (an argument outside the function's range)
    10: (15, "DD"),  # Duplicate Definition
    9: (16, "BS"),  # Subscript out of range
    12: (17, "FC"),  # Illegal direct
    18: (17, "FC"),  # Undefined user function
    8: (18, "UL"),  # Undefined line number
    13: (19, "TM"),  # Type mismatch
    20: (20, "RE"),  # RESUME without error
    4: (22, "DA"),  # Out of DATA
    1: (23, "FO"),  # NEXT without FOR
    26: (24, "NX"),  # FOR without NEXT
    3: (25, "GS"),  # RETURN without GOSUB
    55: (28, "OP"),  # File already open
    54: (29, "AM"),  # Bad file mode
    57: (7, "RW"),  # Device I/O error
    251: (21, "PR"),  # PASS with another password (yaseer's code, errors.PASSWORD_PROTECTED)
}
ERR_VALUES = {gw: casio for gw, (casio, _) in ERROR_CODES.items()}


class Words:
    """The tables above as one object, ``Dialect.words`` (its repr names it, so a
    dialect's repr, part of the compile cache's key, holds no path)."""

    functions = FUNCTIONS
    sets_x_y = SETS_X_Y
    deg_function = DEG_FUNCTION
    spellings = SPELLINGS
    statements = STATEMENTS
    routine_calls = ROUTINE_CALLS
    absent_devices = ABSENT_DEVICES
    reserved_only = RESERVED_ONLY
    reserved_variables = RESERVED_VARIABLES
    open_words = OPEN_WORDS
    refused_commands = REFUSED_COMMANDS
    password_refuses = PASSWORD_REFUSES
    read_mismatch = READ_MISMATCH
    branch_errors_when_reached = BRANCH_ERRORS_WHEN_REACHED
    output_eof = OUTPUT_EOF
    gosub_levels = GOSUB_LEVELS
    for_levels = FOR_LEVELS
    input_expressions = INPUT_EXPRESSIONS
    current_line_period = CURRENT_LINE_PERIOD
    edit_lists_from = EDIT_LISTS_FROM
    command_options = COMMAND_OPTIONS
    list_to_file = False  # LIST.md: LIST writes to the display only; a comma after it is a Syntax error
    variable_area = VARIABLE_AREA
    system_memory = SYSTEM_MEMORY
    input_buffer = INPUT_BUFFER
    stored_words = STORED_WORDS
    reads_variables = READS_VARIABLES
    writes_variables = WRITES_VARIABLES
    line_to_calc = LINE_TO_CALC
    empty_statements = EMPTY_STATEMENTS
    computed_restore = COMPUTED_RESTORE
    empty_on_targets = EMPTY_ON_TARGETS
    keywords = KEYWORDS
    operators = OPERATORS
    redim_same = REDIM_SAME
    erase_missing = ERASE_MISSING
    err_values = ERR_VALUES
    truncates = TRUNCATES
    tab_from_zero = TAB_FROM_ZERO
    asks_each = ASKS_EACH
    closes_parentheses = CLOSES_PARENTHESES
    data_to_line_end = DATA_TO_LINE_END

    def __repr__(self) -> str:
        return "casio.Words()"


WORDS = Words()
