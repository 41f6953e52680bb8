"""VAL in gw: a number whose BASIC type is known only when it runs.

GW-BASIC's VAL reads its text with the number reader's forced-double entry (BISTRS.ASM
VAL calls FINDBL): a double, unless a ``!`` after the number makes it single
(``gwfunctions.val_typed``: ``VAL("1")/3`` is .3333333333333333, ``VAL("1!")/3``
.3333334, ``VAL("-1E+39")`` Overflow and -1.701411834604692D+38).  The compiler gives VAL the type ``"?"``
(``number_models.TypedNumbers``): the value is a plain float for a single and a
:class:`numbers.Double` for a double, and the helpers below give an operation on such a
value the type GW-BASIC gives it (a single with a single or an integer stays single, a
double makes the result double).  An operation with a ``#`` operand is compiled as a
double one, and ``"?"`` is made a single where a single is needed, as any double is.
"""

from __future__ import annotations

from yaseer.basic.errors import OVERFLOW
from yaseer.basic.arithmetic.values import Double, printed_double


def helpers(policy, ns: dict, reading) -> dict:
    """The compiled code's ``_val``, ``_vop``, ``_vdv``, ``_vneg`` and ``_vlike`` for a
    typed dialect; ``ns`` holds the single and double helpers (``_sadd`` ``_ssub``
    ``_dv`` ``_ddv`` ``_dk``), ``policy`` the overflow policy (arith_policy.py)
    and ``reading`` the dialect's number reading (values.NumberReading)."""
    from yaseer.basic.machine.gwfunctions import val_typed

    single_divide, double_divide, in_range = ns["_dv"], ns["_ddv"], ns["_dk"]
    singles = {"+": ns["_sadd"], "-": ns["_ssub"], "*": ns["_smul"]}
    doubles = {"+": ns["_dad"], "-": ns["_dsb"], "*": ns["_dml"]}

    def val(text: str):
        value, kind = val_typed(text, reading)
        if kind == "#":
            return printed_double(in_range(value))
        if value - value:  # beyond the single range: the policy's message and value
            return policy.result(OVERFLOW, value < 0, "!")
        return value

    def operate(op: str, a, b):
        """``a op b`` (+ - *) where either may be VAL's: double if either is a Double."""
        if isinstance(a, Double) or isinstance(b, Double):
            return printed_double(doubles[op](a, b))
        return singles[op](a, b)

    def divide(a, b):
        if isinstance(a, Double) or isinstance(b, Double):
            return printed_double(double_divide(a, b))
        return single_divide(a, b)

    def negate(a):
        return printed_double(-a) if isinstance(a, Double) else -a

    def like(result, argument):
        """ABS, INT or FIX of VAL's value: of its type."""
        return printed_double(result) if isinstance(argument, Double) else result

    return {"_val": val, "_vop": operate, "_vdv": divide, "_vneg": negate, "_vlike": like}
