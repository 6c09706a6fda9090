"""Sweep runner: parallel cases, atomic per-case files, resume by spec, failure records, Dask (signals and worker
processes: test_workers.py)."""
import csv
import json
import os
import signal
import stat

import pytest

from exudyn_bearing import InputError
from exudyn_bearing.sweep import SweepInterrupted, load_case, run_sweep, spec_hash

INDEX = ["index.csv", "index.json"]


def _case(fr, **scenario):
    return dict(bearing="6208", scenario={**dict(Fr=fr, omega=500.0, t_end=0.002, dt=5e-6, tangential="implicit",
                                                 sample_dt=2e-4), **scenario})


def _cases(frs=(1000.0, 3000.0)):
    return {f"Fr{int(fr)}": _case(fr) for fr in frs}


def test_parallel_sweep_writes_one_file_per_case_and_resumes(tmp_path):
    res = run_sweep(_cases(), tmp_path, workers=2, progress=False)
    assert set(res) == {"Fr1000", "Fr3000"}
    assert res["Fr3000"]["summary"]["q_max_inner"] > res["Fr1000"]["summary"]["q_max_inner"]
    assert "lambda_outer" in res["Fr3000"]["arrays"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["Fr1000.json", "Fr1000.npz", "Fr3000.json",
                                                          "Fr3000.npz", *INDEX]
    # resume: finished cases are not run again, a missing one is
    stamp = os.path.getmtime(tmp_path / "Fr3000.json")
    (tmp_path / "Fr1000.json").unlink()
    run_sweep(_cases(), tmp_path, workers=1, progress=False)
    assert os.path.getmtime(tmp_path / "Fr3000.json") == stamp
    assert (tmp_path / "Fr1000.json").exists()
    rec = json.loads((tmp_path / "Fr1000.json").read_text())
    assert rec["spec"]["scenario"]["Fr"] == 1000.0 and rec["status"] == "done"


def test_results_equal_serial_run(tmp_path):
    a = run_sweep(_cases((2000.0,)), tmp_path / "a", workers=1, progress=False)
    b = run_sweep(_cases((2000.0,)), tmp_path / "b", workers=2, progress=False)
    assert a["Fr2000"]["summary"]["q_max_outer"] == b["Fr2000"]["summary"]["q_max_outer"]


@pytest.mark.parametrize("name", ["../x", "", ".hidden", "a/b"])
def test_bad_case_name_rejected(tmp_path, name):
    with pytest.raises(InputError, match="^cases"):
        run_sweep({name: {}}, tmp_path, progress=False)


@pytest.mark.parametrize("workers", [1, 2])
def test_a_failed_case_is_recorded_and_the_others_finish(tmp_path, capsys, workers):
    cases = {"a": _case(1000.0), "bad": _case(2000.0, dt=-1e-6), "c": _case(3000.0), "worse": dict(bearing="6309")}
    res = run_sweep(cases, tmp_path, workers=workers, progress=False)
    assert res["a"]["status"] == res["c"]["status"] == "done" and "summary" in res["c"]
    assert res["bad"]["status"] == "failed"
    assert res["bad"]["error"]["type"] == "InputError" and res["bad"]["error"]["message"].startswith("dt:")
    assert res["worse"]["error"]["message"].startswith("bearing")
    on_disk = json.loads((tmp_path / "bad.error.json").read_text())
    assert on_disk["error"] == res["bad"]["error"] and on_disk["spec"] == cases["bad"]
    assert on_disk["spec_hash"] == spec_hash(cases["bad"]) and "Traceback" in on_disk["traceback"]
    assert not (tmp_path / "bad.json").exists()
    err = capsys.readouterr().err
    assert "2 of 4 cases failed" in err and "bad: InputError: dt:" in err and "worse: InputError: bearing" in err
    index = json.loads((tmp_path / "index.json").read_text())
    assert index["failed"] == ["bad", "worse"] and index["counts"] == {"done": 2, "failed": 2, "pending": 0}
    assert index["cases"]["bad"]["error"]["type"] == "InputError"
    rows = list(csv.reader((tmp_path / "index.csv").read_text().splitlines()))
    assert rows[0][:7] == ["name", "status", "error_type", "error_message", "engine", "bearing", "spec_hash"]
    assert rows[2][:3] == ["bad", "failed", "InputError"] and rows[2][3].startswith("dt:") and len(rows) == 5
    assert rows[1][rows[0].index("scenario.Fr")] == "1000.0"
    # a restart does not raise, retries the failed cases only, and a fixed spec clears the record
    stamp = os.path.getmtime(tmp_path / "a.json")
    cases["bad"] = _case(2000.0)
    res = run_sweep(cases, tmp_path, workers=workers, progress=False)
    assert res["bad"]["status"] == "done" and not (tmp_path / "bad.error.json").exists()
    assert (tmp_path / "worse.error.json").exists() and os.path.getmtime(tmp_path / "a.json") == stamp
    assert json.loads((tmp_path / "index.json").read_text())["failed"] == ["worse"]


def test_a_changed_spec_under_the_same_name_runs_again(tmp_path, capsys):
    run_sweep({"case": _case(1000.0)}, tmp_path, workers=1, progress=False)
    stamp = os.path.getmtime(tmp_path / "case.json")
    q1000 = load_case(tmp_path, "case")["summary"]["q_max_inner"]
    # the same spec written with an integer load is the same case
    run_sweep({"case": _case(1000)}, tmp_path, workers=1, progress=False)
    assert os.path.getmtime(tmp_path / "case.json") == stamp
    res = run_sweep({"case": _case(3000.0)}, tmp_path, workers=1, progress=False)
    assert res["case"]["spec"]["scenario"]["Fr"] == 3000.0
    assert res["case"]["summary"]["q_max_inner"] > 2 * q1000
    assert "changed their spec" in capsys.readouterr().err
    # a record written before the hash was stored: compared through its spec
    rec = json.loads((tmp_path / "case.json").read_text())
    del rec["spec_hash"]
    (tmp_path / "case.json").write_text(json.dumps(rec))
    stamp = os.path.getmtime(tmp_path / "case.json")
    run_sweep({"case": _case(3000.0)}, tmp_path, workers=1, progress=False)
    assert os.path.getmtime(tmp_path / "case.json") == stamp


def test_a_bearing_file_is_hashed_by_its_content(tmp_path):
    from exudyn_bearing import catalog

    f = tmp_path / "b.json"
    f.write_text(json.dumps(catalog["6208"].to_dict()))
    spec = dict(bearing=str(f), scenario=dict(Fr=1000.0))
    h = spec_hash(spec)
    d = catalog["6208"].to_dict()
    d["ball_radius"] *= 1.01
    f.write_text(json.dumps(d))
    assert spec_hash(spec) != h


def test_files_have_the_usual_permissions(tmp_path):
    old = os.umask(0o022)
    try:
        run_sweep({"ok": _case(1000.0)}, tmp_path, workers=1, progress=False)
        run_sweep({"bad": _case(1000.0, dt=-1.0)}, tmp_path, workers=1, progress=False)
    finally:
        os.umask(old)
    names = sorted(p.name for p in tmp_path.iterdir())
    assert names == ["bad.error.json", *INDEX, "ok.json", "ok.npz"]
    for p in tmp_path.iterdir():
        assert stat.S_IMODE(p.stat().st_mode) == 0o644, p.name


def test_sweep_interrupted_is_a_keyboard_interrupt_and_the_handler_is_restored(tmp_path):
    assert issubclass(SweepInterrupted, KeyboardInterrupt)
    before = signal.getsignal(signal.SIGTERM)
    run_sweep({"bad": _case(1000.0, dt=-1.0)}, tmp_path, workers=1, progress=False)
    assert signal.getsignal(signal.SIGTERM) is before


def test_dask_local_cluster(tmp_path):
    # one worker process: the cases still cross a process boundary (pickled out, records back, files
    # written by the worker), which is what a Dask cluster adds; a second worker only doubled the
    # start-up (each spawned worker imports distributed and the package, several seconds of CPU)
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True, dashboard_address=None) as cl, \
            distributed.Client(cl) as client:
        cases = _cases()
        cases["bad"] = _case(1000.0, dt=-1.0)
        res = run_sweep(cases, tmp_path, scheduler=client, progress=False)
    assert res["Fr1000"]["summary"]["steps"] == 400
    assert res["bad"]["error"]["type"] == "InputError"
    assert load_case(tmp_path, "Fr3000")["summary"]["q_max_inner"] > 1000


def test_the_hash_is_over_the_whole_scenario_so_a_changed_default_reruns(monkeypatch):
    """A spec that leaves a field out is hashed with the field's default: a spec written out in full hashes
    alike, and a case computed under another default (the package's Fr default was 3000 N before issue 36's
    defaults) hashes differently, so a resumed sweep runs it again instead of taking the old result."""
    import dataclasses

    from exudyn_bearing.model.scenario import Scenario

    short = {"bearing": "6208", "scenario": {"omega": 500.0, "t_end": 0.01}}
    full = {"bearing": "6208", "scenario": {"omega": 500, "t_end": 0.01, "Fr": 0.0, "cage": "auto"}}
    assert spec_hash(short) == spec_hash(full)
    h = spec_hash(short)
    old_default = dataclasses.make_dataclass("Scenario", [("Fr", float, 3000.0)], bases=(Scenario,), frozen=True)
    assert old_default().Fr == 3000.0
    monkeypatch.setattr("exudyn_bearing.sweep.Scenario", old_default)
    assert spec_hash(short) != h
    assert spec_hash({"bearing": "6208", "scenario": {"Fr": 1.0, "nonsense": 1}})  # invalid: hashed as written
