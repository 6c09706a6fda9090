"""The user-facing entry points that combine data, model, solver and outputs
(as PyBaMM's Simulation): :func:`simulate` runs a scenario on a bearing with a
chosen engine and returns :class:`~exudyn_bearing.outputs.results.Results`;
:func:`CreateBallBearing` adds the bearing element to an Exudyn model."""
from __future__ import annotations

from .data import BallBearing, InputError, Lubricant, load_lubricant
from .model.scenario import Scenario
from .outputs.results import Results
from .solvers.element import BallBearingElement as _ElementBase

__all__ = ["simulate", "ENGINES", "CreateBallBearing", "BallBearingElement"]

#: Engines that :func:`simulate` knows.
ENGINES = ("reference", "exudyn")


def simulate(bearing, scenario: Scenario | None = None, engine: str = "reference",
             lubricant: Lubricant | None = None, progress=None) -> Results:
    """Simulate ``scenario`` (default: ``Scenario()``) on ``bearing``.

    Parameters
    ----------
    bearing : BallBearing or str
        Bearing or catalogue name / JSON file.
    scenario : Scenario
    engine : {"reference", "exudyn"}
        The numba DEM reference core, or the same scene built in Exudyn with
        the bearing element (:mod:`exudyn_bearing.solvers.element`).
    lubricant : Lubricant or str, optional
        Lubricant, catalogue name or JSON file (default: the DEM papers').
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
    lubricant = None if lubricant is None else load_lubricant(lubricant)
    if engine == "reference":
        from .solvers.reference import ReferenceEngine

        return Results(ReferenceEngine(bearing, scenario, lubricant).run(progress=progress))
    if engine == "exudyn":
        from .solvers.element.engine import ExudynEngine

        return Results(ExudynEngine(bearing, scenario, lubricant).run(progress=progress))
    raise InputError(f"engine: unknown engine {engine!r} (valid: {', '.join(ENGINES)})")


class BallBearingElement(_ElementBase):
    """The Exudyn bearing element of :mod:`exudyn_bearing.solvers.element` with
    ``results()``: the run's :class:`~exudyn_bearing.outputs.results.Results`."""

    def results(self, wall_s=None, steps=None) -> Results:
        """The sampled series of the run (``record()`` wrapped in Results)."""
        return Results(self.record(wall_s=wall_s, steps=steps))


def CreateBallBearing(mbs, bearing: BallBearing | str, markerInnerRing, markerOuterRing, **options):
    """Add a lubricated DEM ball bearing between two ring markers of ``mbs``.

    Parameters
    ----------
    mbs : exudyn.MainSystem
    bearing : BallBearing or str
        Geometry (catalogue name or JSON file).
    markerInnerRing, markerOuterRing : int
        Ring markers (see :mod:`exudyn_bearing.solvers.element.element` for the
        supported kinds).
    **options
        Keyword options of :class:`~exudyn_bearing.solvers.element.BallBearingElement`
        (``lubricant``, ``cage``, ``lubrication``, ``friction``, ``tangential``,
        ``hertzModel``, ``film``, ``stepSize``, ``innerRingSpeed``,
        ``initialOmega``, ``initialLoad`` ((Fr, Fa) [N] or a radial load Fr),
        ``sampleInterval``, ``show``, ...); an invalid option raises
        InputError naming it.

    Returns
    -------
    BallBearingElement
        Holds ``items`` and ``sensors``; ``results()`` after the solve.
    """
    return BallBearingElement(mbs, bearing, markerInnerRing, markerOuterRing, **options)
