"""The user-facing entry points that combine data, model, solver and outputs
(as PyBaMM's Simulation): :func:`simulate` runs a scenario on a bearing with a
chosen engine and returns :class:`~exudyn_bearing.outputs.results.Results`;
:func:`CreateBallBearing` adds the bearing element to an Exudyn model."""
from __future__ import annotations

import warnings

from .data import BallBearing, InputError, Lubricant, default_traction, load_bearing, load_lubricant
from .model.load_range import check_load_range, check_run_pressures
from .model.memory import check_sample_memory
from .model.record import RunInterrupted
from .model.scenario import Scenario, engine_speed_error, fixed_step_error
from .outputs.results import Results
from .solvers.element import BallBearingElement as _ElementBase
from .solvers.element.element import element_scenario

__all__ = ["simulate", "ENGINES", "MODELS", "CreateBallBearing", "BallBearingElement", "quasistatic_start",
           "spec_inputs", "SPEC_KEYS"]

#: Keys of a case spec (sweeps, datasets): see :func:`spec_inputs`; ``labels`` is
#: metadata a dataset carries into its records.
SPEC_KEYS = ("bearing", "scenario", "engine", "lubricant", "labels")

#: Engines that :func:`simulate` knows.
ENGINES = ("reference", "exudyn", "reduced")


def simulate(bearing, scenario: Scenario | None = None, engine: str = "reference",
             lubricant: Lubricant | None = None, progress=None) -> Results:
    """Simulate ``scenario`` (default: ``Scenario()``) on ``bearing``.

    Parameters
    ----------
    bearing : BallBearing or str
        Bearing or catalogue name / JSON file.
    scenario : Scenario, optional
        The run (None: ``Scenario()``, no load and at rest, docs/defaults.md;
        the DEM papers' case is ``Scenario(Fr=3000, omega=500)`` or
        ``Scenario.papers_protocol()``).
    engine : {"reference", "exudyn", "reduced"}
        The numba DEM reference core, the same scene built in Exudyn with
        the bearing element (:mod:`exudyn_bearing.solvers.element`), or the
        reduced engine (:mod:`exudyn_bearing.solvers.reduced`,
        docs/theory/reduced.md): the ball centres on their normal force
        balance at every step and a linearly implicit step of tens of
        microseconds (``Scenario.dt``, e.g. 2e-5); cage="none" or "rigid", no
        Cundall-Strack spring (friction="history" at the point level), no
        defects or signals (InputError naming what it does not take).
    lubricant : Lubricant or str, optional
        Lubricant, catalogue name, JSON file or dict (default: the bearing's,
        :func:`exudyn_bearing.data.default_lubricant`; the scenario's traction
        model likewise defaults to the bearing's).
    progress : bool or None
        Progress on stderr (None: for long runs); unless False, a reference
        run estimated to take over a minute says so on stderr first.

    Ctrl-C during the integration (either engine) raises
    :class:`~exudyn_bearing.model.record.RunInterrupted` (a
    KeyboardInterrupt) whose ``results`` hold the samples taken so far
    (None before the first).

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
    if engine not in ENGINES:
        raise InputError(f"engine: unknown engine {engine!r} (valid: {', '.join(ENGINES)})")
    bearing = load_bearing(bearing)
    scenario, lubricant = with_bearing_defaults(bearing, scenario, lubricant)
    err = engine_speed_error(scenario, engine)  # an engine without the outer ring's spin says so by name
    if err is not None:
        raise err
    if engine == "reduced":  # what it does not model, before any work
        from .solvers.reduced.engine import reduced_support_error

        err = reduced_support_error(scenario, bearing)
        if err is not None:
            raise err
    else:  # the step error control is the reduced engine's; the others take a fixed step
        err = fixed_step_error(scenario, engine)
        if err is not None:
            raise err
    check_sample_memory(bearing, scenario)  # before any work: the sampled series must fit in memory
    # the applied loads within the elastic contact model before the engines (and their compilation) start
    check_load_range(bearing if scenario.Pd is None else bearing.with_clearance(scenario.Pd), scenario.Fr,
                     scenario.Fa, scenario.hertz)
    # a speed whose ring growth closes the bearing is refused naming omega (the quasi-static solver's check),
    # not through the grown geometry's own plausibility check
    from .solvers.quasistatic.solve import check_operating_fit

    check_operating_fit(bearing if scenario.Pd is None else bearing.with_clearance(scenario.Pd), scenario.omega,
                        scenario.omega_outer, scenario.ring_growth)
    start = quasistatic_start(bearing, scenario, lubricant) if scenario.initial == "quasistatic" else None
    try:
        if engine == "reference":
            from .solvers.reference import ReferenceEngine

            record = ReferenceEngine(bearing, scenario, lubricant, start=start).run(progress=progress)
        elif engine == "reduced":
            from .solvers.reduced import ReducedEngine

            if scenario.dt < 5e-6 and scenario.tolerance is None:  # allowed, but the reference engine's step
                warnings.warn(f"dt: {scenario.dt:g} s is a step of the reference engine; the reduced engine's steps "
                              "are 1e-5 to 1e-4 s (docs/theory/reduced.md), and at this one it costs more than the "
                              "reference engine", UserWarning, stacklevel=2)
            record = ReducedEngine(bearing, scenario, lubricant, start=start).run(progress=progress)
            warn_unconverged(record)
        else:
            from .solvers.element.engine import ExudynEngine

            record = ExudynEngine(bearing, scenario, lubricant, start=start).run(progress=progress)
    except RunInterrupted as exc:  # Ctrl-C: the samples so far go with it, as Results
        if exc.samples:
            exc.results = Results(exc.record)
        raise
    check_record_pressures(record)
    return Results(record)


def warn_unconverged(record) -> None:
    """Warn when steps of a reduced-engine run (the engine's or the reduced level's) ended their force balance at
    its iteration limit: said, not hidden (the balance of these steps went on from its last iterate); above
    UNCONVERGED_SHARE of the steps the run's results are called unreliable."""
    bad = record.reduced_stats["unconverged_steps"]
    if not bad:
        return
    share = bad / max(record.steps, 1)
    consequence = ("" if share <= UNCONVERGED_SHARE else
                   f" That is {100 * share:.3g} % of the steps, more than {100 * UNCONVERGED_SHARE:g} %: "
                   "the run's loads, speeds and losses are not reliable; run it at a smaller dt (half "
                   "the step: the difference tells) or in the reference engine.")
    warnings.warn(f"reduced engine: the balls' force balance did not converge within its iteration "
                  f"limit in {bad} of {record.steps} steps (the run went on from the last iterate; "
                  "where a ball leaves the load zone and its contact opens, or at a pocket impact); the "
                  "summary's reduced_work counts them (--json on the command line); the reference "
                  "engine has no such balance." + consequence, UserWarning, stacklevel=3)


def check_record_pressures(record) -> None:
    """The elastic-contact limit on the pressures a run sampled
    (:func:`~exudyn_bearing.model.load_range.check_run_pressures`: an error
    for sustained excess, naming ``omega`` when the applied loads alone are
    within the limit, or ``omega_outer`` when the outer ring turns faster; a warning for a brief one)."""
    from .model.layout import D_PMAX

    diag = record.data.get("diag")
    if diag is None or len(diag) == 0:
        return
    sc = record.scenario
    faster = "omega_outer" if abs(sc.omega_outer) > abs(sc.omega) else "omega"  # the speed to reduce
    check_run_pressures(diag[:, :, :, D_PMAX], record.data["t"], faster)


def with_bearing_defaults(bearing: BallBearing, scenario: Scenario, lubricant=None):
    """(scenario, lubricant) with what they leave open taken from the bearing:
    the lubricant (a Lubricant, catalogue name, JSON file or dict; None: the
    bearing's, :func:`exudyn_bearing.data.default_lubricant`) and the
    scenario's traction model (None: the bearing's,
    :func:`exudyn_bearing.data.default_traction`). The run's record carries
    both names (``lubricant.name``, ``scenario.traction``)."""
    lub = load_lubricant(lubricant, bearing=bearing)
    if scenario.traction is None:
        scenario = scenario.replace(traction=default_traction(bearing))
    return scenario, lub


def spec_inputs(spec) -> dict:
    """The validated keyword arguments of :func:`simulate` for a case spec
    (the one validation path of sweeps and datasets): ``bearing`` (catalogue
    name, JSON file or dict), ``scenario`` (dict of Scenario fields or a
    Scenario), optional ``engine`` and ``lubricant`` (catalogue name, JSON
    file, dict of Lubricant fields or a Lubricant), ``labels`` (metadata,
    not read here). An unknown key of the
    spec or of its scenario raises InputError naming it.

    >>> sorted(spec_inputs({"bearing": "6208", "scenario": {"Fr": 3000.0}, "lubricant": "MIL-L-23699_492K"}))
    ['bearing', 'engine', 'lubricant', 'scenario']
    """
    from .data.errors import check_keys

    if not isinstance(spec, dict):
        raise InputError(f"spec: expected a dict with keys {', '.join(SPEC_KEYS)}, got {spec!r}")
    check_keys("spec key", spec, SPEC_KEYS)
    if "bearing" not in spec:
        raise InputError("bearing: missing in the spec")
    engine = spec.get("engine", "reference")
    if engine not in ENGINES:
        raise InputError(f"engine: unknown engine {engine!r} (valid: {', '.join(ENGINES)})")
    lub = spec.get("lubricant")
    return {"bearing": load_bearing(spec["bearing"]), "scenario": Scenario.from_dict(spec.get("scenario", {})),
            "engine": engine, "lubricant": None if lub is None else load_lubricant(lub)}


def quasistatic_start(bearing, scenario: Scenario, lubricant: Lubricant | None = None) -> dict:
    """Initial state of a dynamic run from the quasi-static solution at the
    scenario's loads and initial speed: ring displacement, ball positions and
    contact angles, orbital speeds and ball angular velocities by
    ``scenario.control`` (race control or minimum energy), with the
    scenario's traction model (regularised as the dynamic engines use it),
    ring growth and temperatures. The inner ring's
    tilts are held at zero (the dynamic engines' inner ring translates only);
    the solution is kept as ``start["static"]``.

    A scene with the rigid cage starts from the quasi-static solution with that
    cage (every ball at the cage's speed within its pocket play, the cage speed
    from its torque balance: docs/theory/quasistatic.md#the-rigid-cage), so
    that the run does not begin by pulling cageless balls' own orbital speeds
    together; where that solution does not apply (pockets unequally spaced,
    ``control='min-energy'``, the rings at rest) from the cageless one, as
    ``start["cage_start"]`` says."""
    from .model.parameters import dynamic_traction_model
    from .model.scenario import resolve_cage
    from .solvers.quasistatic import solve_quasistatic

    b = load_bearing(bearing)
    scenario, lubricant = with_bearing_defaults(b, scenario, lubricant)
    if scenario.Pd is not None:
        b = b.with_clearance(scenario.Pd)
    omega0, outer0 = scenario.omega_at(0.0), scenario.omega_outer_at(0.0)
    cage, why = _quasistatic_start_cage(b, resolve_cage(scenario, b), omega0 - outer0)
    sol = solve_quasistatic(b, Fr=scenario.Fr, Fa=scenario.Fa, omega=omega0, omega_outer=outer0,
                            control=scenario.control,
                            traction=dynamic_traction_model(scenario), lubricant=lubricant, ring_growth=scenario.ring_growth,
                            temperatures=scenario.temperatures, fixed={"tilt_x": 0.0, "tilt_y": 0.0},
                            hertz_method=scenario.hertz, n_strips=scenario.n_strips, n_across=scenario.n_across,
                            stiffness=False, inertia_check=False, **cage)  # a start: the run has the inertia
    start = sol.dynamic_start(b)
    start["static"] = sol
    start["cage_start"] = why
    return start


def _quasistatic_start_cage(bearing, scenario: Scenario, relative_speed: float):
    """(keyword arguments of the quasi-static solve, what they mean) for the cage of a quasi-static start:
    the rigid cage of a scene with one where the quasi-static solver takes it, else none; ``relative_speed``
    the rings' relative speed at t = 0 [rad/s]."""
    if scenario.cage != "rigid":
        return {}, f"cageless quasi-static solution (the scene's cage: {scenario.cage})"
    rc = scenario.rigid_cage_of(bearing)
    if rc.pocket_spacing_error != 0.0:
        return {}, "cageless quasi-static solution (the pockets are unequally spaced, which it cannot represent)"
    if scenario.control == "min-energy":
        return {}, "cageless quasi-static solution (control='min-energy' chooses each ball's orbital speed)"
    if relative_speed == 0.0:
        return {}, "cageless quasi-static solution (the rings turn together at t = 0: no cage speed to balance)"
    if scenario.pocket_film:
        return ({"cage": "rigid", "rigid_cage": rc, "pocket_film": True},
                "quasi-static solution with the rigid cage and its pocket film")
    return {"cage": "rigid", "rigid_cage": rc}, "quasi-static solution with the rigid cage"




class BallBearingElement(_ElementBase):
    """The Exudyn bearing element of :mod:`exudyn_bearing.solvers.element` with
    ``results()``: the run's :class:`~exudyn_bearing.outputs.results.Results`."""

    def results(self, wall_s=None, steps=None) -> Results:
        """The sampled series of the run (``record()`` wrapped in Results);
        sustained contact pressures above the elastic limit raise InputError
        (:func:`check_record_pressures`)."""
        import dataclasses

        record = dataclasses.replace(self.record(wall_s=wall_s, steps=steps), load_angle=self.loadAngle)
        check_record_pressures(record)
        return Results(record)


#: Share of a reduced-engine run's steps whose force balance may stop at its iteration limit before the run's
#: warning says its results are not reliable (the 6208 radial has one such step per run at 20 us: at
#: pocket-free steady states the iterate it goes on from is close; a run-up through a ramp with the rigid cage at
#: 20 us had 38 % and loads 18 % off those at 10 us).
UNCONVERGED_SHARE = 0.01

#: Bearing levels of :func:`CreateBallBearing` (``model=``).
MODELS = ("balls", "quasistatic", "linear", "reduced")
#: Options of ``model="reduced"`` (:mod:`exudyn_bearing.solvers.reduced.level`): the levels' common ones, the
#: ball element's physics options the reduced engine takes, and its own ``reducedStep`` (the largest step of the
#: slow states [s]; None: one per Exudyn step) and ``tiltWarning`` [rad].
REDUCED_OPTIONS = ("lubricant", "initialLoad", "loadAngle", "initialOmega", "ringGrowth", "temperatures", "hertzModel",
                   "sampleInterval", "show", "cage", "rigidCage", "pocketFilm", "lubrication", "friction", "film",
                   "guideClearance", "muDry", "regularizingSpeed", "tractionLevel", "traction", "nStrips", "nAcross",
                   "tractionRegularizingSrr", "control", "initial", "rollingResistance", "ballDrag",
                   "oilVolumeFraction", "hysteresisLossFactor", "cageDamping", "reducedStep", "tiltWarning")
#: Defaults of ``model="reduced"`` where they differ from the ball element's: the rigid cage, the traction over
#: the contact ellipse (the reduced engine takes no Cundall-Strack spring) and the quasi-static start.
REDUCED_DEFAULTS = {"cage": "rigid", "tractionLevel": "ellipse", "initial": "quasistatic"}


def CreateBallBearing(mbs, bearing: BallBearing | str, markerInnerRing, markerOuterRing, model="balls",
                      **options):
    """Add a lubricated DEM ball bearing between two ring markers of ``mbs``.

    ``model`` picks the level: ``"balls"`` (default, the DEM element below),
    ``"reduced"`` (the reduced engine's balls and rigid cage advanced after
    each Exudyn step, the ball centres on their force balance inside Exudyn's
    Newton: :mod:`exudyn_bearing.solvers.reduced.level`, options
    ``REDUCED_OPTIONS``, ``results()`` the engines' Results,
    docs/theory/levels.md#reduced-level), ``"quasistatic"`` (5-DOF force
    element from the quasi-static ball equilibrium, no ball DOFs) or
    ``"linear"`` (speed-dependent 5x5 stiffness and damping about the
    operating point ``initialLoad``); the last two are
    :mod:`exudyn_bearing.solvers.quasistatic.levels` (docs/howto/rotor.md,
    docs/theory/levels.md) and take ``lubricant``, ``initialLoad``, ``loadAngle``, ``initialOmega``,
    ``ringGrowth``, ``temperatures``, ``hertzModel``, ``sampleInterval``,
    ``coefficients``, ``coefficientSpeeds``, ``show``, ``operatingTilt``
    ("free": the operating point and the tables with the tilt free, a single
    bearing's equilibrium; "held": at zero, a bearing whose rotor's other
    supports hold the tilt) (quasistatic also ``cageAngle``, ``formulation``). ``model="quasistatic"`` with ``arrangement`` ("DB", "DF", "DT"), ``preload`` and
    ``spacing`` puts a pair of angular-contact bearings between the markers
    (:mod:`exudyn_bearing.solvers.quasistatic.levels.pair`, docs/theory/pairs.md).

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
        (``lubricant``, ``cage`` ("torus", "rigid" or "none"; True / False for torus / none), ``rigidCage``
        (a RigidCage for cage="rigid"; None: the bearing's estimated cage), ``gravity`` (on the rigid cage,
        world frame), ``pocketFilm`` (the ball / pocket oil film of the rigid cage), ``lubrication``, ``friction``,
        ``tangential``,
        ``cageDamping`` (Scenario's ``cage_damping``; "implicit" needs VelocityVerlet), ``hertzModel``, ``film``, ``stepSize``, ``innerRingSpeed``,
        ``initialOmega``, ``initialLoad`` ((Fr, Fa) [N] or a radial load Fr),
        ``sampleInterval``, ``show``, the loss switches ``rollingResistance``,
        ``ballDrag``, ``oilVolumeFraction``, ``hysteresisLossFactor`` of
        docs/theory/losses.md, ...); an invalid option raises InputError
        naming it.

    Returns
    -------
    BallBearingElement
        Holds ``items`` and ``sensors``; ``results()`` after the solve.
    """
    if model != "balls":
        return _create_level(mbs, bearing, markerInnerRing, markerOuterRing, model, options)
    import inspect

    valid = [k for k in inspect.signature(BallBearingElement.__init__).parameters
             if k not in ("self", "mbs", "bearing", "markerInnerRing", "markerOuterRing")]
    for key in options:  # the element's own keyword check raises TypeError: the option named instead
        if key not in valid:
            raise InputError(f"{key}: not an option of model='balls' (valid: {', '.join(valid)})")
    if options.get("initial") == "quasistatic" and options.get("initialState") is None:
        # the element's own option checks (messages name the options), then its quasi-static start
        sc = element_scenario(bearing, **options)
        options["initialState"] = quasistatic_start(bearing, sc, options.get("lubricant"))
    return BallBearingElement(mbs, bearing, markerInnerRing, markerOuterRing, **options)


def _create_level(mbs, bearing, markerInnerRing, markerOuterRing, model, options):
    """The ``"quasistatic"`` and ``"linear"`` levels of :func:`CreateBallBearing`."""
    if model not in MODELS:
        raise InputError(f"model: must be one of {', '.join(MODELS)}, got {model!r}")
    if model == "reduced":
        return _create_reduced_level(mbs, bearing, markerInnerRing, markerOuterRing, options)
    if "arrangement" in options:  # a bearing pair (solvers/quasistatic/levels/pair.py)
        from .solvers.quasistatic.levels.pair import create_pair_level

        return create_pair_level(mbs, bearing, markerInnerRing, markerOuterRing, model, options)
    from .solvers.quasistatic.levels import (
        LEVEL_OPTIONS,
        LinearBearing,
        QuasiStaticBearing,
    )

    allowed = LEVEL_OPTIONS + (("cageAngle", "formulation") if model == "quasistatic" else ())
    for key in options:
        if key not in allowed:
            raise InputError(f"{key}: not an option of model={model!r} (valid: {', '.join(allowed)})")
    cls = _with_results(QuasiStaticBearing if model == "quasistatic" else LinearBearing)
    return cls(mbs, bearing, markerInnerRing, markerOuterRing, **options)


def _create_reduced_level(mbs, bearing, markerInnerRing, markerOuterRing, options):
    """``model="reduced"`` of :func:`CreateBallBearing` (:mod:`exudyn_bearing.solvers.reduced.level`): the ball
    element's options (``REDUCED_OPTIONS``, defaults ``REDUCED_DEFAULTS``) make the scene's Scenario, validated as
    the element validates them; what the reduced engine does not take is refused by its own message
    (:func:`~exudyn_bearing.solvers.reduced.engine.reduced_support_error`) naming the option."""
    from .solvers.element.element import rename_option_error
    from .solvers.reduced.engine import MAX_STEP, reduced_support_error
    from .solvers.reduced.level import TILT_WARNING, ReducedBearing, check_reduced_step

    for key in options:
        if key not in REDUCED_OPTIONS:
            raise InputError(f"{key}: not an option of model='reduced' (valid: {', '.join(REDUCED_OPTIONS)})")
    o = {**REDUCED_DEFAULTS, **options}
    own = {k: o.pop(k) for k in ("reducedStep", "tiltWarning", "show", "loadAngle") if k in o}
    lubricant = o.pop("lubricant", None)
    b = load_bearing(bearing)
    step = check_reduced_step(own.get("reducedStep"))
    scenario = element_scenario(b, stepSize=MAX_STEP if step is None else step, **o)
    scenario, lub = with_bearing_defaults(b, scenario, lubricant)
    err = reduced_support_error(scenario, b) or engine_speed_error(scenario, "reduced")
    if err is not None:
        raise rename_option_error(err)
    check_load_range(b, scenario.Fr, scenario.Fa, scenario.hertz, names=("initialLoad", "initialLoad", "bearing"))
    start = quasistatic_start(b, scenario, lub) if scenario.initial == "quasistatic" else None
    cls = _with_run_results(ReducedBearing)
    return cls(mbs, b, markerInnerRing, markerOuterRing, scenario, lub, start=start,
               loadAngle=own.get("loadAngle", 0.0), reducedStep=step,
               tiltWarning=own.get("tiltWarning", TILT_WARNING), show=own.get("show", False))


def _with_run_results(level_class):
    """``level_class`` with ``results()``: its ``record()`` as :class:`~exudyn_bearing.outputs.results.Results`,
    as the ball element's (the reduced level samples the reduced engine's state)."""
    if level_class not in _LEVEL_CLASSES:
        def results(self) -> Results:
            """The sampled series of the run as Results (the ball element's: per-ball loads, ball and cage speeds,
            dissipation, energy balance, ``summary()`` over a window); sustained contact pressures above the
            elastic limit raise InputError (:func:`check_record_pressures`)."""
            record = self.record()
            check_record_pressures(record)
            warn_unconverged(record)
            return Results(record)

        _LEVEL_CLASSES[level_class] = type(level_class.__name__, (level_class,),
                                           {"results": results, "__doc__": level_class.__doc__,
                                            "__module__": level_class.__module__})
    return _LEVEL_CLASSES[level_class]


_LEVEL_CLASSES = {}


def _with_results(level_class):
    """``level_class`` with ``results()``: the run's samples as
    :class:`~exudyn_bearing.outputs.level_results.LevelResults` (the methods of the ball element's
    ``results()`` that a level can give: ``t``, ``window``, ``summary``, ``save``; the summary's whole loss
    estimated by the quasi-static loss model, docs/theory/levels.md), as :class:`BallBearingElement` adds
    it to the element (the outputs layer sits above the solvers)."""
    if level_class not in _LEVEL_CLASSES:
        from .outputs.level_results import LevelResults

        def results(self):
            return LevelResults(self)

        results.__doc__ = _with_results.__doc__.split(":", 1)[1].strip()
        _LEVEL_CLASSES[level_class] = type(level_class.__name__, (level_class,),
                                           {"results": results, "__doc__": level_class.__doc__,
                                            "__module__": level_class.__module__})
    return _LEVEL_CLASSES[level_class]
