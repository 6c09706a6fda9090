"""Rolling kinematics of a ball bearing (pure rolling, race control).

docs/theory/reference_cases.md and Harris & Kotzalas [1]_ ch. 8, for any contact angle
alpha and either ring rotating. With gamma = R_b cos(alpha) / r_p (that is
D cos(alpha)/d_m):

* cage:        omega_c = omega_i (1 - gamma)/2 + omega_o (1 + gamma)/2
* ball spin relative to the cage, about the rolling axis:
  omega_R = -(r_p / (2 R_b)) (1 - gamma^2) (omega_i - omega_o)
  (negative: the ball turns against the inner ring)
* absolute ball angular speed, rolling axis perpendicular to the contact
  line: |omega_R a + omega_c e_z|, a = (-sin alpha, cos alpha) in (r, z);
  for alpha = 0 and a fixed outer ring it equals omega_i R_i / (2 R_b)
  (docs/theory/reference_cases.md: 952.38 rad/s at 500 rad/s for the 6208).
* defect frequencies [Hz], f = omega / (2 pi):
  FTF = |f_c|, BPFO = Z |f_c - f_o|, BPFI = Z |f_i - f_c|,
  BSF = (r_p / (2 R_b)) (1 - gamma^2) |f_i - f_o| (once per ball revolution).

All functions are plain arithmetic on scalars or arrays.

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed.,
   CRC Press, 2006, ch. 8 (eq. 8.13-8.26).
"""
from __future__ import annotations

import numpy as np

from .._jit import kernel

__all__ = [
    "cage_speed",
    "ball_spin_relative",
    "ball_spin_absolute",
    "rolling_speeds",
    "defect_frequencies",
    "centrifugal_force",
]


def _gamma(ball_radius, pitch_radius, contact_angle):
    return ball_radius * np.cos(contact_angle) / pitch_radius


def cage_speed(omega_inner, omega_outer, ball_radius, pitch_radius, contact_angle=0.0):
    """Cage angular speed omega_c [rad/s] under pure rolling.

    omega_c = omega_i (1 - gamma)/2 + omega_o (1 + gamma)/2 [1]_.

    Examples
    --------
    6208 at 500 rad/s (docs/theory/reference_cases.md: 198.0 rad/s):

    >>> round(float(cage_speed(500.0, 0.0, 6.3e-3, 30.3e-3)), 1)
    198.0
    """
    g = _gamma(ball_radius, pitch_radius, contact_angle)
    return 0.5 * omega_inner * (1.0 - g) + 0.5 * omega_outer * (1.0 + g)


_cage_speed = kernel(cage_speed)


def ball_spin_relative(omega_inner, omega_outer, ball_radius, pitch_radius, contact_angle=0.0):
    """Ball spin about its rolling axis relative to the cage [rad/s], signed.

    omega_R = -(r_p/(2 R_b)) (1 - gamma^2) (omega_i - omega_o) [1]_.
    """
    g = _gamma(ball_radius, pitch_radius, contact_angle)
    return -(pitch_radius / (2.0 * ball_radius)) * (1.0 - g * g) * (omega_inner - omega_outer)


def ball_spin_absolute(omega_inner, omega_outer, ball_radius, pitch_radius, contact_angle=0.0):
    """Magnitude of the ball's absolute angular velocity [rad/s].

    |omega_R a + omega_c e_z| with the rolling axis a perpendicular to the
    contact line; for alpha = 0, outer ring fixed: omega_i R_i / (2 R_b).

    Examples
    --------
    >>> round(float(ball_spin_absolute(500.0, 0.0, 6.3e-3, 30.3e-3)), 2)
    952.38
    """
    wr = ball_spin_relative(omega_inner, omega_outer, ball_radius, pitch_radius, contact_angle)
    wc = cage_speed(omega_inner, omega_outer, ball_radius, pitch_radius, contact_angle)
    return np.sqrt(wr * wr + 2.0 * wr * wc * np.cos(contact_angle) + wc * wc)


def rolling_speeds(omega_inner, omega_outer, ball_radius, pitch_radius, contact_angle=0.0):
    """Rolling (entrainment) speeds u_r at the inner and outer contacts [m/s].

    Under pure rolling both surfaces move at the same speed relative to the
    contact, so u_r equals the race surface speed relative to the cage:
    inner |omega_i - omega_c| (r_p - R_b cos alpha),
    outer |omega_o - omega_c| (r_p + R_b cos alpha) (the two are equal).

    Returns
    -------
    u_inner, u_outer : float or ndarray [m/s]
    """
    wc = cage_speed(omega_inner, omega_outer, ball_radius, pitch_radius, contact_angle)
    rc = ball_radius * np.cos(contact_angle)
    return (np.abs(omega_inner - wc) * (pitch_radius - rc),
            np.abs(omega_outer - wc) * (pitch_radius + rc))


def defect_frequencies(omega_inner, omega_outer, n_balls, ball_radius, pitch_radius,
                       contact_angle=0.0):
    """Kinematic defect frequencies FTF, BPFO, BPFI, BSF [Hz].

    Parameters
    ----------
    omega_inner, omega_outer : float
        Ring angular speeds [rad/s] (either may rotate).
    n_balls : int
        Z.
    ball_radius, pitch_radius : float
        R_b, r_p [m].
    contact_angle : float
        alpha [rad].

    Returns
    -------
    dict with keys ``ftf``, ``bpfo``, ``bpfi``, ``bsf`` [Hz] [1]_.

    Examples
    --------
    >>> f = defect_frequencies(500.0, 0.0, 9, 6.3e-3, 30.3e-3)
    >>> round(f["bpfo"], 2), round(f["bpfi"], 2)
    (283.64, 432.55)
    """
    two_pi = 2.0 * np.pi
    fi, fo = omega_inner / two_pi, omega_outer / two_pi
    fc = cage_speed(fi, fo, ball_radius, pitch_radius, contact_angle)
    bsf = np.abs(ball_spin_relative(fi, fo, ball_radius, pitch_radius, contact_angle))
    return {
        "ftf": float(np.abs(fc)),
        "bpfo": float(n_balls * np.abs(fc - fo)),
        "bpfi": float(n_balls * np.abs(fi - fc)),
        "bsf": float(bsf),
    }


def centrifugal_force(ball_mass, pitch_radius, cage_speed):
    """Centrifugal force of a ball orbiting with the cage, F_c = m r_p omega_c^2 [N].

    It presses the ball on the outer race, so at speed the outer contact
    carries about F_c more than the inner (Harris & Kotzalas [1]_, high-speed
    operation; docs/theory/reference_cases.md, the 1700 rad/s case).

    Examples
    --------
    >>> round(float(centrifugal_force(0.0105, 30.3e-3, 200.0)), 2)
    12.73
    """
    return ball_mass * pitch_radius * np.square(cage_speed)
