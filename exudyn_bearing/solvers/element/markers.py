"""Rings of the Exudyn element: what a ring marker points to (ground, a
rigid body with an Rxyz or Lie-group node, a mass point), the ring's pose at
t = 0, and the mobility of the body it sits on (for the fast mode's stable
step)."""
from __future__ import annotations

import numpy as np

from ...data import InputError
from . import kernels as EK

__all__ = ["ring_from_marker", "ring_mobility", "initial_ring_pose", "RING_REGISTRY"]

#: Key in ``mbs.variables``: ring node -> [(element, ring index)] of every
#: bearing element on it (the fast mode's stable Exudyn step adds them up).
RING_REGISTRY = "exudyn_bearing.ringNodes"


def ring_from_marker(mbs, marker, which):
    """(kind, node, local position, fixed (12,)) of a ring marker, or InputError."""
    name = f"marker{which}Ring"
    try:
        m = mbs.GetMarker(int(marker))
    except Exception:
        raise InputError(f"{name}: {marker!r} is not a marker of this mbs") from None
    mtype = m["markerType"]
    ht = np.asarray(m.get("localHT", np.eye(4)), float)
    if not np.allclose(ht[:3, :3], np.eye(3)):
        raise InputError(f"{name}: the marker has a rotation offset; the bearing axis is the local z "
                         "axis of the ring body, use a marker without rotation")
    local = np.asarray(m.get("localPosition", np.zeros(3)), float)
    fixed = np.zeros(12)
    fixed[3:] = np.eye(3).ravel()
    if mtype in ("BodyRigid", "BodyPosition"):
        obj = mbs.GetObject(m["bodyNumber"])
        otype = obj["objectType"]
        if otype == "Ground":
            fixed[:3] = np.asarray(obj["referencePosition"], float) + np.asarray(
                obj.get("referenceRotation", np.eye(3)), float) @ local
            fixed[3:] = np.asarray(obj.get("referenceRotation", np.eye(3)), float).ravel()
            return EK.RING_FIXED, -1, np.zeros(3), fixed
        if "nodeNumber" not in obj:
            raise InputError(f"{name}: body type {otype} is not supported (use a RigidBody with a "
                             "NodeRigidBodyRxyz or NodeRigidBodyRotVecLG node, a MassPoint, or ground)")
        node = obj["nodeNumber"]
    elif mtype in ("NodeRigid", "NodePosition"):
        node = m["nodeNumber"]
    else:
        raise InputError(f"{name}: marker type {mtype} is not a rigid-body or position marker")
    ntype = mbs.GetNode(node)["nodeType"]
    if ntype == "RigidBodyRxyz":
        return EK.RING_RXYZ, int(node), local, fixed
    if ntype == "RigidBodyRotVecLG":
        return EK.RING_ROTVEC, int(node), local, fixed
    if ntype == "Point":
        fixed[:3] = local
        return EK.RING_POINT, int(node), np.zeros(3), fixed
    hint = (" (Euler-parameter nodes carry an algebraic constraint, which Exudyn's explicit solvers refuse; "
            "use nodeType=exu.NodeType.RotationRxyz or RotationRotationVector)" if ntype == "RigidBodyEP" else "")
    raise InputError(f"{name}: node type {ntype} is not supported (NodeRigidBodyRxyz, NodeRigidBodyRotVecLG, "
                     f"NodePoint or ground){hint}")


def _skew(v):
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


def ring_mobility(mbs, marker, kind, local):
    """Largest eigenvalue of B M^-1 B^T [1/kg] for the ring centre of a ring
    marker: M the mass matrix of the body it sits on (found through the
    marker's body or its node; Exudyn's rigid-body inertia is taken about the
    node, with the centre of mass at ``centerOfMass``), B the map from the
    body's velocity and angular velocity to the ring centre's velocity.
    None for ground or an unknown body."""
    if kind == EK.RING_FIXED:
        return None
    m = mbs.GetMarker(int(marker))
    obj = None
    if "bodyNumber" in m:
        obj = mbs.GetObject(m["bodyNumber"])
    else:
        node = int(m["nodeNumber"])
        for i in range(mbs.systemData.NumberOfObjects()):
            o = mbs.GetObject(i)
            if "nodeNumber" in o and int(o["nodeNumber"]) == node and o.get("mass"):
                obj = o
                break
    if obj is None or not obj.get("mass"):
        return None
    mass = float(obj["mass"])
    if kind == EK.RING_POINT or "inertia" not in obj:
        return 1.0 / mass
    jv = np.asarray(obj["inertia"], float)  # Jxx, Jyy, Jzz, Jyz, Jxz, Jxy about the node
    j = np.array([[jv[0], jv[5], jv[4]], [jv[5], jv[1], jv[3]], [jv[4], jv[3], jv[2]]])
    mc = mass * _skew(np.asarray(obj.get("centerOfMass", np.zeros(3)), float))
    mm = np.block([[mass * np.eye(3), mc.T], [mc, j]])
    bb = np.hstack([np.eye(3), _skew(np.asarray(local, float)).T])  # v + w x o
    return float(np.linalg.eigvalsh(bb @ np.linalg.solve(mm, bb.T)).max())


def initial_ring_pose(mbs, kind, node, local, fixed):
    """Ring centre, rotation matrix, velocity and angular velocity at t = 0."""
    if kind == EK.RING_FIXED:
        return fixed[:3].copy(), fixed[3:].reshape(3, 3), np.zeros(3), np.zeros(3)
    n = mbs.GetNode(node)
    q = np.asarray(n["referenceCoordinates"], float) + np.asarray(n["initialCoordinates"], float)
    v = np.asarray(n.get("initialVelocities", n.get("initialCoordinates_t", np.zeros(q.size))), float)
    if kind == EK.RING_POINT:
        return q[:3] + fixed[:3], fixed[3:].reshape(3, 3), v[:3], np.zeros(3)
    a = np.array(EK.node_rotation(kind, q)).reshape(3, 3)
    g = np.array(EK._g_xyz(q[3], q[4])).reshape(3, 3) if kind == EK.RING_RXYZ else a  # Lie group: local omega
    w = g @ v[3:6]
    o = a @ local
    return q[:3] + o, a, v[:3] + np.cross(w, o), w
