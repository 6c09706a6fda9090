"""The elastic energy stored in the contacts (``contact_energy``, docs/theory/dynamics.md, "Losses and the
energy balance"): it is the potential of the contacts' elastic forces (its gradient in a ball's position is
minus the elastic force on the ball, at the races and at a rigid cage's pocket), and the energy balance of a
window counts its change beside the kinetic energy's."""
import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.model import layout as L
from exudyn_bearing.model.contact import scene_loss_path, scene_paths
from exudyn_bearing.model.motion import ring_poses
from exudyn_bearing.outputs.window_checks import energy_balance, energy_check
from exudyn_bearing.solvers.reference.engine import ReferenceEngine
from exudyn_bearing.solvers.reference.integrators import evaluate


def _at_rest(engine, xb, xc):
    """Forces on the balls and the stored energy of the engine's scene with the balls at ``xb``, the cage at
    ``xc`` and every velocity zero (no damping, no slip: only the elastic forces act)."""
    st = engine.initial_state()
    z = engine.bearing.n_balls
    fb, glob = np.zeros((z, 3)), np.zeros(L.NGLOBAL)
    zero = np.zeros_like
    ring = st["ring"].copy()
    ring[3:] = 0.0  # the inner ring's translation rates
    defect_path, ellipse_path = scene_paths(engine.params)
    evaluate(0.0, engine.params, engine.table, xb.copy(), zero(st["vb"]), zero(st["wb"]), xc.copy(),
             zero(st["vc"]), ring, ring_poses(), zero(st["hist"]), st["hz"].copy(), fb, np.zeros((z, 3)),
             np.zeros((z, 3)), np.zeros((2, 6)), np.zeros(3), glob, np.zeros((z, 2, L.NDIAG)), np.zeros((z, 2)),
             True, defect_path, ellipse_path, scene_loss_path(engine.params))
    return fb, glob[L.G_CONTACT_ENERGY]


def _gradient_check(engine, xb, xc, j, h):
    """Central differences of the stored energy in ball j's position against the force on it."""
    f, e0 = _at_rest(engine, xb, xc)
    assert e0 > 0.0
    grad = np.zeros(3)
    for k in range(3):
        plus, minus = xb.copy(), xb.copy()
        plus[j, k] += h
        minus[j, k] -= h
        grad[k] = (_at_rest(engine, plus, xc)[1] - _at_rest(engine, minus, xc)[1]) / (2.0 * h)
    return grad, f[j]


@pytest.mark.parametrize("law", ["hertz", "power"])
def test_the_stored_energy_is_the_potential_of_the_race_contacts(law):
    # the loaded ball at psi = 0 of the 6208 at rest under 3 kN, moved 1 um off its equilibrium along x and
    # 0.5 um along z (both its contacts then push it): -grad E = F to the differences' accuracy; a factor
    # other than 0.4 (or 1 / (n + 1) for the power law) in the energy fails by tens of per cent
    kw = {"contact_law": "power", "power_law": (2.0e10, 1.5, 0.0)} if law == "power" else {}
    eng = ReferenceEngine("6208", eb.Scenario(Fr=3000.0, omega=0.0, dt=2e-6, ring_growth=False, **kw))
    st = eng.initial_state()
    xb = st["xb"].copy()
    xb[0, 0] += 1e-6
    xb[0, 2] += 0.5e-6
    grad, f = _gradient_check(eng, xb, st["xc"], 0, 1e-9)
    assert np.linalg.norm(f) > 100.0  # the ball carries the load
    np.testing.assert_allclose(-grad, f, rtol=0, atol=1e-3 * np.linalg.norm(f))


def test_the_stored_energy_is_the_potential_of_a_pocket_contact():
    # the rigid cage turned until pocket 0's wall presses ball 0 by 2 um: the pocket's Hertz energy joins
    # the races' and the gradient still equals the force on the ball (races and pocket)
    eng = ReferenceEngine("6208", eb.Scenario(Fr=3000.0, omega=0.0, dt=2e-6, ring_growth=False, cage="rigid"))
    st = eng.initial_state()
    xc = st["xc"].copy()
    gap = eng.params[L.P_POCKET_GAP]
    xc[1, 0] += (gap + 2e-6) / eng.params[L.P_RP]  # the cage's angle: its pocket moves along the orbit
    f_free, e_free = _at_rest(eng, st["xb"], st["xc"])
    f_wall, e_wall = _at_rest(eng, st["xb"], xc)
    assert e_wall > e_free  # the pocket contact stores energy
    grad, f = _gradient_check(eng, st["xb"], xc, 0, 1e-9)
    assert np.linalg.norm(f - f_free[0]) > 1.0  # the pocket pushes the ball
    np.testing.assert_allclose(-grad, f, rtol=0, atol=1e-3 * np.linalg.norm(f))


def test_the_balance_counts_the_stored_energy():
    # 1 J released from the contacts over 1 s into 1 J of kinetic energy with no drive but 1 W, no losses:
    # closed only when the stored energy's change is counted
    b = energy_balance(1.0, 1.0, None, 0.0, 0.0, 2.0, stored_change=-1.0)
    assert b["energy_residual"] == pytest.approx(0.0) and b["contact_energy_change"] == -1.0
    assert energy_balance(1.0, 1.0, None, 0.0, 0.0, 2.0)["energy_residual"] == pytest.approx(-1.0)
    c = energy_check(1.0, {"a": 0.0}, 2.0, 1.0, contact_energy_change=-1.0)
    assert c["passed"] and c["contact_energy_rate"] == -1.0
    assert "contact_energy_change" in c["statement"]
    assert energy_check(1.0, {"a": 0.0}, 2.0, 1.0)["passed"] is False  # not recorded: left out, and it fails


def test_the_losses_by_component_are_the_engine_works():
    # the 6208 with its rigid cage (pocket impacts between samples): each power_loss component is the engine's
    # work of that loss over the window, so they sum to the recorded dissipation to round-off and the energy
    # check sees the residual of the engine's own balance; a record without the works falls back to the means
    # of the samples (a record of an older run), which miss the impacts between them
    import copy

    from exudyn_bearing.model.layout import GLOBAL_FIELDS

    run = eb.simulate("6208", eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.02, cage="rigid", dt=2e-6),
                      progress=False)
    s = run.summary()
    comp = s["power_loss"]
    assert set(comp) >= {"contact_traction_inner", "contact_traction_outer", "contact_damping", "cage_pocket",
                         "cage_land"}
    assert sum(comp.values()) == pytest.approx(s["dissipation"], rel=1e-9)
    assert abs(s["energy_check"]["split_error"]) < 1e-9
    old = copy.copy(run)
    old.data = dict(run.data)
    old.data["glob"] = run.data["glob"][:, :GLOBAL_FIELDS.index("friction_power_inner")]
    sampled = old.summary()["power_loss"]
    assert set(sampled) == set(comp)
    assert sampled["cage_land"] == pytest.approx(comp["cage_land"], rel=0.05)  # the smooth land: close
    assert sampled["cage_pocket"] != comp["cage_pocket"]
