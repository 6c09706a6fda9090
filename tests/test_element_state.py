"""Exudyn bearing element: the views of Exudyn's coordinate vectors its user functions read."""
import warnings

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

import exudyn_bearing as eb  # noqa: E402
from exudyn_bearing.solvers.element.engine import ExudynEngine, solve_dynamic  # noqa: E402

SCENE = dict(Fr=3000.0, omega=500.0, sample_dt=1e-4, t_end=1e-4, dt=5e-6)


def _engine(mode="bodies"):
    return ExudynEngine("6208", eb.Scenario(**SCENE), mode=mode)


def _spy(el, check):
    """Wrap the element's user function: ``check(t)`` before each evaluation; returns the evaluation count."""
    inner = el._force_uf_fast if el.mode == "fast" else el._force_uf
    count = [0]

    def uf(mbs, t, i, q, q_t):
        check(t)
        count[0] += 1
        return inner(mbs, t, i, q, q_t)

    el.mbs.SetObjectParameter(el.items["object"], "forceUserFunction", uf)
    return count


@pytest.mark.parametrize("mode, solver, end, step", [("bodies", "VelocityVerlet", 1e-4, None),
                                                       # its numerical Jacobian perturbs every system coordinate
                                                       ("bodies", "GeneralizedAlpha", 3e-5, 1e-5),
                                                       ("fast", "VelocityVerlet", 1e-4, None)])
def test_coordinate_views_show_every_evaluated_state(mode, solver, end, step):
    # the user function reads views of Exudyn's coordinate vectors taken at the run's start
    # (GetODE2Coordinates(copy=False)); they must hold, at each evaluation, exactly what Exudyn's
    # copying call returns then, with the Jacobian's perturbed states of the implicit solver included
    eng = _engine(mode)
    el = eng.element
    sd = eng.mbs.systemData
    seen = []

    def check(t):
        if el.__dict__.get("_coordinates", [None])[0] is None:
            return  # the first evaluation takes the views
        qs, qs_t, _first = el._coordinates
        seen.append(np.array_equal(qs, sd.GetODE2Coordinates())
                    and np.array_equal(qs_t, sd.GetODE2Coordinates_t()))

    count = _spy(el, check)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ss = el.SimulationSettings(end, step, solverType=solver)
        solve_dynamic(eng.mbs, ss)
    assert count[0] > 5 and len(seen) >= count[0] - 1
    assert all(seen)


@pytest.mark.parametrize("mode", ["bodies", "fast"])
def test_stale_coordinate_views_are_taken_anew(mode):
    # a view that no longer shows Exudyn's current vector (here a frozen copy put in its place halfway)
    # is noticed at the next evaluation and replaced: the run ends bitwise as an undisturbed one; with
    # the frozen copy used, the balls (rings) would feel the forces of a state Exudyn has left
    base = _engine(mode).run()
    eng = _engine(mode)
    el = eng.element
    calls = [0]

    def check(t):
        calls[0] += 1
        if calls[0] == 10:
            el._coordinates[0] = el._coordinates[0].copy()

    _spy(el, check)
    rec = eng.run()
    assert calls[0] > 10
    for key, value in base.data.items():
        np.testing.assert_array_equal(rec.data[key], value, err_msg=key)


def test_engine_speed_function_is_the_protocols_speed():
    # the engine hands the element Scenario.speed_function(), a closure, instead of Scenario.omega_at:
    # on ramps, the steady phase and at rest it must return omega_at's value to the last bit (the runs
    # stay bitwise the same)
    sc = eb.Scenario.papers_protocol(omega=500.0, t_ramp_up=0.02, t_steady=0.06, t_ramp_down=0.02)
    f = sc.speed_function()
    times = np.concatenate([np.linspace(-1e-3, 0.11, 1001), [0.0, 0.02, 0.08, 0.1]])
    assert [f(t) for t in times] == [sc.omega_at(t) for t in times]
    # the protocol's values by hand (to round-off: the compiled ramp may divide by a reciprocal)
    assert (f(0.05), f(0.01), f(0.09), f(0.2)) == pytest.approx((500.0, 250.0, 250.0, 0.0), rel=1e-12, abs=1e-12)
