"""Input checks of every entry point (issue 19 items 2-4, 10-13; issue 18 defaults):
units named in the messages, one validation path for API, CLI, files and sweeps,
and errors that name the parameter the user gave."""
import json
import math

import numpy as np
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


@pytest.mark.parametrize("cls, kw, match", [
    (eb.Material, dict(youngs_modulus=210e3),
     r"^youngs_modulus: 210000 Pa .*Young's modulus is in Pa: 210000 MPa is 2.1e\+11 Pa"),
    (eb.Material, dict(youngs_modulus=210.0), r"^youngs_modulus: 210 Pa .*: 210 GPa is 2.1e\+11 Pa"),
    (eb.Material, dict(density=7.85), r"^density: 7.85 kg/m\^3 .*: 7.85 g/cm\^3 is 7850 kg/m\^3"),
    (eb.Lubricant, dict(viscosity=40.0), r"^viscosity: 40 Pa s .*: 40 mPa s \(cP\) is 0.04 Pa s"),
    (eb.Lubricant, dict(pressure_viscosity=23.0), r"^pressure_viscosity: 23 1/Pa .*: 23 1/GPa is 2.3e-08 1/Pa"),
    (eb.Lubricant, dict(roughness_race=0.3), r"^roughness_race: 0.3 m .*: 0.3 um is 3e-07 m"),
])
def test_material_and_lubricant_unit_mistakes_are_named(cls, kw, match):
    with pytest.raises(InputError, match=match):
        cls(**kw)


def test_temperatures_in_celsius_are_refused_everywhere():
    msg = r"^temperatures.inner: 20 K is not plausible .*temperatures are in kelvin: 20 degC is 293.15 K"
    with pytest.raises(InputError, match=msg):
        eb.Scenario(Fr=3000.0, omega=500.0, temperatures={"inner": 20.0, "outer": 80.0, "ball": 20.0})
    with pytest.raises(InputError, match=msg):
        eb.solve_quasistatic("6208", Fr=3000.0, temperatures={"inner": 20.0, "outer": 80.0, "ball": 20.0})
    assert eb.Scenario(Fr=3000.0, omega=500.0, temperatures={"inner": 353.15}).temperatures == {"inner": 353.15}


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
    assert eb.Scenario(Fr=3000.0, omega=500.0, defects=d).defects == (d,)
    assert eb.Scenario(Fr=3000.0, omega=500.0, defects=d.to_dict()).defects == (d,)
    with pytest.raises(InputError, match=r"^defects: expected a Defect"):
        eb.Scenario(Fr=3000.0, omega=500.0, defects="outer")


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


@pytest.mark.filterwarnings("ignore::exudyn_bearing.data.LubricantDefaultsWarning")  # a viscosity-only lubricant
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


def _cli(capsys, *argv):
    from exudyn_bearing.cli import main
    try:
        rc = main(list(argv))
    except SystemExit as exc:
        rc = exc.code
    out = capsys.readouterr()
    return rc, out.out, out.err


@pytest.mark.parametrize("argv, start", [
    (["static", "6208", "--Fr", "3000", "--My", "5"], "My: a moment load needs the free tilt"),
    (["simulate", "--Fr", "3000", "--omega", "500", "6208", "--dt", "3"], "dt: 3 s is far above any stable step"),
    (["quasistatic", "6208", "--Fr", "3000", "--omega", "1e7"], "omega: the operating interference"),
    (["quasistatic", "6208", "--Fr", "3000", "--fix", "delta_x=1"], "--fix delta_x: 1 m moves the inner ring"),
    (["quasistatic", "6208", "--Fr", "3000", "--My", "5"], "My: a moment load needs the free tilt"),
])
def test_cli_errors_name_the_parameter_given(capsys, argv, start):
    rc, _out, err = _cli(capsys, *argv)
    assert rc == 2 and err.strip().splitlines()[-1].startswith(f"exudyn-bearing: error: {start}")


# -- 19.2 the elastic-contact limit in every command ------------------------------------------------------------
@pytest.mark.parametrize("argv", [
    ["quasistatic", "6208", "--Fr", "1e5"],
    ["stiffness", "6208", "--Fr", "1e5"],
])
def test_every_command_refuses_pressures_above_the_elastic_limit(capsys, argv):
    # 6208: 21.8 kN radial reach 4.2 GPa (model/load_range.py); 1e5 N give 6.98 GPa (vibration three-dof: its
    # own check on main)
    rc, _out, err = _cli(capsys, *argv)
    assert rc == 2 and "above 4.2 GPa" in err and err.startswith("exudyn-bearing: error: Fr:")


def test_a_run_whose_sampled_pressure_exceeds_the_limit_fails_or_warns():
    from exudyn_bearing.model.load_range import ContactPressureWarning, check_run_pressures
    t = np.arange(20) * 1e-4
    p = np.full((20, 9, 2), 2.0e9)           # (samples, balls, races inner / outer)
    check_run_pressures(p, t)                # below 4.2 GPa: nothing
    sustained = p.copy()
    sustained[5:, 3, 1] = 5.0e9              # outer race of ball 3 from sample 5 on: the speed's loads
    with pytest.raises(InputError, match=r"^omega: the run reached a contact pressure of 5 GPa at the outer race "
                                         r"of ball 3, above 4.2 GPa"):
        check_run_pressures(sustained, t)
    brief = p.copy()
    brief[7, 2, 0] = 5.0e9                   # one sample of 20 (5 %): an impact
    with pytest.warns(ContactPressureWarning, match=r"inner race of ball 2.*t = 0.0007 s"):
        check_run_pressures(brief, t)


# -- 19.12 angular-contact bearings under combined load: tilt held by default, --fix everywhere ---------------
def test_a_lone_angular_contact_bearing_points_to_fix_delta_a(capsys):
    for cmd in ("static", "quasistatic", "stiffness"):
        rc, _out, err = _cli(capsys, cmd, "7208", "--Fr", "3000", "--Fa", "2000")
        assert rc == 2 and "--fix delta_a=0" in err, cmd
        rc, out, err = _cli(capsys, cmd, "7208", "--Fr", "3000", "--Fa", "2000", "--fix", "delta_a=0", "--json")
        assert rc == 0, (cmd, err)


def test_the_three_commands_hold_the_tilt_and_agree_at_zero_speed(capsys):
    # 7208 at F_a = 3500 N: quasistatic and stiffness failed "over the shoulder" with a free tilt while static
    # held it; with one default (held) they solve the same equilibrium: static = quasistatic at zero speed
    rc, out, _ = _cli(capsys, "static", "7208", "--Fr", "3000", "--Fa", "3500", "--json")
    st = json.loads(out)
    rc2, out2, _ = _cli(capsys, "quasistatic", "7208", "--Fr", "3000", "--Fa", "3500", "--json")
    qs = json.loads(out2)
    assert rc == rc2 == 0
    assert qs["held_dofs"]["tilt_x"] == qs["held_dofs"]["tilt_y"] == "fixed" and qs["tilt_y"] == 0.0
    # the same solver at zero speed and zero ring growth: equal to round-off
    assert max(qs["q_inner"]) == pytest.approx(st["q_max"], rel=1e-9)
    rc3, out3, err3 = _cli(capsys, "stiffness", "7208", "--Fr", "3000", "--Fa", "3500", "--rpm", "6000", "--json")
    assert rc3 == 0, err3
    assert json.loads(out3)["held_dofs"]["tilt_y"] == "fixed"


# -- 18.3 one set of defaults; bearings carry their lubricant and traction model --------------------------------
def test_catalogue_bearings_name_their_lubricant_and_traction():
    from exudyn_bearing.data import default_lubricant, default_traction
    acbb = eb.catalog["ACBB-120"]
    assert default_lubricant(acbb).name == "MIL-L-23699_492K" and default_traction(acbb) == "ehl_mil_l_23699_492K"
    for name in ("6208", "7208", "6004", "6205"):
        assert default_lubricant(eb.catalog[name]).name == "guessasma2018", name
        assert default_traction(eb.catalog[name]) == "lambda_dem", name
    s = eb.solve_quasistatic("ACBB-120", Fa=22240.0, stiffness=False)
    assert (s.lubricant, s.traction) == ("MIL-L-23699_492K", "ehl_mil_l_23699_492K")
    with pytest.raises(InputError, match=r"^lubricant: unknown lubricant 'olive'"):
        load_bearing(dict(DIMS_6208, lubricant="olive"))


def test_every_solver_has_the_same_physical_defaults():
    import inspect

    from exudyn_bearing.cli.common import RING_GROWTH
    from exudyn_bearing.solvers.element import BallBearingElement
    qs = inspect.signature(eb.solve_quasistatic).parameters
    el = inspect.signature(BallBearingElement.__init__).parameters
    sc = eb.Scenario(Fr=3000.0, omega=500.0)
    assert qs["ring_growth"].default is sc.ring_growth is el["ringGrowth"].default is RING_GROWTH is True
    assert qs["traction"].default is sc.traction is el["traction"].default is None        # None: the bearing's
    assert qs["hertz_method"].default == sc.hertz == el["hertzModel"].default == "exact"
    assert sc.film == el["film"].default == "hd"


def test_simulate_takes_the_bearings_lubricant_and_traction():
    from exudyn_bearing.simulate import with_bearing_defaults
    sc, lub = with_bearing_defaults(eb.catalog["ACBB-120"], eb.Scenario(Fr=3000.0, omega=500.0, traction_level="ellipse"))
    assert (lub.name, sc.traction) == ("MIL-L-23699_492K", "ehl_mil_l_23699_492K")
    sc, lub = with_bearing_defaults(eb.catalog["6208"], eb.Scenario(Fr=3000.0, omega=500.0), "MIL-L-23699_492K")
    assert (lub.name, sc.traction) == ("MIL-L-23699_492K", "lambda_dem")


@pytest.mark.parametrize("cmd", ["static", "quasistatic", "stiffness"])
def test_headers_and_json_name_lubricant_and_traction(capsys, cmd):
    rc, out, _ = _cli(capsys, cmd, "ACBB-120", "--Fr", "0", "--Fa", "22240", "--json")
    d = json.loads(out)
    assert rc == 0 and d["lubricant"] == "MIL-L-23699_492K"
    assert d["traction"] == (None if cmd == "static" else "ehl_mil_l_23699_492K")
    rc, out, _ = _cli(capsys, cmd, "ACBB-120", "--Fr", "0", "--Fa", "22240")
    assert rc == 0 and "lubricant MIL-L-23699_492K" in out


# -- 19.13 output ----------------------------------------------------------------------------------------------
def test_quasistatic_table_has_units_gpa_and_ball_speed(capsys):
    rc, out, _ = _cli(capsys, "quasistatic", "6208", "--Fr", "3000", "--omega", "500")
    lines = out.splitlines()
    head = next(i for i, line in enumerate(lines) if line.startswith("ball"))
    assert "w_ball" in lines[head] and "[GPa]" in lines[head + 1] and "[rad/s]" in lines[head + 1]
    row0 = lines[head + 2].split()
    # ball 0 of the 6208 at 3000 N: p_max at the inner race 2.17 GPa (static: 2.169 GPa), printed in GPa
    assert 2.0 < float(row0[6]) < 2.3 and "G" not in lines[head + 2]


def test_static_free_tilt_prints_no_nan(capsys):
    rc, out, _ = _cli(capsys, "static", "6208", "--Fr", "3000", "--Fa", "1000", "--tilt", "free")
    assert rc == 0 and "nan" not in out and "continuous Stribeck not applicable" in out


def test_round_off_prints_as_zero_and_version(capsys):
    from exudyn_bearing.cli.common import format_value
    assert format_value(6.93889e-18, "m") == "0" and format_value(-7.1e-15, "N m", 4) == "0"
    assert format_value(2.5e-6, "m") == "2.5e-06"
    rc, out, _ = _cli(capsys, "--version")
    assert rc == 0 and out.strip() == f"exudyn-bearing {eb.__version__}"


def test_readme_b3_has_the_6208_geometry():
    b3 = BallBearing.from_dimensions(n_balls=9, ball_diameter=12.6e-3, pitch_diameter=60.6e-3,
                                     inner_conformity=0.52, outer_conformity=0.52, diametral_clearance=0.0,
                                     free_contact_angle=0.0, cage_ball_radius=4.19e-3)
    b = eb.catalog["6208"]
    for key in ("ball_radius", "inner_race_radius", "outer_race_radius", "inner_groove_radius",
                "outer_groove_radius", "cage_ball_radius", "free_contact_angle", "n_balls"):
        assert abs(getattr(b3, key) - getattr(b, key)) <= 1e-18, key
    assert b3.material.youngs_modulus == b.material.youngs_modulus


# a short run: its summary window is not steady, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_simulate_names_its_lubricant_and_traction(capsys):
    rc, out, err = _cli(capsys, "simulate", "--Fr", "3000", "--omega", "500", "6208", "--t-end", "0.0004", "--dt", "2e-6", "--json")
    d = json.loads(out)
    assert rc == 0, err
    assert d["lubricant"] == "guessasma2018" and d["ring_growth"] is True
    assert d["traction"].startswith("point-contact law (history, mu(Lambda)")


def test_simulate_names_omega_where_ring_growth_closes_the_bearing():
    with pytest.raises(eb.InputError, match="^omega: the operating interference"):
        eb.simulate("6208", eb.Scenario(Fr=3000.0, omega=1e9, t_end=1e-4, dt=1e-6))


def test_the_ball_element_names_an_option_it_does_not_take():
    import exudyn as exu
    from exudyn.utilities import InertiaCylinder, MarkerBodyRigid, ObjectGround

    mbs = exu.SystemContainer().AddSystem()
    ground = mbs.AddMarker(MarkerBodyRigid(bodyNumber=mbs.AddObject(ObjectGround())))
    body = mbs.CreateRigidBody(inertia=InertiaCylinder(7850.0, 0.25, 0.02, axis=2), referencePosition=[0, 0, 0])
    with pytest.raises(eb.InputError, match="^operatingTilt: not an option of model='balls'"):
        eb.CreateBallBearing(mbs, "6208", mbs.AddMarker(MarkerBodyRigid(bodyNumber=body)), ground,
                             operatingTilt="held")
