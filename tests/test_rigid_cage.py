"""The rigid cage (docs/theory/cage.md): its data and refusals, the ball / pocket and land forces of the
contact kernel against their laws, the energy balance of a run, the papers' 6208 against the torus cage,
the stable step of the 7208 and the whirl measure."""
import math
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.data import InputError
from exudyn_bearing.data.cages import CAGE_MATERIALS, RigidCage, estimated_cage
from exudyn_bearing.model import layout as L
from exudyn_bearing.model.contact import scene_loss_path, scene_paths
from exudyn_bearing.model.motion import ring_poses
from exudyn_bearing.model.scenario import resolve_cage
from exudyn_bearing.model.stability import land_step_check, stable_step
from exudyn_bearing.outputs.cage_summary import whirl, whirl_line
from exudyn_bearing.physics.short_bearing import short_bearing_force_xy
from exudyn_bearing.solvers.reference.engine import ReferenceEngine
from exudyn_bearing.solvers.reference.integrators import evaluate


def _cage(b, **kw):
    args = {"guidance": "outer_land", "pocket_clearance": 0.25e-3, "inner_radius": b.pitch_radius - 2.8e-3,
            "outer_radius": b.pitch_radius + 2.8e-3, "width": 16e-3, "land_clearance": 0.12e-3,
            "land_width": 2.5e-3}
    args.update(kw)
    return RigidCage(**args)


# -- data ---------------------------------------------------------------------------------------------------

@pytest.mark.parametrize("kw, name", [({"pocket_clearance": -1e-4}, "pocket_clearance"),
                                      ({"pocket_clearance": 0.0}, "pocket_clearance"),
                                      ({"land_clearance": 0.0}, "land_clearance"),
                                      ({"land_clearance": 0.3e-3}, "land_clearance"),  # not below the pockets'
                                      ({"guidance": "shaft"}, "guidance"),
                                      ({"pocket_shape": "square"}, "pocket_shape"),
                                      ({"material": "wood"}, "material"),
                                      ({"pocket_friction": 5.0}, "pocket_friction"),
                                      ({"outer_radius": 0.02}, "outer_radius")])
def test_impossible_cage_refused_by_name(b6208, kw, name):
    with pytest.raises(InputError, match=name):
        _cage(b6208, **kw)


@pytest.mark.parametrize("kw, name", [({"pocket_clearance": 3e-3}, "pocket_clearance"),   # lengths in mm
                                      ({"width": 10e-3}, "width"),                       # narrower than pockets
                                      ({"inner_radius": 0.0305}, "inner_radius"),        # pitch circle outside
                                      ({"outer_radius": 0.0365, "land_clearance": 0.1e-3}, "outer_radius")])
def test_a_cage_that_does_not_fit_the_bearing_is_refused(b6208, kw, name):
    with pytest.raises(InputError, match=name):
        _cage(b6208, **kw).check_fits(b6208)


def test_a_temperature_limit_in_celsius_is_refused():
    with pytest.raises(InputError, match="temperature_limit.*kelvin"):
        eb.data.cages.CageMaterial("x", 1350.0, 8e9, 0.4, 120.0)


@pytest.mark.parametrize("name", ["6208", "7208", "6004", "6205", "ACBB-120"])
def test_every_catalogue_bearing_has_an_estimated_cage_that_fits(name):
    b = eb.catalog[name]
    c = estimated_cage(b)
    c.check_fits(b)
    assert {"pocket_clearance", "land_clearance", "land_width", "width"} <= set(c.estimated)
    # the mass is the section less the pockets: below the solid annulus, above the annulus less Z cylinders
    annulus = c.material.density * math.pi * (c.outer_radius ** 2 - c.inner_radius ** 2) * c.width
    assert 0.0 < c.mass(b) < annulus
    assert c.polar_inertia(b) < annulus * (c.outer_radius ** 2 + c.inner_radius ** 2) / 2.0


def test_mass_and_inertia_of_a_cage_against_the_annulus_formulas(b6208):
    c = _cage(b6208, material="steel")
    rho, (ri, ro, w) = CAGE_MATERIALS["steel"].density, (c.inner_radius, c.outer_radius, c.width)
    pocket = math.pi * (b6208.ball_radius + c.pocket_clearance) ** 2 * (ro - ri)
    assert c.mass(b6208) == pytest.approx(rho * (math.pi * (ro ** 2 - ri ** 2) * w - 9 * pocket), rel=1e-12)
    assert c.polar_inertia(b6208) == pytest.approx(
        rho * (0.5 * math.pi * w * (ro ** 4 - ri ** 4) - 9 * pocket * b6208.pitch_radius ** 2), rel=1e-12)


@pytest.mark.parametrize("value, name", [(True, "torus"), (False, "none"), ("rigid", "rigid"), ("torus", "torus"),
                                         ("none", "none")])
def test_cage_option_and_its_aliases(value, name):
    assert eb.Scenario(Fr=3000.0, omega=500.0, cage=value).cage == name


def test_cage_option_refusals(b6208):
    with pytest.raises(InputError, match="cage"):
        eb.Scenario(Fr=3000.0, omega=500.0, cage="steel")
    with pytest.raises(InputError, match="rigid_cage"):
        eb.Scenario(Fr=3000.0, omega=500.0, cage="torus", rigid_cage=estimated_cage(b6208))
    with pytest.raises(InputError, match="rigid_cage"):
        eb.Scenario(Fr=3000.0, omega=500.0, cage="rigid", rigid_cage="brass")


def test_the_default_cage_is_the_bearings_own():
    """cage='auto' (the default): the torus where the bearing has cage balls (the papers' bearings keep their
    validated scenes), the rigid cage where it has none (the ACBB-120); a RigidCage given chooses the rigid cage."""
    sc = eb.Scenario(Fr=3000.0, omega=500.0)
    assert sc.cage == "auto"
    assert ReferenceEngine("6208", sc).scenario.cage == "torus"
    assert ReferenceEngine("ACBB-120", eb.Scenario(Fa=22240.0, omega=2618.0)).scenario.cage == "rigid"
    assert eb.Scenario(rigid_cage=estimated_cage(eb.catalog["6208"])).cage == "rigid"
    with pytest.raises(InputError, match="rigid_cage"):
        eb.Scenario(cage="none", rigid_cage=estimated_cage(eb.catalog["6208"]))


def test_the_torus_cage_needs_cage_balls():
    # (the Exudyn element's rigid cage: tests/test_element_rigid_cage.py)
    with pytest.raises(InputError, match="rigid"):
        ReferenceEngine("ACBB-120", eb.Scenario(Fa=22240.0, Fr=0.0, omega=2618.0, cage="torus"))


# -- kernel -------------------------------------------------------------------------------------------------

def _engine(cage=None, **kw):
    b = eb.catalog["6208"]
    sc = eb.Scenario(Fr=0.0, omega=0.0, dt=2e-5, cage="rigid", rigid_cage=cage or _cage(b), ring_growth=False,
                     friction="none", lubrication=False, **kw)
    return ReferenceEngine(b, sc)


def _forces(eng, xb, vb, wb, xc, vc):
    z = eng.bearing.n_balls
    out = {"fb": np.zeros((z, 3)), "tb": np.zeros((z, 3)), "fc": np.zeros((z, 3)), "fr": np.zeros((2, 6)),
           "glob": np.zeros(L.NGLOBAL), "cage_load": np.zeros((z, 2))}
    st = eng.initial_state()
    evaluate(0.0, eng.params, eng.table, xb, vb, wb, xc, vc, np.zeros(6), ring_poses(), st["hist"].copy(),
             np.zeros((z, 2, L.HZ_N)), out["fb"], out["tb"], out["fc"], out["fr"], np.zeros(3), out["glob"],
             np.zeros((z, 2, L.NDIAG)), out["cage_load"], True, *scene_paths(eng.params), scene_loss_path(eng.params))
    return out


def _balls_on_pitch_circle(eng, angle=0.0):
    """Balls at rest midway between the races on the pitch circle (no race contact: the 6208 has no
    clearance, so they touch with zero overlap), pocket j at ball j for the cage angle ``angle`` (which the
    caller sets in xc[1, 0]), the cage centred and at rest."""
    b, z = eng.bearing, eng.bearing.n_balls
    psi = angle + 2.0 * math.pi * np.arange(z) / z
    xb = np.stack([b.pitch_radius * np.cos(psi), b.pitch_radius * np.sin(psi), np.zeros(z)], axis=1)
    return xb, np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3))


def test_a_ball_pressed_into_its_pocket_gets_the_hertz_force_and_the_cage_the_reaction():
    eng = _engine()
    p, b = eng.params, eng.bearing
    xb, vb, wb, xc, vc = _balls_on_pitch_circle(eng)
    delta = 2e-6
    j = 2
    psi = 2.0 * math.pi * j / b.n_balls
    t = np.array([-math.sin(psi), math.cos(psi), 0.0])  # the pocket's orbit direction
    # the ball moved along the pitch circle (no race contact) until it is gap + delta off the pocket's axis
    turn = math.asin((p[L.P_POCKET_GAP] + delta) / b.pitch_radius)
    xb[j] = (b.pitch_radius * math.cos(psi + turn), b.pitch_radius * math.sin(psi + turn), 0.0)
    out = _forces(eng, xb, vb, wb, xc, vc)
    f = p[L.P_K_POCKET] * delta ** 1.5
    assert out["fb"][j] == pytest.approx(-f * t, rel=1e-9, abs=1e-9 * f)
    assert np.abs(np.delete(out["fb"], j, axis=0)).max() < 1e-9 * f
    assert out["fc"][0] == pytest.approx(f * t, rel=1e-9, abs=1e-9 * f)
    # the cage's moment about its axis, (contact point) x (f t) = f r_p cos(turn), scaled by m_c / I_c
    assert out["fc"][1, 0] * p[L.P_IC] / p[L.P_MC] == pytest.approx(f * b.pitch_radius * math.cos(turn), rel=1e-9)
    assert out["cage_load"][j, 0] == pytest.approx(f, rel=1e-9)
    assert out["glob"][L.G_POCKET_POWER] == pytest.approx(0.0, abs=1e-12)  # at rest: nothing dissipated


@pytest.mark.parametrize("spacing", [0.0, 0.4 * 0.25e-3])
def test_every_pocket_sits_at_its_angle_for_any_cage_angle(spacing):
    """The kernel turns the pockets' directions pocket after pocket (the pitch's rotation, and the unequal
    spacing's) instead of taking cos and sin of every pocket's angle: every ball pressed delta into its
    pocket at the angle theta + 2 pi j / Z + (e / r_p) sin(2 pi j / Z), for a cage angle theta off the
    ball positions' zero, gets the Hertz force of delta (a pocket off its angle by more than round-off would
    change delta = 2 um by more than 1e-9 of it)."""
    b = eb.catalog["6208"]
    eng = _engine(_cage(b, pocket_spacing_error=spacing))
    p, z = eng.params, b.n_balls
    theta = 0.7
    xb, vb, wb, xc, vc = _balls_on_pitch_circle(eng)
    xc[1, 0] = theta
    delta = 2e-6
    turn = math.asin((p[L.P_POCKET_GAP] + delta) / b.pitch_radius)
    for j in range(z):
        psi = 2.0 * math.pi * j / z
        a = theta + psi + p[L.P_POCKET_SPACING] * math.sin(psi) + (turn if j % 2 == 0 else -turn)
        xb[j] = (b.pitch_radius * math.cos(a), b.pitch_radius * math.sin(a), 0.0)
    out = _forces(eng, xb, vb, wb, xc, vc)
    assert out["cage_load"][:, 0] == pytest.approx(np.full(z, p[L.P_K_POCKET] * delta ** 1.5), rel=1e-9)


def test_pocket_friction_opposes_the_sliding_and_dissipates_mu_f_times_the_slip():
    cage = _cage(eb.catalog["6208"], pocket_friction=0.2)
    eng = _engine(cage)
    p, b = eng.params, eng.bearing
    xb, vb, wb, xc, vc = _balls_on_pitch_circle(eng)
    delta, j = 2e-6, 0
    t = np.array([0.0, 1.0, 0.0])
    turn = math.asin((p[L.P_POCKET_GAP] + delta) / b.pitch_radius)
    xb[j] = (b.pitch_radius * math.cos(turn), b.pitch_radius * math.sin(turn), 0.0)
    wb[j] = (0.0, 0.0, 0.0)
    vb[j] = (0.0, 0.0, 0.5)   # sliding along the bearing axis across the pocket wall, fast above v_reg
    out = _forces(eng, xb, vb, wb, xc, vc)
    f = p[L.P_K_POCKET] * delta ** 1.5
    assert out["fb"][j, 2] == pytest.approx(-0.2 * f, rel=1e-9)
    assert out["fb"][j, 1] == pytest.approx(-f, rel=1e-9)
    # the friction at the contact point r = R_b t gives the ball the moment r x F
    assert out["tb"][j] == pytest.approx(np.cross(b.ball_radius * t, [0.0, 0.0, -0.2 * f]), rel=1e-9, abs=1e-9 * f)
    assert out["glob"][L.G_POCKET_POWER] == pytest.approx(0.2 * f * 0.5, rel=1e-9)


def test_the_land_film_force_and_shear_are_the_short_bearing_laws_and_balance_the_ring():
    eng = _engine()
    p = eng.params
    xb, vb, wb, xc, vc = _balls_on_pitch_circle(eng)
    e = 0.5 * p[L.P_LAND_C]
    xc[0, :2] = (e * math.cos(0.4), e * math.sin(0.4))
    vc[0, :2] = (0.003, -0.002)
    vc[1, 0] = 200.0
    xc[1, 0] = 0.0
    out = _forces(eng, xb, vb, wb, xc, vc)
    fx, fy = short_bearing_force_xy(*xc[0, :2], *vc[0, :2], 200.0, p[L.P_LAND_ETA], p[L.P_LAND_R], p[L.P_LAND_L],
                                    p[L.P_LAND_C])
    assert out["glob"][L.G_LAND_FX] == pytest.approx(float(fx), rel=1e-9)
    assert out["glob"][L.G_LAND_FY] == pytest.approx(float(fy), rel=1e-9)
    assert out["fc"][0, :2] == pytest.approx([float(fx), float(fy)], rel=1e-9)
    assert out["glob"][L.G_LAND_ECC] == pytest.approx(0.5, rel=1e-12)
    shear = -2 * math.pi * p[L.P_LAND_ETA] * p[L.P_LAND_R] ** 3 * p[L.P_LAND_L] * 200.0 / (p[L.P_LAND_C] * math.sqrt(0.75))
    assert out["fc"][1, 0] * p[L.P_IC] / p[L.P_MC] == pytest.approx(shear, rel=1e-9)
    # the outer ring takes the opposite force, and the moments of cage and ring about the bearing centre cancel
    assert out["fr"][1, :2] == pytest.approx([-float(fx), -float(fy)], rel=1e-9)
    moment_cage = shear + xc[0, 0] * fy - xc[0, 1] * fx
    assert out["fr"][1, 5] + moment_cage == pytest.approx(0.0, abs=1e-12 * abs(shear))
    # dissipated: minus the pair's power on the relative motion (the outer ring at rest)
    assert out["glob"][L.G_LAND_POWER] == pytest.approx(-(fx * 0.003 + fy * (-0.002)) - shear * 200.0, rel=1e-9)


# -- runs ---------------------------------------------------------------------------------------------------

@pytest.fixture(scope="module")
def rigid_6208_run():
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.02, dt=4e-6, sample_dt=1e-4, cage="rigid")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        run = eb.simulate("6208", sc)
        return run, run.summary()


def test_energy_closes_with_the_rigid_cage_and_its_losses_are_reported(rigid_6208_run):
    run, s = rigid_6208_run
    assert s["energy_check"]["passed"]
    assert set(s["power_loss"]) >= {"cage_pocket", "cage_land"}
    assert s["power_loss"]["cage_land"] > 0.0 and s["power_loss"]["cage_pocket"] > 0.0
    assert s["cage_power_land"] == pytest.approx(s["power_loss"]["cage_land"], rel=1e-12)
    assert not any("cage pocket friction" in x for x in s["not_modelled"])
    assert any("windage" in x for x in s["not_modelled"])
    # the engine's kinetic energy counts the cage's translation and spin (about half of the total here; the
    # engine takes it at the half-step velocities of its last evaluation, the samples hold the full step's)
    p = run.model_parameters()
    d = run.data
    ke = (0.5 * p[L.P_MB] * np.sum(d["vb"][-1] ** 2) + 0.5 * p[L.P_IB] * np.sum(d["wb"][-1] ** 2)
          + 0.5 * p[L.P_MC] * np.sum(d["vc"][-1, 0] ** 2) + 0.5 * p[L.P_IC] * d["vc"][-1, 1, 0] ** 2)
    assert d["glob"][-1, L.G_KINETIC] == pytest.approx(ke, rel=1e-3)
    assert 0.5 * p[L.P_IC] * d["vc"][-1, 1, 0] ** 2 > 0.3 * ke
    assert s["land_eccentricity_max"] < 1.0
    for key in ("cage_whirl_radius", "cage_slip", "pocket_force_max"):
        assert key in s["units"] and s[key] is not None
    # the cage it ran (no RigidCage given: the estimated one) names its estimated fields in the summary and its JSON
    assert s["rigid_cage_estimated"] == list(estimated_cage(eb.catalog["6208"]).estimated)
    assert "rigid_cage_estimated" in s["units"]


def test_a_frictionless_ball_guided_rigid_cage_runs_like_the_torus_cage_on_the_papers_6208():
    # the DEM papers' torus cage is ball-guided and frictionless: a rigid cage with the same two properties
    # must leave the radial case's loads and speeds as they are (the 0.5 %)
    b = eb.catalog["6208"]
    base = dict(Fr=3000.0, omega=500.0, t_end=0.02, dt=3e-6, sample_dt=1e-4)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        torus = eb.simulate(b, eb.Scenario(**base)).summary()
        rigid = eb.simulate(b, eb.Scenario(**base, cage="rigid", rigid_cage=estimated_cage(b, guidance="ball",
                                                                                         pocket_friction=0.0))).summary()
    for key in ("q_max_inner", "q_max_outer", "cage_speed", "ball_spin"):
        assert rigid[key] == pytest.approx(torus[key], rel=5e-3), key


def test_the_caged_7208_step_is_no_longer_set_by_the_cage():
    # the torus cage's light cage balls set the 7208's step below 1 us; the rigid cage's pockets and land
    # (at the design eccentricity) allow the balls' own limits
    b = eb.catalog["7208"]
    torus = stable_step(b, eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0))
    rigid = stable_step(b, eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0, cage="rigid"))
    assert torus.limited_by == "cage" and torus.dt < 1e-6
    assert rigid.limited_by != "cage" and rigid.dt > 5e-6


def test_the_land_check_warns_where_the_film_stiffens_beyond_the_step(b7208):
    sc = eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0, cage="rigid", dt=5e-6)
    assert land_step_check(b7208, sc, None, 0.5, 5e-6) is None
    msg = land_step_check(b7208, sc, None, 0.99, 5e-6)
    assert msg and "eccentricity" in msg and "cage_damping='implicit'" in msg
    # the linearly implicit land has no step limit of its own
    assert land_step_check(b7208, sc.replace(cage_damping="implicit"), None, 0.99, 5e-6) is None


def test_the_implicit_land_sits_where_the_explicit_one_does():
    # F_eff = (I - dt/m K_v - dt^2/m K_r)^-1 F vanishes with F: a cage in equilibrium on its film (pockets
    # clear, the film's force balancing nothing but itself at the centre) stays there, and off the centre a
    # cage at rest on a land at rest gets a force of the same direction as the explicit one, smaller
    eng = _engine(cage_damping="implicit")
    p = eng.params
    xb, vb, wb, xc, vc = _balls_on_pitch_circle(eng)
    out = _forces(eng, xb, vb, wb, xc.copy(), vc.copy())
    assert np.abs(out["fc"][0]).max() == 0.0
    xc[0, :2] = (0.6 * p[L.P_LAND_C], 0.0)
    vc[0, :2] = (0.01, 0.0)   # squeezing the film
    imp = _forces(eng, xb, vb, wb, xc, vc)["fc"][0, :2]
    exp = _forces(_engine(), xb, vb, wb, xc, vc)["fc"][0, :2]
    assert exp[0] < 0.0 and exp[0] < imp[0] < 0.0


def test_whirl_of_a_circular_orbit():
    t = np.linspace(0.0, 0.1, 1001)
    rate, cage = 40.0 * math.pi, 200.0   # two whole turns in 0.1 s: the mean position is the orbit's centre
    xy = 1e-5 * np.stack([np.cos(rate * t), np.sin(rate * t)], axis=1) + [3e-5, -1e-5]
    radius, ratio = whirl(t, xy, cage)
    assert radius == pytest.approx(1e-5, rel=1e-6)
    assert ratio == pytest.approx(rate / cage, rel=1e-9)
    assert math.isnan(whirl(t, np.zeros((1001, 2)), cage)[1])


def test_the_whirl_line_of_an_irregular_orbit():
    # a forward whirl at 1.5 times the cage speed, 5 um, with a backward one at 0.3 times it, 3 um, and a slow
    # wander of the centre: the mean turning rate is no frequency of either, the strongest line is the forward
    # whirl's, within the resolution, with most of the power; uneven samples are refused (NaN)
    t = np.linspace(0.0, 0.2, 10001)
    cage = 200.0
    z = 5e-6 * np.exp(1j * 1.5 * cage * t) + 3e-6 * np.exp(-1j * 0.3 * cage * t) + 2e-6 * np.sin(7.0 * t) * (1 + 1j)
    xy = np.stack([z.real, z.imag], axis=1)
    line, share, resolution = whirl_line(t, xy, cage)
    assert resolution == pytest.approx(2.0 * math.pi / 0.2 / cage, rel=1e-3)
    assert abs(line - 1.5) <= resolution
    assert share > 0.5
    # turning the cage the other way turns every sign: the line is then against the cage
    assert whirl_line(t, xy, -cage)[0] == pytest.approx(-line)
    uneven = t + 1e-4 * np.sin(t * 50.0) * (t > 0.1)
    assert math.isnan(whirl_line(uneven, xy, cage)[0])
    # a window of two periods of the whirl: the line is not resolved from the orbit's mean (the trial's 50 ms
    # window of a 200 rad/s cage put it in the second bin), so it is not reported
    short = t <= 2.0 * 2.0 * math.pi / (1.5 * cage)
    assert math.isnan(whirl_line(t[short], xy[short], cage)[0])


def _summary_of_orbit(t, xy, cage):
    """rigid_cage_summary of a made-up window: the cage centre at ``xy``, the 6208's outer-land cage."""
    from exudyn_bearing.outputs.cage_summary import rigid_cage_summary

    n = len(t)
    xc = np.zeros((n, 9, 3))
    xc[:, 0, :2] = xy
    data = {"t": t, "xc": xc, "glob": np.zeros((n, L.NGLOBAL)), "cage_load": np.zeros((n, 9, 2))}
    return rigid_cage_summary(data, slice(0, n), _engine().params, cage, cage)


def test_the_summary_gives_a_whirl_ratio_only_for_a_circling_orbit():
    # a circle of 30 um at 1.5 times the cage speed: circling, its mean turning rate is the line; the same with
    # a backward whirl of 20 um and a jitter of 10 um (seeded) on top: irregular, no ratio (its mean turning rate
    # is no frequency), the line still +1.5
    t = np.linspace(0.0, 0.2, 10001)
    cage = 200.0
    fwd = 30e-6 * np.exp(1j * 1.5 * cage * t)
    jitter = 10e-6 * np.random.default_rng(1).standard_normal((t.size, 2)) @ np.array([1.0, 1j])
    for z, motion in ((fwd, "circling"), (fwd + 20e-6 * np.exp(-1j * 0.7 * cage * t) + jitter, "irregular")):
        s = _summary_of_orbit(t, np.stack([z.real, z.imag], axis=1), cage)
        assert s["cage_motion"] == motion
        assert abs(s["cage_whirl_line"] - 1.5) <= s["cage_whirl_resolution"]
        if motion == "circling":
            assert s["cage_whirl_ratio"] == pytest.approx(1.5, rel=1e-2)  # 9.5 turns: the mean position is off
        else:
            assert s["cage_whirl_ratio"] is None


def test_gravity_and_unbalance_act_on_the_cage_and_count_as_drive():
    # the weight m_c g and the unbalance's centrifugal force U omega_c^2 along the cage's angle, at its centre;
    # their power enters the drive power (the energy balance stays closed)
    b = eb.catalog["6208"]
    import dataclasses

    cage = dataclasses.replace(_cage(b), unbalance=2e-5)
    eng = _engine(cage, gravity=(0.0, -9.81, 0.0))
    p = eng.params
    xb, vb, wb, xc, vc = _balls_on_pitch_circle(eng, 0.3)
    xc[1, 0] = 0.3
    vc[1, 0] = 200.0
    vc[0, :2] = (0.002, -0.001)
    out = _forces(eng, xb, vb, wb, xc, vc)
    film = short_bearing_force_xy(0.0, 0.0, 0.002, -0.001, 200.0, p[L.P_LAND_ETA], p[L.P_LAND_R], p[L.P_LAND_L],
                                  p[L.P_LAND_C])
    mc = p[L.P_MC]
    ext = np.array([2e-5 * 200.0 ** 2 * math.cos(0.3), mc * -9.81 + 2e-5 * 200.0 ** 2 * math.sin(0.3)])
    assert out["fc"][0, :2] == pytest.approx(np.array(film, float) + ext, rel=1e-9)
    assert out["glob"][L.G_CAGE_LOAD_POWER] == pytest.approx(ext @ [0.002, -0.001], rel=1e-9)


def test_gravity_and_unbalance_refusals(b6208):
    with pytest.raises(InputError, match="gravity"):
        eb.Scenario(Fr=3000.0, omega=500.0, cage="rigid", gravity=(0.0, -981.0, 0.0))
    with pytest.raises(InputError, match="gravity.*rigid"):
        eb.Scenario(Fr=3000.0, omega=500.0, cage="torus", gravity=(0.0, -9.81, 0.0))
    # the default cage ("auto") with gravity: refused where it resolves to the torus (the 6208), taken on the
    # ACBB-120, whose default is the rigid cage
    auto = eb.Scenario(Fr=3000.0, omega=500.0, gravity=(0.0, -9.81, 0.0))
    with pytest.raises(InputError, match="gravity.*rigid"):
        resolve_cage(auto, b6208)
    assert resolve_cage(auto, eb.catalog["ACBB-120"]).cage == "rigid"
    with pytest.raises(InputError, match="unbalance"):
        _cage(b6208, unbalance=-1.0)
    with pytest.raises(InputError, match="unbalance.*kg m"):
        _cage(b6208, unbalance=1e-3).check_fits(b6208)   # 1 g m: the centre of mass 10 mm off


def test_cage_motion_classes():
    from exudyn_bearing.outputs.cage_summary import cage_motion

    t = np.linspace(0.0, 0.1, 2001)
    c = 1e-4
    w = 100.0 * math.pi   # five whole turns in 0.1 s
    circle = 0.3 * c * np.stack([np.cos(w * t), np.sin(w * t)], axis=1)
    assert cage_motion(t, circle, c, 200.0)["type"] == "circling"
    assert cage_motion(t, 0.001 * circle, c, 200.0)["type"] == "centred"
    rng = np.random.default_rng(1)
    assert cage_motion(t, 0.3 * c * rng.standard_normal((t.size, 2)), c, 200.0)["type"] == "irregular"
    m = cage_motion(t, circle, c, 200.0)
    assert m["orbit_ratio"] == pytest.approx(0.3, rel=1e-3)
    assert m["centre_speed"] == pytest.approx(0.3 * w / 200.0, rel=1e-3)


def test_info_names_the_default_cage_and_the_estimated_rigid_cage(capsys):
    import json

    from exudyn_bearing.cli import main

    assert main(["info", "ACBB-120", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    rc = estimated_cage(eb.catalog["ACBB-120"])
    assert d["default_cage"] == "rigid" and d["rigid_cage"]["estimated"] == list(rc.estimated)
    assert d["rigid_cage"]["land_clearance"] == rc.land_clearance and d["rigid_cage"]["guidance"] == "outer_land"
    assert d["rigid_cage"]["mass"] == pytest.approx(rc.mass(eb.catalog["ACBB-120"]), rel=1e-12)
    assert main(["info", "6208"]) == 0
    out = capsys.readouterr().out
    assert "default_cage" in out and "torus" in out and "rigid cage (cage='rigid'):" in out
    assert "ESTIMATED: pocket_clearance" in out


def test_a_ball_outside_the_cage_section_is_flagged_and_the_run_stops_saying_so():
    """A ball whose centre lies farther along its pocket's axis than half the cage's section has left its
    pocket: the kernel flags the step (G_WORST = POCKET_ESCAPE) and the engines stop with a message naming
    the rigid cage, not a Hertz runaway."""
    eng = _engine()
    p = eng.params
    xb, vb, wb, xc, vc = _balls_on_pitch_circle(eng)
    assert _forces(eng, xb, vb, wb, xc, vc)["glob"][L.G_WORST] < L.POCKET_ESCAPE
    j = 4
    xb[j] *= 1.0 + 1.01 * p[L.P_CAGE_HALF_SECTION] / np.hypot(*xb[j, :2])   # radially out of the section
    assert _forces(eng, xb, vb, wb, xc, vc)["glob"][L.G_WORST] == L.POCKET_ESCAPE


def test_a_ball_guided_cage_needs_spherical_pockets():
    b = eb.catalog["6208"]
    with pytest.raises(InputError, match="^pocket_shape: a ball-guided cage needs spherical pockets"):
        _cage(b, guidance="ball", pocket_shape="cylindrical")
    assert estimated_cage(b, guidance="ball").pocket_shape == "spherical"
    assert estimated_cage(b).pocket_shape == "cylindrical"
    # the 6208 on a ball-guided cage with spherical pockets stays on its balls over a long run (cylindrical ones
    # let it drift off them by many pocket clearances before this was refused): its centre within the pocket
    # clearance plus the pocket contacts' Hertz overlap and the balls' own play (bounded here by one more
    # clearance, far below a drift off the balls)
    cage = estimated_cage(b, guidance="ball")
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.6, dt=2e-6, sample_dt=1e-3, rigid_cage=cage,
                     cage_damping="implicit", friction="regularized")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rec = eb.simulate(b, sc, progress=False)
    assert np.hypot(rec.data["xc"][:, 0, 0], rec.data["xc"][:, 0, 1]).max() < 2.0 * cage.pocket_clearance


def test_unequal_pocket_spacing_moves_the_pockets():
    """pocket_spacing_error e: pocket j at the cage angle + 2 pi j / Z + (e / r_p) sin(2 pi j / Z): a ball on
    the shifted pocket's axis feels nothing, one gap + delta off it the Hertz force of delta."""
    b = eb.catalog["6208"]
    e = 0.4 * 0.25e-3
    eng = _engine(_cage(b, pocket_spacing_error=e))
    p = eng.params
    assert p[L.P_POCKET_SPACING] == pytest.approx(e / b.pitch_radius, rel=1e-12)
    xb, vb, wb, xc, vc = _balls_on_pitch_circle(eng)
    j = 2
    psi = 2.0 * math.pi * j / b.n_balls
    shift = p[L.P_POCKET_SPACING] * math.sin(psi)
    delta = 2e-6
    for extra, force in ((0.0, 0.0), (math.asin((p[L.P_POCKET_GAP] + delta) / b.pitch_radius),
                                       p[L.P_K_POCKET] * delta ** 1.5)):
        a = psi + shift + extra
        xb[j] = (b.pitch_radius * math.cos(a), b.pitch_radius * math.sin(a), 0.0)
        out = _forces(eng, xb, vb, wb, xc, vc)
        assert out["cage_load"][j, 0] == pytest.approx(force, rel=1e-9, abs=1e-12)
    with pytest.raises(InputError, match="^pocket_spacing_error: .* more than half the pocket clearance"):
        _cage(b, pocket_spacing_error=0.6 * 0.25e-3)
    with pytest.raises(InputError, match="^rigid_cage: its pocket_spacing_error"):
        eb.solve_quasistatic(b, 3000.0, omega=500.0, cage="rigid", rigid_cage=_cage(b, pocket_spacing_error=e),
                          stiffness=False)
