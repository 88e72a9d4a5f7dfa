"""The files a command writes, checked before it starts.

A run can take minutes; an output that cannot be written must not fail after it (and lose the run),
and no output may overwrite a file the run reads (the program, machine file, scenario, key script)
or another output. Every check names the option and the path; a failure is a usage error.
"""

from __future__ import annotations

import errno
import os
import re
import stat
from contextlib import contextmanager
from pathlib import Path

from .diagnostics import UsageError
from .records import FrozenRecord

#: what ``--plot`` draws into (matplotlib picks the format from the extension)
PLOT_SUFFIXES = (".png", ".svg", ".pdf")
#: ``--screen-dir`` names its pictures screen_001.png, screen_002.png, ...
SCREEN_PICTURE = re.compile(r"screen_\d{3,}\.png", re.IGNORECASE)


class Output(FrozenRecord):
    """One output option: a file, or (``folder``) a folder the run writes files into."""

    __slots__ = ("option", "path", "suffixes", "folder", "names", "parents")

    def __init__(self, option: str, path: str | None, suffixes: tuple[str, ...] = (), folder: bool = False,
                 names: re.Pattern | None = None, parents: bool = False):
        self.option = option
        self.path = path  # None: the option is not given
        self.suffixes = suffixes  # the extensions the option accepts; empty = any
        self.folder = folder
        self.names = names  # a folder: the names of the files the run writes into it
        self.parents = parents  # a folder: made with its missing parents (else its parent must exist)


class OutputError(UsageError):
    """An output that fails while it is written (a full disk, an I/O error): a usage error, not a bug."""

    def __init__(self, path, error: OSError):
        super().__init__(f"{path}: cannot write: {_reason(error)}")


def check_outputs(outputs: list[Output], inputs: dict[str, str | None], state: str | None = None,
                  json_stdout: bool = False, program_path=(), file_root: str | None = None) -> None:
    """Raise UsageError unless every output can be written and none overwrites an input or another
    output. ``inputs`` maps an option (or "program") to the file it reads (None: not given). No output
    goes into the ``state`` directory (the permanent store, link tables, controller files) or the
    machine's ``file_root`` (the files programs read and write as the run goes), nor, with
    ``json_stdout``, onto stdout, which carries the JSON document, nor onto a program in a folder of the
    machine's ``program_path`` that the run may call (read only when it is called, after the outputs are
    opened)."""
    outputs = [out for out in outputs if out.path]
    read = {what: path for what, path in inputs.items() if path}
    private = {folder: what for folder, what in ((state, "the state directory {} (the controller's memory)"),
                                                 (file_root, "the controller's file root {} (its files)")) if folder}
    for i, out in enumerate(outputs):
        _check_suffix(out)
        for folder, what in private.items():
            if _inside(out.path, folder):
                raise UsageError(f"{out.option} {out.path}: is inside {what.format(folder)}; write it elsewhere")
        (_check_folder if out.folder else _check_file)(out)
        if json_stdout and not out.folder and _is_stdout(out.path):
            raise UsageError(f"{out.option} {out.path}: is stdout, which carries the JSON document; "
                             f"write it to a file")
        for what, path in read.items():
            if _clash(out, path):
                writer = "a file it writes" if out.folder else "it"
                raise UsageError(f"{out.option} {out.path}: {writer} would overwrite the {_input_name(what, path)}")
        if not out.folder and _is_program(out.path, program_path):
            raise UsageError(f"{out.option} {out.path}: would overwrite a program the run may call as a "
                             f"sub-program; write it elsewhere")
        for other in outputs[:i]:
            folder, file = (out, other) if out.folder else (other, out)
            if not file.folder and _clash(folder, file.path):
                same = "has the name of a file written by" if folder.folder else "is the same file as"
                raise UsageError(f"{file.option} {file.path}: {same} {folder.option} {folder.path}")


def refuse_overwrite(option: str, target: Path, source: str) -> None:
    """An output whose name the command chooses itself (``compile`` without -o) is not the source."""
    if _same(str(target), source):
        raise UsageError(f"{option} {target}: would overwrite the source {source}; give another name with -o")


def write_output(path: Path, text: str) -> None:
    """Write an output a command makes in one piece (``compile``'s object and listing); a full disk is a
    usage error naming the file."""
    try:
        path.write_text(text, encoding="latin-1")
    except OSError as e:
        raise OutputError(path, e) from None


@contextmanager
def replacing(path: Path, suffix: str | None = None):
    """A temporary file beside ``path`` (through symbolic links: a link stays a link) for the caller to
    write, moved into place with the permissions of the file it replaces when the block ends normally, and
    removed when it does not (an error, Ctrl-C, a SIGTERM): ``path`` is whole, or as it was. The temporary
    name ends in ``suffix`` (default ``.part`` and the extension of ``path``, which matplotlib reads). A
    path that is not a regular file (a FIFO, a device) is written as it is: it cannot be replaced."""
    import tempfile  # only for an output written so (start-up, issue 18)

    real = Path(os.path.realpath(path))
    if real.exists() and not real.is_file():
        yield str(path)
        return
    fd, name = tempfile.mkstemp(dir=real.parent, prefix=f".{real.name}.",
                                suffix=f".part{real.suffix}" if suffix is None else suffix)
    os.close(fd)
    try:
        yield name
        os.chmod(name, _mode(real))
        os.replace(name, real)
    except BaseException:
        Path(name).unlink(missing_ok=True)
        raise


def _mode(path: Path) -> int:
    """The permissions of the file replaced, or those a new file gets (not the temporary file's 0600)."""
    try:
        return stat.S_IMODE(os.stat(path).st_mode)
    except FileNotFoundError:
        umask = os.umask(0)
        os.umask(umask)
        return 0o666 & ~umask


def _input_name(what: str, path: str) -> str:
    """"the program p.din", "the input of --keys k.keys" (``what`` is an option or the name of an input)."""
    return f"input of {what} {path}" if what.startswith("-") else f"{what} {path}"


def _check_suffix(out: Output) -> None:
    if out.suffixes and Path(out.path).suffix.lower() not in out.suffixes:
        raise UsageError(f"{out.option} {out.path}: the file name must end in "
                         f"{' or '.join(out.suffixes)} (the extension chooses the format)")


def _check_file(out: Output) -> None:
    path = Path(out.path)
    if path.exists() and not path.is_file() and not path.is_dir():
        # a device or a pipe, also behind /dev/stdout -> /proc/self/fd/1 -> pipe:[N] (no real path);
        # opening it could block
        if not os.access(path, os.W_OK):
            raise UsageError(f"{out.option} {out.path}: cannot write: {os.strerror(errno.EACCES)}")
        return
    real = Path(os.path.realpath(path))  # a symbolic link writes where it points
    if real.is_dir():
        raise UsageError(f"{out.option} {out.path}: is a folder, not a file")
    _check_parent(out, real.parent, real.parent if path.is_symlink() else path.parent)
    try:
        if real.exists():
            open(real, "ab").close()  # appends nothing: the file stays as it is until the run writes it
        else:
            os.close(os.open(real, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666))
            real.unlink()
    except OSError as e:
        raise UsageError(f"{out.option} {out.path}: cannot write: {_reason(e)}") from None


def _check_folder(out: Output) -> None:
    real = Path(os.path.realpath(out.path))
    if real.exists() and not real.is_dir():
        raise UsageError(f"{out.option} {out.path}: is not a folder")
    folder, shown = real, Path(out.path)
    if out.parents:  # made with its parents: the nearest folder that exists must take them
        while not folder.exists():
            folder, shown = folder.parent, shown.parent
        if not folder.is_dir():
            raise UsageError(f"{out.option} {out.path}: {shown} is not a folder")
    elif not real.exists():  # made when it is first written, in a folder that exists
        folder, shown = real.parent, shown.parent
        _check_parent(out, folder, shown)
    import tempfile  # only a command with an output folder to try pays for it (start-up)

    try:
        tempfile.TemporaryFile(dir=folder).close()
    except OSError as e:
        raise UsageError(f"{out.option} {out.path}: cannot write into folder {shown}: {_reason(e)}") from None


def _check_parent(out: Output, folder: Path, shown: Path) -> None:
    """The folder a file goes into exists: ncvm makes no folders for files (``shown``: its name as given)."""
    if not folder.exists():
        raise UsageError(f"{out.option} {out.path}: folder {shown} does not exist")
    if not folder.is_dir():
        raise UsageError(f"{out.option} {out.path}: {shown} is not a folder")


def _reason(e: OSError) -> str:
    # creating a file where the file system has no such thing (/proc, /sys) fails with ENOENT
    return "files cannot be made there" if e.errno == errno.ENOENT else e.strerror or str(e)


def _inside(path: str, folder: str) -> bool:
    """``path`` is ``folder`` or below it (through any symbolic links)."""
    real, top = os.path.realpath(path), os.path.realpath(folder)
    return real == top or real.startswith(top.rstrip(os.sep) + os.sep)


def _is_program(path: str, program_path) -> bool:
    """An existing file in a folder of the program path with no extension (a CPL sub-program) or a program
    extension, unless ncvm wrote it (its flat G-code, written again by the next run)."""
    from .dialects import EXTENSIONS
    from .translate.output import MARK, written_by_ncvm

    real = Path(os.path.realpath(path))
    if not real.is_file() or (real.suffix and real.suffix.lower() not in EXTENSIONS):
        return False
    if not any(real.parent == Path(os.path.realpath(folder)) for folder in program_path):
        return False
    try:
        with open(real, "rb") as f:
            return not written_by_ncvm(f.read(len(MARK) + 8).decode("latin-1"))
    except OSError:
        return False


def _is_stdout(path: str) -> bool:
    """``path`` is where stdout goes (/dev/stdout, the file stdout is redirected to); /dev/null takes anything."""
    try:
        st = os.stat(path)
        return os.path.samestat(st, os.fstat(1)) and not os.path.samestat(st, os.stat(os.devnull))
    except OSError:  # no such file yet, or no stdout
        return False


def _clash(out: Output, path: str) -> bool:
    """Would ``out`` write the file ``path`` (for a folder output: as one of the files it writes there)?"""
    if out.folder:
        p = Path(os.path.realpath(path))
        return (out.names is not None and p.parent == Path(os.path.realpath(out.path))
                and bool(out.names.fullmatch(p.name)))
    return _same(out.path, path)


def _same(a: str, b: str) -> bool:
    """The same file: one real path, or two names (hard links) of one existing file. Devices and pipes
    (/dev/null, /dev/stdout) are not files to keep: any number of options may name them."""
    if any(os.path.exists(p) and not os.path.isfile(p) for p in (a, b)):
        return False
    if os.path.realpath(a) == os.path.realpath(b):
        return True
    try:
        return os.path.samefile(a, b)
    except OSError:
        return False
