"""Thermal network (physics/thermal.py) and the thermal quasi-static solve (solvers/quasistatic/thermal.py):
docs/theory/thermal.md."""
import json
import math
import re
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.cli import main
from exudyn_bearing.physics import thermal as th
from exudyn_bearing.physics.lubricant_properties import properties_at
from exudyn_bearing.solvers.quasistatic.thermal import ThermalConvergenceWarning, ThermalRunawayError

#: The DEM papers' 6208 at 500 rad/s, oil in at 40 C, 0.6 l/min (fast: lambda traction, 9 balls).
CASE = {"Fr": 3000.0, "omega": 500.0, "oil_inlet_temperature": 313.15, "ambient_temperature": 293.15}


def test_two_node_network_by_hand():
    # node 1 makes Q and conducts through G12 to node 2, which loses it through g to T0:
    # T2 = T0 + Q / g, T1 = T2 + Q / G12 (series resistances)
    q, g12, g, t0 = 50.0, 2.0, 5.0, 300.0
    t = th.network_temperatures([[0.0, g12], [g12, 0.0]], [q, 0.0], [[0.0], [g]], [t0])
    assert t[1] == pytest.approx(t0 + q / g, rel=1e-12)
    assert t[0] == pytest.approx(t0 + q / g + q / g12, rel=1e-12)
    assert th.network_heat_out(t, [[0.0], [g]], [t0])[0] == pytest.approx(q, rel=1e-12)


def test_relations_by_hand():
    # Holm: two equal half-spaces behind a disc of radius r in series, 1/(4 k r) each: G = 2 k r
    assert th.constriction_conductance(4e-3, 1e-3, 40.0, 40.0) == pytest.approx(2 * 40.0 * 2e-3, rel=1e-12)
    # Incropera eq. 7.30: laminar plate, Re = 1e4, Pr = 8: Nu = 0.664 * 100 * 2 = 132.8
    assert th.flat_plate_heat_transfer(0.1, 1.0, 1e-6, 8.0, 0.01) == pytest.approx(132.8 * 0.1 / 0.01, rel=1e-12)
    # Blok: equal speeds and materials share half and half
    assert th.contact_heat_share(3.0, 3.0) == pytest.approx(0.5, rel=1e-15)
    assert th.oil_enthalpy_flow(0.01, 2000.0, 330.0, 310.0) == pytest.approx(400.0, rel=1e-12)
    # Fourier across a film: k A / h = 0.13 * 2e-3 / 1e-4 = 2.6 W/K
    assert th.film_conductance(0.13, 2e-3, 1e-4) == pytest.approx(2.6, rel=1e-12)
    # sphere against a wall, parallel columns: the integral of k 2 pi r / (c + r^2 / (2 R)) over 0..R, by
    # the trapezoidal rule on 200001 points (error about 1e-9 relative), against the closed form
    k, r_s, c = 0.13, 6e-3, 3e-5
    r = np.linspace(0.0, r_s, 200001)
    f = k * 2 * math.pi * r / (c + r * r / (2 * r_s))
    quad = float(np.sum(0.5 * (f[1:] + f[:-1]) * np.diff(r)))
    assert th.sphere_wall_gap_conductance(k, r_s, c) == pytest.approx(quad, rel=1e-6)
    assert th.sphere_wall_gap_conductance(k, r_s, math.inf) == 0.0  # no film: no conduction


@pytest.fixture(scope="module")
def solved():
    return {q: eb.solve_thermal("6208", oil_flow=q, **CASE) for q in (1e-5, 4e-5)}


def test_energy_balance_at_convergence(solved):
    r = solved[1e-5]
    assert r.converged
    # every loss is heat at a node: the network's heat is the power loss of the last quasi-static solve
    assert sum(r.heat.values()) == pytest.approx(r.power_loss_total, rel=1e-12)
    # heat in = heat out through the oil and the ambient: the linear network solve balances it to round-off
    assert sum(r.heat_out.values()) == pytest.approx(sum(r.heat.values()), rel=1e-9)
    # the oil's share is m_dot c_p (T_out - T_in), by hand from the lubricant's properties; the network took
    # c_p at the last iterate's oil temperature, within the 0.01 K tolerance of T_out: c_p changes by about
    # 0.2 %/K (Cragoe: 0.00339 / 1.685 per K), so the two agree to 2e-5, asserted to 1e-4
    t_out = r.temperatures["oil"]
    m_dot = properties_at("guessasma2018", CASE["oil_inlet_temperature"])["density"] * 1e-5
    c_p = properties_at("guessasma2018", t_out)["specific_heat"]
    assert r.heat_out["oil"] == pytest.approx(m_dot * c_p * (t_out - CASE["oil_inlet_temperature"]), rel=1e-4)
    # the iteration stopped on its tolerance (0.01 K): the temperatures are a fixed point to that
    assert r.history[-1]["change"] < 0.01


def test_more_oil_flow_cools(solved):
    lo, hi = solved[1e-5], solved[4e-5]
    t_in = CASE["oil_inlet_temperature"]
    assert t_in < hi.temperatures["oil"] < lo.temperatures["oil"]
    # the hottest solid is above the oil it gives its heat to
    assert max(lo.temperatures[k] for k in ("inner", "outer", "ball")) > lo.temperatures["oil"]


def test_bad_input_errors():
    with pytest.raises(eb.InputError, match=r"oil_flow: a jet-lubricated bearing needs an oil flow > 0"):
        eb.solve_thermal("6208", oil_flow=0.0, **CASE)
    with pytest.raises(eb.InputError, match=r"oil_inlet_temperature: 450 K is outside the range of lubricant "
                                            r"'guessasma2018' \(258.15-393.15 K\)"):
        eb.solve_thermal("6208", oil_flow=1e-5, **{**CASE, "oil_inlet_temperature": 450.0})


def test_runaway_and_non_convergence_name_the_temperature():
    # a trickle of oil at 1500 rad/s cannot carry the heat out below the oil's 393.15 K limit
    with pytest.raises(ThermalRunawayError, match=r"thermal runaway, the \w+ node reached \d+\.\d K"):
        eb.solve_thermal("6208", oil_flow=1e-8, **{**CASE, "omega": 1500.0})
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = eb.solve_thermal("6208", oil_flow=1e-5, max_iterations=1, **CASE)
    assert not r.converged
    msgs = [str(w.message) for w in caught if issubclass(w.category, ThermalConvergenceWarning)]
    assert len(msgs) == 1
    assert re.search(r"not converged in 1 iterations .* temperatures reached inner \d+\.\d K", msgs[0])


def test_json_keys(solved):
    d = solved[1e-5].to_dict()
    assert set(d["temperatures"]) == {"inner", "outer", "ball", "oil", "cage"}  # the catalogue 6208 has a cage
    assert math.isfinite(d["power_loss_total"]) and "temperatures" in d["units"]
    assert np.isclose(d["power_loss_total"], sum(v for v in d["power_loss"].values() if isinstance(v, float)))


def test_cli_thermal_json(capsys):
    args = ["quasistatic", "6208", "--Fr", "3000", "--omega", "500", "--thermal", "--oil-inlet-temperature",
            "313.15", "--oil-flow", "1e-5"]
    assert main(args + ["--json"]) in (0, None)
    d = json.loads(capsys.readouterr().out)
    assert set(d["temperatures"]) == {"inner", "outer", "ball", "oil", "cage"} and d["thermal"]["converged"]
    assert d["power_loss_total"] > 0.0 and "friction_torque_total" in d
    # --thermal without the oil flow is a one-line error naming the flag
    assert main(args[:-2]) != 0
    assert "--oil-flow: needed with --thermal" in capsys.readouterr().err


# ---------------------------------------------------------------------------------------------------------
# the cage node (docs/theory/thermal.md, "The cage")
# ---------------------------------------------------------------------------------------------------------
def test_cage_node_energy_balance_and_split():
    # an outer-land-guided cage: pocket and land friction both generate heat
    r = eb.solve_thermal("6208", oil_flow=1e-5, cage_guidance="outer_land", tolerance=1e-4, **CASE)
    assert r.converged and set(r.temperatures) == {"inner", "outer", "ball", "oil", "cage"}
    pl = r.losses["power_loss"]
    assert pl["cage_pocket"] > 0.0 and pl["cage_land"] > 0.0
    # heat in = heat out (oil + ambient) to the round-off of the 5 x 5 solve, and every loss is heat at a node
    assert sum(r.heat.values()) == pytest.approx(r.power_loss_total, rel=1e-12)
    assert sum(r.heat_out.values()) == pytest.approx(sum(r.heat.values()), rel=1e-9)
    # the split: the cage gets half of the pocket heat and half of the land heat; the oil only drag + churning
    assert r.heat["cage"] == pytest.approx(0.5 * pl["cage_pocket"] + 0.5 * pl["cage_land"], rel=1e-12)
    assert r.heat["oil"] == pytest.approx(pl["drag"] + pl["churning"], rel=1e-9)
    # the land film by hand: k_oil 2 pi r_land w / c with the default land (R_o - D/4, width D/2, 0.4 % of r)
    b = eb.load_bearing("6208")
    d = 2 * b.ball_radius
    r_land = b.outer_race_radius - 0.25 * d
    k_oil = properties_at("guessasma2018", r.temperatures["oil"])["thermal_conductivity"]
    # k_oil at the converged oil temperature; the network took it at the last iterate's, within 1e-4 K
    assert r.conductances["outer_cage"] == pytest.approx(k_oil * 2 * math.pi * r_land * 0.5 * d / (0.004 * r_land),
                                                         rel=1e-6)
    # the cage's own balance: its heat leaves through its three links (a check of the assembled matrix)
    t = r.temperatures
    out = (r.conductances["ball_cage"] * (t["cage"] - t["ball"]) + r.conductances["cage_oil"] * (t["cage"] - t["oil"])
           + r.conductances["outer_cage"] * (t["cage"] - t["outer"]))
    assert out == pytest.approx(r.heat["cage"], rel=1e-9)
    # the cage carries the land's heat: it is the hottest node
    assert t["cage"] == max(t.values())


def test_isolated_cage_without_losses_sits_at_the_oil_and_changes_nothing():
    # a ball-guided cage without pocket friction (no cage heat) and without pocket film (infinite clearance):
    # its only link is the oil, so it takes the oil's temperature, and the other four nodes are those of the
    # network without a cage; tolerance 1e-6 K on both runs, so the fixed points agree to about that
    kw = dict(oil_flow=1e-5, tolerance=1e-6, **CASE)
    ref = eb.solve_thermal("6208", cage_guidance="none", **kw)
    iso = eb.solve_thermal("6208", cage_guidance="ball", cage_pocket_clearance=math.inf,
                           loss_options={"cage_pocket_friction": 0.0}, **kw)
    assert "cage" not in ref.temperatures and "cage" not in ref.heat
    assert set(ref.conductances) == {"inner_ball", "outer_ball", "inner_oil", "outer_oil", "ball_oil",
                                     "inner_ambient", "outer_ambient", "oil_outflow", "n_balls"}
    assert iso.conductances["ball_cage"] == 0.0 and iso.heat["cage"] == 0.0
    assert iso.temperatures["cage"] == pytest.approx(iso.temperatures["oil"], abs=1e-9)
    for n in ("inner", "outer", "ball", "oil"):
        assert iso.temperatures[n] == pytest.approx(ref.temperatures[n], abs=1e-5)
    # a cageless run without cage losses: the cage's components are 0 and the oil gets drag + churning only
    assert ref.losses["power_loss"]["cage_pocket"] == 0.0 and ref.losses["power_loss"]["cage_land"] == 0.0


def test_cage_pocket_share_moves_heat_between_cage_and_balls():
    kw = dict(oil_flow=1e-5, cage_guidance="outer_land", **CASE)
    to_cage = eb.solve_thermal("6208", cage_pocket_heat_share=1.0, **kw)
    to_ball = eb.solve_thermal("6208", cage_pocket_heat_share=0.0, **kw)
    assert to_cage.heat["cage"] == pytest.approx(to_cage.losses["power_loss"]["cage_pocket"]
                                                 + 0.5 * to_cage.losses["power_loss"]["cage_land"], rel=1e-12)
    assert to_ball.heat["cage"] == pytest.approx(0.5 * to_ball.losses["power_loss"]["cage_land"], rel=1e-12)
    assert to_cage.temperatures["cage"] > to_ball.temperatures["cage"]


@pytest.mark.parametrize("kw, match", [
    ({"cage_pocket_clearance": -1e-5}, r"cage_pocket_clearance: must be > 0 m"),
    ({"cage_pocket_clearance": 0.0}, r"cage_pocket_clearance: must be > 0 m"),
    ({"cage_pocket_heat_share": 1.5}, r"cage_pocket_heat_share: must lie in \[0, 1\]"),
    ({"cage_guidance": "outer_land", "loss_options": {"cage_land_clearance": -1e-5}},
     r"cage_land_clearance: must be > 0"),
    ({"loss_options": {"oil_volume_fraction": 0.1}}, r"loss_options: 'oil_volume_fraction' is set by solve_thermal"),
])
def test_cage_bad_input(kw, match):
    with pytest.raises(eb.InputError, match=match):
        eb.solve_thermal("6208", oil_flow=1e-5, **CASE, **kw)


def test_cageless_bearing_with_a_cage_needs_its_pocket_clearance():
    # the catalogue ACBB-120 has no cage geometry: a land-guided cage needs the pocket clearance given
    with pytest.raises(eb.InputError, match=r"cage_pocket_clearance: bearing 'ACBB-120' has no cage geometry"):
        eb.solve_thermal("ACBB-120", Fa=22240.0, omega=1000.0, oil_inlet_temperature=394.0, oil_flow=6e-5,
                         cage_guidance="outer_land")
