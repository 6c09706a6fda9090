"""Exudyn items of the bearing element: ball and cage-ball nodes, the one
ObjectGenericODE2 that holds them and the ring nodes, and the arrays the
compiled user functions work on (coordinate layout in :mod:`.kernels`)."""
from __future__ import annotations

import math

import numpy as np

from ...model import layout as L
from ...model.contact import HZ_N, scene_loss_path, scene_paths
from ...model.motion import ring_poses
from . import kernels as EK
from .markers import initial_ring_pose

__all__ = ["ItemsMixin"]


class ItemsMixin:
    """Part of :class:`~.element.BallBearingElement`: item creation."""

    #: The rigid cage's Exudyn node, body and marker (body mode with ``cage="rigid"``), else None.
    cageNode = cageBody = cageMarker = None
    _cage_constraints = ()

    def _add_items(self, mbs, xb, vb, wb, xc, vc, n_cage, fast, show):
        """Add the nodes (balls and cage balls unless ``fast``) and the
        ObjectGenericODE2 with the ring nodes; set up the work arrays.
        Returns (ball nodes, cage nodes, ring nodes, object)."""
        from exudyn.itemInterface import NodeGenericODE2, ObjectGenericODE2, VObjectGenericODE2

        b = self.bearing
        z = b.n_balls
        nodes = []
        mass = []
        mb, ib = b.ball_mass, 0.4 * b.ball_mass * b.ball_radius ** 2
        for j in range(0 if fast else z):
            nodes.append(mbs.AddNode(NodeGenericODE2(
                referenceCoordinates=[*xb[j], 0.0, 0.0, 0.0], initialCoordinates=[0.0] * 6,
                initialCoordinates_t=[*vb[j], *wb[j]], numberOfODE2Coordinates=6)))
            mass += [mb] * 3 + [ib] * 3
        cage_nodes = []
        if n_cage and not fast:
            mz = b.cage_ball_mass
            iz = 0.4 * mz * b.cage_ball_radius ** 2
            for k in range(n_cage):
                cage_nodes.append(mbs.AddNode(NodeGenericODE2(
                    referenceCoordinates=[*xc[k], 0.0, 0.0, 0.0], initialCoordinates=[0.0] * 6,
                    initialCoordinates_t=[*vc[k], 0.0, 0.0, 0.0], numberOfODE2Coordinates=6)))
                mass += [mz] * 3 + [iz] * 3
        self.z, self.n_cage = z, n_cage
        rigid_node = self._add_rigid_cage(mbs, xc, vc, mass) if (self.rigid and not fast) else []
        # ring nodes join the object after the balls (once, if both rings share a node)
        self._ring_kind = np.array([sp[0] for sp in self.rings_spec], np.int64)
        ring_nodes = []
        self._ring_data = np.zeros((2, EK.RD_N))
        n = 0 if fast else 6 * (z + n_cage + len(rigid_node))
        ref = [np.zeros(n)]
        if not fast:
            for j in range(z):
                ref[0][6 * j:6 * j + 3] = xb[j]
            for k in range(n_cage):
                ref[0][6 * (z + k):6 * (z + k) + 3] = xc[k]
            if rigid_node:  # the cage node's reference coordinates: its centre and angles
                ref[0][6 * z:6 * z + 6] = mbs.GetNode(rigid_node[0])["referenceCoordinates"]
        offsets = {}
        for r, (kind, node, local, fixed) in enumerate(self.rings_spec):
            self._ring_data[r, EK.RD_OFF] = -1
            if kind != EK.RING_FIXED:
                if node not in offsets:
                    rc = np.asarray(mbs.GetNode(node)["referenceCoordinates"], float)
                    offsets[node] = n
                    ring_nodes.append(node)
                    ref.append(rc)
                    mass += [0.0] * rc.size
                    n += rc.size
                self._ring_data[r, EK.RD_OFF] = offsets[node]
            self._ring_data[r, EK.RD_LOCAL:EK.RD_LOCAL + 3] = local
            self._ring_data[r, EK.RD_FIXED:EK.RD_FIXED + 12] = fixed
        self.ref = np.concatenate(ref)
        outer_axes = initial_ring_pose(mbs, *self.rings_spec[1])[1]
        self._setup_defects_and_signals(outer_axes, float(self.scenario.dt) * (self.subSteps if fast else 1))
        # the latest time evaluated (-inf: none yet), the last committed time, the last time whose powers entered
        # the energy integrals (body mode), the next sample time, whether the last evaluation sampled (kernels.CLK_*;
        # _t_trial, _t_commit, _t_energy and _next_sample read and write it)
        self._times = np.array([-math.inf, 0.0, 0.0, self.sampleInterval, 0.0])
        # runs: [the Exudyn solver object of the current SolveDynamic, time of its first evaluation (inf: none)]
        self._run = [None, math.inf]
        self._sys = mbs.sys  # Exudyn keeps the running solver and its settings here (storeSolver=True)
        # the Hertz cache with the HD film's ellipticity factor, as the reference engine's (without that column
        # the contact kernel computes the factor at every evaluation)
        self._hz = np.zeros((z, 2, HZ_N))
        self._work = np.zeros((8, z, 3))  # xb, vb, wb, xc, vc, fb, tb, fc
        if fast:  # the balls live here, not in Exudyn
            self._work[0], self._work[1], self._work[2] = xb, vb, wb
            self._work[3, :n_cage], self._work[4, :n_cage] = xc[:n_cage], vc[:n_cage]
            if self.rigid:  # the rigid cage's rows (model.layout): integrated with the balls, as the cage balls
                self._work[3, :2], self._work[4, :2] = xc[:2], vc[:2]
            self._rings0 = ring_poses()
            self._rings_sub = ring_poses()
            self._clock = [math.nan, 0.0, self.sampleInterval, False, 0]
        self._work0 = self._work.copy()  # the initial state a restarted run returns to (fast mode: the balls)
        self._rings = ring_poses()
        self._fr = np.zeros((2, 6))
        self._glob = np.zeros(L.NGLOBAL)
        self._diag = np.zeros((z, 2, L.NDIAG))
        self._cage_load = np.zeros((z, 2))
        self._out = np.zeros(n)
        # samples: times and flat rows filled by compiled code (kernels.sample_row)
        self._sample_t, self._sample_rows = [], []
        self._row = np.zeros(sum(int(np.prod(shape)) for _name, shape in EK.sample_layout(z)))
        self._evaluations = 0
        self._wall = 0.0
        self._speeds = [(r, f) for r, f in enumerate(self.speed) if f is not None]
        self._dt_sub = float(self.scenario.dt)
        self._max_overlap = float(self.params[L.P_MAX_OVERLAP])
        self._status = 0.0
        # node -> number of its coordinates, in the object layout (balls, cage balls, ring nodes)
        self._layout_nodes = [(nd, 6) for nd in nodes + cage_nodes + rigid_node] + [(nd, int(np.size(
            mbs.GetNode(nd)["referenceCoordinates"]))) for nd in ring_nodes]
        vis = VObjectGenericODE2(show=bool(show), graphicsDataUserFunction=self._graphics if show else 0)
        # what of the contact kernel the compiled calls compile (model.contact.forces), as in the reference engine
        self._paths = (*scene_paths(self.params), scene_loss_path(self.params))
        nb = 6 * (z + n_cage + len(rigid_node))
        self._out_uf_index = np.r_[0:6, nb:n] if not fast else np.zeros(0, np.int64)
        self._out_uf = np.zeros(self._out_uf_index.size)
        self._sys_index = np.arange(n, dtype=np.int64)  # the coordinates' system index: set at each run's start
        self._state = EK.element_state(
            self._sys_index, np.zeros(self._sys_index.size), np.zeros(self._sys_index.size), self.ref, self.params,
            self.table, self._ring_kind, self._ring_data, self._hist, self._hist_trial, self._hz, self._work,
            self._rings, self._rings0 if fast else ring_poses(), self._rings_sub if fast else ring_poses(), self._fr,
            np.zeros((2, 6)), self._glob, self._diag, self._cage_load, self._out, self._out_uf_index, self._out_uf, self._times)
        if fast:
            self._force_uf_fast = self._make_fast_uf()
            obj = mbs.AddObject(ObjectGenericODE2(nodeNumbers=ring_nodes, massMatrix=np.diag(mass),
                                                  forceUserFunction=self._force_uf_fast, visualization=vis))
            self._ball_object = None
            return nodes, cage_nodes, ring_nodes, obj
        # body mode: Exudyn converts the coordinates of a user function's object to Python lists and its
        # returned forces back, per coordinate (about 0.1 us each, validation/performance/profile_element.py); the user
        # function's object holds only the first ball and the ring nodes, and the user function reads all
        # coordinates from the system at once and hands the other balls' forces to the force vector of a
        # second object, evaluated after it (the objects' forces are evaluated in the order of their numbers)
        self._out_balls = self._out[6:nb]
        self._force_uf = self._make_body_uf()
        obj = mbs.AddObject(ObjectGenericODE2(nodeNumbers=nodes[:1] + ring_nodes,
                                              massMatrix=np.diag(np.array(mass)[self._out_uf_index]),
                                              forceUserFunction=self._force_uf, visualization=vis))
        self._ball_object = mbs.AddObject(ObjectGenericODE2(
            nodeNumbers=nodes[1:] + cage_nodes + rigid_node, massMatrix=np.diag(mass[6:nb]),
            forceVector=np.zeros(nb - 6),
            visualization=VObjectGenericODE2(show=False)))
        return nodes, cage_nodes, ring_nodes, obj

    def _add_rigid_cage(self, mbs, xc, vc, mass):
        """Body mode with the rigid cage: the cage as an Exudyn rigid body (``cageNode``, ``cageBody``,
        ``cageMarker``; docs/theory/dynamics.md#the-exudyn-element). A NodeRigidBodyRxyz (the element's
        explicit solvers refuse Euler parameters; Tait-Bryan angles have no singularity at the held tilts)
        with an ObjectRigidBody of the cage's mass m_c and inertia (I_c about the axis, the thin ring's
        I_c / 2 + m_c w^2 / 12 about the diameters, which the held tilts never use), its tilts held by two
        CoordinateConstraints to a ground node (Exudyn's explicit solvers eliminate such constraints): the four
        degrees of freedom of the reference engine's cage. Its angles at the cage angle 0 and the one that turns
        it about the bearing axis (the third, about its local z, or the first, about its local x, for the world
        x axis) are :func:`~.kernels.cage_frame`'s and :func:`~.kernels.cage_spin`'s; the other two are held,
        with I_c about the turning axis. The node also joins the element's ball object with zero mass there, so
        that its coordinates and the cage's force and moment from the contact kernel take the path of the
        balls'. Appends its six zero masses to ``mass``; returns [node]."""
        from exudyn.itemInterface import (CoordinateConstraint, MarkerBodyRigid, MarkerNodeCoordinate,
                                          NodePointGround, NodeRigidBodyRxyz, ObjectRigidBody)

        p = self.params
        mc, ic = float(p[L.P_MC]), float(p[L.P_IC])
        it = 0.5 * ic + mc * self._cage_geometry.width ** 2 / 12.0
        k, sign = EK.cage_spin(float(self.cageFrame[0, 2]))
        angles, rates, inertia = list(self._cage_angles), [0.0] * 3, [it, it, it]
        angles[k - 3] = sign * (float(xc[1, 0]) - self._cage_offset)
        rates[k - 3] = sign * float(vc[1, 0])
        inertia[k - 3] = ic
        node = mbs.AddNode(NodeRigidBodyRxyz(referenceCoordinates=[*xc[0], *angles], initialCoordinates=[0.0] * 6,
                                             initialVelocities=[*vc[0], *rates]))
        self.cageNode = node
        self.cageBody = mbs.AddObject(ObjectRigidBody(mass=mc, inertia=[*inertia, 0.0, 0.0, 0.0], nodeNumber=node))
        self.cageMarker = mbs.AddMarker(MarkerBodyRigid(bodyNumber=self.cageBody, localPosition=[0.0, 0.0, 0.0]))
        ground = mbs.AddNode(NodePointGround())
        m_ground = mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=ground, coordinate=0))
        self._cage_constraints = [mbs.AddObject(CoordinateConstraint(markerNumbers=[
            m_ground, mbs.AddMarker(MarkerNodeCoordinate(nodeNumber=node, coordinate=c))]))
            for c in (3, 4, 5) if c != k]
        mass += [0.0] * 6
        return [node]
