"""Sweep and dataset robustness: workers end with their parent, signals give one line and the conventional exit
status, a failing case does not break a dataset, warnings name their case, unstable steps are refined."""
import json
import os
import signal
import subprocess
import sys
import textwrap
import time
import warnings
from pathlib import Path

import pytest

from exudyn_bearing import StepSizeWarning, load_bearing
from exudyn_bearing import sweep as sw
from exudyn_bearing.sweep import run_sweep
from exudyn_bearing.datasets import build_dataset, dataset_cases, read_index
from exudyn_bearing.model.scenario import Scenario
from exudyn_bearing.model.stability import SimulationError, stable_step

ROOT = Path(__file__).resolve().parents[1]
linux = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")


def _descendants(pid):
    """Pids of the running descendants of ``pid`` (Linux /proc)."""
    children = {}
    for d in Path("/proc").iterdir():
        if d.name.isdigit():
            try:
                fields = (d / "stat").read_text().rsplit(")", 1)[1].split()
            except OSError:
                continue
            children.setdefault(int(fields[1]), []).append(int(d.name))
    out, todo = [], [pid]
    while todo:
        kids = children.get(todo.pop(), [])
        out += kids
        todo += kids
    return out


def _alive(pid):
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def _interruptible():
    """In the child before exec: SIGINT to its default, so that Python installs its KeyboardInterrupt
    handler. A test session started in the background of a non-interactive shell (``pytest ... &``, as
    some CI runners do) inherits SIGINT ignored, and an ignored SIGINT stays ignored across exec: the
    command under test would then rightly ignore the test's SIGINT, as a background job does Ctrl-C."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _start(argv, tmp_path):
    """Start ``argv`` (a Python command line) and wait until it runs two workers (:func:`_wait_for_workers`)."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.Popen([sys.executable, *argv], cwd=tmp_path, env=env, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, preexec_fn=_interruptible)
    return proc, _wait_for_workers(proc)


def _wait_for_workers(proc, polls=600):
    """The descendants of ``proc`` once it runs two workers (looked at every 0.2 s; after ``polls`` looks,
    or when ``proc`` ends, whatever runs then: the caller asserts on it)."""
    workers = []
    for _ in range(polls):
        if len(workers) >= 2 or proc.poll() is not None:
            break
        time.sleep(0.2)
        workers = _descendants(proc.pid)
    return workers


def _still_alive(workers, polls=1200):
    """The ``workers`` still alive once all have ended, looked at every 0.05 s up to ``polls`` times. The
    tests assert that the workers end, not how fast: no clock is read, and the number of looks only keeps
    a broken run from hanging the suite."""
    for _ in range(polls):
        if not any(_alive(p) for p in workers):
            break
        time.sleep(0.05)
    return [p for p in workers if _alive(p)]


def _cleanup(proc, workers):
    for p in [proc.pid, *workers]:
        if _alive(p):
            os.kill(p, signal.SIGKILL)
    proc.wait(10)


# a dataset that runs long enough to be signalled: two cases of 20 s each on two workers
DATASET = ["-m", "exudyn_bearing", "dataset", "6205", "ds", "--faults", "healthy", "outer", "--t-end", "20", "--workers", "2"]
SWEEP = textwrap.dedent("""
    from exudyn_bearing.sweep import run_sweep
    cases = {f"c{i}": dict(bearing="6208", scenario=dict(Fr=1000.0 + i, t_end=30.0, dt=5e-6,
             tangential="implicit", sample_dt=1e-2)) for i in range(4)}
    run_sweep(cases, "out", workers=2, progress=False)
""")


@linux
@pytest.mark.parametrize("argv", [DATASET, ["-c", SWEEP]], ids=["dataset", "sweep"])
def test_workers_end_when_the_parent_is_killed(tmp_path, argv):
    proc, workers = _start(argv, tmp_path)
    try:
        assert len(workers) >= 2, "the run did not start its workers"
        proc.kill()  # SIGKILL: no handler runs in the parent
        proc.wait(10)
        assert _still_alive(workers) == []
    finally:
        _cleanup(proc, workers)


@linux
@pytest.mark.parametrize("sig, status", [(signal.SIGTERM, 143), (signal.SIGINT, 130)])
def test_a_signal_stops_a_dataset_with_one_line_and_the_conventional_status(tmp_path, sig, status):
    proc, workers = _start(DATASET, tmp_path)
    try:
        assert len(workers) >= 2, "the run did not start its workers"
        time.sleep(0.5)
        proc.send_signal(sig)
        _out, err = proc.communicate(timeout=60)
        assert proc.returncode == status
        lines = [line for line in err.splitlines() if line.strip() and not line.startswith("exudyn_bearing: compiling")]
        assert len(lines) == 1 and "Traceback" not in err, err
        assert signal.Signals(sig).name in lines[0] and "resumes" in lines[0]
        assert [p for p in workers if _alive(p)] == []
        assert json.loads((tmp_path / "ds" / "index.json").read_text())["counts"]["pending"] == 2
    finally:
        _cleanup(proc, workers)


# -- progress lines: one per sweep, and an interrupted run ends its own -------------------------------------------
def test_the_cases_of_a_sweep_print_no_progress_line_of_their_own(tmp_path, monkeypatch):
    """Long cases would print the engine's automatic progress line; on parallel workers those lines overwrite each
    other and the sweep's own (and broke the one-line stop message of the signal tests above)."""
    seen = []

    def recording(bearing, scenario, **kw):
        seen.append(kw.get("progress", "not given"))
        return real(bearing, scenario, **kw)

    real = sw.simulate
    monkeypatch.setattr(sw, "simulate", recording)
    cases = {"c": dict(bearing="6208", scenario=dict(Fr=1000.0, t_end=1e-3, dt=5e-6, tangential="implicit"))}
    run_sweep(cases, tmp_path, workers=1, progress=False)
    assert seen == [False]


def test_an_interrupted_run_ends_its_progress_line(monkeypatch, capsys):
    """Ctrl-C (or an error) after a progress line (printed with a carriage return and no newline) ends that line,
    so that the traceback or the stop message that follows starts a line of its own."""
    import exudyn_bearing.solvers.reference.engine as engine_module

    class Clock:  # one second per reading: every chunk prints its progress line
        now = 0.0

        def perf_counter(self):
            Clock.now += 1.0
            return Clock.now

    real, calls = engine_module.run_verlet, []

    def interrupted(n_steps, *args):
        calls.append(n_steps)
        if len([n for n in calls if n > 0]) == 2:
            raise KeyboardInterrupt
        return real(n_steps, *args)

    monkeypatch.setattr(engine_module, "time", Clock())
    monkeypatch.setattr(engine_module, "run_verlet", interrupted)
    eng = engine_module.ReferenceEngine("6208", Scenario(omega=500.0, Fr=1000.0, t_end=2e-3, dt=5e-6, tangential="implicit"))
    with pytest.raises(KeyboardInterrupt):
        eng.run(progress=True, chunk_steps=100)
    err = capsys.readouterr().err
    assert "[reference] t =" in err and err.endswith("\n"), repr(err)


# -- datasets: failures, per-case step, refinement ---------------------------------------------------------
KW = dict(speeds_rpm=(1797.0,), loads=(1000.0,), sizes=((1e-3, 1.5e-3, 1e-4),), t_end=0.002, workers=1,
          progress=False)


def _failing_outer(real):
    """simulate() that blows up on every outer-race case and runs the others."""
    def fake(bearing, scenario, **kw):
        if scenario.defects and scenario.defects[0].race == "outer":
            raise SimulationError("dt: the state became non-finite at t = 1e-3 s (test)")
        return real(bearing, scenario, **kw)
    return fake


def test_a_failing_case_leaves_the_index_of_the_others(tmp_path, monkeypatch, capsys):
    monkeypatch.setattr(sw, "simulate", _failing_outer(sw.simulate))
    rows = build_dataset(tmp_path, faults=("healthy", "outer"), **KW)
    assert [r["fault"] for r in rows] == ["healthy"]
    assert [r["fault"] for r in read_index(tmp_path)] == ["healthy"]
    index = json.loads((tmp_path / "index.json").read_text())
    assert index["counts"] == {"done": 1, "failed": 1, "pending": 0}
    (name,) = index["failed"]
    err = json.loads((tmp_path / f"{name}.error.json").read_text())
    # every attempt blew up: the error of the last one, after REFINE halvings of the step
    assert err["error"]["type"] == "SimulationError"
    assert name in capsys.readouterr().err


def test_cli_exit_status_3_when_a_case_failed(tmp_path, monkeypatch, capsys):
    from exudyn_bearing.cli import main

    monkeypatch.setattr(sw, "simulate", _failing_outer(sw.simulate))
    with pytest.raises(SystemExit) as e:
        main(["dataset", "6205", str(tmp_path), "--faults", "healthy", "outer", "--t-end", "0.002", "--workers", "1"])
    assert e.value.code == 3
    out = capsys.readouterr().out
    assert "cases.failed" in out and (tmp_path / "index.csv").exists()


def test_each_case_takes_its_own_stable_step():
    # at 4000 N the 6205's stable step is below the 5.2 us of 4 steps per 48 kHz sample: that case takes more
    b = load_bearing("6205")
    cases = dataset_cases("6205", loads=(500.0, 4000.0), faults=("healthy",), t_end=0.01)
    steps = {}
    for name, spec in cases.items():
        sc = Scenario(**spec["scenario"])
        n = sc.signal_dt / sc.dt
        assert n == pytest.approx(round(n), rel=1e-12)  # an integer number of steps per signal sample
        assert sc.dt <= stable_step(b, sc).dt
        steps[spec["labels"]["load_N"]] = round(n)
    assert steps[500.0] == 4 and steps[4000.0] > 4


def test_a_blow_up_or_an_unstable_step_is_refined(tmp_path, monkeypatch, capsys):
    real = sw.simulate
    seen = []

    def fake(bearing, scenario, **kw):
        seen.append(scenario.dt)
        if len(seen) == 1:
            raise SimulationError("dt: the state became non-finite (test)")
        if len(seen) == 2:
            warnings.warn("dt: the ball / cage-ball contacts reached 40 N (test)", StepSizeWarning)
        return real(bearing, scenario, **kw)

    monkeypatch.setattr(sw, "simulate", fake)
    spec = dict(bearing="6208", scenario=dict(Fr=1000.0, omega=500.0, t_end=0.001, dt=4e-6, sample_dt=1e-4,
                                              tangential="implicit"), refine=2)
    res = sw.run_sweep({"c": spec}, tmp_path, workers=1, progress=False)
    assert seen == [4e-6, 2e-6, 1e-6]
    rec = res["c"]
    assert rec["dt"] == 1e-6 and rec["summary"]["steps"] == 1000
    assert [r["dt"] for r in rec["retries"]] == [4e-6, 2e-6] and "cage" in rec["retries"][1]["reason"]
    # the kept run's: no step warning (a 1 ms run's summary says it is too short to judge steadiness)
    assert [w for w in rec["warnings"] if w["type"] == "StepSizeWarning"] == []
    # without refine the warning stays, in the record and in the summary on stderr with the case's name
    seen.clear()
    seen.append(None)
    res = sw.run_sweep({"d": {**spec, "refine": 0}}, tmp_path, workers=1, progress=False)
    assert res["d"]["warnings"][0]["type"] == "StepSizeWarning" and res["d"]["dt"] == 4e-6
    assert "StepSizeWarning in 1 of 1 cases (first d): dt: the ball / cage-ball" in capsys.readouterr().err


def test_refine_must_be_a_small_integer(tmp_path):
    spec = dict(bearing="6208", scenario=dict(Fr=1000.0, t_end=0.001), refine=-1)
    res = sw.run_sweep({"c": spec}, tmp_path, workers=1, progress=False)
    assert res["c"]["error"]["type"] == "InputError" and res["c"]["error"]["message"].startswith("refine")
    assert set(res["c"]) == set(sw.FAILED_RECORD_FIELDS)  # a refused case has the failed record's fields


@linux
@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGINT])
def test_a_signal_to_the_parent_stops_the_workers(tmp_path, sig):
    # six long cases on two workers: the parent alone is signalled while the first two
    # run; no worker may survive it, no queued case may start, the index lists them pending
    script = textwrap.dedent(f"""
        import sys
        from exudyn_bearing.sweep import SweepInterrupted, run_sweep
        cases = {{f"c{{i}}": dict(bearing="6208", scenario=dict(Fr=1000.0 + i, t_end=30.0, dt=5e-6,
                  tangential="implicit", sample_dt=1e-2)) for i in range(6)}}
        try:
            run_sweep(cases, {str(tmp_path)!r}, workers=2, progress=False)
        except SweepInterrupted:
            sys.exit(43)
        except KeyboardInterrupt:
            sys.exit(42)
    """)
    proc = subprocess.Popen([sys.executable, "-c", script], preexec_fn=_interruptible)
    workers = []
    try:
        workers = _wait_for_workers(proc)
        assert len(workers) >= 2, "the sweep did not start its workers"
        time.sleep(1.0)
        workers = _descendants(proc.pid)
        proc.send_signal(sig)
        rc = proc.wait(60)
        assert rc == 43  # SweepInterrupted for both (a KeyboardInterrupt)
        # the workers end with the parent (polled: a worker that has ended stays ended)
        assert _still_alive(workers) == []
        index = json.loads((tmp_path / "index.json").read_text())
        assert index["counts"]["pending"] == 6
        assert not list(tmp_path.glob("c*.json"))
    finally:
        for p in [proc.pid, *workers]:
            if _alive(p):
                os.kill(p, signal.SIGKILL)
        proc.wait(10)
