"""Energy balance: the traction over the contact ellipse takes from the bodies
exactly the power it dissipates (docs/theory/tangential.md), so that in the
quasi-static traction equilibrium the power that drives the rings equals the
contact dissipation, and a dynamic run's drive work equals its dissipated work
plus the change of kinetic energy."""
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.model.layout import GLOBAL_FIELDS


@pytest.fixture(scope="module")
def thrust_6208():
    """The 6208 under 3000 N thrust at 500 rad/s, traction equilibrium (Lambda traction, 16 x 4 points)."""
    return eb.solve_quasistatic("6208", Fa=3000.0, omega=500.0, control="equilibrium", n_strips=16, n_across=4,
                                fixed={"tilt_x": 0.0, "tilt_y": 0.0}, stiffness=False)


def test_quasistatic_traction_equilibrium_conserves_energy(thrust_6208):
    # every ball in its steady Newton-Euler balance takes no net power: drive power = dissipation
    # (the residual is the root solver's, 1e-8 of the load in the scaled equations)
    sol = thrust_6208
    assert sol.dissipation_total > 1.0
    assert sol.friction_torque > 0.0
    assert abs(sol.energy_residual) < 1e-6


def test_a_kinematic_hypothesis_shows_as_an_energy_residual():
    # outer-race control fixes the ball's speeds without its traction balance: the balls take net power
    # from the traction, which the residual reports (it is no round-off: above 1 %)
    sol = eb.solve_quasistatic("6208", Fa=3000.0, omega=500.0, control="outer", n_strips=16, n_across=4,
                               fixed={"tilt_x": 0.0, "tilt_y": 0.0}, stiffness=False)
    assert abs(sol.energy_residual) > 0.01


def test_dynamic_drive_work_equals_dissipation_at_the_ellipse_level(thrust_6208):
    # from the traction equilibrium the reference engine stays near it: over the second half of the run the
    # rings' drive work = friction and damping dissipation + kinetic-energy change within 1 % (the engine
    # integrates the powers with the step's end value, an O(dt) quadrature of a steady power)
    sc = eb.Scenario(Fa=3000.0, Fr=0.0, omega=500.0, t_end=0.01, dt=2e-6, sample_dt=5e-4, cage=False,
                     traction_level="ellipse", n_strips=16, n_across=4, initial="quasistatic",
                     control="equilibrium")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        run = eb.simulate("6208", sc)
    g = run.data["glob"]
    i0 = len(run.data["t"]) // 2
    col = {k: GLOBAL_FIELDS.index(k) for k in ("drive_work", "dissipated_work", "kinetic_energy", "friction_power")}
    drive = g[-1, col["drive_work"]] - g[i0, col["drive_work"]]
    diss = g[-1, col["dissipated_work"]] - g[i0, col["dissipated_work"]]
    dke = g[-1, col["kinetic_energy"]] - g[i0, col["kinetic_energy"]]
    assert drive > 0.0
    assert abs(drive - diss - dke) < 0.01 * drive
    # and the dissipation is the quasi-static equilibrium's (same traction, same integration)
    t = run.data["t"][-1] - run.data["t"][i0]
    assert np.mean(g[i0:, col["friction_power"]]) == pytest.approx(thrust_6208.dissipation_total, rel=0.01)
    assert drive / t == pytest.approx(thrust_6208.drive_power, rel=0.01)
