"""Where the blocks of a program area start, and which FOR loops can be native.

The planning half of the compiler (``compiler.py`` generates the code).  A block
is a run of statements entered only at its top; see the compiler's docstring.
Everything here works on the flat list of top-level statements of an area,
``[(line number, statement)]``.
"""

from __future__ import annotations

from yaseer.basic.source import syntax_tree as ast
from yaseer.basic.errors import BasicError

def flatten(lines: list) -> list:
    """[(line number, statement)] in program order; a line with no statement gets a Rem.

    A statement that does not parse is its ``BasicError`` (see ``Line.error``)."""
    flat = []
    for line in lines:
        if line.error is not None and not line.statements:
            flat.append((line.number, line.error))
            continue
        statements = line.statements or [ast.Rem()]
        for stmt in statements:
            flat.append((line.number, stmt))
    return flat


def _jump_targets(stmt) -> list:
    """The line numbers a statement (or its IF branches) may jump to."""
    if isinstance(stmt, (ast.Goto, ast.Gosub, ast.ReturnTo)):
        return [stmt.target]
    if isinstance(stmt, ast.OnJump):
        return list(stmt.targets)
    if isinstance(stmt, ast.OnError):
        return [stmt.target] if stmt.target else []
    if isinstance(stmt, ast.EventTrap):  # where the event's GOSUB goes
        return [stmt.line] if stmt.line else []
    if isinstance(stmt, ast.Resume) and stmt.mode == "line":
        return [stmt.target]
    if isinstance(stmt, ast.Bank) and stmt.word == "RESTORE#" and len(stmt.args) == 3 \
            and isinstance(stmt.args[2], ast.Num):  # RESTORE# "text", mode, line: where "not found" goes
        return [int(stmt.args[2].value)]
    if isinstance(stmt, ast.If):
        out = []
        for branch in (stmt.then, stmt.otherwise):
            if isinstance(branch, int):
                out.append(branch)
            elif branch:
                for s in branch:
                    out.extend(_jump_targets(s))
        return out
    return []


def walk_statements(stmt, unreachable: bool = True):
    """The statement and every statement nested in its IF branches (and in the text
    after ``THEN n:``, which never runs, unless ``unreachable`` is False)."""
    yield stmt
    if isinstance(stmt, ast.If):
        for branch in (stmt.then, stmt.otherwise, stmt.unreachable if unreachable else None):
            if isinstance(branch, list):
                for s in branch:
                    yield from walk_statements(s, unreachable)


def scanned_statements(stmt):
    """:func:`walk_statements`, and the statements of the text a remark made of an unowned
    ELSE skips (``Rem.skipped``): what GW-BASIC's FOR sees scanning the text for its NEXT."""
    for s in walk_statements(stmt):
        yield s
        if isinstance(s, ast.Rem) and s.skipped:
            for inner in s.skipped:
                yield from scanned_statements(inner)


def data_statements(stmt):
    """The DATA statements of ``stmt`` that READ sees: GW-BASIC looks for DATA at the
    start of a statement after a colon, so a DATA right after THEN or ELSE is not one."""
    if isinstance(stmt, ast.Data):
        yield stmt
    elif isinstance(stmt, ast.If):
        for branch in (stmt.then, stmt.otherwise, stmt.unreachable):
            if isinstance(branch, list):
                for k, s in enumerate(branch):
                    if not (k == 0 and branch is not stmt.unreachable and isinstance(s, ast.Data)):
                        yield from data_statements(s)


def nodes(value):
    """Every syntax-tree node in ``value`` (a node, list or tuple), depth first."""
    stack = [value]
    while stack:
        item = stack.pop()
        if isinstance(item, (list, tuple)):
            stack.extend(item)
        elif isinstance(item, ast.Node):
            yield item
            stack.extend(getattr(item, name) for name in item._fields)


def splits(stmt, bare_returns=frozenset()) -> bool:
    """True when code after ``stmt`` must be enterable from outside (a return point).

    A GOSUB to a line of ``bare_returns`` (lines that start with a plain RETURN) is
    compiled in place (see :func:`bare_return_lines`) and returns nowhere."""
    for s in walk_statements(stmt):
        if isinstance(s, ast.Gosub) and s.target in bare_returns:
            continue
        if isinstance(s, (ast.Gosub, ast.Stop, ast.For, ast.Trace, ast.Erase, ast.OptionBase, ast.DefType, ast.Clear)):
            return True
        if isinstance(s, ast.OnJump) and s.gosub:
            return True
        if s is not stmt and isinstance(s, (ast.While, ast.Wend)):
            return True  # a WHILE or WEND inside an IF branch starts a block there
    return False


# Statements that may come before a program's last DEFINT/DEFSNG/DEFDBL/DEFSTR without making
# its types depend on the order things run in: none of them jumps or ends the run.
_BEFORE_TYPES = (
    ast.Rem, ast.Data, ast.Let, ast.Print, ast.Dim, ast.DefFn, ast.Randomize, ast.Cls, ast.Key,
    ast.Width, ast.ScreenStatement, ast.Locate, ast.ViewPrint, ast.OptionBase,
)


def _names(stmt):
    """The variable, array and function names ``stmt`` holds (as written)."""
    for node in nodes(stmt):
        if isinstance(node, (ast.Var, ast.Elem, ast.FnCall)):
            yield node.name
        elif isinstance(node, ast.DefFn):
            yield node.name
            yield from node.params
        elif isinstance(node, ast.Dim):
            yield from (name for name, _ in node.arrays)


def types_fixed(flat: list) -> bool:
    """May the area's DEFINT/DEFSNG/DEFDBL/DEFSTR be applied to the whole text before it runs?

    In GW-BASIC they are statements: a name without a type character takes the type its
    letter has in the table (GWMAIN.ASM DEFCON sets DEFTBL) when the reference runs, and
    CLEAR (and RUN) set every letter back to single (BIMISC.ASM CLEARC).  Applying them
    first gives the same types when they all stand at the top level before anything that
    jumps or ends the run, and no name of a letter they type comes before the last of them;
    and no CLEAR follows.  Otherwise the compiler writes each as a switch of the type table
    when it runs (``AreaCompiler.dynamic_types``)."""
    statements = [stmt for _, stmt in flat]
    found = [i for i, stmt in enumerate(statements) if not isinstance(stmt, BasicError)
             and any(isinstance(s, ast.DefType) for s in walk_statements(stmt))]
    if not found:
        return True
    if any(isinstance(s, ast.Clear) or (isinstance(s, ast.Command) and s.name == "RUN" and isinstance(s.argument, int))
           for stmt in statements if not isinstance(stmt, BasicError) for s in walk_statements(stmt)):
        return False  # the table back to single, then on (RUN n: not from the top)
    letters = set()
    for i in found:
        for first, last in statements[i].ranges if isinstance(statements[i], ast.DefType) else ():
            letters.update(chr(code) for code in range(ord(first), ord(last) + 1))
    for stmt in statements[:found[-1]]:
        if isinstance(stmt, ast.DefType):
            continue
        if not isinstance(stmt, _BEFORE_TYPES) or any(
                name[-1] not in "$%!#" and name[0] in letters for name in _names(stmt)):
            return False
    return isinstance(statements[found[-1]], ast.DefType)


_NATIVE_BODY = (
    ast.Let, ast.Print, ast.GosubProg, ast.Rem, ast.Data, ast.Read, ast.Dim, ast.Angle,
    ast.Randomize, ast.DefFn, ast.Restore, ast.End, ast.OnError, ast.Cls,
    ast.Error, ast.Swap, ast.MidAssign, ast.Write, ast.Open, ast.Close,
    ast.Kill, ast.Rename, ast.Files, ast.Locate, ast.ScreenStatement, ast.ViewPrint, ast.Key, ast.EventTrap, ast.EventSwitch, ast.DefChr, ast.EndMark, ast.GosubArea, ast.GotoArea, ast.GosubFile, ast.GotoFile,
)  # not INPUT nor LINE INPUT: they start a block (see plan)


def bare_return_lines(flat: list, fine: bool) -> frozenset:
    """The lines whose first statement is a plain RETURN: a GOSUB to one of them pushes
    its return point and pops it at once, so it is compiled in place as the check for
    a full stack alone (the block and return point it would need are not made).  None
    in a program that uses RESUME (every statement is a block there)."""
    if fine:
        return frozenset()
    first: dict[int, object] = {}
    for number, stmt in flat:
        first.setdefault(number, stmt)
    return frozenset(number for number, stmt in first.items() if type(stmt) is ast.Return)


def _native_statement(stmt, bare_returns=frozenset()) -> bool:
    """May ``stmt`` sit inside a native loop (no jump, no return point, no NEXT)?"""
    for s in walk_statements(stmt):
        if isinstance(s, ast.If):
            if isinstance(s.then, int) or isinstance(s.otherwise, int):
                return False
        elif isinstance(s, ast.Gosub) and s.target in bare_returns:
            continue
        elif not isinstance(s, _NATIVE_BODY):
            return False
    return True


class Plan:
    """Where blocks start and which loops are native.

    ``entries`` sorted statement indices that start blocks (the last is len(flat));
    ``native`` FOR index -> its NEXT index, for loops compiled to ``while``;
    ``for_next`` the same for loops run through the FOR stack; ``next_for`` NEXT
    index -> FOR index; ``fine`` every statement starts a block (RESUME is used);
    ``branch_for_next`` id(FOR inside an IF branch) -> index of its NEXT;
    ``branch_nexts`` id(NEXT inside an IF branch) for each NEXT a FOR's scan finds
    (GW-BASIC's zero-trip loop goes on right after it, in the middle of the branch);
    ``bare_returns`` the lines a GOSUB to which is compiled in place (:func:`bare_return_lines`).
    """

    def __init__(self, entries, native, for_next, next_for, fine, branch_for_next, bare_returns=frozenset()):
        self.entries, self.native, self.for_next = entries, native, for_next
        self.next_for, self.fine, self.branch_for_next = next_for, fine, branch_for_next
        self.bare_returns = bare_returns


def _match_loops(flat: list) -> tuple[dict, dict]:
    """Match each top-level FOR to its NEXT by program order (as MS-BASIC scans).

    FORs and NEXTs inside IF branches take part in the scan (a NEXT in a branch
    closes the loop it names) but are not recorded: only a top-level pair can become
    a native loop, and ``_branch_loops`` finds where a branch-closed loop ends.
    """
    for_next, next_for = {}, {}
    open_loops: list[tuple] = []  # (statement index, loop variable, top level?)
    for i, (_, stmt) in enumerate(flat):
        if isinstance(stmt, BasicError):
            continue
        if isinstance(stmt, ast.If):
            for inner in walk_statements(stmt):
                if isinstance(inner, ast.For):
                    open_loops.append((i, inner.var, False))
                elif isinstance(inner, ast.Next):
                    _close(open_loops, inner.var)
        elif isinstance(stmt, ast.For):
            open_loops.append((i, stmt.var, True))
        elif isinstance(stmt, ast.Next):
            closed = _close(open_loops, stmt.var)
            if closed is not None and closed[2]:
                for_next[closed[0]], next_for[i] = i, closed[0]
    return for_next, next_for


def _close(open_loops: list, var):
    """Close the innermost open loop over ``var`` (any loop for a NEXT without a name),
    and the loops opened inside it; the closed loop's entry, or None."""
    for k in range(len(open_loops) - 1, -1, -1):
        if var is None or open_loops[k][1] == var:
            closed = open_loops[k]
            del open_loops[k:]
            return closed
    return None


def scan_for_next(statements: list, start: int, branch_for=None):
    """GW-BASIC's FOR: the NEXT it finds scanning forward from statement ``start``,
    counting the FORs and NEXTs met on the way (names ignored, IF branches included).
    ``branch_for``: a FOR inside an IF branch of statement ``start - 1``; the scan
    then starts with the statements that follow it in that IF's text.

    Returns ``(index of the statement holding it, the NEXT)``, or None when the
    program has none (``FOR without NEXT``).  PC-BASIC 2.0.8 binds the loop to that
    NEXT when the FOR runs; a NEXT naming another variable is ``NEXT without FOR``.
    (One scan; a compiler asking for many holds a :class:`NextScan`.)
    """
    return NextScan(statements).find(start, branch_for)


class NextScan:
    """:func:`scan_for_next` answered for every start at once, in one pass over the program
    (scanning anew for each FOR made compiling n nested loops cost n**2).

    With ``level[p]`` the FORs minus the NEXTs before inner statement ``p`` (the
    statements and their IF branches in text order), the scan from ``p`` stops at the
    first NEXT ``q >= p`` with ``level[q] == level[p]``: the one it meets at depth 0.
    """

    def __init__(self, statements: list):
        self.inners: list[tuple[int, object]] = []  # (statement index, inner statement), text order
        self.first: list[int] = []  # statement index -> position of its first inner statement (or the next's)
        for k, stmt in enumerate(statements):
            self.first.append(len(self.inners))
            if not isinstance(stmt, BasicError):
                self.inners.extend((k, inner) for inner in scanned_statements(stmt))
        self.first.append(len(self.inners))
        self.position = {id(inner): p for p, (_, inner) in enumerate(self.inners)}
        levels, level = [], 0
        for _, inner in self.inners:
            levels.append(level)
            level += 1 if isinstance(inner, ast.For) else -1 if isinstance(inner, ast.Next) else 0
        self.answer: list[int | None] = [None] * (len(self.inners) + 1)
        nearest: dict[int, int] = {}  # level -> the nearest NEXT at or after the position, at that level
        for p in range(len(self.inners) - 1, -1, -1):
            if isinstance(self.inners[p][1], ast.Next):
                nearest[levels[p]] = p
            self.answer[p] = nearest.get(levels[p])

    def find(self, start: int, branch_for=None):
        """``scan_for_next(statements, start, branch_for)`` for these statements."""
        if branch_for is not None:
            p = self.position[id(branch_for)] + 1
        else:
            p = self.first[min(start, len(self.first) - 1)]
        q = self.answer[p]
        return None if q is None else self.inners[q]


MAX_NATIVE_DEPTH = 8
"""Native loops nested deeper than this are run by the FOR stack instead: each native loop is
a Python ``while`` (or ``for``) block, and Python refuses a function with more than 20
statically nested blocks.  So loops nest as deep as the FOR stack allows (10,000), the
innermost eight at native speed."""


def plan(flat: list, entry_lines=(), dynamic_loops=(), resumable: bool = False) -> Plan:
    """Decide the blocks of an area (see :class:`Plan`); the FORs at ``dynamic_loops``
    (statement indices) are never native; ``resumable``: every statement starts a block
    even without a RESUME here (a direct line whose error a program's handler may RESUME NEXT)."""
    n = len(flat)
    statements = [s for _, s in flat]
    # every statement starts a block where a RESUME may go back into a line, and where an
    # event's GOSUB may come between any two statements (GW-BASIC looks for events before each)
    events = any(isinstance(s, ast.EventTrap) for stmt in statements if not isinstance(stmt, BasicError)
                 for s in walk_statements(stmt))
    fine = resumable or events or any(isinstance(s, ast.Resume) and s.mode != "line"
               for stmt in statements if not isinstance(stmt, BasicError) for s in walk_statements(stmt))
    bare_returns = bare_return_lines(flat, fine)
    first_index: dict[int, int] = {}
    for i, (number, _) in enumerate(flat):
        first_index.setdefault(number, i)
    targets = {first_index[line] for line in entry_lines if line in first_index}
    for _, stmt in flat:
        if isinstance(stmt, BasicError):
            continue
        for line in _jump_targets(stmt):
            if line in first_index:
                targets.add(first_index[line])
    for_next, next_for = _match_loops(flat)
    scan = NextScan(statements)
    native: dict[int, int] = {}
    depth: dict[int, int] = {}  # native FOR index -> how many native loops deep its body is, itself included
    if not fine:
        # innermost loops first, so a loop knows whether the loops inside it are native
        for f in sorted(for_next, key=lambda k: for_next[k] - k):
            j = for_next[f]
            body_ok = True
            depth[f] = 1
            k = f + 1
            while k < j:
                stmt = statements[k]
                if isinstance(stmt, ast.For):
                    if k not in native:
                        body_ok = False
                        break
                    depth[f] = max(depth[f], depth[k] + 1)
                    k = native[k] + 1
                    continue
                if isinstance(stmt, BasicError) or not _native_statement(stmt, bare_returns):
                    body_ok = False
                    break
                k += 1
            bound = scan.find(f + 1)
            same_pair = bound is not None and bound[0] == j  # GW-BASIC's FOR binds the same NEXT
            if body_ok and same_pair and depth[f] <= MAX_NATIVE_DEPTH and f not in dynamic_loops \
                    and not any(f < t <= j for t in targets):
                native[f] = j
    entries = {0, n} | targets
    bounds = []  # (statement index, NEXT) of each FOR's scan
    for i, stmt in enumerate(statements):
        if fine:
            entries.add(i)  # a line that does not parse too: RESUME NEXT goes on after it
        if isinstance(stmt, BasicError):
            continue
        if isinstance(stmt, (ast.Input, ast.LineInput)):
            entries.add(i)  # Ctrl-C while INPUT waits breaks before it, and CONT asks again
        if isinstance(stmt, ast.For) and i not in native:
            entries.add(i + 1)
            if i in for_next:
                entries.add(for_next[i] + 1)
            bound = scan.find(i + 1)
            if bound is not None:
                entries.add(bound[0] + 1)  # where GW-BASIC goes when the loop runs zero times
                bounds.append(bound)
        elif not isinstance(stmt, ast.For) and splits(stmt, bare_returns):
            entries.add(i + 1)
        if isinstance(stmt, ast.If):
            for loop in walk_statements(stmt):
                bound = scan.find(i + 1, loop) if isinstance(loop, ast.For) else None
                if bound is not None:
                    entries.add(bound[0] + 1)  # likewise for a FOR in an IF branch
                    bounds.append(bound)
    # dynamic loops' NEXTs are not consumed; natives' are
    dynamic_for_next = {f: j for f, j in for_next.items() if f not in native}
    branch_for_next = _branch_loops(statements, entries, for_next)  # adds the entries it needs
    result = Plan(sorted(entries), native, dynamic_for_next, next_for, fine, branch_for_next, bare_returns)
    result.polls_events = events  # no block loops inside itself: each pass goes by the run loop
    result.next_scan = scan  # the compiler asks it again for each FOR
    result.branch_nexts = {id(found) for k, found in bounds if found is not statements[k] and any(
        s is found for s in walk_statements(statements[k], unreachable=False))}
    _plan_while_loops(statements, result)
    return result


def _plan_while_loops(statements: list, result: Plan) -> None:
    """Match WHILE and WEND by nesting, in the program's text order (IF branches
    included: GW-BASIC's WHILE scans the text for its WEND the same way).

    ``while_wend``: id(WHILE) -> (index of the statement holding its WEND, the WEND);
    ``wend_while`` the other way.  A top-level WHILE starts a block (WEND jumps back to
    it), so does the statement after a top-level WEND (where a false condition goes);
    the compiler makes the blocks of those inside IF branches.  Also notes whether
    OPTION BASE is used."""
    result.while_wend, result.wend_while = {}, {}
    open_loops: list[tuple[int, object]] = []
    extra = set()
    for i, stmt in enumerate(statements):
        if isinstance(stmt, BasicError):
            continue
        for inner in walk_statements(stmt):
            if isinstance(inner, ast.While):
                open_loops.append((i, inner))
            elif isinstance(inner, ast.Wend) and open_loops:
                start, loop = open_loops.pop()
                result.while_wend[id(loop)], result.wend_while[id(inner)] = (i, inner), (start, loop)
                if loop is statements[start]:
                    extra.add(start)
                if inner is stmt:
                    extra.add(i + 1)
    result.entries = sorted(set(result.entries) | extra)
    result.option_base = any(isinstance(s, ast.OptionBase) for stmt in statements
                             if not isinstance(stmt, BasicError) for s in walk_statements(stmt))


def _branch_loops(statements: list, entries: set, for_next: dict) -> dict:
    """Where a loop that runs zero times goes when the simple match cannot say.

    For a FOR inside an IF branch, or a top-level FOR whose NEXT sits inside an IF
    branch: id(FOR) -> index of the top-level statement holding the closing NEXT.
    MS-BASIC scans forward for that NEXT and goes on after it; here (casio, whose
    FOR is not bound to a NEXT) execution goes on with the statement after the one
    holding it, which therefore becomes a block entry.  (gw goes on right after the
    NEXT the FOR's scan finds: ``Plan.branch_nexts``.)
    """
    found = {}
    for i, stmt in enumerate(statements):
        if isinstance(stmt, ast.If):
            loops = [s for s in walk_statements(stmt) if isinstance(s, ast.For)]
        elif isinstance(stmt, ast.For) and i not in for_next:
            loops = [stmt]
        else:
            continue
        for loop in loops:
            k = i if _closes_later(stmt, loop) else _closing_statement(statements, i + 1, loop.var)
            if k is not None:
                found[id(loop)] = k
                entries.add(k + 1)
    return found


def _closes_later(stmt, loop) -> bool:
    """Does a NEXT after ``loop`` inside the same IF statement close it?"""
    inner = list(walk_statements(stmt))
    if not isinstance(stmt, ast.If) or not any(s is loop for s in inner):
        return False
    depth = 0
    for other in inner[next(k for k, s in enumerate(inner) if s is loop) + 1:]:
        if isinstance(other, ast.For):
            depth += 1
        elif isinstance(other, ast.Next):
            if depth == 0 and (other.var is None or other.var == loop.var):
                return True
            depth = max(0, depth - 1)
    return False


def _closing_statement(statements: list, start: int, var) -> int | None:
    """The index of the first top-level statement from ``start`` that holds a NEXT
    closing a loop over ``var`` (loops opened on the way are skipped over)."""
    depth = 0
    for k in range(start, len(statements)):
        for inner in walk_statements(statements[k]) if not isinstance(statements[k], BasicError) else ():
            if isinstance(inner, ast.For):
                depth += 1
            elif isinstance(inner, ast.Next):
                if depth == 0 and (inner.var is None or inner.var == var):
                    return k
                depth = max(0, depth - 1)
    return None


# ------------------------------------------------------------------ code generation
