"""Exudyn's console output without its known-benign notes.

Exudyn prints through Python's ``sys.stdout``. Two of its messages appear in
every run of the bearing element and mean nothing is wrong:

* ``WARNING: VelocityVerlet: still under development``: the solver the
  element recommends; its results match the reference core to round-off
  (tests/test_element.py);
* ``WARNING: VelocityVerlet detected large amount (...) of memory
  allocations, which seem to occur in every time step; this may be due to
  user functions; solver may be slow``: the element's user function receives
  its coordinates as new vectors every call, which Exudyn counts (its cost is
  in validation/performance/bench_overhead.py).

:func:`filter_exudyn_notes` drops exactly these lines while it is active and
passes everything else (solver progress, real warnings and errors) through.
"""
from __future__ import annotations

import contextlib
import sys

__all__ = ["BENIGN_NOTES", "filter_exudyn_notes"]

#: Substrings of Exudyn's known-benign console lines.
BENIGN_NOTES = ("VelocityVerlet: still under development",
                "memory allocations, which seem to occur in every time step")


class _LineFilter:
    """A text stream that forwards complete lines to ``stream`` unless they hold one of ``notes``."""

    def __init__(self, stream, notes):
        self._stream = stream
        self._notes = tuple(notes)
        self._pending = ""

    def write(self, text):
        self._pending += text
        while "\n" in self._pending:
            line, self._pending = self._pending.split("\n", 1)
            self._forward(line + "\n")
        return len(text)

    def _forward(self, text):
        if not any(note in text for note in self._notes):
            self._stream.write(text)

    def flush(self):
        if self._pending:
            self._forward(self._pending)
            self._pending = ""
        self._stream.flush()

    def __getattr__(self, name):
        return getattr(self._stream, name)


@contextlib.contextmanager
def filter_exudyn_notes(quiet: bool = False, notes=BENIGN_NOTES):
    """Context manager around ``mbs.SolveDynamic`` (or any Exudyn call) that
    drops Exudyn's known-benign console notes (:data:`BENIGN_NOTES`);
    ``quiet=True`` silences Exudyn's console output altogether
    (``exudyn.config.printToConsole``, restored afterwards).

    >>> import exudyn_bearing as eb
    >>> with eb.filter_exudyn_notes():
    ...     print("WARNING: VelocityVerlet: still under development")
    ...     print("STEP100, t = 0.001s")
    STEP100, t = 0.001s
    """
    import exudyn as exu

    printing = exu.config.printToConsole
    if quiet:
        exu.config.printToConsole = False
    stream = sys.stdout
    filtered = _LineFilter(stream, notes)
    sys.stdout = filtered
    try:
        yield
    finally:
        try:
            filtered.flush()
        finally:
            sys.stdout = stream
            exu.config.printToConsole = printing
