"""Rolling resistance and ball drag as forces in the dynamic engines (docs/theory/losses.md, "In the
dynamic engines"): switched off they leave the contact kernel's forces unchanged (to round-off); switched on,
the rolling resistance is a moment pair of magnitude (F_h + 2 F_R) R_x at every loaded contact and
the drag the force 1/2 C_D rho A v^2 on every ball, both taking from the bodies exactly the power the
engines report, and a steady run reports the quasi-static solver's rolling and drag losses."""
import math
import warnings

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing.data import InputError
from exudyn_bearing.model import layout as L
from exudyn_bearing.model.contact import scene_loss_path, scene_paths
from exudyn_bearing.model.motion import ring_poses
from exudyn_bearing.physics import losses as ls
from exudyn_bearing.physics.geometry import raceway_radii
from exudyn_bearing.physics.hertz import material_reduced_modulus
from exudyn_bearing.solvers.reference.engine import ReferenceEngine
from exudyn_bearing.solvers.reference.integrators import evaluate

OMEGA = 500.0


def _evaluate(engine, loss_path, state=None, t=0.0):
    """All forces of the engine's scene at its initial state (or ``state``) at time t, with the
    rolling-resistance / drag code compiled in (``loss_path`` True) or not (None); diagnostics on."""
    st = engine.initial_state() if state is None else state
    z = engine.bearing.n_balls
    out = {"fb": np.zeros((z, 3)), "tb": np.zeros((z, 3)), "fc": np.zeros((z, 3)), "fr": np.zeros((2, 6)),
           "glob": np.zeros(L.NGLOBAL), "diag": np.zeros((z, 2, L.NDIAG)), "cage_load": np.zeros((z, 2))}
    rings = ring_poses()
    defect_path, ellipse_path = scene_paths(engine.params)
    out["worst"] = evaluate(t, engine.params, engine.table, st["xb"].copy(), st["vb"].copy(), st["wb"].copy(), st["xc"].copy(),
             st["vc"].copy(), st["ring"].copy(), rings, st["hist"].copy(), st["hz"].copy(), out["fb"], out["tb"],
             out["fc"], out["fr"], np.zeros(3), out["glob"], out["diag"], out["cage_load"], True, defect_path,
             ellipse_path, loss_path)
    out["rings"] = rings
    out["state"] = st
    return out


def _scene(**kw):
    sc = eb.Scenario(Fr=3000.0, omega=OMEGA, dt=2e-6, ring_growth=False, **kw)
    return ReferenceEngine("6208", sc)


@pytest.mark.parametrize("level", ["point", "ellipse"])
def test_switched_off_the_forces_equal_the_kernel_without_the_loss_code(level):
    # the same scene evaluated by the specialisation without the new code (loss_path None, what the
    # reference engine runs for a default scene) and by the one with it compiled in but switched off
    # (what the Exudyn element runs): every output the same. Not asserted to the last bit: the two are
    # separately compiled functions, and with contraction allowed (fast-math 'contract') the compiler may
    # fuse a multiply-add in one and not the other on some CPU; 1e-12 of each array's scale is far below
    # any effect of the new code (its smallest term, the hysteresis moment, is ~1e-3 of the friction's)
    eng = _scene(traction_level=level)
    assert scene_loss_path(eng.params) is None
    a, b = _evaluate(eng, None), _evaluate(eng, True)
    for k in ("fb", "tb", "fc", "fr", "glob", "cage_load", "diag"):
        scale = float(np.nanmax(np.abs(a[k]))) if np.any(np.isfinite(a[k])) else 0.0
        assert np.allclose(a[k], b[k], rtol=1e-12, atol=1e-12 * scale, equal_nan=True), k
    assert a["glob"][L.G_EHL_POWER] == a["glob"][L.G_HYST_POWER] == a["glob"][L.G_DRAG_POWER] == 0.0


def test_a_kernel_compiled_without_the_loss_code_refuses_a_scene_that_needs_it():
    # the NaN on which the engines stop, not a run without the asked-for losses
    for kw in (dict(rolling_resistance=True), dict(ball_drag=True)):
        eng = _scene(**kw)
        assert scene_loss_path(eng.params) is True
        assert math.isnan(_evaluate(eng, None)["worst"])


@pytest.mark.parametrize("level", ["point", "ellipse"])
def test_rolling_resistance_is_a_moment_pair_of_the_hand_magnitude(level):
    # the 6208's analytic state at 500 rad/s (balls at their kinematic speeds): with the switch on, the
    # forces change by moments only; the balls' moments are minus the rings'; each contact dissipates
    # |M| |roll| with |M| = (F_h + 2 F_R) R_x from physics.losses at the contact's load, ellipse, rolling
    # speed and R_x (raceway_radii at its contact angle); all of it is the power the moments take
    # from the bodies
    off = _evaluate(_scene(traction_level=level), True)
    eng = _scene(traction_level=level, rolling_resistance=True)
    on = _evaluate(eng, True)
    b, lub = eng.bearing, eng.lubricant
    d_fb, d_tb, d_fr = on["fb"] - off["fb"], on["tb"] - off["tb"], on["fr"] - off["fr"]
    scale = float(np.max(np.abs(d_tb)))
    assert scale > 0.0
    assert np.max(np.abs(d_fb)) < 1e-12 * np.max(np.abs(off["fb"]))       # no force (round-off of the sums)
    assert np.max(np.abs(d_fr[:, :3])) < 1e-12 * np.max(np.abs(off["fr"][:, :3]))
    assert np.allclose(d_tb.sum(axis=0), -(d_fr[0, 3:] + d_fr[1, 3:]), rtol=0.0, atol=1e-12 * scale)
    e_prime = material_reduced_modulus(b.material)
    diag = on["diag"]
    v_reg = eng.params[L.P_VREG]
    n_loaded = 0
    for race, inner in ((0, True), (1, False)):
        rho, _z = b.inner_groove_center if inner else b.outer_groove_center
        r_c = b.inner_groove_radius if inner else b.outer_groove_radius
        for j in range(b.n_balls):
            q = diag[j, race, L.D_LOAD]
            if q <= 0.0:
                assert diag[j, race, L.D_ROLLRES] == 0.0
                continue
            n_loaded += 1
            alpha = diag[j, race, L.D_ANGLE]
            r_contact = abs(rho - r_c * math.cos(alpha)) if inner else rho + r_c * math.cos(alpha)
            r_x = raceway_radii(b.ball_radius, r_c, r_contact, alpha, inner)[0]
            a_ax, b_ax, u_r, roll = (diag[j, race, k] for k in (L.D_A, L.D_B, L.D_UR, L.D_ROLL))
            assert r_x * abs(roll) > v_reg      # rolling: beyond the regularised band
            f_h = ls.hysteresis_rolling_force(q, b_ax, r_x, ls.HYSTERESIS_LOSS_FACTOR_STEEL)
            f_r = ls.ehl_rolling_force(u_r, q, r_x, a_ax / b_ax, e_prime, lub.viscosity, lub.pressure_viscosity)
            # at the contact's normal force (the diagnostic "load"); 1e-9: rounding of the power laws
            assert diag[j, race, L.D_ROLLRES] == pytest.approx((f_h + 2.0 * f_r) * r_x * abs(roll), rel=1e-9)
    assert n_loaded >= 4
    g = on["glob"]
    power = g[L.G_EHL_POWER] + g[L.G_HYST_POWER]
    assert power == pytest.approx(float(np.sum(diag[:, :, L.D_ROLLRES])), rel=1e-12)
    # the power the moments take from the balls and rings: -(sum M_b . w_b + sum M_r . w_r)
    w_rings = on["rings"][:, 15:18]
    taken = -(float(np.sum(d_tb * on["state"]["wb"])) + float(np.sum(d_fr[:, 3:] * w_rings)))
    assert taken == pytest.approx(power, rel=1e-9)


def test_ball_drag_is_the_hand_force_against_the_ball_velocity():
    # oil fraction 0.05: density 0.05 * 860 + 0.95 * 1.204, viscosity of the mixture; each ball's force
    # change is 1/2 C_D rho (pi D^2 / 4) v^2 against its velocity (outer ring at rest), C_D of the
    # standard drag curve (Clift, Grace & Weber: 24/Re (1 + 0.15 Re^0.687) up to Re = 1000, 0.44 above),
    # and the outer ring takes the reaction
    phi = 0.05
    off = _evaluate(_scene(), True)
    eng = _scene(ball_drag=True, oil_volume_fraction=phi)
    on = _evaluate(eng, True)
    b = eng.bearing
    rho = phi * 860.0 + (1.0 - phi) * 1.204
    eta = phi * eng.lubricant.viscosity + (1.0 - phi) * 1.81e-5
    d = 2.0 * b.ball_radius
    vb = on["state"]["vb"]
    d_fb = on["fb"] - off["fb"]
    total = 0.0
    for j in range(b.n_balls):
        v = float(np.linalg.norm(vb[j]))
        re = rho * v * d / eta
        cd = 24.0 / re * (1.0 + 0.15 * re ** 0.687) if re <= 1000.0 else 0.44
        f = 0.5 * cd * rho * math.pi * d * d / 4.0 * v * v
        assert np.allclose(d_fb[j], -f * vb[j] / v, rtol=1e-9, atol=1e-12 * f)
        total += f * v
    assert on["glob"][L.G_DRAG_POWER] == pytest.approx(total, rel=1e-9)
    d_fr = on["fr"] - off["fr"]
    assert np.allclose(d_fr[1, :3], -d_fb.sum(axis=0), rtol=1e-9, atol=1e-15)
    x = on["state"]["xb"]  # outer ring centred at the origin
    assert np.allclose(d_fr[1, 3:], -np.cross(x, d_fb).sum(axis=0), rtol=1e-9, atol=1e-15)
    assert np.array_equal(d_fr[0], np.zeros(6))
    assert np.array_equal(on["tb"], off["tb"])


def _steady_summary(engine, t_end):
    sc = eb.Scenario(Fr=3000.0, omega=OMEGA, t_end=t_end, dt=2e-6, sample_dt=1e-4, rolling_resistance=True,
                     ball_drag=True, oil_volume_fraction=0.05)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return eb.simulate("6208", sc, engine=engine).summary(fraction=0.5)


@pytest.fixture(scope="module")
def quasistatic_losses():
    from exudyn_bearing.solvers.quasistatic.losses import power_losses

    sol = eb.solve_quasistatic("6208", Fr=3000.0, omega=OMEGA)
    return power_losses(sol, oil_volume_fraction=0.05)["power_loss"]


@pytest.mark.parametrize("engine,t_end", [("reference", 0.004), ("exudyn", 0.002)])
def test_steady_run_reports_the_quasistatic_rolling_and_drag_losses(engine, t_end, quasistatic_losses):
    # the same relations at the dynamic contacts: within 3 %, the spread of the dynamic window against the
    # quasi-static equilibrium (the loads oscillate with the ball passage and F_R ~ Q^0.47 u^0.66 is
    # averaged over 10-20 samples; the point level's balls orbit at the DEM kinematics, about 0.3 % off the
    # quasi-static race control, and the drag power grows as v^3); the energy check closes within 1 %
    s = _steady_summary(engine, t_end)
    p = s["power_loss"]
    for k in ("ehl_rolling", "hysteresis", "drag"):
        assert p[k] == pytest.approx(quasistatic_losses[k], rel=0.03), k
    assert s["power_loss_total"] == pytest.approx(sum(p.values()), rel=1e-12)
    c = s["energy_check"]
    assert c["passed"] is True and abs(c["residual"]) <= 0.01
    assert "EHL rolling resistance" not in s["not_modelled"]
    assert not any(x.startswith("ball drag") for x in s["not_modelled"])


@pytest.mark.parametrize("kw,name", [
    (dict(oil_volume_fraction=-0.1), "oil_volume_fraction"),
    (dict(oil_volume_fraction=1.5), "oil_volume_fraction"),
    (dict(oil_volume_fraction=float("nan")), "oil_volume_fraction"),
    (dict(hysteresis_loss_factor=1.0), "hysteresis_loss_factor"),
    (dict(hysteresis_loss_factor=-0.01), "hysteresis_loss_factor"),
    (dict(rolling_resistance="yes"), "rolling_resistance"),
    (dict(ball_drag=1.0), "ball_drag"),
    (dict(rolling_resistance=True, contact_law="power", power_law=(1e9, 1.5, 0.0)), "rolling_resistance"),
])
def test_bad_loss_input_is_refused_naming_the_parameter(kw, name):
    with pytest.raises(InputError, match=f"^{name}:"):
        eb.Scenario(**kw)


def test_the_element_names_its_own_option():
    from exudyn_bearing.solvers.element.element import element_scenario

    with pytest.raises(InputError, match="^oilVolumeFraction:"):
        element_scenario("6208", oilVolumeFraction=-1.0)
    assert element_scenario("6208", rollingResistance=True).rolling_resistance is True
