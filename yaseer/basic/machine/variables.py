"""The BASIC machine's variables: scalars and arrays as Python program areas see
them, DIM, ERASE, OPTION BASE, FRE and CLEAR, and the array budget (the
:class:`Variables` mixin of :class:`yaseer.basic.machine.machine.Machine`)."""

from __future__ import annotations

import math

from yaseer.basic.machine import memory_model, runtime, string_space
from yaseer.basic.errors import BasicError, DUPLICATE_DEFINITION, ILLEGAL_FUNCTION_CALL, OUT_OF_MEMORY, SUBSCRIPT_OUT_OF_RANGE
from yaseer.basic.compile.number_models import initial_value, local_name

# Array limits (each exceeded limit is "Out of memory in N").
MAX_ARRAY_ELEMENTS = 2_000_000  # per array
MAX_TOTAL_ELEMENTS = 8_000_000  # 8-byte units for all arrays together (64 MB)
STRING_ELEMENT_UNITS = 33  # a string element's share: the most it can hold (8 + 255 bytes) in 8-byte units,
# so that arrays of full strings stay inside the budget too (four DIM A$(1999999) once took 2.5 GB)


def _units(name: str, dims: tuple) -> int:
    """The budget units of array ``name`` with ``dims``: one an element, STRING_ELEMENT_UNITS a string's."""
    return math.prod(d + 1 for d in dims) * (STRING_ELEMENT_UNITS if name.endswith("$") else 1)


def _new_array(dims: tuple, fill):
    if len(dims) == 1:
        return [fill] * (dims[0] + 1)
    return [_new_array(dims[1:], fill) for _ in range(dims[0] + 1)]


class MadeNames(dict):
    """The simple variables a statement made (compiler.made), in the order they were made
    (a set that keeps its order: GW's variable table lists them so, machine/data_segment.py);
    a DEF FN's entry among them as ``memory_model.FN_KEY`` + its name."""

    __slots__ = ()

    def add(self, name: str) -> None:
        self[name] = None

    def discard(self, name: str) -> None:
        self.pop(name, None)

    def update(self, names) -> None:
        dict.update(self, dict.fromkeys(names))


class Variables:
    """Scalars (``scalars``: name -> float or str) and arrays (``arrays``: name -> list,
    nested for more than one dimension).  A mixin of ``Machine``, on its state."""

    def variable_name(self, name: str) -> str:
        """``name`` as the dialect spells variables: in upper case unless names keep their
        case (casio: ``a`` and ``A`` are two variables)."""
        return name if self.dialect.names_keep_case else name.upper()

    def scalar(self, name: str):
        """The value of scalar ``name`` (0.0, or "" for a string, if unset)."""
        name = self.variable_name(name)
        return self.scalars.get(name, initial_value(name))

    def set_scalar(self, name: str, value) -> None:
        name = self.variable_name(name)
        if name.endswith("$"):
            self.scalars[name] = str(value)
        elif self.dialect.arithmetic == "decimal":  # (a 12-digit decimal, as every value it holds)
            from yaseer.basic.arithmetic.decimal_arith import held

            self.scalars[name] = held(float(value))
        else:
            self.scalars[name] = float(value)

    def array(self, name: str) -> list:
        """The 1-D array ``name`` as a mutable list indexed by subscript."""
        return self.array_nd(self.variable_name(name), 1)

    def array_nd(self, name: str, ndim: int) -> list:
        """Array ``name``; created with its implicit dimension(s) if the program has none."""
        found = self.arrays.get(name)
        if found is not None:
            return found
        dims = (self.dialect.implicit_size(name, ndim),) * ndim
        self._reserve(name, dims)
        created = _new_array(dims, initial_value(name))
        self.arrays[name] = created
        self.array_dims[name] = dims
        self._check_variable_area(name, None)
        if self.making_flags:
            self.mark_made((name + "()",))
        return created

    def _reserve(self, name: str, dims: tuple) -> None:
        """Check the array limits for ``name`` with ``dims`` (replacing its old size)."""
        count = math.prod(d + 1 for d in dims)
        old = self.array_dims.get(name)
        total = self.array_elements + _units(name, dims) - (_units(name, old) if old else 0)
        if count > MAX_ARRAY_ELEMENTS or total > MAX_TOTAL_ELEMENTS:
            raise BasicError("Out of memory", OUT_OF_MEMORY)
        self.array_elements = total

    def dim(self, name: str, sizes: tuple) -> None:
        """DIM name(sizes): replaces an implicit array (where the dialect allows it:
        Dialect.dim_after_use_duplicate); a second DIM is an error."""
        words = self.dialect.words
        dims = tuple(int(s) if words and words.truncates else runtime.cint(s) for s in sizes)
        if name in self.explicit_arrays or self.dialect.dim_after_use_duplicate and name in self.arrays:
            if words and words.redim_same and dims == self.array_dims.get(name):
                return  # the Casio passes over the same declaration again (DIM.md)
            raise BasicError.of_code(DUPLICATE_DEFINITION)
        if any(d < 0 for d in dims):
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        if any(d < self.subscript_base for d in dims):  # DIM A(0) under OPTION BASE 1: no element
            raise BasicError("Subscript out of range", SUBSCRIPT_OUT_OF_RANGE)
        old = self.arrays.get(name), self.array_dims.get(name), self.array_elements
        self._reserve(name, dims)
        self.files.forget_array(name)  # FIELD's elements of the array it replaces are no longer fields
        self.arrays[name] = _new_array(dims, initial_value(name))
        self.array_dims[name] = dims
        self._check_variable_area(name, old)
        self.explicit_arrays.add(name)
        if self.making_flags:
            self.mark_made((name + "()",))

    def _check_variable_area(self, name: str, old) -> None:
        """Where the dialect's variable area has a size (casio: 8192 bytes, CLEAR.md's
        FX-880P figure), an array that does not fit in it with the other variables (bytes as
        FRE counts them: casio_words.variable_bytes) is Out of memory (the Casio's OM error)
        and is not made; in gw one that does not fit in the 64 KB segment with the program,
        the variables and the strings they hold (memory_model, FRE("") below 0); ``old``:
        the array, its sizes and the budget before (None: none)."""
        words = self.dialect.words
        self.string_slack = 0  # the strings' room is counted afresh at the next string stored
        if words is not None and words.variable_area is not None:
            if self.variable_bytes() <= words.variable_area:
                return
        elif self.dialect.free_memory is None or self._room_for_array():
            return
        array, dims, elements = old if old is not None else (None, None, None)
        if array is None:
            self.array_elements -= _units(name, self.array_dims[name])
            del self.arrays[name], self.array_dims[name]
        else:
            self.arrays[name], self.array_dims[name], self.array_elements = array, dims, elements
        raise BasicError("Out of memory", OUT_OF_MEMORY)

    def _room_for_array(self) -> bool:
        """gw: do the variables and arrays fit in the 64 KB segment with the program, the variables and the
        strings they hold?  Where the garbage of the string space is in the way it is
        collected first, whether or not the array then fits (GWMAIN.ASM REASON calls GARBAG);
        else the room new strings have left is counted again (less what was just made), which
        make_variable then takes its bytes from without counting the whole segment again."""
        names = string_space.block_locals()
        free, strings = self.measure_memory(names)
        space = self.string_space
        if free - space.garbage(strings) < 0:
            space.collected(free, strings, names)
        else:  # the room left for new strings, less what was just made (none is garbage if none was known)
            if space.base is None:
                space.base = (strings, space.count[0])
            space.count[1] = space.count[0] + free - space.garbage(strings)
        return free >= 0

    def erase(self, name: str) -> None:
        """ERASE name: forget the array (a later DIM may size it again); not there: Illegal function call."""
        dims = self.array_dims.get(name)
        if name not in self.arrays or dims is None:
            words = self.dialect.words
            if words and words.erase_missing:
                return  # the Casio goes on (ERASE.md)
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        self.array_elements -= _units(name, dims)
        del self.arrays[name], self.array_dims[name]
        self.files.forget_array(name)  # FIELD's elements of it are no longer fields
        self.explicit_arrays.discard(name)
        self.unmark_made(name + "()")

    def option_base(self, base: int) -> None:
        """OPTION BASE 0 or 1: the lowest subscript.  The base it already is: no error, even with
        arrays made; another once an OPTION BASE has run or an array exists (since the run or a
        CLEAR): Duplicate Definition (GWMAIN.ASM OPTION: OPTVAL, then OPTFLG, then the arrays).
        A real GW-BASIC 3.23 counts an OPTION BASE of the base it already is as one that ran
        (recorded in PC-BASIC's OPTION test: ``OPTION BASE 0`` then ``OPTION BASE 1``)."""
        if base != self.subscript_base:
            if self.arrays or self.option_seen:
                raise BasicError("Duplicate Definition", DUPLICATE_DEFINITION)
            self.set_subscript_base(base)
        self.option_seen = True

    def set_subscript_base(self, base: int) -> None:
        self.subscript_base = base
        check = self.subscript_check(base)
        for ns in list(self.namespaces.values()):
            ns["_ix"] = check

    def subscript_check(self, base: int):
        """The function compiled code checks a computed subscript with (``_ix``)."""
        words = self.dialect.words
        if words and words.truncates:
            return runtime.subscript_truncated
        read = runtime.subscript_integer if self.dialect.typed_numbers else runtime.subscript
        return read if base == 0 else runtime.from_one(read)

    def free_memory(self, argument) -> float:
        """FRE(x): in GW-BASIC the bytes its segment has left (machine/memory_model.py), the
        garbage of the string space counted as used, FRE("") after collecting it
        (machine/string_space.py); otherwise those left in the array budget (8 bytes a
        number, 264 a string element: the most it can hold), whatever x is."""
        if self.dialect.free_memory is not None:
            free, strings = self.measure_memory({})
            if type(argument) is str:  # (GARBA2 keeps the temporaries an operation works on)
                return float(self.string_space.collected(free, strings, {}))
            return float(free - self.string_space.garbage(strings))
        return float(8 * (MAX_TOTAL_ELEMENTS - self.array_elements))

    def scalars_with(self, block_locals: dict) -> dict:
        """The scalars with the running block's ``block_locals`` (its scalars' Python locals,
        not yet stored back) over them."""
        scalars = self.scalars
        if block_locals:
            names = {local_name(name): name for name in scalars}
            scalars = dict(scalars)
            scalars.update((names[local], value) for local, value in block_locals.items() if local in names)
        return scalars

    def measure_memory(self, block_locals: dict) -> tuple[int, int]:
        """(GW's free bytes without garbage, the bytes its strings hold), the running block's
        ``block_locals`` (its scalars' Python locals, not yet stored back) over the scalars."""
        scalars = self.scalars_with(block_locals)
        return memory_model.free_and_strings(self.dialect.free_memory, self.programs.get(0, {}), scalars,
                                             self.arrays, self.held_dims(), self.fns, self.strings_outside(),
                                             self.made)

    def strings_outside(self) -> dict:
        """id -> string of the strings that take no string space: held in the program text
        (StringSpace.text) or in a random file's buffer (FileTable.field_strings)."""
        fielded = self.files.field_strings()
        return {**self.string_space.text, **fielded} if fielded else self.string_space.text

    def data_layout(self):
        """gw: the data segment laid out as GW-BASIC would hold the program and the variables
        now (machine/data_segment.py, imported only here), the running block's values
        over the scalars (see :meth:`measure_memory`)."""
        from yaseer.basic.machine.data_segment import Layout

        scalars = self.scalars_with(string_space.block_locals())
        made = self.made
        order = [name for name in made if name in scalars or name.startswith(memory_model.FN_KEY)]
        order += [name for name, value in scalars.items() if value and name not in made]
        space = self.string_space
        places = space.places[0]
        layout = Layout(self.dialect.data_segment, self.programs.get(0, {}), scalars, order, self.arrays,
                        self.held_dims(), self.fns, space.text, self.subscript_base, places)
        if places is None:  # the strings' places are kept from now on (string_space.track)
            space.track(self.dialect.data_segment.string_top, layout.placed)
        return layout

    def held_dims(self) -> dict:
        """Each array's largest subscripts as GW's memory holds it: under OPTION BASE 1 one
        entry fewer a dimension (BIPTRG.ASM reads each subscript less one, DEC DX after
        INTIDX, before DIM adds the zero entry; one made without DIM has 10 entries, NOTDIM:
        OPTVAL XOR 11), so A(10) holds A(1) to A(10)."""
        if not self.subscript_base:
            return self.array_dims
        return {name: tuple(d - 1 for d in dims) for name, dims in self.array_dims.items()}

    def held_strings(self, block_locals: dict) -> set:
        """The ids of the string objects the variables hold (``block_locals`` as in
        :meth:`measure_memory`) and the literals of the compiled program (they stay in the
        program text): an operation on one of them makes no temporary."""
        held = {id(value) for value in self.scalars_with(block_locals).values() if type(value) is str}
        for name, values in self.arrays.items():
            if name.endswith("$"):
                held.update(id(value) for value in memory_model.flat_strings(values))
        held.update(self.string_space.text)  # the literals and DATA: they stay in the program text
        return held

    def make_variable(self, name: str) -> None:
        """GW's PTRGET makes simple variable ``name`` (compiler.made, in an area that counts
        its makings): FRE counts it from now on, whatever it holds; where it does not fit
        in the 64 KB segment with the program, the other variables and the strings (the
        garbage collected first) it is ``Out of memory`` and is not made (BIPTRG.ASM
        SMKVAR moves the arrays up with BLTU, whose REASON gives OMERR)."""
        self.made.add(name)
        if not self._take_room(memory_model.variable_bytes(name)):
            self.made.discard(name)
            raise BasicError("Out of memory", OUT_OF_MEMORY)
        self.mark_made((name,))

    def _all_made(self, names) -> bool:
        """Are the simple variables and arrays (``name()``) ``names`` all made?"""
        arrays, made = self.arrays, self.made
        return all(name[:-2] in arrays if name[-1] == ")" else name in made for name in names)

    def register_makings(self, key, namespace: dict, makings: dict, merge: bool = False) -> None:
        """The code of ``namespace`` (an area's, or a direct line's: ``key``) makes the simple
        variables ``makings`` (block -> names: CompiledArea.makings); its flags ``_f<block>``
        are kept true while one of a block's names is not made (compiler.made), so that a
        block whose names are all made pays nothing for their making.  ``merge``: a variant
        of the code already registered (TRON, DEF types), with the same blocks."""
        old = self.making_flags.get(key)
        if merge and old is not None and old[0] is namespace:
            makings = {b: tuple(sorted(set(old[1].get(b, ())) | set(names))) for b, names in
                       (old[1] | makings).items()}
        by_name: dict[str, list[int]] = {}
        for block, names in makings.items():
            for name in names:
                by_name.setdefault(name, []).append(block)
            namespace[f"_f{block}"] = not self._all_made(names)
        self.making_flags[key] = (namespace, makings, by_name)

    def mark_made(self, names) -> None:
        """``names`` are made now: the flags of the blocks whose names are then all made go
        false (see :meth:`register_makings`)."""
        for namespace, makings, by_name in self.making_flags.values():
            for name in names:
                for block in by_name.get(name, ()):
                    flag = f"_f{block}"
                    if namespace[flag] and self._all_made(makings[block]):
                        namespace[flag] = False

    def unmark_made(self, name: str) -> None:
        """``name`` (an array: ``A!()``) is gone (ERASE): the blocks that make it make it again."""
        for namespace, _, by_name in self.making_flags.values():
            for block in by_name.get(name, ()):
                namespace[f"_f{block}"] = True

    def _unmade(self) -> None:
        """Nothing is made (CLEAR, RUN): every block that makes a variable makes it again."""
        self.made.clear()
        for namespace, makings, _ in self.making_flags.values():
            for block in makings:
                namespace[f"_f{block}"] = True

    def define_function(self, name: str, function, parameters: tuple) -> None:
        """DEF FN ``name``: ``function`` (the compiled body, or its name in a variant) with
        the variables ``parameters`` (full names).  In gw a function defined for the first
        time is a new simple variable (GWEVAL.ASM DEF: GETFNM's PTRGT2 makes an entry with
        the function bit on its name, of the function's type): its bytes (memory_model) come
        from the room left, after a garbage collection if need be, or it is ``Out of
        memory`` and is not defined; then SCNLIS's PTRGET makes each parameter's variable
        that does not exist yet, as a LET would (:meth:`make_variable`)."""
        new = name not in self.fns
        self.fns[name] = (function, len(parameters))
        if new and self.dialect.free_memory is not None:
            if not self._take_room(memory_model.function_bytes(name)):
                del self.fns[name]
                raise BasicError("Out of memory", OUT_OF_MEMORY)
            self.made.add(memory_model.FN_KEY + name)  # its entry's place among the variables
        if self.dialect.variables_made:
            for parameter in parameters:
                if parameter in self.made:
                    continue
                value = self.scalars.setdefault(parameter, initial_value(parameter))
                if value or self.dialect.free_memory is None:  # (one holding a value is counted already)
                    self.made.add(parameter)
                    self.mark_made((parameter,))
                else:
                    self.make_variable(parameter)

    def _take_room(self, size: int) -> bool:
        """gw: can ``size`` bytes just added to the variables (already among them) have
        room?  They come from the room new strings were counted to have left, without
        counting the whole segment again, where that room surely holds them; else the
        segment is counted again (:meth:`_room_for_array`)."""
        count = self.string_space.count
        if count[1] - count[0] >= size and count[1] >= 0:  # room the strings surely leave
            count[1] -= size
            return True
        return self._room_for_array()


    def swap_second(self, name: str, value) -> None:
        """SWAP's second variable, a simple one, holding ``value``: it must exist (BIMISC.ASM
        SWAP compares ARYTAB around its PTRGET: a variable made there is Illegal function
        call, though it stays made).  One a statement made is in ``made`` where the compiler
        recorded it (compiler.made); one holding a value other than 0 or "" was made anyway
        (by a program that had no SWAP asking for it)."""
        if name in self.made:
            return
        self.made.add(name)
        self.mark_made((name,))
        if value == 0 or value == "":
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)

    def clear(self) -> None:
        """CLEAR: every variable to 0 or "", arrays back to their implicit state, no FN;
        no error trapping either (ON ERROR off, ERR and ERL 0, an error handler left:
        its RESUME is then RESUME without error, as PC-BASIC shows)."""
        for name in self.scalars:
            self.scalars[name] = initial_value(name)
        self.string_slack = 0
        self.arrays.clear()
        self.array_dims.clear()
        self.array_elements = 0
        self.explicit_arrays.clear()
        self.fns.clear()
        for rt in self.runtimes.values():
            rt.data_index = rt.data_start = 0
        self.on_error = None
        self.in_handler = False
        self.err = self.erl = 0.0
        self.string_space.reset()
        self.string_space.temps.clear()
        self._unmade()
        self.reset_def_types()
        self.set_subscript_base(0)  # OPTION BASE 0, as none had run (BIMISC.ASM CLEARC: OPTFLG, OPTVAL)
        self.option_seen = False


def _check_clear_arguments(*sizes) -> None:
    """CLEAR n, m, k: the memory sizes are not used; a negative first one is Illegal function call."""
    if sizes and sizes[0] is not None and sizes[0] < 0:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)


# GW-BASIC's CLEAR [n][, m[, k]] (BIMISC.ASM CLEAR): the highest data-segment byte a program
# may ask for (m; a real GW-BASIC 3.23 recorded 65535 as Out of memory, 65534 accepted: PC-BASIC's
# CLEARERR test), and the smallest stack k (2 * NUMLEV + 20 bytes, OEM.H NUMLEV = 110)
CLEAR_TOP = 65534
CLEAR_LEAST_STACK = 2 * 110 + 20


def clear_argument(reading: str, value: float) -> int:
    """One of GW-BASIC's CLEAR arguments, checked as it is read: ``"whole"`` (n, BIMISC.ASM
    CLEAR's INTID2: an integer, beyond 16 bits Overflow, negative Illegal function call),
    ``"top"`` or ``"stack"`` (m and k in bytes, GETMPM: FRQINT's unsigned word, 0 Illegal
    function call; m above :data:`CLEAR_TOP` Out of memory)."""
    if reading == "whole":
        n = runtime.cint(value)
        if not -32768 <= n <= 32767:
            runtime.overflow()
        if n < 0:
            raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
        return n
    n = runtime.unsigned_word(value)
    if n == 0:
        raise BasicError("Illegal function call", ILLEGAL_FUNCTION_CALL)
    if reading == "top" and n > CLEAR_TOP:
        raise BasicError("Out of memory", OUT_OF_MEMORY)
    return n


def clear_sizes(_whole=None, top=None, stack=None) -> None:
    """GW-BASIC's CLEAR once its arguments are read (BIMISC.ASM CLEART): a stack k of at most
    :data:`CLEAR_LEAST_STACK` bytes, or not below the top m (or :data:`CLEAR_TOP`), is Out of
    memory.  The sizes are not kept: yaseer's memory model has no stack."""
    if stack is not None and (stack <= CLEAR_LEAST_STACK or stack >= (top or CLEAR_TOP)):
        raise BasicError("Out of memory", OUT_OF_MEMORY)

