"""The quasi-static level's node formulation (``formulation="node"``): the bearing as a force on the ring nodes'
coordinates of an ``ObjectGenericODE2``, with the level's own Jacobian.

The connector formulation (``formulation="connector"``, :mod:`.base`) hands the level to Exudyn's
``ObjectConnectorRigidBodySpringDamper``, whose Jacobian Exudyn computes by numerical differentiation (13
evaluations); its modified Newton therefore keeps one Jacobian per run, which the turning ball set makes stale
(the 6208's y stiffness under a radial load varies by 20 % over a ball passage), and each step takes about 3.6
evaluations. Here the same evaluation (:func:`.element.level_forces`) also returns the stiffness K = -dG/du and
damping C of the balls' current state (:func:`..damping.ring_damping_force`, the condensation of
:func:`..damping.condensed_matrices`), Exudyn's ``jacobianUserFunction`` hands them to Newton at every step
(``modifiedNewtonJacUpdatePerStep``, set by ``SimulationSettings``), and the bearings between the same nodes share
one object, one call into Python per evaluation and in it one compiled call for all of them
(:func:`.element.group_level_forces`; the Jacobian :func:`group_jacobian`).

Kinematics (those of the connector, ObjectConnectorRigidBodySpringDamper with its default rotationMarker0/1 = I):
each ring marker is a ``MarkerBodyRigid`` on ground or on a ``RigidBody`` with a ``NodeRigidBodyRxyz`` node, or a
``MarkerNodeRigid`` on such a node: position p = x + A l, rotation A (:func:`exudyn_bearing.model.rigid_nodes.rot_xyz`
of the node's angles), velocity x' + omega x (A l), global angular velocity omega = G a'. With marker 0 the outer
ring and marker 1 the inner ring: d = A0^T (p1 - p0), r = the Tait-Bryan angles of A0^T A1
(:func:`~exudyn_bearing.model.rigid_nodes.rot_xyz_angles`), v = A0^T (v1 - v0), w = A0^T (omega1 - omega0). The
level's f (:mod:`.base`: the connector's "spring force") acts as Exudyn's connector applies it: A0 f_force and
A0 f_moment on the inner ring's node with the left-hand side B1^T f, and their negatives on the outer ring's,
B_i = s_i [[A0^T, -A0^T [A_i l_i]~ G_i], [0, A0^T G_i]] (s_1 = +1, s_0 = -1) the map of node i's velocity
coordinates to (v, w); the generalized force returned to Exudyn is -sum_i B_i^T f.

Jacobian (Newton's only: it changes the iterations, not the solution, which meets Newton's tolerance on the
same residual): d(lhs_i)/dq_j = B_i^T K6 B_j and d(lhs_i)/dq'_j = B_i^T C6 B_j, with K6, C6 the 6x6 extension of
K and C (the spin row and column zero, plus C times the spin terms of the tilt rates, (w_x - w_z theta_y,
w_y + w_z theta_x)); the derivatives of A0, G_i and A_i l_i are left out (force times lever over stiffness
times lever squared: about 1e-4 of the terms kept for the 6208 at 3000 N).
"""
from __future__ import annotations

import math

import numpy as np

from ...._jit import kernel
from ....data import InputError
from ....model.rigid_nodes import g_xyz, rot_xyz, rot_xyz_angles
from .base import entry_point, python_calls

__all__ = ["FORMULATIONS", "NodeGroup", "group_jacobian", "node_force", "node_formulation_markers", "node_jacobian",
           "node_kinematics"]

#: Values of the quasi-static level's ``formulation`` option ("auto": "node" where the markers allow it)
FORMULATIONS = ("auto", "connector", "node")
#: Key in ``mbs.variables``: node tuple -> the NodeGroup of the bearings between those nodes
GROUP_REGISTRY = "exudyn_bearing.levelNodeGroups"
#: NodeGroup's solver of its last force call before any (no solver is this object)
_NO_RUN = object()
#: ring state row: position (3), rotation matrix (9), velocity (3), global angular velocity (3), G (9), A l (3)
_P, _A, _V, _W, _G, _O, _NS = 0, 3, 12, 15, 18, 27, 30
#: a bearing's node work array (one array: each array argument of a compiled call costs its unboxing): per ring
#: (outer = marker 0, inner = marker 1) the coordinate offset in the object (-1: ground), the node's reference
#: coordinates (6), the marker's local position (3), a ground marker's position and rotation (12), the ring state
#: (_NS); then the connector's quantities d, r, v, w (12), the level's K and C (50), what the group's call checks
#: (:meth:`NodeGroup._force`: the speed band of the grooves' last update (2), the ball load limit, the largest ball
#: load of the last evaluation), the Jacobian's scratch (the 6x6 matrix of K and C, the two B_i and B_i^T of that
#: matrix: 36 + 72 + 36), the bearing's share of the generalized force (6 per node of the object)
N_OFFS, N_REFS, N_LOCAL, N_FIXED, N_STATES = 0, 2, 14, 20, 44
N_CONN = N_STATES + 2 * _NS
N_MATS = N_CONN + 12
N_BAND = N_MATS + 50
N_QLIMIT = N_BAND + 2
N_QMAX = N_QLIMIT + 1
N_SCRATCH = N_QMAX + 1
N_SHARE = N_SCRATCH + 144


def node_formulation_markers(mbs, marker):
    """(node or -1 for ground, local position (3,), fixed position (3,) and rotation (9,) of a ground marker) of a
    ring marker the node formulation can take, else the reason it cannot (a str)."""
    m = mbs.GetMarker(int(marker))
    mtype = m["markerType"]
    local = np.asarray(m.get("localPosition", np.zeros(3)), float)
    fixed = np.concatenate([np.zeros(3), np.eye(3).ravel()])
    if mtype == "BodyRigid":
        obj = mbs.GetObject(m["bodyNumber"])
        if obj["objectType"] == "Ground":
            rot = np.asarray(obj.get("referenceRotation", np.eye(3)), float)
            fixed[:3] = np.asarray(obj["referencePosition"], float) + rot @ local
            fixed[3:] = rot.ravel()
            return -1, np.zeros(3), fixed
        if obj["objectType"] != "RigidBody":
            return f"the marker's body is a {obj['objectType']}, not a RigidBody or ground"
        node = int(obj["nodeNumber"])
    elif mtype == "NodeRigid":
        node, local = int(m["nodeNumber"]), np.zeros(3)
    else:
        return f"the marker is a {mtype} marker"
    ntype = mbs.GetNode(node)["nodeType"]
    if ntype != "RigidBodyRxyz":
        return f"its node is a {ntype} node, not a NodeRigidBodyRxyz"
    return node, local, fixed


@kernel(no_runtime=True)
def _ring_state(q, qt, nws, i):
    """Ring i's state (layout _P.._O, in ``nws``) from the object's coordinates ``q``, ``qt``."""
    s = nws[N_STATES + _NS * i:N_STATES + _NS * (i + 1)]
    off = int(nws[N_OFFS + i])
    for k in range(_NS):
        s[k] = 0.0
    if off < 0:
        for k in range(3):
            s[_P + k] = nws[N_FIXED + 12 * i + k]
        for k in range(9):
            s[_A + k] = nws[N_FIXED + 12 * i + 3 + k]
        return
    ref = nws[N_REFS + 6 * i:N_REFS + 6 * i + 6]
    a = rot_xyz(ref[3] + q[off + 3], ref[4] + q[off + 4], ref[5] + q[off + 5])
    g = g_xyz(ref[3] + q[off + 3], ref[4] + q[off + 4])
    for k in range(9):
        s[_A + k] = a[k]
        s[_G + k] = g[k]
    loc = nws[N_LOCAL + 3 * i:N_LOCAL + 3 * i + 3]
    for j in range(3):
        s[_O + j] = a[3 * j] * loc[0] + a[3 * j + 1] * loc[1] + a[3 * j + 2] * loc[2]
        s[_W + j] = g[3 * j] * qt[off + 3] + g[3 * j + 1] * qt[off + 4] + g[3 * j + 2] * qt[off + 5]
    for j in range(3):
        s[_P + j] = ref[j] + q[off + j] + s[_O + j]
    s[_V] = qt[off] + s[_W + 1] * s[_O + 2] - s[_W + 2] * s[_O + 1]
    s[_V + 1] = qt[off + 1] + s[_W + 2] * s[_O] - s[_W] * s[_O + 2]
    s[_V + 2] = qt[off + 2] + s[_W] * s[_O + 1] - s[_W + 1] * s[_O]


@kernel(inline="always")
def _col_dot(s0, s1, i, j):
    """(A0^T A1)[i, j]: column i of ring state s0's rotation matrix times column j of s1's."""
    return s0[_A + i] * s1[_A + j] + s0[_A + 3 + i] * s1[_A + 3 + j] + s0[_A + 6 + i] * s1[_A + 6 + j]


@kernel(no_runtime=True)
def node_kinematics(q, qt, nws):
    """Both rings' states and the connector's quantities d, r, v, w (module docstring) into the node work array."""
    _ring_state(q, qt, nws, 0)
    _ring_state(q, qt, nws, 1)
    s0 = nws[N_STATES:N_STATES + _NS]
    s1 = nws[N_STATES + _NS:N_STATES + 2 * _NS]
    conn = nws[N_CONN:N_CONN + 12]
    for i in range(3):  # A0^T (.): column i of A0
        dp = dv = dw = 0.0
        for k in range(3):
            a = s0[_A + 3 * k + i]
            dp += a * (s1[_P + k] - s0[_P + k])
            dv += a * (s1[_V + k] - s0[_V + k])
            dw += a * (s1[_W + k] - s0[_W + k])
        conn[i] = dp
        conn[6 + i] = dv
        conn[9 + i] = dw
    rel = (_col_dot(s0, s1, 0, 0), _col_dot(s0, s1, 0, 1), _col_dot(s0, s1, 0, 2),
           _col_dot(s0, s1, 1, 0), _col_dot(s0, s1, 1, 1), _col_dot(s0, s1, 1, 2),
           _col_dot(s0, s1, 2, 0), _col_dot(s0, s1, 2, 1), _col_dot(s0, s1, 2, 2))  # A0^T A1
    a0, a1, a2 = rot_xyz_angles(rel)
    conn[3] = a0
    conn[4] = a1
    conn[5] = a2


@kernel(no_runtime=True)
def _b_matrix(s0, si, sign, b):
    """B_i (6x6 row-major, module docstring) of ring state ``si`` in the frame of ring state ``s0``, into ``b``."""
    for k in range(36):
        b[k] = 0.0
    for r in range(3):
        for c in range(3):
            at = s0[_A + 3 * c + r]  # (A0^T)[r, c]
            b[6 * r + c] = sign * at
            for m in range(3):
                # -A0^T [o]~ G and A0^T G: [o]~[c, k] G[k, m]
                if c == 0:
                    cross = -si[_O + 2] * si[_G + 3 + m] + si[_O + 1] * si[_G + 6 + m]
                elif c == 1:
                    cross = si[_O + 2] * si[_G + m] - si[_O] * si[_G + 6 + m]
                else:
                    cross = -si[_O + 1] * si[_G + m] + si[_O] * si[_G + 3 + m]
                b[6 * r + 3 + m] -= sign * at * cross
                b[6 * (r + 3) + 3 + m] += sign * at * si[_G + 3 * c + m]


@kernel(no_runtime=True)
def node_force(out, nws, gen):
    """gen -= B_i^T out for both rings on a node: the connector's f = ``out`` (6,) applied as Exudyn applies it
    (module docstring): on ring i (sign s_i) s_i A0 f_force on the position coordinates and
    s_i G_i^T (A0 f_moment + (A_i l_i) x A0 f_force) on the angles."""
    s0 = nws[N_STATES:N_STATES + _NS]
    fp0 = s0[_A] * out[0] + s0[_A + 1] * out[1] + s0[_A + 2] * out[2]
    fp1 = s0[_A + 3] * out[0] + s0[_A + 4] * out[1] + s0[_A + 5] * out[2]
    fp2 = s0[_A + 6] * out[0] + s0[_A + 7] * out[1] + s0[_A + 8] * out[2]
    fr0 = s0[_A] * out[3] + s0[_A + 1] * out[4] + s0[_A + 2] * out[5]
    fr1 = s0[_A + 3] * out[3] + s0[_A + 4] * out[4] + s0[_A + 5] * out[5]
    fr2 = s0[_A + 6] * out[3] + s0[_A + 7] * out[4] + s0[_A + 8] * out[5]
    for i in range(2):
        off = int(nws[N_OFFS + i])
        if off < 0:
            continue
        si = nws[N_STATES + _NS * i:N_STATES + _NS * (i + 1)]
        sign = 1.0 if i == 1 else -1.0
        o0 = si[_O]
        o1 = si[_O + 1]
        o2 = si[_O + 2]
        t0 = fr0 + o1 * fp2 - o2 * fp1
        t1 = fr1 + o2 * fp0 - o0 * fp2
        t2 = fr2 + o0 * fp1 - o1 * fp0
        gen[off] -= sign * fp0
        gen[off + 1] -= sign * fp1
        gen[off + 2] -= sign * fp2
        for m in range(3):
            gen[off + 3 + m] -= sign * (si[_G + m] * t0 + si[_G + 3 + m] * t1 + si[_G + 6 + m] * t2)


@kernel(no_runtime=True)
def group_jacobian(nwss, f2, f2t, jac):
    """jac = the sum of :func:`node_jacobian` over the bearings of a group (``nwss``: a tuple of their node work
    arrays): one compiled call for all."""
    for r in range(jac.shape[0]):
        for c in range(jac.shape[1]):
            jac[r, c] = 0.0
    for i in range(len(nwss)):
        node_jacobian(nwss[i], f2, f2t, jac)


@kernel(no_runtime=True)
def node_jacobian(nws, f2, f2t, jac):
    """jac += f2 B_i^T K6 B_j + f2t B_i^T C6 B_j over both rings on a node (module docstring), K and C and the
    connector's quantities of the bearing's last evaluation (in ``nws``; the products in its scratch, N_SCRATCH:
    no allocation, the kernel runs without numba's runtime)."""
    mats = nws[N_MATS:N_MATS + 50]
    conn = nws[N_CONN:N_CONN + 12]
    m = nws[N_SCRATCH:N_SCRATCH + 36]  # row-major 6x6
    bs = nws[N_SCRATCH + 36:N_SCRATCH + 108]  # B_0, B_1 (row-major 6x6 each)
    left = nws[N_SCRATCH + 108:N_SCRATCH + 144]  # B_i^T m
    for k in range(36):
        m[k] = 0.0
    w2 = conn[11]
    for r in range(5):
        for c in range(5):
            m[6 * r + c] = f2 * mats[5 * r + c] + f2t * mats[25 + 5 * r + c]
        # the tilt rates (w_x - w_z theta_y, w_y + w_z theta_x): their C columns on theta and on w_z
        m[6 * r + 4] -= f2 * mats[25 + 5 * r + 3] * w2
        m[6 * r + 3] += f2 * mats[25 + 5 * r + 4] * w2
        m[6 * r + 5] = f2t * (-mats[25 + 5 * r + 3] * conn[4] + mats[25 + 5 * r + 4] * conn[3])
    for i in range(2):
        if int(nws[N_OFFS + i]) >= 0:  # a ring on ground has no coordinates, and no B_i
            _b_matrix(nws[N_STATES:N_STATES + _NS], nws[N_STATES + _NS * i:N_STATES + _NS * (i + 1)],
                      1.0 if i == 1 else -1.0, bs[36 * i:36 * (i + 1)])
    for i in range(2):
        oi = int(nws[N_OFFS + i])
        if oi < 0:
            continue
        for r in range(6):
            for c in range(6):
                acc = 0.0
                for k in range(6):
                    acc += bs[36 * i + 6 * k + r] * m[6 * k + c]
                left[6 * r + c] = acc
        for j in range(2):
            oj = int(nws[N_OFFS + j])
            if oj < 0:
                continue
            for r in range(6):
                for c in range(6):
                    acc = 0.0
                    for k in range(6):
                        acc += left[6 * r + k] * bs[36 * j + 6 * k + c]
                    jac[oi + r, oj + c] += acc


class NodeGroup:
    """The ObjectGenericODE2 of the bearings (node formulation) between one set of nodes: one force and one
    Jacobian call per evaluation for all of them, each one compiled call for all of them (``kernel``: the
    level's kernel over a group's bearings, :func:`.element.group_level_forces`; set by the level)."""

    def __init__(self, mbs, nodes):
        from exudyn.itemInterface import ObjectGenericODE2, VObjectGenericODE2

        self.nodes = tuple(nodes)
        self.bearings = []
        self.kernel = None
        self._calls = None  # (bearings, force call, its arguments after gen, Jacobian call): made on first use
        self._ready = False  # whether every bearing has K and C of an evaluation (the Jacobian's)
        n = 6 * len(self.nodes)
        self._sys = mbs.sys
        self._run = _NO_RUN  # the dynamic solver and time of the last force call (:meth:`_force`)
        self._t_last = -math.inf
        self._gen = np.zeros(n)
        self._jac = np.zeros((n, n))
        self.object = mbs.AddObject(ObjectGenericODE2(
            nodeNumbers=list(self.nodes), forceUserFunction=self._force, jacobianUserFunction=self._jacobian,
            visualization=VObjectGenericODE2(show=False)))

    @classmethod
    def of(cls, mbs, nodes):
        """The group of ``nodes`` in ``mbs`` (made on first use)."""
        groups = mbs.variables.setdefault(GROUP_REGISTRY, {})
        key = tuple(nodes)
        if key not in groups:
            groups[key] = cls(mbs, key)
        return groups[key]

    def offset(self, node):
        return -1 if node < 0 else 6 * self.nodes.index(node)

    def add(self, bearing):
        """A bearing joins the group (its compiled calls are made again at the next call)."""
        self.bearings.append(bearing)
        self._calls = None

    def _compiled_calls(self):
        """(bearings, the force kernel's entry point and its arguments after ``gen``, the Jacobian kernel's): one
        compiled call for the group's bearings (tuples of their arrays), made again when a bearing joined."""
        if self._calls is None or len(self._calls[0]) != len(self.bearings):
            bs = tuple(self.bearings)
            args = (bs[0]._hz_table, tuple(b._method for b in bs), tuple(b._nws for b in bs),
                    tuple(b._ws for b in bs), tuple(b._start for b in bs), tuple(b._balls for b in bs))
            qq = np.zeros(2 * self._gen.size)
            self._calls = (bs, entry_point(self.kernel, (qq, self._gen, *args)), args,
                           entry_point(group_jacobian, (args[2], 1.0, 1.0, self._jac)))
            self._ready = False
        return self._calls

    def _force(self, mbs, t, itemNumber, q, q_t):
        """The generalized force of the group's bearings: per bearing the steps of the connector's evaluation
        before the kernel (a new run, the first evaluation's cage angle), one compiled call for all
        (:func:`.element.group_level_forces`), per bearing the steps after it where that call asks for them (the
        speed left the grooves' band, a ball load or contact angle beyond its limit), and the samples. Exudyn hands
        q and q_t as lists of floats: one conversion of both (about 0.5 us per conversion of a short list; twice
        that with a dtype to check). The next step of the same run (a later time, the same solver) starts nothing
        over: each bearing only takes the time and counts the evaluation (what LevelBearing._begin does then)."""
        python_calls[0] += 1
        gen = self._gen
        qq = np.array(q + q_t) if type(q) is list else np.concatenate((np.asarray(q, float), np.asarray(q_t, float)))
        calls = self._calls
        if calls is None or len(calls[0]) != len(self.bearings):
            calls = self._compiled_calls()
        bs, kern, args, _ = calls
        solver = self._sys.get("dynamicSolver")
        n = gen.size
        if t == self._t_last and solver is self._run:
            # Newton's next evaluation of the same step: nothing starts over, nothing is sampled
            # (LevelBearing._begin and _end do nothing but count it)
            for b in bs:
                b._evaluations += 1
            if kern(qq, gen, *args):
                for b in bs:
                    b._node_after(qq[:n], qq[n:], gen)
            return gen
        q, q_t = qq[:n], qq[n:]
        if solver is self._run and t > self._t_last:
            for b in bs:
                if b._t_last >= b._next_sample - 1e-12:  # its last step is a sample: the work arrays hold it
                    b._step_done(b._t_last)
                b._t_last = t
                b._evaluations += 1
        else:
            for b in bs:
                b._node_before(t, q, q_t)
        if kern(qq, gen, *args):
            for b in bs:
                b._node_after(q, q_t, gen)
        for b in bs:
            if t >= b._next_sample - 1e-12:
                b._end(t)
        if not self._ready:
            for b in bs:
                b._mats_ready = True
            self._ready = True
        self._t_last = t
        self._run = solver
        return gen

    def _jacobian(self, mbs, t, itemNumber, q, q_t, fODE2, fODE2_t):
        python_calls[0] += 1
        calls = self._calls
        if calls is None or len(calls[0]) != len(self.bearings):
            calls = self._compiled_calls()
        if not self._ready:
            for b in calls[0]:
                if not b._mats_ready:  # no evaluation yet: one at this state
                    b._node_evaluation(t, np.asarray(q, float), np.asarray(q_t, float), np.zeros_like(self._gen))
            self._ready = True
        calls[3](calls[2][2], fODE2, fODE2_t, self._jac)
        return self._jac


def check_formulation(value):
    """``formulation`` if it is one of FORMULATIONS, else InputError naming it."""
    if value not in FORMULATIONS:
        raise InputError(f"formulation: must be one of {', '.join(FORMULATIONS)}, got {value!r}")
    return value


def refuse_node(reason, which):
    """The InputError of formulation='node' for ring markers it cannot take."""
    return InputError(f"formulation: 'node' needs the two ring markers on two bodies, each on ground or on a "
                      f"RigidBody with a NodeRigidBodyRxyz node; {which}: {reason} (use formulation='connector' "
                      "or 'auto')")

