"""Stable-step estimate and its warning: every limit a step exceeds is named with
its consequence, and the a-priori cage limit follows the protocol (steady runs
from the analytic state load the cage with about 1 N, start-up and slow-down
with a tenth of the ball load); validation/studies/step_limits.py measures the claims."""
import warnings

import pytest

import exudyn_bearing as eb
from exudyn_bearing.model.stability import (CAGE_BLOW_UP_RATIO, START_UP_CAGE_LOAD, STEADY_CAGE_LOAD,
                                            expected_cage_load, stable_step, step_warning)

STEADY = eb.Scenario(Fr=3000.0, omega=500.0, t_end=0.2)
PROTOCOL = eb.Scenario(Fr=3000.0, omega=500.0, t_ramp_up=0.05, t_steady=0.2, t_ramp_down=0.05, t_end=0.3,
                       initial="rest")


def message(bearing, sc, dt):
    return step_warning(f"dt = {dt:.3g} s", dt, stable_step(eb.catalog[bearing], sc.replace(dt=dt)))


@pytest.mark.parametrize("tangential, dt", [("explicit", 5e-6), ("implicit", 8e-6)])
def test_readme_recommended_steady_steps_do_not_warn(tangential, dt):
    # README: steady runs at 5 us with the explicit spring, 8 us with the implicit one
    assert message("6208", STEADY.replace(tangential=tangential), dt) is None
    with warnings.catch_warnings():
        warnings.simplefilter("error", eb.StepSizeWarning)
        eb.simulate("6208", STEADY.replace(tangential=tangential, dt=dt, t_end=0.002))


def test_protocol_at_5_us_still_warns_about_the_cage_only():
    text = message("6208", PROTOCOL, 5e-6)
    assert "ball / cage-ball contacts" in text and "start-up and slow-down" in text
    assert "normal" not in text and "blow up" not in text and "cage loads may chatter" in text
    with pytest.warns(eb.StepSizeWarning, match="cage-ball"):
        eb.simulate("6208", PROTOCOL.replace(dt=5e-6, t_end=0.002, t_ramp_up=0.002))


def test_every_exceeded_limit_is_named_with_what_blows_up():
    text = message("6208", PROTOCOL, 9e-6)
    head = text.split(". ")[0]
    for limit in ("normal contacts", "tangential (Cundall-Strack) springs", "ball / cage-ball contacts"):
        assert limit in head
    assert "will blow up (normal contacts and cage contacts" in text
    assert "friction forces may chatter" in text and "tangential='implicit'" in text
    # the steady 6208 at 8 us with the explicit spring: the springs only
    text = message("6208", STEADY, 8e-6)
    assert "tangential" in text and "cage" not in text.split(". ")[0] and "blow up" not in text
    # regularised friction: named, chatters, does not blow up
    text = message("6208", STEADY.replace(friction="regularized"), 3e-6)
    assert "regularised friction" in text and "blow up" not in text


def test_7208_at_1_us_is_told_its_cage_contacts_may_blow_up():
    # validation/studies/step_limits.py: the 7208 under F_r = F_a = 3000 N blows up at 1 us, 1.6 times its
    # cage estimate (its loaded balls roll at different contact angles and load the cage)
    sc = eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0)
    st = stable_step(eb.catalog["7208"], sc)
    assert st.limited_by == "cage" and 1e-6 >= CAGE_BLOW_UP_RATIO * st.dt
    text = message("7208", sc, 1e-6)
    assert "unequal contact angles" in text and "may blow up (cage contacts" in text
    assert "may blow up" not in message("7208", sc, 0.8e-6)


@pytest.mark.parametrize("kw, fraction", [
    (dict(), STEADY_CAGE_LOAD),
    (dict(Fa=500.0), START_UP_CAGE_LOAD),             # unequal contact angles
    (dict(Fr=0.0, Fa=2000.0), STEADY_CAGE_LOAD),      # pure axial: one angle
    (dict(initial="rest"), START_UP_CAGE_LOAD),
    (dict(t_ramp_up=0.01), START_UP_CAGE_LOAD),
    (dict(t_steady=0.1, t_ramp_down=0.05), START_UP_CAGE_LOAD),   # slows down within t_end = 0.2
    (dict(t_steady=0.3, t_ramp_down=0.05), STEADY_CAGE_LOAD),     # ends before the slow-down
])
def test_expected_cage_load_follows_the_protocol(kw, fraction):
    assert expected_cage_load(eb.catalog["6208"], STEADY.replace(**kw))[0] == fraction


def test_exudyn_engine_estimates_the_protocol_like_the_reference_engine():
    from exudyn_bearing.solvers.element.engine import ExudynEngine
    from exudyn_bearing.solvers.reference import ReferenceEngine

    sc = PROTOCOL.replace(dt=3e-6)
    assert ExudynEngine("6208", sc).stable == ReferenceEngine("6208", sc).stable


@pytest.mark.parametrize("fr", [25000.0, 1e9])
def test_loads_outside_the_elastic_contact_range_are_refused(fr):
    # a 1e9 N load gave a 75 mm overlap without a word; the limit is the ISO 76 contact pressure
    from exudyn_bearing.model.load_range import MAX_CONTACT_PRESSURE, check_load_range, contact_pressures
    from exudyn_bearing.solvers.analytic import static_analysis

    limit = f"{MAX_CONTACT_PRESSURE / 1e9:g} GPa"
    with pytest.raises(eb.InputError, match=f"^radial_load: .*{limit}"):
        static_analysis(eb.catalog["6208"], fr)
    with pytest.raises(eb.InputError, match=f"^Fr: .*{limit}"):
        eb.simulate("6208", eb.Scenario(omega=500.0, Fr=fr, t_end=1e-4, dt=1e-6))
    # the papers' 3000 N: 2.2 GPa, well inside
    p_in, p_out = contact_pressures(check_load_range(eb.catalog["6208"], 3000.0))
    assert 0.4 * MAX_CONTACT_PRESSURE < p_in.max() < 0.6 * MAX_CONTACT_PRESSURE and p_out.max() < p_in.max()


def test_the_load_range_error_names_the_load():
    from exudyn_bearing.model.load_range import check_load_range

    with pytest.raises(eb.InputError, match="^Fa: F_r = 0 N, F_a = 50000 N give a contact pressure of"):
        check_load_range(eb.catalog["7208"], 0.0, 50000.0)
    assert check_load_range(eb.catalog["6208"], 0.0, 0.0) is None  # unloaded with clearance: nothing to check
