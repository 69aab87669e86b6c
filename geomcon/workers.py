"""Independent jobs on several cores, results in submission order: what ``geomcon gallery --jobs N`` runs on.

Every job is a module-level function and its arguments; the results come back in the order the jobs were given,
whatever the number of workers and whichever worker ran which job, so output assembled from them is the same
bytes for ``jobs=1`` and ``jobs=8``. With one worker (or one job) everything runs in this process, in order —
no pool, no pickling, and an error raises as it is. Workers are forked (where the platform has ``fork``) after the caller has imported what
the jobs need, so no worker imports or compiles a module again; the caller's objects are frozen for the
workers' garbage collector (``gc.freeze``, the documented way before a fork) while they run, and unfrozen after.

A job that raises :class:`~geomcon.errors.GeomconError` is reported as that error's message and its ``file``
(an error class with its own constructor need not survive pickling): :func:`run_ordered` raises a
``GeomconError`` with the same text and ``file`` in the caller, the first failing job in submission order.

Examples
--------
>>> run_ordered([(pow, (2, 10)), (divmod, (7, 2))], jobs=1)
[1024, (3, 1)]
>>> default_jobs() >= 1
True
"""
from __future__ import annotations

import gc
import multiprocessing
import os
from contextlib import contextmanager
from dataclasses import dataclass
from typing import Any, Callable, Iterator, Sequence

from .errors import GeomconError

Job = tuple[Callable[..., Any], tuple[Any, ...]]


def default_jobs() -> int:
    """The cores this process may run on (``os.sched_getaffinity`` where there is one, else ``os.cpu_count()``)."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:                   # macOS, Windows
        return max(1, os.cpu_count() or 1)


@contextmanager
def collector_paused() -> Iterator[None]:
    """No cyclic garbage collection inside the block (``gc.disable``), the collector as it was after it.

    For a bounded batch such as the gallery: its cycles (scenes, figures, parsed documents) are few and die
    with the process, while the collector's generational passes walk every live object again and again (in
    the gallery, about 6 % of one process's CPU and a fifth of the imports before the fork). Memory still
    comes back through reference counting; forked workers inherit the paused collector.

    On leaving, what the block left alive is moved into the oldest generation (``gc.freeze`` then
    ``gc.unfreeze``: a move of lists, no walk) before the collector runs again: else the first allocation after
    the block would walk all of it as the youngest generation (in a ``--jobs 1`` gallery build ~0.35 s of ~10 s
    CPU, just before the process ends). It stays collectable: the next full collection walks it, as any
    long-lived object (the second example).

    Examples
    --------
    >>> with collector_paused():
    ...     gc.isenabled()
    False
    >>> gc.isenabled()
    True
    >>> import weakref
    >>> class Node: pass
    >>> with collector_paused():
    ...     a, b = Node(), Node()
    ...     a.other, b.other = b, a               # a cycle: only the collector frees it
    ...     gone = weakref.ref(a)
    ...     del a, b
    >>> _ = gc.collect()
    >>> gone() is None
    True
    """
    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if not gc.get_freeze_count():         # (objects a caller froze stay frozen)
            gc.freeze()
            gc.unfreeze()
        if was:
            gc.enable()


@dataclass(frozen=True)
class _Refused:
    """A job's :class:`GeomconError`, carried back as text."""

    message: str
    file: str | None


def _call(job: Job) -> Any:
    fn, args = job
    try:
        return fn(*args)
    except GeomconError as exc:
        return _Refused(str(exc), getattr(exc, "file", None))


def run_ordered(jobs_list: Sequence[Job], jobs: int | None = None) -> list[Any]:
    """``[fn(*args) for fn, args in jobs_list]``, on up to ``jobs`` processes (default :func:`default_jobs`).

    Raises
    ------
    GeomconError
        The first job (in submission order) that refused, with its message and ``file``.
    ValueError
        When ``jobs`` is below 1.
    """
    n = default_jobs() if jobs is None else jobs
    if n < 1:
        raise ValueError(f"jobs must be at least 1, got {n}")
    n = min(n, len(jobs_list))
    if n <= 1:
        return [fn(*args) for fn, args in jobs_list]       # a refusal raises as it is, at once
    else:
        methods = multiprocessing.get_all_start_methods()
        ctx = multiprocessing.get_context("fork" if "fork" in methods else None)
        gc.freeze()          # what the caller holds (the modules imported for the jobs): left out of every
        try:                 # worker's full collections, which would each walk it again
            with ctx.Pool(n) as pool:
                out = pool.map(_call, jobs_list, chunksize=1)
        finally:
            gc.unfreeze()
    for r in out:
        if isinstance(r, _Refused):
            err = GeomconError(r.message)
            if r.file is not None:
                err.file = r.file  # type: ignore[attr-defined]
            raise err
    return out


__all__ = ["collector_paused", "default_jobs", "run_ordered"]
