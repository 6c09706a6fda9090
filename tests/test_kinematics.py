"""Kinematic speeds and defect frequencies (Harris & Kotzalas ch. 8)."""
import math

import numpy as np
import pytest

from exudyn_bearing.physics import kinematics as kin
from exudyn_bearing.physics.geometry import groove_contact

RB, RP = 6.3e-3, 30.3e-3


def test_6208_speeds_at_500_rad_s():
    # docs/theory/reference_cases.md: ball spin omega R_i/(2 R_b) = 952.38 rad/s, cage 198.0 rad/s
    assert kin.ball_spin_absolute(500.0, 0.0, RB, RP) == pytest.approx(952.38, abs=0.005)
    assert kin.ball_spin_absolute(500.0, 0.0, RB, RP) == pytest.approx(500 * 24e-3 / (2 * RB), rel=1e-12)
    assert kin.cage_speed(500.0, 0.0, RB, RP) == pytest.approx(198.0, abs=0.05)


def test_rolling_without_slip_at_both_contacts():
    # the ball's surface speed equals each race's in the cage frame
    for alpha in (0.0, math.radians(40)):
        wc = kin.cage_speed(500.0, 0.0, RB, RP, alpha)
        wr = kin.ball_spin_relative(500.0, 0.0, RB, RP, alpha)
        ui, uo = kin.rolling_speeds(500.0, 0.0, RB, RP, alpha)
        assert ui == pytest.approx(uo, rel=1e-12)
        assert abs(wr) * RB == pytest.approx(ui, rel=1e-12)
        assert (500.0 - wc) * (RP - RB * math.cos(alpha)) == pytest.approx(ui)


@pytest.mark.parametrize("alpha_deg", [0.0, 15.0, 40.0])
def test_defect_frequencies_identities(alpha_deg):
    a = math.radians(alpha_deg)
    z = 9
    f = kin.defect_frequencies(500.0, 0.0, z, RB, RP, a)
    fr = 500.0 / (2 * math.pi)
    g = RB * math.cos(a) / RP
    # textbook closed forms (Harris & Kotzalas eq. 8.20-8.26)
    assert f["ftf"] == pytest.approx(fr / 2 * (1 - g))
    assert f["bpfo"] == pytest.approx(z * fr / 2 * (1 - g))
    assert f["bpfi"] == pytest.approx(z * fr / 2 * (1 + g))
    assert f["bsf"] == pytest.approx(fr * RP / (2 * RB) * (1 - g * g))
    assert f["bpfo"] + f["bpfi"] == pytest.approx(z * fr)


def test_outer_ring_rotating_swaps_the_race_roles():
    fi = kin.defect_frequencies(500.0, 0.0, 9, RB, RP)
    fo = kin.defect_frequencies(0.0, 500.0, 9, RB, RP)
    # with the outer ring rotating the cage runs at fr (1 + g)/2, and the
    # ball passes the (stationary) inner ring at Z f_c
    fr = 500 / (2 * math.pi)
    g = RB / RP
    assert fo["ftf"] == pytest.approx(fr / 2 * (1 + g))
    assert fo["bpfi"] == pytest.approx(fi["bpfi"]) and fo["bpfo"] == pytest.approx(fi["bpfo"])
    assert fo["bsf"] == pytest.approx(fi["bsf"])


def test_groove_contact_overlap_and_angle():
    # ball pushed 10 um radially out in a 6208 outer groove: overlap 10 um, alpha 0
    g = groove_contact([RP + 1e-5, 0.0, 0.0], 36.6e-3 - 6.552e-3, 0.0, 6.552e-3, RB, False)
    assert g["overlap"] == pytest.approx(1e-5, abs=1e-15)
    assert g["contact_angle"] == pytest.approx(0.0)
    np.testing.assert_allclose(g["normal"], [1, 0, 0])
    # ball moved along a 30 deg line from the groove centre: contact angle 30 deg
    rho, zg = 30.0e-3, 0.0
    d = 6.552e-3 - RB + 2e-6
    c = [rho + d * math.cos(math.pi / 6), 0.0, d * math.sin(math.pi / 6)]
    g = groove_contact(c, rho, zg, 6.552e-3, RB, False)
    assert g["overlap"] == pytest.approx(2e-6, abs=1e-15)
    assert g["contact_angle"] == pytest.approx(math.pi / 6)
    # same for the inner groove on the opposite side: angle keeps its sign convention
    c = [rho - d * math.cos(math.pi / 6), 0.0, -d * math.sin(math.pi / 6)]
    g = groove_contact(c, rho, zg, 6.552e-3, RB, True)
    assert g["contact_angle"] == pytest.approx(math.pi / 6)
    assert g["r_contact"] == pytest.approx(rho - 6.552e-3 * math.cos(math.pi / 6))
