"""The students' answers file: untrusted bytes from a spreadsheet, read without evaluating anything.

Limits (refused beyond, the file unusable): at most :data:`MAX_BYTES` bytes, :data:`MAX_ROWS` rows and
:data:`MAX_COLUMNS` columns. Encodings: UTF-8 with or without a byte-order mark, UTF-16 with a byte-order mark
(what Excel's "Unicode text" writes), else GB18030 (a superset of GBK, what Chinese spreadsheets export).
Separators: comma, semicolon or tab, whichever the header line uses most (a spreadsheet set to decimal commas
writes semicolons). The header needs ``id``; ``name`` is optional; every other column names an answer. A row
with another number of cells than the header, or without an id, is malformed: it is kept (graded as
unreadable) with its line number.

Examples
--------
>>> s = read_answers("id,name,1.AB\\n7,Li,\\"21,07\\"\\n8,Wang\\n".encode("gb18030"))
>>> s.columns, [(r.line, r.id, r.cells, r.problem) for r in s.rows]
(('1.AB',), [(2, '7', ('21,07',), ''), (3, '8', ('',), 'line 3: 2 cells where the header has 3')])
"""
from __future__ import annotations

import codecs
import csv
import io
from dataclasses import dataclass

from ..errors import ProblemError

MAX_BYTES = 32 * 2 ** 20
MAX_ROWS = 200_000
MAX_COLUMNS = 402
MAX_ID = 64
MAX_NAME = 200


@dataclass(frozen=True)
class Row:
    """One student's row: its line in the file (of its first physical line), id, name, the answer cells in
    the order of :attr:`Sheet.columns` (missing cells empty), and what is wrong with it (empty when fine)."""

    line: int
    id: str
    name: str
    cells: tuple[str, ...]
    problem: str = ""


@dataclass(frozen=True)
class Sheet:
    """The answer columns named by the header, the rows, and the encoding and separator found."""

    columns: tuple[str, ...]
    rows: tuple[Row, ...]
    encoding: str
    delimiter: str


def decode(data: bytes) -> tuple[str, str]:
    """(text, encoding) of the file's bytes.

    >>> decode("id".encode("utf-16"))
    ('id', 'utf-16')
    """
    if data.startswith(codecs.BOM_UTF8):
        return data[3:].decode("utf-8"), "utf-8-sig"
    if data.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        return data.decode("utf-16"), "utf-16"
    try:
        return data.decode("utf-8"), "utf-8"
    except UnicodeDecodeError:
        pass
    return data.decode("gb18030"), "gb18030"


def read_answers(data: bytes, *, max_rows: int = MAX_ROWS) -> Sheet:
    """Parse an answers file's bytes (see the module).

    Raises
    ------
    ProblemError
        An unusable file: too big, not text in a known encoding, no header with ``id``, a repeated column,
        too many rows or columns.
    """
    if len(data) > MAX_BYTES:
        raise ProblemError(f"the answers file has {len(data)} bytes; at most {MAX_BYTES} ({MAX_BYTES // 2 ** 20} MiB)")
    try:
        text, enc = decode(data)
    except UnicodeDecodeError as exc:
        raise ProblemError(f"not text in UTF-8, UTF-16 or GB18030 (byte {exc.start})") from None
    if "\x00" in text:
        raise ProblemError("the answers file holds NUL characters (UTF-16 without a byte-order mark?)")
    first = text.split("\n", 1)[0]
    delim = max((",", ";", "\t"), key=lambda d: (first.count(d), d == ","))
    reader = csv.reader(io.StringIO(text, newline=""), delimiter=delim)
    try:
        header = next(reader)
    except StopIteration:
        raise ProblemError("the answers file is empty") from None
    except csv.Error as exc:
        raise ProblemError(f"line 1: {exc}") from None
    header = [h.strip() for h in header]
    if len(header) > MAX_COLUMNS:
        raise ProblemError(f"{len(header)} columns; at most {MAX_COLUMNS}")
    if "id" not in header:
        raise ProblemError(f"the header (line 1) has no 'id' column: {', '.join(repr(h[:40]) for h in header[:8])}")
    seen: set[str] = set()
    for h in header:
        if h in seen:
            raise ProblemError(f"the header repeats the column {h[:40]!r}")
        seen.add(h)
    i_id = header.index("id")
    i_name = header.index("name") if "name" in header else None
    cols = [i for i, h in enumerate(header) if i not in (i_id, i_name)]
    rows: list[Row] = []
    line = reader.line_num + 1
    while True:
        try:
            cells = next(reader)
        except StopIteration:
            break
        except csv.Error as exc:
            rows.append(Row(line, "", "", ("",) * len(cols), f"line {line}: {exc}"))
            line = reader.line_num + 1
            continue
        start, line = line, reader.line_num + 1
        if not cells or all(not c.strip() for c in cells):
            continue
        if len(rows) >= max_rows:
            raise ProblemError(f"more than {max_rows} rows (at line {start})")
        problem = ""
        if len(cells) != len(header):
            problem = f"line {start}: {len(cells)} cells where the header has {len(header)}"
        ident = cells[i_id].strip() if i_id < len(cells) else ""
        name = cells[i_name].strip() if i_name is not None and i_name < len(cells) else ""
        if not problem and not ident:
            problem = f"line {start}: no id"
        if len(ident) > MAX_ID:
            problem, ident = f"line {start}: an id longer than {MAX_ID} characters", ident[:MAX_ID]
        name = name[:MAX_NAME]
        vals = tuple(cells[i] if i < len(cells) else "" for i in cols)
        rows.append(Row(start, ident, name, ("",) * len(cols) if problem else vals, problem))
    return Sheet(tuple(header[i] for i in cols), tuple(rows), enc, delim)


__all__ = ["MAX_BYTES", "MAX_COLUMNS", "MAX_ID", "MAX_NAME", "MAX_ROWS", "Row", "Sheet", "decode", "read_answers"]
