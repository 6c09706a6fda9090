"""One call to run a scenario on a bearing with a chosen engine (as PyBaMM's Simulation)."""
from __future__ import annotations

from .data import InputError, Lubricant
from .scenario import Scenario

__all__ = ["simulate", "ENGINES"]

#: Engines that :func:`simulate` knows.
ENGINES = ("reference", "exudyn")


def simulate(bearing, scenario: Scenario | None = None, engine: str = "reference",
             lubricant: Lubricant | None = None, progress=None):
    """Simulate ``scenario`` (default: ``Scenario()``) on ``bearing``.

    Parameters
    ----------
    bearing : BallBearing or str
        Bearing or catalogue name / JSON file.
    scenario : Scenario
    engine : {"reference", "exudyn"}
        The numba DEM reference core, or the same scene built in Exudyn with
        the bearing element (:mod:`exudyn_bearing.element`).
    lubricant : Lubricant, optional
    progress : bool or None
        Progress on stderr (None: for long runs).

    Returns
    -------
    Results
        ``.summary()``, ``.plot(png)``, ``.save(dir)``.

    Examples
    --------
    >>> import exudyn_bearing as eb
    >>> run = eb.simulate("6208", eb.Scenario(Fr=3000, omega=500, t_end=0.004, dt=2e-6))
    >>> round(run.summary()["cage_speed"])
    198
    """
    scenario = Scenario() if scenario is None else scenario
    if engine == "reference":
        from .reference import ReferenceEngine

        return ReferenceEngine(bearing, scenario, lubricant).run(progress=progress)
    if engine == "exudyn":
        from .element.engine import ExudynEngine

        return ExudynEngine(bearing, scenario, lubricant).run(progress=progress)
    raise InputError(f"engine: unknown engine {engine!r} (valid: {', '.join(ENGINES)})")
