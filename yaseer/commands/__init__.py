"""One module per ``yaseer`` sub-command; each defines ``add_arguments(parser)`` and ``main(args) -> int``."""
