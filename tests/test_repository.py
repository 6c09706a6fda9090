"""The repository itself: no generated output tracked, and the session guard
(tests/conftest.py) that keeps test runs from writing into the working tree."""
import subprocess

import pytest

from conftest import ROOT, working_tree_changes


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


def test_guard_sees_a_file_written_into_the_tree():
    _git("status")
    before = working_tree_changes()
    probe = ROOT / "solution_probe_of_the_tree_guard.txt"
    probe.write_text("x")
    try:
        after = working_tree_changes()
    finally:
        probe.unlink()
    assert [e for e, _ in after - before] == ["?? solution_probe_of_the_tree_guard.txt"]
    assert working_tree_changes() == before
