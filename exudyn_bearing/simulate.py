"""The user-facing entry points that combine data, model, solver and outputs
(as PyBaMM's Simulation): :func:`simulate` runs a scenario on a bearing with a
chosen engine and returns :class:`~exudyn_bearing.outputs.results.Results`;
:func:`CreateBallBearing` adds the bearing element to an Exudyn model."""
from __future__ import annotations

from .data import BallBearing, InputError, Lubricant, load_bearing, load_lubricant
from .model.scenario import Scenario
from .outputs.results import Results
from .solvers.element import BallBearingElement as _ElementBase

__all__ = ["ENGINES", "MODELS", "BallBearingElement", "CreateBallBearing", "quasistatic_start", "simulate"]

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
    if engine not in ENGINES:
        raise InputError(f"engine: unknown engine {engine!r} (valid: {', '.join(ENGINES)})")
    start = quasistatic_start(bearing, scenario, lubricant) if scenario.initial == "quasistatic" else None
    if engine == "reference":
        from .solvers.reference import ReferenceEngine

        return Results(ReferenceEngine(bearing, scenario, lubricant, start=start).run(progress=progress))
    from .solvers.element.engine import ExudynEngine

    return Results(ExudynEngine(bearing, scenario, lubricant, start=start).run(progress=progress))


def quasistatic_start(bearing, scenario: Scenario, lubricant: Lubricant | None = None) -> dict:
    """Initial state of a dynamic run from the quasi-static solution at the
    scenario's loads and initial speed: ring displacement, ball positions and
    contact angles, orbital speeds and ball angular velocities by
    ``scenario.control`` (race control or minimum energy), with the
    scenario's traction model (regularised as the dynamic engines use it),
    ring growth and temperatures. The inner ring's
    tilts are held at zero (the dynamic engines' inner ring translates only);
    the solution is kept as ``start["static"]``."""
    from .model.parameters import dynamic_traction_model
    from .solvers.quasistatic import solve_quasistatic

    b = load_bearing(bearing)
    if scenario.Pd is not None:
        b = b.with_clearance(scenario.Pd)
    sol = solve_quasistatic(b, Fr=scenario.Fr, Fa=scenario.Fa, omega=scenario.omega_at(0.0), control=scenario.control,
                            traction=dynamic_traction_model(scenario), lubricant=lubricant, ring_growth=scenario.ring_growth,
                            temperatures=scenario.temperatures, fixed={"tilt_x": 0.0, "tilt_y": 0.0},
                            hertz_method=scenario.hertz, n_strips=scenario.n_strips, n_across=scenario.n_across,
                            stiffness=False)
    start = sol.dynamic_start(b)
    start["static"] = sol
    return start




class BallBearingElement(_ElementBase):
    """The Exudyn bearing element of :mod:`exudyn_bearing.solvers.element` with
    ``results()``: the run's :class:`~exudyn_bearing.outputs.results.Results`."""

    def results(self, wall_s=None, steps=None) -> Results:
        """The sampled series of the run (``record()`` wrapped in Results)."""
        return Results(self.record(wall_s=wall_s, steps=steps))


#: Bearing levels of :func:`CreateBallBearing` (``model=``).
MODELS = ("balls", "quasistatic", "linear")


def CreateBallBearing(mbs, bearing: BallBearing | str, markerInnerRing, markerOuterRing, model="balls",
                      **options):
    """Add a lubricated DEM ball bearing between two ring markers of ``mbs``.

    ``model`` picks the level: ``"balls"`` (default, the DEM element below),
    ``"quasistatic"`` (5-DOF force element from the quasi-static ball
    equilibrium, no ball DOFs) or ``"linear"`` (speed-dependent 5x5 stiffness
    and damping about the operating point ``initialLoad``); the last two are
    :mod:`exudyn_bearing.solvers.quasistatic.levels` (README, "Bearing levels
    in Exudyn") and take ``lubricant``, ``initialLoad``, ``loadAngle``, ``initialOmega``,
    ``ringGrowth``, ``temperatures``, ``hertzModel``, ``sampleInterval``,
    ``coefficients``, ``coefficientSpeeds``, ``show`` (quasistatic also
    ``cageAngle``).

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
    if model != "balls":
        return _create_level(mbs, bearing, markerInnerRing, markerOuterRing, model, options)
    if options.get("initial") == "quasistatic" and options.get("initialState") is None:
        load = options.get("initialLoad", (0.0, 0.0))
        fr, fa = (float(load), 0.0) if isinstance(load, (int, float)) else (float(load[0]), float(load[1]))
        sc = Scenario(Fr=fr, Fa=fa, omega=float(options.get("initialOmega", 0.0)),
                      control=options.get("control", "auto"), traction=options.get("traction", "lambda_dem"),
                      ring_growth=bool(options.get("ringGrowth", False)), temperatures=options.get("temperatures"),
                      hertz=options.get("hertzModel", "exact"))
        options["initialState"] = quasistatic_start(bearing, sc, options.get("lubricant"))
    return BallBearingElement(mbs, bearing, markerInnerRing, markerOuterRing, **options)


def _create_level(mbs, bearing, markerInnerRing, markerOuterRing, model, options):
    """The ``"quasistatic"`` and ``"linear"`` levels of :func:`CreateBallBearing`."""
    if model not in MODELS:
        raise InputError(f"model: must be one of {', '.join(MODELS)}, got {model!r}")
    from .solvers.quasistatic.levels import (
        LEVEL_OPTIONS,
        LinearBearing,
        QuasiStaticBearing,
    )

    allowed = LEVEL_OPTIONS + (("cageAngle",) if model == "quasistatic" else ())
    for key in options:
        if key not in allowed:
            raise InputError(f"{key}: not an option of model={model!r} (valid: {', '.join(allowed)})")
    cls = QuasiStaticBearing if model == "quasistatic" else LinearBearing
    return cls(mbs, bearing, markerInnerRing, markerOuterRing, **options)
