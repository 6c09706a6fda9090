"""The oil film between a ball and its cage pocket (docs/theory/cage.md#pocket-oil-film).

A ball inside its pocket's clearance is separated from the pocket wall by oil. Two forces of that film push
the ball away from the wall, both rigid-surface, constant-viscosity (isoviscous-rigid) lubrication, since the
pocket's film is thick against the surfaces' elastic deformation at these loads:

* the **hydrodynamic** force of the oil the surfaces drag into the converging gap at the entraining speed u
  (the mean of the two surfaces' speeds relative to the contact). Brewe, Hamrock & Taylor [1]_ fitted the
  minimum film of a rigid ellipsoid on a plane in the isoviscous-rigid regime as

      H_hat = (h / R_x) (W / U)^2 = 128 alpha_r lambda_b^2 [0.131 atan(alpha_r / 2) + 1.683]^2,
      lambda_b = (1 + 2 / (3 alpha_r))^-1,

  with U = eta u / (E' R_x), W = w / (E' R_x^2) and alpha_r = R_y / R_x the ratio of the radii across and
  along the entraining direction (Hamrock, Schmid & Jacobson [2]_, the isoviscous-rigid regime of the
  film-thickness map); solved for the load, w = eta |u| R_x sqrt(H_hat R_x / h), independent of E' as a rigid
  film must be;
* the **squeeze** force of the oil pressed out of the gap when the ball approaches the wall at v = -dh/dt:
  for a sphere of radius R approaching a plane, F = 6 pi eta R^2 v / h, the lubrication limit of Brenner's
  exact solution [3]_ (and of Reynolds' equation for the gap h + r^2 / (2R)). A pocket's wall conforms to
  the ball (a cylindrical pocket in one direction, a spherical one in both), which raises the force; the
  sphere-on-plane value is therefore a lower bound for the pocket, and the kernel uses it. When the ball
  moves away from the wall the film cavitates and carries no tension (half-Sommerfeld): no squeeze force.

Both diverge as h -> 0; the dynamic engines evaluate them at a film no thinner than the surfaces' composite
roughness, where the pocket's Hertz contact takes over (:mod:`exudyn_bearing.model.contact`).

The film's **shear**: the ball's surface slides past the wall (its rotation relative to the cage, and its
centre's motion along the wall), and the oil in the gap resists it. Goldman, Cox & Brenner [4]_ give the
force and moment on a sphere of radius R at the gap h from a plane for its translation U along the plane and
its rotation Omega about an axis in the plane, as h / R -> 0 (the leading terms of the lubrication
expansion, L = ln(R / h)):

    F = -6 pi eta R (8/15 L + 0.9588) U - 6 pi eta R^2 (2/15 L + 0.2526) Omega,
    T = -8 pi eta R^2 (1/10 L + 0.1895) U - 8 pi eta R^3 (2/5 L + 0.3817) Omega

(signs for U along e, Omega along n x e, n the unit normal from the sphere's centre to the plane; the two
coupling coefficients agree to 3e-4, as the reciprocal theorem requires; the torque-free sphere rotates at a
quarter of the rolling speed as h -> 0). Like the squeeze force, a sphere-on-plane value: the conforming
pocket raises it, so it is a lower bound there; the rotation about the normal (a finite moment) is left out.

References
----------
.. [1] D. E. Brewe, B. J. Hamrock and C. M. Taylor, "Effect of geometry on hydrodynamic film thickness,"
   J. Lubr. Technol. 101(2) (1979) 231-239. doi:10.1115/1.3453332
.. [2] B. J. Hamrock, S. R. Schmid and B. O. Jacobson, Fundamentals of Fluid Film Lubrication, 2nd ed.,
   Marcel Dekker, 2004 (the film-thickness formulas of the four regimes of fluid-film lubrication, the
   isoviscous-rigid one Brewe, Hamrock & Taylor's).
.. [3] H. Brenner, "The slow motion of a sphere through a viscous fluid towards a plane surface,"
   Chem. Eng. Sci. 16 (1961) 242-251. doi:10.1016/0009-2509(61)80035-3
.. [4] A. J. Goldman, R. G. Cox and H. Brenner, "Slow viscous motion of a sphere parallel to a plane
   wall - I. Motion through a quiescent fluid," Chem. Eng. Sci. 22 (1967) 637-651.
   doi:10.1016/0009-2509(67)80047-2 (the asymptotic forms for small gaps, after O'Neill & Stewartson,
   J. Fluid Mech. 27 (1967) 705-724)
"""
from __future__ import annotations

import math

import numpy as np

from .._jit import kernel

__all__ = ["isoviscous_rigid_film_constant", "hydrodynamic_film_load", "hydrodynamic_film_force",
           "squeeze_film_force", "squeeze_film_damping", "pocket_film_radii", "shear_resistance",
           "sphere_wall_shear"]


def isoviscous_rigid_film_constant(radius_ratio):
    """H_hat = 128 alpha_r lambda_b^2 [0.131 atan(alpha_r / 2) + 1.683]^2 [-], lambda_b = (1 + 2 / (3
    alpha_r))^-1: the dimensionless minimum film (h / R_x) (W / U)^2 of a rigid ellipsoid on a plane in the
    isoviscous-rigid regime, Brewe, Hamrock & Taylor's fit [1]_ (module docstring); ``radius_ratio``
    alpha_r = R_y / R_x > 0.

    Examples
    --------
    >>> round(float(isoviscous_rigid_film_constant(1.0)), 2)   # a sphere on a plane
    140.11
    """
    a = np.asarray(radius_ratio, float)
    lam = 1.0 / (1.0 + 2.0 / (3.0 * a))
    return 128.0 * a * lam * lam * (0.131 * np.arctan(0.5 * a) + 1.683) ** 2


def hydrodynamic_film_load(viscosity, entraining_speed, r_x, h_hat, film_thickness):
    """w = eta |u| R_x sqrt(H_hat R_x / h) [N]: the load a rigid isoviscous film of minimum thickness h [m]
    carries at the entraining speed u [m/s] (the mean of the surfaces' speeds), R_x [m] the radius along u,
    ``h_hat`` the film constant H_hat of :func:`isoviscous_rigid_film_constant` (Brewe, Hamrock & Taylor [1]_
    solved for the load). ``viscosity`` eta [Pa s]. Scalars or arrays (also compiled: ``_hydrodynamic_film_load``)."""
    return viscosity * np.abs(entraining_speed) * r_x * np.sqrt(h_hat * r_x / film_thickness)


def hydrodynamic_film_force(viscosity, entraining_speed, r_x, radius_ratio, film_thickness):
    """:func:`hydrodynamic_film_load` [N] for the radius ratio ``radius_ratio`` = R_y / R_x."""
    return hydrodynamic_film_load(viscosity, entraining_speed, r_x, isoviscous_rigid_film_constant(radius_ratio),
                                  np.asarray(film_thickness, float))


def squeeze_film_damping(viscosity, radius, film_thickness):
    """C = 6 pi eta R^2 / h [N s/m]: the squeeze film's force per approach speed of a sphere of radius R [m]
    at the gap h [m] from a plane (Brenner's lubrication limit [3]_); ``viscosity`` eta [Pa s]. Scalars or
    arrays (also compiled: ``_squeeze_film_damping``)."""
    return 6.0 * math.pi * viscosity * radius * radius / film_thickness


def squeeze_film_force(viscosity, radius, film_thickness, approach_speed):
    """F = 6 pi eta R^2 v / h [N] for a sphere approaching a plane at v = -dh/dt > 0 [m/s]; 0 when it moves
    away (the film cavitates, half-Sommerfeld). :func:`squeeze_film_damping` times max(v, 0)."""
    return squeeze_film_damping(viscosity, radius, film_thickness) * np.maximum(approach_speed, 0.0)


def pocket_film_radii(ball_radius, pocket_clearance, cylindrical):
    """(R_x [m], alpha_r [-]) of the film between a ball of radius R_b and its pocket wall (radius R_b +
    c_p), the entraining direction taken along a cylindrical pocket's axis, where the wall is straight
    (R_x = R_b, the ball rolling about the bearing's axis; across it the wall conforms, R_y = R_b (R_b +
    c_p) / c_p); a spherical pocket conforms in both directions (R_x = R_y = R_b (R_b + c_p) / c_p)."""
    rb, c = float(ball_radius), float(pocket_clearance)
    conform = rb * (rb + c) / c
    if cylindrical:
        return rb, conform / rb
    return conform, 1.0


def shear_resistance(viscosity, radius, film_thickness):
    """(A [N s/m], B [N s], C [N m s]): the resistance of a sphere of radius R [m] at the gap h [m] from a
    plane to its motion along the plane, F = -(A U + B Omega), T = -(B U + C Omega) (module docstring;
    Goldman, Cox & Brenner [4]_, h / R -> 0): A = 6 pi eta R (8/15 L + 0.9588), B = 8 pi eta R^2 (1/10 L +
    0.1895), C = 8 pi eta R^3 (2/5 L + 0.3817), L = ln(R / h), at least 0 (a gap beyond the radius is outside
    the expansion). ``viscosity`` eta [Pa s]. Scalars or arrays (also compiled: ``_shear_resistance``).

    Examples
    --------
    >>> a, b, c = shear_resistance(1.0, 1.0, 1e-3)     # eta = R = 1, h / R = 1e-3 (L = 6.91)
    >>> round(float(a / (6 * math.pi)), 3), round(float(c / (8 * math.pi)), 3)
    (4.643, 3.145)
    """
    big_l = np.maximum(np.log(radius / film_thickness), 0.0)
    a = 6.0 * math.pi * viscosity * radius * (8.0 / 15.0 * big_l + 0.9588)
    b = 8.0 * math.pi * viscosity * radius * radius * (0.1 * big_l + 0.1895)
    c = 8.0 * math.pi * viscosity * radius * radius * radius * (0.4 * big_l + 0.3817)
    return a, b, c


def sphere_wall_shear(viscosity, radius, film_thickness, nx, ny, nz, ux, uy, uz, ox, oy, oz):
    """(F_x, F_y, F_z [N], T_x, T_y, T_z [N m]): the shear force and moment (about the sphere's centre) of the
    film on a sphere of radius R [m] at the gap h [m] from a wall, n the unit normal from the sphere's centre
    to the wall, (ux, uy, uz) [m/s] and (ox, oy, oz) [rad/s] the sphere's velocity and angular velocity
    relative to the wall. Only the parts along the wall count (:func:`shear_resistance`): the approach is the
    squeeze film's, the rotation about n is left out. The power -(F.u + T.omega) >= 0 is dissipated. Scalars
    (also compiled: ``_sphere_wall_shear``)."""
    a, b, c = _shear_resistance(viscosity, radius, film_thickness)
    un = ux * nx + uy * ny + uz * nz
    tx, ty, tz = ux - un * nx, uy - un * ny, uz - un * nz  # the velocity along the wall
    on = ox * nx + oy * ny + oz * nz
    rx, ry, rz = ox - on * nx, oy - on * ny, oz - on * nz  # the rotation about axes in the wall's plane
    # the force: -A U (along U) and -B Omega along Omega x n (the direction the surface moves at the gap);
    # the moment: -B U along n x U and -C Omega
    fx = -a * tx - b * (ry * nz - rz * ny)
    fy = -a * ty - b * (rz * nx - rx * nz)
    fz = -a * tz - b * (rx * ny - ry * nx)
    mx = -b * (ny * tz - nz * ty) - c * rx
    my = -b * (nz * tx - nx * tz) - c * ry
    mz = -b * (nx * ty - ny * tx) - c * rz
    return fx, fy, fz, mx, my, mz


_hydrodynamic_film_load = kernel(hydrodynamic_film_load, no_runtime=True, inline="always")
_squeeze_film_damping = kernel(squeeze_film_damping, no_runtime=True, inline="always")
_shear_resistance = kernel(shear_resistance, no_runtime=True, inline="always")
_sphere_wall_shear = kernel(sphere_wall_shear, no_runtime=True, inline="always")
