"""The one directory a program's files live in, reached without a race.

Every name a program (or the interactive session) gives is looked up in one
directory, the *sandbox*.  A name is checked as text first (an absolute name, a
drive, a ``..`` component or a ``:`` is ``Path/File access error``, an empty name
or a part over :data:`NAME_MAX` bytes ``Bad file name``), then walked one
component at a time from a descriptor of the directory, each opened relative to
the one before without following links (``openat`` with ``O_NOFOLLOW``).  A
symbolic link met on the way is read and its target walked by the same rules (a
link inside the directory is followed; one leading out of it, or more than
:data:`MAX_LINKS` of them, is ``Path/File access error``).  The file itself is
opened by the descriptor of its directory, again without following a link, and
checked through its own descriptor: so a second process that swaps a file for a
link between the check and the use meets ``O_NOFOLLOW`` and an error, never a
file outside.  A new file is created with ``O_CREAT | O_EXCL``; an existing one
is written only if it is a regular file with one name (a hard link could lead
out); a FIFO, device or directory is refused at once (opened non-blocking, it
never waits for a writer).
"""

from __future__ import annotations

import errno
import os
import stat

from yaseer.basic.errors import (
    BAD_FILE_NAME, FILE_ALREADY_EXISTS, FILE_NOT_FOUND, PATH_FILE_ACCESS_ERROR, PATH_NOT_FOUND, BasicError, error_for,
)

NAME_MAX = 255  # bytes in one part of a name (Linux's NAME_MAX; longer is Bad file name)
MAX_LINKS = 40  # symbolic links followed in one name (Linux's own limit)
_NOFOLLOW = getattr(os, "O_NOFOLLOW", 0)
_DIRECTORY = getattr(os, "O_DIRECTORY", 0)
_NONBLOCK = getattr(os, "O_NONBLOCK", 0)
_CLOEXEC = getattr(os, "O_CLOEXEC", 0)


def _os_error(error: OSError) -> BasicError:
    """The BASIC error for a failed system call on a name inside the sandbox."""
    if error.errno == errno.ENOENT:
        return error_for(FILE_NOT_FOUND)
    if error.errno == errno.ENAMETOOLONG:
        return error_for(BAD_FILE_NAME)
    return error_for(PATH_FILE_ACCESS_ERROR)


def nameless(name: str) -> bool:
    """Does ``name`` name nothing as DOS reads it: nothing but blanks up to a NUL, or only
    blanks before its first ``.`` (DOS drops a name's trailing blanks: ``"  .TXT"``)?"""
    head = name.split("\x00", 1)[0]
    stem = head.split(".", 1)[0]
    return not head.strip(" ") or (stem != "" and not stem.strip(" "))


class Sandbox:
    """The one directory a program's files live in (see the module docstring)."""

    def __init__(self, root: str | os.PathLike | None = None, reserved: frozenset = frozenset(),
                 nameless: int = BAD_FILE_NAME):
        self._root = os.fspath(root) if root is not None else os.getcwd()
        self.current: list[str] = []  # CHDIR's directory: its parts from the sandbox's top (its "root")
        self.reserved = reserved  # names of devices (DOS's CON, NUL ...), whatever the extension: never made
        self.nameless = nameless  # the error of a name that names nothing (Dialect.nameless_file_error)

    def _not_reserved(self, name: str) -> None:
        """Refuse to make a file named as a device (``Path/File access error``): on DOS the
        name is the device, so a program meaning it must never leave such a file behind."""
        if self.reserved and self.parts(name)[-1].split(".", 1)[0].rstrip().upper() in self.reserved:
            raise error_for(PATH_FILE_ACCESS_ERROR)

    # ---------------------------------------------------------------- names
    def parts(self, name: str) -> list[str]:
        """The components of ``name`` from the sandbox's top, checked as text (see the module
        docstring), read from CHDIR's directory (``current``; ``..`` goes up, above the top
        ``Path/File access error``); a name that names nothing (:func:`nameless`) is the
        sandbox's ``nameless`` error."""
        parts = self._resolved(name)
        if not parts:
            raise error_for(BAD_FILE_NAME)
        return parts

    def _resolved(self, name: str) -> list[str]:
        """:meth:`parts`, which may be none (the top itself: ``CHDIR ".."`` from a folder)."""
        if nameless(name):
            raise error_for(self.nameless)
        if "\x00" in name:
            raise error_for(BAD_FILE_NAME)
        text = name.replace("\\", "/")
        if text.startswith("/") or ":" in name:
            raise error_for(PATH_FILE_ACCESS_ERROR)
        parts = list(self.current)  # a name is read from CHDIR's directory, ".." going up
        for part in text.split("/"):
            if part == "..":
                if not parts:  # above the sandbox's top
                    raise error_for(PATH_FILE_ACCESS_ERROR)
                parts.pop()
            elif part not in ("", "."):
                parts.append(part)
        if any(len(os.fsencode(part)) > NAME_MAX for part in parts):
            raise error_for(BAD_FILE_NAME)
        return parts

    def check(self, name: str) -> None:
        """Refuse ``name`` as :meth:`parts` does (a FILES pattern, before it is matched)."""
        self.parts(name)

    def dos_name(self, name: str) -> str:
        """``name``, or, when nothing has it exactly, the name of the one entry in its folder
        whose name differs from it only in case (DOS ignores case: ``"data.txt"`` opens
        ``DATA.TXT``); the sandbox's rules apply to ``name`` first.  Only a name: whatever
        uses it walks it again, so a swap after this look cannot lead out."""
        directory, leaf = self._walk(name, follow_last=False)
        try:
            try:
                os.stat(leaf, dir_fd=directory, follow_symlinks=False)
                return name
            except FileNotFoundError:
                matches = [entry for entry in os.listdir(directory) if entry.upper() == leaf.upper()]
        except OSError:
            return name
        finally:
            os.close(directory)
        if len(matches) != 1:
            return name
        folder = name.replace("\\", "/").rpartition("/")[0]
        return (folder + "/" if folder else "") + matches[0]

    def _walk(self, name: str | None, follow_last: bool = True, parts: list[str] | None = None) -> tuple[int, str]:
        """(an open descriptor of the directory holding ``name``'s last component, that component);
        links on the way (and the last one, with ``follow_last``) followed inside the sandbox only.
        ``parts``: the components from the top instead of a name.  The caller closes the descriptor."""
        pending = list(parts) if parts is not None else self.parts(name)
        stack = [self._top()]
        links = 0
        try:
            while True:
                part = pending.pop(0)
                if part == "..":  # only from a link's target
                    if len(stack) == 1:
                        raise error_for(PATH_FILE_ACCESS_ERROR)
                    os.close(stack.pop())
                    continue
                if not pending and not follow_last:
                    return stack.pop(), part
                target = _link_target(part, stack[-1])
                if target is not None:
                    links += 1
                    if links > MAX_LINKS:
                        raise error_for(PATH_FILE_ACCESS_ERROR)
                    if os.path.isabs(target):  # allowed when it names a place inside the sandbox
                        inside = os.path.relpath(target, os.path.realpath(self._root))
                        if inside == ".." or inside.startswith("../"):
                            raise error_for(PATH_FILE_ACCESS_ERROR)
                        while len(stack) > 1:
                            os.close(stack.pop())
                        target = inside
                    pending = [p for p in target.split("/") if p not in ("", ".")] + pending
                    if not pending:
                        raise error_for(PATH_FILE_ACCESS_ERROR)  # a link to the sandbox itself
                    continue
                if not pending:
                    return stack.pop(), part
                try:
                    stack.append(os.open(part, os.O_RDONLY | _DIRECTORY | _NOFOLLOW | _CLOEXEC, dir_fd=stack[-1]))
                except OSError as error:
                    if error.errno == errno.ENOTDIR:
                        raise error_for(PATH_FILE_ACCESS_ERROR) from None
                    raise _os_error(error) from None
        finally:
            for descriptor in stack:
                os.close(descriptor)

    # ---------------------------------------------------------------- directories
    def change_directory(self, name: str) -> None:
        """CHDIR name: the directory names are read from from now on (the sandbox's top is
        the drive's root: nothing above it is reached); a missing one ``Path not found``."""
        parts = self._directory_name(name)
        if parts:
            os.close(self._open_directory(parts))
        self.current = parts

    def make_directory(self, name: str) -> None:
        """MKDIR name: a new directory (one there already, or a file of that name,
        ``Path/File access error``; its folder missing ``Path not found``)."""
        parts = self._directory_name(name)
        if not parts:
            raise error_for(PATH_FILE_ACCESS_ERROR)
        self._not_reserved(name)
        directory, leaf = self._directory_walk(parts, follow_last=False)
        try:
            os.mkdir(leaf, 0o777, dir_fd=directory)
        except FileExistsError:
            raise error_for(PATH_FILE_ACCESS_ERROR) from None
        except OSError as error:
            raise _directory_error(error) from None
        finally:
            os.close(directory)

    def remove_directory(self, name: str) -> None:
        """RMDIR name: an empty directory removed (not the current one or one holding it, nor a
        directory with entries: ``Path/File access error``; a missing one, a file or a link
        ``Path not found``)."""
        parts = self._directory_name(name)
        if not parts or self.current[:len(parts)] == parts:
            raise error_for(PATH_FILE_ACCESS_ERROR)
        directory, leaf = self._directory_walk(parts, follow_last=False)
        try:
            if not stat.S_ISDIR(os.stat(leaf, dir_fd=directory, follow_symlinks=False).st_mode):
                raise error_for(PATH_NOT_FOUND)
            os.rmdir(leaf, dir_fd=directory)
        except OSError as error:
            raise _directory_error(error) from None
        finally:
            os.close(directory)

    def _directory_name(self, name: str) -> list[str]:
        """A directory's parts from the top (none: the top); an empty name ``Bad file name``."""
        if nameless(name):
            raise error_for(BAD_FILE_NAME)
        return self._resolved(name)

    def _directory_walk(self, parts: list[str], follow_last: bool) -> tuple[int, str]:
        """:meth:`_walk` of ``parts``, a missing folder on the way ``Path not found``."""
        try:
            return self._walk(None, follow_last, parts)
        except BasicError as error:
            if error.code == FILE_NOT_FOUND:
                raise error_for(PATH_NOT_FOUND) from None
            raise

    def _open_directory(self, parts: list[str]) -> int:
        """A descriptor of the directory ``parts`` (none: the top), walked as every name is."""
        if not parts:
            return self._top()
        directory, leaf = self._directory_walk(parts, follow_last=True)
        try:
            return os.open(leaf, os.O_RDONLY | _DIRECTORY | _NOFOLLOW | _CLOEXEC, dir_fd=directory)
        except OSError as error:
            raise _directory_error(error) from None
        finally:
            os.close(directory)

    def current_path(self) -> str:
        """CHDIR's directory as DOS shows it after the drive: ``\\`` and the folders."""
        return "\\" + "\\".join(self.current)

    # ---------------------------------------------------------------- listings
    def listing(self, pattern: str | None = None) -> list[str]:
        """FILES [pattern]: the names of the files in the sandbox that match (``*`` ``?``);
        a pattern nothing matches is ``File not found`` (GW-BASIC)."""
        import fnmatch

        if pattern is not None:
            self.check(pattern.replace("*", "x").replace("?", "x"))  # the same rules for the pattern
        names = sorted(entry.name for entry in self._entries() if not entry.is_dir(follow_symlinks=False))
        found = [n for n in names if fnmatch.fnmatch(n.upper(), (pattern or "*").upper())]
        if pattern is not None and not found:
            raise error_for(FILE_NOT_FOUND)
        return found

    def directory(self, pattern: str | None = None) -> list[str]:
        """FILES [pattern]: GW-BASIC's entries for the sandbox's directories (``.`` and
        ``..`` too) then its files, each sorted, whose 8.3 names match ``pattern``
        (``*`` ``?``; name and extension matched apart, as DOS does: ``A*`` is only
        names without extension); each entry 17 columns: :func:`directory_entry`.
        Names starting with ``.`` are hidden."""
        import fnmatch

        if pattern is not None:
            if not pattern:
                raise error_for(BAD_FILE_NAME)
            if pattern not in (".", ".."):  # (DOS matches these to the entries "." and "..")
                self.check(pattern.replace("*", "x").replace("?", "x"))  # the same rules for the pattern
        mask = dos_split((pattern or "*.*").upper())
        dirs, files = [("", ""), ("", ".")], []
        for entry in self._entries():
            if not entry.name.startswith("."):
                (dirs if entry.is_dir(follow_symlinks=False) else files).append(dos_split(entry.name.upper()))
        return [directory_entry(name, is_dir) for group, is_dir in ((dirs, True), (files, False))
                for name in sorted(n for n in group if all(map(fnmatch.fnmatchcase, n, mask)))]

    def _entries(self) -> list:
        """The directory's entries (``os.DirEntry``, read through a descriptor of it; a link is
        shown as what it is, never followed)."""
        directory = self._open_directory(self.current)
        try:
            with os.scandir(directory) as entries:
                return list(entries)
        except OSError as error:
            raise _os_error(error) from None
        finally:
            os.close(directory)

    def free_bytes(self) -> int:
        """The free bytes of the sandbox's disk (FILES' last line)."""
        directory = self._top()
        try:
            status = os.statvfs(directory)
        finally:
            os.close(directory)
        return status.f_bavail * status.f_frsize

    def _top(self) -> int:
        """A descriptor of the sandbox's directory (the caller closes it)."""
        try:
            return os.open(self._root, os.O_RDONLY | _DIRECTORY | _CLOEXEC)
        except OSError as error:
            raise _os_error(error) from None

    # ---------------------------------------------------------------- files
    def open_input(self, name: str) -> int:
        """A descriptor of the regular file ``name`` opened for reading (never blocking):
        ``File not found`` when it is missing or a directory, ``Path/File access error``
        for a FIFO, device or socket."""
        directory, leaf = self._walk(name)
        try:
            descriptor = os.open(leaf, os.O_RDONLY | _NOFOLLOW | _NONBLOCK | _CLOEXEC, dir_fd=directory)
        except OSError as error:
            raise (error_for(FILE_NOT_FOUND) if error.errno == errno.EISDIR else _os_error(error)) from None
        finally:
            os.close(directory)
        return _regular(descriptor)

    def open_output(self, name: str, readable: bool = False) -> int:
        """A descriptor of file ``name`` for writing (``readable``: also reading), created new
        (``O_CREAT | O_EXCL``) or an existing regular file with one name; nothing is truncated."""
        self._not_reserved(name)
        directory, leaf = self._walk(name)
        access = os.O_RDWR if readable else os.O_WRONLY
        try:
            try:
                descriptor = os.open(leaf, access | os.O_CREAT | os.O_EXCL | _NOFOLLOW | _CLOEXEC, 0o666,
                                     dir_fd=directory)
            except FileExistsError:
                descriptor = os.open(leaf, access | _NOFOLLOW | _NONBLOCK | _CLOEXEC, dir_fd=directory)
            descriptor = _regular(descriptor)
            _still_named(descriptor, leaf, directory)
        except OSError as error:
            raise _os_error(error) from None
        finally:
            os.close(directory)
        return descriptor

    def read_bytes(self, name: str) -> bytes:
        """The whole of the regular file ``name``."""
        with os.fdopen(self.open_input(name), "rb") as handle:
            return handle.read()

    def write_bytes(self, name: str, data: bytes) -> None:
        """Replace the contents of file ``name`` (created if missing) with ``data``."""
        with os.fdopen(self.open_output(name), "wb") as handle:
            handle.truncate(0)
            handle.write(data)

    def exists(self, name: str) -> bool:
        """Whether ``name`` is a regular file (its links followed inside the sandbox)."""
        try:
            os.close(self.open_input(name))
        except BasicError:
            return False
        return True

    def identity(self, name: str) -> tuple[int, int]:
        """(device, inode) of the regular file ``name``, to tell whether two names are one file."""
        descriptor = self.open_input(name)
        try:
            return identity_of(descriptor)
        finally:
            os.close(descriptor)

    def kill(self, name: str) -> None:
        """KILL name: delete the file (the name itself: a link inside is removed, not its target)."""
        self.identity(name)  # a regular file inside, or the error
        directory, leaf = self._walk(name, follow_last=False)
        try:
            os.unlink(leaf, dir_fd=directory)
        except OSError as error:
            raise _os_error(error) from None
        finally:
            os.close(directory)

    def rename(self, old: str, new: str) -> None:
        """NAME old AS new (the names themselves, never what a link points to)."""
        self.identity(old)
        self._not_reserved(new)
        source, old_leaf = self._walk(old, follow_last=False)
        try:
            target, new_leaf = self._walk(new, follow_last=False)
            try:
                try:
                    os.stat(new_leaf, dir_fd=target, follow_symlinks=False)
                except FileNotFoundError:
                    pass
                else:
                    raise error_for(FILE_ALREADY_EXISTS)
                os.rename(old_leaf, new_leaf, src_dir_fd=source, dst_dir_fd=target)
            except OSError as error:
                raise _os_error(error) from None
            finally:
                os.close(target)
        finally:
            os.close(source)


def _directory_error(error: OSError) -> BasicError:
    """The BASIC error of a failed directory call: missing (or not a directory) ``Path not
    found``, any other ``Path/File access error``."""
    if error.errno in (errno.ENOENT, errno.ENOTDIR, errno.ELOOP):
        return error_for(PATH_NOT_FOUND)
    return error_for(PATH_FILE_ACCESS_ERROR)


def _link_target(name: str, directory: int) -> str | None:
    """The target of ``name`` in ``directory`` if it is a symbolic link, else None."""
    try:
        return os.readlink(name, dir_fd=directory)
    except OSError as error:
        if error.errno in (errno.EINVAL, errno.ENOENT):  # not a link, or nothing there yet
            return None
        raise _os_error(error) from None


def identity_of(descriptor: int) -> tuple[int, int]:
    """(device, inode) of an open file: two descriptors with the same one are one file."""
    status = os.fstat(descriptor)
    return status.st_dev, status.st_ino


def _still_named(descriptor: int, leaf: str, directory: int) -> None:
    """Refuse (closing ``descriptor``) a file opened for writing unless ``leaf`` in
    ``directory`` names it while it has that one name.  The name may be swapped for a hard
    link to a file outside around the open and swapped back, so the link count alone can
    read 1 for the file outside: the count is read before and after the name is looked at,
    and a link or unlink in between changes the file's ctime, so equal counts of 1 and an
    equal ctime mean the name looked at was the file's only name."""
    try:
        before = os.fstat(descriptor)
        entry = os.stat(leaf, dir_fd=directory, follow_symlinks=False)
        after = os.fstat(descriptor)
    except OSError:
        os.close(descriptor)
        raise
    if ((entry.st_dev, entry.st_ino) != (after.st_dev, after.st_ino) or before.st_nlink != 1
            or after.st_nlink != 1 or before.st_ctime_ns != after.st_ctime_ns):
        os.close(descriptor)
        raise error_for(PATH_FILE_ACCESS_ERROR)


def _regular(descriptor: int) -> int:
    """``descriptor`` if it is a regular file, blocking again; otherwise closed and an error
    (a file to be written is checked for its one name by :func:`_still_named`)."""
    status = os.fstat(descriptor)
    if stat.S_ISREG(status.st_mode):
        os.set_blocking(descriptor, True)
        return descriptor
    os.close(descriptor)
    raise error_for(FILE_NOT_FOUND if stat.S_ISDIR(status.st_mode) else PATH_FILE_ACCESS_ERROR)


def dos_split(name: str) -> tuple[str, str]:
    """A name as DOS shows it: (name, extension) split at the first ``.``, clipped to
    8 and 3 characters with ``+`` marking a clipped one (``LONGNAME1.DAT`` is
    ``LONGNAM+``, ``DAT``)."""
    trunk, _, ext = name.partition(".")
    if len(trunk) > 8:
        trunk = trunk[:7] + "+"
    if len(ext) > 3:
        ext = ext[:2] + "+"
    return trunk, ext


def directory_entry(name: tuple[str, str], is_dir: bool) -> str:
    """One FILES entry: the name in 8 columns, ``.`` and the extension in 4, then
    ``<DIR>`` or 5 blanks (``A       .BAS     ``; ``.`` itself is ``        .   <DIR>``)."""
    trunk, ext = name
    return trunk.ljust(8) + ("." if ext or not trunk else " ") + ext.ljust(3) + ("<DIR>" if is_dir else " " * 5)
