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
