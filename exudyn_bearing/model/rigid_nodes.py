"""Kinematics of Exudyn's rigid-body nodes, shared by the ball element and the bearing levels' node
formulation: the rotation matrix and the G matrix of Tait-Bryan xyz angles (Exudyn's NodeRigidBodyRxyz:
A = A_x(a0) A_y(a1) A_z(a2), global angular velocity = G(a0, a1) d(angles)/dt), and the Tait-Bryan angles of a
rotation matrix (the inverse map, as Exudyn's RigidBodyMath::RotationMatrix2RotXYZ, which the connector
ObjectConnectorRigidBodySpringDamper hands its user function). Row-major 9-tuples."""
from __future__ import annotations

import math

from .._jit import kernel

__all__ = ["g_xyz", "rot_xyz", "rot_xyz_angles"]


@kernel
def rot_xyz(a0, a1, a2):
    """Rotation matrix A = Ax Ay Az of Tait-Bryan xyz angles (Exudyn's Rxyz), row-major."""
    c0, s0 = math.cos(a0), math.sin(a0)
    c1, s1 = math.cos(a1), math.sin(a1)
    c2, s2 = math.cos(a2), math.sin(a2)
    return (c1 * c2, -c1 * s2, s1,
            s0 * s1 * c2 + c0 * s2, -s0 * s1 * s2 + c0 * c2, -s0 * c1,
            -c0 * s1 * c2 + s0 * s2, c0 * s1 * s2 + s0 * c2, c0 * c1)


@kernel
def g_xyz(a0, a1):
    """G of Tait-Bryan xyz angles (global angular velocity = G d(angles)/dt), row-major."""
    c0, s0 = math.cos(a0), math.sin(a0)
    c1, s1 = math.cos(a1), math.sin(a1)
    return (1.0, 0.0, s1,
            0.0, c0, -c1 * s0,
            0.0, s0, c0 * c1)


@kernel
def rot_xyz_angles(r):
    """Tait-Bryan xyz angles (a0, a1, a2) of the row-major rotation matrix ``r`` (A = Ax Ay Az): a1 from the
    (0, 2) entry, a0 and a2 from the rest; at a1 = +-pi/2 (gimbal lock) a0 = 0 and a2 takes the whole turn about
    the common axis. Each angle in (-pi, pi]."""
    c1 = math.sqrt(r[5] * r[5] + r[8] * r[8])
    a1 = math.atan2(r[2], c1)
    if c1 > 1e-14:
        return math.atan2(-r[5], r[8]), a1, math.atan2(-r[1], r[0])
    return 0.0, a1, math.atan2(r[3], r[4])
