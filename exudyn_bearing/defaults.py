"""The defaults of every entry point, read from the code, and the check that
one quantity has one default (docs/defaults.md).

Entry points: the Python API's functions (their signatures, by
:mod:`inspect`), :class:`~exudyn_bearing.model.scenario.Scenario`'s fields
(what :func:`~exudyn_bearing.simulate`, sweeps and dataset specs default
to), the ball element's and the two levels' options of
:func:`~exudyn_bearing.CreateBallBearing`, and every CLI command's options
(its argparse defaults). :data:`QUANTITY` maps each spelling of a parameter
to the quantity it sets; :func:`conflicts` lists the quantities that two
entry points default differently unless :data:`ALLOWED_DIFFERENCES` gives
the reason. ``python -m exudyn_bearing.defaults`` rewrites docs/defaults.md
(tests/test_defaults.py fails when the committed file is stale).
"""
from __future__ import annotations

import argparse
import dataclasses
import inspect
import math
from pathlib import Path

__all__ = ["ALLOWED_DIFFERENCES", "QUANTITY", "QUANTITY_BY_ENTRY", "collect", "conflicts", "quantities", "render",
           "write"]

#: Spelling of a parameter in an entry point -> the quantity it sets (parameters not listed are their own
#: quantity under their name).
QUANTITY = {
    "Fr": "Fr", "Fa": "Fa", "initialLoad": "Fr, Fa", "omega": "omega", "initialOmega": "omega",
    "ring_growth": "ring_growth", "ringGrowth": "ring_growth", "hertz": "hertz", "hertz_method": "hertz",
    "hertzModel": "hertz", "n_strips": "n_strips", "nStrips": "n_strips", "strips": "n_strips",
    "n_across": "n_across", "nAcross": "n_across", "points_across": "n_across",
    "traction_regularizing_srr": "traction_regularizing_srr", "tractionRegularizingSrr": "traction_regularizing_srr",
    "dt": "dt", "stepSize": "dt", "sample_dt": "sample_dt", "sampleInterval": "sample_dt",
    "ball_drag": "ball_drag", "ballDrag": "ball_drag", "rolling_resistance": "rolling_resistance",
    "rollingResistance": "rolling_resistance", "oil_volume_fraction": "oil_volume_fraction",
    "oilVolumeFraction": "oil_volume_fraction", "hysteresis_loss_factor": "hysteresis_loss_factor",
    "hysteresisLossFactor": "hysteresis_loss_factor", "n_phases": "n_phases", "phases": "n_phases",
    "fixed": "tilt", "tilt": "tilt", "traction_level": "traction_level", "tractionLevel": "traction_level",
    "mu_dry": "mu_dry", "muDry": "mu_dry", "guide_clearance": "guide_clearance", "guideClearance": "guide_clearance",
    "cage_damping": "cage_damping", "cageDamping": "cage_damping", "loadAngle": "loadAngle",
    "contact_law": "contact_law", "contactLaw": "contact_law", "power_law": "power_law", "powerLaw": "power_law",
    "regularizing_speed": "regularizing_speed", "regularizingSpeed": "regularizing_speed",
    "tangential_stiffness_ratio": "tangential_stiffness_ratio",
    "tangentialStiffnessRatio": "tangential_stiffness_ratio", "signal_dt": "signal_dt",
    "signalInterval": "signal_dt", "load": "Fr", "loads": "Fr", "rpm": "omega", "speeds_rpm": "omega",
    "radial_load": "Fr", "axial_load": "Fa", "diametral_clearance": "Pd",
}
#: Spellings that mean another quantity in one entry point ((entry point, parameter) -> quantity).
QUANTITY_BY_ENTRY = {("solve_thermal (API)", "lubrication"): "lubrication_method",
                     ("solve_pair (API)", "fixed"): "fixed (pair shaft DOFs)"}

#: What an entry point does without a parameter to set it (entry point -> {quantity: behaviour}): shown in the
#: tables and compared as the parameters' defaults are.
BEHAVIOUR = {
    "simulate (API)": {"tilt": "held (the reference engine's inner ring translates only)"},
    "ball element (CreateBallBearing)": {"tilt": "held in the initial state (then the user's node)"},
    "levels quasistatic, linear (CreateBallBearing)": {"tilt": "free (the user's node; operating point with "
                                                               "fixed={})"},
    "solve_pair (API)": {"tilt": "free with spacing (held without)"},
    "power_losses (API)": {"ball_drag": True, "rolling_resistance": True},
    "level reduced (CreateBallBearing)": {"tilt": "held (the reduced engine's inner ring translates only; a "
                                                  "relative tilt above tiltWarning warns)"},
}

#: The reason of the 3-DOF vibration model's operating point.
ELHAD = ("the 3-DOF model's source case, El Had et al. (2014)'s SKF 6004 at 500 N and 3000 rpm with 12.5 um "
         "clearance, which it reproduces (docs/theory/vibration.md); a linear model about zero load has no Hertz "
         "stiffness")

#: The reason of the reduced level's defaults (cage, traction level, start).
REDUCED_LEVEL = ("the reduced engine takes neither the torus cage nor the Cundall-Strack spring of the point level "
                 "(its refusals, reduced_support_error), and its level is for the balls' skidding and the cage in a "
                 "rotor: the rigid cage, the traction over the ellipse and the quasi-static start, from which the "
                 "rotor starts on the bearing's equilibrium as at the other levels (docs/theory/levels.md)")

#: Quantities two entry points may default differently, with the reason (quantity -> {entry point: reason}).
ALLOWED_DIFFERENCES = {
    "traction_level": {"level reduced (CreateBallBearing)": REDUCED_LEVEL},
    "initial": {"level reduced (CreateBallBearing)": REDUCED_LEVEL},
    "t_end": {"Scenario": "the Python API's run length (0.05 s: the DEM papers' runs); simulate on the CLI runs "
                          "0.02 s without --t-end or --ramp (cli.simulate.DEFAULT_T_END) for a first look in "
                          "seconds"},
    "progress": {"dataset (CLI)": "a command prints its progress line only with --progress (scripts read its "
                                  "output); run_sweep, called from Python, shows it by default"},
    "cage": {"quasistatic (CLI)": "the quasi-static solver has no torus of cage balls: 'none' (each ball its own "
                                  "orbital speed, solve_quasistatic(cage=None)) or its rigid cage",
             "solve_quasistatic (API)": "as the quasistatic command",
             "level reduced (CreateBallBearing)": REDUCED_LEVEL},
    "tilt": {"levels quasistatic, linear (CreateBallBearing)": "a level is a force element between the user's "
             "markers: the node's tilt is a DOF of the user's model, so the operating point it starts from is "
             "the free-tilt equilibrium (docs/theory/levels.md)",
             "solve_pair (API)": "two bearings at the given spacing carry a moment: the pair's shaft tilts freely "
                                 "(held at zero without a spacing, as a single bearing's)"},
    "ball_drag": {"power_losses (API)": "the quasi-static loss model always adds the ball drag (in air without "
                                        "oil_volume_fraction) and the rolling resistances as losses; the dynamic "
                                        "engines leave them out as forces by default and their summary's whole "
                                        "loss adds this estimate (docs/theory/losses.md)"},
    "rolling_resistance": {"power_losses (API)": "as ball_drag"},
    "Fr": {"dataset (CLI)": "a grid of labelled fault signals needs a load: the CWRU bearing test rig's "
                            "(about 1 kN on the 6205, --load)",
           "dataset_cases (API)": "the same grid as the dataset command",
           "Scenario.papers_protocol (API)": "the DEM papers' protocol: their 3000 N case",
           "Scenario.quasi_static (API)": "the DEM papers' Appendix A: their 3000 N case",
           **dict.fromkeys(("vibration three-dof (CLI)", "three_dof.derived_parameters (API)"), ELHAD)},
    "omega": {"dataset (CLI)": "the CWRU bearing test rig's 1797 rpm (--rpm), as the load",
              "dataset_cases (API)": "the same grid as the dataset command",
              "Scenario.papers_protocol (API)": "the DEM papers' protocol: their 500 rad/s steady speed",
              **dict.fromkeys(("vibration three-dof (CLI)", "three_dof.derived_parameters (API)"), ELHAD)},
    "bearing": {"simulate (CLI)": "the DEM papers' 6208, so that the older `simulate --Fr ... --omega ...` "
                                  "without a bearing keeps running; every other command needs the bearing",
                "dataset_cases (API)": "the CWRU bearing test rig's 6205 (the dataset command needs the "
                                       "bearing)",
                **dict.fromkeys(("vibration three-dof (CLI)", "three_dof.derived_parameters (API)"), ELHAD)},
    "Pd": dict.fromkeys(("vibration three-dof (CLI)", "three_dof.derived_parameters (API)"), ELHAD),
    "t_ramp_up": {"Scenario.papers_protocol (API)": "the DEM papers' protocol"},
    "t_steady": {"Scenario.papers_protocol (API)": "the DEM papers' protocol"},
    "t_ramp_down": {"Scenario.papers_protocol (API)": "the DEM papers' protocol"},
}


#: The rules every entry point follows (the head of docs/defaults.md; docs/theory/README.md points here).
RULES = (
    "Rules (one per quantity; the tables below are read from the code and tests/test_defaults.py checks them):",
    "",
    ("- **Loads** default to zero everywhere (F_r, F_y, F_a, M_x, M_y; the levels' and the element's "
     "`initialLoad`). The DEM papers' case, F_r = 3000 N at omega = 500 rad/s, is README's example and the "
     "default of `Scenario.papers_protocol` and `Scenario.quasi_static` only; `simulate ACBB-120 --Fa 22240` "
     "loads the bearing axially only. The 3-DOF vibration model (`vibration three-dof`) keeps its source's "
     "operating point, El Had et al.'s 6004 at 500 N and 3000 rpm (a linear model needs a load)."),
    ("- **Speeds** default to zero (at rest), except that `simulate` on the command line needs a speed "
     "(`--omega` or `--rpm`; `--omega 0` runs at rest), and `info` and `static` take none (geometry, load "
     "distribution; a speed adds the kinematics and the lubrication map)."),
    ("- **Tilt**: the inner ring's tilt is held at zero (`solve_quasistatic(fixed=None)`, the CLI's "
     "`--tilt fixed`, the reference engine's translating ring, the ball element's initial state); a free "
     "tilt by `fixed={}` or `--tilt free` (needed for moment loads). Documented exceptions: the bearing "
     "levels in Exudyn (the tilt is the user's node's) and a pair with a spacing (it carries the moment)."),
    ("- **Stiffness** averages `n_phases` = 3 ball-set positions within one ball pitch "
     "(`bearing_coefficients`, `stiffness --phases`, the linear level's tables); the spread over them is "
     "reported (`operating_point['phase_spread_stiffness']`, the CLI's header and JSON). One position lies up to "
     "15 % from the 16-position mean of the diagonal entries on the 6208 and 6205, three within 2 %."),
    ("- **Ball drag and rolling resistance** are off as forces in both dynamic engines (Scenario, "
     "simulate, the ball element alike); the quasi-static loss model always counts them as losses, and a "
     "dynamic run's whole loss adds that estimate (docs/theory/losses.md)."),
    ("- **Step and mode of the ball element**: `stepSize` = Scenario's `dt` = 1 us (the DEM papers' step, "
     "the same scene as `simulate`) in `mode='bodies'`; a larger step up to the scene's stable step "
     "(`bearing.stable.dt`, 6.3 us for the 6208 at 3000 N and 500 rad/s; a larger one warns) and "
     "`mode='fast'` are speed-ups a model chooses (docs/howto/rotor.md), not defaults."),
    "- **Bearing first**: every command takes the bearing as its first argument (`dataset BEARING OUT`).",
    ("- **Files and sweeps**: a scenario read from a file or a sweep's case (`Scenario.from_dict`) takes "
     "Scenario's defaults below; a bearing file's optional fields those of 'bearing file'."),
)


def _scenario_defaults() -> dict:
    from .model.scenario import Scenario

    return _dataclass_defaults(Scenario)


def _dataclass_defaults(cls) -> dict:
    out = {}
    for f in dataclasses.fields(cls):
        if f.default is not dataclasses.MISSING:
            out[f.name] = f.default
        elif f.default_factory is not dataclasses.MISSING:  # type: ignore[misc]
            out[f.name] = f.default_factory()  # type: ignore[misc]
    return out


def _signature_defaults(fn, skip=("self", "mbs", "bearing", "markerInnerRing", "markerOuterRing")) -> dict:
    out = {}
    for name, p in inspect.signature(fn).parameters.items():
        if name in skip or p.kind in (p.VAR_KEYWORD, p.VAR_POSITIONAL):
            continue
        out[name] = "(required)" if p.default is inspect.Parameter.empty else p.default
    return out


def _parser_defaults(name, parser, module) -> dict:
    """{option dest: (label, default)} of one (sub-)command's parser; a default None that the command takes
    from its module's ``DEFAULTS`` (vibration three-dof) is shown as that value."""
    table = getattr(module, "DEFAULTS", {})
    opts = {}
    for a in parser._actions:
        if isinstance(a, (argparse._HelpAction, argparse._SubParsersAction)) or a.dest in ("json",):
            continue
        if a.dest in opts:  # an alias of an option listed before (--no-cage for --cage none)
            continue
        label = " / ".join(a.option_strings) if a.option_strings else a.dest.upper()
        if a.required or not a.option_strings and a.nargs is None:
            value = "(required)"
        else:
            value = table.get(a.dest, a.default) if a.default is None else a.default
        opts[a.dest] = (label, value)
    for k, v in parser._defaults.items():  # set_defaults: e.g. the speed when neither --omega nor --rpm
        if k == "omega_default":  # add_speed_arguments / omega_from_args: None is no speed (info, static)
            opts["omega"] = ("--omega / --rpm", "(required)" if v is None and name == "simulate" else v)
            opts.pop("rpm", None)
        if k == "bearing_default":  # add_bearing_argument(default=...): BEARING may be left out
            opts["bearing"] = ("BEARING", v)
    return opts


def _cli_defaults() -> dict:
    """{command: {option dest: (label, default)}} of every CLI command and sub-command (argparse)."""
    from .cli import COMMANDS, command_module
    from .cli.common import Parser

    out = {}
    for name in COMMANDS:
        p = Parser(prog="exudyn-bearing")
        sub = p.add_subparsers(dest="command", parser_class=Parser)
        module = command_module(name)
        module.add_parser(sub)
        parser = sub.choices[name]
        models = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
        if not models:
            out[name] = _parser_defaults(name, parser, module)
        for m in models:  # vibration MODEL
            for model, subparser in m.choices.items():
                out[f"{name} {model}"] = _parser_defaults(name, subparser, module)
    return out


def collect() -> dict:
    """{entry point: {parameter: default}} of every entry point (CLI entries as (option, default))."""
    from .data.bearings import BallBearing
    from .datasets import dataset_cases
    from .model.scenario import Scenario
    from .physics.rating_life import rating_life
    from .simulate import simulate
    from .solvers.analytic import static_analysis
    from .solvers.element.element import BallBearingElement
    from .solvers.quasistatic import bearing_coefficients, solve_quasistatic
    from .solvers.quasistatic.levels.base import LevelBearing
    from .solvers.quasistatic.levels.element import QuasiStaticBearing
    from .solvers.quasistatic.levels.pair import PairBearing
    from .solvers.quasistatic.losses import power_losses
    from .solvers.quasistatic.pair import solve_pair
    from .solvers.quasistatic.thermal import solve_thermal
    from .solvers.vibration import three_dof
    from .sweep import run_sweep

    out = {
        "Scenario": _scenario_defaults(),
        "simulate (API)": _signature_defaults(simulate),
        "solve_quasistatic (API)": _signature_defaults(solve_quasistatic),
        "bearing_coefficients (API)": _signature_defaults(bearing_coefficients),
        "power_losses (API)": _signature_defaults(power_losses, skip=("sol", "bearing")),
        "solve_thermal (API)": _signature_defaults(solve_thermal),
        "dataset_cases (API)": _signature_defaults(dataset_cases, skip=()),
        "run_sweep (API)": _signature_defaults(run_sweep, skip=("cases", "out_dir")),
        "bearing file (BallBearing JSON)": _dataclass_defaults(BallBearing),
        "Scenario.papers_protocol (API)": _signature_defaults(Scenario.papers_protocol),
        "Scenario.quasi_static (API)": _signature_defaults(Scenario.quasi_static),
        "solve_pair (API)": _signature_defaults(solve_pair),
        "static_analysis (API)": _signature_defaults(static_analysis),
        "rating_life (API)": _signature_defaults(rating_life, skip=("bearing", "loads")),
        "three_dof.derived_parameters (API)": _signature_defaults(three_dof.derived_parameters, skip=()),
        "ball element (CreateBallBearing)": _signature_defaults(BallBearingElement.__init__),
        "levels quasistatic, linear (CreateBallBearing)": {
            **_signature_defaults(LevelBearing.__init__),
            **{f"{k} (quasistatic)": v for k, v in _signature_defaults(QuasiStaticBearing.__init__,
                                                                        skip=("self", "args")).items()}},
        "pair level (CreateBallBearing, arrangement=)": _signature_defaults(PairBearing.__init__),
        "level reduced (CreateBallBearing)": _reduced_level_defaults(BallBearingElement),
    }
    for name, opts in _cli_defaults().items():
        out[f"{name} (CLI)"] = opts
    for entry, behaviour in BEHAVIOUR.items():
        out[entry] = {**out[entry], **{f"{q} (no parameter)": v for q, v in behaviour.items()}}
    return out


def _reduced_level_defaults(element) -> dict:
    """The reduced level's options (simulate.REDUCED_OPTIONS): the ball element's defaults, the level's own
    (simulate.REDUCED_DEFAULTS) where they differ, and those of its constructor (reducedStep, tiltWarning)."""
    from .simulate import REDUCED_DEFAULTS, REDUCED_OPTIONS
    from .solvers.reduced.level import ReducedBearing

    own = _signature_defaults(ReducedBearing.__init__, skip=("self", "mbs", "bearing", "markerInnerRing",
                                                              "markerOuterRing", "scenario", "lubricant", "start"))
    base = {**_signature_defaults(element.__init__), **REDUCED_DEFAULTS, **own}
    return {k: v for k, v in base.items() if k in REDUCED_OPTIONS}


def _tilt(value):
    """The tilt rule of a default: "held" (solve_quasistatic's fixed=None, --tilt fixed, a behaviour "held ...")
    or "free" (fixed={}, --tilt free, "free ...")."""
    if value is None or value == "fixed" or (isinstance(value, str) and value.startswith("held")):
        return "held"
    if value == {} or value == "free" or (isinstance(value, str) and value.startswith("free")):
        return "free"
    return value


def _norm(quantity, value):
    """A default in the form two entry points compare: initialLoad split, the tilt rule, numbers as floats."""
    if quantity == "tilt":
        return _tilt(value)
    if quantity == "cage" and isinstance(value, bool):  # model.scenario.cage_model: True/False alias torus/none
        return "torus" if value else "none"
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, (int, float)):
        return float(value)
    if isinstance(value, (list, tuple)):
        return tuple(_norm(None, v) for v in value)
    return repr(value)


def quantities() -> dict:
    """{quantity: {entry point: (parameter spelling, default)}} over :func:`collect`."""
    out: dict = {}
    for entry, params in collect().items():
        for name, value in params.items():
            label = name
            if isinstance(value, tuple) and len(value) == 2 and entry.endswith("(CLI)"):
                label, value = value
            if name.endswith(" (no parameter)"):
                name = label = name[:-len(" (no parameter)")]
                label = "(no parameter)"
            q = QUANTITY_BY_ENTRY.get((entry, name), QUANTITY.get(name, name))
            if q == "Fr, Fa" and isinstance(value, (tuple, list)) and len(value) == 2:
                out.setdefault("Fr", {})[entry] = (f"{label}[0]", value[0])
                out.setdefault("Fa", {})[entry] = (f"{label}[1]", value[1])
                continue
            if value is None and entry in out.get(q, {}):  # --omega None beside --rpm 3000 (vibration)
                continue
            out.setdefault(q, {})[entry] = (label, value)
    return out


def conflicts() -> list[str]:
    """The quantities that two entry points default differently (not required or derived: None and
    '(required)' are left out) without an entry in :data:`ALLOWED_DIFFERENCES`; one line each."""
    bad = []
    for q, entries in quantities().items():
        allowed = ALLOWED_DIFFERENCES.get(q, {})
        vals = {e: _norm(q, v) for e, (_, v) in entries.items()
                if (v is not None or q == "tilt") and v != "(required)" and e not in allowed}
        if len(set(map(repr, vals.values()))) > 1:
            bad.append(f"{q}: " + "; ".join(f"{e} {v!r}" for e, v in vals.items()))
    return bad


def _fmt(v) -> str:
    if isinstance(v, float):
        return "inf" if math.isinf(v) else f"{v:g}"
    if callable(v) and not isinstance(v, type):
        return getattr(v, "__name__", repr(v))
    text = repr(v) if not isinstance(v, str) else v
    return text.replace("|", "\\|").replace("\n", " ")


def render() -> str:
    """docs/defaults.md: the defaults of every entry point, then the quantities several entry points set and
    the allowed differences with their reasons."""
    lines = ["# Defaults of every entry point", "",
             ("Generated from the code by `python -m exudyn_bearing.defaults` (do not edit; "
              "tests/test_defaults.py fails when this file is stale, and when two entry points default one "
              "quantity differently without a reason in `exudyn_bearing.defaults.ALLOWED_DIFFERENCES`)."),
             "", *RULES, ""]
    for entry, params in collect().items():
        lines += [f"## {entry}", "", "| parameter | default |", "|---|---|"]
        for name, value in params.items():
            if isinstance(value, tuple) and len(value) == 2 and entry.endswith("(CLI)"):
                name, value = value
            lines.append(f"| `{name}` | {_fmt(value)} |")
        lines.append("")
    lines += ["## One quantity, several entry points", "",
              "| quantity | entry point: parameter = default |", "|---|---|"]
    for q, entries in sorted(quantities().items()):
        if len(entries) < 2:
            continue
        cell = "; ".join(f"{e}: `{label}` = {_fmt(v)}" for e, (label, v) in entries.items())
        lines.append(f"| {q} | {cell} |")
    lines += ["", "## Allowed differences", "", "| quantity | entry point | reason |", "|---|---|---|"]
    for q, reasons in ALLOWED_DIFFERENCES.items():
        for e, why in reasons.items():
            lines.append(f"| {q} | {e} | {why} |")
    return "\n".join(lines) + "\n"


def write(path=None) -> Path:
    """Write :func:`render` to ``path`` (default: docs/defaults.md of the source tree)."""
    p = Path(path) if path is not None else Path(__file__).resolve().parent.parent / "docs" / "defaults.md"
    p.write_text(render())
    return p


if __name__ == "__main__":
    print(write())
