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
    c = caged.cage
    assert np.all(caged.kinematics[:, 0] == c["speed"])
    assert np.all(caged.balls["control_used"] == "equilibrium")
    torque, scale = cage_torque(caged)
    assert scale > 0.1 * abs(c["land_torque"]) > 0.0          # pocket forces and land both act
    assert abs(torque) < 1e-9 * scale
    assert abs(c["torque_residual"]) < 1e-9
    # each ball's tractions along the orbit and its pocket force balance; power: drive = contacts + cage
    for j in range(B.n_balls):
        cont = km.ball_contacts(caged.kinematics[j], caged.contact_geometry[j], caged.traction_model,
                                caged.n_strips, caged.n_across)
        assert abs(cont[0, 6] + cont[1, 6] + caged.balls["pocket_force"][j]) < 1e-9 * caged.q_max_inner
    assert caged.cage_power > 0.0
    assert abs(caged.energy_residual) < 1e-8


def test_losses_come_from_the_cage_balance(caged):
    pl = power_losses(caged)
    c = caged.cage
    rb = caged.contact_geometry[:, km.G_RB]
    w = np.hypot(caged.kinematics[:, 1], caged.kinematics[:, 2])
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


@pytest.mark.parametrize("kw, name", [
    ({"cage": "rigid", "control": "min-energy"}, "control"),
    ({"cage": "torus"}, "cage"),
    ({"rigid_cage": IDEAL}, "rigid_cage"),
    ({"cage": "rigid", "rigid_cage": "brass"}, "rigid_cage"),
])
def test_bad_cage_input(kw, name):
    with pytest.raises(InputError, match=f"^{name}:"):
        solve_quasistatic(B, 3000.0, omega=500.0, **QUICK, **kw)


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
    assert d["cage"] == "rigid" and len(set(d["orbital_speed"])) == 1
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
