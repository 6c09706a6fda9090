"""The series catalogue (exudyn_bearing/data/series.py, docs/theory/geometry.md#series-catalogue): ISO 15 boundary
dimensions of the 60/62/63 and 70/72/73 series, the estimated internal geometry, its load ratings against
manufacturers', the names, ``info --list`` and the marking of estimated values."""
import json
import math

import pytest

from exudyn_bearing.cli import main
from exudyn_bearing.data import BallBearing, InputError, catalog, get_bearing, load_bearing
from exudyn_bearing.data.bearings import EstimatedGeometryWarning
from exudyn_bearing.data.catalog import series_catalog
from exudyn_bearing.data.series import (ANGULAR_FILL_DEG, C_DEVIATION, C_DEVIATION_10MM, CONRAD_FILL_DEG, ESTIMATED,
                                        boundary_dimensions, cn_clearance, estimate_internal_geometry,
                                        series_entry, series_names)
from exudyn_bearing.physics.rating_life import rating_life

#: Boundary dimensions d x D x B [mm] published independently of the table: the catalogue's own 6208 and 6205
#: (catalog.json, docs/theory/geometry.md) and manufacturers' data sheets of the smallest and largest bores.
ANCHOR_DIMENSIONS = {
    "6208": (40, 80, 18), "6205": (25, 52, 15), "6200": (10, 30, 9), "6300": (10, 35, 11), "6000": (10, 26, 8),
    "6220": (100, 180, 34), "6320": (100, 215, 47), "6020": (100, 150, 24),
}
#: Manufacturers' basic dynamic load ratings C [kN]: SKF (6005, 6010, 6205, 6208, 6305, 6308; 7208 BECBP, 40 deg)
#: and, for the 10 mm bores, NTN's catalogue (6000, 6200, 6300).
SKF_C = {"6005-ISO": 11.9, "6010-ISO": 22.9, "6205-ISO": 14.8, "6208-ISO": 32.5, "6305-ISO": 23.4,
         "6308-ISO": 42.3, "7208B-ISO": 36.5}
NTN_C_10MM = {"6000-ISO": 4.55, "6200-ISO": 5.10, "6300-ISO": 8.20}


def mm(x):
    return round(x * 1e3, 6)


@pytest.mark.parametrize("designation", sorted(ANCHOR_DIMENSIONS))
def test_anchor_boundary_dimensions(designation):
    """The table gives the anchors' d x D x B, and the angular-contact series 7x the same as 6x."""
    series, code = designation[:2], designation[2:]
    assert tuple(map(mm, boundary_dimensions(series, code))) == ANCHOR_DIMENSIONS[designation]
    assert boundary_dimensions("7" + series[1], code) == boundary_dimensions(series, code)


def test_table_is_ordered_like_iso15():
    """Within a series D and B do not fall as the bore grows; at one bore the diameter series 0 < 2 < 3 grow in D
    and do not shrink in B (a mistyped row breaks one of these)."""
    codes = [f"{i:02d}" for i in range(21)]
    for series in ("60", "62", "63"):
        rows = [boundary_dimensions(series, c) for c in codes]
        assert all(b[0] > a[0] and b[1] > a[1] and b[2] >= a[2] for a, b in zip(rows, rows[1:])), series
    for c in codes:
        r0, r2, r3 = (boundary_dimensions(s, c) for s in ("60", "62", "63"))
        assert r0[1] < r2[1] < r3[1] and r0[2] <= r2[2] <= r3[2], c


def test_papers_entries_match_iso15():
    """The validated entries that carry bore and outside diameter agree with the table."""
    b = catalog["6205"]
    d, big_d, _ = boundary_dimensions("62", "05")
    assert (b.bore, b.outer_diameter) == pytest.approx((d, big_d))


def test_names_count_and_resolve():
    names = series_names()
    assert len(names) == len(set(names)) == 3 * 21 + 3 * 21 * 3
    assert load_bearing("6310-ISO").name == "6310-ISO"
    assert get_bearing("7208B-ISO").free_contact_angle == pytest.approx(math.radians(40.0))
    assert load_bearing("7210ac-iso").name == "7210AC-ISO"
    assert load_bearing("7005C-ISO").free_contact_angle == pytest.approx(math.radians(15.0))
    assert load_bearing("6310-ISO") is load_bearing("6310-ISO")  # built once


def test_papers_bearings_keep_their_names_and_geometry():
    """``6208`` is the papers' validated bearing (12.6 mm balls, no estimates); ``6208-ISO`` the rule's."""
    paper, estimate = load_bearing("6208"), load_bearing("6208-ISO")
    assert paper.estimated == () and mm(paper.ball_diameter) == 12.6
    assert estimate.estimated == ESTIMATED and estimate is not paper
    for name in ("6208", "7208", "6004", "6205", "ACBB-120"):
        assert load_bearing(name).estimated == ()


@pytest.mark.parametrize("bad, match", [
    ("7208-ISO", "needs a contact-angle suffix: 7208C-ISO"), ("6208B-ISO", "take no contact-angle suffix"),
    ("6321-ISO", "bore code 21 is outside"), ("6409-ISO", "unknown bearing '6409-ISO'"),
    ("6310", "unknown bearing '6310'.*6310-ISO")])
def test_bad_names_say_what_is_wrong(bad, match):
    with pytest.raises(InputError, match=f"^bearing: .*{match}"):
        load_bearing(bad)


@pytest.mark.parametrize("name", series_names())
def test_every_entry_is_plausible_and_marked(name):
    """The rule's geometry fits inside the rings of its boundary dimensions: the balls fit on the pitch circle
    and in the radial section, both ring sections under the grooves are positive, the ball count is the
    assembly rule's largest, the cage balls fit; every estimated quantity is listed."""
    b, e = series_catalog[name], series_entry(name)
    z, dw, dm = b.n_balls, b.ball_diameter, b.pitch_diameter
    assert z * dw < math.pi * dm
    assert dw < 0.5 * (e.outer_diameter - e.bore)
    assert b.inner_race_radius - 0.5 * e.bore > 0.0 and 0.5 * e.outer_diameter - b.outer_race_radius > 0.0
    arc = math.degrees(2.0 * math.asin(dw / dm))
    if e.kind == "deep-groove":
        assert (z - 1) * arc <= CONRAD_FILL_DEG < z * arc
        lo, hi = cn_clearance(e.bore)
        assert lo < b.diametral_clearance < hi
    else:
        assert z * arc <= ANGULAR_FILL_DEG < (z + 1) * arc
        assert b.diametral_clearance == pytest.approx(0.0, abs=1e-12)
    assert b.cage_pocket_clearance > 0.0
    assert (b.inner_conformity, b.outer_conformity) == pytest.approx((0.52, 0.53))
    assert b.estimated == ESTIMATED and "ESTIMATED" in b.source


@pytest.mark.parametrize("designation, z, dw_mm", [("6205", 9, 7.94), ("6203", 8, 6.747)])
def test_rule_reproduces_known_internal_geometry(designation, z, dw_mm):
    """The CWRU test rig's SKF 6205 (9 x 7.94 mm) and 6203 (8 x 6.747 mm, 0.2656 in) from the rule."""
    d, big_d, _ = boundary_dimensions(designation[:2], designation[2:])
    g = estimate_internal_geometry(d, big_d, angular=False)
    assert g["n_balls"] == z and mm(g["ball_diameter"]) == pytest.approx(dw_mm, abs=0.005)


@pytest.mark.parametrize("name, c_kn, band", [(n, c, C_DEVIATION) for n, c in SKF_C.items()]
                         + [(n, c, C_DEVIATION_10MM) for n, c in NTN_C_10MM.items()])
def test_load_rating_within_stated_band(name, c_kn, band):
    """ISO 281's C of the estimated geometry lies within the band docs/theory/geometry.md states of the
    manufacturer's published C."""
    c = rating_life(series_catalog[name], (0.0, 0.0), warn=False).C
    assert band[0] <= c / (1e3 * c_kn) - 1.0 <= band[1]


def test_info_list_lists_the_catalogue(capsys):
    assert main(["info", "--list"]) == 0
    lines = capsys.readouterr().out.splitlines()
    first = {ln.split()[0]: ln for ln in lines[1:] if ln.strip()}
    assert set(catalog) | set(series_names()) <= set(first)
    assert first["6310-ISO"].split()[-1] == "estimated" and "50 x 110 x 27" in first["6310-ISO"]
    assert first["6208"].split()[-1] == "sheet" and "9 x 12.600" in first["6208"]
    assert main(["info", "--list", "--json"]) == 0
    rows = {r["name"]: r for r in json.loads(capsys.readouterr().out)["bearings"]}
    assert rows["7208B-ISO"]["free_contact_angle_deg"] == 40.0 and rows["7208B-ISO"]["estimated"] == list(ESTIMATED)
    assert rows["6208"]["geometry"] == "data sheet" and rows["6208"]["estimated"] == []


def test_info_list_refuses_a_bearing(capsys):
    assert main(["info", "--list", "6208"]) == 2
    assert "list:" in capsys.readouterr().err


def test_info_shows_estimated(capsys):
    assert main(["info", "6310-ISO", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["estimated"] == list(ESTIMATED)
    assert main(["info", "6310-ISO"]) == 0
    assert "estimated (not from a data sheet): n_balls" in capsys.readouterr().out


def test_from_dimensions_without_conformities_takes_the_rule_and_says_so():
    with pytest.warns(EstimatedGeometryWarning, match="0.52, 0.53 assumed"):
        b = BallBearing.from_dimensions(9, 7.94e-3, 39.04e-3, source="CWRU 6205")
    assert (b.inner_conformity, b.outer_conformity) == pytest.approx((0.52, 0.53))
    assert b.estimated == ("inner_conformity", "outer_conformity") and "ISO 281" in b.source
    with pytest.warns(EstimatedGeometryWarning, match="^bearing custom: outer_conformity not given"):
        b = BallBearing.from_dimensions(9, 7.94e-3, 39.04e-3, inner_conformity=0.51)
    assert b.inner_conformity == pytest.approx(0.51) and b.estimated == ("outer_conformity",)
    with pytest.warns(EstimatedGeometryWarning):  # the dict / file form alike
        assert load_bearing({"n_balls": 9, "ball_diameter": 7.94e-3, "pitch_diameter": 39.04e-3}).estimated


def test_from_dimensions_with_conformities_estimates_nothing(recwarn):
    b = BallBearing.from_dimensions(9, 7.94e-3, 39.04e-3, 0.52, 0.52)
    assert b.estimated == () and not [w for w in recwarn if issubclass(w.category, EstimatedGeometryWarning)]


def test_estimated_survives_to_dict():
    b = series_catalog["6305-ISO"]
    d = b.to_dict()
    assert d["estimated"] == ESTIMATED
    assert load_bearing(json.loads(json.dumps(d))).estimated == ESTIMATED
    with pytest.raises(InputError, match="^estimated: "):
        b.replace(estimated=5)
