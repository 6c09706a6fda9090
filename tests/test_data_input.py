"""Bearings from the dimensions engineers have, bearing files in either form or
shaped like catalog.json, lubricants by name or file, and types checked on
construction (strings, booleans, numpy numbers) with errors naming the field."""
import json
import re
import math
from pathlib import Path

import numpy as np
import pytest

import exudyn_bearing as eb
from exudyn_bearing import BallBearing, InputError, Lubricant, Material, load_bearing, load_lubricant

GEOMETRY = ("n_balls", "ball_radius", "inner_race_radius", "outer_race_radius", "inner_groove_radius",
            "outer_groove_radius", "cage_ball_radius", "free_contact_angle")
CATALOG_JSON = Path(eb.__file__).parent / "data" / "catalog.json"


def same_geometry(a, b):
    for key in GEOMETRY:
        if getattr(b, key) is None:
            assert getattr(a, key) is None, key
        else:
            assert getattr(a, key) == pytest.approx(getattr(b, key), rel=1e-12, abs=1e-15), key
    assert a.material == b.material


@pytest.mark.parametrize("name, f, alpha_deg, rz", [("6208", 0.52, 0.0, 4.19e-3), ("7208", 0.57, 40.0, 1.0e-3)])
def test_from_dimensions_reproduces_the_catalogue(name, f, alpha_deg, rz):
    # data sheet: Z = 9 / 13, D = 12.6 mm, d_m = 60.6 mm, f_i = f_o, P_d = 0
    z = eb.catalog[name].n_balls
    b = BallBearing.from_dimensions(z, 12.6e-3, 60.6e-3, f, f, diametral_clearance=0.0,
                                    free_contact_angle=math.radians(alpha_deg), cage_ball_radius=rz, name=name,
                                    material=eb.materials["steel"])
    same_geometry(b, eb.catalog[name])
    assert b.diametral_clearance == pytest.approx(0.0, abs=1e-15)
    assert b.pitch_diameter == pytest.approx(60.6e-3) and b.inner_conformity == pytest.approx(f)


def test_from_dimensions_clearance_and_bad_dimensions():
    b = BallBearing.from_dimensions(9, 12.6e-3, 60.6e-3, 0.52, 0.52, diametral_clearance=12.6e-6)
    assert b.diametral_clearance == pytest.approx(12.6e-6) and b.pitch_diameter == pytest.approx(60.6e-3)
    with pytest.raises(InputError, match=r"^inner_conformity: must lie in \(0.5, 0.6\]"):
        BallBearing.from_dimensions(9, 12.6e-3, 60.6e-3, 0.49, 0.52)
    with pytest.raises(InputError, match=r"^ball_diameter: must be smaller than pitch_diameter"):
        BallBearing.from_dimensions(9, 70e-3, 60.6e-3, 0.52, 0.52)


def test_bearing_json_in_the_dimensions_form(tmp_path):
    d = {"name": "my 6208", "n_balls": 9, "ball_diameter": 12.6e-3, "pitch_diameter": 60.6e-3,
         "inner_conformity": 0.52, "outer_conformity": 0.52, "cage_ball_radius": 4.19e-3, "material": "steel"}
    f = tmp_path / "mine.json"
    f.write_text(json.dumps(d))
    b = load_bearing(str(f))
    same_geometry(b, eb.catalog["6208"])
    assert b.name == "my 6208"
    nested = {"name": "nested", "dimensions": {k: v for k, v in d.items() if k != "name"}}
    same_geometry(load_bearing(nested), eb.catalog["6208"])
    with pytest.raises(InputError, match="^inner_race_radius: give the race radii"):
        load_bearing(dict(d, inner_race_radius=24e-3))
    with pytest.raises(InputError, match="^pitch_radius: unknown bearing parameter"):
        load_bearing(dict(d, pitch_radius=30.3e-3))


def test_catalogue_shaped_files_are_accepted(tmp_path):
    # README: "a JSON file in the format of catalog.json"; such a file was rejected
    f = tmp_path / "catalog_copy.json"
    f.write_text(CATALOG_JSON.read_text())
    same_geometry(load_bearing(f"{f}#7208"), eb.catalog["7208"])
    same_geometry(load_bearing(str(f), name="6004"), eb.catalog["6004"])
    names = ", ".join(eb.catalog)
    with pytest.raises(InputError, match=rf"^bearing: .* holds {len(eb.catalog)} entries under 'bearings' "
                                         rf"\({re.escape(names)}\)"):
        load_bearing(str(f))
    with pytest.raises(InputError, match=r"^bearing: no '6309' in"):
        load_bearing(f"{f}#6309")
    # one bearing with a material of the file's own
    one = {"materials": {"ceramic": {"youngs_modulus": 310e9, "poisson_ratio": 0.26, "density": 3200.0}},
           "bearings": {"hybrid": dict(eb.catalog["6208"].to_dict(), material="ceramic", name="hybrid")}}
    g = tmp_path / "hybrid.json"
    g.write_text(json.dumps(one))
    b = load_bearing(str(g))
    assert b.name == "hybrid" and b.material.youngs_modulus == 310e9 and b.material.name == "ceramic"
    assert load_lubricant(f"{f}#guessasma2018") == eb.lubricants["guessasma2018"]
    with pytest.raises(InputError, match=r"^lubricant: .* entries under 'lubricants' \(guessasma2018, "):
        load_lubricant(str(f))


def test_single_bearing_file_round_trips(tmp_path):
    f = tmp_path / "b.json"
    f.write_text(json.dumps(eb.catalog["ACBB-120"].to_dict()))
    back = load_bearing(str(f))
    same_geometry(back, eb.catalog["ACBB-120"])  # free_contact_angle through degrees: to the last bit
    assert (back.name, back.source, back.bore, back.outer_diameter) == ("ACBB-120", eb.catalog["ACBB-120"].source, 0.12, 0.19)


@pytest.mark.parametrize("change, match", [
    (dict(ball_radius="6.3e-3"), r"^ball_radius: expected a number, got '6.3e-3' \(str\)"),
    (dict(n_balls="9"), r"^n_balls: expected an integer, got '9'"),
    (dict(n_balls=True), r"^n_balls: expected an integer"),
    (dict(material={"youngs_modulus": "2.1e11"}), r"^youngs_modulus: expected a number"),
    (dict(material={"youngs_modulus": 2.1e11, "colour": "red"}), r"^colour: unknown material parameter"),
    (dict(material="unobtainium"), r"^material: unknown material 'unobtainium'"),
    (dict(free_contact_angle_deg="40"), r"^free_contact_angle_deg: expected a number"),
    (dict(name=6208), r"^name: expected a string"),
])
def test_bearing_dicts_with_wrong_types_name_the_field(change, match):
    d = dict(eb.catalog["6208"].to_dict(), **change)
    with pytest.raises(InputError, match=match):
        load_bearing(d)


def test_dataclasses_check_types_on_construction():
    with pytest.raises(InputError, match=r"^youngs_modulus: expected a number, got '210e9'"):
        Material(youngs_modulus="210e9")
    with pytest.raises(InputError, match=r"^viscosity: expected a number"):
        Lubricant(viscosity="0.04")
    with pytest.raises(InputError, match=r"^cage: must be one of torus, rigid, none, auto \(True: torus, False or None: none\), got 'no'"):
        eb.Scenario(Fr=3000.0, omega=500.0, cage="no")
    with pytest.raises(InputError, match=r"^lubrication: must be True or False, got 1"):
        eb.Scenario(Fr=3000.0, omega=500.0, lubrication=1)
    with pytest.raises(InputError, match=r"^Fr: expected a number, got '3000'"):
        eb.Scenario(omega=500.0, Fr="3000")
    with pytest.raises(InputError, match=r"^viscocity: unknown lubricant parameter"):
        load_lubricant({"viscocity": 0.04})


def test_numpy_numbers_are_numbers():
    b = BallBearing(**dict({k: v for k, v in eb.catalog["6208"].to_dict().items() if k in GEOMETRY[:-1]},
                           n_balls=np.int64(9), ball_radius=np.float32(6.3e-3)), free_contact_angle=np.float64(0.0))
    assert b.n_balls == 9 and type(b.n_balls) is int and type(b.ball_radius) is float
    m = Material(youngs_modulus=np.float64(2.1e11), density=np.int32(7850))
    assert type(m.density) is float
    sc = eb.Scenario(Fr=np.int64(3000), omega=np.float32(500.0), cage=np.bool_(True), dt=np.float64(4e-6))
    assert sc.Fr == 3000.0 and type(sc.Fr) is float and sc.cage == "torus"
    assert eb.Scenario(omega=500.0, Fr=np.int64(3000)) == eb.Scenario(omega=500.0, Fr=3000.0)


def test_a_lubricant_file_needs_its_viscosity_and_names_what_it_takes_from_the_papers_oil(tmp_path):
    from exudyn_bearing.data import LubricantDefaultsWarning

    empty = tmp_path / "empty.json"
    empty.write_text("{}")
    with pytest.raises(InputError, match=r"^viscosity: the lubricant 'empty' gives no viscosity"):
        load_lubricant(str(empty))
    with pytest.warns(LubricantDefaultsWarning, match=r"pressure_viscosity = 2.3e-08.* not given") as caught:
        lub = load_lubricant({"name": "x", "viscosity": 0.02, "roughness_race": 2e-7})
    assert "roughness_race" not in str(caught[0].message)  # what was given is not named
    assert lub.viscosity == 0.02 and lub.pressure_viscosity == eb.lubricants["guessasma2018"].pressure_viscosity
    import dataclasses
    import warnings

    full = dict(dataclasses.asdict(eb.lubricants["guessasma2018"]), name="full")
    with warnings.catch_warnings():
        warnings.simplefilter("error", LubricantDefaultsWarning)  # a complete lubricant: no warning
        load_lubricant(full)
