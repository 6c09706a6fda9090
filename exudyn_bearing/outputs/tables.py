"""Tables a person reads: aligned rows of name, value and unit, and the summary of a run as one.

One implementation for the command line and the Python API: ``python -m exudyn_bearing simulate``
prints :func:`summary_rows` through :func:`format_table`, and ``print(run.summary())`` prints the
same table, because :meth:`~exudyn_bearing.outputs.results.Results.summary` returns a
:class:`Summary`, a ``dict`` whose ``str`` and ``repr`` are that table.
"""
from __future__ import annotations

import math

from .whole_loss import basis_text

__all__ = ["ROUND_OFF", "NOT_CONVERGED_MARK", "Summary", "format_value", "format_table", "summary_rows"]

#: Magnitudes printed as 0 in tables: round-off of solvers whose inputs are about 1e-3 m and 1 N or larger.
ROUND_OFF = {"m": 1e-15, "um": 1e-9, "N": 1e-9, "N m": 1e-9}

#: How a summary marks the entries of POINT_STEP_DEPENDENT (descriptions, the table).
NOT_CONVERGED_MARK = ("not converged: step-dependent at the point level; "
                      "use traction_level='ellipse' (--traction-level ellipse)")


def format_value(v, unit: str = "", digits: int = 6):
    """A float for a table: 6 significant digits, round-off below
    :data:`ROUND_OFF` of its unit (a length of 6.9e-18 m) shown as 0."""
    if isinstance(v, float):
        if abs(v) < ROUND_OFF.get(unit, 0.0):
            v = 0.0
        return f"{v + 0.0:.{digits}g}"
    return v


def format_table(rows) -> str:
    """Rows of (name, value) or (name, value, unit), aligned, one line each."""
    width = max(len(r[0]) for r in rows)
    lines = []
    for r in rows:
        k, v = r[0], r[1]
        unit = r[2] if len(r) > 2 and r[2] not in (None, "") else ""  # "-": dimensionless, said
        v = format_value(v, unit)
        lines.append(f"{k:<{width}}  {v}{'  ' + unit if unit else ''}".rstrip())
    return "\n".join(lines)


def _not_converged(value, unit):
    """A table value with its unit and the mark of a step-dependent output (:data:`NOT_CONVERGED_MARK`)."""
    v = format_value(value, unit or "")
    return f"{v}{' ' + unit if unit else ''}  ({NOT_CONVERGED_MARK})"


def summary_rows(summary, t_end=None):
    """Rows of a run's summary table (each scalar with its unit from ``summary["units"]``, then the
    losses, the energy sources, the regimes and the protocol phases); ``t_end``: the run length asked
    for, shown with the last sample's time when the sample interval (a whole number of steps) does not
    end on it."""
    units = summary["units"]
    w = summary["window"]
    st = summary["steady"]
    rows = [("window", f"{w['t0']:.6g} - {w['t1']:.6g} s, protocol phase '{w['phase']}' ({w['rule']}, "
                       f"{w['samples']} samples)"),
            ("steady", "yes (drift and oscillation within the thresholds of summary['steady'])" if st["steady"]
             else f"NO: {st['reason']}")]
    # the bearing's whole loss and torque first, with what is modelled and what estimated (outputs.whole_loss)
    first = ()
    if "power_loss_whole" in summary:
        first = ("power_loss_whole", "friction_torque_whole")
        rows += [("power_loss_whole", summary["power_loss_whole"], "W"),
                 ("friction_torque_whole", summary["friction_torque_whole"], units.get("friction_torque_whole")),
                 ("power_loss_whole_basis", basis_text(summary["power_loss_whole_basis"]))]
        rows += [(f"power_loss_estimated.{k}", v, "W") for k, v in (summary.get("power_loss_estimated") or {}).items()]
    # a quantity the run cannot give (None) says where the summary explains why, without a unit
    rows += [(k, v, units.get(k)) if v is not None else
             (k, f"n/a (energy_source.{k})" if k in summary.get("energy_source", {}) else "n/a")
             for k, v in summary.items() if not isinstance(v, (dict, list)) and k not in ("window", "note", *first)]
    # vectors of numbers (ring_displacement, cage_offset): their components on one row
    rows += [(k, ", ".join(format_value(float(x), (units.get(k) or "").split(" ")[0]) for x in v), units.get(k))
             for k, v in summary.items() if isinstance(v, list) and v and all(isinstance(x, (int, float)) for x in v)]
    if t_end is not None and "t_end" in summary and not math.isclose(summary["t_end"], t_end, rel_tol=1e-9):
        rows = [(k, f"{t_end:g} s (last sample at {summary['t_end']:.6g} s)", None) if k == "t_end" else r
                for r in rows for k in (r[0],)]
    work = summary.get("reduced_work") or {}
    if work.get("tolerance") is not None:  # the reduced engine's step error control: the steps it took
        rows.append(("step_control", f"tolerance {work['tolerance']:g}: {summary.get('steps')} steps, "
                                     f"{work['steps_rejected']} rejected, {work['restarts']} restarts; dt min / median "
                                     f"/ max {work['dt_min']:.3g} / {work['dt_median']:.3g} / {work['dt_max']:.3g} s"))
    rows += [(f"power_loss.{k}", v, "W") for k, v in summary["power_loss"].items()]
    rows.append(("q_max_method", ", ".join(f"{race}: {m}" for race, m in summary["q_max_method"].items())))
    rows += [(f"energy_source.{k}", v) for k, v in summary["energy_source"].items()]
    rows += [("losses_modelled", "; ".join(summary["losses_modelled"])),
             ("losses_not_modelled", "; ".join(summary["losses_not_modelled"]))]
    if summary.get("not_modelled"):  # everything the run leaves out (the losses above, the cage's, the engine's)
        rows.append(("not_modelled", "; ".join(summary["not_modelled"])))
    if "note" in summary:
        rows.append(("note", summary["note"]))
    rows += [(f"regime_fraction.{k}", v) for k, v in summary["regime_fraction"].items()]
    check = summary.get("energy_check") or {}
    if summary.get("energy_residual") is not None and check:
        # the energy check's verdict on the residual's row: not judged (a drive power below the loss floor: noise),
        # or a failure (the check's residual is of the sum of the reported losses)
        if check.get("passed") is None and check.get("reason"):
            note = f"not judged: {check['reason'].removesuffix(': not judged')}; energy_source.energy_residual"
        elif check.get("passed") is False:
            note = (f"energy check FAILS: residual of the reported losses {100 * check['residual']:.3g} %, "
                    f"tolerance {100 * check['tolerance']:g} %; energy_check")
        else:
            note = None
        if note:
            rows = [(r[0], f"{r[1]:.6g} ({note})") if r[0] == "energy_residual" else r for r in rows]
    marked = set(summary.get("not_converged", ()))  # step noise (the point level's friction outputs): said on the row
    rows = [(r[0], _not_converged(r[1], r[2] if len(r) > 2 else None)) if r[0] in marked and r[1] is not None else r
            for r in rows]
    for name, ph in summary.get("phases", {}).items():
        outer = f", omega_outer {ph['omega_outer']:.4g} rad/s" if "omega_outer" in ph else ""
        rows.append((f"phase {name}", f"{ph['t0']:.4g} - {ph['t1']:.4g} s: omega {ph['omega']:.4g} rad/s{outer}, cage "
                                      f"{ph['cage_speed']:.4g} rad/s, ball spin {ph['ball_spin']:.4g} rad/s, "
                                      f"q_max inner/outer {ph['q_max_inner']:.0f}/{ph['q_max_outer']:.0f} N"))
    return rows


class Summary(dict):
    """The summary of a run: a ``dict`` (keys, JSON, ``summary["cage_speed"]`` as before) that prints
    as the command line's table, each value with its unit (:func:`summary_rows`)::

        >>> print(run.summary())            # doctest: +SKIP
        window             0.15 - 0.25 s, protocol phase 'steady' (...)
        q_max_inner        1461.7  N
        cage_speed         198.0  rad/s
        ...

    ``dict(summary)`` or ``summary.items()`` give the plain mapping; the descriptions of the keys are
    in ``summary["descriptions"]``."""

    def __str__(self):
        return format_table(summary_rows(self))

    __repr__ = __str__
