"""What writing validation/REPORT.md shares: a run of a script (:class:`Run`: its command, its outputs under
validation/out, its printout), the figures the report shows, the percentages it prints and the sentences of
its head (the machine, the host-speed probes).

The convention (validation/README.md): a script that has a section in validation/REPORT.md defines
``report_section(run) -> str``, the markdown of that section written from what the script wrote under
``run.out`` ("" when there is nothing to report). ``validation/make_report.py`` runs the scripts, then calls
each script's ``report_section`` in the report's order (its SECTIONS) and joins them; it puts validation/ on
``sys.path``, so a script imports these helpers inside its ``report_section`` (``from _report import pct``),
not at its top (run on its own, a script does not need them).
"""
from __future__ import annotations

import json
from dataclasses import dataclass
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
#: What the scripts write (data, figures) and their printouts (not tracked).
OUT = HERE / "out"
#: Tracked copies of the figures the report shows (REPORT.md links them relatively).
FIGURES = HERE / "report_figures"
#: Largest size of a published figure [bytes].
MAX_FIGURE_BYTES = 150_000
#: Names of the figures this report shows (:func:`figure`); the others are removed from FIGURES.
_published = []


def script_path(script):
    """Path of the validation script named ``script``: in its purpose folder (validation/published,
    consistency, performance, studies; validation/README.md), or at the top level for one not yet sorted."""
    found = sorted(HERE.glob(f"*/{script}"))
    return found[0] if found else HERE / script


@dataclass(frozen=True)
class Run:
    """One run of a validation script: ``script`` (file name), its ``args`` and a ``tag`` naming a second run of
    a script under other arguments (its printout is ``<stem>_<tag>.stdout.txt``)."""

    script: str
    args: tuple = ()
    tag: str | None = None

    @property
    def path(self):
        return script_path(self.script)

    @property
    def out(self):
        """Where the script writes (validation/out)."""
        return OUT

    @property
    def key(self):
        """The run's name in the report's wall times and host-speed probes (the arguments of a tagged run)."""
        return f"{self.script} {' '.join(self.args)}" if self.tag else self.script

    @property
    def command(self):
        """``python validation/<folder>/<script> [args]``, as the report names it (from the repository root)."""
        rel = self.path.relative_to(HERE.parent).as_posix()
        return f"python {rel}{' ' + ' '.join(self.args) if self.args else ''}"

    @property
    def printout(self):
        """File under OUT holding what the script printed in this run."""
        return self.out / f"{Path(self.script).stem}{'_' + self.tag if self.tag else ''}.stdout.txt"

    def load(self, name):
        """The JSON file ``name`` under OUT (this script's or another's)."""
        return json.loads((self.out / name).read_text())

    def figure(self, src, sentence):
        """:func:`figure` of ``src`` under OUT."""
        return figure(self.out / src, sentence)

    def printed(self, title, intro, figures=(), last_lines=40):
        """A report section quoting what the script printed in this run (its last ``last_lines`` non-empty
        lines) under its command, with ``figures`` ((file under OUT, sentence), ...) below."""
        lines = [f"## {title}", "", intro, "", f"Command: `{self.command}`; what it printed in this run:", ""]
        if self.printout.exists():
            printed = [ln for ln in self.printout.read_text().splitlines() if ln.strip()][-last_lines:]
            lines += ["```text", *printed, "```", ""]
        else:
            lines += ["(not run for this report)", ""]
        for src, sentence in figures:
            lines += self.figure(src, sentence)
        return "\n".join(lines)


def pct(x, digits=3):
    """``x`` as a percentage with ``digits`` decimals ("n/a" for None)."""
    return "n/a" if x is None else f"{100 * x:.{digits}f} %"


def figure(path, sentence):
    """Markdown lines showing the figure ``path`` (copied into FIGURES as a 64-colour PNG) with ``sentence``
    below it; none if the script did not write it."""
    path = Path(path)
    if not path.exists():
        print(f"figure {path} missing: not in the report")
        return []
    from PIL import Image

    FIGURES.mkdir(exist_ok=True)
    target = FIGURES / path.name
    with Image.open(path) as im:
        small = im.convert("RGB").quantize(colors=64, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
        small.save(target, optimize=True)
    if target.stat().st_size > MAX_FIGURE_BYTES:
        raise SystemExit(f"{target}: {target.stat().st_size} bytes, above {MAX_FIGURE_BYTES}: lower the figure's dpi")
    _published.append(target.name)
    return [f"![{path.stem}]({FIGURES.name}/{target.name})", "", f"*{path.name}*: {sentence}", ""]


def remove_unpublished():
    """Delete figures of FIGURES that this report no longer shows."""
    if FIGURES.exists():
        for f in FIGURES.glob("*.png"):
            if f.name not in _published:
                f.unlink()


# The report's head: the machine of the run and the host-speed probes (make_report.py measures them).

#: The host-speed probe (make_report.host_probe): the reference engine on bench_reference.py's scene (6208,
#: F_r = 3000 N, 500 rad/s, implicit spring, dt 8 us) for PROBE_T simulated seconds, median of PROBE_REPEAT runs.
PROBE_T = 0.05
PROBE_REPEAT = 5
#: A script is named as disturbed when the probe before or after it is below this share of the run's fastest.
PROBE_SHARE = 0.85


def _probe_values(probes, end):
    """The probes of a run [steps/s]: each script's (``probes``: [(script, steps/s), ...]) and ``end`` (None:
    not taken)."""
    return [v for _s, v in probes] + ([end] if end is not None else [])


def disturbed_scripts(probes, end=None, share=PROBE_SHARE):
    """Scripts run while the host was slow: ``probes`` [(script, probe before it [steps/s]), ...] in run
    order, ``end`` the probe after the last one (None: not taken). A script's probes are the one before it
    and the next script's (or ``end``); it is named when the smaller is below ``share`` of the fastest probe
    of the run. Returns [(script, before, after), ...] (after None when not taken).

    >>> disturbed_scripts([("a", 100.0), ("b", 80.0), ("c", 99.0)], end=100.0)
    [('a', 100.0, 80.0), ('b', 80.0, 99.0)]
    """
    values = _probe_values(probes, end)
    if not values:
        return []
    best = max(values)
    out = []
    for i, (script, before) in enumerate(probes):
        after = probes[i + 1][1] if i + 1 < len(probes) else end
        low = before if after is None else min(before, after)
        if low < share * best:
            out.append((script, before, after))
    return out


def probe_sentence(record):
    """The report's sentence on the host-speed probes of a run (``record``: {"probes": [[script, steps/s],
    ...], "end": steps/s} as make_report.run_all writes it), or "" without probes."""
    probes = [tuple(p) for p in (record or {}).get("probes", [])]
    if not probes:
        return ""
    end = record.get("end")
    values = _probe_values(probes, end)
    bad = disturbed_scripts(probes, end)
    named = ("; ".join(f"{s} ({b:.3g} before, {'-' if a is None else f'{a:.3g}'} after)" for s, b, a in bad)
             if bad else "none")
    return (f"Host-speed probe (the reference engine on bench_reference.py's scene at 8 us, implicit spring, "
            f"{PROBE_T:g} s simulated, median of {PROBE_REPEAT} runs, steps per second of wall time, taken before "
            f"each script and at the end): fastest {max(values):.3g}, median {float(np.median(values)):.3g}, "
            f"slowest {min(values):.3g}. Scripts with a probe before or after them below {PROBE_SHARE:g} of the "
            f"fastest (the host was slower then: their wall times may be inflated, their ratios less so): {named}.")


def machine_sentence(machine):
    """The report's sentence naming the machine of a run (``machine``: {"start": facts, "end": facts} as
    run_all writes them), or "" without a record."""
    if not machine:
        return ""
    start, end = machine.get("start", {}), machine.get("end", {})
    load = "; load average (1, 5, 15 min) {} at the start ({}), {} at the end ({})".format(
        start.get("load"), start.get("time"), end.get("load"), end.get("time")) if end else ""
    return (f"Measured on: {start.get('cpu')}, {start.get('cores')} logical cores, shared with other jobs"
            f"{load}.")
