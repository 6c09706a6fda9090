"""The quasi-static solver with the rigid cage (docs/theory/quasistatic.md#the-rigid-cage)."""
import dataclasses
import json

import numpy as np
import pytest

from exudyn_bearing import catalog
from exudyn_bearing.cli import main
from exudyn_bearing.data import InputError
from exudyn_bearing.data.cages import estimated_cage
from exudyn_bearing.solvers.quasistatic import kinematics as km
from exudyn_bearing.solvers.quasistatic import solve_quasistatic
from exudyn_bearing.solvers.quasistatic.losses import power_losses
from exudyn_bearing.solvers.quasistatic.solve import CageLandWarning
from exudyn_bearing.solvers.quasistatic.thermal import CAGE_NODE, solve_thermal

B = catalog["6208"]
IDEAL = estimated_cage(B, guidance="ball", pocket_friction=0.0)  # frictionless, ball-guided: no cage torque but Q_p
QUICK = {"stiffness": False, "resolution_check": False}


@pytest.fixture(scope="module")
def caged():
    """The 6208 radial case with the estimated outer-land brass cage (pocket friction 0.1), traction equilibrium."""
    return solve_quasistatic(B, 3000.0, omega=500.0, control="equilibrium", cage="rigid", **QUICK)


def cage_torque(sol):
    """The cage's torque about the axis, from the solution's outputs: the pocket forces' reactions at the ball
    centres' radii, the pocket friction's moment mu_c |Q_p| R_b w_z / |w|, the land's shear torque."""
    q = sol.balls["pocket_force"]
    kin = sol.kinematics
    rb = sol.contact_geometry[:, km.G_RB]
    w = np.hypot(kin[:, 1], kin[:, 2])
    parts = np.concatenate([-q * sol.balls["ball_center_r"],
                            sol.cage["pocket_friction"] * np.abs(q) * rb * kin[:, 2] / w, [sol.cage["land_torque"]]])
    return float(np.sum(parts)), float(np.sum(np.abs(parts)))


def test_balls_share_the_cage_speed_and_the_cage_torque_balances(caged):
    """Held by their pockets the balls run at the cage speed (``kinematics``); with the pocket play the outputs
    are the time means of held and free (docs/theory/quasistatic.md#pocket-play)."""
    c = caged.cage
    assert np.all(caged.kinematics[:, 0] == c["speed"])
    f = caged.balls["pocket_contact_fraction"]
    assert np.all((f >= 0.0) & (f <= 1.0)) and np.any(f < 1.0)
    np.testing.assert_allclose(caged.balls["pocket_force"], f * caged.balls["pocket_force_held"], rtol=1e-12)
    assert np.all(caged.balls["control_used"] == "equilibrium")
    torque, scale = cage_torque(caged)
    assert scale > 0.1 * abs(c["land_torque"]) > 0.0          # pocket forces and land both act
    assert abs(torque) < 1e-9 * scale
    assert abs(c["torque_residual"]) < 1e-9
    # each ball's tractions along the orbit and its pocket force balance; power: drive = contacts + cage
    for j in range(B.n_balls):
        cont = km.ball_contacts(caged.kinematics[j], caged.contact_geometry[j], caged.traction_model,
                                caged.n_strips, caged.n_across)
        assert abs(cont[0, 6] + cont[1, 6] + caged.balls["pocket_force_held"][j]) < 1e-9 * caged.q_max_inner
    assert caged.cage_power > 0.0
    assert abs(caged.energy_residual) < 1e-8


@pytest.fixture(scope="module")
def caged_feedback():
    """The same with the cage's displacement fed back into the pocket play (``land_feedback=True``)."""
    return solve_quasistatic(B, 3000.0, omega=500.0, control="equilibrium", cage="rigid", land_feedback=True,
                             **QUICK)


def test_the_land_feedback_is_an_option(caged, caged_feedback):
    """Off by default: the centred cage's pockets (no displacement, as before the option); on, the cage sits
    displaced and its torque and energy balances close as without it; refused without a guiding land."""
    assert caged.cage["land_displacement"] == (0.0, 0.0) and caged.cage["land_feedback_evaluations"] == 0
    c = caged_feedback.cage
    assert c["land_feedback_converged"] and np.hypot(*c["land_displacement"]) > 0.0
    assert abs(c["torque_residual"]) < 1e-9 and abs(caged_feedback.energy_residual) < 1e-8
    # no net pocket force (a pure axial load): the cage stays centred, at once
    axial = solve_quasistatic(B, 0.0, 3000.0, omega=500.0, control="equilibrium", cage="rigid", land_feedback=True,
                              **QUICK)
    assert axial.cage["land_displacement"] == (0.0, 0.0) and axial.cage["land_feedback_converged"]
    with pytest.raises(InputError, match="^land_feedback:"):
        solve_quasistatic(B, 3000.0, omega=500.0, control="equilibrium", cage="rigid", rigid_cage=IDEAL,
                          land_feedback=True, **QUICK)
    with pytest.raises(InputError, match="^land_feedback:"):
        solve_quasistatic(B, 3000.0, omega=500.0, control="equilibrium", land_feedback=True, **QUICK)


def test_the_land_carries_the_net_pocket_force_at_the_cages_displacement(caged_feedback):
    """The cage's displacement e on its land (docs/theory/quasistatic.md#the-cages-displacement): the land
    film's force there (the reference engine's short bearing, no squeeze or whirl) balances the net pocket force
    of the pockets displaced by e . e_psi, recomputed from the outputs (the weighted pocket forces along -e_psi
    and their friction's radial part), to 1e-7 of it (the solver's tolerance: |G(F(e)) - e| below 1e-8 of the
    land clearance); e lies at the short bearing's attitude angle ahead of the pocket force."""
    from exudyn_bearing.data.catalog import load_lubricant
    from exudyn_bearing.physics.short_bearing import short_bearing_attitude_angle, short_bearing_force_xy

    c, rc = caged_feedback.cage, caged_feedback.cage["rigid_cage"]
    psi, q, kin = caged_feedback.balls["psi"], caged_feedback.balls["pocket_force"], caged_feedback.kinematics
    f_r = c["pocket_friction"] * q * kin[:, 2] / np.hypot(kin[:, 1], kin[:, 2])
    pocket = np.array([np.sum(q * np.sin(psi) + f_r * np.cos(psi)), np.sum(-q * np.cos(psi) + f_r * np.sin(psi))])
    ex, ey = c["land_displacement"]
    assert c["land_feedback_converged"] and c["guidance"] == "outer_land"
    np.testing.assert_allclose(np.hypot(ex, ey) / rc.land_clearance, c["land_eccentricity"], rtol=1e-8)
    assert 0.0 < c["land_eccentricity"] < 0.9
    land = np.array(short_bearing_force_xy(ex, ey, 0.0, 0.0, c["speed"] + c["ring_speed"],
                                           load_lubricant(None, bearing=B).viscosity, rc.guide_radius, rc.land_width,
                                           rc.land_clearance), float)
    norm = float(np.hypot(*pocket))
    assert norm > 0.0 and np.hypot(*(land + pocket)) < 1e-7 * norm
    turn = np.angle(np.exp(1j * (np.arctan2(ey, ex) - np.arctan2(pocket[1], pocket[0]))))
    assert abs(turn - float(short_bearing_attitude_angle(c["land_eccentricity"]))) < 1e-6


def test_the_cages_displacement_does_not_depend_on_the_start(caged, caged_feedback):
    """The displacement's balance at the solution has one root among those reached from the survey's 17 starts
    spread over the land clearance (``land_feedback_roots``), and the whole solve started from the solution
    without the feedback (other ring displacements, kinematics and cage speed) ends at the same displacement
    and cage speed, within 1e-6 of the land clearance and 1e-9 relative."""
    c = caged_feedback.cage
    assert c["land_feedback_converged"] and c["land_feedback_roots"] == 1
    other = solve_quasistatic(B, 3000.0, omega=500.0, control="equilibrium", cage="rigid", land_feedback=True,
                              start=caged, **QUICK)
    assert other.cage["land_feedback_converged"] and other.cage["land_feedback_roots"] == 1
    assert np.hypot(*np.subtract(other.cage["land_displacement"], c["land_displacement"])) \
        < 1e-6 * c["rigid_cage"].land_clearance
    assert abs(other.cage["speed"] / c["speed"] - 1.0) < 1e-9


def test_a_land_feedback_that_does_not_converge_says_so():
    """The 20 um land (crushed film, below): the displacement's balance has no root the solver reaches; the
    solution warns, flags it (``land_feedback_converged``) and is the one without the feedback."""
    narrow = dataclasses.replace(estimated_cage(B), land_width=2e-5)
    args = (B, 3000.0)
    kw = {"omega": 500.0, "control": "equilibrium", "cage": "rigid", "rigid_cage": narrow, **QUICK}
    with pytest.warns(CageLandWarning, match="did not converge"):
        fed = solve_quasistatic(*args, land_feedback=True, **kw)
    with pytest.warns(CageLandWarning):
        plain = solve_quasistatic(*args, **kw)
    assert not fed.cage["land_feedback_converged"] and fed.cage["land_displacement"] == (0.0, 0.0)
    assert fed.cage["speed"] == plain.cage["speed"] and fed.cage["power_land"] == plain.cage["power_land"]


def test_losses_come_from_the_cage_balance(caged):
    pl = power_losses(caged)
    c = caged.cage
    rb = caged.contact_geometry[:, km.G_RB]
    w = np.hypot(caged.kinematics[:, 1], caged.kinematics[:, 2])    # the held balls' spin
    pocket = float(np.sum(c["pocket_friction"] * np.abs(caged.balls["pocket_force"]) * rb * w))
    assert pl["power_loss"]["cage_pocket"] == pytest.approx(pocket, rel=1e-12)
    assert pl["power_loss"]["cage_land"] == pytest.approx(-c["land_torque"] * c["speed"], rel=1e-12)
    assert pl["cage_guidance"] == "outer_land"
    for bad, name in (({"cage_pocket_friction": 0.2}, "cage_pocket_friction"),
                      ({"cage_land_clearance": 1e-4}, "cage_land_clearance"),
                      ({"cage_guidance": "ball"}, "cage_guidance")):
        with pytest.raises(InputError, match=f"^{name}:"):
            power_losses(caged, **bad)


def test_outputs_carry_the_cage(caged):
    d = caged.to_dict()
    assert d["cage"] == "rigid" and d["cage_speed"] == caged.cage["speed"]
    assert len(d["pocket_force"]) == B.n_balls
    for k in ("cage_speed", "pocket_force", "cage_power_pocket", "cage_power_land", "cage_land_eccentricity"):
        assert k in d["units"]
    assert d["rigid_cage"]["guidance"] == "outer_land" and "pocket_clearance" in d["rigid_cage"]["estimated"]
    assert "rigid cage (outer_land): speed" in caged.summary()
    assert solve_quasistatic(B, 3000.0, omega=500.0, **QUICK).to_dict()["cage"] is None


def test_frictionless_ball_guided_cage_equals_cageless_where_balls_orbit_alike():
    """Under a pure axial load every ball orbits alike without a cage: the cage carries nothing and changes
    nothing."""
    free = solve_quasistatic(B, 0.0, 3000.0, omega=500.0, control="equilibrium", **QUICK)
    sol = solve_quasistatic(B, 0.0, 3000.0, omega=500.0, control="equilibrium", cage="rigid", rigid_cage=IDEAL,
                            **QUICK)
    assert np.ptp(free.kinematics[:, 0]) == 0.0
    assert sol.cage["speed"] == pytest.approx(free.kinematics[0, 0], rel=1e-9)
    assert np.max(np.abs(sol.balls["pocket_force"])) < 1e-8 * sol.q_max_inner
    assert sol.dissipation_total == pytest.approx(free.dissipation_total, rel=1e-8)
    assert sol.cage_power == 0.0


def test_frictionless_ball_guided_cage_radial_close_to_cageless():
    """Radially loaded, the cageless balls orbit at slightly different speeds (198.09 to 198.31 rad/s); the
    frictionless ball-guided cage holds them at one speed inside that range, with the same loads and the
    dissipation within 0.1 %, and loses nothing itself."""
    free = solve_quasistatic(B, 3000.0, omega=500.0, control="equilibrium", **QUICK)
    sol = solve_quasistatic(B, 3000.0, omega=500.0, control="equilibrium", cage="rigid", rigid_cage=IDEAL, **QUICK)
    wc = sol.cage["speed"]
    assert free.kinematics[:, 0].min() < wc < free.kinematics[:, 0].max()
    assert sol.q_max_inner == pytest.approx(free.q_max_inner, rel=1e-5)
    assert sol.dissipation_total == pytest.approx(free.dissipation_total, rel=1e-3)
    assert sol.cage_power == 0.0
    assert abs(cage_torque(sol)[0]) < 1e-9 * cage_torque(sol)[1]


def test_race_control_with_the_cage():
    sol = solve_quasistatic(B, 3000.0, omega=500.0, control="outer", cage="rigid", **QUICK)
    assert np.all(sol.kinematics[:, 0] == sol.cage["speed"])
    torque, scale = cage_torque(sol)
    assert abs(torque) < 1e-9 * scale
    # each ball rolls without spin at the centre of its outer contact, at the cage speed
    for j in range(B.n_balls):
        c = km.ball_contacts(sol.kinematics[j], sol.contact_geometry[j], sol.traction_model, 1, 1)
        assert abs(c[0, 0]) < 1e-9 * abs(c[0, 3]) and abs(c[0, 4]) < 1e-9 * abs(c[0, 5])


def test_minimum_energy_with_the_cage():
    """Gupta's hypothesis with the cage: each loaded ball at the cage speed, its spin the minimum of its contacts'
    dissipation there (checked here by perturbing the spin), its pocket force the tractions' net force along
    the orbit; the cage torque balances (to the minimisation's precision, 1e-7)."""
    sol = solve_quasistatic(B, 3000.0, omega=500.0, control="min-energy", cage="rigid", **QUICK)
    assert np.all(sol.kinematics[:, 0] == sol.cage["speed"])
    used = sol.balls["control_used"]
    assert "min-energy" in set(used) and set(used) <= {"min-energy", "outer"}
    torque, scale = cage_torque(sol)
    assert abs(torque) < 1e-7 * scale and abs(sol.cage["torque_residual"]) < 1e-7
    model, ns, na = sol.traction_model, sol.n_strips, sol.n_across
    for j in np.flatnonzero(used == "min-energy"):
        kin, geo = sol.kinematics[j], sol.contact_geometry[j]
        c = km.ball_contacts(kin, geo, model, ns, na)
        assert abs(c[0, 6] + c[1, 6] + sol.balls["pocket_force_held"][j]) < 1e-9 * sol.q_max_inner
        assert sol.minimum_checks[j]["is_minimum"]
        p0 = km.ball_contacts(kin, geo, model, ns, na)[:, 9].sum()       # the contacts' dissipation [W]
        h = 1e-4 * np.hypot(kin[1], kin[2])
        for k in (1, 2):
            for sign in (1.0, -1.0):
                moved = kin.copy()
                moved[k] += sign * h
                assert km.ball_contacts(moved, geo, model, ns, na)[:, 9].sum() > p0


def test_minimum_energy_with_the_cage_balances_the_orbit_under_thrust():
    """Under a pure axial load with a frictionless ball-guided cage the pockets carry nothing: the cage speed is
    where each ball's tractions have no net force along the orbit, which the cageless minimum leaves (the cage's
    balance adds the condition Gupta's hypothesis does not impose)."""
    free = solve_quasistatic(B, 0.0, 3000.0, omega=500.0, control="min-energy", **QUICK)
    sol = solve_quasistatic(B, 0.0, 3000.0, omega=500.0, control="min-energy", cage="rigid", rigid_cage=IDEAL,
                            **QUICK)
    q = sol.q_max_inner
    assert np.abs(sol.balls["pocket_force"]).max() < 1e-8 * q
    c = km.ball_contacts(free.kinematics[0], free.contact_geometry[0], free.traction_model, free.n_strips,
                         free.n_across)
    assert abs(c[0, 6] + c[1, 6]) > 1e-4 * q                 # the cageless minimum's net traction along the orbit
    assert sol.cage["speed"] != pytest.approx(free.kinematics[0, 0], rel=1e-6)


@pytest.mark.parametrize("kw, name", [
    ({"cage": "torus"}, "cage"),
    ({"rigid_cage": IDEAL}, "rigid_cage"),
    ({"cage": "rigid", "rigid_cage": "brass"}, "rigid_cage"),
])
def test_bad_cage_input(kw, name):
    with pytest.raises(InputError, match=f"^{name}:"):
        solve_quasistatic(B, 3000.0, omega=500.0, **QUICK, **kw)


@pytest.mark.parametrize("cage", [None, "none", False])
def test_no_cage_is_spelt_as_the_scenario_spells_it(cage):
    # the three spellings Scenario takes for "no cage" give the same cageless solution here
    from exudyn_bearing import Scenario

    assert Scenario(cage=cage).cage == "none"
    sol = solve_quasistatic(B, 3000.0, omega=500.0, **QUICK, cage=cage)
    ref = solve_quasistatic(B, 3000.0, omega=500.0, **QUICK)
    assert sol.cage is None and np.array_equal(sol.balls["q_inner"], ref.balls["q_inner"])


def test_thermal_takes_the_cage_from_the_solution():
    common = {"omega": 500.0, "oil_inlet_temperature": 313.15, "oil_flow": 1e-6, "control": "equilibrium",
              "cage": "rigid"}
    r = solve_thermal(B, 3000.0, **common)
    assert CAGE_NODE in r.temperatures
    assert r.quasistatic.cage is not None
    assert r.losses["power_loss"]["cage_land"] == pytest.approx(r.quasistatic.cage["power_land"], rel=1e-12)
    with pytest.raises(InputError, match="^cage_pocket_clearance:"):
        solve_thermal(B, 3000.0, cage_pocket_clearance=1e-4, **common)


def test_cli_cage_rigid(capsys):
    assert main(["quasistatic", "6208", "--Fr", "3000", "--omega", "500", "--control", "equilibrium",
                 "--cage", "rigid", "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    # the mean orbital speeds: the cage's for a ball its pocket always holds, between it and the free ball's else
    f = np.array(d["pocket_contact_fraction"])
    assert d["cage"] == "rigid" and np.all(np.array(d["orbital_speed"])[f == 1.0] == d["cage_speed"])
    assert d["power_loss"]["cage_land"] > 0.0


def test_a_land_too_narrow_for_the_pocket_force_warns():
    """A 20 um land cannot carry the net pocket force on its film: the cage would touch its land."""
    narrow = dataclasses.replace(estimated_cage(B), land_width=2e-5)
    with pytest.warns(CageLandWarning, match="^rigid_cage:"):
        sol = solve_quasistatic(B, 3000.0, omega=500.0, control="equilibrium", cage="rigid", rigid_cage=narrow,
                                **QUICK)
    assert sol.cage["land_crushed"]


def test_torque_residual_relative_to_the_tractions_where_the_pockets_carry_nothing():
    """Under a pure axial load every ball alike: the frictionless ball-guided cage has pocket forces of
    round-off only, and its residual is measured against the tractions they balance."""
    sol = solve_quasistatic(B, 0.0, 3000.0, omega=500.0, control="outer", cage="rigid", rigid_cage=IDEAL, **QUICK)
    assert np.max(np.abs(sol.balls["pocket_force"])) < 1e-9 * sol.q_max_inner
    assert abs(sol.cage["torque_residual"]) < 1e-9


def test_thermal_checks_the_cage_against_its_material_limit():
    """The cage node against the rigid cage material's permissible temperature: within for brass (523 K) at a
    40 degC inlet, a CageTemperatureWarning for a material whose limit lies below the computed cage node."""
    from exudyn_bearing.data.cages import (
        CAGE_MATERIALS,
        CageMaterial,
        CageTemperatureWarning,
    )

    common = {"omega": 500.0, "oil_inlet_temperature": 313.15, "oil_flow": 1e-6, "control": "equilibrium",
              "cage": "rigid"}
    r = solve_thermal(B, 3000.0, **common)
    assert r.cage_limit == {"material": "brass", "temperature_limit": CAGE_MATERIALS["brass"].temperature_limit,
                            "within": True}
    t_cage = r.temperatures[CAGE_NODE]
    cool = CageMaterial("test", 8500.0, 100e9, 0.34, t_cage - 2.0, "a limit 2 K below the brass run's cage")
    with pytest.warns(CageTemperatureWarning, match="^cage temperature: .* above the test cage's permissible"):
        r2 = solve_thermal(B, 3000.0, rigid_cage=estimated_cage(B, material=cool), **common)
    assert r2.cage_limit["within"] is False and r2.to_dict()["cage_temperature_limit"]["material"] == "test"
    assert solve_thermal(B, 3000.0, **{**common, "cage": None}).cage_limit is None


def _play_by_time_steps(u, psi, omega_c, radius, clearance, revolutions=400, steps=20000, offset=None):
    """The pocket play integrated in time from the pocket's centre (explicit steps, u linear between the
    azimuths), the wall contact of the last revolution per ball: an independent check of the periodic solution.
    ``offset``: the pocket centre's displacement along the orbit at the azimuths (linear between), whose change
    over a step is taken off the ball's position relative to the pocket."""
    order = np.argsort(np.mod(psi, 2 * np.pi))
    ang = np.append(np.mod(psi, 2 * np.pi)[order], np.mod(psi, 2 * np.pi)[order][0] + 2 * np.pi)
    uu = np.append(u[order], u[order][0])
    oo = np.zeros(len(u) + 1) if offset is None else np.append(offset[order], offset[order][0])
    t_rev = 2 * np.pi / omega_c
    s, on, tot = 0.0, np.zeros(len(u)), np.zeros(len(u))
    dt = t_rev / steps
    for rev in range(revolutions):
        for k in range(steps):
            a = ang[0] + (k + 0.5) / steps * 2 * np.pi
            a0, a1 = ang[0] + k / steps * 2 * np.pi, ang[0] + (k + 1) / steps * 2 * np.pi
            rate = radius * np.interp(a, ang, uu) - (np.interp(a1, ang, oo) - np.interp(a0, ang, oo)) / dt
            s_new = s + rate * dt
            resting = (s_new >= clearance and rate > 0) or (s_new <= -clearance and rate < 0)
            s = min(max(s_new, -clearance), clearance)
            if rev == revolutions - 1:
                i = int(np.argmin(np.abs(np.angle(np.exp(1j * (a - ang[:-1]))))))
                tot[i] += dt
                on[i] += dt * resting
    out = np.empty(len(u))
    out[order] = on / tot
    return out


def test_pocket_contact_fraction_against_time_steps():
    from exudyn_bearing.solvers.quasistatic.solve import pocket_contact_fraction

    z, r, c, wc = 9, 0.03, 50e-6, 200.0
    psi = 2 * np.pi * np.arange(z) / z
    # a drift ahead on the loaded side and back on the other: net forward (rests on the front wall part of the time)
    u = 0.05 + 0.4 * np.cos(psi)
    f = pocket_contact_fraction(u, psi, wc, r, c)
    assert np.all((f >= 0.0) & (f <= 1.0)) and 0.0 < f.max() and f.min() == 0.0
    ref = _play_by_time_steps(u, psi, wc, r, c, revolutions=3, steps=9000)
    np.testing.assert_allclose(f, ref, atol=0.02)
    # the mirror image (the cage turning the other way, u even in psi): the ball meets the azimuths in the reverse
    # order, so the fractions are those of the mirrored azimuths -psi
    mirror = (-np.arange(z)) % z
    np.testing.assert_allclose(pocket_contact_fraction(-u, psi, -wc, r, c), f[mirror], atol=1e-12)


def test_pocket_contact_fraction_limits():
    from exudyn_bearing.solvers.quasistatic.solve import pocket_contact_fraction

    z, r, c, wc = 13, 0.03, 50e-6, 200.0
    psi = 2 * np.pi * np.arange(z) / z
    assert np.all(pocket_contact_fraction(np.full(z, 0.01), psi, wc, r, c) == 1.0)   # always ahead: always held
    assert np.all(pocket_contact_fraction(np.full(z, -0.01), psi, wc, r, c) == 1.0)  # always behind: held too
    small = 0.2 * np.cos(psi)          # no net drift, a swing of 2 r 0.2 / wc = 60 um < the play of 100 um: floats
    assert np.all(pocket_contact_fraction(small, psi, wc, r, c) == 0.0)
    f = [pocket_contact_fraction(a * np.cos(psi), psi, wc, r, c).mean() for a in (0.4, 0.8, 1.6)]
    assert 0.0 < f[0] < f[1] < f[2] < 1.0                    # a larger swing rests longer on the walls
    # continuous in u (the wall reached within a sub-step counted to the instant)
    g = [pocket_contact_fraction(0.05 + 0.4 * np.cos(psi) + e, psi, wc, r, c) for e in (0.0, 1e-9)]
    assert np.abs(g[1] - g[0]).max() < 1e-5


def test_pocket_contact_fraction_is_continuous_where_a_ball_leaves_its_wall():
    """The time on a wall ends where the drift rate turns inward, inside a sub-step (the rate linear in time
    over it): the fraction moves smoothly with the drift, no jump of a sub-step's time (1/64 of a spacing per
    ball, 1.6 %) when the turn crosses a sub-step's end. A scan of a common drift over 4000 values: every step
    changes each fraction by less than 1e-3 (the rate constant over each sub-step, as before, jumped by 1/64
    at 6 steps of this scan), while the scan moves the largest by more than 0.5."""
    from exudyn_bearing.solvers.quasistatic.solve import pocket_contact_fraction

    z, r, c, wc = 9, 0.03, 50e-6, 200.0
    psi = 2 * np.pi * np.arange(z) / z
    shifts = np.linspace(0.0, 0.02, 4000)
    f = np.array([pocket_contact_fraction(0.01 + s + 0.3 * np.cos(psi), psi, wc, r, c) for s in shifts])
    assert np.ptp(f, axis=0).max() > 0.5
    assert np.abs(np.diff(f, axis=0)).max() < 1e-3


def test_pocket_contact_fraction_with_a_displaced_cage_by_hand():
    """No drift of its own (u = 0): the ball's position relative to its pocket is minus the pocket's offset,
    here a cage displaced by e: o(psi) = e . e_psi, sampled at 4 azimuths (A, 0, -A, 0) and linear between.
    By hand: the relative path -o rises by 2 A over the first half revolution and falls back over the second;
    the ball leaves the back wall at psi = 0, meets the front wall after 2 c of the rise, at 180 c / A deg, and
    rests there until 180 deg, then likewise on the back wall from 180 + 180 c / A to 360 deg. With A = 4 c the
    walls hold 45-180 and 225-360 deg: each ball owns +-45 deg about its azimuth, so f = (1/2, 1, 1/2, 1);
    with A = 2 c (90-180, 270-360 deg) f = 1/2 each; with A < c the ball floats."""
    from exudyn_bearing.solvers.quasistatic.solve import pocket_contact_fraction

    z, r, c, wc = 4, 0.03, 50e-6, 200.0
    psi = 2 * np.pi * np.arange(z) / z
    u = np.zeros(z)
    for amp, want in ((4 * c, [0.5, 1.0, 0.5, 1.0]), (2 * c, [0.5] * 4), (0.9 * c, [0.0] * 4)):
        np.testing.assert_allclose(pocket_contact_fraction(u, psi, wc, r, c, offset=amp * np.cos(psi)), want,
                                   atol=1e-12)
    # only the pockets' motion enters: a common offset changes nothing, and none is the same as no offset
    u = 0.05 + 0.4 * np.cos(psi)
    f = pocket_contact_fraction(u, psi, wc, r, c)
    assert np.array_equal(pocket_contact_fraction(u, psi, wc, r, c, offset=np.full(z, 3e-5)), f)
    assert np.array_equal(pocket_contact_fraction(u, psi, wc, r, c, offset=np.zeros(z)), f)


def test_pocket_contact_fraction_with_offset_against_time_steps():
    """A drift of its own and a displaced cage: the fraction against the play integrated in time with the
    pocket's own motion subtracted step by step (the ball relative to its pocket is S - o); the offset that
    follows the drift leaves the ball floating where it alone would touch."""
    from exudyn_bearing.solvers.quasistatic.solve import pocket_contact_fraction

    z, r, c, wc = 9, 0.03, 50e-6, 200.0
    psi = 2 * np.pi * np.arange(z) / z
    u = 0.05 + 0.4 * np.cos(psi)
    off = 60e-6 * np.sin(psi + 0.3)
    f = pocket_contact_fraction(u, psi, wc, r, c, offset=off)
    ref = _play_by_time_steps(u, psi, wc, r, c, revolutions=3, steps=9000, offset=off)
    np.testing.assert_allclose(f, ref, atol=0.02)
    assert np.abs(f - pocket_contact_fraction(u, psi, wc, r, c)).max() > 0.1   # the offset matters here
    # no net drift, a swing of 2 r 0.4 / wc = 120 um > the play of 100 um: touches; the pockets following the
    # ball's swing (o = its own free path at the azimuths, the sign convention: S - o) leave it floating
    swing = 0.4 * np.cos(psi)
    assert pocket_contact_fraction(swing, psi, wc, r, c).max() > 0.0
    follow = r * 0.4 * np.sin(psi) / wc            # S(psi) = int r u dt = r 0.4 sin(psi) / wc
    assert pocket_contact_fraction(swing, psi, wc, r, c, offset=follow).max() == 0.0


def test_pocket_play_lowers_the_cage_losses_of_unequal_balls():
    """7208 under F_r = 3000, F_a = 10000 N: the balls' own orbital speeds differ by 0.1 %; with the estimated
    pocket clearance (252 um) they drift inside the play and touch their pockets part of the time, so the pocket
    loss is well below that of the same balls held all the time. Pure axial: every ball alike, always held."""
    b = catalog["7208"]
    common = dict(omega=500.0, control="equilibrium", cage="rigid", fixed={"tilt_x": 0.0, "tilt_y": 0.0}, **QUICK)
    play = solve_quasistatic(b, 3000.0, 10000.0, **common)
    f = play.balls["pocket_contact_fraction"]
    assert np.any(f < 1.0) and np.any(f > 0.0)
    rb = play.contact_geometry[:, km.G_RB]
    w = np.hypot(play.kinematics[:, 1], play.kinematics[:, 2])
    held_always = float(np.sum(play.cage["pocket_friction"] * np.abs(play.balls["pocket_force_held"]) * rb * w))
    assert play.cage["power_pocket"] < 0.5 * held_always
    assert abs(play.energy_residual) < 1e-8 and abs(play.cage["torque_residual"]) < 1e-9
    # the free balls' orbital speeds lie on both sides of the cage's (a net drift either way would leave no play)
    free = play.balls["orbital_speed"][f == 0.0]
    assert free.size and np.all(np.abs(free / play.cage["speed"] - 1.0) < 0.01)
    axial = solve_quasistatic(b, 0.0, 3000.0, **common)
    assert np.all(axial.balls["pocket_contact_fraction"] == 1.0)
    # every ball alike: the net pocket force is round-off (1e-11 N), its eccentricity too
    assert axial.cage["land_eccentricity"] < 1e-9 and play.cage["land_eccentricity"] > 1e-3


def test_acbb120_rigid_cage_dem_equals_the_quasistatic_equilibrium():
    """Gupta's ACBB-120 at 25,000 rpm under 22,240 N (its oil and EHL traction, the estimated outer-land brass
    cage, the bearing's default cage): the reference engine's steady state (40 ms from the quasi-static start,
    ellipse traction) equals the quasi-static traction equilibrium with the cage within 1 % in the loads and
    the cage speed and 3 % in the dissipation, cage losses included (issue 34's check;
    validation/consistency/acbb120_rigid_cage.py prints it)."""
    import warnings

    import exudyn_bearing as eb

    ehl, lub = "ehl_mil_l_23699_492K", "MIL-L-23699_492K"
    s = solve_quasistatic("ACBB-120", 0.0, 22240.0, omega=2618.0, control="equilibrium", cage="rigid", traction=ehl,
                          lubricant=lub, fixed={"tilt_x": 0.0, "tilt_y": 0.0}, stiffness=False, n_strips=16,
                          n_across=4)
    pl = power_losses(s)["power_loss"]
    sc = eb.Scenario(Fa=22240.0, omega=2618.0, t_end=0.04, dt=2e-6, traction_level="ellipse", traction=ehl,
                     n_strips=16, n_across=4, initial="quasistatic", control="equilibrium", cage_damping="implicit",
                     sample_dt=1e-4)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)
        d = eb.simulate("ACBB-120", sc, lubricant=lub, progress=False).summary()
    assert d["steady"]["steady"]
    for k in ("q_max_inner", "q_max_outer"):
        assert d[k] == pytest.approx(getattr(s, k), rel=0.01)
    assert d["cage_speed"] == pytest.approx(s.cage["speed"], rel=0.01)
    qs = s.dissipation_total + pl["cage_pocket"] + pl["cage_land"]
    assert d["dissipation"] == pytest.approx(qs, rel=0.03)
    assert d["cage_power_land"] == pytest.approx(pl["cage_land"], rel=0.03)
    assert d["cage_power_pocket"] == pytest.approx(pl["cage_pocket"], rel=0.1)


def test_ball_inertia_power_is_the_sliding_cost_of_the_speed_changes():
    """check_ball_inertia's power by hand (exudyn_bearing/solvers/quasistatic/inertia.py): two balls whose
    angular velocities and orbital speeds differ; each ball pitch costs J |dw|^2 / 2 + m (r d omega_m)^2 / 2."""
    from types import SimpleNamespace

    from exudyn_bearing.solvers.quasistatic.inertia import ball_mass_inertia, check_ball_inertia
    kin = np.array([[200.0, -100.0, 1000.0, 0.0], [220.0, -50.0, 1100.0, 0.0]])
    sol = SimpleNamespace(kinematics=kin, omega=500.0, omega_outer=0.0, geometry={"ball_thermal_growth": 0.0},
                          balls={"ball_center_r": np.array([0.03, 0.03]), "psi": np.array([0.0, np.pi])},
                          dissipation_total=10.0, cage_power=2.0)
    m, j = ball_mass_inertia(B, B.ball_radius)
    dt = 2.0 * np.pi / (2 * 210.0)
    per_pitch = 0.5 * j * (50.0 ** 2 + 100.0 ** 2) + 0.5 * m * (0.03 * 20.0) ** 2
    with pytest.warns(UserWarning) as rec:
        out = check_ball_inertia(sol, B, tolerance=0.0)
    assert out["power"] == pytest.approx(2 * per_pitch / dt, rel=1e-12)
    assert out["share"] == pytest.approx(out["power"] / 12.0, rel=1e-12) and not out["valid"]
    assert any("inertia" in str(w.message) for w in rec)
    sol.kinematics = np.tile(kin[:1], (2, 1))               # alike balls: nothing to change
    assert check_ball_inertia(sol, B)["power"] == 0.0
    sol.omega_outer = sol.omega                             # no orbit: no check
    assert check_ball_inertia(sol, B) is None


def test_quasistatic_warns_where_the_balls_inertia_matters():
    """The caged 7208 at 500 rad/s: under F_r = F_a = 3000 N its lightly loaded balls leave and re-enter the
    load zone, and changing their spin costs a third of the dissipation (the case where the reference engine
    dissipates 35 % more, validation/consistency/quasistatic_cage.py); under F_r = 3000, F_a = 10000 N every
    ball stays loaded and the check passes."""
    from exudyn_bearing import BallInertiaWarning
    with pytest.warns(BallInertiaWarning, match="inertia"):
        light = solve_quasistatic("7208", 3000.0, 3000.0, omega=500.0, control="equilibrium", cage="rigid", **QUICK)
    assert not light.inertia_check["valid"] and light.inertia_check["share"] > 0.1
    assert light.to_dict()["ball_inertia"] == light.inertia_check
    heavy = solve_quasistatic("7208", 3000.0, 10000.0, omega=500.0, control="equilibrium", cage="rigid", **QUICK)
    assert heavy.inertia_check["valid"] and heavy.inertia_check["share"] < 1e-3
    assert solve_quasistatic(B, 3000.0, omega=500.0, inertia_check=False, **QUICK).inertia_check is None


def test_a_rigid_cage_scene_starts_from_the_caged_quasistatic_solution():
    """initial='quasistatic' with the rigid cage: the balls start at the caged solution's orbital speeds (one
    speed within the pocket play), not at the cageless balls' own; the fallbacks say why. A start does not warn
    that the balls' inertia matters (the dynamic run has it)."""
    import warnings

    import exudyn_bearing as eb
    from exudyn_bearing.simulate import quasistatic_start

    b = catalog["7208"]
    common = dict(Fr=3000.0, Fa=3000.0, omega=500.0, initial="quasistatic", control="equilibrium",
                  traction_level="ellipse", n_strips=16, n_across=4)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        caged = quasistatic_start(b, eb.Scenario(cage="rigid", **common))
        free = quasistatic_start(b, eb.Scenario(cage="none", **common))
    assert caged["cage_start"] == "quasi-static solution with the rigid cage"
    assert caged["static"].cage is not None and free["static"].cage is None
    spread = [float(np.ptp(s["static"].kinematics[:, 0])) for s in (caged, free)]
    assert spread[0] < 0.05 * spread[1]  # the cageless 7208's balls orbit at 209.5 ... 263.6 rad/s
    assert np.allclose(caged["static"].kinematics[:, 0], caged["static"].cage["speed"], rtol=0.01)
    uneven = dataclasses.replace(estimated_cage(b), pocket_spacing_error=1e-5)
    fallback = quasistatic_start(b, eb.Scenario(cage="rigid", rigid_cage=uneven, **common))
    assert fallback["static"].cage is None and "unequally spaced" in fallback["cage_start"]


@pytest.mark.parametrize("guidance, omega_outer", [("inner_land", 0.0), ("outer_land", -100.0)])
def test_energy_closes_where_the_land_turns(guidance, omega_outer):
    """A land on a turning ring (inner-land guidance, or the outer ring turning under an outer-land cage): the
    ring's drive supplies the land torque T_land times its speed (the film puts -T_land on the ring), and in the
    traction equilibrium drive power = contacts + pockets + land (the sign of that share: -3.6 of the drive power
    off with the outer ring at -100 rad/s). The orbit march counts it the same way."""
    from exudyn_bearing.solvers.quasistatic.orbit import march_orbit
    cage = estimated_cage(B, guidance=guidance)
    sol = solve_quasistatic(B, 2000.0, 500.0, omega=300.0, omega_outer=omega_outer, control="equilibrium",
                            cage="rigid", rigid_cage=cage, inertia_check=False, **QUICK)
    ring = sol.omega if guidance == "inner_land" else sol.omega_outer
    assert sol.cage["ring_speed"] == ring and abs(sol.cage["land_torque"] * ring) > 0.1 * sol.cage_power
    assert abs(sol.energy_residual) < 1e-8
    m = march_orbit(sol, steps_per_pitch=20)
    assert abs(m["energy_residual"]) < 0.01


def test_a_cycling_kinematics_iteration_settles_with_half_steps(monkeypatch):
    """The caged ACBB-120 under race control at 25,000 rpm: the plain iteration between the ring equilibrium and
    the kinematics cycles between two cage speeds 10 % apart (1028.7 and 1131.7 rad/s, after its 40 iterations);
    half steps past them settle it (the fixed point kept), without a warning; with no half steps allowed, the
    unsettled iterate warns."""
    import warnings

    from exudyn_bearing.solvers.quasistatic import solve as qs
    kw = dict(omega=2618.0, control="outer", cage="rigid", inertia_check=False, **QUICK)
    with warnings.catch_warnings():
        warnings.simplefilter("error", qs.KinematicsIterationWarning)
        s = solve_quasistatic("ACBB-120", 0.0, 22240.0, **kw)
    assert 40 < s.iterations < 40 + qs.RELAXED_ITERATIONS      # it needed the half steps, and settled
    again = solve_quasistatic("ACBB-120", 0.0, 22240.0, start=s, **kw)
    assert again.cage["speed"] == pytest.approx(s.cage["speed"], rel=1e-6)
    monkeypatch.setattr(qs, "RELAXED_ITERATIONS", 0)
    with pytest.warns(qs.KinematicsIterationWarning, match="^control: the ball kinematics did not settle"):
        solve_quasistatic("ACBB-120", 0.0, 22240.0, **kw)
