"""Bearing, material and lubricant data: derived values and rejected input."""
import json
import math

import pytest

from exudyn_bearing import BallBearing, InputError, Lubricant, Material, catalog, load_bearing
from exudyn_bearing.data import get_bearing


def test_catalogue_has_the_physics_md_bearings():
    assert set(catalog) >= {"6208", "7208", "6004", "ACBB-120"}
    for b in catalog.values():
        assert b.source


def test_6208_derived_values(b6208):
    # docs/theory/geometry.md: r_p = (R_i + R_o)/2, P_d = 0 as built, f = 0.52, B = 0.04
    assert b6208.pitch_radius == pytest.approx(30.3e-3)
    assert b6208.diametral_clearance == pytest.approx(0.0, abs=1e-12)
    assert b6208.inner_conformity == pytest.approx(0.52)
    assert b6208.conformity_sum == pytest.approx(0.04)
    # deep-groove tube-centre circles: rho_i = R_i + R_ci, rho_o = R_o - R_co
    assert b6208.inner_groove_center == pytest.approx((24.0e-3 + 6.552e-3, 0.0))
    assert b6208.outer_groove_center == pytest.approx((36.6e-3 - 6.552e-3, 0.0))


def test_6208_cage_pocket_clearance(b6208):
    # docs/theory/geometry.md: 2 r_p sin(pi/(2Z)) = 10.52 mm vs R_b + R_z = 10.49 mm: about 30 um
    spacing = 2 * b6208.pitch_radius * math.sin(math.pi / 18)
    assert spacing == pytest.approx(10.52e-3, abs=5e-6)
    assert 25e-6 < b6208.cage_pocket_clearance < 35e-6


def test_7208_construction(b7208):
    # B = 0.14 and groove centres A = R_ci + R_co - 2 R_b apart at 40 deg
    assert b7208.conformity_sum == pytest.approx(0.14)
    ri, zi = b7208.inner_groove_center
    ro, zo = b7208.outer_groove_center
    assert math.hypot(ri - ro, zi - zo) == pytest.approx(b7208.groove_distance)
    assert math.degrees(math.atan2(zi - zo, ri - ro)) == pytest.approx(40.0)
    assert b7208.cage_pocket_clearance > 0


def test_acbb120_pitch_and_conformities():
    b = catalog["ACBB-120"]
    assert b.pitch_diameter == pytest.approx(155e-3)
    assert b.inner_conformity == pytest.approx(0.54)
    assert b.outer_conformity == pytest.approx(0.52)
    assert math.degrees(b.free_contact_angle) == pytest.approx(24.0)
    assert not b.has_cage


def test_with_clearance_and_ball_mass(b6208):
    b = b6208.with_clearance(12.6e-6)
    assert b.diametral_clearance == pytest.approx(12.6e-6)
    assert b6208.ball_mass == pytest.approx(4 / 3 * math.pi * 6.3e-3 ** 3 * 7850)


def _kw(**over):
    d = dict(n_balls=9, ball_radius=6.3e-3, inner_race_radius=24e-3, outer_race_radius=36.6e-3,
             inner_groove_radius=6.552e-3, outer_groove_radius=6.552e-3, cage_ball_radius=4.19e-3)
    d.update(over)
    return d


@pytest.mark.parametrize("over, name", [
    (dict(ball_radius=-6.3e-3), "ball_radius"),
    (dict(ball_radius=float("nan")), "ball_radius"),
    (dict(inner_race_radius=float("inf")), "inner_race_radius"),
    (dict(inner_groove_radius=6.0e-3), "inner_groove_radius"),       # ball larger than groove
    (dict(outer_groove_radius=6.3e-3), "outer_groove_radius"),
    (dict(outer_race_radius=20e-3), "outer_race_radius"),            # R_o <= R_i
    (dict(outer_race_radius=37.0e-3), "outer_race_radius"),          # clearance: balls leave grooves
    (dict(outer_race_radius=36.0e-3), "outer_race_radius"),          # preload: ball does not fit
    (dict(cage_ball_radius=4.3e-3), "cage_ball_radius"),             # cage balls overlap balls
    (dict(cage_ball_radius=0.0), "cage_ball_radius"),
    (dict(n_balls=15), "n_balls"),                                   # balls do not fit on pitch circle
    (dict(n_balls=2), "n_balls"),
    (dict(n_balls=9.5), "n_balls"),
    (dict(free_contact_angle=math.radians(95)), "free_contact_angle"),
    (dict(free_contact_angle=-0.1), "free_contact_angle"),
])
def test_rejected_geometry_names_the_parameter(over, name):
    with pytest.raises(InputError, match=f"^{name}"):
        BallBearing(**_kw(**over))


def test_clearance_limit_is_the_free_contact_angle(b6208):
    # P_d = 40 um gives 16 deg: accepted; a free contact angle above 60 deg is rejected
    assert math.degrees(b6208.with_clearance(40e-6).free_contact_angle_max) == pytest.approx(
        math.degrees(math.acos(1 - 40e-6 / (2 * b6208.groove_distance))))
    with pytest.raises(InputError, match="outer_race_radius"):
        b6208.with_clearance(1.2 * b6208.groove_distance)  # cos = 0.4: 66 deg


@pytest.mark.parametrize("kw, name", [
    (dict(youngs_modulus=0.0), "youngs_modulus"),
    (dict(poisson_ratio=0.5), "poisson_ratio"),
    (dict(density=-1.0), "density"),
])
def test_rejected_material(kw, name):
    with pytest.raises(InputError, match=f"^{name}"):
        Material(**kw)


@pytest.mark.parametrize("kw, name", [
    (dict(viscosity=0.0), "viscosity"),
    (dict(lambda_mixed=3.0, lambda_full_film=1.0), "lambda_full_film"),
    (dict(roughness_race=0.0, roughness_ball=0.0), "roughness_race"),
    (dict(mu_boundary=float("nan")), "mu_boundary"),
])
def test_rejected_lubricant(kw, name):
    with pytest.raises(InputError, match=f"^{name}"):
        Lubricant(**kw)


def test_lubricant_defaults_give_the_papers_roughness():
    # docs/theory/lubrication.md#film-thickness: Lambda = h_min / 3.75e-7 m
    assert Lubricant().composite_roughness == pytest.approx(3.75e-7)


def test_unknown_catalogue_name_lists_valid_ones():
    with pytest.raises(InputError, match="6208"):
        get_bearing("6309")


def test_bearing_from_json_file(tmp_path):
    d = catalog["6208"].to_dict()
    d["name"] = "mine"
    p = tmp_path / "mine.json"
    p.write_text(json.dumps(d))
    b = load_bearing(str(p))
    assert b.name == "mine" and b.pitch_radius == pytest.approx(30.3e-3)
    d["ball_radius"] = -1
    p.write_text(json.dumps(d))
    with pytest.raises(InputError, match="^ball_radius"):
        load_bearing(str(p))
    d = catalog["6208"].to_dict()
    d["bogus"] = 1
    p.write_text(json.dumps(d))
    with pytest.raises(InputError, match="^bogus"):
        load_bearing(str(p))
