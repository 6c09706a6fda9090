"""What a dynamic solver hands over: the sampled series of one run and the
inputs that produced them (interpreted by :class:`exudyn_bearing.outputs.results.Results`)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

__all__ = ["RunRecord"]


@dataclass
class RunRecord:
    """One run of a dynamic solver.

    ``data`` holds the sampled arrays (``t``, ``glob``, ``diag``,
    ``cage_load``, ``xb``, ``vb``, ``wb``, ``xc``, ``vc``, ``ring``; layouts in
    :mod:`exudyn_bearing.model.layout`) and, when the scenario asked for
    signals, ``signal_t`` and ``signal`` (``SIGNAL_FIELDS``), ``steps`` the time steps taken,
    ``wall_s`` the wall time of the integration [s], ``engine`` the solver's
    name, ``stable_dt`` its stable-step estimate [s], ``static`` the
    quasi-static solution the run started from (None if not known).
    """

    bearing: Any
    scenario: Any
    lubricant: Any
    data: dict
    steps: int
    wall_s: float
    engine: str
    stable_dt: float | None = None
    static: Any = None
