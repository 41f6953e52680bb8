"""Where a command's output goes: ``--out`` places, and streams whose errors name them.

``--out`` means the same in every command: a FILE where the command writes one
file (``animate``), a DIR where it writes several (``plot``, ``bench``,
``stability``, ``centrode``).  Missing parent directories are created; a place
that cannot be used is a :class:`~yaseer.commands.options.CommandError` naming it.
"""

from __future__ import annotations


class NamedStream:
    """Wraps a text stream; an ``OSError`` from write, flush or close becomes an
    :class:`~yaseer.basic.errors.OutputError` naming ``name`` (which a running
    BASIC machine lets through instead of making it a BASIC error).

    (``standard output: No space left on device``, ``/dev/full: No space left on
    device``.)  A BrokenPipeError passes unchanged (the reader went away: a quiet
    stop, see ``yaseer.cli``); everything else is the wrapped stream's.
    """

    def __init__(self, stream, name: str) -> None:
        self._stream = stream
        self.name = name

    def write(self, text: str) -> int:
        return self._call(self._stream.write, text)

    def flush(self) -> None:
        self._call(self._stream.flush)

    def close(self) -> None:
        self._call(self._stream.close)

    def _call(self, method, *arguments):
        try:
            return method(*arguments)
        except BrokenPipeError:
            raise
        except OSError as error:
            from yaseer.basic.errors import OutputError

            raise OutputError(error.errno, error.strerror or str(error), self.name) from None

    def __getattr__(self, name: str):
        return getattr(self._stream, name)


def open_for_writing(path: str) -> NamedStream:
    """``path`` opened for writing text (replaced), its errors naming it."""
    return NamedStream(open(path, "w", encoding="utf-8"), path)


def output_directory(path):
    """``--out DIR`` made ready (a ``pathlib.Path``): created with its parents; an error naming it if it is a file."""
    from pathlib import Path  # here, not at the top: `yaseer run` has no --out (start-up)

    from yaseer.commands.options import CommandError

    directory = Path(path)
    if directory.exists() and not directory.is_dir():
        raise CommandError(f"--out {directory}: is a file; --out names a directory here (several files are written)")
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise CommandError(f"--out {directory}: cannot create the directory: {error.strerror or error}") from None
    return directory


def output_file(path):
    """``--out FILE`` made ready (a ``pathlib.Path``): its directory created; an error naming it if it is a directory."""
    from pathlib import Path

    from yaseer.commands.options import CommandError

    file = Path(path)
    if file.is_dir():
        raise CommandError(f"--out {file}: is a directory; --out names the one file written here")
    try:
        file.parent.mkdir(parents=True, exist_ok=True)
    except OSError as error:
        raise CommandError(f"--out {file}: cannot create its directory: {error.strerror or error}") from None
    return file
