"""The bearing levels without ball DOFs (model="quasistatic" and "linear" of
CreateBallBearing): static equilibrium against solve_quasistatic, the
kinematic cage, the ball-pass periodicity of the quasi-static level, and
their input errors."""
import math

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")
from exudyn.itemInterface import MarkerBodyMass  # noqa: E402

import exudyn_bearing as eb  # noqa: E402

FR, FA = 3000.0, 1000.0
SPEEDS = [0.0, 200.0]  # a short coefficient table keeps the set-up quick


def _levels_checks():
    """validation/consistency/levels_checks.py as a module (its shaft serves the tests and the script)."""
    import importlib.util
    from pathlib import Path

    path = Path(__file__).resolve().parents[1] / "validation" / "consistency" / "levels_checks.py"
    spec = importlib.util.spec_from_file_location("levels_checks", path)
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


_CHECKS = _levels_checks()


def shaft(load=(FR, 0.0, FA), omega=0.0, moment=None):
    """A 2.5 kg shaft (Rxyz node) at the origin, the load (and ``moment``) on it, an outer-ring marker on ground
    and a pure damper to ground (no force at rest: it settles the shaft without moving its equilibrium):
    levels_checks.shaft's."""
    return _CHECKS.shaft(load, omega=omega, moment=moment)[:5]


@pytest.mark.parametrize("model, speeds", [("quasistatic", SPEEDS), ("linear", SPEEDS), ("linear", [0.0])])
def test_static_equilibrium_is_the_quasistatic_solution(model, speeds):
    # the shaft settles where solve_quasistatic puts the inner ring under (Fr, Fa); 0.5 % is the issue's
    # tolerance (the remaining motion after 0.03 s with the damper is far below it)
    sc, mbs, node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, FA), coefficientSpeeds=speeds)
    mbs.Assemble()
    ss = br.SimulationSettings(0.03)
    mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    got = mbs.GetNodeOutput(node, exu.OutputVariableType.Position)
    ref = eb.solve_quasistatic("6208", Fr=FR, Fa=FA, ring_growth=False, fixed={}).displacement
    assert got[0] == pytest.approx(ref[0], rel=5e-3)
    assert got[2] == pytest.approx(ref[2], rel=5e-3)
    assert abs(got[1]) < 5e-3 * ref[0]


@pytest.mark.parametrize("solver, step", [("RK44", 2e-5), ("VelocityVerlet", 2e-5), ("TrapezoidalIndex2", 1e-4)])
def test_quasistatic_level_runs_other_solvers(solver, step):
    # the same equilibrium under two explicit solvers and Exudyn's other implicit one
    sc, mbs, node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="quasistatic", initialLoad=(FR, FA),
                              coefficientSpeeds=SPEEDS, hertzModel="hamrock_brewe")
    mbs.Assemble()
    ss = br.SimulationSettings(0.02, stepSize=step, solverType=solver)
    mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    ref = eb.solve_quasistatic("6208", Fr=FR, Fa=FA, ring_growth=False, hertz_method="hamrock_brewe",
                                fixed={}).displacement
    got = br.samples()["displacement"][-1]
    assert got[0] == pytest.approx(ref[0], rel=5e-3)


def test_cage_speed_is_kinematic_and_ball_pass_periodic():
    # cage speed omega (1 - D cos(alpha)/d_m)/2 (Harris & Kotzalas, pure rolling), written from the catalogue
    # dimensions; the balls' force on the fixed ring pose repeats after one ball pitch 2 pi/Z of the cage and
    # varies within it (positive clearance: the loaded zone changes as balls pass)
    b = eb.catalog["6208"].with_clearance(20e-6)
    sc, mbs, node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, b, m_b, m_g, model="quasistatic", initialLoad=(FR, 0.0), coefficientSpeeds=[0.0])
    w = 300.0
    assert br.cageRatio * w == pytest.approx(0.5 * w * (1.0 - b.ball_radius / b.pitch_radius), rel=1e-12)
    br._restart(0.0)
    d = br.initialRingDisplacement
    fx = []
    z = b.n_balls
    for k in range(2 * 8 + 1):
        spin = (2.0 * math.pi / z) / br.cageRatio * k / 8.0  # ring angle that turns the cage by k/8 of a pitch
        br._state[:] = [0.0, spin, 0.0]  # unwrapped spin angle set directly; r[2] = 0 adds nothing
        br._evaluate(d[:3].copy(), np.array([d[3], d[4], 0.0]), np.zeros(3), np.array([0.0, 0.0, w]))
        fx.append(br._force[0])
    fx = np.array(fx)
    assert fx[8] == pytest.approx(fx[0], rel=1e-9) and fx[16] == pytest.approx(fx[0], rel=1e-9)
    assert np.ptp(fx) > 1e-3 * FR


def test_errors_name_the_parameter_and_limit():
    sc, mbs, node, m_b, m_g = shaft()
    with pytest.raises(eb.InputError, match=r"^initialLoad: .*4.2 GPa"):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="quasistatic", initialLoad=(1e6, 0.0))
    with pytest.raises(eb.InputError, match="^model: "):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="rollers")
    with pytest.raises(eb.InputError, match="^stepSize: not an option of model='linear'"):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", stepSize=1e-6)
    m_mass = mbs.AddMarker(MarkerBodyMass(bodyNumber=1))
    with pytest.raises(eb.InputError, match="^markerInnerRing: "):
        eb.CreateBallBearing(mbs, "6208", m_mass, m_g, model="linear", initialLoad=(FR, 0.0))


def test_runtime_load_beyond_the_elastic_limit_stops_the_run():
    # a tilt of 0.02 rad presses the balls far beyond the load at which the Hertz pressure reaches 4.2 GPa
    sc, mbs, node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="quasistatic", coefficientSpeeds=[0.0])
    br._restart(0.0)
    with pytest.raises(eb.SimulationError, match=r"^load: .*4.2 GPa"):
        br._evaluate(np.zeros(3), np.array([0.02, 0.0, 0.0]), np.zeros(3), np.zeros(3))


@pytest.mark.parametrize("model", ["quasistatic", "linear"])
def test_load_along_minus_y_with_load_angle(model):
    # the same radial load along -y (loadAngle = -pi/2 turns the linear level's table; the quasi-static level's
    # ball 0 is put under the load, as solve_quasistatic's): the shaft settles at solve_quasistatic's radial
    # displacement along -y, within the 0.5 %
    _sc, mbs, node, m_b, m_g = shaft(load=(0.0, -FR, 0.0))
    extra = {"cageAngle": -0.5 * math.pi} if model == "quasistatic" else {}
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, 0.0), loadAngle=-0.5 * math.pi,
                              coefficientSpeeds=SPEEDS, **extra)
    mbs.Assemble()
    ss = br.SimulationSettings(0.03)
    mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    got = mbs.GetNodeOutput(node, exu.OutputVariableType.Position)
    ref = eb.solve_quasistatic("6208", Fr=FR, ring_growth=False, fixed={}).displacement[0]
    assert -got[1] == pytest.approx(ref, rel=5e-3)
    assert abs(got[0]) < 5e-3 * ref


def _level_and_poses(bearing, load, omega, n=40, seed=3):
    """A quasi-static level at (load, omega) and n inner-ring poses scattered about its operating pose
    (5 % of each coordinate plus 0.1 um / 1 urad), each with a spin angle."""
    _sc, mbs, _node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, bearing, m_b, m_g, model="quasistatic", initialLoad=(load, 0.0),
                              initialOmega=omega, coefficientSpeeds=[0.0, 2.0 * omega + 1.0])
    br._restart(0.0)
    rng = np.random.default_rng(seed)
    d0 = br.initialRingDisplacement
    poses = [d0 * (1.0 + 0.05 * rng.standard_normal(5)) + rng.standard_normal(5) * [1e-7, 1e-7, 1e-7, 1e-6, 1e-6]
             for _ in range(n)]
    return br, [(list(d[:3]), [d[3], d[4], 0.013 * k], [0.0] * 3, [0.0, 0.0, omega]) for k, d in enumerate(poses)]


@pytest.mark.parametrize("clearance, load, omega", [(0.0, FR, 500.0), (20e-6, 500.0, 500.0), (20e-6, 500.0, 3000.0)])
def test_level_forces_are_the_quasistatic_solvers(clearance, load, omega):
    # the level (tabulated exact Hertz constants, warm-started balls) against the quasi-static solver's ring_forces
    # (direct exact Hertz, cold starts) for the same balls: the table's error, <= 1e-7 on k, F and E
    # (physics.hertz.exact_table), enters K = pi k E' sqrt(2 E R / (9 F^3)) at most 1e-7 (1 + 1/2 + 3/2) = 3e-7
    # and the forces through the ball equilibrium likewise; 1e-6 leaves a factor 3. Zero rates: no damping force.
    from exudyn_bearing.solvers.quasistatic.balls import B_NIR, B_NIZ, B_QI, ring_forces

    br, calls = _level_and_poses(eb.catalog["6208"].with_clearance(clearance), load, omega)
    for d, r, v, w in calls:
        br._evaluate(d, r, v, w)
        gen, _balls = ring_forces(br._pose, br._psi.copy(), br.geometry, br._m_w2.copy(), br._fto.copy(),
                                  br._fti.copy(), br._e_prime, br._method)
        scale = np.abs(gen[:3]).max()
        assert np.abs(br._force - gen).max() <= 1e-6 * scale
        # the largest loaded inner contact angle the level checks (element.level_forces ranks without atan2)
        loaded = br._balls[:, B_QI] > 0.0
        assert br._qmax[2] == np.abs(np.arctan2(-br._balls[loaded, B_NIZ], -br._balls[loaded, B_NIR])).max()


@pytest.mark.parametrize("clearance, load, omega", [(0.0, FR, 500.0), (20e-6, 500.0, 3000.0)])
def test_warm_started_balls_give_the_cold_started_forces(clearance, load, omega):
    # each ball's Newton starts from its last solution; at the same pose a cold start (warm starts cleared) gives
    # the same forces within Newton's tolerance: the ball residual stops at 1e-13 of the ball's forces, and 1e-9
    # of the ring force leaves four decades for the ball stiffness's conditioning
    br, calls = _level_and_poses(eb.catalog["6208"].with_clearance(clearance), load, omega)
    for d, r, v, w in calls:
        br._evaluate(d, r, v, w)
        warm = br._force.copy()
        assert br._start[:, 2].any()  # the balls were warm-started (kind recorded)
        br._start[:] = 0.0
        br._evaluate(d, r, v, w)  # the same spin angle again: the cage has not moved
        assert np.abs(br._force - warm).max() <= 1e-9 * np.abs(warm[:3]).max()


def _ball_scene(omega=500.0):
    """One 6208 ball's grooves at ``omega`` (grown rings), its m omega_c^2 and a gyroscopic traction at the outer
    race, the Hertz table: the arguments of balls._ball_equilibrium after the inner groove centre."""
    from exudyn_bearing.model.operating_geometry import operating_geometry
    from exudyn_bearing.physics import hertz

    b = eb.catalog["6208"]
    g = operating_geometry(b, omega, 0.0, True, 0.0, None)
    m_w2 = b.ball_mass * (0.4 * omega) ** 2
    return g, (g.rho_o, g.z_o, g.r_ci, g.r_co, g.r_b, m_w2, -0.3, 0.0,
               hertz.material_reduced_modulus(b.material), hertz.method_code("exact"), hertz.exact_table())


def _solve_ball(pir, piz, rest, start=None):
    from exudyn_bearing.solvers.quasistatic.balls import NB, _ball_equilibrium

    out = np.zeros(NB)
    _ball_equilibrium(pir, piz, *rest, out, np.zeros(0) if start is None else start)
    return out


def test_ball_warm_start_sensitivity_is_the_solutions_derivative():
    # the warm start's prediction dc/dp = A^-1 A_i (balls._ball_sensitivity) against central differences of
    # cold-started solutions, for a loaded ball with a contact angle: it leaves out the Hertz constants' change
    # with the contact angle, as the condensation does (damping.py: 2e-5 to 5e-4 of the largest entry with
    # contact angles, tests/test_stiffness.py); 2e-3 of the largest entry
    from exudyn_bearing.solvers.quasistatic.balls import B_CR, B_CZ, B_QI, WARM_START

    g, rest = _ball_scene()
    pir, piz = g.rho_i + 25e-6, g.z_i + 40e-6
    start = np.zeros(WARM_START)
    assert _solve_ball(pir, piz, rest, start)[B_QI] > 100.0  # loaded
    sens = start[5:9].reshape(2, 2)
    h = 1e-8
    fd = np.empty((2, 2))
    for k, (dr, dz) in enumerate(((h, 0.0), (0.0, h))):
        hi, lo = _solve_ball(pir + dr, piz + dz, rest), _solve_ball(pir - dr, piz - dz, rest)
        fd[:, k] = [(hi[B_CR] - lo[B_CR]) / (2 * h), (hi[B_CZ] - lo[B_CZ]) / (2 * h)]
    assert 0.2 < abs(fd[0, 0]) < 0.8  # the ball follows the ring by part of its move (stated scale of the check)
    assert np.abs(sens - fd).max() <= 2e-3 * np.abs(fd).max()


def test_free_ball_keeps_its_last_solution_where_a_cold_start_finds_it():
    # a ball outside the load zone (inner contact open, held by its centrifugal force at the outer race): the
    # warm start returns its last solution without a Newton iteration (balls._still_free) when the inner groove
    # centre moved but the contact stays open; a cold start at the new centre finds the same ball (centre, outer
    # load and normal within Newton's tolerance) and the same open inner contact's normal and gap
    from exudyn_bearing.solvers.quasistatic import balls as bl

    g, rest = _ball_scene()
    start = np.zeros(bl.WARM_START)
    out = np.zeros(bl.NB)
    bl._ball_equilibrium(g.rho_i - 10e-6, g.z_i, *rest, out, start)
    assert out[bl.B_QI] == 0.0 and out[bl.B_QO] > 0.0 and start[9] == 1.0  # free, converged on the residual
    first = out.copy()
    bl._ball_equilibrium(g.rho_i - 12e-6, g.z_i + 3e-6, *rest, out, start)  # the ring moved, the gap stays open
    for k in (bl.B_CR, bl.B_CZ, bl.B_QO):  # kept
        assert out[k] == first[k]
    assert start[3] == g.rho_i - 12e-6  # the warm start follows the groove centre
    cold = _solve_ball(g.rho_i - 12e-6, g.z_i + 3e-6, rest)
    assert cold[bl.B_QI] == 0.0
    for k in (bl.B_CR, bl.B_CZ):
        assert abs(out[k] - cold[k]) <= 1e-12 * g.r_b
    assert out[bl.B_QO] == pytest.approx(cold[bl.B_QO], rel=1e-9)
    for k in (bl.B_NIR, bl.B_NIZ, bl.B_NOR):
        assert abs(out[k] - cold[k]) <= 1e-9
    assert abs(out[bl.B_DI] - cold[bl.B_DI]) <= 1e-12 * g.r_b
    assert out[bl.B_DI] < 0.0


def test_tabulated_hertz_constant_is_the_direct_one():
    # the Hertz constant from physics.hertz.exact_table against the direct exact solution over R_y/R_x from 1 to
    # 1e4 (either orientation): the table's stated 1e-7 on k, F, E gives at most 3e-7 on K (as above)
    from exudyn_bearing.physics import hertz
    from exudyn_bearing.solvers.quasistatic.balls import _DIRECT, _hertz_constant

    table = hertz.exact_table()
    e_prime = hertz.material_reduced_modulus(eb.catalog["6208"].material)
    for ratio in np.geomspace(1.0, 9.9e3, 97):
        for r_x, r_y in ((1e-3, 1e-3 * ratio), (1e-3 * ratio, 1e-3)):
            direct = _hertz_constant(r_x, r_y, e_prime, hertz.EXACT, _DIRECT)
            assert direct == pytest.approx(hertz.hertz_stiffness(r_x, r_y, e_prime, "exact"), rel=1e-12)
            assert _hertz_constant(r_x, r_y, e_prime, hertz.EXACT, table) == pytest.approx(direct, rel=3e-7)


@pytest.mark.parametrize("model", ["quasistatic", "linear"])
def test_explicit_euler_is_refused_by_both_levels(model):
    # ExplicitEuler's amplification of an undamped oscillation x'' = -w^2 x is |1 + i w h| > 1 at every step h:
    # refused in SimulationSettings and, for settings made otherwise, at the run's first evaluation
    sc, mbs, node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, FA), coefficientSpeeds=SPEEDS)
    mbs.Assemble()
    with pytest.raises(eb.InputError, match="^solverType: ExplicitEuler .* GeneralizedAlpha"):
        br.SimulationSettings(0.05, solverType="ExplicitEuler")
    ss = br.SimulationSettings(1e-3)
    ss.timeIntegration.solverType = exu.DynamicSolverType.ExplicitEuler
    with pytest.raises(ValueError, match="InputError: solverType: ExplicitEuler"):  # Exudyn's ModelError
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    assert np.all(br._out == 0.0)  # refused before the first force was computed


def test_linear_level_stops_beyond_the_elastic_limit():
    # the trial's case: operating point 3000 N, 1e6 N applied. The limit is the radial load at which the elastic
    # contact model ends: the quasi-static level's own input check (model.load_range.check_load_range, each ball
    # at its contact angle) accepts 0.99 of it and refuses 1.01 of it (1 %: the limit is solved to 1e-6)
    from exudyn_bearing.model.load_range import check_load_range

    sc, mbs, node, m_b, m_g = shaft(load=(1e6, 0.0, 0.0))
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", initialLoad=(FR, 0.0), coefficientSpeeds=SPEEDS)
    check_load_range(br.bearing, 0.99 * br.forceLimit)
    with pytest.raises(eb.InputError, match="4.2 GPa"):
        check_load_range(br.bearing, 1.01 * br.forceLimit)
    mbs.Assemble()
    ss = br.SimulationSettings(0.01)
    with pytest.raises(ValueError, match="SimulationError: linear: .* left its validity; use model='quasistatic'"):
        mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    br._restart(0.0)
    with pytest.raises(eb.SimulationError, match="^linear: .* not finite"):
        br._evaluate([math.nan, 0.0, 0.0], [0.0] * 3, [0.0] * 3, [0.0] * 3)


def test_linear_level_has_no_ball_load_sensors():
    # the linear level knows no ball loads: no qMax sensors, NaN in its samples (not the operating point's values)
    sc, mbs, node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="linear", initialLoad=(FR, FA), coefficientSpeeds=SPEEDS)
    assert "qMaxInner" not in br.sensors and "qMaxOuter" not in br.sensors
    br._restart(0.0)
    br._user_function(mbs, 0.0, 0, list(br.initialRingDisplacement[:3]), [0.0] * 3, [0.0] * 3, [0.0] * 3, None, None,
                      np.eye(3), np.eye(3), None)
    assert math.isnan(br.samples()["q_max_inner"][0]) and math.isnan(br.samples()["q_max_outer"][0])


def test_cage_angle_must_be_finite():
    sc, mbs, node, m_b, m_g = shaft()
    with pytest.raises(eb.InputError, match="^cageAngle: "):
        eb.CreateBallBearing(mbs, "6208", m_b, m_g, model="quasistatic", cageAngle=math.nan, coefficientSpeeds=[0.0])


@pytest.mark.parametrize("model", ["quasistatic", "linear"])
def test_initial_coordinates_start_the_node_at_the_operating_point(model):
    # six coordinates, the displacement and tilts of initialRingDisplacement: the node set to them starts at the
    # quasi-static displacement under (Fr, Fa), which the shaft then keeps (its equilibrium) within 0.5 %
    sc, mbs, node, m_b, m_g = shaft()
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, FA), coefficientSpeeds=SPEEDS)
    q0 = br.initialCoordinates
    assert len(q0) == 6 and list(q0[:5]) == list(br.initialRingDisplacement) and q0[5] == 0.0
    mbs.SetNodeParameter(node, "initialCoordinates", list(q0))
    mbs.Assemble()
    ss = br.SimulationSettings(2e-3)
    mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    ref = eb.solve_quasistatic("6208", Fr=FR, Fa=FA, ring_growth=False, fixed={}).displacement
    got = br.samples()["displacement"]
    assert got[0][0] == pytest.approx(ref[0], rel=5e-3) and got[-1][0] == pytest.approx(ref[0], rel=5e-3)


def test_ball_element_initial_coordinates_have_the_levels_meaning():
    # the ball element's six initial coordinates put the node at its analytic initial state, the static
    # displacement under (Fr, 0): solve_quasistatic's at rest within the 0.5 %, tilts and spin zero
    sc, mbs, node, m_b, m_g = shaft()
    el = eb.CreateBallBearing(mbs, "6208", m_b, m_g, initialLoad=(FR, 0.0), stepSize=5e-6)
    q0 = el.initialCoordinates
    assert len(q0) == 6 and list(q0[3:]) == [0.0, 0.0, 0.0]
    mbs.SetNodeParameter(node, "initialCoordinates", list(q0))
    mbs.Assemble()
    got = mbs.GetNodeOutput(node, exu.OutputVariableType.Position, exu.ConfigurationType.Initial)
    ref = eb.solve_quasistatic("6208", Fr=FR, ring_growth=False, fixed={}).displacement
    assert got[0] == pytest.approx(ref[0], rel=5e-3)


def test_operating_tilt_of_an_angular_contact_bearing_under_combined_load():
    """A single 7208 under F_r = F_a = 3000 N with its inner ring free to tilt tilts until a contact passes the
    shoulder (solve_quasistatic(fixed={}) refuses it); in a rotor the other supports hold the tilt:
    operatingTilt='held' solves the operating point and the tables with the tilt at zero (as solve_quasistatic's
    default). The refusals name what to change: initialLoad (with the held tilt's way out) and, for a default
    table that reaches a speed the bearing cannot carry, coefficientSpeeds."""
    load, w = (3000.0, 3000.0), 500.0
    _sc, mbs, _node, m_b, m_g = shaft()
    with pytest.raises(eb.InputError, match="^initialLoad: with the inner ring's tilt free.*operatingTilt='held'"):
        eb.CreateBallBearing(mbs, "7208", m_b, m_g, model="quasistatic", initialLoad=load, initialOmega=w)
    with pytest.raises(eb.InputError, match="^coefficientSpeeds: the level's table .* 750 rad/s"):
        eb.CreateBallBearing(mbs, "7208", m_b, m_g, model="linear", initialLoad=load, initialOmega=w,
                             operatingTilt="held")
    with pytest.raises(eb.InputError, match="^operatingTilt: "):
        eb.CreateBallBearing(mbs, "7208", m_b, m_g, model="quasistatic", initialLoad=load, operatingTilt="fixed")
    br = eb.CreateBallBearing(mbs, "7208", m_b, m_g, model="quasistatic", initialLoad=load, initialOmega=w,
                              operatingTilt="held", coefficientSpeeds=[0.0, 250.0, 500.0])
    held = eb.solve_quasistatic("7208", *load, omega=w, stiffness=False, inertia_check=False).displacement
    np.testing.assert_array_equal(br.initialRingDisplacement, held)
    assert np.all(br.initialRingDisplacement[3:] == 0.0)
