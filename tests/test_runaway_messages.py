"""The element's blow-up message names the cause the evidence shows: non-finite input from the Exudyn model,
loads above the elastic contact limit, or else the step (model.stability.runaway_error)."""
import math

import pytest

exu = pytest.importorskip("exudyn")
from exudyn.itemInterface import (LoadForceVector, MarkerBodyRigid, MarkerNodePosition, NodePoint,  # noqa: E402
                                  ObjectGround, ObjectMassPoint)

import exudyn_bearing as eb  # noqa: E402
from exudyn_bearing.model.load_range import MAX_CONTACT_PRESSURE  # noqa: E402
from exudyn_bearing.model.stability import SimulationError  # noqa: E402
from exudyn_bearing.solvers.element.engine import solve_dynamic  # noqa: E402
from exudyn_bearing.solvers.element.userfunctions import overlap_contacts  # noqa: E402


def _shaft_run(load, t_end=2e-3, **options):
    """A 6208 between ground (outer ring) and a 1 kg shaft (mass point, inner ring) under the radial
    ``load`` [N] vector, 500 rad/s, solved with the element's own settings (VelocityVerlet at its step)."""
    SC = exu.SystemContainer()
    mbs = SC.AddSystem()
    ground = mbs.AddObject(ObjectGround())
    m_out = mbs.AddMarker(MarkerBodyRigid(bodyNumber=ground, localPosition=[0.0, 0.0, 0.0]))
    node = mbs.AddNode(NodePoint(referenceCoordinates=[0.0, 0.0, 0.0]))
    mbs.AddObject(ObjectMassPoint(mass=1.0, nodeNumber=node))
    m_in = mbs.AddMarker(MarkerNodePosition(nodeNumber=node))
    mbs.AddLoad(LoadForceVector(markerNumber=m_in, loadVector=load))
    el = eb.CreateBallBearing(mbs, "6208", m_in, m_out, initialOmega=500.0, sampleInterval=1e-3, **options)
    mbs.Assemble()
    solve_dynamic(mbs, el.SimulationSettings(t_end))
    return el


@pytest.mark.parametrize("mode", ["bodies", "fast"])
def test_a_huge_load_is_named_not_the_step(mode):
    # 1e6 N on a 6208: the quasi-static ball load (Stribeck, 5 F_r / Z = 5.6e5 N) is 25 times the
    # 21.8 kN at which the Hertz pressure reaches 4.2 GPa (model/load_range.py), and its overlap is
    # far past the runaway limit of 5 % of R_b: the run must stop, and the loads be named. When it
    # stops depends on the CPU's last bits; the message's cause does not.
    with pytest.raises(SimulationError, match=r"^load: the bearing state became non-finite or runaway at t = "
                                              r".* above 4\.2 GPa, the limit of the elastic contact model .*the "
                                              r"loads on the bearing are the likely cause, not the step"):
        _shaft_run([1e6, 0.0, 0.0], mode=mode)


@pytest.mark.parametrize("mode", ["bodies", "fast"])
def test_a_nan_load_is_named_as_the_model_input(mode):
    with pytest.raises(SimulationError, match=r"^markerInnerRing: the bearing state became non-finite at t = .*: "
                                              r"the inner ring marker's position and velocity handed to the "
                                              r"bearing element from the Exudyn model became non-finite .*the "
                                              r"input is non-finite, not the step"):
        _shaft_run([math.nan, 0.0, 0.0], mode=mode)


def test_a_planted_runaway_under_normal_loads_names_the_step(runaway):
    # the runaway limit below zero stops the run at its first check, where no load has been reached yet
    with pytest.raises(SimulationError, match=r"^stepSize: the bearing state became non-finite or runaway .*"
                                              r"reduce the solver step"):
        _shaft_run([3000.0, 0.0, 0.0], initialLoad=(3000.0, 0.0))


def test_overlap_contacts_at_the_elastic_limit():
    # Hertz: Q = K delta^1.5 and p_max = 3 Q / (2 pi a b); at the overlap where the inner contact's
    # pressure is the limit, the load is the contact's own closed form at that overlap
    b = eb.catalog["6208"]
    (q1, p1), (q1o, p1o) = overlap_contacts(b, 1e-5)
    (q8, p8), (q8o, p8o) = overlap_contacts(b, 8e-5)
    # Hertz scaling by hand: Q ~ delta^1.5, p_max ~ delta^0.5 (the ellipse's shape is load-independent)
    assert q8 / q1 == pytest.approx(8.0 ** 1.5, rel=1e-9)
    assert p8o / p1o == pytest.approx(8.0 ** 0.5, rel=1e-9)
    assert p1 < MAX_CONTACT_PRESSURE
