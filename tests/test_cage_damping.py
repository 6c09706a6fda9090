"""The implicit (backward-Euler) damping of the cage contacts, ``Scenario(cage_damping="implicit")``
(docs/theory/dynamics.md#implicit-cage-damping): the coefficient is backward Euler of the contact's own
damping, its velocity-Verlet step limit is where the amplification matrix turns unstable, the estimate and
the refusals follow it, and a start-up at a step where the explicit damping is beyond its limit keeps the
loads, speeds and energy balance of a resolved run (validation/studies/cage_step_checks.py measures the table)."""
import math
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.data import InputError
from exudyn_bearing.model.layout import GLOBAL_FIELDS
from exudyn_bearing.model.stability import explicit_step_factor, stable_step, step_warning
from exudyn_bearing.physics.damping import implicit_damping

#: a short start-up from rest of the README's main job (6208, F_r = 3000 N, 0 -> 500 rad/s), with the implicit
#: tangential spring (the explicit one limits at 6.3 us)
START = eb.Scenario(Fr=3000.0, omega=500.0, t_ramp_up=0.02, t_steady=0.02, t_end=0.04, initial="rest",
                    sample_dt=1e-4, tangential="implicit")


@pytest.mark.parametrize("c, m, dt", [(10.0, 2.0, 0.1), (3e3, 2.4e-3, 5e-6), (1e-3, 8e-3, 1e-6)])
def test_implicit_damping_is_one_backward_euler_step_of_the_damper(c, m, dt):
    # m u' = -c u over dt, backward Euler: u1 = u0 / (1 + c dt / m); the coefficient applied to u0 gives u1
    u0 = 0.37
    u1 = u0 / (1.0 + c * dt / m)
    assert u0 - dt * implicit_damping(c, m, dt) * u0 / m == pytest.approx(u1, rel=1e-12)
    assert implicit_damping(c, m, dt) < min(c, m / dt)
    assert implicit_damping(c, m, 0.0) == c  # bit for bit: the explicit damping


@pytest.mark.parametrize("zeta", [0.5, 1.0, 2.0])
def test_verlet_factor_with_implicit_damping_is_where_the_amplification_matrix_turns_unstable(zeta):
    # velocity Verlet as the kernels do it (damping at the half-step velocity) on x'' = -x - 2 zeta x',
    # the damping coefficient taken implicit over the step: 2 zeta / (1 + 2 zeta h)
    def radius(h):
        c = 2.0 * zeta / (1.0 + 2.0 * zeta * h)
        m = np.zeros((3, 3))
        for i, (x, v, f) in enumerate(np.eye(3)):  # state (x, v, force)
            vh = v + 0.5 * h * f
            x1 = x + h * vh
            f1 = -x1 - c * vh
            m[:, i] = (x1, vh + 0.5 * h * f1, f1)
        return max(abs(np.linalg.eigvals(m)))

    f = explicit_step_factor(zeta, "verlet", "implicit")
    assert radius(0.999 * f) <= 1.0 + 1e-9 < radius(1.01 * f)
    assert f > explicit_step_factor(zeta, "verlet")
    if zeta == 1.0:
        assert f == pytest.approx(1.5754, abs=1e-4)   # the figure docs/theory/dynamics.md quotes


def test_the_implicit_damping_is_refused_where_it_is_not_defined():
    with pytest.raises(InputError, match="^cage_damping: must be"):
        eb.Scenario(Fr=3000.0, omega=500.0, cage_damping="backward")
    with pytest.raises(InputError, match="^cage_damping: 'implicit' .* integrator='verlet'"):
        eb.Scenario(Fr=3000.0, omega=500.0, cage_damping="implicit", integrator="rk4", friction="regularized")
    with pytest.raises(InputError, match="^damping"):
        explicit_step_factor(1.0, "rk4", "implicit")
    from exudyn_bearing.solvers.element.userfunctions import solver_error

    err = solver_error("bodies", "RK44", 5e-6, 1e-5, "implicit")
    assert isinstance(err, InputError) and str(err).startswith("cageDamping:")
    assert solver_error("bodies", "VelocityVerlet", 5e-6, 1e-5, "implicit") is None
    assert solver_error("fast", "RK44", 5e-6, 1e-5, "implicit") is None   # the fast mode's balls: Verlet sub-steps


def test_the_element_passes_its_option_to_the_scene():
    from exudyn_bearing.solvers.element.element import element_scenario

    assert element_scenario("6208", cageDamping="implicit", stepSize=5e-6).cage_damping == "implicit"
    assert element_scenario("6208").cage_damping == "explicit"
    with pytest.raises(InputError, match="^cageDamping"):
        element_scenario("6208", cageDamping="no")


def test_the_estimate_lifts_only_the_cage_limit_by_the_factor_ratio():
    b = eb.catalog["6208"]
    ex, im = stable_step(b, START.replace(dt=2e-6)), stable_step(b, START.replace(dt=2e-6, cage_damping="implicit"))
    ratio = explicit_step_factor(1.0, "verlet", "implicit") / explicit_step_factor(1.0, "verlet")
    assert im.cage == pytest.approx(ex.cage * ratio, rel=1e-12) and ratio == pytest.approx(1.90, abs=0.01)
    assert (im.normal, im.tangential, im.friction) == (ex.normal, ex.tangential, ex.friction)
    assert ex.limited_by == "cage" and im.dt > 1.5 * ex.dt
    # 7 us: beyond the explicit cage limit (the warning suggests the option), within the implicit one
    text = step_warning("dt = 7e-06 s", 7e-6, ex)
    assert "ball / cage-ball" in text and "cage_damping='implicit'" in text
    assert step_warning("dt = 7e-06 s", 7e-6, im) is None
    # above the implicit cage limit a run may blow up at once (CAGE_BLOW_UP_RATIO_IMPLICIT = 1)
    assert im.limited_by == "cage" and 1.05 * im.dt < 0.85 * im.normal
    text = step_warning("dt", 1.05 * im.dt, im)
    assert "may blow up (cage contacts" in text and "cage_damping='implicit' lifts" not in text


def _start_up(dt, cage_damping):
    with warnings.catch_warnings():
        warnings.simplefilter("error", eb.StepSizeWarning)
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        return eb.simulate("6208", START.replace(dt=dt, cage_damping=cage_damping))


@pytest.fixture(scope="module")
def resolved():
    return _start_up(2e-6, "explicit")


@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")  # both summaries on the same short run
def test_a_start_up_at_7_us_with_implicit_cage_damping_keeps_the_resolved_loads(resolved):
    # 7 us is 1.8 times the explicit cage estimate of this start-up (3.9 us): with the implicit damping it
    # runs without a step warning (the loads it reached are checked too: the warning would be an error here)
    # and keeps the resolved run's cage loads, ball loads and speeds
    run = _start_up(7e-6, "implicit")
    a, b = resolved.summary(), run.summary()
    assert b["q_max_inner"] == pytest.approx(a["q_max_inner"], rel=5e-3)
    assert b["cage_speed"] == pytest.approx(a["cage_speed"], rel=1e-3)
    p_a, p_b = (np.percentile(r.data["cage_load"], 99.9) for r in (resolved, run))
    assert p_a > 10.0   # the start-up loads the cage (tens of N)
    assert p_b == pytest.approx(p_a, rel=0.15)


def test_the_implicit_damping_dissipates_what_it_takes(resolved):
    # the engine counts the applied damping force's power as dissipation, so the drive work of the whole
    # start-up = dissipated work + kinetic energy of the balls and cage balls + the elastic energy stored in
    # the contacts, as with the explicit damping, at each of the run's last 11 samples (1 ms): a sample that
    # falls into a cage impact holds part of the energy in the contact (docs/theory/dynamics.md, "Losses and
    # the energy balance")
    col = {k: GLOBAL_FIELDS.index(k) for k in ("drive_work", "dissipated_work", "kinetic_energy", "contact_energy")}
    for run in (resolved, _start_up(7e-6, "implicit")):
        g = run.data["glob"][-11:] - run.data["glob"][0]
        drive = g[:, col["drive_work"]]
        assert drive.min() > 0.0
        rel = (drive - g[:, col["dissipated_work"]] - g[:, col["kinetic_energy"]] - g[:, col["contact_energy"]]) / drive
        assert np.abs(rel).max() < 0.01


def _evaluate_with_cage_ball(xc_row):
    """The kernel's runaway measure on the 6208's analytic state with cage ball 0 moved to ``xc_row``."""
    from exudyn_bearing.model import layout as L
    from exudyn_bearing.model.contact import scene_loss_path, scene_paths
    from exudyn_bearing.model.motion import ring_poses
    from exudyn_bearing.solvers.reference.engine import ReferenceEngine
    from exudyn_bearing.solvers.reference.integrators import evaluate

    eng = ReferenceEngine("6208", eb.Scenario(Fr=3000.0, omega=500.0, dt=2e-6))
    st = eng.initial_state()
    z = eng.bearing.n_balls
    xc = st["xc"].copy()
    xc[0] = xc_row(xc[0], eng.bearing)
    return evaluate(0.0, eng.params, eng.table, st["xb"].copy(), st["vb"].copy(), st["wb"].copy(), xc,
                    st["vc"].copy(), st["ring"].copy(), ring_poses(), st["hist"].copy(), np.zeros((z, 2, L.HZ_N)),
                    np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((2, 6)), np.zeros(3),
                    np.zeros(L.NGLOBAL), np.zeros((z, 2, L.NDIAG)), np.zeros((z, 2)), False,
                    *scene_paths(eng.params), scene_loss_path(eng.params))


def test_a_runaway_or_non_finite_cage_ball_stops_the_engines():
    # a cage ball that leaves its guide torus far beyond the clearance (10 % of its radius into the guide) or
    # becomes non-finite stops the engines like a ball (the 7208 at 1.5 us with implicit cage damping ran on
    # with a cage ball gone to infinity: cage speed NaN in a result); in place the measure stays the balls'
    normal = _evaluate_with_cage_ball(lambda x, b: x)
    assert 0.0 < normal < 0.01
    clearance = eb.Scenario(Fr=3000.0, omega=500.0).guide_clearance
    deep = _evaluate_with_cage_ball(
        lambda x, b: x * (1.0 + (clearance + 0.1 * b.cage_ball_radius) / np.linalg.norm(x[:2])))
    assert deep == pytest.approx(0.1, rel=0.05)   # its overlap / R_z, beyond the runaway limit 0.05
    assert math.isnan(_evaluate_with_cage_ball(lambda x, b: np.full(3, np.nan)))


@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_the_exudyn_element_damps_the_cage_contacts_like_the_reference_engine():
    # the element's body mode (VelocityVerlet) with cageDamping="implicit" at 7 us: the same kernel with the
    # Exudyn step as dt, so the start-up keeps the reference engine's loads and speeds at that step
    ref = _start_up(7e-6, "implicit")
    with warnings.catch_warnings():
        warnings.simplefilter("error", eb.StepSizeWarning)
        ex = eb.simulate("6208", START.replace(dt=7e-6, cage_damping="implicit"), engine="exudyn")
    a, b = ref.summary(), ex.summary()
    assert b["q_max_inner"] == pytest.approx(a["q_max_inner"], rel=5e-3)
    assert b["cage_speed"] == pytest.approx(a["cage_speed"], rel=1e-3)
    p_a, p_b = (np.percentile(r.data["cage_load"], 99.9) for r in (ref, ex))
    assert p_b == pytest.approx(p_a, rel=0.15)


def test_the_kernel_applies_and_counts_the_implicit_damping_on_a_cage_contact():
    # cage ball 0 placed 2 um into ball 0 and approaching it at 0.05 m/s: the kernel's contact force is
    # K delta^1.5 + C' u with C' = C / (1 + C dt / m) (C = 2 sqrt(m 1.5 K sqrt(delta)), m the pair's reduced
    # mass), and the damping power it counts changes by (C - C') u^2 from the explicit damping
    from exudyn_bearing.model import layout as L
    from exudyn_bearing.model.contact import scene_loss_path, scene_paths
    from exudyn_bearing.model.motion import ring_poses
    from exudyn_bearing.solvers.reference.engine import ReferenceEngine
    from exudyn_bearing.solvers.reference.integrators import evaluate

    dt, delta, u = 5e-6, 2e-6, 0.05
    out = {}
    for damping in ("explicit", "implicit"):
        eng = ReferenceEngine("6208", eb.Scenario(Fr=3000.0, omega=500.0, dt=dt, cage_damping=damping))
        st = eng.initial_state()
        p = eng.params
        z = eng.bearing.n_balls
        xb, xc, vb, vc = st["xb"].copy(), st["xc"].copy(), st["vb"].copy(), st["vc"].copy()
        n = (xb[0] - xc[0]) / np.linalg.norm(xb[0] - xc[0])      # from the cage ball to the ball
        xc[0] = xb[0] - n * (p[L.P_RB] + p[L.P_RZ] - delta)
        vc[0] = vb[0] + u * n                                     # closing: d(delta)/dt = u
        glob, cage_load = np.zeros(L.NGLOBAL), np.zeros((z, 2))
        evaluate(0.0, p, eng.table, xb, vb, st["wb"].copy(), xc, vc, st["ring"].copy(), ring_poses(),
                 st["hist"].copy(), np.zeros((z, 2, L.HZ_N)), np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3)),
                 np.zeros((2, 6)), np.zeros(3), glob, np.zeros((z, 2, L.NDIAG)), cage_load, True,
                 *scene_paths(p), scene_loss_path(p))
        out[damping] = (cage_load[0, 0], glob[L.GLOBAL_FIELDS.index("damping_power")])
        k, m = p[L.P_K_BZ], p[L.P_MB] * p[L.P_MZ] / (p[L.P_MB] + p[L.P_MZ])
    c = 2.0 * math.sqrt(m * 1.5 * k * math.sqrt(delta))
    c_impl = c / (1.0 + c * dt / m)
    assert c_impl < 0.9 * c   # the test point is where the two differ
    f_el = k * delta ** 1.5
    assert out["explicit"][0] == pytest.approx(f_el + c * u, rel=1e-9)
    assert out["implicit"][0] == pytest.approx(f_el + c_impl * u, rel=1e-9)
    assert out["explicit"][1] - out["implicit"][1] == pytest.approx((c - c_impl) * u * u, rel=1e-6)


def test_a_non_finite_cage_ball_stops_the_reference_engine(monkeypatch):
    # the engine's run on a state whose cage ball 0 is NaN ends with an error naming dt, not with a result
    from exudyn_bearing.solvers.reference.engine import ReferenceEngine

    eng = ReferenceEngine("6208", eb.Scenario(Fr=3000.0, omega=500.0, dt=5e-6, t_end=1e-3))
    st = eng.initial_state()
    st["xc"][0] = np.nan
    monkeypatch.setattr(eng, "initial_state", lambda: st)
    with pytest.raises(eb.SimulationError, match=r"^dt: the bearing state became"):
        eng.run()


def test_the_command_line_and_the_scene_without_cage():
    from exudyn_bearing.cli import _parser
    from exudyn_bearing.cli.simulate import scenario_from_args

    argv = ["simulate", "6208", "--Fr", "3000", "--omega", "500", "--dt", "7e-6", "--cage-damping", "implicit"]
    assert scenario_from_args(_parser(argv).parse_args(argv)).cage_damping == "implicit"
    with pytest.raises(InputError, match="^cage_damping: 'implicit' damps .* no cage"):
        eb.Scenario(Fr=3000.0, omega=500.0, cage=False, cage_damping="implicit")


def test_the_element_refuses_a_solver_step_other_than_the_damping_step():
    # cageDamping="implicit" takes the damping over stepSize: a solver stepping otherwise (here 4 instead of
    # 5 us) is refused at the run's start; the element's own SimulationSettings step by stepSize
    from exudyn_bearing.solvers.element.engine import ExudynEngine, solve_dynamic

    eng = ExudynEngine("6208", START.replace(dt=5e-6, cage_damping="implicit", t_end=2e-4))
    with pytest.raises(InputError, match=r"^cageDamping: 'implicit' .* stepSize = 5e-06 s, but the balls step"):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            solve_dynamic(eng.mbs, eng.element.SimulationSettings(2e-4, stepSize=4e-6))
