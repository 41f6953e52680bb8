"""Build of the optional C accelerators (everything else is in pyproject.toml).

yaseer.basic.arithmetic._mbf_fast computes gw's SIN COS TAN ATN LOG EXP and ``^`` bit for
bit as yaseer/basic/arithmetic/gw_transcendental.py does, faster;
yaseer.basic.arithmetic._decimal_fast computes ``--arith decimal``'s + - * / SQR LN LOG EXP
bit for bit as yaseer/basic/arithmetic/decimal_arith.py does (decimal_fast.py);
yaseer.linkages._straight_fast runs a library program's recorded paths (straight_line.py)
as programs of double operations, writing what their Python functions write.  They are
optional: where no C compiler (or no Python headers) is found the build warns and goes on,
and yaseer uses the Python functions (arith_policy.gw_routines, decimal_fast.accelerated).
"""

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


class BuildExt(build_ext):
    """No contraction of ``a*b + c`` into fused multiply-adds (gcc's default on some
    machines): every double operation of the module must round as Python's does; sin and cos
    called as the functions Python's math calls, never merged into one sincos call."""

    def build_extensions(self):
        if self.compiler.compiler_type != "msvc":  # (MSVC does not contract by default)
            for extension in self.extensions:
                extension.extra_compile_args = [*extension.extra_compile_args, "-ffp-contract=off",
                                                "-fno-builtin-sin", "-fno-builtin-cos"]
        super().build_extensions()


setup(
    ext_modules=[Extension("yaseer.basic.arithmetic._mbf_fast", ["yaseer/basic/arithmetic/_mbf_fast.c"],
                           depends=["yaseer/basic/arithmetic/_bound_routine.h"], optional=True),
                 Extension("yaseer.basic.arithmetic._decimal_fast", ["yaseer/basic/arithmetic/_decimal_fast.c"],
                           depends=["yaseer/basic/arithmetic/_bound_routine.h"], optional=True),
                 Extension("yaseer.linkages._straight_fast", ["yaseer/linkages/_straight_fast.c"], optional=True)],
    cmdclass={"build_ext": BuildExt},
)
