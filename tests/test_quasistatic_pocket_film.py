"""The pocket oil film in the quasi-static solver with the rigid cage (docs/theory/quasistatic.md#the-pocket-film)."""
import json

import numpy as np
import pytest

from exudyn_bearing import Scenario, catalog
from exudyn_bearing.cli import main
from exudyn_bearing.data import InputError
from exudyn_bearing.data.cages import estimated_cage
from exudyn_bearing.data.catalog import default_lubricant
from exudyn_bearing.physics import pocket_film as pf
from exudyn_bearing.simulate import _quasistatic_start_cage
from exudyn_bearing.solvers.quasistatic import solve_quasistatic
from exudyn_bearing.solvers.quasistatic.losses import power_losses
from exudyn_bearing.solvers.quasistatic.pocket_film import PocketFilm
from exudyn_bearing.solvers.quasistatic.thermal import CAGE_NODE, solve_thermal

B = catalog["6208"]
RC = estimated_cage(B)
LUB = default_lubricant(B)
QUICK = {"stiffness": False, "resolution_check": False}
CASE = dict(omega=500.0, cage="rigid", **QUICK)  # the 6208 radial case at 3000 N with its estimated cage


@pytest.fixture(scope="module")
def race():
    """Race control (Jones' criterion), dry pockets and with the film."""
    return (solve_quasistatic(B, 3000.0, **CASE), solve_quasistatic(B, 3000.0, pocket_film=True, **CASE))


def centred_shear(sol):
    """2 C(c_p) |w|^2 per ball: the two walls' shear of a ball centred in its pocket (Goldman, Cox & Brenner's
    C of physics/pocket_film.py at the gap c_p), w the held ball's rotation relative to the cage."""
    _a, _b, c = pf.shear_resistance(LUB.viscosity, B.ball_radius, RC.pocket_clearance)
    return 2.0 * c * (sol.kinematics[:, 1] ** 2 + sol.kinematics[:, 2] ** 2)


def test_film_off_is_the_dry_solution(race):
    dry, _ = race
    off = solve_quasistatic(B, 3000.0, pocket_film=False, **CASE)
    a, b = dry.to_dict(), off.to_dict()
    for k in ("q_inner", "orbital_speed", "pocket_force", "dissipation_inner_ball", "cage_speed", "cage_power_pocket",
              "cage_power_land", "power_loss_total"):
        assert np.array_equal(a[k], b[k]), k
    assert not dry.cage["pocket_film"] and dry.cage["power_pocket_film"] == 0.0
    assert np.array_equal(dry.balls["pocket_contact_force"], dry.balls["pocket_force"])
    assert power_losses(dry)["cage_pocket_film"] == 0.0


def test_a_centred_ball_is_sheared_by_both_walls():
    film = PocketFilm.of(RC, LUB, B.ball_radius)
    w_r, w_z = 120.0, -1150.0
    c = film.centred(w_r, w_z)
    _a, _b, cc = pf.shear_resistance(LUB.viscosity, B.ball_radius, RC.pocket_clearance)
    assert c["power"] == pytest.approx(2.0 * cc * (w_r ** 2 + w_z ** 2), rel=1e-12)
    assert (c["m_r"], c["m_z"]) == pytest.approx((-2.0 * cc * w_r, -2.0 * cc * w_z), rel=1e-12)
    assert c["f_r"] == pytest.approx(0.0, abs=1e-12) and c["film_force"] == 0.0 and c["contact_force"] == 0.0


def test_a_held_ball_rides_on_the_hydrodynamic_film_until_the_floor():
    film = PocketFilm.of(RC, LUB, B.ball_radius)
    w = 1150.0
    u = 0.5 * B.ball_radius * w
    r_x, alpha = pf.pocket_film_radii(B.ball_radius, RC.pocket_clearance, RC.pocket_shape == "cylindrical")

    def net(h):  # the near film less the far one (gap 2 c_p - h)
        return (pf.hydrodynamic_film_force(LUB.viscosity, u, r_x, alpha, h)
                - pf.hydrodynamic_film_force(LUB.viscosity, u, r_x, alpha, 2.0 * RC.pocket_clearance - h))

    near, carried, contact = film.held_gap(2.0, w)
    assert LUB.composite_roughness < near < RC.pocket_clearance and contact == 0.0
    assert float(net(near)) == pytest.approx(2.0, rel=1e-9)
    top = float(net(LUB.composite_roughness))
    near, carried, contact = film.held_gap(-(top + 5.0), w)  # beyond the film at the floor: the wall's contact
    assert near == LUB.composite_roughness and carried == pytest.approx(top) and contact == pytest.approx(5.0)
    # the thinner near gap shears more than the centred ball (ln(R/h) + ln(R/(2 c_p - h)) >= 2 ln(R/c_p))
    assert film.held(2.0, 0.0, -w)["power"] > film.centred(0.0, -w)["power"]


def test_film_raises_the_pocket_loss_by_at_least_the_centred_shear(race):
    dry, wet = race
    shear = centred_shear(wet)
    assert np.all(wet.balls["pocket_film_power"] >= shear)
    assert wet.cage["power_pocket"] >= float(np.sum(shear)) + 0.0
    assert wet.cage["power_pocket_film"] == pytest.approx(float(np.sum(wet.balls["pocket_film_power"])), rel=1e-12)
    # the film's pressure takes the pocket forces off the walls here: the friction's part goes, the shear stays
    assert np.all(np.abs(wet.balls["pocket_contact_force"]) <= np.abs(wet.balls["pocket_force"]))
    pl = power_losses(wet)
    assert pl["power_loss"]["cage_pocket"] == pytest.approx(wet.cage["power_pocket"], rel=1e-12)
    assert pl["cage_pocket_film"] == pytest.approx(wet.cage["power_pocket_film"], rel=1e-12)
    assert wet.cage["power_pocket"] - wet.cage["power_pocket_film"] < dry.cage["power_pocket"]
    assert abs(wet.cage["torque_residual"]) < 1e-9


def test_film_enters_the_balls_and_the_cages_balances():
    # the traction equilibrium: the drive power goes into the contacts, the pockets (friction and the film's
    # shear) and the land, so the film's moment is in the balls' balance and its loss in the cage's
    sol = solve_quasistatic(B, 3000.0, control="equilibrium", pocket_film=True, **CASE)
    assert sol.cage["power_pocket_film"] > 0.5 * sol.cage["power_pocket"]
    assert abs(sol.energy_residual) < 1e-6 and abs(sol.cage["torque_residual"]) < 1e-9


@pytest.mark.parametrize("kw", [{"cage": None}, {"cage": "rigid", "pocket_film": "yes"}])
def test_refusals_name_pocket_film(kw):
    with pytest.raises(InputError, match="^pocket_film:"):
        solve_quasistatic(B, 3000.0, omega=500.0, **QUICK, **{"pocket_film": True, **kw})


def test_without_oil_the_scene_refuses_pocket_film():
    with pytest.raises(InputError, match="^pocket_film:"):
        Scenario(cage="rigid", pocket_film=True, lubrication=False)


def test_cli_pocket_film(capsys):
    assert main(["quasistatic", "6208", "--Fr", "3000", "--omega", "500", "--pocket-film"]) != 0
    assert "pocket_film" in capsys.readouterr().err
    assert main(["quasistatic", "6208", "--Fr", "3000", "--omega", "500", "--cage", "rigid", "--pocket-film",
                 "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["pocket_film"] and d["cage_pocket_film"] > 0.0
    assert d["power_loss"]["cage_pocket"] >= d["cage_pocket_film"]


def test_the_quasistatic_start_and_the_thermal_network_take_the_film():
    kw, why = _quasistatic_start_cage(B, Scenario(cage="rigid", pocket_film=True), 500.0)
    assert kw["pocket_film"] is True and "pocket film" in why
    assert "pocket_film" not in _quasistatic_start_cage(B, Scenario(cage="rigid"), 500.0)[0]
    common = {"omega": 500.0, "oil_inlet_temperature": 313.15, "oil_flow": 1e-6, "cage": "rigid"}
    r = solve_thermal(B, 3000.0, pocket_film=True, **common)
    assert CAGE_NODE in r.temperatures and r.quasistatic.cage["pocket_film"]
    assert r.losses["power_loss"]["cage_pocket"] == pytest.approx(r.quasistatic.cage["power_pocket"], rel=1e-12)
    assert r.losses["cage_pocket_film"] > 0.0
