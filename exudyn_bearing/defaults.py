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
}
#: Spellings that mean another quantity in one entry point ((entry point, parameter) -> quantity).
QUANTITY_BY_ENTRY = {("solve_thermal (API)", "lubrication"): "lubrication_method"}

#: Quantities two entry points may default differently, with the reason (quantity -> {entry point: reason}).
ALLOWED_DIFFERENCES = {
    "cage": {"ball element (CreateBallBearing)": "a switch (True: the bearing's cage balls) where Scenario and "
                                                 "simulate name the model ('torus', 'rigid', 'none'); both mean the "
                                                 "DEM papers' torus of cage balls"},
    "t_end": {"Scenario": "the Python API's run length (0.05 s: the DEM papers' runs); simulate on the CLI runs "
                          "0.02 s without --t-end or --ramp (cli.simulate.DEFAULT_T_END) for a first look in "
                          "seconds"},
    "initial": {"ball element (CreateBallBearing)": "the same 'analytic' start"},
    "Fr": {"dataset (CLI)": "a grid of labelled fault signals needs a load: the CWRU bearing test rig's "
                            "(about 1 kN on the 6205, --load)",
           "dataset_cases (API)": "the same grid as the dataset command"},
    "omega": {"dataset (CLI)": "the CWRU bearing test rig's 1797 rpm (--rpm), as the load",
              "dataset_cases (API)": "the same grid as the dataset command"},
    "progress": {"dataset (CLI)": "a command prints its progress line only with --progress (scripts read its "
                                  "output); run_sweep, called from Python, shows it by default"},
}


def _scenario_defaults() -> dict:
    from .model.scenario import Scenario

    out = {}
    for f in dataclasses.fields(Scenario):
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


def _cli_defaults() -> dict:
    """{command: {option dest: default}} of every CLI command (argparse)."""
    from .cli import COMMANDS, command_module
    from .cli.common import Parser

    out = {}
    for name in COMMANDS:
        p = Parser(prog="exudyn-bearing")
        sub = p.add_subparsers(dest="command", parser_class=Parser)
        command_module(name).add_parser(sub)
        parser = sub.choices[name]
        opts = {}
        for a in parser._actions:
            if isinstance(a, (argparse._HelpAction, argparse._SubParsersAction)) or a.dest in ("json",):
                continue
            label = a.option_strings[-1] if a.option_strings else a.dest.upper()
            if a.required:
                value = "(required)"
            elif not a.option_strings and a.nargs is None:
                value = "(required)"
            else:
                value = a.default
            opts[a.dest] = (label, value)
        for k, v in parser._defaults.items():  # set_defaults: e.g. the speed when neither --omega nor --rpm
            if k == "omega_default":
                opts["omega"] = ("--omega / --rpm", "(required)" if v is None and name == "simulate" else
                                 (0.0 if v is None else v))
        out[name] = opts
    return out


def collect() -> dict:
    """{entry point: {parameter: default}} of every entry point (CLI entries as (option, default))."""
    from .datasets import dataset_cases
    from .simulate import simulate
    from .solvers.element.element import BallBearingElement
    from .solvers.quasistatic import bearing_coefficients, solve_quasistatic
    from .solvers.quasistatic.levels.base import LevelBearing
    from .solvers.quasistatic.levels.element import QuasiStaticBearing
    from .solvers.quasistatic.losses import power_losses
    from .solvers.quasistatic.thermal import solve_thermal
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
        "ball element (CreateBallBearing)": _signature_defaults(BallBearingElement.__init__),
        "levels quasistatic, linear (CreateBallBearing)": {
            **_signature_defaults(LevelBearing.__init__),
            **{f"{k} (quasistatic)": v for k, v in _signature_defaults(QuasiStaticBearing.__init__,
                                                                        skip=("self", "args")).items()}},
    }
    for name, opts in _cli_defaults().items():
        out[f"{name} (CLI)"] = opts
    return out


def _norm(quantity, value):
    """A default in the form two entry points compare: initialLoad split, the tilt rule, numbers as floats."""
    if quantity == "tilt":
        return "fixed" if value in (None, "fixed") else value
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
            q = QUANTITY_BY_ENTRY.get((entry, name), QUANTITY.get(name, name))
            if q == "Fr, Fa" and isinstance(value, (tuple, list)) and len(value) == 2:
                out.setdefault("Fr", {})[entry] = (f"{label}[0]", value[0])
                out.setdefault("Fa", {})[entry] = (f"{label}[1]", value[1])
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
                if v is not None and v != "(required)" and e not in allowed}
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
             "Generated from the code by `python -m exudyn_bearing.defaults` (do not edit; "
             "tests/test_defaults.py fails when this file is stale, and when two entry points default one "
             "quantity differently without a reason in `exudyn_bearing.defaults.ALLOWED_DIFFERENCES`).",
             "", "Rules: loads default to zero everywhere; speeds to zero, except `simulate` on the CLI, which "
             "needs a speed (--omega or --rpm); the inner-ring tilt is held at zero everywhere "
             "(`solve_quasistatic(fixed=None)`, the CLI's `--tilt fixed`; a free tilt by `fixed={}` or "
             "`--tilt free`); the ball drag and rolling resistance are off in the dynamic engines (the summary's "
             "whole loss adds their quasi-static estimate, docs/theory/losses.md); the stiffness averages "
             "`n_phases` = 1 ball-set position (`bearing_coefficients`, `stiffness --phases`; its spread over the "
             "positions is reported in `operating_point`); the ball element's `stepSize` is Scenario's `dt`, "
             "1 us (the DEM papers' step) with `mode='bodies'`: README's 3.5-5 us in `mode='fast'` is a speed-up "
             "that stays below the 6208's stable step (`element.stable.dt`), not a default; the bearing levels "
             "leave the tilt free, as a DOF of the user's model (their operating point and tables are solved "
             "with `fixed={}`). The DEM papers' case (F_r = 3000 N, omega = 500 rad/s) is README's example and "
             "the default of `Scenario.papers_protocol` and `Scenario.quasi_static` only.", ""]
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
