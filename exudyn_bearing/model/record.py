"""What a dynamic solver hands over: the sampled series of one run and the
inputs that produced them (interpreted by :class:`exudyn_bearing.outputs.results.Results`)."""
from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from .layout import NDIAG, NGLOBAL

__all__ = ["RunRecord", "RunInterrupted", "sample_buffers"]


def sample_buffers(n_samples: int, z: int) -> dict:
    """The zeroed sample buffers of a dynamic engine's run of ``n_samples`` samples and ``z`` balls: the
    arrays of :attr:`RunRecord.data` (``t``, ``glob``, ``diag``, ``cage_load``, ``xb``, ``vb``, ``wb``, ``xc``,
    ``vc``, ``ring``; layouts in :mod:`.layout`), one row per sample."""
    return {
        "t": np.zeros(n_samples), "glob": np.zeros((n_samples, NGLOBAL)),
        "diag": np.zeros((n_samples, z, 2, NDIAG)), "cage_load": np.zeros((n_samples, z, 2)),
        "xb": np.zeros((n_samples, z, 3)), "vb": np.zeros((n_samples, z, 3)),
        "wb": np.zeros((n_samples, z, 3)), "xc": np.zeros((n_samples, z, 3)),
        "vc": np.zeros((n_samples, z, 3)), "ring": np.zeros((n_samples, 6)),
    }


@dataclass
class RunRecord:
    """One run of a dynamic solver.

    ``data`` holds the sampled arrays (``t``, ``glob``, ``diag``,
    ``cage_load``, ``xb``, ``vb``, ``wb``, ``xc``, ``vc``, ``ring``; layouts in
    :mod:`exudyn_bearing.model.layout`) and, when the scenario asked for
    signals, ``signal_t`` and ``signal`` (``SIGNAL_FIELDS``), ``steps`` the time steps taken,
    ``wall_s`` the wall time of the integration [s], ``engine`` the solver's
    name, ``stable_dt`` its stable-step estimate [s], ``static`` the
    quasi-static solution the run started from (None if not known),
    ``load_angle`` the azimuth of the radial load from the outer ring's x axis
    [rad] (the element's ``loadAngle``; the summary measures psi from it).
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
    load_angle: float = 0.0


class RunInterrupted(KeyboardInterrupt):
    """Ctrl-C stopped a dynamic run (both engines): ``t`` the time reached
    and ``t_end`` the run's end [s], ``record`` the :class:`RunRecord` of the
    samples taken so far (None before the first; ``results``: their Results,
    set by :func:`exudyn_bearing.simulate`)."""

    def __init__(self, t: float, t_end: float, record=None):
        super().__init__(f"run stopped at t = {t:.6g} of {t_end:.6g} s")
        self.t, self.t_end, self.record = t, t_end, record
        self.results = None

    @property
    def samples(self) -> int:
        """Samples taken before the stop."""
        return 0 if self.record is None else len(self.record.data["t"])
