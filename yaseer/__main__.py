import _signal

# Ctrl-C while yaseer.entry is still being found ends the program as the shell's Ctrl-C does
# (no traceback); yaseer.entry then puts its one-line handler in place.
_signal.signal(_signal.SIGINT, _signal.SIG_DFL)

from yaseer.entry import main  # noqa: E402

raise SystemExit(main())
