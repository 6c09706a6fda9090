"""BearingCoefficients record and its export to a ROSS BearingElement.

The record's validation runs without ROSS; the export tests need the
optional extra (pip install -e ".[ross]") and are skipped otherwise. The
coefficients are hand-made numbers, not solver output, so the checks are of
the mapping alone: ROSS's element must return them at each speed, rotated
onto ROSS's axes, with the signs of its K q + C q' convention."""
import math
import warnings

import numpy as np
import pytest

from exudyn_bearing.data import InputError
from exudyn_bearing.model.coefficients import AXES, BearingCoefficients
from exudyn_bearing.outputs.ross import lateral_coefficients, to_ross_bearing

SPEEDS = np.array([0.0, 100.0, 250.0, 500.0, 1000.0])


def _record(cross=0.0):
    """Hand-made 5x5 matrices: speed-dependent, anisotropic, with cross terms."""
    n = SPEEDS.size
    k = np.zeros((n, 5, 5))
    c = np.zeros((n, 5, 5))
    for i, w in enumerate(SPEEDS):
        k[i, 0, 0] = 3.0e8 + 1.0e5 * w          # loaded direction, stiffening with speed
        k[i, 1, 1] = 1.0e8 - 2.0e4 * w
        k[i, 0, 1], k[i, 1, 0] = 2.0e6 + 1e3 * w, -1.5e6 - 1e3 * w   # non-symmetric on purpose
        k[i, 2, 2] = 4.0e7 + 3.0e3 * w
        k[i, 3, 3] = k[i, 4, 4] = 2.0e3
        k[i, 0, 2] = k[i, 2, 0] = cross * math.sqrt(k[i, 0, 0] * k[i, 2, 2])
        c[i, 0, 0] = 150.0 + 0.1 * w
        c[i, 1, 1] = 90.0 + 0.05 * w
        c[i, 0, 1], c[i, 1, 0] = 7.0 + 0.01 * w, -3.0
        c[i, 2, 2] = 40.0
        c[i, 3, 3] = c[i, 4, 4] = 0.01
    return BearingCoefficients(SPEEDS, k, c, {"bearing": "hand-made", "Fr": 1000.0}, "test numbers")


# -- the record (no ROSS needed) ---------------------------------------------------
def test_record_holds_axes_units_and_round_trips():
    r = _record()
    assert r.axes == AXES == ("x", "y", "axial", "tilt_x", "tilt_y")
    u = r.units
    assert u["speeds"] == "rad/s"
    assert u["stiffness"][0][0] == "N/m" and u["stiffness"][0][3] == "N/rad"
    assert u["stiffness"][3][0] == "N" and u["stiffness"][4][4] == "N m/rad"
    assert u["damping"][0][0] == "N s/m" and u["damping"][3][4] == "N m s/rad"
    back = BearingCoefficients.from_dict(r.to_dict())
    np.testing.assert_array_equal(back.stiffness, r.stiffness)
    np.testing.assert_array_equal(back.speeds, r.speeds)
    assert back.operating_point == {"bearing": "hand-made", "Fr": 1000.0}
    assert r.index("axial") == 2
    np.testing.assert_allclose(r.rpm()[1], 100.0 * 60 / (2 * math.pi))
    with pytest.raises(ValueError):
        r.stiffness[0, 0, 0] = 1.0  # read-only


@pytest.mark.parametrize("change, word", [
    (dict(speeds=[0.0, 100.0]), "stiffness"),
    (dict(speeds=[0.0, 100.0, 100.0, 500.0, 1000.0]), "speeds"),
    (dict(speeds=[-1.0, 100.0, 250.0, 500.0, 1000.0]), "speeds"),
    (dict(speeds=[]), "speeds"),
    (dict(stiffness=np.zeros((5, 4, 4))), "stiffness"),
    (dict(damping=np.full((5, 5, 5), np.nan)), "damping"),
    (dict(operating_point=[1, 2]), "operating_point"),
])
def test_record_validation(change, word):
    r = _record()
    kw = dict(speeds=r.speeds, stiffness=r.stiffness, damping=r.damping, operating_point={})
    kw.update(change)
    with pytest.raises(InputError, match=f"^{word}"):
        BearingCoefficients(**kw)


def test_record_bad_axes_and_names():
    d = _record().to_dict()
    d["axes"] = ["y", "x", "axial", "tilt_x", "tilt_y"]
    with pytest.raises(InputError, match="^axes"):
        BearingCoefficients.from_dict(d)
    with pytest.raises(InputError, match="^axis"):
        _record().index("z")


def test_lateral_mapping_rotates_the_load_direction():
    r = _record()
    same = lateral_coefficients(r, 0.0)
    np.testing.assert_array_equal(same["k"], r.stiffness[:, :2, :2])
    # load along ROSS's -y (gravity): our x -> ROSS -y, our y -> ROSS +x
    down = lateral_coefficients(r, -math.pi / 2)
    k = r.stiffness
    np.testing.assert_allclose(down["k"][:, 1, 1], k[:, 0, 0], rtol=1e-12)
    np.testing.assert_allclose(down["k"][:, 0, 0], k[:, 1, 1], rtol=1e-12)
    np.testing.assert_allclose(down["k"][:, 1, 0], -k[:, 0, 1], rtol=1e-12)   # F_y,ross = -F_x = ...
    np.testing.assert_allclose(down["k"][:, 0, 1], -k[:, 1, 0], rtol=1e-12)
    # invariants of a rotation about the spin axis: trace, determinant, antisymmetric part
    for a in (0.3, 2.0):
        rot = lateral_coefficients(r, a)["k"]
        np.testing.assert_allclose(np.trace(rot, axis1=1, axis2=2), np.trace(k[:, :2, :2], axis1=1, axis2=2))
        np.testing.assert_allclose(np.linalg.det(rot), np.linalg.det(k[:, :2, :2]), rtol=1e-10)
        np.testing.assert_allclose(rot[:, 0, 1] - rot[:, 1, 0], k[:, 0, 1] - k[:, 1, 0], rtol=1e-10)
    with pytest.raises(InputError, match="^load_angle"):
        lateral_coefficients(r, float("inf"))
    with pytest.raises(InputError, match="^coefficients"):
        lateral_coefficients({"speeds": [0.0]}, 0.0)


# -- the ROSS element ----------------------------------------------------------------
@pytest.fixture(scope="module")
def ross():
    return pytest.importorskip("ross", reason="ROSS is an optional extra: pip install -e \".[ross]\"")


def test_ross_element_returns_the_coefficients_at_each_speed(ross):
    r = _record()
    b = to_ross_bearing(r, n=3, tag="A")
    assert isinstance(b, ross.BearingElement) and b.n == 3 and b.tag == "A" and b.n_link is None
    np.testing.assert_array_equal(b.frequency, SPEEDS)
    for i, w in enumerate(SPEEDS):
        kr, cr = b.K(w), b.C(w)   # ROSS: 3x3 over (x, y, z)
        np.testing.assert_allclose(kr[:2, :2], r.stiffness[i, :2, :2], rtol=1e-6)
        np.testing.assert_allclose(cr[:2, :2], r.damping[i, :2, :2], rtol=1e-6)
        assert kr[2, 2] == pytest.approx(r.stiffness[i, 2, 2], rel=1e-6)
        assert cr[2, 2] == pytest.approx(r.damping[i, 2, 2], rel=1e-6)
    # named coefficients: kxy is the force along x per displacement along y, as in our K[0, 1]
    np.testing.assert_allclose(b.kxy, r.stiffness[:, 0, 1])
    np.testing.assert_allclose(b.kyx, r.stiffness[:, 1, 0])
    np.testing.assert_allclose(b.cxy, r.damping[:, 0, 1])
    # between the speeds ROSS interpolates: the linear data stay linear
    w = 750.0
    assert b.K(w)[0, 0] == pytest.approx(3.0e8 + 1.0e5 * w, rel=1e-6)


def test_ross_element_with_gravity_load_direction_and_no_axial(ross):
    r = _record()
    b = to_ross_bearing(r, n=0, load_angle=-math.pi / 2, include_axial=False)
    for i, w in enumerate(SPEEDS):
        kr = b.K(w)
        assert kr[1, 1] == pytest.approx(r.stiffness[i, 0, 0], rel=1e-6)   # the load direction is ROSS's y
        assert kr[0, 0] == pytest.approx(r.stiffness[i, 1, 1], rel=1e-6)
        assert kr[1, 0] == pytest.approx(-r.stiffness[i, 0, 1], rel=1e-6)
        assert kr[2, 2] == 0.0


def _rotor_on(ross, q):
    """A short, stiff rotor (disk on a 0.2 m shaft of 0.1 m diameter) on two bearings with
    K = [[k, q], [-q, k]], k = 1e6 N/m, and light damping 50 N s/m."""
    k = np.zeros((2, 5, 5))
    k[:, 0, 0] = k[:, 1, 1] = 1e6
    k[:, 0, 1], k[:, 1, 0] = q, -q
    c = np.zeros((2, 5, 5))
    c[:, 0, 0] = c[:, 1, 1] = 50.0
    rec = BearingCoefficients([0.0, 1000.0], k, c)
    steel = ross.materials.steel
    shaft = [ross.ShaftElement(L=0.1, idl=0.0, odl=0.1, material=steel) for _ in range(2)]
    disk = ross.DiskElement.from_geometry(n=1, material=steel, width=0.05, i_d=0.1, o_d=0.3)
    return ross.Rotor(shaft, [disk], [to_ross_bearing(rec, 0), to_ross_bearing(rec, 2)])


def test_ross_rotor_on_exported_bearings_translates_at_sqrt_2k_over_m(ross):
    # the shaft is 100 times stiffer than the bearings: the lowest modes are the rigid
    # rotor translating on the two springs, sqrt(2 k / m) (k negative in the wrong sign convention
    # would give no such mode)
    rotor = _rotor_on(ross, 0.0)
    modal = rotor.run_modal(speed=0.0, num_modes=12)
    assert modal.wn[0] / (2 * math.pi) == pytest.approx(math.sqrt(2e6 / rotor.m) / (2 * math.pi), rel=0.01)


def test_ross_cross_coupling_sign_drives_the_whirl_our_convention_predicts(ross):
    # our K[0, 1] = q > 0 with K[1, 0] = -q: a displacement x gives the force +q x along y, tangential
    # in the sense of the spin about +z, which feeds forward whirl. In ROSS the same numbers
    # must destabilise its forward mode (spin about +z), and -q its backward mode.
    for q, unstable in ((2e5, "Forward"), (-2e5, "Backward")):
        modal = _rotor_on(ross, q).run_modal(speed=100.0, num_modes=12)
        whirl = list(modal.whirl_direction()[:2])
        logdec = list(modal.log_dec[:2])
        assert sorted(whirl) == ["Backward", "Forward"]
        assert logdec[whirl.index(unstable)] < 0.0 < logdec[1 - whirl.index(unstable)]


def test_ross_export_warns_about_dropped_coupling(ross):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        to_ross_bearing(_record(cross=0.01), n=0)        # 1 %: below the warning ratio
    with pytest.warns(UserWarning, match="x, axial"):
        to_ross_bearing(_record(cross=0.2), n=0)
    with pytest.raises(InputError, match="^n"):
        to_ross_bearing(_record(), n=-1)
