"""Sweep runner: parallel cases, atomic per-case files, resume, Dask."""
import json
import os

import pytest

from exudyn_bearing.sweep import load_case, run_sweep


def _cases(frs=(1000.0, 3000.0)):
    return {f"Fr{int(fr)}": dict(bearing="6208", scenario=dict(Fr=fr, omega=500.0, t_end=0.002, dt=5e-6,
                                                              tangential="implicit", sample_dt=2e-4))
            for fr in frs}


def test_parallel_sweep_writes_one_file_per_case_and_resumes(tmp_path):
    res = run_sweep(_cases(), tmp_path, workers=2, progress=False)
    assert set(res) == {"Fr1000", "Fr3000"}
    assert res["Fr3000"]["summary"]["q_max_inner"] > res["Fr1000"]["summary"]["q_max_inner"]
    assert "lambda_outer" in res["Fr3000"]["arrays"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["Fr1000.json", "Fr1000.npz", "Fr3000.json", "Fr3000.npz"]
    # resume: finished cases are not run again, a missing one is
    stamp = os.path.getmtime(tmp_path / "Fr3000.json")
    (tmp_path / "Fr1000.json").unlink()
    run_sweep(_cases(), tmp_path, workers=1, progress=False)
    assert os.path.getmtime(tmp_path / "Fr3000.json") == stamp
    assert (tmp_path / "Fr1000.json").exists()
    rec = json.loads((tmp_path / "Fr1000.json").read_text())
    assert rec["spec"]["scenario"]["Fr"] == 1000.0


def test_results_equal_serial_run(tmp_path):
    a = run_sweep(_cases((2000.0,)), tmp_path / "a", workers=1, progress=False)
    b = run_sweep(_cases((2000.0,)), tmp_path / "b", workers=2, progress=False)
    assert a["Fr2000"]["summary"]["q_max_outer"] == b["Fr2000"]["summary"]["q_max_outer"]


def test_bad_case_name_rejected(tmp_path):
    with pytest.raises(ValueError, match="cases"):
        run_sweep({"../x": {}}, tmp_path, progress=False)


def test_dask_local_cluster(tmp_path):
    distributed = pytest.importorskip("distributed")
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cl, \
            distributed.Client(cl) as client:
        res = run_sweep(_cases(), tmp_path, scheduler=client, progress=False)
    assert res["Fr1000"]["summary"]["steps"] == 400
    assert load_case(tmp_path, "Fr3000")["summary"]["q_max_inner"] > 1000
