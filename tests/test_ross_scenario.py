"""scenarios/ross_rotor_6208.py: the same rotor in ROSS on our 6208 coefficients and on ROSS's
BallBearingElement. Needs the optional extra (pip install -e ".[ross]")."""
import math
from pathlib import Path

import numpy as np
import pytest

pytest.importorskip("ross", reason="ROSS (ross-rotordynamics) not installed: pip install -e \".[ross]\"")

import exudyn_bearing as eb  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]


def test_ross_rotor_scenario(tmp_path, load_script):
    """Both rotors build and solve; independent numbers: ROSS's element follows the fit it documents,
    k_yy = 13e6 Z^(2/3) D^(1/3) F^(1/3) cos^(5/3) alpha; our exported coefficients are the quasi-static
    solver's at the same load, with the load direction on ROSS's y; each first lateral mode lies between
    Dunkerley's lower bound and the smaller of the rigid-bearing and rigid-rotor frequencies; and in each
    plane the rotor with the stiffer bearing has the higher first mode."""
    mod = load_script("scenarios/ross_rotor_6208.py")
    res = mod.main(["--speeds", "3", "--no-critical", "--out", str(tmp_path)])
    b = eb.catalog["6208"]
    f = res["load_per_bearing"]
    assert f == pytest.approx(res["rotor"]["mass"] * 9.81 / 2 + 1000.0)
    assert res["k_ross"]["vertical"] == pytest.approx(13e6 * b.n_balls ** (2 / 3) * (2 * b.ball_radius) ** (1 / 3)
                                                      * f ** (1 / 3), rel=1e-9)
    s = eb.solve_quasistatic(b, f, phase=0.0)
    z = b.n_balls
    k_mean = np.mean([eb.solve_quasistatic(b, f, phase=2 * math.pi / z * m / 3).stiffness for m in range(3)], axis=0)
    assert res["k_ours"]["vertical"] == pytest.approx(k_mean[0, 0], rel=1e-6)
    assert res["k_ours"]["horizontal"] == pytest.approx(k_mean[1, 1], rel=1e-6)
    assert s.stiffness[0, 0] > s.stiffness[1, 1]          # the load direction is the stiff one
    for key, v in res["bounds"].items():
        assert v["inside"], (key, v)
    modes = res["modes_at_rest"]
    for plane in ("horizontal", "vertical"):
        ours = res["bounds"][f"ours_{plane}"]["first"]
        ross = res["bounds"][f"ross_{plane}"]["first"]
        stiffer_ours = res["k_ours"][plane] > res["k_ross"][plane]
        assert (ours > ross) == stiffer_ours, (plane, ours, ross)
    assert modes["rigid"][0]["wd"] > max(m["wd"] for m in modes["ours"][:2])
    assert (tmp_path / "campbell.png").stat().st_size > 0 and (tmp_path / "campbell.csv").exists()
