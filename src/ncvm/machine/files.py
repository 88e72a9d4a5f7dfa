"""The controller's file root: every file a program opens is resolved here.

A program's file name can never reach outside the root: absolute paths and
drive letters are mapped inside it, and ``..`` that would climb out is refused.
"""

from __future__ import annotations

from pathlib import Path, PurePosixPath


class FileRootError(ValueError):
    """A file name that cannot be placed inside the controller's file root."""


def resolve_in_root(root: Path, name: str) -> Path:
    """Map the control's file name ``name`` to a path inside ``root``.

    ``C:\\DATA\\LOG.TXT`` and ``/DATA/LOG.TXT`` both become ``<root>/DATA/LOG.TXT``;
    a name that climbs above the root with ``..`` raises :class:`FileRootError`.
    """
    text = name.strip().replace("\\", "/")
    if len(text) >= 2 and text[1] == ":" and text[0].isalpha():  # drive letter
        text = text[2:]
    parts = []
    for part in PurePosixPath(text).parts:
        if part in ("/", "", "."):
            continue
        if part == "..":
            if not parts:
                raise FileRootError(name)
            parts.pop()
            continue
        parts.append(part)
    if not parts:
        raise FileRootError(name)
    root = root.resolve()
    path = root.joinpath(*parts)
    resolved = path.resolve()
    if resolved != root and root not in resolved.parents:  # a symlink pointing out
        raise FileRootError(name)
    return path
