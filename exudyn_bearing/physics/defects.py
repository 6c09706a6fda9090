"""How far a ball drops into a localized defect (spall) of a raceway or of a ball.

A spall is a pit in the rolling surface, ``2 h_L`` long along the rolling
direction, ``2 h_W`` wide across it and H deep, with sharp edges or edges
rounded with radius r_e. When the centre of the contact lies over the pit,
the surfaces approach each other by the **drop** e: the ball sinks into the
pit until it rests on its rim, or reaches its floor. The contact model then
uses the overlap delta - e in place of delta (Sawalhi & Randall [1]_: the
defect enters the dynamics as a loss of contact deflection while the ball
passes it; the ball follows the entry edge down (de-stressing) and is pushed
back up by the exit edge (re-stressing, the impact)).

A ball cannot follow a short or narrow pit to its floor: its curvature holds
it on the rim (Moazen-Ahmadi, Petersen & Howard [2]_ on the finite size of
the rolling element). Near the contact the undeformed gap between the two
surfaces is, to second order, x^2/(2 R_x) + y^2/(2 R_y) with the effective
radii of the contact along (R_x) and across (R_y) the rolling direction
(Harris & Kotzalas [4]_, the same radii as in the Hertz contact), so the
contact behaves as an equivalent body of radii R_x, R_y on the plane of the
rim. An edge at distance d from the contact centre lets the equivalent body
sink at most

    g(d, R) = R - sqrt(R^2 - d^2) = d^2 / (R + sqrt(R^2 - d^2))   (d < R; no limit for d >= R)

the circular path of its centre around the edge, and the drop is

    e(s, w) = min(H, g(h_L - s, R_x'), g(h_L + s, R_x'), g(h_W - w, R_y'), g(h_W + w, R_y'))

for |s| < h_L and |w| < h_W (0 outside), s and w the position of the
contact centre relative to the spall centre along and across the rolling
direction. A rounded edge of radius r_e is a cylinder about which the centre
of the equivalent body turns at R + r_e: R_x' = R_x + r_e, R_y' = R_y + r_e
(Liu & Shao [3]_: rounded edges make the entry and exit gentler); a sharp
edge has r_e = 0.

This makes the size of the pit count against the contact ellipse: for a
Hertz contact the semi-axis across the rolling direction is about
sqrt(2 R_y delta) (exactly so for a circular contact, a^2 = R delta), so a
pit of half-width h_W lets the ball lose about (h_W / a)^2 / 2 of its
deflection; a pit narrower than the contact ellipse (the EDM pits of test
rigs are often so) costs only a fraction of the load, one wider than it
unloads the ball completely if it is also long enough (h_L against the
semi-axis along the rolling direction). The drop is geometric: the
surrounding material's extra compliance near the pit, and the tilt of the
contact force on an edge, are not modelled (docs/theory/defects.md).

References
----------
.. [1] N. Sawalhi and R. B. Randall, "Simulating gear and bearing
   interactions in the presence of faults: Part I. The combined gear bearing
   dynamic model and the simulation of localised bearing faults," Mech.
   Syst. Signal Process., vol. 22, no. 8, pp. 1924-1951, 2008,
   doi:10.1016/j.ymssp.2007.12.001.
.. [2] A. Moazen-Ahmadi, D. Petersen and C. Howard, "A nonlinear dynamic
   vibration model of defective bearings - The importance of modelling the
   finite size of rolling elements," Mech. Syst. Signal Process., vol. 52-53,
   pp. 309-326, 2015, doi:10.1016/j.ymssp.2014.06.006.
.. [3] J. Liu and Y. Shao, "A new dynamic model for vibration analysis of a
   ball bearing due to a localized surface defect considering edge
   topographies," Nonlinear Dyn., vol. 79, pp. 1329-1351, 2015,
   doi:10.1007/s11071-014-1745-y.
.. [4] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   CRC Press, 2006, ch. 2 (curvature of the contacting bodies) and ch. 6
   (Hertz contact).
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel

__all__ = ["edge_drop", "spall_drop", "max_spall_drop"]


def _edge_drop(d, radius):
    """g(d, R): sag of a circle of radius R over the half-chord d [m] (inf for d >= R)."""
    if d >= radius:
        return math.inf
    return d * d / (radius + math.sqrt(radius * radius - d * d))


_edge_drop_k = kernel(_edge_drop)


def _spall_drop(s, w, half_length, half_width, depth, edge_radius, r_x, r_y):
    if s >= half_length or s <= -half_length or w >= half_width or w <= -half_width:
        return 0.0
    rx = r_x + edge_radius
    ry = r_y + edge_radius
    e = depth
    g = _edge_drop_k(half_length - s, rx)
    if g < e:
        e = g
    g = _edge_drop_k(half_length + s, rx)
    if g < e:
        e = g
    g = _edge_drop_k(half_width - w, ry)
    if g < e:
        e = g
    g = _edge_drop_k(half_width + w, ry)
    if g < e:
        e = g
    return e


#: Scalar kernel of :func:`spall_drop` for compiled callers (the contact kernel).
_spall_drop_k = kernel(_spall_drop)


def edge_drop(d, radius):
    """Sag g(d, R) = R - sqrt(R^2 - d^2) [m] of the equivalent body of radius R
    over an edge at distance d from the contact centre ([2]_, [3]_): how far
    it can sink before it touches the edge; ``inf`` for d >= R (no limit).

    Parameters
    ----------
    d : float or ndarray
        Distance of the edge from the contact centre [m], >= 0.
    radius : float or ndarray
        Effective radius R [m] (R_x or R_y of the contact, plus the edge radius).

    Examples
    --------
    A ball of 3.97 mm radius over a 1 mm gap (d = 0.5 mm): 31.6 um.

    >>> round(float(edge_drop(0.5e-3, 3.97e-3)) * 1e6, 1)
    31.6
    """
    return np.vectorize(_edge_drop, otypes=[float])(d, radius)


def spall_drop(s, w, half_length, half_width, depth, edge_radius, r_x, r_y):
    """Drop e [m] of a contact into a spall (module docstring, [1]_-[3]_).

    Parameters
    ----------
    s, w : float or ndarray
        Position of the contact centre relative to the spall centre along and
        across the rolling direction [m].
    half_length, half_width : float
        Half the spall's length along and width across the rolling direction [m].
    depth : float
        Spall depth H [m].
    edge_radius : float
        Edge radius r_e [m] (0: sharp edges).
    r_x, r_y : float or ndarray
        Effective radii of the contact along and across the rolling direction
        [m] (:func:`exudyn_bearing.physics.geometry.raceway_radii`).

    Returns
    -------
    float or ndarray
        Drop e >= 0 [m]: min(H, the four edge limits) over the pit, 0 outside.

    Examples
    --------
    A 2 mm long, 3 mm wide, 0.1 mm deep spall under a contact of R_x = 4.8 mm,
    R_y = 103 mm (6205 outer race), at its centre: along the rolling
    direction the ball could reach the floor (g(1 mm, 4.8 mm) = 105 um > H),
    but across it the flat groove curvature holds it on the rim at
    g(1.5 mm, 103 mm) = 10.9 um.

    >>> round(float(spall_drop(0.0, 0.0, 1e-3, 1.5e-3, 0.1e-3, 0.0, 4.8e-3, 103e-3)) * 1e6, 2)
    10.92
    """
    return np.vectorize(_spall_drop, otypes=[float])(s, w, half_length, half_width, depth, edge_radius, r_x, r_y)


def max_spall_drop(length, width, depth, edge_radius, r_x, r_y):
    """Largest drop [m] a contact can reach in a spall: the drop at its centre,
    min(H, g(L/2, R_x + r_e), g(W/2, R_y + r_e)) (module docstring).

    Examples
    --------
    The 0.021 in (0.533 mm) EDM pit of the CWRU 6205 rig, 0.279 mm deep, under
    the outer-race contact (R_x = 4.8 mm, R_y = 103 mm): about 0.34 um, a few
    per cent of the contact deflection.

    >>> round(float(max_spall_drop(0.533e-3, 0.533e-3, 0.279e-3, 0.0, 4.8e-3, 103e-3)) * 1e6, 3)
    0.345
    """
    return spall_drop(0.0, 0.0, 0.5 * np.asarray(length, float), 0.5 * np.asarray(width, float), depth, edge_radius,
                      r_x, r_y)
