"""Defects and condition-monitoring signals of the bearing element: the spin
angle of rings with a prescribed speed, the ball body frames, and the
signal series (layout ``model.layout.SIGNAL_FIELDS``)."""
from __future__ import annotations

import math

import numpy as np

from ...data import InputError
from ...model.initial_state import initial_history
from ...model.layout import NSIGNAL
from . import kernels as EK

__all__ = ["SignalsMixin"]


class SignalsMixin:
    """Part of :class:`~.element.BallBearingElement`: defects and signals."""

    def _setup_defects_and_signals(self, outer_axes, exudyn_step):
        """Contact history with the balls' body frames along the outer ring's
        axes at t = 0 (``outer_axes``: its rotation matrix), the spin-angle
        state of rings with a prescribed speed (kept only when the scene has
        defects) and the signal state (``signalInterval``: a multiple of the
        Exudyn step ``exudyn_step``)."""
        z = self.bearing.n_balls
        self._hist0 = initial_history(z, outer_axes)
        self._hist = self._hist0.copy()
        self._hist_trial = self._hist0.copy()
        self._track_angle = bool(self.scenario.defects)
        # per ring: time, speed and angle of the base (last committed) and the last evaluation
        self._spin_state = np.full((2, 6), np.nan)
        interval = self.scenario.signal_dt
        self._sig = None
        self._signal_t, self._signal_rows = [], []
        if interval is not None:
            ratio = interval / exudyn_step
            if abs(ratio - round(ratio)) > 1e-9 * ratio or round(ratio) < 1:
                raise InputError(f"signalInterval: must be an integer multiple of the Exudyn step {exudyn_step:.6g} s "
                                 f"(stepSize times subSteps in the fast mode), got {interval:.6g} s")
            self._sig = np.zeros(EK.SIG_N)
            self._sig[EK.SIG_INTERVAL] = interval
            self._sig[EK.SIG_NEXT] = interval
            self._sig[EK.SIG_TPREV] = -math.inf
            self._sig_row = np.zeros(1 + NSIGNAL)

    def _reset_defects_and_signals(self, t):
        """A new run from t (:meth:`~.userfunctions.UserFunctionsMixin._restart`):
        contact history and ball body frames as at the start, ring spin angles
        and the signal series anew."""
        self._hist[:] = self._hist0
        self._hist_trial[:] = self._hist0
        self._spin_state[:] = np.nan
        self._signal_rows.clear()
        if self._sig is not None:
            interval = self._sig[EK.SIG_INTERVAL]
            self._sig[:] = 0.0
            self._sig[EK.SIG_INTERVAL] = interval
            self._sig[EK.SIG_NEXT] = t + interval
            self._sig[EK.SIG_TPREV] = -math.inf

    def _spin_angles(self, t):
        """Spin angle [rad] of the rings with a prescribed speed at t (ring data
        ``RD_ANGLE``): the speed integrated by the trapezoidal rule over the
        evaluation times, the base moving on when time advances (exact for a
        constant speed and on linear ramps between evaluations)."""
        for r, _f in self._speeds:
            st = self._spin_state[r]
            w = self._ring_data[r, EK.RD_SPIN]
            if not st[3] == st[3]:  # first evaluation: the angle starts at 0
                st[:] = (t, w, 0.0, t, w, 0.0)
            elif t > st[3]:
                st[0:3] = st[3:6]
            a = st[2] + 0.5 * (st[1] + w) * (t - st[0])
            st[3:6] = (t, w, a)
            self._ring_data[r, EK.RD_ANGLE] = a

    def _signal_sample(self, t):
        """Feed the evaluation at t to the signal series (:func:`~.kernels.signal_step`)."""
        if EK.signal_step(t, self._rings, self._fr, self._sig, self._sig_row):
            self._signal_rows.append(self._sig_row.copy())

    def _signal_data(self, data):
        """Add ``signal_t`` and ``signal`` to a record's data when the element records signals."""
        if self._sig is None:
            return
        rows = np.array(self._signal_rows).reshape(-1, 1 + NSIGNAL)
        data["signal_t"] = rows[:, 0].copy()
        data["signal"] = rows[:, 1:].copy()
