"""The bench's clocks: CPU time, so that other work on the machine does not count.

A 2-core development machine running tests or other jobs beside the bench stretches wall time by 2–4× and
unevenly (a reference and the thing measured against it can be slowed differently in the same run); the CPU
time this process (or a child process) spends is what the code costs.

Examples
--------
>>> t0 = clock()
>>> _ = sum(range(10000))
>>> clock() - t0 >= 0.0
True
"""
from __future__ import annotations

import resource
import subprocess
import time
from typing import Mapping, Sequence

clock = time.process_time
"""CPU time of this process (user + system, all its threads), in seconds."""


def child_seconds(argv: Sequence[str], env: Mapping[str, str] | None = None) -> float:
    """Run ``argv`` to completion (output discarded) and return the CPU time it spent (user + system);
    ``env`` replaces the environment when given."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(list(argv), stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False,
                   env=None if env is None else dict(env))
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
