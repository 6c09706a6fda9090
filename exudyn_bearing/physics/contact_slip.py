"""Slip over a Hertz contact ellipse and the traction it transmits.

A ball rolling on a race slides at most points of its contact ellipse: the
ball and the race turn about different axes, so their surface speeds agree
only along lines ("pure-rolling points" on the major axis), not everywhere.
Three effects make the slip vary over the ellipse (Jones [1]_, Harris &
Kotzalas [2]_, Johnson [3]_ ch. 8; Gupta [4]_ for the minimum-energy use):

* rolling slip: a uniform sliding speed v0 in the rolling direction;
* spin about the contact normal at the relative spin speed w_n, which adds
  -w_n y in the rolling direction and +w_n x across it;
* curvature-induced (Heathcote) slip: across the rolling direction the
  contact surface is curved (radius R_d between the ball's and the
  groove's), so points at a distance y from the centre lie at other radii
  from the ball's and the race's axes: a term c2 y^2 in the rolling direction.

Contact frame and slip field
----------------------------
e_x: rolling direction (along the minor semi-axis b), e_y: along the major
semi-axis a, e_z = e_x x e_y. The slip of body 1 (the ball) relative to body
2 (the race) at (x, y) on the ellipse x^2/b^2 + y^2/a^2 <= 1 is::

    v_x = v0 - w_n y + c2 y^2          (rolling direction)
    v_y = v_t + w_n x                  (across)

with w_n the spin of body 1 relative to body 2 about e_z. The Hertz pressure
is p = p0 sqrt(1 - x^2/b^2 - y^2/a^2), p0 = 3 Q / (2 pi a b), and the shear
stress on body 1 is tau = -mu(|v|, u, p, h) p v/|v| (:mod:`.traction`).

Strip integration
-----------------
The ellipse is cut into ``n_strips`` strips of equal width along the major
axis; each strip carries the exact share of the load,
dQ_j = Q (3/4) int_strip (1 - v^2) dv (v = y/a), so the strip loads add up
to Q for any strip count. Across a strip (along x) the pressure profile
sqrt(1 - u^2) is integrated by ``n_across`` Gauss-Chebyshev points of the
second kind (u_k = cos(k pi/(m+1)), weights pi/(m+1) sin^2(k pi/(m+1))),
exact for the load. ``n_across = 1`` is the classical strip theory (slip
taken on the major axis, the spin's cross-slip w_n x dropped); more points
resolve the cross-slip. Totals on body 1:

    F_x, F_y = sum tau dA,   M_z = sum (x tau_y - y tau_x) dA   (about e_z at the centre)
    M_y = sum tau_x z(y) dA,  z(y) = y^2 / (2 R_d)          (about e_y at the centre)
    P  = sum mu p |v| dA  >= 0   frictional dissipation [W]
    QV = sum p |v| dA            load-times-slip integral [N m/s] (Archard-type wear)

M_y is the rolling-resistance moment of the curvature slip: the pressed
surface is curved across the rolling direction (radius R_d), so a shear
stress tau_x at y acts at the depth z(y) = y^2/(2 R_d) below the contact
plane and turns about e_y. The curvature slip c2 y^2 is that depth times the
relative rolling speed omega_roll = 2 R_d c2 about e_y, so the power the
field takes from the relative motion of the two bodies is exactly

    -P = F_x v0 + F_y v_t + M_z w_n + M_y omega_roll

(point by point, tau . v = tau_x (v0 - w_n y + c2 y^2) + tau_y (v_t + w_n x)).
A model that applies F_x, F_y and M_z but not M_y reports a dissipation the
applied forces do not take from the bodies (drive power < dissipation):
every caller applies the full resultant (F_x, F_y, M_y, M_z) to both bodies.

Closed forms the integration reproduces (asserted in tests/test_contact_slip.py):
pure rolling gives no force; uniform sliding with constant mu gives
F_x = -mu Q, P = mu Q |v0|; pure spin with constant mu gives the spin
moment |M_z| -> (3/8) mu Q a for ``n_across = 1`` and (3/8) mu Q a E(e) as
``n_across`` grows (:func:`spin_moment_coulomb`, Jones [1]_); with v0 and c2
placing the pure-rolling points at y = +-0.347 a the Coulomb force vanishes
(Heathcote's points, Johnson [3]_).

Compiled interface (for the dynamics engines)
---------------------------------------------
``_contact_traction(a, b, load, v0, w_n, c2, r_d, v_t, u_roll, h_central,
h_min, code, params, n_strips, n_across)`` -> ``(F_x, F_y, M_z, P, QV, M_y)``: scalar
float arguments, ``code`` and the strip counts int, ``params`` a float64
array (:attr:`exudyn_bearing.data.TractionModel.vector`); it allocates
nothing and evaluates the traction law (``physics.traction._traction_srr``,
inlined) once per point (``n_strips * n_across`` points). ``a`` is the semi-axis along e_y,
``b`` along e_x (the rolling direction); a zero load or semi-axis returns
zeros. ``u_roll`` is the rolling (entrainment) speed [m/s] that defines the
slide-to-roll ratio; the films [m] are used by the ``ehl`` (central) and
``lambda`` (minimum) models only. The caller builds v0, w_n, c2 from its
body velocities. For a ball (angular velocity w_b) on a race (w_r) with
the unit normal n from the groove's curvature centre to the ball centre,
contact centre X = c + R_b n, rolling direction e_x and e_y = e_x x n (so
e_z = -n): v0 = e_x . (v_ball(X) - v_race(X)) (surface velocities at X),
w_n = -(w_b - w_r) . n, c2 = ((w_b - w_r) . e_y) / (2 R_d) with R_d from
:func:`deformed_contact_radius` (``r_d``; 0 for a flat contact, M_y = 0), v_t = e_y . (v_ball(X) - v_race(X)), and
u_roll = |e_x . (v_ball(X) + v_race(X))| / 2 with velocities relative to the
contact point; :mod:`exudyn_bearing.solvers.quasistatic.kinematics` does
this for the orbiting frame of a bearing ball. F_x, F_y act on the ball
along e_x, e_y (the race gets the opposite); M_z acts on the ball about
e_z = -n and M_y about e_y (the race gets the opposite moments). Measured cost per call (``python validation/performance/bench_quasistatic.py``,
compiled loop, shared 2-core machine): about 130 ns for Coulomb friction and
210 ns for the traction curve at 8 strips x 1 point, 240 / 390 ns at 16
strips, 650 ns for the EHL model at 8 strips.

References
----------
.. [1] A. B. Jones, "Ball motion and sliding friction in ball bearings,"
   J. Basic Eng. 81 (1959) 1-12. doi:10.1115/1.4008346
.. [2] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   CRC Press, 2006, Advanced Concepts ch. 'Friction in rolling element-
   raceway contacts'.
.. [3] K. L. Johnson, Contact Mechanics, Cambridge University Press, 1985,
   ch. 8 (rolling of elastic bodies: Heathcote slip).
.. [4] P. K. Gupta, "Minimum energy hypothesis in quasi-static equilibrium
   solutions for angular contact ball bearings," Tribol. Trans. (2020).
"""
from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from .._jit import kernel
from ..data import get_traction_model
from ..data.errors import InputError, check_integer
from .hertz import _ellipke
from .traction import _inverse_rolling_speed, _traction_srr

#: Strips along the major axis and points across each strip: the default of
#: every solver (quasi-static, both dynamic engines), chosen by
#: ``python validation/studies/traction_convergence.py`` (dissipation within 1 % of a
#: 64 x 8 integration and the spin-axis angle within 0.1 deg on its cases).
DEFAULT_N_STRIPS = 16
DEFAULT_N_ACROSS = 4
#: Largest strips and points across accepted by every entry point (solve_quasistatic, Scenario, the
#: CLI's --strips and --points-across): 16 and 4 times the default, beyond the 64 x 8 reference of the
#: convergence study; a dynamic run pays every point at every step.
MAX_N_STRIPS = 256
MAX_N_ACROSS = 16

__all__ = ["DEFAULT_N_STRIPS", "DEFAULT_N_ACROSS", "MAX_N_STRIPS", "MAX_N_ACROSS", "check_resolution",
           "contact_traction", "ContactTraction", "deformed_contact_radius", "spin_moment_coulomb",
           "slip_profile", "pure_rolling_points"]


def check_resolution(n_strips, n_across, names=("n_strips", "n_across")) -> tuple[int, int]:
    """``(n_strips, n_across)`` as ints in [1, MAX_N_STRIPS] and [1, MAX_N_ACROSS], else InputError naming
    ``names`` (the caller's spelling: ``"--strips"`` on the command line)."""
    out = []
    for name, v, hi in zip(names, (n_strips, n_across), (MAX_N_STRIPS, MAX_N_ACROSS)):
        v = check_integer(name, v)
        if not 1 <= v <= hi:
            raise InputError(f"{name}: must be an integer in [1, {hi}], got {v}")
        out.append(v)
    return out[0], out[1]


@kernel(no_runtime=True)
def _contact_traction(a, b, load, v0, w_n, c2, r_d, v_t, u_roll, h_central, h_min, code, params, n_strips,
                       n_across):
    """Strip integration of the traction over a Hertz ellipse (module docstring).

    Returns (F_x, F_y, M_z, P, QV, M_y) on body 1: forces [N], moment about e_z [N m],
    dissipation [W], load-times-slip [N m/s], curvature moment about e_y [N m].
    """
    fx = 0.0
    fy = 0.0
    mz = 0.0
    my2 = 0.0
    power = 0.0
    qv = 0.0
    if load <= 0.0 or a <= 0.0 or b <= 0.0 or n_strips < 1:
        return fx, fy, mz, power, qv, 0.0
    m = n_across if n_across > 0 else 1
    p0 = 1.5 * load / (math.pi * a * b)
    theta = math.pi / (m + 1)
    ct = math.cos(theta)
    st = math.sin(theta)
    wscale = 0.75 * load * (2.0 / math.pi) * theta  # Q (3/4) * (2/pi) * pi/(m+1)
    dv = 2.0 / n_strips
    inv_u = _inverse_rolling_speed(u_roll)
    for j in range(n_strips):
        vl = -1.0 + j * dv
        vr = vl + dv
        vm = vl + 0.5 * dv
        wj = dv - (vr * vr * vr - vl * vl * vl) / 3.0  # int (1 - v^2) dv over the strip
        sm = math.sqrt(max(1.0 - vm * vm, 0.0))
        y = a * vm
        y2 = y * y
        vx = v0 - w_n * y + c2 * y2
        ck = 1.0  # cos(0), sin(0): start of the node recurrence
        sk = 0.0
        for _k in range(m):
            if m == 1:  # the single node u = 0 of classical strip theory
                ck = 0.0
                sk = 1.0
            else:
                c_next = ck * ct - sk * st
                sk = sk * ct + ck * st
                ck = c_next  # cos(k theta), sin(k theta), k = 1..m
            x = b * sm * ck
            vy = v_t + w_n * x
            speed = math.sqrt(vx * vx + vy * vy)
            if speed <= 0.0:
                continue
            dq = wscale * wj * sk * sk
            pressure = p0 * sm * sk
            mu = _traction_srr(code, params, speed, speed * inv_u, pressure, h_central, h_min)
            f = mu * dq / speed
            tx = -f * vx
            ty = -f * vy
            fx += tx
            fy += ty
            mz += x * ty - y * tx
            my2 += tx * y2
            power += mu * dq * speed
            qv += dq * speed
    my = my2 / (2.0 * r_d) if r_d > 0.0 else 0.0
    return fx, fy, mz, power, qv, my


class ContactTraction(NamedTuple):
    """Result of :func:`contact_traction` (on body 1, the ball)."""

    force_x: float     #: traction force along the rolling direction [N]
    force_y: float     #: traction force along the major axis [N]
    moment_z: float    #: moment about the contact normal e_z at the centre [N m]
    dissipation: float  #: frictional power [W]
    qv: float          #: load-times-slip integral [N m/s]
    moment_y: float = 0.0  #: curvature (rolling-resistance) moment about e_y at the centre [N m]


def contact_traction(a, b, load, v0, spin, c2=0.0, v_t=0.0, u_roll=1.0, h_central=0.0, h_min=0.0,
                     model="coulomb_0.1", n_strips=DEFAULT_N_STRIPS, n_across=DEFAULT_N_ACROSS,
                     r_d=0.0) -> ContactTraction:
    """Traction force, spin moment, dissipation and QV of one Hertz contact.

    Parameters
    ----------
    a, b : float
        Semi-axes [m]: a along e_y (across rolling), b along e_x (rolling).
    load : float
        Contact load Q [N].
    v0 : float
        Rolling-direction slip at the centre [m/s] (body 1 minus body 2).
    spin : float
        Relative spin w_n about e_z = e_x x e_y [rad/s].
    c2 : float
        Curvature coefficient [1/(m s)] of the slip v0 - w_n y + c2 y^2.
    v_t : float
        Uniform slip across the rolling direction [m/s].
    u_roll : float
        Rolling speed [m/s] (slide-to-roll ratio |v|/u).
    h_central, h_min : float
        Film thicknesses [m] for the ``ehl`` and ``lambda`` models.
    model : TractionModel or str
        Traction model or catalogue name (default Coulomb mu = 0.1).
    n_strips, n_across : int
        Strips along the major axis and points across each strip (default
        :data:`DEFAULT_N_STRIPS` x :data:`DEFAULT_N_ACROSS`, as every solver;
        ``n_across=1`` is classical strip theory).
    r_d : float
        Radius of the pressed surface across the rolling direction [m]
        (:func:`deformed_contact_radius`; c2 = omega_roll / (2 r_d)); sets the
        curvature moment M_y. 0 (default): no curvature moment.

    Returns
    -------
    ContactTraction

    Examples
    --------
    Pure spin, mu = 0.1, Q = 1000 N, a = 2 mm, strip theory: |M_z| -> (3/8) mu Q a = 0.075 N m

    >>> round(abs(contact_traction(2e-3, 0.2e-3, 1000.0, 0.0, 100.0, n_strips=400, n_across=1).moment_z), 4)
    0.075
    """
    m = get_traction_model(model)
    return ContactTraction(*_contact_traction(float(a), float(b), float(load), float(v0), float(spin), float(c2),
                                              float(r_d), float(v_t), float(u_roll), float(h_central),
                                              float(h_min), m.code, m.vector, int(n_strips), int(n_across)))


def spin_moment_coulomb(mu, load, a, b):
    """Spin moment of a Hertz contact under pure spin with constant mu [N m].

    M_s = (3/8) mu Q a E(e), e^2 = 1 - b^2/a^2, E the complete elliptic
    integral of the second kind (Jones [1]_; Harris & Kotzalas [2]_): the
    integral of mu p rho over the ellipse, rho the distance from its centre.

    Notes
    -----
    With x = b s cos(phi), y = a s sin(phi): int p rho dA = p0 a b
    int_0^1 s^2 sqrt(1 - s^2) ds * int_0^{2 pi} sqrt(a^2 sin^2 + b^2 cos^2) dphi
    = p0 a b (pi/16) 4 a E(e) = (3/8) Q a E(e).

    Examples
    --------
    Circular contact (E = pi/2): (3 pi/16) mu Q a

    >>> round(float(spin_moment_coulomb(0.1, 1000.0, 1e-3, 1e-3)), 6)
    0.058905
    """
    mu, load, a, b = (np.asarray(v, float) for v in (mu, load, a, b))
    m = 1.0 - np.square(np.minimum(a, b) / np.maximum(a, b))
    ee = np.vectorize(lambda x: _ellipke(float(x))[1], otypes=[float])(m)
    return 0.375 * mu * load * np.maximum(a, b) * ee


def deformed_contact_radius(r_ball, r_groove):
    """Radius of the pressed contact surface across the rolling direction [m].

    R_d = 2 R_b R_c / (R_b + R_c), between the ball radius and the groove
    radius (Harris & Kotzalas [2]_, sliding in the contact: 2 r D / (2 r + D)
    with r = R_c, D = 2 R_b). It sets the curvature-induced slip.

    Examples
    --------
    6208 groove (f = 0.52): R_d = 1.04 D / 2.04

    >>> round(float(deformed_contact_radius(6.3e-3, 6.552e-3)) * 1e3, 4)
    6.4235
    """
    return 2.0 * np.asarray(r_ball, float) * r_groove / (np.asarray(r_ball, float) + r_groove)


def slip_profile(a, v0, spin, c2, n_points=101):
    """Rolling-direction slip along the major axis, v_x(y) = v0 - w_n y + c2 y^2 [m/s].

    Returns (y [m], v_x [m/s]) at ``n_points`` points from -a to a.
    """
    y = np.linspace(-a, a, n_points)
    return y, v0 - spin * y + c2 * y * y


def pure_rolling_points(a, v0, spin, c2):
    """Points of pure rolling on the major axis [m]: roots of v0 - w_n y + c2 y^2 = 0 in [-a, a].

    Returns an array of 0, 1 or 2 points, sorted.

    Examples
    --------
    Heathcote slip with the points at +-0.347 a (Johnson, Contact Mechanics sec. 8):

    >>> pure_rolling_points(1.0, -0.347 ** 2, 0.0, 1.0).round(3).tolist()
    [-0.347, 0.347]
    """
    if abs(c2) * a * a <= 1e-14 * (abs(spin) * a + abs(v0) + 1e-300):
        roots = [v0 / spin] if spin != 0.0 else []
    else:
        disc = spin * spin - 4.0 * c2 * v0
        if disc < 0.0:
            roots = []
        else:
            sq = math.sqrt(disc)
            roots = [(spin - sq) / (2.0 * c2), (spin + sq) / (2.0 * c2)]
    return np.array(sorted(r for r in roots if -a <= r <= a))
