"""What a scenario printed, kept beside its figures.

:func:`recording` copies what the script prints through Python (its tables and summaries, not the
solver's own progress lines) into ``printed.txt`` of its output folder, after a first line with the
command. The copy of the documented run of a scenario lives in ``scenarios/printed/<script>.txt``
(tracked: ``cp scenarios/out/<script>/printed.txt scenarios/printed/<script>.txt`` after running the
command of its first line); tests/test_scenario_tables.py checks the scenario's docstring against it,
and tests/test_readme_claims.py the numbers the docs pages quote from it.
"""
import contextlib
import io
import shlex
import sys
from pathlib import Path


class _Tee(io.TextIOBase):
    """A text stream that writes to several."""

    def __init__(self, *streams):
        self.streams = streams

    def write(self, text):
        for s in self.streams:
            s.write(text)
        return len(text)

    def flush(self):
        for s in self.streams:
            s.flush()


def command_line(script, argv=None) -> str:
    """``python scenarios/<script> ARGS`` as typed (``argv``: the script's arguments, default sys.argv[1:])."""
    args = sys.argv[1:] if argv is None else list(argv)
    return " ".join(["python", f"scenarios/{Path(script).name}", *(shlex.quote(a) for a in args)])


@contextlib.contextmanager
def recording(path, script, argv=None):
    """Print as usual and, when the block ends without an error, write the command and what was printed
    to ``path`` (paths inside the repository written relative to it)."""
    buf = io.StringIO()
    old = sys.stdout
    sys.stdout = _Tee(old, buf)
    try:
        yield
    finally:
        sys.stdout = old
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    root = f"{Path(script).resolve().parents[1]}/"
    path.write_text(f"$ {command_line(script, argv)}\n{buf.getvalue().replace(root, '')}")
