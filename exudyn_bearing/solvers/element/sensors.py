"""Sensors, samples and the run record of the bearing element."""
from __future__ import annotations

import math
import warnings

import numpy as np

from ...model import layout as L
from ...model.record import RunRecord
from ...model.stability import StepSizeWarning, cage_load_check, land_step_check
from . import kernels as EK

__all__ = ["SensorsMixin"]


class SensorsMixin:
    """Part of :class:`~.element.BallBearingElement`: sensors, sampling, graphics, record."""

    def _add_sensors(self, mbs, n_cage):
        """Exudyn SensorUserFunction items for the element's quantities (``self.sensors``)."""
        from exudyn.itemInterface import SensorUserFunction

        self.sensors = {}
        if self.rigid:  # the rigid cage's spin about the bearing axis (its rows in _work: model.layout)
            def cage_speed():
                return [float(self._work[4, 1, 0])]
        else:
            def cage_speed():
                return [float(np.mean(self._orbital(self._work[3, :n_cage], self._work[4, :n_cage])))
                        if n_cage else float(np.mean(self._orbital(self._work[0], self._work[1])))]
        sensor_defs = {
            "cageSpeed": cage_speed,
            "qMaxInner": lambda: [float(self._diag[:, 0, 0].max())],
            "qMaxOuter": lambda: [float(self._diag[:, 1, 0].max())],
            "lambdaOuterPsi0": lambda: [float(self._diag[self._psi0(), 1, 8])],
            "innerRingForce": lambda: list(self._fr[0, :3]),
            "outerRingForce": lambda: list(self._fr[1, :3]),
        }
        for key, fn in sensor_defs.items():
            self.sensors[key] = mbs.AddSensor(SensorUserFunction(
                sensorNumbers=[], factors=[], storeInternal=True, writeToFile=False,
                sensorUserFunction=(lambda f: (lambda mbs_, t, sn, fac, conf: self._check_run(t) or f()))(fn)))

    @property
    def _row_offsets(self):
        """Start of each part of a sample row (:func:`~.kernels.sample_layout`) in it."""
        out, k = {}, 0
        for name, shape in EK.sample_layout(self.z):
            out[name] = k
            k += int(np.prod(shape))
        return out

    def _sample(self, t, rings):
        self._store(t, rings)
        self._next_sample += self.sampleInterval * max(1.0, math.floor((t - self._next_sample)
                                                                       / self.sampleInterval) + 1.0)

    def _graphics(self, mbs, itemNumber):
        """Graphics for Exudyn's renderer: balls, cage balls (or the rigid cage's section) and the two groove
        tori at the last evaluated state (world frame)."""
        import exudyn.graphics as gr

        b = self.bearing
        w = self._work
        data = [gr.Spheres(points=list(w[0]), radii=b.ball_radius, colors=[0.6, 0.6, 0.65, 1.0], nTiles=16)]
        if self.n_cage:
            data.append(gr.Spheres(points=list(w[3, :self.n_cage]), radii=b.cage_ball_radius,
                                   colors=[0.8, 0.6, 0.2, 1.0], nTiles=12))
        if self.rigid:  # the rigid cage's section, a hollow cylinder about the bearing axis (pockets not drawn)
            rc = self._cage_geometry
            axis = self.cageFrame[:, 2]
            data.append(gr.Cylinder(pAxis=list(w[3, 0] - 0.5 * rc.width * axis), vAxis=list(rc.width * axis),
                                    radius=rc.outer_radius, radiusInner=rc.inner_radius,
                                    color=[0.8, 0.6, 0.2, 0.5], nTiles=48))
        for r, ((rho, zg), rc) in enumerate(((b.inner_groove_center, b.inner_groove_radius),
                                             (b.outer_groove_center, b.outer_groove_radius))):
            a = self._rings[r, 6:15].reshape(3, 3)
            centre = self._rings[r, :3] + a[:, 2] * zg
            data.append(gr.Torus(point=list(centre), axis=list(a[:, 2]), radiusMajor=rho, radiusMinor=rc,
                                 color=[0.5, 0.5, 0.55, 0.3], nTilesMajor=48, nTilesMinor=12))
        return data

    def _store(self, t, rings):
        """Sample at t; ``rings``: the ring poses the balls saw there."""
        EK.sample_row(rings, self._work, self._glob, self._diag, self._cage_load, self._row)
        if self.rigid:
            # the rigid cage's angle and spin rows are no position and velocity: relative to the outer ring, as the
            # reference engine's (its outer ring is the frame), the angle and spin less the ring's about the bearing
            # axis (in the bearing frame)
            angle, spin = self._outer_ring_turn(rings[1, 6:15].reshape(3, 3)[:, 0], rings[1, 15:18])
            k = self._row_offsets["xc"] + 3
            self._row[k:k + 3] = (self._work[3, 1, 0] - angle - rings[1, L.R_ANGLE], 0.0, 0.0)
            k = self._row_offsets["vc"] + 3
            self._row[k:k + 3] = (self._work[4, 1, 0] - spin, 0.0, 0.0)
        self._sample_t.append(t)
        self._sample_rows.append(self._row.copy())

    @staticmethod
    def _orbital(x, v):
        r2 = x[:, 0] ** 2 + x[:, 1] ** 2
        return (x[:, 0] * v[:, 1] - x[:, 1] * v[:, 0]) / np.where(r2 > 0.0, r2, np.inf)

    def _psi0(self):
        return int(np.argmin(np.abs(np.arctan2(self._work[0, :, 1], self._work[0, :, 0]))))

    def record(self, wall_s=None, steps=None) -> RunRecord:
        """The sampled series of the run as a :class:`~exudyn_bearing.model.record.RunRecord`
        (the same layout as the reference engine's: positions, velocities and
        ring displacement in the outer-ring frame, ball angular velocity
        relative to the outer ring). ``exudyn_bearing.CreateBallBearing``'s
        element also has ``results()``, the same wrapped in
        :class:`~exudyn_bearing.outputs.results.Results`."""
        if not self._sample_t:
            ran = (self._clock[4] if self.mode == "fast" else self._evaluations) > 0
            if ran:
                raise RuntimeError(f"results: the run ended before its first sample, sampleInterval = "
                                   f"{self.sampleInterval:g} s after its start: run longer than sampleInterval "
                                   f"(endTime) or give CreateBallBearing a smaller sampleInterval")
            raise RuntimeError("results: no samples yet; run mbs.SolveDynamic first")
        rows = np.array(self._sample_rows)
        data, k = {"t": np.array(self._sample_t)}, 0
        for name, shape in EK.sample_layout(self.z):
            size = int(np.prod(shape))
            data[name] = rows[:, k:k + size].reshape((len(rows), *shape))
            k += size
        self._signal_data(data)
        if steps is None:  # force evaluations (body mode) or Exudyn steps (fast mode) of the run
            steps = self._clock[4] if self.mode == "fast" else self._evaluations
        msg = cage_load_check(self.bearing, self.scenario, self.lubricant,
                              float(data["cage_load"].max(initial=0.0)), self.scenario.dt)
        if msg:
            warnings.warn(msg, StepSizeWarning, stacklevel=3)
        if self.rigid:  # the land's film where the run took the cage (the reference engine's check)
            msg = land_step_check(self.bearing, self.scenario, self.lubricant,
                                  float(data["glob"][:, L.G_LAND_ECC].max()), self.scenario.dt)
            if msg:
                warnings.warn(msg, StepSizeWarning, stacklevel=3)
        return RunRecord(self.bearing, self.scenario, self.lubricant, data, steps=steps,
                         wall_s=self._wall if wall_s is None else wall_s, engine="exudyn", stable_dt=self.stable.dt)
