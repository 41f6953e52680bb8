"""yaseer: a pocket-computer BASIC that runs the Al-Yaseer listings.

Flow: source text -> tokens (``basic.scanner``) -> AST (``basic.parser``) ->
compiled program (``basic.compiler``) -> machine state (``basic.machine``) -> output.
The numerics live in ``linkages`` and know nothing of BASIC; ``binding`` maps
``GOSUB PROG n`` to them.
"""

__version__ = "0.1.0"
