"""Dynamic runs, issue 33 items 4, 7 and 11: Ctrl-C gives one line and status 130 and keeps the samples so far;
the memory check counts the process's own limits (ulimit -v); a long run says its estimated wall time first;
one rule for history friction under multi-stage solvers in Scenario and the Exudyn element; the point level's
step-dependent friction outputs are marked in every output."""
import json
import math
import os
import re
import resource
import select
import signal
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing._jit import COMPILE_NOTICE
from exudyn_bearing.cli import main
from exudyn_bearing.data import InputError
from exudyn_bearing.model import memory
from exudyn_bearing.model.record import RunInterrupted
from exudyn_bearing.model.scenario import history_friction_error
from exudyn_bearing.outputs.jsonio import to_jsonable
from exudyn_bearing.outputs.results import (
    NOT_CONVERGED_MARK,
    POINT_STEP_DEPENDENT,
    SteadyStateWarning,
)
from exudyn_bearing.solvers.reference import engine as ref_engine
from exudyn_bearing.model.memory import wall_time_message
from exudyn_bearing.solvers.reference.engine import ReferenceEngine

ROOT = Path(__file__).resolve().parents[1]
linux = pytest.mark.skipif(not sys.platform.startswith("linux"), reason="reads /proc")


def _interruptible():
    """In the child before exec: SIGINT to its default (a test session started in the background inherits it
    ignored; tests/test_workers.py)."""
    signal.signal(signal.SIGINT, signal.SIG_DFL)


def _quiet(fn, *args, **kw):
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return fn(*args, **kw)


# -- item 4a: Ctrl-C ------------------------------------------------------------------------------------------
def test_ctrl_c_in_the_reference_run_keeps_the_samples_so_far(monkeypatch):
    # Ctrl-C arrives between two chunks of the integration: RunInterrupted (a KeyboardInterrupt) with the time
    # reached and the samples taken up to it, as Results from simulate()
    real, calls = ref_engine.run_verlet, []

    def interrupted(n_steps, *args):
        calls.append(n_steps)
        if len([n for n in calls if n > 0]) == 3:
            raise KeyboardInterrupt
        return real(n_steps, *args)

    monkeypatch.setattr(ref_engine, "run_verlet", interrupted)
    sc = eb.Scenario(omega=500.0, Fr=1000.0, t_end=2e-3, dt=5e-6, sample_dt=5e-5, tangential="implicit")
    with pytest.raises(RunInterrupted) as exc:
        _quiet(ReferenceEngine("6208", sc).run, progress=False, chunk_steps=100)
    assert isinstance(exc.value, KeyboardInterrupt)
    assert exc.value.t == pytest.approx(200 * 5e-6) and exc.value.t_end == pytest.approx(2e-3)
    assert exc.value.samples == 20 and exc.value.record.data["t"][-1] == pytest.approx(exc.value.t)
    calls.clear()
    with pytest.raises(RunInterrupted) as exc:
        _quiet(eb.simulate, "6208", sc, progress=False)
    assert exc.value.results is not None and len(exc.value.results.t) == exc.value.samples > 0


def test_ctrl_c_in_the_exudyn_run_is_a_run_interrupted_not_exudyns_error():
    # Exudyn wraps the KeyboardInterrupt raised in the element's user function in its ModelError: the engine
    # hands on Ctrl-C as RunInterrupted with the samples so far
    from exudyn_bearing.solvers.element.engine import ExudynEngine

    sc = eb.Scenario(omega=500.0, Fr=3000.0, t_end=2e-3, dt=5e-6, sample_dt=1e-4)
    eng = _quiet(ExudynEngine, "6208", sc)
    el = eng.element
    inner, count = el._force_uf, [0]

    def uf(mbs, t, i, q, q_t):
        count[0] += 1
        if count[0] == 150:
            raise KeyboardInterrupt
        return inner(mbs, t, i, q, q_t)

    eng.mbs.SetObjectParameter(el.items["object"], "forceUserFunction", uf)
    with pytest.raises(RunInterrupted) as exc:
        _quiet(eng.run)
    assert 0 < exc.value.samples < 20 and 0.0 < exc.value.t < sc.t_end


def test_ctrl_c_before_the_run_is_one_line_and_status_130(monkeypatch, capsys):
    import exudyn_bearing.cli.simulate as cli_simulate

    def stopped(*args, **kw):
        raise KeyboardInterrupt

    monkeypatch.setattr(cli_simulate, "simulate", stopped)
    assert main(["simulate", "--Fr", "3000", "--omega", "500", "6208", "--t-end", "1e-3"]) == 130
    err = capsys.readouterr().err
    assert err == "exudyn-bearing: simulate stopped by SIGINT\n"


def _read_until(proc, pattern, polls=600, timeout=0.5):
    """stderr of ``proc`` read until ``pattern`` (a compiled regex) matches it (at most ``polls`` waits of
    ``timeout`` s, or the process's end); returns (text, match)."""
    fd = proc.stderr.fileno()
    text = ""
    for _ in range(polls):
        ready, _, _ = select.select([fd], [], [], timeout)
        if ready:
            chunk = os.read(fd, 65536).decode(errors="replace")
            if not chunk:
                break
            text += chunk
        m = pattern.search(text)
        if m or proc.poll() is not None:
            return text, m
    return text, pattern.search(text)


@linux
def test_sigint_of_a_long_simulate_says_its_estimate_then_one_line_130(tmp_path):
    # 1e9 steps: the estimated wall time comes on stderr first (within the first second of integration), then
    # the progress; SIGINT after a sample: one line, status 130, no traceback, the samples in --out
    out = tmp_path / "run"
    proc = subprocess.Popen([sys.executable, "-m", "exudyn_bearing", "simulate", "--Fr", "3000", "--omega", "500", "6208", "--t-end", "1e3",
                             "--dt", "1e-6", "--sample-dt", "0.05", "--out", str(out)], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, preexec_fn=_interruptible)
    try:
        text, est = _read_until(proc, re.compile(r"estimated wall time ([0-9.e+]+) (s|min|h|d) \("))
        assert est, text
        assert math.isfinite(float(est.group(1))) and float(est.group(1)) > 0.0
        assert re.search(r"--t-end", text[est.start():].splitlines()[0])
        # a progress line past the first sample, so that there is something to keep
        more, _ = _read_until(proc, re.compile(r"t = (0\.[1-9]|[1-9])[0-9.]*/1000"))
        proc.send_signal(signal.SIGINT)
        rest, err = proc.communicate(timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    err = text + more + err.decode()
    assert proc.returncode == 130, err
    assert "Traceback" not in err and "KeyboardInterrupt" not in err
    stop = [line for line in err.replace("\r", "\n").splitlines() if "stopped by SIGINT" in line]
    assert len(stop) == 1 and re.search(r"at t = \S+ of 1000 s \((\d+) samples, written to ", stop[0]), stop
    assert (out / "run.npz").exists() and (out / "run.json").exists()
    assert rest == b""


# -- item 4b: memory limits -----------------------------------------------------------------------------------
@linux
def test_the_memory_check_counts_the_address_space_limit(monkeypatch):
    real = resource.getrlimit
    vm = memory._status_bytes("VmSize")
    assert vm and vm > 0

    def limited(which):
        if which == resource.RLIMIT_AS:
            return (vm + 2 ** 30, resource.RLIM_INFINITY)  # 1 GiB more than the process takes now
        return real(which)

    monkeypatch.setattr(resource, "getrlimit", limited)
    room, what = memory.limit_room()
    assert room <= 2 ** 30 and "ulimit -v" in what
    assert memory.available_memory() <= 2 ** 30
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.3, dt=1e-6, sample_dt=1e-6)  # 3e5 samples of 9 balls: 1.2 GiB
    with pytest.raises(InputError, match=r"^sample_dt: .*ulimit -v.*--sample-dt .*--t-end"):
        memory.check_sample_memory("6208", sc)


@linux
def test_simulate_under_ulimit_v_refuses_instead_of_numpys_memory_error():
    # 2.01 GiB of samples (5e5 of 9 balls): within half the free memory of a machine with more than 5 GiB
    # free, beyond what a 1.5 GiB address space leaves
    free = memory._free_memory()
    if free is None or free < 5 * 2 ** 30:
        pytest.skip("the refusal would then name the free memory, not the limit")
    limit = int(1.5 * 2 ** 30)

    def limited():
        _interruptible()
        resource.setrlimit(resource.RLIMIT_AS, (limit, limit))

    p = subprocess.run([sys.executable, "-m", "exudyn_bearing", "simulate", "--Fr", "3000", "--omega", "500", "6208", "--t-end", "0.5",
                        "--sample-dt", "1e-6", "--dt", "1e-6"], cwd=ROOT, capture_output=True, text=True,
                       preexec_fn=limited, timeout=300)
    assert p.returncode == 2, p.stderr
    assert p.stderr.startswith("exudyn-bearing: error: sample_dt: ") and "ulimit -v" in p.stderr
    assert "--sample-dt" in p.stderr and "--t-end" in p.stderr and "Traceback" not in p.stderr


# -- item 4c: the wall-time estimate --------------------------------------------------------------------------
def test_wall_time_message_names_the_estimate_and_what_shortens_it():
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=1e3, dt=1e-6, sample_dt=0.1)
    msg = wall_time_message(10 ** 9, 10 ** 5, 0.2, sc, 6e-6)
    assert msg.startswith("1e+09 steps of dt = 1e-06 s") and "--t-end" in msg and "--dt" in msg
    assert re.search(r"estimated wall time [0-9.]+ min \(2 us per step over the first 100000 steps\)", msg)
    # a short run, a finished run or no measurement say nothing
    assert wall_time_message(10 ** 6, 10 ** 5, 0.2, sc, 6e-6) is None  # 2 s
    assert wall_time_message(10 ** 9, 10 ** 9, 2000.0, sc, 6e-6) is None
    assert wall_time_message(10 ** 9, 0, 0.0, sc, 6e-6) is None
    # at the stable step, a larger dt is no advice
    assert "--dt" not in wall_time_message(10 ** 9, 10 ** 5, 0.2, sc, 1e-6)


class GainingClock:
    """A stand-in for the engines' ``time`` module whose perf_counter gains 1 s per reading: every run looks
    long, whatever this machine's speed (what the tests below assert is the message, never a duration)."""

    def __init__(self):
        self.now = 0.0

    def perf_counter(self):
        self.now += 1.0
        return self.now


def test_a_run_estimated_long_says_so_once_before_its_progress(monkeypatch, capsys):
    # every run looks long (GainingClock); the estimate comes after the first chunk, once, on a line of its
    # own, ahead of the progress lines, and progress=False says nothing
    monkeypatch.setattr(ref_engine, "time", GainingClock())
    monkeypatch.setattr(memory, "LONG_RUN_S", 10.0)  # the 400 steps at 1 s per chunk of 20: 20 s or more
    sc = eb.Scenario(omega=500.0, Fr=1000.0, t_end=2e-3, dt=5e-6, tangential="implicit")
    _quiet(ReferenceEngine("6208", sc).run, progress=None)
    err = capsys.readouterr().err
    lines = [x for x in err.replace("\r", "\n").splitlines() if "estimated wall time" in x]
    assert len(lines) == 1 and lines[0].startswith("[reference] 400 steps of dt = 5e-06 s")
    first_progress = err.index("[reference] t =")
    assert "estimated wall time" in err[:first_progress]  # said before the progress, not after it
    _quiet(ReferenceEngine("6208", sc).run, progress=False)
    assert capsys.readouterr().err == ""


def test_a_long_exudyn_run_says_its_estimate_too(monkeypatch, capsys):
    # every run counts as long here (GainingClock): the Exudyn engine measures the step cost between its samples
    # and says the estimate once, on stderr; progress=False says nothing
    from exudyn_bearing.solvers.element import engine as el_engine

    monkeypatch.setattr(el_engine, "time", GainingClock())
    monkeypatch.setattr(memory, "LONG_RUN_S", 5.0)  # 200 steps, 20 of them measured at 1 s: 10 s estimated
    monkeypatch.setattr(el_engine, "ESTIMATE_AFTER_S", 0.0)
    sc = eb.Scenario(omega=500.0, Fr=3000.0, t_end=1e-3, dt=5e-6, sample_dt=1e-4)
    _quiet(el_engine.ExudynEngine("6208", sc).run)
    err = capsys.readouterr().err.replace(COMPILE_NOTICE + "\n", "")  # a cold numba cache says so first
    assert err.count("estimated wall time") == 1 and err.startswith("[exudyn] 200 steps of dt = 5e-06 s"), err
    assert _quiet(el_engine.ExudynEngine("6208", sc).run, progress=False).data["t"].size == 10
    assert "estimated" not in capsys.readouterr().err


# -- item 7: history friction under multi-stage solvers -------------------------------------------------------
def _element(mode="bodies", **kw):
    import exudyn as exu
    from exudyn.itemInterface import (
        MarkerBodyRigid,
        MarkerNodePosition,
        NodePoint,
        ObjectGround,
        ObjectMassPoint,
    )

    mbs = exu.SystemContainer().AddSystem()
    node = mbs.AddNode(NodePoint(referenceCoordinates=[0.0, 0.0, 0.0]))
    mbs.AddObject(ObjectMassPoint(mass=0.5, nodeNumber=node))
    m_in = mbs.AddMarker(MarkerNodePosition(nodeNumber=node))
    m_out = mbs.AddMarker(MarkerBodyRigid(bodyNumber=mbs.AddObject(ObjectGround()), localPosition=[0, 0, 0]))
    el = eb.CreateBallBearing(mbs, "6208", m_in, m_out, stepSize=5e-6, innerRingSpeed=lambda t: 500.0,
                              initialOmega=500.0, initialLoad=(3000.0, 0.0), mode=mode, **kw)
    mbs.Assemble()
    return mbs, el


def test_history_friction_has_one_rule_for_scenario_and_element():
    import exudyn as exu

    from exudyn_bearing.solvers.element.engine import solve_dynamic

    with pytest.raises(InputError) as sc_err:
        eb.Scenario(Fr=3000.0, omega=500.0, integrator="rk4", friction="history")
    assert str(sc_err.value) == str(history_friction_error("history", "rk4", "integrator"))
    mbs, el = _element()
    expected = str(history_friction_error("history", "RK44", "solverType"))
    with pytest.raises(InputError) as el_err:
        el.SimulationSettings(1e-4, solverType="RK44")
    assert str(el_err.value) == expected
    # the two messages differ only in the parameter they name and the way to ask for velocity Verlet
    assert expected.startswith("solverType: RK44 ") and str(sc_err.value).startswith("integrator: rk4 ")
    tail = "advances the Cundall-Strack spring once per step"
    assert tail in expected and tail in str(sc_err.value)
    # settings made otherwise: refused at the run's first evaluation, before any step
    ss = _quiet(el.SimulationSettings, 1e-4)
    with pytest.raises(InputError, match="^solverType: RK44 "):
        solve_dynamic(mbs, ss, exu.DynamicSolverType.RK44)
    # history-free friction, VelocityVerlet, and the fast mode (its balls take Verlet sub-steps) are accepted
    _quiet(_element(friction="regularized")[1].SimulationSettings, 1e-4, solverType="RK44")
    _quiet(el.SimulationSettings, 1e-4, solverType="VelocityVerlet")
    _quiet(_element(mode="fast")[1].SimulationSettings, 1e-4, solverType="RK44")
    for solver in ("RK33", "ExplicitMidpoint", "RK67"):
        assert history_friction_error("history", solver) is not None
    for solver in ("VelocityVerlet", "GeneralizedAlpha"):
        assert history_friction_error("history", solver) is None
    assert history_friction_error("regularized", "RK44") is None


# -- item 11: the point level's friction outputs --------------------------------------------------------------
@pytest.fixture(scope="module")
def point_run():
    return _quiet(eb.simulate, "6208", eb.Scenario(omega=500.0, Fr=3000.0, t_end=2e-3, dt=4e-6, sample_dt=1e-4),
                  progress=False)


def test_point_level_summary_marks_its_step_dependent_outputs(point_run):
    s = _quiet(point_run.summary)
    assert s["traction_level"] == "point" and s["friction"] == "history"
    assert s["friction_outputs_converged"] is False and s["not_converged"] == list(POINT_STEP_DEPENDENT)
    for key in POINT_STEP_DEPENDENT:  # the numbers stay (the energy check uses them), marked
        top, _, part = key.partition(".")
        value = s[top][part] if part else s[top]
        assert isinstance(value, float) and math.isfinite(value)
        assert s["descriptions"][key].startswith(f"({NOT_CONVERGED_MARK})")
    assert "passed" in s["energy_check"]
    # the JSON file of the run carries the same fields
    js = json.loads(json.dumps(to_jsonable(s)))
    assert js["friction_outputs_converged"] is False


def test_results_say_the_ellipse_level_and_history_free_laws_are_not_flagged(point_run):
    r, original = point_run, point_run.scenario
    for change, converged in ((dict(traction_level="ellipse"), True), (dict(friction="regularized"), True),
                              ({}, False)):
        r.scenario = original.replace(**change)
        assert r.friction_outputs_converged() is converged
    r.scenario = original


def test_simulate_marks_the_rows_and_the_json(capsys):
    argv = ["simulate", "--Fr", "3000", "--omega", "500", "6208", "--t-end", "2e-3", "--dt", "4e-6"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", SteadyStateWarning)
        assert main(argv) == 0
        table = capsys.readouterr().out
        assert main([*argv, "--json"]) == 0
        js = json.loads(capsys.readouterr().out)
    rows = {line.split()[0]: line for line in table.splitlines() if line.strip()}
    for key in ("friction_torque", "friction_power", "dissipation", "dissipation_inner",
                "power_loss.contact_traction_inner", "power_loss_total"):
        assert rows[key].endswith(f"({NOT_CONVERGED_MARK})"), rows[key]
    for key in ("q_max_inner", "cage_speed", "drive_power"):
        assert "not converged" not in rows[key]
    assert rows["friction_outputs_converged"].split()[1] == "False"
    assert js["friction_outputs_converged"] is False and "friction_torque" in js["not_converged"]
    assert np.isfinite(js["friction_torque"])
