"""Lubricants with temperature: ASTM D341 (Walther), Gold's pressure-viscosity form, density, Cragoe's
conductivity and specific heat (physics.lubricant_properties) and the data of
lubricants_temperature.json (data.lubricants_temperature)."""
import math

import pytest

from exudyn_bearing.data import InputError, lubricants
from exudyn_bearing.data.lubricants_temperature import (LubricantTemperatureData, get_lubricant_temperature,
                                                        lubricants_temperature)
from exudyn_bearing.physics import lubricant_properties as lp


def test_walther_z_and_its_inverse():
    # ASTM D341: above 2 mm^2/s Z is Walther's nu + 0.7 (the extra term is exp(-1.47 - 3.68 - 2.04) = 7.5e-4)
    assert lp.walther_z(2.0) - 2.7 == pytest.approx(math.exp(-1.47 - 1.84 * 2 - 0.51 * 4), rel=1e-12)
    assert lp.walther_z(30.0) == pytest.approx(30.7, abs=1e-12)
    # the standard's inverse is a fit of the forward form: they agree within 2e-4 mm^2/s from 0.3 to
    # 30 mm^2/s (the largest gap of these points is 1.7e-4 at 2 mm^2/s)
    for nu in (0.3, 0.5, 1.0, 2.0, 5.0, 30.0):
        assert lp.walther_nu(lp.walther_z(nu)) == pytest.approx(nu, abs=2e-4)


def test_walther_fit_hand_calculation():
    # log10 log10 Z = A - B log10 T through 32 mm^2/s at 313.15 K and 5.4 mm^2/s at 373.15 K, by hand
    y1, y2 = math.log10(math.log10(32.7)), math.log10(math.log10(5.4 + 0.7 + math.exp(-1.47 - 1.84 * 5.4
                                                                                          - 0.51 * 5.4 ** 2)))
    b = (y1 - y2) / (math.log10(373.15) - math.log10(313.15))
    a = y1 + b * math.log10(313.15)
    assert lp.walther_constants(313.15, 32e-6, 373.15, 5.4e-6) == pytest.approx((a, b), rel=1e-12)
    nu333 = 10 ** (10 ** (a - b * math.log10(333.15))) - 0.7          # above 2 mm^2/s: plain Walther
    assert lp.kinematic_viscosity_walther(333.15, a, b) == pytest.approx(nu333 * 1e-6, rel=1e-4)
    # the fit passes through both points
    assert lp.kinematic_viscosity_walther(373.15, a, b) == pytest.approx(5.4e-6, rel=1e-5)


def test_mil_l_23699_at_492_k_agrees_with_the_fixed_temperature_entry():
    # catalog.json's MIL-L-23699_492K: 1.22 mm^2/s at 492 K (plain Walther from 25 and 5 mm^2/s) times
    # 857 kg/m^3 = 1.04e-3 Pa s. ASTM D341's low-viscosity term lowers nu by 1 % (1.206 mm^2/s here).
    p = lp.properties_at("MIL-L-23699", 492.0)
    assert p["density"] == pytest.approx(857.0, abs=0.5)
    assert p["kinematic_viscosity"] == pytest.approx(1.22e-6, rel=0.015)
    assert p["viscosity"] == pytest.approx(lubricants["MIL-L-23699_492K"].viscosity, rel=0.015)


def test_gold_form_through_two_points():
    s, t = lp.gold_constants(32e-6, 2.1e-8, 5.4e-6, 1.6e-8)
    assert lp.pressure_viscosity_gold(32.0, s, t) == pytest.approx(2.1e-8, rel=1e-12)
    assert lp.pressure_viscosity_gold(5.4, s, t) == pytest.approx(1.6e-8, rel=1e-12)
    assert t == pytest.approx(math.log(1.6 / 2.1) / math.log(5.4 / 32.0), rel=1e-12)


def test_density_conductivity_specific_heat_hand_calculation():
    assert lp.density_linear(373.15, 288.15, 860.0, 0.6) == pytest.approx(860.0 - 0.6 * 85.0)
    # Cragoe 1929: k = 0.1167 (1 - 0.00054 theta) / d, c_p = (1.685 + 0.00339 theta) / sqrt(d) kJ/(kg K)
    assert lp.thermal_conductivity_cragoe(373.15, 900.0) == pytest.approx(0.1167 * (1 - 0.054) / 0.9, rel=1e-12)
    assert lp.specific_heat_cragoe(373.15, 900.0) == pytest.approx((1.685 + 0.339) / math.sqrt(0.9) * 1e3,
                                                                   rel=1e-12)


def test_catalogue_entries_reproduce_their_points_and_fall_with_temperature():
    assert {"MIL-L-23699", "ISO_VG_32_mineral", "ISO_VG_68_mineral"} <= set(lubricants_temperature)
    for name, d in lubricants_temperature.items():
        assert d.source
        for t, nu in d.viscosity_points:
            assert lp.properties_at(name, t)["kinematic_viscosity"] == pytest.approx(nu, rel=1e-5)
        for t, alpha in d.pressure_viscosity_points:
            assert lp.properties_at(name, t)["pressure_viscosity"] == pytest.approx(alpha, rel=1e-5)
        lo, hi = d.temperature_range
        cold, hot = lp.properties_at(name, lo), lp.properties_at(name, hi)
        for key in ("viscosity", "pressure_viscosity", "density"):
            assert hot[key] < cold[key]


def test_lubricant_at_gives_a_solver_lubricant():
    lub = lp.lubricant_at("ISO_VG_68_mineral", 333.15, mu_full_film=0.02)
    p = lp.properties_at("ISO_VG_68_mineral", 333.15)
    assert lub.viscosity == p["viscosity"] and lub.pressure_viscosity == p["pressure_viscosity"]
    assert lub.mu_full_film == 0.02 and lub.name == "ISO_VG_68_mineral@333.15K"


def test_quasistatic_losses_with_a_lubricant_at_temperature():
    import exudyn_bearing as eb
    from exudyn_bearing.solvers.quasistatic.losses import power_losses

    lub = lp.lubricant_at("ISO_VG_68_mineral", 333.15)
    s = eb.solve_quasistatic("6208", Fr=3000.0, omega=500.0, lubricant=lub, stiffness=False)
    d = s.to_dict()            # the solution's lubricant name "ISO_VG_68_mineral@333.15K" is rebuilt
    assert d["power_loss"]["ehl_rolling"] == power_losses(s, lubricant=lub)["power_loss"]["ehl_rolling"] > 0.0


def test_bad_input():
    with pytest.raises(InputError, match=r"temperature: 600 K is outside the range of lubricant 'MIL-L-23699'"):
        lp.properties_at("MIL-L-23699", 600.0)
    with pytest.raises(InputError, match="unknown lubricant"):
        get_lubricant_temperature("castor")
    good = dict(viscosity_points=[[313.15, 32e-6], [373.15, 5.4e-6]], density_reference=[288.15, 860.0],
                density_slope=0.6, pressure_viscosity_points=[[313.15, 2.1e-8], [373.15, 1.6e-8]],
                temperature_range=[253.15, 393.15])
    LubricantTemperatureData(**good)
    with pytest.raises(InputError, match="viscosity_points"):
        LubricantTemperatureData(**{**good, "viscosity_points": [[373.15, 5.4e-6], [313.15, 32e-6]]})
    with pytest.raises(InputError, match="temperature_range"):
        LubricantTemperatureData(**{**good, "density_slope": 10.0})         # zero density at 374 K
    with pytest.raises(InputError, match="density_reference"):
        LubricantTemperatureData(**{**good, "density_reference": "hot"})
