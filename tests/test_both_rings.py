"""Quasi-static solver with the outer ring turning: both rings at one speed (a rigid-body rotation) and the
outer ring alone (the kinematic cage speed)."""
import pytest

from exudyn_bearing import catalog
from exudyn_bearing.cli import main
from exudyn_bearing.physics import kinematics
from exudyn_bearing.solvers.quasistatic import solve_quasistatic


def test_both_rings_at_one_speed_turn_the_balls_with_them():
    # no race moves relative to the other: the whole bearing turns as one body, every ball orbits at the
    # ring speed without spinning in its orbit frame, and nothing slips or dissipates
    w = 500.0
    s = solve_quasistatic("6208", 3000.0, omega=w, omega_outer=w, ring_growth=False, stiffness=False)
    bl, b = s.balls, catalog["6208"]
    assert bl["orbital_speed"] == pytest.approx([w] * b.n_balls, rel=1e-12)
    assert bl["ball_speed"] == pytest.approx([0.0] * b.n_balls, abs=1e-9)
    assert bl["ball_speed_absolute"] == pytest.approx([w] * b.n_balls, rel=1e-12)
    # the centrifugal force the equilibrium applied is the one of that orbital speed, m r_c w^2
    assert bl["centrifugal_force"] == pytest.approx(b.ball_mass * bl["ball_center_r"] * w ** 2, rel=1e-12)
    assert s.dissipation_total == 0.0


def test_cli_prints_the_orbital_speed_of_both_rings_turning(capsys):
    assert main(["quasistatic", "6208", "--Fr", "3000", "--omega", "500", "--omega-outer", "500"]) == 0
    lines = [line.split() for line in capsys.readouterr().out.splitlines()]
    header = next(cols for cols in lines if cols[:2] == ["ball", "psi"])
    row = next(cols for cols in lines if cols[:1] == ["0"])
    # ball 0's orbital speed, found by its column name
    assert float(row[header.index("w_orbit")]) == pytest.approx(500.0)


@pytest.mark.parametrize("w_i, w_o", [(0.0, 500.0), (500.0, 0.0)])
# the default 16 x 4 traction grid, expected not converged to 1 % here
@pytest.mark.filterwarnings("ignore::exudyn_bearing.solvers.quasistatic.solve.TractionResolutionWarning")
def test_one_ring_turning_orbits_at_the_kinematic_cage_speed(w_i, w_o):
    # pure rolling (race control, light radial load, contact angle 0):
    # omega_c = omega_i (1 - gamma)/2 + omega_o (1 + gamma)/2, gamma = D cos(alpha)/d_m
    # (physics.kinematics.cage_speed: 301.98 rad/s with the outer ring alone, 198.02 with the inner).
    # The solver rolls on the loaded contact radii (overlaps of a few um on a 6.35 mm ball): 2e-3 covers that.
    b = catalog["6208"]
    s = solve_quasistatic("6208", 100.0, omega=w_i, omega_outer=w_o, ring_growth=False, stiffness=False)
    expected = float(kinematics.cage_speed(w_i, w_o, b.ball_radius, b.pitch_radius, 0.0))
    assert s.balls["orbital_speed"][0] == pytest.approx(expected, rel=2e-3)
    # the cage follows the faster race: above half the ring speed when the outer ring turns
    assert (s.balls["orbital_speed"][0] > 0.5 * 500.0) == (w_o > 0.0)
    spin = abs(float(kinematics.ball_spin_relative(w_i, w_o, b.ball_radius, b.pitch_radius, 0.0)))
    assert s.balls["ball_speed"][0] == pytest.approx(spin, rel=2e-3)
