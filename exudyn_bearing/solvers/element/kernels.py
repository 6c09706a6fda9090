"""Compiled part of the Exudyn bearing element: one call per force evaluation.

It turns the coordinates of the bearing's ObjectGenericODE2 (balls, cage
balls and the ring nodes) into ring poses, calls the shared contact kernel
:func:`exudyn_bearing.model.contact.forces`, and returns the generalized
forces of all these coordinates.

Coordinate layout of the object: ball j owns coordinates 6j..6j+5 (position
and an integrated global rotation vector whose rate is the angular velocity:
exact Newton-Euler for a homogeneous sphere, whose orientation never enters
the forces), cage ball k owns 6(Z+k)..6(Z+k)+5. With the rigid cage (body
mode) its NodeRigidBodyRxyz owns 6Z..6Z+5 (centre, Tait-Bryan angles; the
tilts held at their reference values by constraints), mapped to and from the contact kernel's
cage rows (:mod:`exudyn_bearing.model.layout`: ``xc[0]`` the centre,
``xc[1, 0]`` the angle about the bearing axis in the cage's bearing frame, ``vc`` their rates;
:func:`cage_frame`, :func:`cage_spin`).
"""
from __future__ import annotations

import math

import numpy as np
from numba.core import types
from numba.experimental import structref

from ..._jit import kernel
from ...model.contact import accumulate_energy, forces
from ...model.layout import (NDIAG, NGLOBAL, NSIGNAL, P_CAGE, P_CAGE_ANGLE0, P_CAGE_FRAME, P_IB, P_IC, P_MB, P_MC,
                             P_MZ, P_NDEF, P_RIGID, R_ANGLE, RING_N)
from ...model.motion import kick_drift
from ...model.rigid_nodes import g_xyz as _g_xyz
from ...model.rigid_nodes import rot_xyz as _rot_xyz

#: Ring couplings: fixed in space (ground), node with position coordinates
#: only (mass point: axes parallel to the world, prescribed spin), rigid-body
#: node with Tait-Bryan xyz rotation parameters (Exudyn's NodeRigidBodyRxyz),
#: rigid-body node with a rotation vector and the local angular velocity as
#: velocity coordinates (Exudyn's Lie-group node NodeRigidBodyRotVecLG).
RING_FIXED, RING_POINT, RING_RXYZ, RING_ROTVEC = 0, 1, 2, 3

#: How close (1 - |cos| of the angle) a bearing axis must be to the world's x axis for the rigid cage's node to turn
#: by its first Tait-Bryan angle (:func:`cage_frame`): the tolerance of the element's check that the ring axes are
#: parallel.
AXIS_TOLERANCE = 1e-9


def cage_frame(rotation):
    """The rigid cage's bearing frame and its Exudyn node's angles, for the outer ring's rotation matrix
    ``rotation`` at t = 0 (world; its third column the bearing axis u).

    Returns (B, angles, offset): B (3, 3) the frame of the outer ring at t = 0, its axes e1, e2, e3 = u in its
    columns (the contact kernel's ``P_CAGE_FRAME``, in which the cage moves and gravity is taken:
    docs/theory/cage.md#in-the-exudyn-element); the NodeRigidBodyRxyz angles of the cage body whose node angle
    :func:`cage_spin` turns it about u; and ``offset``, the cage's angle in B [rad] where that node angle is 0
    (the kernel's cage angle is sign * node angle + offset, ``P_CAGE_ANGLE0``).

    The node: in general R_x(a) R_y(b) R_z(c), whose (a, b) turn z onto u (u = (sin b, -sin a cos b,
    cos a cos b): b = asin(u_x), a = atan2(-u_y, u_z)) and whose third angle c turns the body about its local
    z, the axis. Within ``AXIS_TOLERANCE`` of the world's +-x axis (cos b = 0: Tait-Bryan xyz angles are
    singular there, and so is Exudyn's mass matrix of the node) the axis is taken as +-x and the node's first
    angle turns the body about the world x axis, its local x, from the frame (e_y, +-e_z, +-e_x). B is that
    frame of the node at its turning angle 0, turned about u by the angle of the outer ring's x axis in it:
    the identity for an outer ring not turned."""
    a_o = np.asarray(rotation, float)
    u = a_o[:, 2] / np.linalg.norm(a_o[:, 2])
    if abs(u[0]) > 1.0 - AXIS_TOLERANCE:
        s = 1.0 if u[0] > 0.0 else -1.0
        b0, angles = np.array([[0.0, 0.0, s], [1.0, 0.0, 0.0], [0.0, s, 0.0]]), np.zeros(3)
    else:
        a, b = math.atan2(-u[1], u[2]), math.asin(u[0])
        ca, sa, cb, sb = math.cos(a), math.sin(a), math.cos(b), math.sin(b)
        rx = np.array([[1.0, 0.0, 0.0], [0.0, ca, -sa], [0.0, sa, ca]])
        ry = np.array([[cb, 0.0, sb], [0.0, 1.0, 0.0], [-sb, 0.0, cb]])
        b0, angles = rx @ ry, np.array([a, b, 0.0])
    x = b0.T @ a_o[:, 0]
    c0 = math.atan2(x[1], x[0])  # the outer ring's x axis in the node's frame
    cc, sc = math.cos(c0), math.sin(c0)
    return b0 @ np.array([[cc, -sc, 0.0], [sc, cc, 0.0], [0.0, 0.0, 1.0]]), angles, -c0


@kernel
def cage_spin(e3x):
    """(Index among its 6 coordinates, sign) of the rigid cage node's angle that turns the cage about the
    bearing axis, for the x component ``e3x`` of the bearing frame's e3 (:func:`cage_frame`): the first angle
    (3, +-1) when the axis is the world's +-x axis (``e3x`` exactly +-1), else the third (5, 1). The cage's
    angle about the axis is the sign times that coordinate."""
    if e3x == 1.0 or e3x == -1.0:
        return 3, e3x
    return 5, 1.0


@kernel
def _rot_vec(v0, v1, v2):
    """Rotation matrix of a rotation vector (Rodrigues: I + sin(p)/p [v] + (1 - cos(p))/p^2 [v]^2), row-major."""
    p2 = v0 * v0 + v1 * v1 + v2 * v2
    if p2 < 1e-16:  # series to second order
        s, c = 1.0 - p2 / 6.0, 0.5 - p2 / 24.0
    else:
        ph = math.sqrt(p2)
        s, c = math.sin(ph) / ph, (1.0 - math.cos(ph)) / p2
    return (1.0 - c * (v1 * v1 + v2 * v2), -s * v2 + c * v0 * v1, s * v1 + c * v0 * v2,
            s * v2 + c * v0 * v1, 1.0 - c * (v0 * v0 + v2 * v2), -s * v0 + c * v1 * v2,
            -s * v1 + c * v0 * v2, s * v0 + c * v1 * v2, 1.0 - c * (v0 * v0 + v1 * v1))


@kernel
def node_rotation(kind, rq):
    """Rotation matrix (row-major 9-tuple) of a rigid ring node's total coordinates ``rq``."""
    if kind == RING_ROTVEC:
        return _rot_vec(rq[3], rq[4], rq[5])
    return _rot_xyz(rq[3], rq[4], rq[5])


@kernel(no_runtime=True)
def ring_pose(kind, rq, rqt, local, fixed, spin, angle, rings, r):
    """Row r of ``rings`` (centre, velocity, rotation matrix, angular velocity,
    spin angle beyond the matrix).

    ``rq``, ``rqt`` (6 values): total coordinates and velocities of the ring node
    (position, Tait-Bryan angles; point nodes use the first three);
    ``local`` (3,): ring centre in the body frame (rigid nodes); ``fixed``
    (12,): position (fixed ring) or offset (point ring) and rotation matrix
    of fixed and point rings; ``spin``: their prescribed spin about the ring
    axis [rad/s], ``angle`` its integral [rad] (layout ``R_ANGLE``; rigid
    rings carry their rotation in the matrix and get 0).
    """
    for k in range(RING_N):
        rings[r, k] = 0.0
    if kind == RING_FIXED or kind == RING_POINT:
        rings[r, R_ANGLE] = angle
        for d in range(3):
            rings[r, d] = fixed[d]
        for k in range(9):
            rings[r, 6 + k] = fixed[3 + k]
        if kind == RING_POINT:
            for d in range(3):
                rings[r, d] += rq[d]
                rings[r, 3 + d] = rqt[d]
        # spin about the ring axis: the third column of its rotation matrix
        rings[r, 15] = spin * fixed[5]
        rings[r, 16] = spin * fixed[8]
        rings[r, 17] = spin * fixed[11]
        return
    a = node_rotation(kind, rq)
    # global angular velocity: G times the angle rates (Rxyz), A times the local one (Lie group)
    g = _g_xyz(rq[3], rq[4]) if kind == RING_RXYZ else a
    w0 = g[0] * rqt[3] + g[1] * rqt[4] + g[2] * rqt[5]
    w1 = g[3] * rqt[3] + g[4] * rqt[4] + g[5] * rqt[5]
    w2 = g[6] * rqt[3] + g[7] * rqt[4] + g[8] * rqt[5]
    o0 = a[0] * local[0] + a[1] * local[1] + a[2] * local[2]
    o1 = a[3] * local[0] + a[4] * local[1] + a[5] * local[2]
    o2 = a[6] * local[0] + a[7] * local[1] + a[8] * local[2]
    rings[r, 0] = rq[0] + o0
    rings[r, 1] = rq[1] + o1
    rings[r, 2] = rq[2] + o2
    rings[r, 3] = rqt[0] + w1 * o2 - w2 * o1
    rings[r, 4] = rqt[1] + w2 * o0 - w0 * o2
    rings[r, 5] = rqt[2] + w0 * o1 - w1 * o0
    for k in range(9):
        rings[r, 6 + k] = a[k]
    rings[r, 15] = w0
    rings[r, 16] = w1
    rings[r, 17] = w2


#: Columns of the per-ring data row: node coordinate offset in the object
#: (-1: none), local position (3), fixed/offset position and rotation (12),
#: prescribed spin [rad/s] and its integral, the spin angle [rad] (kept by
#: the element when the scene has defects).
RD_OFF, RD_LOCAL, RD_FIXED, RD_SPIN, RD_ANGLE, RD_N = 0, 1, 4, 16, 17, 18


@structref.register
class ElementStateType(types.StructRef):
    """numba type of :class:`ElementState`."""

    def preprocess_fields(self, fields):
        return tuple((name, types.unliteral(typ)) for name, typ in fields)


class ElementState(structref.StructRefProxy):
    """The arrays of one bearing element the compiled user-function calls
    work on (:data:`STATE_FIELDS`), held in one numba structure that the
    element's Python arrays share their memory with: a compiled call takes it
    as one argument, where the 20-odd separate arrays cost numba's entry point
    about 0.06 us each to unbox (validation/performance/profile_element.py). Built by
    :func:`element_state` (compiled and cached: constructing it from Python
    would compile numba's constructor in every process)."""


#: Fields of :class:`ElementState`: the system ODE2 index of each object
#: coordinate and the object's coordinates gathered from the system (body
#: mode), the reference coordinates, parameters, Hertz table, ring couplings
#: (kinds, data rows), committed and trial contact history, Hertz cache, ball
#: work rows, ring poses (the fast mode's at the last sub-step and at its end
#: too), ring reactions (and the fast mode's sums of them over its sub-steps), diagnostics, generalized forces ``out`` and those the
#: body mode's user function returns (``out_uf``, indices ``uf_index``), and
#: the body mode's clock (``CLK_*``).
STATE_FIELDS = ("index", "q", "q_t", "ref", "p", "table", "ring_kind", "ring_data", "hist", "hist_trial", "hz", "work",
                "rings", "rings0", "rings_sub", "fr", "fsum", "glob", "diag", "cage_load", "out", "uf_index", "out_uf",
                "clock")
structref.define_proxy(ElementState, ElementStateType, list(STATE_FIELDS))

#: Entries of the body mode's clock (``ElementState.clock``): the latest
#: evaluated time (-inf: none yet), the last committed time (its Cundall-Strack
#: history is ``hist``), the last time whose powers entered the energy
#: integrals, the next sample time, and whether the last evaluation sampled.
CLK_TRIAL, CLK_COMMIT, CLK_ENERGY, CLK_NEXT_SAMPLE, CLK_WANT, CLK_N = 0, 1, 2, 3, 4, 5


@kernel
def element_state(index, q, q_t, ref, p, table, ring_kind, ring_data, hist, hist_trial, hz, work, rings, rings0,
                  rings_sub, fr, fsum, glob, diag, cage_load, out, uf_index, out_uf, clock):
    """An :class:`ElementState` of these arrays (fields :data:`STATE_FIELDS`; it shares their memory)."""
    return ElementState(index, q, q_t, ref, p, table, ring_kind, ring_data, hist, hist_trial, hz, work, rings, rings0,
                        rings_sub, fr, fsum, glob, diag, cage_load, out, uf_index, out_uf, clock)


@kernel(no_runtime=True)
def element_rhs(q, q_t, ref, p, table, z, n_cage, ring_kind, ring_data, hist, hist_out, dt_hist, hz, work,
                rings, fr, glob, diag, cage_load, want, out, defect_path=True, ellipse_path=True, loss_path=True):
    """Generalized forces ``out`` of the bearing object for q, q_t.

    The object's coordinates are those of the balls, the cage balls and then
    the ring nodes (offsets in ``ring_data``); ``ref`` holds their reference
    values. The ring reactions enter ``out`` at the ring coordinates: force on
    the position coordinates, G^T times the torque about the node point on
    Tait-Bryan rotation coordinates. ``work`` (8, >= Z, 3) is scratch space
    for ball and cage states and forces. Returns the largest overlap / R_b.
    ``defect_path``, ``ellipse_path``, ``loss_path``: what of the contact
    kernel is compiled (:func:`~exudyn_bearing.model.contact.forces`; the
    element passes the scene's, as the reference engine does).
    """
    xb = work[0, :z]
    vb = work[1, :z]
    wb = work[2, :z]
    xc = work[3]
    vc = work[4]
    fb = work[5, :z]
    tb = work[6, :z]
    fc = work[7]
    for j in range(z):
        b = 6 * j
        for d in range(3):
            xb[j, d] = ref[b + d] + q[b + d]
            vb[j, d] = q_t[b + d]
            wb[j, d] = q_t[b + 3 + d]
    for k in range(n_cage):
        b = 6 * (z + k)
        for d in range(3):
            xc[k, d] = ref[b + d] + q[b + d]
            vc[k, d] = q_t[b + d]
    rigid = p[P_RIGID] > 0.5
    g = (0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    e0, e1, e2 = p[P_CAGE_FRAME + 2], p[P_CAGE_FRAME + 5], p[P_CAGE_FRAME + 8]  # the bearing axis (cage_frame)
    if rigid:  # the rigid cage's node after the balls: centre, angle about the bearing axis and their rates
        b = 6 * (z + n_cage)
        g = _g_xyz(ref[b + 3] + q[b + 3], ref[b + 4] + q[b + 4])
        for d in range(3):
            xc[0, d] = ref[b + d] + q[b + d]
            vc[0, d] = q_t[b + d]
        k, sign = cage_spin(e0)
        xc[1, 0] = sign * (ref[b + k] + q[b + k]) + p[P_CAGE_ANGLE0]
        # the angular velocity G times the angle rates, about the axis
        vc[1, 0] = (e0 * (g[0] * q_t[b + 3] + g[1] * q_t[b + 4] + g[2] * q_t[b + 5])
                    + e1 * (g[3] * q_t[b + 3] + g[4] * q_t[b + 4] + g[5] * q_t[b + 5])
                    + e2 * (g[6] * q_t[b + 3] + g[7] * q_t[b + 4] + g[8] * q_t[b + 5]))
    ring_poses_from(q, q_t, ref, ring_kind, ring_data, rings)
    worst = forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist_out, dt_hist, hz, fb, tb, fc, fr, glob,
                   diag, cage_load, want, defect_path, ellipse_path, loss_path)
    out[:] = 0.0
    for j in range(z):
        for d in range(3):
            out[6 * j + d] = fb[j, d]
            out[6 * j + 3 + d] = tb[j, d]
    for k in range(n_cage):
        for d in range(3):
            out[6 * (z + k) + d] = fc[k, d]
    if rigid:  # force on the centre, G^T times the moment about the axis (fc[1, 0] un-scaled by I_c / m_c)
        b = 6 * (z + n_cage)
        tz = fc[1, 0] * p[P_IC] / p[P_MC]
        for d in range(3):
            out[b + d] = fc[0, d]
            out[b + 3 + d] = (g[d] * e0 + g[3 + d] * e1 + g[6 + d] * e2) * tz
    ring_generalized_forces(q, ref, ring_kind, ring_data, rings, fr, out)
    return worst


@kernel(no_runtime=True)
def body_rhs(qs, qs_t, index, q, q_t, ref, p, table, z, n_cage, ring_kind, ring_data, hist, hist_out, dt_hist, hz,
             work, rings, fr, glob, diag, cage_load, want, dt_energy, out, defect_path=True, ellipse_path=True,
             loss_path=True):
    """Body mode, one force evaluation in one compiled call: the object-layout
    coordinates ``q``, ``q_t`` gathered from the system's ODE2 coordinates
    ``qs``, ``qs_t`` (``index``: their system index), :func:`element_rhs`
    into ``out``, then the energy integrals over ``dt_energy`` (the time
    since the last evaluation that advanced; 0 adds nothing). Returns the
    largest overlap / R_b."""
    for i in range(index.shape[0]):
        q[i] = qs[index[i]]
        q_t[i] = qs_t[index[i]]
    worst = element_rhs(q, q_t, ref, p, table, z, n_cage, ring_kind, ring_data, hist, hist_out, dt_hist, hz, work,
                        rings, fr, glob, diag, cage_load, want, out, defect_path, ellipse_path, loss_path)
    if dt_energy > 0.0:
        accumulate_energy(glob, dt_energy)
    return worst


@kernel
def body_step(qs, qs_t, st, t, n_cage, defect_path=True, ellipse_path=True, loss_path=True):
    """Body mode, one force evaluation at t in one compiled call on the
    element's state ``st`` (:class:`ElementState`) and the system's ODE2
    coordinates ``qs``, ``qs_t``: the Cundall-Strack history committed when
    time advances past the last evaluated time (the trial state of that
    evaluation becomes the committed one), whether to sample (t at or past
    the next sample time, ``clock[CLK_WANT]``), :func:`body_rhs`, the energy
    integrals over the time since the last evaluation that advanced, and the
    forces the user function returns into ``out_uf``. ``n_cage``: cage balls
    (0 without cage). Returns the largest overlap / R_b."""
    clock = st.clock
    hist = st.hist
    hist_trial = st.hist_trial
    t_trial = clock[CLK_TRIAL]
    if t > t_trial:
        if t_trial > -math.inf:
            for j in range(hist.shape[0]):
                for k in range(hist.shape[1]):
                    for d in range(hist.shape[2]):
                        hist[j, k, d] = hist_trial[j, k, d]
            clock[CLK_COMMIT] = t_trial
        clock[CLK_TRIAL] = t
    want = t >= clock[CLK_NEXT_SAMPLE] - 1e-12
    t_energy = clock[CLK_ENERGY]
    dt_energy = t - t_energy if t > t_energy else 0.0
    worst = body_rhs(qs, qs_t, st.index, st.q, st.q_t, st.ref, st.p, st.table, hist.shape[0], n_cage, st.ring_kind,
                     st.ring_data, hist, hist_trial, t - clock[CLK_COMMIT], st.hz, st.work, st.rings, st.fr, st.glob,
                     st.diag, st.cage_load, want, dt_energy, st.out, defect_path, ellipse_path, loss_path)
    if dt_energy > 0.0:
        clock[CLK_ENERGY] = t
    clock[CLK_WANT] = 1.0 if want else 0.0
    out = st.out
    out_uf = st.out_uf
    uf_index = st.uf_index
    for i in range(uf_index.shape[0]):
        out_uf[i] = out[uf_index[i]]
    return worst


@kernel(no_runtime=True)
def ring_generalized_forces(q, ref, ring_kind, ring_data, rings, fr, out):
    """Ring reactions ``fr`` (force, torque about the ring centre) as generalized
    forces of the ring-node coordinates in ``out``: the force on the position
    coordinates, G^T times the torque about the node point on Tait-Bryan
    rotation coordinates, the torque in the body frame (A^T times it) on a
    Lie-group node's rotation coordinates."""
    for r in range(2):
        off = int(ring_data[r, RD_OFF])
        if off < 0 or ring_kind[r] == RING_FIXED:
            continue
        for d in range(3):
            out[off + d] += fr[r, d]
        if ring_kind[r] == RING_RXYZ or ring_kind[r] == RING_ROTVEC:
            o0 = rings[r, 0] - (ref[off] + q[off])
            o1 = rings[r, 1] - (ref[off + 1] + q[off + 1])
            o2 = rings[r, 2] - (ref[off + 2] + q[off + 2])
            t0 = fr[r, 3] + o1 * fr[r, 2] - o2 * fr[r, 1]
            t1 = fr[r, 4] + o2 * fr[r, 0] - o0 * fr[r, 2]
            t2 = fr[r, 5] + o0 * fr[r, 1] - o1 * fr[r, 0]
            # G^T torque on Tait-Bryan angles, A^T torque (local torque) on a Lie-group
            # node, A being the ring's rotation matrix already in ``rings``
            if ring_kind[r] == RING_RXYZ:
                g = _g_xyz(ref[off + 3] + q[off + 3], ref[off + 4] + q[off + 4])
            else:
                g = (rings[r, 6], rings[r, 7], rings[r, 8], rings[r, 9], rings[r, 10], rings[r, 11],
                     rings[r, 12], rings[r, 13], rings[r, 14])
            out[off + 3] += g[0] * t0 + g[3] * t1 + g[6] * t2
            out[off + 4] += g[1] * t0 + g[4] * t1 + g[7] * t2
            out[off + 5] += g[2] * t0 + g[5] * t1 + g[8] * t2


@kernel(no_runtime=True)
def ring_poses_from(q, q_t, ref, ring_kind, ring_data, rings):
    """Both ring poses from the object coordinates (see :func:`ring_pose`; the
    node's coordinates as tuples, 0 beyond a point node's three: nothing to
    allocate)."""
    for r in range(2):
        off = int(ring_data[r, RD_OFF])
        x0 = x1 = x2 = x3 = x4 = x5 = 0.0
        v0 = v1 = v2 = v3 = v4 = v5 = 0.0
        if off >= 0:
            x0, x1, x2 = ref[off] + q[off], ref[off + 1] + q[off + 1], ref[off + 2] + q[off + 2]
            v0, v1, v2 = q_t[off], q_t[off + 1], q_t[off + 2]
            if ring_kind[r] != RING_POINT:
                x3, x4, x5 = ref[off + 3] + q[off + 3], ref[off + 4] + q[off + 4], ref[off + 5] + q[off + 5]
                v3, v4, v5 = q_t[off + 3], q_t[off + 4], q_t[off + 5]
        ring_pose(ring_kind[r], (x0, x1, x2, x3, x4, x5), (v0, v1, v2, v3, v4, v5),
                  ring_data[r, RD_LOCAL:RD_LOCAL + 3], ring_data[r, RD_FIXED:RD_FIXED + 12], ring_data[r, RD_SPIN],
                  ring_data[r, RD_ANGLE], rings, r)


@kernel(no_runtime=True)
def advance_balls(n_sub, tau, t, t_end, p, table, work, rings0, rings1, rings, hist, hz, fr, fsum, glob, diag,
                  cage_load, want, defect_path=True, ellipse_path=True, loss_path=True):
    """Fast mode: integrate balls and cage balls (or the rigid cage) in ``n_sub`` velocity-Verlet
    sub-steps from their last force evaluation at ``tau`` to ``t_end``.

    The ring poses the balls see: ``rings0`` at ``tau`` (what the balls saw
    last), ``rings1`` at the Exudyn time ``t``; centres linear in between and
    extrapolated with the velocity of ``rings1`` beyond ``t`` (velocities,
    rotation and angular velocity those of ``rings1``). ``work`` holds the
    ball state and the forces of the last evaluation on entry and exit.

    ``fr`` returns the mean ring reaction over the sub-step evaluations (their sum
    in ``fsum``, (2, 6) scratch: nothing allocated here): with
    the windows centred on the Exudyn times (``t_end = t + (H - dt) / 2``),
    the impulse Exudyn's velocity-Verlet step gives the ring, ``H fr``, is
    the sum of the sub-step impulses the balls received (momentum exchange
    consistent between the two integrators, no lag). ``rings0`` is left at
    the pose of the last evaluation. Diagnostics of the last sub-step when
    ``want``. With defects in the scene, each ring's spin angle (``R_ANGLE``)
    is extrapolated from t with its spin about its axis, so that ring-frame
    azimuths move within the window as the matrix held at t does not.
    Returns the largest overlap / R_b."""
    xb = work[0]
    vb = work[1]
    wb = work[2]
    xc = work[3]
    vc = work[4]
    fb = work[5]
    tb = work[6]
    fc = work[7]
    inv_mb = 1.0 / p[P_MB]
    inv_ib = 1.0 / p[P_IB]
    # cage balls, or the rigid cage in their first two rows (its moment comes scaled by m_c / I_c: model.layout)
    inv_mz = 1.0 / p[P_MZ] if (p[P_CAGE] > 0.5 or p[P_RIGID] > 0.5) else 0.0
    dt = (t_end - tau) / n_sub
    h = 0.5 * dt
    worst = 0.0
    for r in range(2):
        for k in range(6):
            fsum[r, k] = 0.0
    span = t - tau
    for r in range(2):  # velocities, rotation and angular velocity: those at t throughout
        for k in range(3, RING_N):
            rings[r, k] = rings1[r, k]
    for i in range(n_sub):
        kick_drift(h, dt, xb, vb, wb, xc, vc, fb, tb, fc, inv_mb, inv_ib, inv_mz)
        s = t_end if i == n_sub - 1 else tau + (i + 1) * dt
        for r in range(2):
            # Exudyn's velocity-Verlet drift moves the ring linearly from its pose
            # at the previous step to the new one; beyond t, extrapolate at the
            # velocity Exudyn passes (the half-step velocity)
            if s < t and span > 0.0:
                a = (s - tau) / span
                for k in range(3):
                    rings[r, k] = rings0[r, k] + a * (rings1[r, k] - rings0[r, k])
            else:
                for k in range(3):
                    rings[r, k] = rings1[r, k] + (s - t) * rings1[r, 3 + k]
            if p[P_NDEF] > 0.0:
                rings[r, R_ANGLE] = rings1[r, R_ANGLE] + (s - t) * (
                    rings1[r, 8] * rings1[r, 15] + rings1[r, 11] * rings1[r, 16] + rings1[r, 14] * rings1[r, 17])
        w = forces(p, table, xb, vb, wb, xc, vc, rings, hist, hist, dt, hz, fb, tb, fc, fr, glob, diag,
                   cage_load, want and i == n_sub - 1, defect_path, ellipse_path, loss_path)
        accumulate_energy(glob, dt)
        if w > worst or w != w:  # a NaN state is the worst (and stays it): the element stops on it
            worst = w
        for r in range(2):
            for k in range(6):
                fsum[r, k] += fr[r, k]
        kick_drift(h, 0.0, xb, vb, wb, xc, vc, fb, tb, fc, inv_mb, inv_ib, inv_mz)
    for r in range(2):
        for k in range(6):
            fr[r, k] = fsum[r, k] / n_sub
        for k in range(RING_N):
            rings0[r, k] = rings[r, k]
    return worst


@kernel
def fast_step(qs, qs_t, st, n_sub, tau, t, t_end, want, defect_path=True, ellipse_path=True, loss_path=True):
    """Fast mode, one Exudyn evaluation in one compiled call on the element's
    state ``st`` (:class:`ElementState`): ring poses from the object
    coordinates (gathered from the system's ODE2 coordinates ``qs``,
    ``qs_t`` at their system index ``st.index``), ``n_sub`` ball sub-steps from ``tau`` to ``t_end``
    (:func:`advance_balls`; none when ``n_sub`` is 0), the mean ring
    reactions ``fr`` as generalized forces ``out``. Returns the largest
    overlap / R_b."""
    ref = st.ref
    rings = st.rings
    fr = st.fr
    out = st.out
    q = st.q
    q_t = st.q_t
    index = st.index
    for i in range(index.shape[0]):
        q[i] = qs[index[i]]
        q_t[i] = qs_t[index[i]]
    ring_poses_from(q, q_t, ref, st.ring_kind, st.ring_data, rings)
    worst = 0.0
    if n_sub > 0:
        worst = advance_balls(n_sub, tau, t, t_end, st.p, st.table, st.work, st.rings0, rings, st.rings_sub, st.hist,
                              st.hz, fr, st.fsum, st.glob, st.diag, st.cage_load, want, defect_path, ellipse_path,
                              loss_path)
    out[:] = 0.0
    ring_generalized_forces(q, ref, st.ring_kind, st.ring_data, rings, fr, out)
    return worst


#: Entries of the element's signal state (:func:`signal_step`): sample
#: interval [s], end of the current window [s], time of the last evaluation
#: [s] (-inf: none yet), its inner-ring centre velocity (3) [m/s],
#: outer-ring force (3) [N] and inner-ring speed [rad/s], the window's sums
#: (NSIGNAL) and their count.
SIG_INTERVAL, SIG_NEXT, SIG_TPREV, SIG_V, SIG_F, SIG_W, SIG_SUM = 0, 1, 2, 3, 6, 9, 10
SIG_COUNT = SIG_SUM + NSIGNAL
SIG_N = SIG_COUNT + 1


@kernel
def signal_step(t, rings, fr, sig, row):
    """Condition-monitoring signals of the element at a force evaluation at t
    (layout ``SIGNAL_FIELDS``, the same means as the reference engine's).

    When t has advanced past the last evaluation t_p, that evaluation is
    complete: its outer-ring force, its inner-ring speed and its inner-ring
    acceleration (v(t) - v(t_p)) / (t - t_p) join the sums of the window
    (t_k - interval, t_k] that contains t_p; with velocity Verlet, where an
    evaluation sees the half-step velocity, this difference quotient is
    exactly the acceleration the solver gave the ring at t_p (the ring's
    mass and every force on it, not only the bearing's). When t_p closes the
    window, ``row`` gets (t_k, the means) and the function returns True: a
    sample is one evaluation late, with its own time. Evaluations repeated at
    the same t replace the last one."""
    eps = 1e-6 * sig[SIG_INTERVAL]
    tp = sig[SIG_TPREV]
    emitted = False
    if t > tp and tp > -1e300:
        nxt = sig[SIG_NEXT]
        if tp > nxt - sig[SIG_INTERVAL] + eps:
            h = t - tp
            for d in range(3):
                sig[SIG_SUM + d] += sig[SIG_F + d]
                sig[SIG_SUM + 3 + d] += (rings[0, 3 + d] - sig[SIG_V + d]) / h
            sig[SIG_SUM + 6] += sig[SIG_W]
            sig[SIG_COUNT] += 1.0
        if tp >= nxt - eps:
            n = sig[SIG_COUNT]
            row[0] = nxt
            for c in range(NSIGNAL):
                row[1 + c] = sig[SIG_SUM + c] / n if n > 0.0 else np.nan
                sig[SIG_SUM + c] = 0.0
            sig[SIG_COUNT] = 0.0
            sig[SIG_NEXT] = nxt + sig[SIG_INTERVAL]
            emitted = True
    sig[SIG_TPREV] = t
    for d in range(3):
        sig[SIG_V + d] = rings[0, 3 + d]
        sig[SIG_F + d] = fr[1, d]
    sig[SIG_W] = rings[0, 8] * rings[0, 15] + rings[0, 11] * rings[0, 16] + rings[0, 14] * rings[0, 17]
    return emitted


def sample_layout(z):
    """(name, shape) of the parts of a sample row (:func:`sample_row`), in order."""
    return (("glob", (NGLOBAL,)), ("diag", (z, 2, NDIAG)), ("cage_load", (z, 2)), ("xb", (z, 3)), ("vb", (z, 3)),
            ("wb", (z, 3)), ("xc", (z, 3)), ("vc", (z, 3)), ("ring", (6,)))


@kernel
def sample_row(rings, work, glob, diag, cage_load, row):
    """One sample of the element into the flat ``row`` (layout
    :func:`sample_layout`): the diagnostics as they are, and the way the
    reference engine reports its state, in the outer-ring frame (``rings[1]``):
    positions and velocities of balls and cage balls relative to the outer
    ring, ball angular velocities relative to it, the inner ring's
    displacement and velocity."""
    z = work.shape[1]
    k = 0
    for i in range(glob.shape[0]):
        row[k] = glob[i]
        k += 1
    for j in range(z):
        for r in range(2):
            for i in range(diag.shape[2]):
                row[k] = diag[j, r, i]
                k += 1
    for j in range(z):
        for r in range(2):
            row[k] = cage_load[j, r]
            k += 1
    x1 = rings[1, 0:3]
    v1 = rings[1, 3:6]
    w1 = rings[1, 15:18]
    # xb, vb, wb, xc, vc: rows of work 0, 1, 2, 3, 4
    for ix in range(5):
        for j in range(z):
            for c in range(3):
                acc = 0.0
                for m in range(3):
                    if ix == 0 or ix == 3:  # position relative to the outer-ring centre
                        u = work[ix, j, m] - x1[m]
                    elif ix == 2:  # angular velocity relative to the ring's
                        u = work[2, j, m] - w1[m]
                    else:  # velocity relative to the ring point there: v - v1 - w1 x d
                        d0 = work[ix - 1, j, 0] - x1[0]
                        d1 = work[ix - 1, j, 1] - x1[1]
                        d2 = work[ix - 1, j, 2] - x1[2]
                        if m == 0:
                            wxd = w1[1] * d2 - w1[2] * d1
                        elif m == 1:
                            wxd = w1[2] * d0 - w1[0] * d2
                        else:
                            wxd = w1[0] * d1 - w1[1] * d0
                        u = work[ix, j, m] - v1[m] - wxd
                    acc += u * rings[1, 6 + 3 * m + c]
                row[k] = acc
                k += 1
    for c in range(3):
        acc_x = 0.0
        acc_v = 0.0
        for m in range(3):
            acc_x += (rings[0, m] - x1[m]) * rings[1, 6 + 3 * m + c]
            acc_v += (rings[0, 3 + m] - v1[m]) * rings[1, 6 + 3 * m + c]
        row[k + c] = acc_x
        row[k + 3 + c] = acc_v
