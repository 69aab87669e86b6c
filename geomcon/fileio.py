"""Writing outputs all-or-nothing: every text is rendered first, then written to a temporary file beside
its target and renamed over it, so a failure never leaves a half-written file.

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
import tempfile
from pathlib import Path
from typing import Mapping


def write_all(files: Mapping[Path | str, str]) -> None:
    """Write every ``path → text``: all temporaries first, then the renames (UTF-8, ``\\n`` newlines)."""
    staged: list[tuple[str, Path]] = []
    try:
        for path, text in files.items():
            target = Path(path)
            target.parent.mkdir(parents=True, exist_ok=True)
            fd, tmp = tempfile.mkstemp(dir=target.parent, prefix=f".{target.name}.", suffix=".tmp")
            with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as fh:
                fh.write(text)
            staged.append((tmp, target))
    except BaseException:
        for tmp, _ in staged:
            os.unlink(tmp)
        raise
    for tmp, target in staged:
        os.replace(tmp, target)
