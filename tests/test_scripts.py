"""The scenario scripts and saved runs keep working (short versions of the real runs)."""
from pathlib import Path

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.outputs.results import Results

from conftest import manual_text

ROOT = Path(__file__).resolve().parents[1]


# a short run: its summary window is not steady, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_saved_run_loads_back(tmp_path):
    r = eb.simulate("6208", eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.002, dt=5e-6, sample_dt=2e-4))
    npz, js = r.save(tmp_path)
    back = Results.load(npz)
    assert back.summary()["q_max_inner"] == pytest.approx(r.summary()["q_max_inner"], rel=1e-12)
    assert back.scenario == r.scenario and back.bearing == r.bearing
    np.testing.assert_array_equal(back.data["diag"], r.data["diag"])


# a short run: its summary window is not steady, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_papers_scenario_script(tmp_path, capsys, load_script):
    mod = load_script("scenarios/papers_6208.py")
    mod.main(["--up", "0.005", "--steady", "0.01", "--down", "0.005", "--out", str(tmp_path)])
    for name in ("overview.png", "speeds.png", "srr_ball0.png", "film_outer.png", "run.npz", "run.json"):
        assert (tmp_path / name).stat().st_size > 0
    assert "steady phase: cage" in capsys.readouterr().out


# a short run: its summary window is not steady, nor its energy balance closed, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
@pytest.mark.filterwarnings("ignore::exudyn_bearing.EnergyBalanceWarning")
def test_rotor_scenario_script(tmp_path, capsys, load_script):
    mod = load_script("scenarios/rotor_two_6208.py")
    # a short run to 30 rad/s (the speed limiter takes the last 1 % in about 25 ms)
    mod.main(["--t-end", "0.04", "--omega", "30", "--out", str(tmp_path)])
    assert (tmp_path / "rotor.png").stat().st_size > 0 and (tmp_path / "bearing_A.npz").exists()
    # the table its docstring quotes: windows of orbit radius and outer ball loads
    out = capsys.readouterr().out.splitlines()
    head = next(i for i, line in enumerate(out) if line.strip().startswith("window [ms]"))
    assert "run-up to 30 rad/s ends at" in out[head - 1]
    assert "bearing A q_outer" in out[head] and "bearing B q_outer" in out[head]
    rows = [line for line in out[head + 1:] if line.startswith("  ") and line.count("/") == 3]
    assert len(rows) == 5
    # the catalogue 6208 has no clearance: the docstring must not promise a whirl "at the full clearance"
    assert "window [ms]" in mod.__doc__ and "no diametral clearance" in mod.__doc__
    assert "full clearance" not in mod.__doc__


# a short run: its summary window is not steady, nor its energy balance closed, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
@pytest.mark.filterwarnings("ignore::exudyn_bearing.EnergyBalanceWarning")
@pytest.mark.filterwarnings("ignore::exudyn_bearing.BallInertiaWarning")  # expected: lightly loaded balls
def test_7208_scenario_script(tmp_path, capsys, load_script):
    mod = load_script("scenarios/bearing_7208.py")
    mod.main(["--t-end", "0.002", "--out", str(tmp_path)])
    out = capsys.readouterr().out
    assert "reference:" in out and "exudyn" in out and (tmp_path / "bearing_7208.png").exists()


# a short run: its summary window is not steady, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_readme_element_example_runs_without_step_warnings(capsys):
    # the README's Exudyn example, shortened to 5 ms: it must run as printed, on a
    # CreateRigidBody shaft, inside the stable-step estimates, and carry the load
    import warnings

    text = manual_text()
    start = text.index("```python\nimport exudyn as exu, exudyn_bearing as eb")
    code = text[start + len("```python\n"):text.index("```\n", start + 10)]
    assert "endTime=0.1" in code
    with warnings.catch_warnings():
        warnings.simplefilter("error", eb.StepSizeWarning)
        scope = {}
        exec(compile(code.replace("endTime=0.1", "endTime=0.005"), "README.md", "exec"), scope)
    # quiet: Exudyn's known-benign notes ("VelocityVerlet: still under development") are filtered
    out = capsys.readouterr().out
    assert "still under development" not in out and "memory allocations" not in out
    s = scope["bearing"].results().summary()
    assert s["q_max_inner"] == pytest.approx(eb.simulate("6208", eb.Scenario(
        Fr=3000.0, omega=500.0, t_end=0.005, dt=3.5e-6, tangential="implicit")).summary()["q_max_inner"], rel=0.02)
