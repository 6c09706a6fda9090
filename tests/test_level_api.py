"""One API across CreateBallBearing's levels: results() on the quasistatic and linear levels (the Results
methods a level can give, the whole loss estimated), loadAngle on the ball element too."""
import math

import numpy as np
import pytest

exu = pytest.importorskip("exudyn")

import exudyn_bearing as eb  # noqa: E402
from exudyn_bearing.outputs.results import SUMMARY_KEYS  # noqa: E402
from exudyn_bearing.outputs.level_results import LEVEL_SUMMARY_KEYS  # noqa: E402

from test_levels import FR, SPEEDS, shaft  # noqa: E402

OMEGA = 200.0


@pytest.mark.parametrize("model", ["quasistatic", "linear"])
def test_levels_have_results_with_the_dynamic_summary_keys(model, tmp_path):
    _sc, mbs, _node, m_b, m_g = shaft(load=(FR, 0.0, 0.0), omega=OMEGA)
    br = eb.CreateBallBearing(mbs, "6208", m_b, m_g, model=model, initialLoad=(FR, 0.0), initialOmega=OMEGA,
                              coefficientSpeeds=SPEEDS)
    mbs.Assemble()
    ss = br.SimulationSettings(0.02)
    mbs.SolveDynamic(ss, solverType=ss.timeIntegration.solverType)
    res = br.results()
    s = res.summary()
    assert set(LEVEL_SUMMARY_KEYS) <= set(s)
    # the keys a level shares with the dynamic summary mean the same there
    assert set(LEVEL_SUMMARY_KEYS) - {"model", "ring_force", "Fr", "Fa", "omega", "bearing", "engine",
                                     "ring_displacement"} <= set(SUMMARY_KEYS)
    assert s["Fr"] == pytest.approx(FR, rel=1e-2) and s["omega"] == pytest.approx(OMEGA, rel=1e-2)
    assert (s["q_max_inner"] is None) == (model == "linear")
    # no modelled loss: the whole loss is the quasi-static estimate at the window's loads and speed
    sol = eb.solve_quasistatic("6208", Fr=s["Fr"], omega=s["omega"], fixed={"tilt_x": 0.0, "tilt_y": 0.0})
    from exudyn_bearing.solvers.quasistatic.losses import power_losses

    assert s["power_loss_total"] == 0.0 and s["power_loss_whole_basis"]["modelled"] == []
    assert s["power_loss_whole"] == pytest.approx(power_losses(sol)["power_loss_total"], rel=1e-6)
    npz, js = res.save(tmp_path)
    assert npz.exists() and js.exists()


def test_ball_element_places_its_balls_along_load_angle():
    # the same radial load along -y: the analytic state turned by -pi/2, the ring's displacement along -y and
    # the most loaded ball (nearest the load) at psi = -90 deg
    _sc, mbs, _node, m_b, m_g = shaft(load=(0.0, -FR, 0.0))
    a = eb.CreateBallBearing(mbs, "6208", m_b, m_g, initialLoad=(FR, 0.0), stepSize=5e-6)
    _sc, mbs2, _node, m_b2, m_g2 = shaft(load=(0.0, -FR, 0.0))
    b = eb.CreateBallBearing(mbs2, "6208", m_b2, m_g2, initialLoad=(FR, 0.0), stepSize=5e-6,
                             loadAngle=-0.5 * math.pi)
    da, db = a.initialRingDisplacement, b.initialRingDisplacement
    assert db[1] == pytest.approx(-da[0], rel=1e-12) and abs(db[0]) < 1e-12 * abs(da[0])
    def balls(mbs_, el):
        return np.array([mbs_.GetNodeParameter(n, "referenceCoordinates")[:3] for n in el.items["ballNodes"]])

    xa, xb = balls(mbs, a), balls(mbs2, b)
    assert np.allclose(xb[:, 0], xa[:, 1], atol=1e-12) and np.allclose(xb[:, 1], -xa[:, 0], atol=1e-12)
    with pytest.raises(eb.InputError, match="loadAngle"):
        eb.CreateBallBearing(mbs2, "6208", m_b2, m_g2, initialLoad=(FR, 0.0), loadAngle=90.0)


def test_summary_measures_psi_from_the_record_load_angle():
    # the same synthetic run turned by -pi/2 about z with load_angle -pi/2: the same azimuths and q_max
    import dataclasses
    import warnings

    from test_summary import _record

    a = _record()
    rz = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])  # rotation by -pi/2
    data = dict(a.data)
    for k in ("xb", "vb", "xc", "vc"):
        data[k] = a.data[k] @ rz.T
    b = eb.Results(dataclasses.replace(a.record, data=data, load_angle=-0.5 * math.pi))
    assert np.allclose(b.azimuth(), a.azimuth(), atol=1e-12)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        sa, sb = a.summary(), b.summary()
    assert sb["q_max_inner"] == pytest.approx(sa["q_max_inner"], rel=1e-12)
