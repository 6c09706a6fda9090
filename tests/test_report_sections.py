"""validation/REPORT.md is assembled from the scripts: each section is written by the ``report_section(run)`` of
the script whose outputs it shows (validation/README.md), and validation/make_report.py only runs the scripts and
joins the sections in its SECTIONS order. These checks import the scripts and render sections from made-up
printouts; nothing is run."""
import inspect
import re
import sys

from conftest import ROOT

sys.path.insert(0, str(ROOT / "validation"))
import _report  # noqa: E402
import make_report  # noqa: E402


def _section_source(entry):
    run = make_report.section_run(entry)
    return inspect.getsource(make_report.script_module(run.script).report_section)


def _writes(entry, source):
    """A test of whether the section ``entry`` writes a title: its rendered title where it renders without outputs
    (a printed section, of a run not run: this tells a script's tagged runs apart), else its report_section's
    ``source`` naming the title."""
    run = make_report.section_run(entry)
    try:
        text = make_report.script_module(run.script).report_section(run)
    except (OSError, KeyError):
        text = ""
    if text:
        return lambda title: f"\n## {title}\n" in f"\n{text}\n"
    return lambda title: f'"## {title}"' in source or f'"{title}"' in source


def test_every_section_of_the_report_is_written_by_a_script_make_report_runs(tmp_path, monkeypatch):
    monkeypatch.setattr(_report, "OUT", tmp_path)  # no outputs: printed sections render under their titles
    monkeypatch.setattr(_report, "FIGURES", tmp_path / "report_figures")
    keys = [(e, None) if isinstance(e, str) else tuple(e) for e in make_report.SECTIONS]
    assert len(set(keys)) == len(keys)
    runs = {(r.script, r.tag) for r in make_report.SCRIPTS}
    assert len(runs) == len(make_report.SCRIPTS)
    assert set(keys) <= runs  # every section's data comes from a run of make_report
    sources = {key: _section_source(entry) for key, entry in zip(keys, make_report.SECTIONS)}
    # a run without a section of its own is a script without report_section whose outputs another section reads
    for script, tag in runs - set(keys):
        if tag is None:
            assert not hasattr(make_report.script_module(script), "report_section"), script
        stem = script.removesuffix(".py")
        assert any(f'"{stem}.json"' in src for src in sources.values()), script
    # every section of the committed report, in its order, comes from the section list: its command's script has
    # a section, and its title is written by a section's report_section at or after the previous title's
    report = (ROOT / "validation" / "REPORT.md").read_text()
    blocks = re.split(r"^## ", report, flags=re.M)[1:]
    assert len(blocks) > 30
    scripts = {script for script, _tag in keys}
    writes = {key: _writes(entry, sources[key]) for key, entry in zip(keys, make_report.SECTIONS)}
    last = 0
    for block in blocks:
        title = block.split("\n", 1)[0].strip()
        command = re.search(r"^Command: `python validation/\w+/(\w+\.py)", block, flags=re.M)
        assert command and command.group(1) in scripts, title
        at = [i for i, key in enumerate(keys) if writes[key](title)]
        assert at and max(at) >= last, title
        last = min(i for i in at if i >= last)


def test_a_printed_section_quotes_its_run_and_an_empty_one_is_left_out(tmp_path, monkeypatch):
    monkeypatch.setattr(_report, "OUT", tmp_path)
    run = make_report.section_run(("bench_kernel_ab.py", "session"))
    module = make_report.script_module("bench_kernel_ab.py")
    assert "(not run for this report)" in module.report_section(run)
    run.printout.write_text("\n".join(f"line {i}" for i in range(30)) + "\n\n")
    text = module.report_section(run).split("\n")
    assert text[0] == "## Step time against the start of this work"
    assert "Command: `python validation/performance/bench_kernel_ab.py --baseline 58652e8`; what it printed" in \
        text[4]
    quoted = text[text.index("```text") + 1:text.index("```", text.index("```text") + 1)]
    assert quoted == [f"line {i}" for i in range(10, 30)]  # its last 20 lines
    # the untagged run of the same script writes another section, from its own printout
    plain = module.report_section(make_report.section_run("bench_kernel_ab.py"))
    assert plain.startswith("## Step time against the code before the kernel work") and "line 29" not in plain
    # a section with nothing to report is left out of the report (mutation_run.json absent)
    monkeypatch.setattr(make_report, "SECTIONS", ["mutation_run.py", ("bench_kernel_ab.py", "session")])
    assert make_report.sections() == [module.report_section(run)]
