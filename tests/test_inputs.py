"""Input checks of every entry point (issue 19 items 2-4, 10-13; issue 18 defaults):
units named in the messages, one validation path for API, CLI, files and sweeps,
and errors that name the parameter the user gave."""
import json
import math

import pytest

import exudyn_bearing as eb
from exudyn_bearing import BallBearing, InputError, load_bearing

DIMS_6208 = {"n_balls": 9, "ball_diameter": 12.6e-3, "pitch_diameter": 60.6e-3, "inner_conformity": 0.52,
             "outer_conformity": 0.52, "cage_ball_radius": 4.19e-3}


# -- 19.4 one angle convention: radians under free_contact_angle, degrees under free_contact_angle_deg --------
def test_free_contact_angle_is_radians_in_files_as_in_python():
    # 40 deg = 0.6981317 rad: the file, the dict and from_dimensions give the same bearing
    rad = dict(DIMS_6208, free_contact_angle=math.radians(40.0), inner_conformity=0.57, outer_conformity=0.57,
               n_balls=13, cage_ball_radius=1.0e-3)
    deg = dict(rad, free_contact_angle_deg=40.0)
    del deg["free_contact_angle"]
    a, b = load_bearing(rad), load_bearing(deg)
    assert a.free_contact_angle == pytest.approx(math.radians(40.0), rel=1e-15)
    assert b.free_contact_angle == pytest.approx(math.radians(40.0), rel=1e-15)
    c = BallBearing.from_dimensions(13, 12.6e-3, 60.6e-3, 0.57, 0.57, free_contact_angle=math.radians(40.0),
                                    cage_ball_radius=1.0e-3)
    assert c.free_contact_angle == a.free_contact_angle
    # the catalogue 7208 (40 deg) reads the same
    assert eb.catalog["7208"].free_contact_angle == pytest.approx(math.radians(40.0), rel=1e-15)


@pytest.mark.parametrize("key, value, match", [
    # degrees under the radians key: named, with the conversion
    ("free_contact_angle", 40.0, r"^free_contact_angle: 40 rad is not a free contact angle; angles are in radians "
                                 r"\(40 deg is 0.698132 rad"),
    # radians under the degrees key (the 0.698 that became 0.698 deg)
    ("free_contact_angle_deg", 0.698, r"^free_contact_angle_deg: 0.698 deg looks like an angle in radians "
                                      r"\(0.698 rad = 39.99 deg\)"),
    ("free_contact_angle_deg", 75.0, r"^free_contact_angle_deg: must lie in \[0, 60\] deg"),
])
def test_an_angle_in_the_other_unit_is_refused(key, value, match):
    d = dict(DIMS_6208, **{key: value})
    with pytest.raises(InputError, match=match):
        load_bearing(d)


def test_python_refuses_degrees_and_both_keys():
    with pytest.raises(InputError, match=r"^free_contact_angle: 40 rad .*\(40 deg is 0.698132 rad"):
        BallBearing.from_dimensions(13, 12.6e-3, 60.6e-3, 0.57, 0.57, free_contact_angle=40.0)
    with pytest.raises(InputError, match=r"^free_contact_angle: given both"):
        load_bearing(dict(DIMS_6208, free_contact_angle=0.0, free_contact_angle_deg=0.0))


def test_to_dict_round_trips_through_a_file_in_degrees(tmp_path):
    d = eb.catalog["7208"].to_dict()
    assert "free_contact_angle" not in d and d["free_contact_angle_deg"] == pytest.approx(40.0, rel=1e-15)
    f = tmp_path / "b.json"
    f.write_text(json.dumps(d))
    assert load_bearing(str(f)).free_contact_angle == eb.catalog["7208"].free_contact_angle


# -- 19.3 unit mistakes named -------------------------------------------------------------------------------
def test_a_bearing_file_in_mm_is_refused_naming_metres(tmp_path):
    mm = {k: (v * 1e3 if k.endswith("radius") and v is not None else v)
          for k, v in eb.catalog["6208"].to_dict().items()}
    f = tmp_path / "mm.json"
    f.write_text(json.dumps(mm))
    with pytest.raises(InputError, match=r"^ball_radius: 6.3 m is not plausible .*; lengths are in metres: "
                                         r"6.3 mm is 0.0063 m"):
        load_bearing(str(f))
    with pytest.raises(InputError, match=r"^ball_diameter: 12.7 m .* lengths are in metres: 12.7 mm is 0.0127 m"):
        BallBearing.from_dimensions(9, 12.7, 60.6, 0.52, 0.52)


@pytest.mark.parametrize("f, match", [
    (52.0, r"^inner_conformity: 52 is a percentage; .* 52 % is 0.52"),
    (0.7, r"^inner_conformity: must lie in \(0.5, 0.6\]"),
    (0.5, r"^inner_conformity: must lie in \(0.5, 0.6\]"),
])
def test_conformity_outside_half_to_0_6_is_refused(f, match):
    with pytest.raises(InputError, match=match):
        BallBearing.from_dimensions(9, 12.6e-3, 60.6e-3, f, 0.52)


def test_groove_radius_beyond_conformity_0_6_is_refused():
    # race-radii form: R_ci = 0.7 D = 8.82 mm for D = 12.6 mm
    with pytest.raises(InputError, match=r"^inner_groove_radius: 0.00882 m is 0.7 ball diameters"):
        eb.catalog["6208"].replace(inner_groove_radius=8.82e-3)


@pytest.mark.parametrize("kw, match", [
    (dict(youngs_modulus=210e3), r"^youngs_modulus: 210000 Pa .*Young's modulus is in Pa: 210000 MPa is 2.1e\+11 Pa"),
    (dict(youngs_modulus=210.0), r"^youngs_modulus: 210 Pa .*: 210 GPa is 2.1e\+11 Pa"),
    (dict(density=7.85), r"^density: 7.85 kg/m\^3 .*: 7.85 g/cm\^3 is 7850 kg/m\^3"),
])
def test_material_unit_mistakes_are_named(kw, match):
    with pytest.raises(InputError, match=match):
        eb.Material(**kw)


@pytest.mark.parametrize("kw, match", [
    (dict(viscosity=40.0), r"^viscosity: 40 Pa s .*: 40 mPa s \(cP\) is 0.04 Pa s"),
    (dict(pressure_viscosity=23.0), r"^pressure_viscosity: 23 1/Pa .*: 23 1/GPa is 2.3e-08 1/Pa"),
    (dict(roughness_race=0.3), r"^roughness_race: 0.3 m .*: 0.3 um is 3e-07 m"),
])
def test_lubricant_unit_mistakes_are_named(kw, match):
    with pytest.raises(InputError, match=match):
        eb.Lubricant(**kw)


def test_temperatures_in_celsius_are_refused_everywhere():
    msg = r"^temperatures.inner: 20 K is not plausible .*temperatures are in kelvin: 20 degC is 293.15 K"
    with pytest.raises(InputError, match=msg):
        eb.Scenario(temperatures={"inner": 20.0, "outer": 80.0, "ball": 20.0})
    with pytest.raises(InputError, match=msg):
        eb.solve_quasistatic("6208", Fr=3000.0, temperatures={"inner": 20.0, "outer": 80.0, "ball": 20.0})
    assert eb.Scenario(temperatures={"inner": 353.15}).temperatures == {"inner": 353.15}


def test_cli_temperature_in_celsius_exits_2(capsys):
    from exudyn_bearing.cli import main
    assert main(["quasistatic", "6208", "--Fr", "3000", "--temperature", "20", "80", "20"]) == 2
    err = capsys.readouterr().err
    assert "temperatures.inner: 20 K" in err and "20 degC is 293.15 K" in err


# -- 19.10 one validation path for API, CLI, files and sweeps -------------------------------------------------
@pytest.mark.parametrize("kw, match", [
    (dict(Fr=True), r"^Fr: expected a number, got True \(bool\)"),
    (dict(Fr="3000"), r"^Fr: expected a number, got '3000' \(str\)"),
    (dict(Fr=3000.0, shoulder_angle=float("nan")), r"^shoulder_angle: must be finite"),
    (dict(Fr=3000.0, ring_growth="no"), r"^ring_growth: must be True or False"),
    (dict(Fr=3000.0, n_strips=8.5), r"^n_strips: expected an integer"),
    (dict(Fr=3000.0, lubricant="no-such-oil"), r"^lubricant: unknown lubricant 'no-such-oil'"),
])
def test_solve_quasistatic_refuses_what_the_data_layer_refuses(kw, match):
    with pytest.raises(InputError, match=match):
        eb.solve_quasistatic("6208", **kw)


def test_one_defect_is_a_sequence_of_one():
    d = eb.Defect("outer", position=0.0, length=1e-3, width=1e-3, depth=1e-4)
    assert eb.Scenario(defects=d).defects == (d,)
    assert eb.Scenario(defects=d.to_dict()).defects == (d,)
    with pytest.raises(InputError, match=r"^defects: expected a Defect"):
        eb.Scenario(defects="outer")


def test_element_options_take_a_lubricant_name_and_one_defect():
    from exudyn_bearing.solvers.element.element import element_scenario
    d = eb.Defect("outer", position=0.0, length=1e-3, width=1e-3, depth=1e-4)
    assert element_scenario(defects=d).defects == (d,)
    with pytest.raises(InputError, match=r"^initialLoad: expected a number, got '3000'"):
        element_scenario(initialLoad=("3000", 0.0))
    with pytest.raises(InputError, match=r"^ringGrowth: must be True or False, got 1"):
        element_scenario(ringGrowth=1)
    with pytest.raises(InputError, match=r"^initalLoad: unknown option of the bearing element"):
        element_scenario(initalLoad=3000.0)
    assert eb.load_lubricant("MIL-L-23699_492K") is eb.lubricants["MIL-L-23699_492K"]


def test_sweep_specs_go_through_one_check():
    from exudyn_bearing.simulate import spec_inputs
    kw = spec_inputs({"bearing": "6208", "scenario": {"Fr": 3000.0}, "lubricant": "MIL-L-23699_492K"})
    assert kw["lubricant"] is eb.lubricants["MIL-L-23699_492K"] and kw["scenario"].Fr == 3000.0
    assert spec_inputs({"bearing": "6208", "lubricant": {"viscosity": 0.03}})["lubricant"].viscosity == 0.03
    with pytest.raises(InputError, match=r"^lubricnt: unknown spec key"):
        spec_inputs({"bearing": "6208", "lubricnt": "MIL-L-23699_492K"})
    with pytest.raises(InputError, match=r"^Frr: unknown scenario field"):
        spec_inputs({"bearing": "6208", "scenario": {"Frr": 3000.0}})


# -- 19.11 errors that name the parameter the user gave --------------------------------------------------------
def test_quasistatic_speed_that_closes_the_clearance_names_omega():
    with pytest.raises(InputError, match=r"^omega: the operating interference .*\(centrifugal ring growth"):
        eb.solve_quasistatic("6208", Fr=3000.0, omega=1e7)


def test_held_displacement_in_the_wrong_unit_names_the_dof():
    with pytest.raises(InputError, match=r"^fixed.delta_x: 1 m moves the inner ring by more than 0.1 R_b"):
        eb.solve_quasistatic("6208", Fr=3000.0, fixed={"delta_x": 1.0})


def test_a_held_radial_displacement_is_held():
    # x held at 10 um, 6208 under 3000 N (free: 24.8 um): the ring stays at 10 um and the reaction carries
    # the rest of the load, in the direction of +x (the balls push back less than 3000 N)
    s = eb.solve_quasistatic("6208", Fr=3000.0, fixed={"delta_x": 10e-6}, stiffness=False)
    assert s.displacement[0] == 10e-6
    assert s.reactions["delta_x"] < 0.0
