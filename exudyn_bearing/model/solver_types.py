"""Exudyn's dynamic solvers the bearing models refuse, shared by the ball
element and the bearing levels (one check, one message)."""
from __future__ import annotations

from ..data import InputError

__all__ = ["IMPLICIT_SOLVERS", "UNSTABLE_SOLVERS", "settings_solver", "unstable_solver_error"]

#: Exudyn's implicit dynamic solvers (names of exudyn.DynamicSolverType).
IMPLICIT_SOLVERS = ("GeneralizedAlpha", "TrapezoidalIndex2")
#: Explicit solvers whose stability region leaves out the imaginary axis: an undamped oscillation grows at
#: every step (|1 + i w h| > 1 for any step h), and only damping holds it below a step limit.
UNSTABLE_SOLVERS = ("ExplicitEuler",)


def settings_solver(settings):
    """The name of the solver in Exudyn's simulation ``settings`` ("" if it has none)."""
    return getattr(getattr(getattr(settings, "timeIntegration", None), "solverType", None), "name", "")


def unstable_solver_error(solver, what, use, unless=""):
    """The InputError for a ``solver`` (a name) of UNSTABLE_SOLVERS, else None: it drives ``what`` (the
    contacts of a model) unstable ``unless`` (the condition, if any); ``use``: the solvers to use instead."""
    if solver not in UNSTABLE_SOLVERS:
        return None
    return InputError(f"solverType: {solver} drives {what} unstable{unless} (its stability region leaves out the "
                      f"undamped contact oscillation); use {use}")
