"""The class list: ``CLASS.csv`` with a header holding ``id`` and optionally ``name`` (other columns are
ignored), or ``--count N`` students numbered 1 … N.

The file is untrusted and comes from spreadsheets: UTF-8 with or without a byte-order mark, UTF-16 with one,
or GBK/GB18030 (what Chinese spreadsheets export; GB18030 decodes every GBK file); commas, or semicolons or
tabs when the header holds no comma. Limits (:data:`LIMITS`) are checked before anything is solved; a
refusal names the line.

Examples
--------
>>> [s.id for s in parse_roster("id,name\\n2023001,张三\\n2023002,李四\\n".encode("gb18030"))]
['2023001', '2023002']
>>> parse_roster("\\ufeffname;ID\\nAnn;7\\n".encode("utf-8"))[0]
Student(id='7', name='Ann')
>>> [s.id for s in numbered(3)]
['1', '2', '3']
"""
from __future__ import annotations

import csv
import io
import os
import stat
import unicodedata
from dataclasses import dataclass
from pathlib import Path

from ..errors import ProblemError

LIMITS = {"file_bytes": 1 << 20, "students": 2000, "id_chars": 64, "name_chars": 200}
"""Size limits of a class list."""


@dataclass(frozen=True)
class Student:
    """One student: an id (unique in the class) and a name (may be empty)."""

    id: str
    name: str = ""


def numbered(count: int) -> tuple[Student, ...]:
    """Students ``1`` … ``count`` (no leading zeros, so that a larger count keeps every id)."""
    if not 1 <= count <= LIMITS["students"]:
        raise ProblemError(f"--count {count}: a class has 1 to {LIMITS['students']} students")
    return tuple(Student(str(i)) for i in range(1, count + 1))


def load_roster(path: str | Path) -> tuple[Student, ...]:
    """Read a class list file (a regular file of at most ``LIMITS['file_bytes']``)."""
    p = Path(path)
    try:
        st = os.stat(p)
        if not stat.S_ISREG(st.st_mode):
            raise ProblemError("--students: not a regular file")
        if st.st_size > LIMITS["file_bytes"]:
            raise ProblemError(f"--students: the file has {st.st_size} bytes; a class list is at most "
                               f"{LIMITS['file_bytes']} bytes")
        with open(p, "rb") as fh:
            raw = fh.read(LIMITS["file_bytes"] + 1)
    except OSError as exc:
        raise ProblemError(f"--students: cannot read the file: {exc.strerror or exc}") from None
    if len(raw) > LIMITS["file_bytes"]:
        raise ProblemError(f"--students: the file has more than {LIMITS['file_bytes']} bytes")
    return parse_roster(raw)


def decode(raw: bytes) -> str:
    """The text of a class list: UTF-8 (a BOM dropped), UTF-16 with a BOM, else GB18030.

    >>> decode("张三".encode("gbk")), decode(b"\\xef\\xbb\\xbfid"), decode("id".encode("utf-16"))
    ('张三', 'id', 'id')
    """
    if raw.startswith(b"\xef\xbb\xbf"):
        return _strict(raw[3:], "utf-8")
    if raw.startswith((b"\xff\xfe", b"\xfe\xff")):
        return _strict(raw, "utf-16")
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError:
        return _strict(raw, "gb18030")


def _strict(raw: bytes, encoding: str) -> str:
    try:
        return raw.decode(encoding)
    except UnicodeDecodeError as exc:
        raise ProblemError(f"--students: not {encoding.upper()} text ({exc.reason} at byte {exc.start})") from None


def parse_roster(raw: bytes) -> tuple[Student, ...]:
    """Students from the bytes of a class list, in file order; refuses a missing ``id`` column, empty or
    duplicate ids, control characters and sizes beyond :data:`LIMITS`."""
    text = decode(raw)
    lines = text.splitlines()
    header_line = next((ln for ln in lines if ln.strip()), "")
    delim = "," if "," in header_line or not any(d in header_line for d in ";\t") else (
        ";" if ";" in header_line else "\t")
    rows = list(csv.reader(io.StringIO(text, newline=""), delimiter=delim))
    numbered_rows = [(i + 1, r) for i, r in enumerate(rows) if any(c.strip() for c in r)]
    if not numbered_rows:
        raise ProblemError("--students: the class list is empty (a header with 'id' and one row per student)")
    _, header = numbered_rows[0]
    cols = [unicodedata.normalize("NFKC", c).strip().lower() for c in header]
    if "id" not in cols:
        raise ProblemError(f"--students: the header has no 'id' column (it has: {', '.join(cols)[:120]})")
    i_id = cols.index("id")
    i_name = cols.index("name") if "name" in cols else None
    out: list[Student] = []
    seen: dict[str, int] = {}
    for line, row in numbered_rows[1:]:
        sid = row[i_id].strip() if i_id < len(row) else ""
        name = row[i_name].strip() if i_name is not None and i_name < len(row) else ""
        if not sid:
            raise ProblemError(f"--students: line {line}: empty id")
        for what, value, limit in (("id", sid, LIMITS["id_chars"]), ("name", name, LIMITS["name_chars"])):
            if len(value) > limit:
                raise ProblemError(f"--students: line {line}: the {what} has {len(value)} characters; at most {limit}")
            bad = next((ch for ch in value if unicodedata.category(ch) in ("Cc", "Cs", "Zl", "Zp")), None)
            if bad is not None:
                raise ProblemError(f"--students: line {line}: the {what} holds the control character U+{ord(bad):04X}")
        if sid in seen:
            raise ProblemError(f"--students: line {line}: id {sid!r} again (first on line {seen[sid]})")
        seen[sid] = line
        out.append(Student(sid, name))
        if len(out) > LIMITS["students"]:
            raise ProblemError(f"--students: more than {LIMITS['students']} students")
    if not out:
        raise ProblemError("--students: the class list has a header but no student")
    return tuple(out)


__all__ = ["LIMITS", "Student", "decode", "load_roster", "numbered", "parse_roster"]
