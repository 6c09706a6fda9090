"""The ball / pocket oil film in the quasi-static solver with the rigid cage (``solve_quasistatic(...,
cage="rigid", pocket_film=True)``; docs/theory/quasistatic.md#the-pocket-film).

The same physics as the dynamic engines' kernel (:mod:`exudyn_bearing.model.contact`, ``_pocket_film_force``
and ``_pocket_film_shear``), from the same functions of :mod:`exudyn_bearing.physics.pocket_film`, for the
steady state of a ball in its pocket: the ball's centre moves with the pocket (no squeeze: the approach speed
is zero), the ball turns at (w_r, w_z) relative to the cage (the orbit frame turns with the cage), the wall it
presses on faces it along the orbit, n = s e_psi (s = -sign Q_p: the pocket pushes the ball along -n).

* Held on a wall (the pocket force Q_p): the hydrodynamic film at the near wall (gap h) less the one at the
  far wall (gap 2 c_p - h) carries |Q_p| (:func:`~exudyn_bearing.physics.pocket_film.hydrodynamic_film_load`,
  the entraining speed u = R_b |w| / 2, half the ball's sliding on the wall, as the kernel's); a force beyond
  what the film carries at the composite roughness (the kernel's floor) presses the ball onto the wall, and
  only that contact force has the Coulomb friction mu_c (as in the kernel).
* Floating (the pocket play's free share of the time, :func:`~.solve.pocket_contact_fraction`): the ball
  centred in its pocket, both gaps c_p, no net pressure.

In both the two walls shear the ball (:func:`~exudyn_bearing.physics.pocket_film.sphere_wall_shear` at the
near wall, normal n, and at the far wall, normal -n): a moment on the ball, its reaction on the cage (about the
bearing's axis: -M_z), a radial force, and the dissipation -M.w.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

from scipy import optimize as _opt

from ...physics import pocket_film as _pf

__all__ = ["PocketFilm"]


@dataclass(frozen=True)
class PocketFilm:
    """The pocket film of one bearing: ``viscosity`` eta [Pa s], ``ball_radius`` R_b [m], ``clearance`` c_p
    [m] (per side), ``r_x`` [m] and ``h_hat`` [-] of the hydrodynamic film
    (:func:`~exudyn_bearing.physics.pocket_film.pocket_film_radii`,
    :func:`~exudyn_bearing.physics.pocket_film.isoviscous_rigid_film_constant`), ``floor`` [m] the thinnest
    film (the composite roughness). Built by :meth:`of`, as ``model.parameters`` builds the kernel's."""

    viscosity: float
    ball_radius: float
    clearance: float
    r_x: float
    h_hat: float
    floor: float

    @classmethod
    def of(cls, rigid_cage, lubricant, ball_radius):
        """The film of ``rigid_cage`` (a RigidCage) with ``lubricant`` and the balls' radius [m]."""
        r_x, alpha_r = _pf.pocket_film_radii(ball_radius, rigid_cage.pocket_clearance,
                                             rigid_cage.pocket_shape == "cylindrical")
        return cls(float(lubricant.viscosity), float(ball_radius), float(rigid_cage.pocket_clearance), float(r_x),
                   float(_pf.isoviscous_rigid_film_constant(alpha_r)), float(lubricant.composite_roughness))

    def _net_load(self, near, w):
        """The hydrodynamic film's net force [N] off the near wall (gap ``near``) for the ball's rotation
        ``w`` [rad/s] relative to the cage: the near film less the far one (gap 2 c_p - near)."""
        u = 0.5 * self.ball_radius * w
        far = 2.0 * self.clearance - near
        return float(_pf.hydrodynamic_film_load(self.viscosity, u, self.r_x, self.h_hat, near)
                     - _pf.hydrodynamic_film_load(self.viscosity, u, self.r_x, self.h_hat, far))

    def held_gap(self, force, w):
        """(near gap [m], the film's net force [N], the contact force [N]) of a ball pressed by |``force``|
        [N] on its pocket wall, turning at ``w`` [rad/s] relative to the cage: the gap where the film's net
        force carries it, else the floor (the film's force there, and the rest the contact's)."""
        q = abs(float(force))
        if q == 0.0:
            return self.clearance, 0.0, 0.0
        floor = min(self.floor, self.clearance)
        top = self._net_load(floor, w)
        if top <= q:
            return floor, top, q - top
        near = _opt.brentq(lambda h: self._net_load(h, w) - q, floor, self.clearance,
                           xtol=1e-12 * self.clearance, rtol=1e-12)
        return near, q, 0.0

    def shear(self, near, side, w_r, w_z):
        """(f_r [N], f_z [N], m_r [N m], m_z [N m], power [W]): the shear of the two walls on a ball turning at
        (w_r, w_z) [rad/s] relative to the cage (orbit frame e_r, e_psi, e_z), the near wall at the gap ``near``
        along ``side`` e_psi, the far one at 2 c_p - near; the force and moment on the ball, the power it
        dissipates."""
        far = 2.0 * self.clearance - near
        out = [0.0] * 6
        for h, s in ((near, side), (far, -side)):
            res = _pf.sphere_wall_shear(self.viscosity, self.ball_radius, max(h, self.floor), 0.0, s, 0.0,
                                        0.0, 0.0, 0.0, w_r, 0.0, w_z)
            out = [a + float(b) for a, b in zip(out, res)]
        fx, _fy, fz, mx, _my, mz = out
        return fx, fz, mx, mz, -(mx * w_r + mz * w_z)

    def held(self, force, w_r, w_z):
        """The film on a ball held by the pocket force ``force`` [N] (along e_psi, positive forward) turning
        at (w_r, w_z) relative to the cage: dict near gap [m], film force and contact force [N], the shear's
        f_r, f_z [N], m_r, m_z [N m] on the ball and its power [W]."""
        w = math.hypot(w_r, w_z)
        near, film, contact = self.held_gap(force, w)
        side = -1.0 if force > 0.0 else 1.0
        f_r, f_z, m_r, m_z, power = self.shear(near, side, w_r, w_z)
        return {"gap": near, "film_force": film, "contact_force": contact, "f_r": f_r, "f_z": f_z,
                "m_r": m_r, "m_z": m_z, "power": power}

    def centred(self, w_r, w_z):
        """:meth:`held` of a ball floating centred in its pocket (both gaps c_p, no force)."""
        return self.held(0.0, w_r, w_z)
