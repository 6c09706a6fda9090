"""``results()`` of the bearing levels without ball DOFs: the subset of
:class:`~exudyn_bearing.outputs.results.Results` that a level can give, with
the same method names (``t``, ``window``, ``summary``, ``save``) and the same
summary keys where the level knows the quantity (docs/theory/levels.md,
"One API across the levels").

The levels sample the ring pose, the force of the bearing on the inner ring,
the kinematic cage and (quasi-static level) the ball loads; they model no
loss. Their summary's whole loss is therefore the quasi-static estimate
(:func:`~exudyn_bearing.outputs.whole_loss.estimate_losses`) at the window's
mean loads and speed, labelled as such (``power_loss_whole_basis``).
"""
from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

from ..data import InputError
from .jsonio import to_jsonable
from .window_checks import sample_window
from .whole_loss import WHOLE_LOSS_DESCRIPTIONS, WHOLE_LOSS_UNITS, NOT_ESTIMATED, estimate_losses

__all__ = ["LEVEL_SUMMARY_KEYS", "LevelResults"]

#: Keys of a level's summary (all of them also keys of the dynamic summary, except ``model`` and ``ring_force``).
LEVEL_SUMMARY_KEYS = ("engine", "model", "bearing", "window", "Fr", "Fa", "omega", "cage_speed", "q_max_inner",
                      "q_max_outer", "ring_displacement", "ring_force", "power_loss", "power_loss_total",
                      "power_loss_estimated", "power_loss_whole", "power_loss_whole_basis", "friction_torque_whole",
                      "friction_torque_estimated", "not_modelled", "units", "descriptions")
_UNITS = {"Fr": "N", "Fa": "N", "omega": "rad/s", "cage_speed": "rad/s", "q_max_inner": "N", "q_max_outer": "N",
          "ring_displacement": "m", "ring_force": "N, N, N, N m, N m", "power_loss": "W per component",
          "power_loss_total": "W", **WHOLE_LOSS_UNITS}
_DESCRIPTIONS = {
    "Fr": "radial load on the inner ring over the window: |mean of minus the bearing's force in x, y|",
    "Fa": "axial load on the inner ring over the window: minus the mean of the bearing's axial force",
    "omega": "relative ring speed over the window: the mean cage speed over the kinematic cage ratio",
    "q_max_inner": "largest ball load over the window (quasi-static level; None on the linear level)",
    "ring_force": "mean force and moment of the bearing on the inner ring (outer-ring frame)",
    "power_loss": "losses the level models: none (the levels carry forces only)",
    "power_loss_total": "modelled components only: 0 (the whole loss is power_loss_whole)",
    **WHOLE_LOSS_DESCRIPTIONS,
}


class LevelResults:
    """The sampled series of a bearing level (``level.samples()``) with the
    :class:`~exudyn_bearing.outputs.results.Results` methods a level can give."""

    def __init__(self, level):
        self.level = level
        self.bearing = level.bearing
        self.model = level.model
        self.data = level.samples()
        self.loadAngle = level.loadAngle

    @property
    def t(self) -> np.ndarray:
        return self.data["t"]

    def window(self, fraction: float = 0.25, t_window=None) -> slice:
        """Slice of the last ``fraction`` of the samples, or of those with t in ``t_window = (t0, t1)``
        (:func:`.window_checks.sample_window`, as the ball element's results)."""
        return sample_window(self.t, fraction, t_window)

    def summary(self, fraction: float | None = None, t_window=None) -> dict:
        """Scalar results over the window (the last quarter of the run, the last ``fraction`` or
        ``t_window``): the keys :data:`LEVEL_SUMMARY_KEYS`, the loss keys of the dynamic summary with
        every loss estimated (:mod:`~exudyn_bearing.outputs.whole_loss`)."""
        w = self.window(0.25 if fraction is None else fraction, t_window)
        t = self.t[w]
        f = np.mean(self.data["force"][w], axis=0)
        omega = float(np.mean(self.data["cage_speed"][w])) / self.level.cageRatio
        fr, fa = float(math.hypot(f[0], f[1])), float(-f[2])

        def peak(name):
            x = self.data[name][w]
            return float(np.max(x)) if np.all(np.isfinite(x)) else None

        out = {"engine": f"level:{self.model}", "model": self.model, "bearing": self.bearing.name,
               "window": {"t0": float(t[0]), "t1": float(t[-1]), "samples": len(t),
                          "rule": "t_window" if t_window is not None else
                          f"last {100 * (0.25 if fraction is None else fraction):g} % of the run"},
               "Fr": fr, "Fa": fa, "omega": omega, "cage_speed": float(np.mean(self.data["cage_speed"][w])),
               "q_max_inner": peak("q_max_inner"), "q_max_outer": peak("q_max_outer"),
               "ring_displacement": [float(x) for x in np.mean(self.data["displacement"][w][:, :3], axis=0)],
               "ring_force": [float(x) for x in f], "power_loss": {}, "power_loss_total": 0.0}
        out.update(self._whole_loss(fr, fa, omega))
        out["not_modelled"] = ["every loss (the level carries forces only): see power_loss_estimated"]
        out["units"] = dict(_UNITS)
        out["descriptions"] = dict(_DESCRIPTIONS)
        return out

    def _whole_loss(self, fr, fa, omega) -> dict:
        """The whole loss, all of it estimated at (fr, fa, omega), cached by operating point."""
        key = (round(fr, 6), round(fa, 6), round(omega, 9))
        cache = self.__dict__.setdefault("_estimates", {})
        lv = self.level
        point = {"Fr": fr, "Fa": fa, "omega": omega}
        basis = {"modelled": [], "estimated": {}, "not_estimated": list(NOT_ESTIMATED), "operating_point": point,
                 "source": "solvers.quasistatic.losses.power_losses of solve_quasistatic at the window's mean loads "
                           "(moments left out, tilt held) and speed"}
        try:
            if key not in cache:
                cache[key] = estimate_losses(self.bearing, lv.lubricant, fr, fa, abs(omega),
                                             ring_growth=lv.ringGrowth, temperatures=lv.temperatures,
                                             hertz=lv.hertzModel)
        except (InputError, ValueError, ArithmeticError) as err:
            basis["error"] = f"no quasi-static estimate at this operating point: {err}"
            return {"power_loss_estimated": None, "power_loss_whole": None, "power_loss_whole_basis": basis,
                    "friction_torque_whole": None, "friction_torque_estimated": None}
        p = cache[key]["power_loss"]
        est = {k: float(v) for k, v in p.items() if not isinstance(v, str)}
        basis["estimated"] = {k: "quasi-static component" for k in est}
        whole = float(sum(est.values()))
        dw = abs(omega)
        t = whole / dw if dw > 0.0 else 0.0
        return {"power_loss_estimated": est, "power_loss_whole": whole, "power_loss_whole_basis": basis,
                "friction_torque_whole": t, "friction_torque_estimated": t}

    def save(self, directory, stem: str = "run") -> tuple[Path, Path]:
        """Write ``stem.npz`` (the samples) and ``stem.json`` (the summary) into ``directory``."""
        d = Path(directory)
        d.mkdir(parents=True, exist_ok=True)
        npz, js = d / f"{stem}.npz", d / f"{stem}.json"
        np.savez_compressed(npz, **{k: np.asarray(v) for k, v in self.data.items()})
        js.write_text(json.dumps(to_jsonable(self.summary()), indent=2))
        return npz, js

    def __repr__(self):
        return f"LevelResults(model={self.model!r}, bearing={self.bearing.name!r}, samples={len(self.t)})"
