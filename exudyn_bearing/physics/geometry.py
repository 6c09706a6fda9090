"""Ball centre in a torus groove: overlap, normal, contact angle, radii.

docs/theory/geometry.md, docs/theory/hertz.md. A raceway is a torus about the ring's z axis whose
tube (radius R_c) is the groove; its tube-centre circle has radius ``rho``
and lies at axial position ``z_g``. With ``p`` the point of that circle
nearest to the ball centre ``c``, the overlap is
delta = |c - p| - (R_c - R_b) and the contact normal n points from p to c.
The contact point lies at p + R_c n; the race pushes the ball along -n.
(Exudyn's ObjectContactSphereTorus uses the same sphere-in-tube geometry.)

The contact angle alpha is the angle of the contact line to the radial
plane, signed so that both contacts of a ball loaded along the designed
contact line have the same positive alpha:
alpha = atan2(s n_z, s n_r) with s = +1 on the outer race, -1 on the inner.

Principal radii (docs/theory/hertz.md, Harris & Kotzalas ch. 2): raceway in the
rolling direction R_2x = r_c / cos(alpha), r_c the distance of the contact
point from the axis (convex on the inner race, concave on the outer), across
the rolling direction the groove R_c (concave); effective radii
R_x = R_b R_2x / (R_2x +- R_b), R_y = R_b R_c / (R_c - R_b).
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel

__all__ = ["raceway_radii", "groove_contact", "GROOVE_CONTACT_FIELDS"]


def _radii_from_cos(r_ball, r_groove, r_contact, cos_alpha, inner):
    # R_b R_2x / (R_2x +- R_b) with R_2x = r_c / cos(alpha), one division
    if inner:
        rx = r_ball * r_contact / (r_contact + r_ball * cos_alpha)
    else:
        rx = r_ball * r_contact / (r_contact - r_ball * cos_alpha)
    ry = r_ball * r_groove / (r_groove - r_ball) + 0.0 * rx
    return rx, ry


#: Kernel of :func:`raceway_radii` taking cos(alpha) instead of alpha.
_raceway_radii_cos = kernel(_radii_from_cos)


def raceway_radii(r_ball, r_groove, r_contact, contact_angle, inner):
    """Effective radii R_x, R_y [m] of a ball on a raceway (docs/theory/hertz.md).

    R_2x = r_c / cos(alpha); inner (convex): R_x = R_b R_2x/(R_2x + R_b);
    outer (concave): R_x = R_b R_2x/(R_2x - R_b); R_y = R_b R_c/(R_c - R_b).

    Parameters
    ----------
    r_ball : float
        R_b [m].
    r_groove : float
        Groove radius R_c [m].
    r_contact : float or ndarray
        Distance of the contact point from the bearing axis [m].
    contact_angle : float or ndarray
        alpha [rad].
    inner : bool
        True for the inner (convex) race, False for the outer (concave).

    Examples
    --------
    6208 inner contact at alpha = 0 (docs/theory/hertz.md: R_y/R_x = 32.8):

    >>> rx, ry = raceway_radii(6.3e-3, 6.552e-3, 24e-3, 0.0, True)
    >>> round(float(ry / rx), 1)
    32.8
    """
    return _radii_from_cos(r_ball, r_groove, r_contact, np.cos(contact_angle), inner)


#: Names of the values returned by :func:`groove_contact`, in order.
GROOVE_CONTACT_FIELDS = ("overlap", "nx", "ny", "nz", "contact_angle", "r_contact", "r_x", "r_y")


@kernel
def _groove_geometry(cx, cy, cz, rho, z_g, r_groove, r_ball, inner):
    """Ball (centre c in the ring frame) in a torus groove: the cheap part.

    Returns (delta, nx, ny, nz, cos_alpha, sin_alpha, r_contact); see the
    module docstring. A ball centre on the bearing axis takes the x direction
    as its radial direction.
    """
    r = math.sqrt(cx * cx + cy * cy)
    if r > 0.0:
        inv = 1.0 / r
        ex = cx * inv
        ey = cy * inv
    else:
        ex = 1.0
        ey = 0.0
    dr = r - rho
    dz = cz - z_g
    dist = math.sqrt(dr * dr + dz * dz)
    if dist > 0.0:
        inv = 1.0 / dist
        nr = dr * inv
        nz = dz * inv
    else:
        nr = -1.0 if inner else 1.0
        nz = 0.0
    delta = dist - (r_groove - r_ball)
    s = -1.0 if inner else 1.0
    return delta, nr * ex, nr * ey, nz, s * nr, s * nz, abs(rho + r_groove * nr)


@kernel
def _groove_contact(cx, cy, cz, rho, z_g, r_groove, r_ball, inner):
    """:func:`_groove_geometry` plus the contact angle and the radii:
    (delta, nx, ny, nz, alpha, r_contact, R_x, R_y)."""
    delta, nx, ny, nz, ca, sa, r_contact = _groove_geometry(cx, cy, cz, rho, z_g, r_groove, r_ball, inner)
    rx, ry = _raceway_radii_cos(r_ball, r_groove, r_contact, ca, inner)
    return delta, nx, ny, nz, math.atan2(sa, ca), r_contact, rx, ry


def groove_contact(center, rho, z_g, r_groove, r_ball, inner):
    """Contact of balls (centres ``center``, shape (..., 3), ring frame) with a groove.

    Parameters
    ----------
    center : array_like, shape (..., 3)
        Ball centres in the ring frame (ring axis = z) [m].
    rho, z_g : float
        Radius and axial position of the tube-centre circle [m]
        (``BallBearing.inner_groove_center`` / ``outer_groove_center``).
    r_groove, r_ball : float
        R_c and R_b [m].
    inner : bool
        Inner (convex) or outer (concave) race.

    Returns
    -------
    dict of ndarray
        overlap [m] (> 0: contact), normal (..., 3) from the tube centre to
        the ball centre, contact_angle [rad], r_contact [m], r_x, r_y [m].

    Examples
    --------
    6208 ball at the pitch radius, rings concentric, P_d = 0: zero overlap.

    >>> g = groove_contact([0.0303, 0, 0], 0.030552, 0.0, 6.552e-3, 6.3e-3, True)
    >>> abs(float(g["overlap"])) < 1e-15, round(float(g["r_contact"]), 6)
    (True, 0.024)
    """
    c = np.asarray(center, float)
    flat = c.reshape(-1, 3)
    out = np.empty((flat.shape[0], 8))
    for j in range(flat.shape[0]):
        out[j] = _groove_contact(flat[j, 0], flat[j, 1], flat[j, 2], rho, z_g, r_groove, r_ball, inner)
    shape = c.shape[:-1]
    return {
        "overlap": out[:, 0].reshape(shape),
        "normal": out[:, 1:4].reshape(shape + (3,)),
        "contact_angle": out[:, 4].reshape(shape),
        "r_contact": out[:, 5].reshape(shape),
        "r_x": out[:, 6].reshape(shape),
        "r_y": out[:, 7].reshape(shape),
    }
