"""yaseer: a pocket-computer BASIC that runs the Al-Yaseer listings.

Flow: source text -> tokens (``basic.source.scanner``) -> AST (``basic.source.parser``) ->
blocks and Python (``basic.compile``) -> machine state (``basic.machine``) -> output.
The numerics live in ``linkages`` and know nothing of BASIC; ``binding`` maps
``GOSUB PROG n`` to them.

From Python: ``yaseer.run(listing, ...)`` (see ``yaseer.api``); in Jupyter:
``%load_ext yaseer`` then ``%%basic`` (see ``yaseer.jupyter``).  Importing this
package imports nothing else: ``run`` and ``Result`` are loaded on first use.
"""

from yaseer.version import __version__
__all__ = ["run", "Result", "load_ipython_extension"]


def __getattr__(name: str):
    if name in ("run", "Result"):
        from yaseer import api

        return getattr(api, name)
    raise AttributeError(f"module 'yaseer' has no attribute {name!r}")


def load_ipython_extension(ipython) -> None:
    """``%load_ext yaseer``: register the ``%basic`` / ``%%basic`` magics."""
    from yaseer.jupyter import load_ipython_extension as load

    load(ipython)
