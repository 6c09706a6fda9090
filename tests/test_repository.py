"""The repository itself: no generated output tracked, and the session guard
(tests/conftest.py) that keeps test runs from writing into the working tree."""
import json
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT, TREE_WRITES, TreeWrites


def _git(*args):
    try:
        out = subprocess.run(["git", "-C", str(ROOT), *args], capture_output=True, text=True, timeout=60)
    except OSError:
        pytest.skip("git not available")
    if out.returncode != 0:
        pytest.skip("not a git work tree")
    return out.stdout


def test_no_exudyn_output_is_tracked():
    # Exudyn's default SimulationSettings write solution/coordinatesSolution.txt
    assert _git("ls-files", "solution") == ""
    assert "solution/" in (ROOT / ".gitignore").read_text().split()


def test_guard_sees_what_the_test_writes_into_the_tree(tmp_path):
    # a guard on a stand-in clone (tmp_path / "clone"): a file the test writes there, a folder it makes and a
    # file it removes are seen with the test's id; outputs under a relative name land in the test's own
    # directory (the current one), outside the clone
    clone = tmp_path / "clone"
    clone.mkdir()
    guard = TreeWrites(clone)
    sys.addaudithook(guard)
    guard.active, guard.current = True, "a test"
    (clone / "out").mkdir()
    (clone / "out" / "run.csv").write_text("x")
    (clone / "out" / "run.csv").unlink()
    Path("relative.csv").write_text("x")
    (clone / "__pycache__").mkdir()
    guard.active = False
    assert [(t, Path(p).relative_to(clone).as_posix()) for t, p in guard.writes] == \
        [("a test", "out"), ("a test", "out/run.csv"), ("a test", "out/run.csv")]
    assert Path.cwd() == tmp_path and (tmp_path / "relative.csv").exists()


def test_a_file_someone_else_writes_into_the_clone_does_not_fail_the_run():
    # another process (the user running a README example from the repository root, say) writes into the
    # real clone while the session runs: the session's guard does not see it, so the run does not fail
    probe = ROOT / "out_probe_of_the_tree_guard.txt"
    seen = len(TREE_WRITES.writes)
    try:
        subprocess.run([sys.executable, "-c", f"open({str(probe)!r}, 'w').write('x')"], check=True, timeout=60)
        assert probe.exists()
        assert TREE_WRITES.active and TREE_WRITES.writes[seen:] == []
    finally:
        subprocess.run([sys.executable, "-c", f"import os; os.remove({str(probe)!r})"], check=True, timeout=60)


def _scripts():
    # not validation/out: the scripts' outputs (untracked; bench_defects.py copies a baseline's sources there);
    # the documentation's gallery examples too
    return sorted((ROOT / "scenarios").glob("*.py")) + sorted(
        p for p in (ROOT / "validation").rglob("*.py") if p.relative_to(ROOT / "validation").parts[0] != "out") + \
        sorted((ROOT / "docs" / "examples_src").glob("*.py"))


#: Private names a script may import: benchmarks that time a compiled kernel itself.
ALLOWED_PRIVATE = {"bench_quasistatic.py: exudyn_bearing.physics.contact_slip._contact_traction"}


def test_scripts_use_only_public_names_of_the_package():
    import ast

    private = []
    for path in _scripts():
        for node in ast.walk(ast.parse(path.read_text(), str(path))):
            if isinstance(node, ast.ImportFrom) and (node.module or "").startswith("exudyn_bearing"):
                private += [f"{path.name}: {node.module}.{a.name}" for a in node.names if a.name.startswith("_")]
    assert sorted(set(private) - ALLOWED_PRIVATE) == []


def test_validation_and_scenarios_refer_to_no_issue_tracker():
    import re

    hits = [f"{p.name}:{i}" for p in _scripts() for i, line in enumerate(p.read_text().splitlines(), 1)
            if re.search(r"\bissue\b", line, re.IGNORECASE)]
    assert hits == []


def test_no_unused_imports_or_variables():
    import os
    import shutil
    import sys

    # the venv's own ruff first: a venv run without activation has its bin/ off PATH
    ruff = shutil.which("ruff", path=os.pathsep.join([str(Path(sys.executable).parent), os.environ.get("PATH", "")]))
    if ruff is None:
        pytest.skip("ruff not installed (pip install ruff)")
    out = subprocess.run([ruff, "check", "--no-cache", "--select", "F401,F841", "tests", "validation", "scenarios",
                          "exudyn_bearing", "docs"], cwd=ROOT, capture_output=True, text=True)
    assert out.returncode == 0, out.stdout


def test_report_figures_are_tracked_small_and_each_shown_once():
    import re

    report = (ROOT / "validation" / "REPORT.md").read_text()
    links = re.findall(r"!\[[^\]]*\]\(([^)]+)\)", report)
    assert len(links) >= 10
    folder = ROOT / "validation" / "report_figures"
    assert sorted(links) == sorted(f"report_figures/{p.name}" for p in folder.glob("*.png"))
    for link in links:
        path = ROOT / "validation" / link
        assert path.stat().st_size < 150_000, link
        # each figure has its sentence right below it
        after = report[report.index(link):].splitlines()
        assert after[2].startswith(f"*{path.name}*: ") and after[2].endswith("."), link
    # every figure the text names is shown (the cross-engine pattern stands for the scenes shown)
    named = set(re.findall(r"([A-Za-z0-9_]+\.png)", report))
    assert named == {link.split("/")[-1] for link in links}
    tracked = _git("ls-files", "validation/report_figures").split()
    assert sorted(tracked) == sorted(f"validation/{link}" for link in links)


def test_make_report_publishes_a_figure_small(tmp_path, monkeypatch):
    import sys

    sys.path.insert(0, str(ROOT / "validation"))
    import _report
    from exudyn_bearing.outputs.plotting import pyplot, save_figure

    monkeypatch.setattr(_report, "OUT", tmp_path / "out")
    monkeypatch.setattr(_report, "FIGURES", tmp_path / "report_figures")
    monkeypatch.setattr(_report, "_published", [])
    (tmp_path / "out").mkdir()
    plt = pyplot()
    fig, ax = plt.subplots()
    ax.plot([0, 1, 2], [1, 3, 2], "o-")
    save_figure(fig, tmp_path / "out" / "a.png")
    (tmp_path / "report_figures").mkdir()
    (tmp_path / "report_figures" / "stale.png").write_bytes(b"x")
    lines = _report.Run("cross_engine.py").figure("a.png", "A line.")
    assert lines == ["![a](report_figures/a.png)", "", "*a.png*: A line.", ""]
    assert _report.figure(tmp_path / "out" / "missing.png", "Not there.") == []
    _report.remove_unpublished()
    assert sorted(p.name for p in (tmp_path / "report_figures").iterdir()) == ["a.png"]
    from PIL import Image

    with Image.open(tmp_path / "report_figures" / "a.png") as im:
        assert im.mode == "P" and im.size == Image.open(tmp_path / "out" / "a.png").size


def test_make_report_names_the_machine_of_its_run(tmp_path, monkeypatch):
    """The report names the machine it measured on (CPU, cores, load average at the run's start and end),
    as read off during the run (run_all), not when the text is written."""
    import os
    import sys

    sys.path.insert(0, str(ROOT / "validation"))
    import _report
    import make_report

    monkeypatch.setattr(_report, "OUT", tmp_path)
    monkeypatch.setattr(make_report, "SCRIPTS", [])
    make_report.run_all()
    record = json.loads((tmp_path / "make_report_machine.json").read_text())
    assert record["start"]["cores"] == os.cpu_count() and record["end"]["cores"] == os.cpu_count()
    sentence = _report.machine_sentence(record)
    assert record["start"]["cpu"] in sentence and f"{os.cpu_count()} logical cores" in sentence
    if hasattr(os, "getloadavg"):
        assert str(record["end"]["load"]) in sentence
    assert _report.machine_sentence({}) == ""


def test_the_repository_cites_its_own_theory_document():
    # the project's theory is docs/theory/ (no file cites the former private specification), and every
    # cited page exists
    import re
    import subprocess

    root = ROOT
    files = subprocess.run(["git", "ls-files"], cwd=root, capture_output=True, text=True).stdout.split()
    pages = set()
    for name in files:
        if not name.endswith((".py", ".md", ".json")) or name.startswith("docs/") or name == "validation/REPORT.md":
            continue
        text = (root / name).read_text()
        assert "PHYSICS" + ".md" not in text, name
        pages.update(re.findall(r"docs/theory/([a-z_]+\.md)", text))
    assert len(pages) >= 8
    for page in pages:
        assert (root / "docs" / "theory" / page).is_file(), page


def test_validation_is_laid_out_by_purpose_and_make_report_finds_every_script():
    # validation/README.md names each purpose folder; every script there says what it is (a module
    # docstring, which the docs' per-folder pages list); make_report runs each script it names from its folder
    import ast
    import sys

    sys.path.insert(0, str(ROOT / "validation"))
    import make_report

    folders = sorted(p.name for p in (ROOT / "validation").iterdir() if p.is_dir() and any(p.glob("*.py")))
    assert folders == ["consistency", "performance", "published", "studies"]
    readme = (ROOT / "validation" / "README.md").read_text()
    assert all(f"`{f}/`" in readme for f in folders)
    undocumented = [p.name for f in folders for p in (ROOT / "validation" / f).glob("*.py")
                    if not ast.get_docstring(ast.parse(p.read_text()))]
    assert undocumented == []
    for run in make_report.SCRIPTS:
        assert run.path.is_file(), run.script
        parts = run.command.split()[1].split("/")
        assert len(parts) == 2 or parts[1] in folders, run.script  # a new script may wait at the top level


def test_make_report_names_the_scripts_the_host_slowed():
    """The report's host-speed probe: a script is named when the probe before or after it is below
    PROBE_SHARE of the run's fastest, and only then; without probes the report says nothing."""
    import sys

    sys.path.insert(0, str(ROOT / "validation"))
    import _report

    share = _report.PROBE_SHARE
    fast = 3.8e5
    slow = 0.99 * share * fast
    probes = [("a.py", fast), ("b.py", fast), ("c.py", slow), ("d.py", 0.999 * fast)]
    # c ran after a slow probe; b ended on it; a and d are between fast probes
    assert _report.disturbed_scripts(probes, end=fast) == [("b.py", fast, slow), ("c.py", slow, 0.999 * fast)]
    # a slow end probe names the last script; no end probe: the last script has its own probe only
    assert _report.disturbed_scripts(probes[:2], end=slow) == [("b.py", fast, slow)]
    assert _report.disturbed_scripts([("a.py", fast), ("b.py", 1.01 * share * fast)], end=None) == []
    assert _report.disturbed_scripts([]) == []
    text = _report.probe_sentence({"probes": [list(p) for p in probes], "end": fast})
    assert "c.py" in text and "b.py" in text and "a.py" not in text and "d.py" not in text
    assert _report.probe_sentence({"probes": [["a.py", fast]], "end": fast}).endswith(": none.")
    assert _report.probe_sentence({}) == ""
