"""Warnings of a sweep or dataset: kept per case in the index (index.json, index.csv) and summarised at the end in
one line per type, not printed between the progress lines (issue 35)."""
import csv
import json
import warnings

from exudyn_bearing import StepSizeWarning
from exudyn_bearing import sweep as sw
from exudyn_bearing.datasets import build_dataset, read_index
from exudyn_bearing.outputs.window_checks import SteadyStateWarning


def _case(fr):
    return dict(bearing="6208", scenario=dict(Fr=fr, omega=500.0, t_end=0.001, dt=5e-6, tangential="implicit",
                                              sample_dt=2e-4))


def _warning_simulate(real):
    """simulate that warns twice (two lines) in the cases with Fr 2000 N, once more (another type) in 3000 N."""
    def fake(bearing, scenario, **kw):
        if scenario.Fr >= 2000.0:
            warnings.warn(f"first line of the case at {scenario.Fr:g} N\nsecond line", StepSizeWarning)
        if scenario.Fr >= 3000.0:
            warnings.warn("a user warning", UserWarning)
        return real(bearing, scenario, **kw)
    return fake


def test_warnings_go_into_the_index_and_one_line_per_type_at_the_end(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(sw, "simulate", _warning_simulate(sw.simulate))
    cases = {"a": _case(1000.0), "b": _case(2000.0), "c": _case(3000.0)}
    sw.run_sweep(cases, tmp_path, workers=1, progress=True)
    err = capsys.readouterr().err
    # the progress line is not broken up: every warning line comes after its last update
    progress_end = err.rindex("3/3 cases")
    assert "first line of the case" not in err[:progress_end]
    summary = [ln.strip() for ln in err[progress_end:].splitlines()[2:]]
    kinds = [ln.split(" in ")[0] for ln in summary]
    assert len(kinds) == len(set(kinds)) and {"StepSizeWarning", "UserWarning"} <= set(kinds)
    assert "StepSizeWarning in 2 of 3 cases (first b): first line of the case at 2000 N" in summary
    assert "UserWarning in 1 of 3 cases (first c): a user warning" in summary
    assert "second line" not in err
    index = json.loads((tmp_path / "index.json").read_text())["cases"]

    def mine(warns):  # besides the run's own (a 1 ms run's summary says it is too short to judge steadiness)
        return [w for w in warns if w["type"] in ("StepSizeWarning", "UserWarning")]

    assert mine(index["a"]["warnings"]) == []
    assert mine(index["c"]["warnings"]) == [
        {"type": "StepSizeWarning", "message": "first line of the case at 3000 N\nsecond line"},
        {"type": "UserWarning", "message": "a user warning"}]
    rows = {r["name"]: r for r in csv.DictReader((tmp_path / "index.csv").read_text().splitlines())}
    for n in "abc":
        assert rows[n]["warnings"].split(";") == list(dict.fromkeys(w["type"] for w in index[n]["warnings"]))
    assert "UserWarning" in rows["c"]["warnings"] and "StepSizeWarning" not in rows["a"]["warnings"]
    # a later call runs nothing and keeps the finished cases' warnings (from their records) in the index
    monkeypatch.setattr(sw, "simulate", None)
    sw.run_sweep(cases, tmp_path, workers=1, progress=False)
    assert json.loads((tmp_path / "index.json").read_text())["cases"]["c"]["warnings"] == index["c"]["warnings"]
    assert "UserWarning in 1 of 3 cases (first c)" in capsys.readouterr().err


def test_a_sweep_without_warnings_prints_no_summary(tmp_path, capsys):
    # a refused case (a negative step) warns of nothing
    sw.run_sweep({"a": dict(bearing="6208", scenario=dict(dt=-1e-6))}, tmp_path, workers=1, progress=False)
    err = capsys.readouterr().err
    assert "1 of 1 cases failed" in err and "[sweep] warnings" not in err
    assert sw.warning_summary({}) == [] and sw.warning_summary({"a": []}) == []


def test_a_dataset_index_lists_the_warning_types_of_each_case(tmp_path, capsys):
    # a 2 ms run's summary window is too short to judge steadiness: every case says so
    rows = build_dataset(tmp_path, faults=("healthy",), t_end=0.002, workers=1, progress=False)
    assert rows[0]["warnings"] == SteadyStateWarning.__name__
    assert read_index(tmp_path)[0]["warnings"] == SteadyStateWarning.__name__
    err = capsys.readouterr().err
    assert err.count("SteadyStateWarning") == 1 and "SteadyStateWarning in 1 of 1 cases" in err


def test_a_cold_kernel_cache_is_said_once_before_the_progress_line(tmp_path, monkeypatch, capsys):
    import exudyn_bearing._jit as jit

    monkeypatch.setattr(jit, "_announced", False)
    monkeypatch.setattr(jit, "_cache_is_cold", lambda dispatcher: True)
    sw.run_sweep({"a": {"bearing": "6208", "scenario": {"dt": -1e-6}}}, tmp_path, workers=1, progress=True)
    err = capsys.readouterr().err
    assert err.count(jit.COMPILE_NOTICE) == 1 and err.startswith(jit.COMPILE_NOTICE + "\n\r[sweep] |")
