"""The optional C accelerator of ``--arith decimal`` (``_decimal_fast``, built by setup.py).

Where it is built (and ``YASEER_PURE_PYTHON`` is not set, arith_policy.PURE_PYTHON), the
compiled code (number_models.DecimalNumbers) calls its routines instead of writing the scale
caches' tests inline: ``_zcadd _zcsub _zcmul _zcdiv`` for ``+ - * /``, ``_zcrnd`` for a local
plus the number RND draws, ``_zcsqrt _zclog _zclog10 _zcexp`` for SQR, LN, LOG and EXP.  Each
computes the float result and rounds it to 12 digits with the scale of its own decade, where
decimal_scales.py's and decimal_calls.py's proofs show that is decimal_arith's result, and
hands any other call to decimal_arith's routine (so its errors, overflow and underflow stay
that module's).  A C call costs about what one inline test costs, and it never misses a
cached scale when a value changes decade.  Where it is not built the inline caches serve;
the choice is part of a compiled program's cache key (program_cache.key).
"""

from __future__ import annotations

from yaseer.basic.arithmetic.arith_policy import pure_python

_loaded: list = []  # [module or None], once looked up


def module():
    """The C module, or None (not built, or arith_policy.PURE_PYTHON set)."""
    if pure_python():
        return None
    if not _loaded:
        try:
            from yaseer.basic.arithmetic import _decimal_fast
        except ImportError:  # not built (no C compiler where yaseer was installed)
            _decimal_fast = None
        _loaded.append(_decimal_fast)
    return _loaded[0]


def accelerated() -> bool:
    """Does the compiled decimal code call the C routines?"""
    return module() is not None


def drawn_sum(add, rounded):
    """``a + v`` for the number ``v`` RND drew: ``v`` rounded to 12 digits, then added (the
    C routine's fallback, and the meaning of the compiled ``local + RND``)."""
    def summed(a, v):
        return add(a, rounded(v))
    return summed


def helpers(namespace: dict) -> dict:
    """The compiled code's ``_zc...`` routines, each bound to the namespace's decimal routine
    (decimal_arith.RUNTIME's ``_dadd`` ... and ``_d13``), or {} where the C module is absent."""
    fast = module()
    if fast is None:
        return {}
    python = {"add": namespace["_dadd"], "subtract": namespace["_dsub"], "multiply": namespace["_dmul"],
              "divide": namespace["_ddiv13"], "drawn_sum": drawn_sum(namespace["_dadd"], namespace["_d13"]),
              "sqrt": namespace["_sqrt"], "log": namespace["_log"], "log10": namespace["_log10"],
              "exp": namespace["_exp"]}
    return {NAMES[name]: fast.bound(name, function) for name, function in python.items()}


NAMES = {"add": "_zcadd", "subtract": "_zcsub", "multiply": "_zcmul", "divide": "_zcdiv",
         "drawn_sum": "_zcrnd", "sqrt": "_zcsqrt", "log": "_zclog", "log10": "_zclog10", "exp": "_zcexp"}
"""The compiled code's name of each C routine."""
