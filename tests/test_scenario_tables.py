"""Each scenario's documented table against what the scenario printed.

A scenario records what it prints (scenarios/_printed.py: ``printed.txt`` in its output folder, the
command on the first line); the documented run's copy is tracked in scenarios/printed/<script>.txt.
Running the documented runs here would take minutes, so the test compares the docstring with the
stored output of that run, and a short run of the same script checks that the stored output has the
shape the script prints today (the parser below reads both).
"""
import re

import pytest

from conftest import ROOT

PRINTED = ROOT / "scenarios" / "printed"

#: A row of rotor_two_6208's window table as printed: window [ms], orbit radius mean / largest [um],
#: then bearing A's and B's largest outer ball load mean / largest [N].
ROTOR_ROW = re.compile(r"^\s+(\d+)-\s*(\d+)\s+([\d.]+) /\s+([\d.]+)\s+(\d+) /\s+(\d+)\s+(\d+) /\s+(\d+)$")
#: The same row in the docstring's table (both bearings alike: one load column).
ROTOR_DOC_ROW = re.compile(r"^(\d+)-(\d+)\s+([\d.]+) / ([\d.]+)\s+(\d+) / (\d+)$")


def stored(name):
    """(command, lines) of scenarios/printed/<name>.txt."""
    first, *lines = (PRINTED / f"{name}.txt").read_text().splitlines()
    assert first.startswith("$ python scenarios/"), first
    return first[2:], lines


def rotor_table(lines):
    """(run-up end [ms], rows, {bearing: (cage [rad/s], Lambda_out at psi = 0)}) of rotor_two_6208's print."""
    end = next(re.search(r"ends at (\d+) ms", x) for x in lines if x.startswith("run-up to "))
    rows = [m.groups() for m in map(ROTOR_ROW.match, lines) if m]
    tail = {m.group(1): (m.group(2), m.group(3)) for m in
            (re.match(r"bearing (\w) \(last quarter\): .* cage ([\d.]+) rad/s, Lambda_out\(psi=0\) ([\d.]+)", x)
             for x in lines) if m}
    return (end.group(1) if end else None), rows, tail


def test_rotor_two_6208_docstring_is_its_stored_run(load_script):
    mod = load_script("scenarios/rotor_two_6208.py")
    command, lines = stored("rotor_two_6208")
    assert command == "python scenarios/rotor_two_6208.py"  # the defaults, as the docstring says
    end, rows, tail = rotor_table(lines)
    assert len(rows) == 5 and set(tail) == {"A", "B"}
    assert all(r[4:6] == r[6:8] for r in rows) and tail["A"] == tail["B"]  # the symmetric rotor: both alike
    doc = mod.__doc__
    doc_rows = [m.groups() for m in map(ROTOR_DOC_ROW.match, doc.splitlines()) if m]
    # the docstring's windows are the printed ones (the printed start is padded: "   0-  26")
    assert doc_rows == [r[:6] for r in rows]
    flat = " ".join(doc.split())
    assert f"run-up to 1000 rad/s ends at {end} ms" in flat
    cage, lam = tail["A"]
    assert f"cage {cage} rad/s" in flat and f"psi = 0 {lam}" in flat


@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")  # a 40 ms run is not steady
@pytest.mark.filterwarnings("ignore::exudyn_bearing.EnergyBalanceWarning")  # nor its balance closed: mW of drive at 30 rad/s with the shaft rattling in the fast mode (3.6 % off with the stored energy, 20 % with --sub-steps 4: not diagnosed)
def test_the_rotor_script_prints_what_the_stored_run_holds(tmp_path, load_script):
    # a short run to 30 rad/s: its printed.txt has the stored run's shape (command, table, last-quarter lines)
    mod = load_script("scenarios/rotor_two_6208.py")
    mod.main(["--t-end", "0.04", "--omega", "30", "--out", str(tmp_path)])
    first, *lines = (tmp_path / "printed.txt").read_text().splitlines()
    assert first == f"$ python scenarios/rotor_two_6208.py --t-end 0.04 --omega 30 --out {tmp_path}"
    end, rows, tail = rotor_table(lines)
    assert end is not None and len(rows) == 5 and set(tail) == {"A", "B"}


def test_the_scenarios_import_without_their_folder_on_the_path(monkeypatch):
    # validation/consistency/levels_checks.py loads rotor_two_6208's build() by file: _printed is imported in main()
    import importlib.util
    import sys

    monkeypatch.setattr(sys, "path", [p for p in sys.path if p != str(ROOT / "scenarios")])
    monkeypatch.delitem(sys.modules, "_printed", raising=False)
    for name in ("rotor_two_6208", "defects_6205"):
        spec = importlib.util.spec_from_file_location(f"{name}_by_file", ROOT / "scenarios" / f"{name}.py")
        spec.loader.exec_module(importlib.util.module_from_spec(spec))
