"""Where the blocks of a program area start, and which FOR loops can be native.

The planning half of the compiler (``compiler.py`` generates the code).  A block
is a run of statements entered only at its top; see the compiler's docstring.
Everything here works on the flat list of top-level statements of an area,
``[(line number, statement)]``.
"""

from __future__ import annotations

from yaseer.basic import syntax_tree as ast
from yaseer.basic.errors import BasicError

def flatten(lines: list) -> list:
    """[(line number, statement)] in program order; a line with no statement gets a Rem."""
    flat = []
    for line in lines:
        if line.error is not None:
            flat.append((line.number, line.error))
            continue
        statements = line.statements or [ast.Rem()]
        for stmt in statements:
            flat.append((line.number, stmt))
    return flat


def _jump_targets(stmt) -> list:
    if isinstance(stmt, (ast.Goto, ast.Gosub)):
        return [stmt.target]
    if isinstance(stmt, ast.OnJump):
        return list(stmt.targets)
    if isinstance(stmt, ast.OnError):
        return [stmt.target] if stmt.target else []
    if isinstance(stmt, ast.Resume) and stmt.mode == "line":
        return [stmt.target]
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


def walk_statements(stmt):
    """The statement and every statement nested in its IF branches."""
    yield stmt
    if isinstance(stmt, ast.If):
        for branch in (stmt.then, stmt.otherwise):
            if isinstance(branch, list):
                for s in branch:
                    yield from walk_statements(s)


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


def splits(stmt) -> bool:
    """True when code after ``stmt`` must be enterable from outside (a return point)."""
    for s in walk_statements(stmt):
        if isinstance(s, (ast.Gosub, ast.Stop, ast.For)):
            return True
        if isinstance(s, ast.OnJump) and s.gosub:
            return True
    return False


_NATIVE_BODY = (
    ast.Let, ast.Print, ast.GosubProg, ast.Rem, ast.Data, ast.Read, ast.Dim, ast.Angle,
    ast.Randomize, ast.DefFn, ast.Input, ast.Clear, ast.Restore, ast.End, ast.OnError,
)


def _native_statement(stmt) -> bool:
    """May ``stmt`` sit inside a native loop (no jump, no return point, no NEXT)?"""
    for s in walk_statements(stmt):
        if isinstance(s, ast.If):
            if isinstance(s.then, int) or isinstance(s.otherwise, int):
                return False
        elif not isinstance(s, _NATIVE_BODY):
            return False
    return True


def _same_var(a, b) -> bool:
    return a == b


class Plan:
    """Where blocks start and which loops are native.

    ``entries`` sorted statement indices that start blocks (the last is len(flat));
    ``native`` FOR index -> its NEXT index, for loops compiled to ``while``;
    ``for_next`` the same for loops run through the FOR stack; ``next_for`` NEXT
    index -> FOR index; ``fine`` every statement starts a block (RESUME is used);
    ``branch_for_next`` id(FOR inside an IF branch) -> index of its NEXT.
    """

    def __init__(self, entries, native, for_next, next_for, fine, branch_for_next):
        self.entries, self.native, self.for_next = entries, native, for_next
        self.next_for, self.fine, self.branch_for_next = next_for, fine, branch_for_next


def _match_loops(flat: list) -> tuple[dict, dict]:
    """Match each top-level FOR to its NEXT by program order (as MS-BASIC scans)."""
    for_next, next_for = {}, {}
    open_loops: list[int] = []
    for i, (_, stmt) in enumerate(flat):
        if isinstance(stmt, ast.For):
            open_loops.append(i)
        elif isinstance(stmt, ast.Next):
            if stmt.var is None:
                if open_loops:
                    f = open_loops.pop()
                    for_next[f], next_for[i] = i, f
                continue
            # NEXT I closes inner loops left open, down to the FOR I.
            for k in range(len(open_loops) - 1, -1, -1):
                if _same_var(flat[open_loops[k]][1].var, stmt.var):
                    f = open_loops[k]
                    del open_loops[k:]
                    for_next[f], next_for[i] = i, f
                    break
    return for_next, next_for


def plan(flat: list, entry_lines=()) -> Plan:
    n = len(flat)
    statements = [s for _, s in flat]
    fine = any(isinstance(s, ast.Resume) and s.mode != "line"
               for stmt in statements if not isinstance(stmt, BasicError) for s in walk_statements(stmt))
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
    native: dict[int, int] = {}
    if not fine:
        # innermost loops first, so a loop knows whether the loops inside it are native
        for f in sorted(for_next, key=lambda k: for_next[k] - k):
            j = for_next[f]
            body_ok = True
            k = f + 1
            while k < j:
                stmt = statements[k]
                if isinstance(stmt, ast.For):
                    if k not in native:
                        body_ok = False
                        break
                    k = native[k] + 1
                    continue
                if isinstance(stmt, BasicError) or not _native_statement(stmt):
                    body_ok = False
                    break
                k += 1
            if body_ok and not any(f < t <= j for t in targets):
                native[f] = j
    entries = {0, n} | targets
    for i, stmt in enumerate(statements):
        if isinstance(stmt, BasicError):
            continue
        if fine:
            entries.add(i)
        if isinstance(stmt, ast.For) and i not in native:
            entries.add(i + 1)
            if i in for_next:
                entries.add(for_next[i] + 1)
        elif not isinstance(stmt, ast.For) and splits(stmt):
            entries.add(i + 1)
    # dynamic loops' NEXTs are not consumed; natives' are
    dynamic_for_next = {f: j for f, j in for_next.items() if f not in native}
    branch_for_next = _branch_loops(statements, entries)  # adds the entries it needs
    return Plan(sorted(entries), native, dynamic_for_next, next_for, fine, branch_for_next)


def _branch_loops(statements: list, entries: set) -> dict:
    """FORs inside IF branches: id(FOR) -> index of the top-level NEXT that closes it.

    A loop that runs zero times continues after that NEXT (MS-BASIC scans forward for
    it), so the statement after it becomes a block entry.
    """
    found = {}
    for i, stmt in enumerate(statements):
        if not isinstance(stmt, ast.If):
            continue
        for inner in walk_statements(stmt):
            if not isinstance(inner, ast.For):
                continue
            depth = 0
            for k in range(i + 1, len(statements)):
                other = statements[k]
                if isinstance(other, ast.For):
                    depth += 1
                elif isinstance(other, ast.Next):
                    if depth == 0 and (other.var is None or other.var == inner.var):
                        found[id(inner)] = k
                        entries.add(k + 1)
                        break
                    depth = max(0, depth - 1)
    return found


# ------------------------------------------------------------------ code generation
