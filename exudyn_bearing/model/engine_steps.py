"""Step helpers shared by the dynamic engines' compiled loops (the reference engine's velocity Verlet and RK4,
the reduced engine): the rings' poses and the inner ring's force in the reference scene, the copy of a state into the
sample buffers, and the finiteness checks."""
from __future__ import annotations

import math

from .._jit import kernel
from .layout import P_AXIAL_FREE, P_FA, P_FR, P_NDEF, P_T_DOWN, P_T_STEADY, P_T_UP, P_W_MAX, P_W_OUTER, R_ANGLE
from .motion import omega_profile, spin_angle

__all__ = ["set_inner_ring", "inner_ring_force", "store_sample", "finite", "finite_ring"]


@kernel(inline="always")
def set_inner_ring(t, p, ring, rings, defect_path):
    """The reference scene's rings at time t (both dynamic engines): the inner ring translates (state
    ``ring``: position, velocity) and spins at the protocol speed omega(t); the outer ring stays in place
    and spins about the bearing axis (z) at the protocol's outer speed (``P_W_OUTER`` times the same ramp
    factor, 0 by default). The kernel takes either ring's surface velocity from its angular velocity
    (``model.contact._surface_kinematics``, the outer contacts' slip, traction, spin and entrainment), its
    centrifugal growth from its spin and the drive power from both rings' torques
    (``model.contact._drive_power``). The rotation matrices stay the identity; with defects in the scene the
    spin angles (the protocol's integrals) go to ``R_ANGLE`` (compiled only with a ``defect_path``,
    :func:`~exudyn_bearing.model.contact.forces`). The name keeps the engines' call sites; the outer
    ring's spin is set here, in one place for both engines."""
    for d in range(6):
        rings[0, d] = ring[d]
    rings[0, 17] = omega_profile(t, p[P_W_MAX], p[P_T_UP], p[P_T_STEADY], p[P_T_DOWN])
    rings[1, 17] = omega_profile(t, p[P_W_OUTER], p[P_T_UP], p[P_T_STEADY], p[P_T_DOWN])
    if defect_path is not None and p[P_NDEF] > 0.0:
        rings[0, R_ANGLE] = spin_angle(t, p[P_W_MAX], p[P_T_UP], p[P_T_STEADY], p[P_T_DOWN])
        rings[1, R_ANGLE] = spin_angle(t, p[P_W_OUTER], p[P_T_UP], p[P_T_STEADY], p[P_T_DOWN])


@kernel(inline="always")
def inner_ring_force(p, fr, fring):
    """Force that accelerates the inner ring: applied load plus the ball reactions."""
    fring[0] = p[P_FR] + fr[0, 0]
    fring[1] = fr[0, 1]
    fring[2] = (p[P_FA] + fr[0, 2]) if p[P_AXIAL_FREE] > 0.5 else 0.0


@kernel(inline="always")
def store_sample(k, t, glob, diag, cage_load, xb, vb, wb, xc, vc, ring,
                 s_t, s_glob, s_diag, s_cage, s_xb, s_vb, s_wb, s_xc, s_vc, s_ring):
    """Copy the state and diagnostics into row k of the sample buffers
    (element by element: numba's broadcasting row assignment compiled for
    about 10 s of a cold start)."""
    s_t[k] = t
    for i in range(glob.shape[0]):
        s_glob[k, i] = glob[i]
    for i in range(ring.shape[0]):
        s_ring[k, i] = ring[i]
    for j in range(xb.shape[0]):
        for r in range(diag.shape[1]):
            for i in range(diag.shape[2]):
                s_diag[k, j, r, i] = diag[j, r, i]
            s_cage[k, j, r] = cage_load[j, r]
        for d in range(3):
            s_xb[k, j, d] = xb[j, d]
            s_vb[k, j, d] = vb[j, d]
            s_wb[k, j, d] = wb[j, d]
            s_xc[k, j, d] = xc[j, d]
            s_vc[k, j, d] = vc[j, d]


@kernel(no_runtime=True, internal=True)
def finite(a):
    """True when every entry of the 2-D array ``a`` is finite (a loop: numba's
    np.all(np.isfinite(...)) compiled for about 0.6 s of a cold start)."""
    for i in range(a.shape[0]):
        for k in range(a.shape[1]):
            if not math.isfinite(a[i, k]):
                return False
    return True


@kernel(inline="always")
def finite_ring(ring):
    """True when the ring state (6,) is finite (the 2-D check on a reshaped view made the integrator
    need numba's memory runtime for the view)."""
    for d in range(ring.shape[0]):
        if not math.isfinite(ring[d]):
            return False
    return True
