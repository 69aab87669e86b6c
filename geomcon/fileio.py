"""Writing outputs all-or-nothing: every target is checked before anything is computed
(:func:`check_targets`), every text is rendered first, then written to a temporary file beside its target
and renamed over it, so a failure never leaves a half-written file or a temporary behind. Files get the
permissions the umask allows (as ``open`` would create them), not the 0600 of ``mkstemp``.

Examples
--------
>>> import tempfile, pathlib
>>> d = pathlib.Path(tempfile.mkdtemp())
>>> write_all({d / "a.txt": "alpha", d / "sub" / "b.txt": "beta"})
>>> (d / "sub" / "b.txt").read_text()
'beta'
"""
from __future__ import annotations

import os
from pathlib import Path
from typing import Mapping

from .errors import ProblemError


def _umask() -> int:
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _parent_ok(path: Path) -> bool:
    """Whether ``path``'s parent exists as a directory or can be made (its first existing ancestor is a
    directory)."""
    for up in path.parents:
        if up.exists():
            return up.is_dir()
    return True


def check_targets(files: Mapping[str, str | Path], dirs: Mapping[str, str | Path] = {}) -> None:
    """Refuse, before anything is computed or written, an output that cannot be written: a file target that is
    a directory, a directory target that is a file, a parent that is a file.

    Parameters
    ----------
    files, dirs : mapping
        Option name (for the message) → path.

    Examples
    --------
    >>> import tempfile
    >>> d = tempfile.mkdtemp()
    >>> check_targets({"--svg": d})
    Traceback (most recent call last):
    ...
    geomcon.errors.ProblemError: --svg: the output path is a directory
    """
    for opt, p in files.items():
        path = Path(p)
        if path.is_dir():
            raise ProblemError(f"{opt}: the output path is a directory")
        if path.exists() and not path.is_file():
            raise ProblemError(f"{opt}: the output path exists and is not a regular file")
        if not _parent_ok(path):
            raise ProblemError(f"{opt}: the output's folder is not a directory")
    for opt, p in dirs.items():
        path = Path(p)
        if path.exists() and not path.is_dir():
            raise ProblemError(f"{opt}: the output path exists and is not a directory")
        if not _parent_ok(path / "x"):
            raise ProblemError(f"{opt}: the output's folder is not a directory")


def changed(files: Mapping[Path | str, str]) -> dict[Path | str, str]:
    """The entries of ``files`` (path → text) whose target is not already a regular file holding exactly the
    text's UTF-8 bytes: what :func:`write_all` must write for the folder to hold ``files``.

    ``geomcon gallery`` writes only these: reading and comparing the ~470 files of the gallery takes about a
    sixth of the time of writing them all again (16 MB through temporaries and renames), and a file that did not
    change keeps its time stamp.

    Examples
    --------
    >>> import tempfile, pathlib
    >>> d = pathlib.Path(tempfile.mkdtemp())
    >>> write_all({d / "a.txt": "alpha", d / "b.txt": "beta"})
    >>> sorted(p.name for p in changed({d / "a.txt": "alpha", d / "b.txt": "beta!", d / "c.txt": ""}))
    ['b.txt', 'c.txt']
    """
    out: dict[Path | str, str] = {}
    for path, text in files.items():
        try:
            with open(path, "rb") as fh:
                same = fh.read() == text.encode("utf-8")
        except OSError:              # missing, a directory, unreadable: write_all writes it or says why not
            same = False
        if not same:
            out[path] = text
    return out


def write_all(files: Mapping[Path | str, str]) -> None:
    """Write every ``path → text``: all temporaries first, then the renames (UTF-8, ``\\n`` newlines).

    Every temporary is removed whatever fails, and a target that turns out not to be writable by rename
    stops the writing before the first rename.
    """
    if not files:
        return
    import tempfile          # here: a solve that writes nothing (JSON to stdout) does not load it (random, shutil…)

    mode = 0o666 & ~_umask()
    staged: list[tuple[str, Path]] = []
    try:
        for path, text in files.items():
            target = Path(path)
            if target.is_dir():
                raise IsADirectoryError(21, "Is a directory", str(target))
            target.parent.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(dir=target.parent, prefix=f".{target.name}.", suffix=".tmp")
            staged.append((tmp, target))
            with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as fh:
                fh.write(text)
            os.chmod(tmp, mode)
        for tmp, target in staged:
            os.replace(tmp, target)
    finally:
        for tmp, _ in staged:
            if os.path.exists(tmp):
                os.unlink(tmp)
