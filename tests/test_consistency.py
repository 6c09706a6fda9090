"""Consistency of the solvers (validation/consistency/consistency_matrix.py has the whole
matrix): static = quasi-static at zero speed, the quasi-static traction
equilibrium converges where race control does and conserves energy, balls
without an equilibrium of their own are carried at the cage speed, and the
reference engine started there stays there, with the Exudyn element on it."""
import math
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.data import load_bearing
from exudyn_bearing.model.layout import D_LOAD, GLOBAL_FIELDS
from exudyn_bearing.model.stability import stable_step
from exudyn_bearing.physics.load_distribution import static_equilibrium
from exudyn_bearing.solvers.quasistatic import kinematics as km

HELD = {"tilt_x": 0.0, "tilt_y": 0.0}
ACBB_OIL = dict(lubricant="MIL-L-23699_492K", traction="ehl_mil_l_23699_492K")


@pytest.mark.parametrize("bearing, fr, fa", [("6208", 3000.0, 0.0), ("7208", 3000.0, 3000.0), ("6205", 1000.0, 0.0)])
def test_static_is_the_quasistatic_solution_at_zero_speed(bearing, fr, fa):
    # two implementations of Jones' ball / ring balance without speed terms (the classical discrete load
    # distribution and the 5-DOF quasi-static solver with the tilt held): the same loads, angles and ring
    # displacement; both solve to a relative residual of 1e-10, so they agree far below 1e-8
    s = static_equilibrium(load_bearing(bearing), fr, fa)
    q = eb.solve_quasistatic(bearing, Fr=fr, Fa=fa, omega=0.0, fixed=HELD, stiffness=False)
    assert np.abs(q.balls["q_inner"] - s.q).max() < 1e-8 * s.q.max()
    assert np.abs(q.balls["q_outer"] - s.q).max() < 1e-8 * s.q.max()
    loaded = s.q > 0.0
    assert np.abs(q.balls["alpha_inner"] - s.contact_angle)[loaded].max() < 1e-8
    assert np.abs(q.displacement[:3] - s.displacement).max() < 1e-8 * np.abs(s.displacement).max()


def _equilibrium_power_balance(sol):
    """(drive power, dissipation) of the balls in traction equilibrium (inner ring driven, outer fixed)."""
    b = sol.balls
    eq = np.asarray(b["control_used"]) == "equilibrium"
    drive = float(np.sum(b["drive_torque_inner_ball"][eq])) * sol.omega
    diss = float(np.sum(b["dissipation_inner_ball"][eq] + b["dissipation_outer_ball"][eq]))
    return eq, drive, diss


@pytest.mark.filterwarnings("ignore::exudyn_bearing.BallInertiaWarning")  # expected: lightly loaded balls
@pytest.mark.parametrize("omega", [100.0, 1700.0, 6000.0])
def test_traction_equilibrium_converges_on_the_radial_6208(omega):
    # every ball that touches both races reaches its traction equilibrium; those with a contact without
    # load have none (nothing drives them) and are carried at the cage speed. The balls in equilibrium take
    # no net power: their drive power equals their dissipation (the root solver's residual is 1e-8 of the
    # load in the scaled equations: 1e-6 leaves a margin of 100)
    sol = eb.solve_quasistatic("6208", Fr=3000.0, omega=omega, control="equilibrium", stiffness=False)
    b = sol.balls
    both = (b["q_inner"] > 0.0) & (b["q_outer"] > 0.0)
    eq, drive, diss = _equilibrium_power_balance(sol)
    assert np.array_equal(eq, both) and eq.sum() >= 3
    assert diss > 0.0
    assert abs(drive - diss) < 1e-6 * diss


@pytest.mark.parametrize("case", [
    dict(bearing="6208", Fa=3000.0, omega=500.0, n_strips=8, n_across=1),
    dict(bearing="7208", Fr=3000.0, Fa=3000.0, omega=500.0),
    dict(bearing="ACBB-120", Fa=22240.0, omega=25000.0 * math.pi / 30.0, **ACBB_OIL),
], ids=["6208-thrust-8x1", "7208-combined", "ACBB-120-own-oil"])
@pytest.mark.filterwarnings("ignore::exudyn_bearing.BallInertiaWarning")  # expected: lightly loaded balls
def test_traction_equilibrium_converges_and_conserves_energy(case):
    # every ball of these cases is loaded at both races and reaches its equilibrium; the bearing's drive
    # power is then its dissipation (round-off and the 1e-8 residual of the scaled equations)
    kw = dict(case)
    bearing = kw.pop("bearing")
    sol = eb.solve_quasistatic(bearing, control="equilibrium", fixed=HELD, stiffness=False, **kw)
    assert all(c == "equilibrium" for c in sol.balls["control_used"])
    assert all(c["converged"] and c["held_fraction"] == 1.0 for c in sol.minimum_checks)
    assert sol.dissipation_total > 0.0
    assert abs(sol.energy_residual) < 1e-6


def test_a_ball_without_equilibrium_is_carried_at_the_cage_speed():
    # 6208 at 1700 rad/s: the balls of the unloaded half press on the outer race only (centrifugal force);
    # they orbit at the mean orbital speed of the balls in equilibrium and roll on the outer race: no slip
    # at its contact centre and no spin about its normal (cage_kinematics)
    sol = eb.solve_quasistatic("6208", Fr=3000.0, omega=1700.0, control="equilibrium", stiffness=False)
    b = sol.balls
    cage = np.asarray(b["control_used"]) == "cage"
    assert cage.any() and np.all(b["q_inner"][cage] == 0.0) and np.all(b["q_outer"][cage] > 0.0)
    mean = np.mean(b["orbital_speed"][~cage])
    assert b["orbital_speed"][cage] == pytest.approx(np.full(cage.sum(), mean), rel=1e-12)
    for j in np.flatnonzero(cage):
        c = km.ball_contacts(sol.kinematics[j], sol.contact_geometry[j], sol.traction_model, 4, 1)
        u = c[0, 3]
        assert abs(c[0, 0]) < 1e-9 * u       # v0 at the outer contact centre
        assert abs(c[0, 4]) < 1e-9 * sol.omega  # spin about the outer normal


def _run(engine, t_end=0.003):
    sc = eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0, t_end=t_end, cage=False, traction_level="ellipse",
                     ring_growth=True, initial="quasistatic", control="equilibrium", sample_dt=t_end / 6)
    sc = sc.replace(dt=stable_step(load_bearing("7208"), sc).dt)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return eb.simulate("7208", sc, engine=engine).data


@pytest.fixture(scope="module")
def runs_7208():
    return {e: _run(e) for e in ("reference", "exudyn")}


def test_both_engines_agree_on_the_7208(runs_7208):
    # the same scene, the same physics kernels: ring pose after 3 ms, mean dissipation over the run and the
    # most loaded ball's loads within 1e-3 (the matrix's target; the lightly loaded balls of this radially
    # loaded cageless bearing, whose loads change fastest along their orbit, are the matrix's to show)
    ref, exu = runs_7208["reference"], runs_7208["exudyn"]
    p = GLOBAL_FIELDS.index("friction_power")
    assert np.abs(exu["ring"][-1, :3] - ref["ring"][-1, :3]).max() < 1e-3 * np.abs(ref["ring"][-1, :3]).max()
    assert np.mean(exu["glob"][:, p]) == pytest.approx(np.mean(ref["glob"][:, p]), rel=1e-3)
    j = int(np.argmax(ref["diag"][-1, :, 0, D_LOAD]))
    assert exu["diag"][-1, j, :, D_LOAD] == pytest.approx(ref["diag"][-1, j, :, D_LOAD], rel=1e-3)


def test_the_exudyn_engine_hands_every_scenario_field_to_the_element():
    # simulate(engine="exudyn") builds the element from the Scenario: a field it left out would run with the
    # element's default, silently another model than the reference engine's (cage_damping was the last one
    # added). Built from a scene with the switches away from their defaults, the element's own Scenario must
    # equal it in every field but t_end (the Exudyn solve sets the run's end), traction (None: the bearing's
    # model, which the element fills in) and the speed protocol (the element drives the ring with the
    # scenario's speed function: checked below)
    import dataclasses

    from exudyn_bearing.solvers.element.engine import ExudynEngine

    s = eb.Scenario(Fr=2000.0, Fa=100.0, omega=400.0, dt=4e-6, t_end=0.01, sample_dt=2e-4, cage_damping="implicit",
                    tangential="implicit", tangential_stiffness_ratio=0.8, guide_clearance=40e-6, film="mk",
                    hertz="hamrock_brewe", ring_growth=False, rolling_resistance=True, ball_drag=True,
                    oil_volume_fraction=0.02, hysteresis_loss_factor=0.01, t_ramp_up=0.002)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        element = ExudynEngine("6208", s).element
    # the default cage ("auto") is resolved for the bearing by both engines alike (model.scenario.resolve_cage)
    from exudyn_bearing.model.scenario import resolve_cage

    assert element.scenario.cage == resolve_cage(s, eb.catalog["6208"]).cage == "torus"
    s = resolve_cage(s, eb.catalog["6208"])
    differ = {f.name for f in dataclasses.fields(s) if getattr(s, f.name) != getattr(element.scenario, f.name)}
    assert differ <= {"t_end", "traction", "t_ramp_up"}
    t = np.linspace(0.0, 0.004, 9)
    assert [element.speed[0](x) for x in t] == pytest.approx([s.omega_at(x) for x in t], abs=1e-12)
    # and every field is read where the engine builds the element (the scene above leaves some at their
    # defaults, where a dropped field would not show): the protocol's three through s.speed_function()
    import inspect

    from exudyn_bearing.solvers.element import engine as element_engine

    src = inspect.getsource(element_engine.ExudynEngine)
    unread = {f.name for f in dataclasses.fields(s) if f"s.{f.name}" not in src and f"scenario.{f.name}" not in src}
    # omega_outer: the Exudyn engine's outer ring is the ground, so it refuses a turning outer ring by name
    # (model.scenario.engine_speed_error; tests/test_outer_ring.py) rather than reading the field
    assert unread == {"t_ramp_up", "t_steady", "t_ramp_down", "omega_outer"} and "s.speed_function()" in src
    assert "engine_speed_error(" in src
