"""Array layouts of the compiled bearing model, each defined once.

The kernels take flat float64 arrays; this module names their entries:

* the **parameter vector** ``p`` (:data:`PARAMETERS`, indices ``P_*``): the
  bearing, the lubricant, the model switches and the loads of one scene,
  filled by :func:`exudyn_bearing.model.parameters.scene_parameters`;
* the **ring pose rows** ``rings`` (2, :data:`RING_N`): inner (0) and outer
  (1) ring, columns ``R_*``;
* the **contact history** ``hist`` (Z, :data:`HIST_N`, 3): per ball the
  Cundall-Strack springs of its two contacts and the orientation of the
  ball (rows ``H_*``);
* the **signal rows** (n, :data:`NSIGNAL`) of the condition-monitoring
  signals, columns named in :data:`SIGNAL_FIELDS`, units in :data:`SIGNAL_UNITS`;
* the **contact diagnostics** ``diag`` (Z, 2, :data:`NDIAG`), race 0 inner /
  1 outer, columns ``D_*`` named in :data:`DIAG_FIELDS`, and the **global
  diagnostics** ``glob`` (:data:`NGLOBAL`), named in :data:`GLOBAL_FIELDS`;
  their units are in :data:`DIAG_UNITS` and :data:`GLOBAL_UNITS`.

Codes stored in the parameter vector (integers as floats): friction models
``FRIC_*``, ball / raceway contact laws ``LAW_*``, Hertz levels
(:data:`exudyn_bearing.physics.hertz.METHODS`) and film models
(:data:`exudyn_bearing.physics.ehl.FILM_MODELS`) by their index.

The indices are plain module-level integers, so numba compiles them into the
kernels as constants.
"""
from __future__ import annotations

from typing import NamedTuple

from ..data.traction import N_TRACTION_PARAMS

__all__ = ["ParameterEntry", "PARAMETERS", "N_PARAMS", "RING_N", "DIAG_FIELDS", "DIAG_UNITS", "NDIAG",
           "GLOBAL_FIELDS", "GLOBAL_UNITS", "NGLOBAL", "FRIC_HISTORY", "FRIC_REGULARIZED", "FRIC_NONE",
           "LAW_HERTZ", "LAW_POWER", "describe_parameters", "MAX_DEFECTS", "DEFECT_FIELDS", "DEF_N",
           "DEF_INNER", "DEF_OUTER", "DEF_BALL", "HIST_N", "HZ_N", "SIGNAL_FIELDS", "SIGNAL_UNITS", "NSIGNAL"]


class ParameterEntry(NamedTuple):
    """One entry of the parameter vector."""

    name: str     #: identifier (also the key of ``describe_parameters``)
    unit: str     #: SI unit; "-" dimensionless, "code" an integer code, "switch" 0 or 1
    meaning: str  #: what it is


_ENTRIES: list[ParameterEntry] = []


def _entry(name: str, unit: str, meaning: str) -> int:
    _ENTRIES.append(ParameterEntry(name, unit, meaning))
    return len(_ENTRIES) - 1


# -- geometry ------------------------------------------------------------
P_Z = _entry("n_balls", "-", "number of balls Z")
P_RB = _entry("ball_radius", "m", "ball radius R_b")
P_RCI = _entry("inner_groove_radius", "m", "inner groove (tube) radius R_ci")
P_RCO = _entry("outer_groove_radius", "m", "outer groove (tube) radius R_co")
P_RHO_I = _entry("inner_groove_center_radius", "m", "radius rho_i of the inner tube-centre circle")
P_ZG_I = _entry("inner_groove_center_z", "m", "axial position z_i of the inner tube-centre circle")
P_RHO_O = _entry("outer_groove_center_radius", "m", "radius rho_o of the outer tube-centre circle")
P_ZG_O = _entry("outer_groove_center_z", "m", "axial position z_o of the outer tube-centre circle")
P_RZ = _entry("cage_ball_radius", "m", "cage-ball radius R_z (R_b when the scene has no cage)")
P_RP = _entry("pitch_radius", "m", "pitch radius r_p (centre circle of the cage guide)")
P_RGUIDE = _entry("guide_radius", "m", "tube radius of the cage-ball guide torus, R_z + guide clearance")
# -- material and masses ------------------------------------------------
P_EPRIME = _entry("e_prime", "Pa", "effective modulus E' of ball and race")
P_MB = _entry("ball_mass", "kg", "ball mass m_b")
P_IB = _entry("ball_inertia", "kg m^2", "ball moment of inertia 2/5 m_b R_b^2")
P_MZ = _entry("cage_ball_mass", "kg", "cage-ball mass m_z (1 when the scene has no cage)")
P_MR = _entry("ring_mass", "kg", "translating mass of the inner ring (reference engine)")
P_ALPHA_E = _entry("hysteretic_damping", "s/m", "Hunt-Crossley coefficient alpha_e")
# -- lubricant -----------------------------------------------------------
P_ETA = _entry("viscosity", "Pa s", "dynamic viscosity eta")
P_XI = _entry("pressure_viscosity", "m^2/N", "pressure-viscosity coefficient xi")
P_SIGMA = _entry("composite_roughness", "m", "denominator of Lambda, c sqrt(sigma_1^2 + sigma_2^2)")
P_L1 = _entry("lambda_mixed", "-", "Lambda breakpoint boundary | mixed")
P_L3 = _entry("lambda_full_film", "-", "Lambda breakpoint mixed | full film")
P_MU_B = _entry("mu_boundary", "-", "friction coefficient in boundary lubrication")
P_MU_F = _entry("mu_full_film", "-", "friction coefficient in full-film lubrication")
# -- model switches ------------------------------------------------------
P_HERTZ = _entry("hertz_method", "code", "Hertz fidelity level, index into physics.hertz.METHODS")
P_FILM = _entry("film_model", "code", "film-thickness model, index into physics.ehl.FILM_MODELS")
P_LUB = _entry("lubrication", "switch", "Lambda-switched damping and friction (1) or dry contact (0)")
P_MU_DRY = _entry("mu_dry", "-", "friction coefficient without lubrication")
P_FRIC = _entry("friction_model", "code", "tangential force model FRIC_*")
P_VREG = _entry("regularizing_speed", "m/s", "slip speed below which regularised friction is linear")
P_KT_RATIO = _entry("tangential_stiffness_ratio", "-", "K_t / K_n of the Cundall-Strack spring")
P_CAGE = _entry("cage", "switch", "torus cage (1) or ball / ball contacts (0)")
# -- loads and speed protocol (reference engine) -------------------------
P_FR = _entry("radial_load", "N", "radial load on the inner ring along +x")
P_FA = _entry("axial_load", "N", "axial load on the inner ring along +z")
P_W_MAX = _entry("omega", "rad/s", "inner-ring speed of the steady phase")
P_T_UP = _entry("t_ramp_up", "s", "duration of the start-up ramp")
P_T_STEADY = _entry("t_steady", "s", "duration of the steady phase (1e300: never ends)")
P_T_DOWN = _entry("t_ramp_down", "s", "duration of the slow-down ramp")
P_W_OUTER = _entry("omega_outer", "rad/s", "outer-ring speed of the steady phase (same protocol as omega)")
# -- secondary contacts ----------------------------------------------------
P_K_BZ = _entry("k_ball_cage", "N/m^1.5", "Hertz constant of a ball / cage-ball contact")
P_K_BB = _entry("k_ball_ball", "N/m^1.5", "Hertz constant of a ball / ball contact (no cage)")
P_K_GUIDE = _entry("k_guide", "N/m^1.5", "Hertz constant of a cage-ball / guide contact")
# -- solver ----------------------------------------------------------------
P_DT = _entry("dt", "s", "time step (implicit tangential spring, Cundall-Strack increment)")
P_AXIAL_FREE = _entry("axial_free", "switch", "the inner ring moves axially (1) or not (0)")
P_MAX_OVERLAP = _entry("max_overlap", "-", "overlap / R_b (cage contacts: over the radius of their sphere) above which "
                       "a run stops as runaway")
P_KT_IMPLICIT = _entry("tangential_implicit", "switch", "implicit (1) or explicit (0) Cundall-Strack spring")
P_CAGE_TAU = _entry("cage_damping_step", "s", "step of the backward-Euler damping of the cage contacts "
                    "(cage_damping='implicit': dt; 0: explicit damping)")
# -- peer contact law ------------------------------------------------------
P_LAW = _entry("contact_law", "code", "ball / raceway contact law LAW_*")
P_LAW_K = _entry("power_law_k", "N/m^n", "power-law stiffness k of F = k delta^n + d d(delta)/dt")
P_LAW_N = _entry("power_law_n", "-", "power-law exponent n")
P_LAW_D = _entry("power_law_d", "N s/m", "power-law damping d")
# -- localized defects (data.Defect; physics.defects) ----------------------
P_NDEF = _entry("n_defects", "-", "number of filled defect slots (0: no defect, the kernel skips the defect code)")
#: Most defects a scene can hold (the fixed number of defect slots).
MAX_DEFECTS = 8
#: Entries of one defect slot: (name, unit, meaning); slot k starts at
#: ``P_DEF0 + k * DEF_N``, its entries at the offsets ``DF_*``.
DEFECT_FIELDS = (
    ("race", "code", "surface: DEF_INNER, DEF_OUTER or DEF_BALL"),
    ("position", "rad", "race: azimuth of the spall centre in the ring frame"),
    ("across", "rad", "race: contact angle at which the spall is centred across the groove (free contact angle)"),
    ("half_length", "m", "half the spall length along the rolling direction"),
    ("half_width", "m", "half the spall width across the rolling direction"),
    ("depth", "m", "spall depth"),
    ("edge_radius", "m", "edge radius (0: sharp edges)"),
    ("ball", "-", "ball: index of the defective ball"),
    ("dir_x", "-", "ball: spall centre direction in the ball's body frame (hist rows H_E1, H_E2 at t = 0), x"),
    ("dir_y", "-", "ball: spall centre direction in the ball's body frame, y"),
    ("dir_z", "-", "ball: spall centre direction in the ball's body frame, z"),
)
DF_RACE, DF_POS, DF_ACROSS, DF_HL, DF_HW, DF_DEPTH, DF_EDGE, DF_BALL, DF_DIR = 0, 1, 2, 3, 4, 5, 6, 7, 8
DEF_N = len(DEFECT_FIELDS)
P_DEF0 = len(_ENTRIES)
for _k in range(MAX_DEFECTS):
    for _name, _unit, _meaning in DEFECT_FIELDS:
        _entry(f"defect{_k}_{_name}", _unit, f"defect slot {_k}: {_meaning}")
#: Defect surface codes: the race codes equal the race (ring) indices.
DEF_INNER, DEF_OUTER, DEF_BALL = 0, 1, 2

# -- ellipse traction and ring growth (high-speed dynamics) ---------------
P_TRACTION_LEVEL = _entry("traction_level", "switch", "tangential force: point-contact law (0) or over the Hertz "
                          "ellipse (1)")
P_TRACTION_CODE = _entry("traction_code", "code", "traction model kind, index into data.TRACTION_KINDS")
P_N_STRIPS = _entry("n_strips", "-", "strips of the ellipse integration along the major axis")
P_N_ACROSS = _entry("n_across", "-", "points across each strip")
P_TRACTION_PARAMS = _entry("traction_param_0", "model", "first entry of TractionModel.vector (its units)")
for _k in range(1, N_TRACTION_PARAMS):
    _entry(f"traction_param_{_k}", "model", f"entry {_k} of TractionModel.vector (its units)")
P_RD_I = _entry("deformed_radius_inner", "m", "radius of the pressed inner contact across rolling (Heathcote slip)")
P_RD_O = _entry("deformed_radius_outer", "m", "radius of the pressed outer contact across rolling")
P_GROWTH_I = _entry("growth_inner", "m s^2", "centrifugal growth of the inner groove radius per omega_i^2")
P_GROWTH_O = _entry("growth_outer", "m s^2", "centrifugal growth of the outer groove radius per omega_o^2")
# -- rolling resistance and ball drag as forces (docs/theory/losses.md, "In the dynamic engines") ----
P_ROLLRES = _entry("rolling_resistance", "switch", "rolling-resistance moment pair at every loaded ball / raceway "
                   "contact: elastic hysteresis and, with lubrication, the EHL rolling force (1) or none (0)")
P_ALPHA_H = _entry("hysteresis_loss_factor", "-", "hysteresis loss factor alpha_h of the rolling resistance")
P_DRAG = _entry("ball_drag", "switch", "drag of the oil-air mixture (at rest with the outer ring) on every ball "
                "centre, reaction on the outer ring (1) or none (0)")
P_RHO_MIX = _entry("mixture_density", "kg/m^3", "density of the oil-air mixture of the ball drag")
P_ETA_MIX = _entry("mixture_viscosity", "Pa s", "dynamic viscosity of the oil-air mixture of the ball drag")

# -- rigid cage (docs/theory/cage.md) ------------------------------------------
P_RIGID = _entry("rigid_cage", "switch", "rigid cage body with pockets (1; then cage 0: no cage balls) or none (0)")
P_MC = _entry("cage_mass", "kg", "mass m_c of the rigid cage")
P_IC = _entry("cage_inertia", "kg m^2", "polar moment of inertia I_c of the rigid cage")
P_POCKET_GAP = _entry("pocket_clearance", "m", "radial gap c_p between pocket and ball")
P_POCKET_SHAPE = _entry("pocket_shape", "code", "pocket shape: 0 cylindrical (axis radial), 1 spherical")
P_K_POCKET = _entry("k_pocket", "N/m^1.5", "Hertz constant of a ball / pocket contact")
P_MU_POCKET = _entry("pocket_friction", "-", "Coulomb coefficient mu_c of the ball / pocket contact")
P_POCKET_VREG = _entry("pocket_regularizing_speed", "m/s", "slip speed below which the pocket friction is linear")
P_GUIDANCE = _entry("cage_guidance", "code", "guidance GUIDE_*: balls, inner-ring land, outer-ring land")
P_LAND_R = _entry("land_radius", "m", "radius R of the cage's guiding surface")
P_LAND_C = _entry("land_clearance", "m", "radial clearance c between guiding surface and land")
P_LAND_L = _entry("land_width", "m", "width L of the land film")
P_LAND_ETA = _entry("land_viscosity", "Pa s", "dynamic viscosity of the land film")
P_LAND_EPS = _entry("land_crush_eccentricity", "-", "eccentricity ratio beyond which the land film is crushed "
                    "(1 - composite roughness / c): the land contact's penalty takes over")
P_K_LAND = _entry("k_land", "N/m", "stiffness of the crushed land contact (line contact over the land width)")
P_GX = _entry("gravity_x", "m/s^2", "gravity on the rigid cage, x (the cage's bearing frame, P_CAGE_FRAME)")
P_GY = _entry("gravity_y", "m/s^2", "gravity on the rigid cage, y")
P_GZ = _entry("gravity_z", "m/s^2", "gravity on the rigid cage, z (bearing axis)")
#: The rigid cage's bearing frame: a rotation matrix (row-major, 9 entries) whose columns e1, e2, e3 are the frame's
#: axes in the world, e3 the bearing axis. The cage's pockets, land, spin and gravity (P_GX..P_GZ) are taken in it:
#: the identity in the reference engine (its world is the outer-ring frame), in the Exudyn element the outer ring's
#: frame at t = 0 (solvers/element/kernels.cage_frame).
P_CAGE_FRAME = _entry("cage_frame_0", "-", "rigid cage's bearing frame, row-major rotation matrix entry 0 (columns: "
                      "its axes in the world, the third the bearing axis)")
for _k in range(1, 9):
    _entry(f"cage_frame_{_k}", "-", f"rigid cage's bearing frame, row-major rotation matrix entry {_k}")
P_CAGE_ANGLE0 = _entry("cage_angle_offset", "rad", "Exudyn element, body mode: the rigid cage's angle in its bearing "
                       "frame where its node's turning angle is 0 (solvers/element/kernels.cage_frame; 0 elsewhere)")
P_UNBALANCE = _entry("cage_unbalance", "kg m", "unbalance U of the rigid cage (mass times the offset of its centre of "
                     "mass, along the cage's angle 0)")
P_CAGE_HALF_SECTION = _entry("cage_half_section", "m", "half the radial section of the rigid cage, (R_o - R_i) / 2: a "
                             "ball whose centre moves farther along its pocket's axis has left the cage (the run stops)")
#: :data:`G_WORST` of a step in which a ball left its rigid cage's pocket (the engines stop and say so)
POCKET_ESCAPE = 1e300
P_POCKET_SPACING = _entry("pocket_spacing_error", "rad", "unequal pocket spacing e / r_p: pocket j at the cage angle + "
                          "2 pi j / Z + (e / r_p) sin(2 pi j / Z)")
P_POCKET_FILM = _entry("pocket_film", "switch", "the ball / pocket oil film (1: hydrodynamic and squeeze forces, "
                       "physics/pocket_film.py) or none (0: dry Hertz contact only)")
P_POCKET_ETA = _entry("pocket_viscosity", "Pa s", "dynamic viscosity of the pocket film")
P_POCKET_FILM_RX = _entry("pocket_film_rx", "m", "radius R_x of the pocket film along its entraining direction")
P_POCKET_FILM_HHAT = _entry("pocket_film_h_hat", "-", "isoviscous-rigid film constant H_hat of the pocket film "
                            "(Brewe, Hamrock & Taylor)")
P_POCKET_FILM_FLOOR = _entry("pocket_film_floor", "m", "thinnest pocket film the forces are evaluated at (the "
                             "composite roughness of ball and cage; thinner, the Hertz contact takes over)")

#: All entries of the parameter vector, in index order.
PARAMETERS: tuple[ParameterEntry, ...] = tuple(_ENTRIES)
#: Length of the parameter vector.
N_PARAMS = len(PARAMETERS)

#: Tangential force models: Cundall-Strack spring with Coulomb cap (contact
#: history), regularised Coulomb on the slip velocity (history-free), none.
FRIC_HISTORY, FRIC_REGULARIZED, FRIC_NONE = 0, 1, 2
#: Ball / raceway contact laws: elliptic Hertz with the Lambda-switched
#: lubrication of docs/theory/lubrication.md (default), or the power law k delta^n + d
#: d(delta)/dt with constant mu of Exudyn's ObjectContactSphereTorus (for
#: the peer check against exudyn.machines.CreateBallBearing).
LAW_HERTZ, LAW_POWER = 0, 1
#: Guidance codes of the rigid cage (``P_GUIDANCE``), in the order of ``data.cages.GUIDANCES``.
GUIDE_BALL, GUIDE_INNER, GUIDE_OUTER = 0, 1, 2

# -- ring pose rows ----------------------------------------------------------
#: Columns of a ring pose row (world frame): centre (3) [m], velocity (3)
#: [m/s], rotation matrix row-major (9; the bearing axis is the ring's local
#: z, the third column), angular velocity (3) [rad/s], and the angle [rad]
#: the ring has turned about its axis beyond its rotation matrix: the
#: integrated prescribed spin of a ring whose matrix does not turn (the
#: reference engine's rings, a point-mass ring of the Exudyn element);
#: 0 for a ring whose matrix carries its rotation. Ring-frame azimuths (of
#: race defects) are measured in the matrix's frame minus this angle; only
#: the defect code reads it.
R_POS, R_VEL, R_ROT, R_OMEGA, R_ANGLE = 0, 3, 6, 15, 18
#: Length of a ring pose row.
RING_N = 19

# -- contact history -----------------------------------------------------------
#: Rows of the per-ball contact history ``hist`` (Z, HIST_N, 3), world frame:
#: the Cundall-Strack tangential displacement [m] of the inner (0) and outer
#: (1) contact, then two orthonormal axes e1, e2 of the ball's body frame
#: (unit vectors; e1 = x and e2 = y of the outer-ring frame at t = 0),
#: turned with the ball's angular velocity by the contact kernel when the
#: scene has a ball defect (its only reader). A hist of 2 rows (no body frame)
#: is accepted by the kernel and then ignores ball defects.
H_INNER, H_OUTER, H_E1, H_E2 = 0, 1, 2, 3
HIST_N = 4

# -- per-contact cache ---------------------------------------------------------
#: Columns of the per-contact cache ``hz`` (Z, 2, HZ_N) of the contact kernel: the Hertz
#: constants R_y/R_x, k, F, E and the HD film's ellipticity factor of the last re-evaluation
#: (``HZ_RATIO`` ... ``HZ_FILM_K``), then three anchors of the film's transcendental functions
#: (``model.contact._ln_anchored``, ``_exp_anchored``): 1/U_0 and ln U_0 of the dimensionless
#: speed, 1/W_0 and ln W_0 of the load, E_0 and exp(E_0) of the HD film's exponent; from ``HZ_GEO``
#: on the contact's geometry of the current evaluation, which ``model.contact.forces`` computes for all
#: contacts before their forces (``model.contact._race_geometry``: the ball centre relative to the ring,
#: world (3) and ring frame (2), the ring's rotated flag, the overlap, the local normal (3), cos and sin
#: of the contact angle, the contact radius); then (``HZ_LN_RATIO``, ``HZ_EXP_K``, ``HZ_EXP_FILM``) the
#: anchors of the Hertz constants' re-evaluation at the exact level: 1/a_0 and ln a_0 of R_y/R_x,
#: (ln k)_0 and k_0, and -0.68 k_0 and exp(-0.68 k_0) of the film's ellipticity factor (a re-evaluation
#: takes ln a_r, k and that factor from them to round-off instead of the C library's log and exp).
#: All zero: nothing cached (every entry is re-evaluated
#: at its first use). Every caller allocates all HZ_N columns: the kernel refuses a narrower cache
#: (it returns NaN, which every caller stops on).
HZ_RATIO, HZ_K, HZ_F, HZ_E, HZ_FILM_K, HZ_LN_U, HZ_LN_W, HZ_EXP, HZ_GEO = 0, 1, 2, 3, 4, 5, 7, 9, 11
HZ_LN_RATIO, HZ_EXP_K, HZ_EXP_FILM = 24, 26, 28
#: Width of the per-contact cache ``hz``.
HZ_N = 30

# -- diagnostics ---------------------------------------------------------------
#: Fields of the per-contact diagnostics, in order.
#: ``overlap`` is the overlap the contact law sees (the geometric overlap
#: minus ``defect_drop``, the drop of the contact into a localized defect).
DIAG_FIELDS = ("load", "overlap", "contact_angle", "a", "b", "p_max", "u_r", "h_min",
               "lambda", "regime", "mu", "slip_speed", "srr", "friction_force", "defect_drop", "spin", "roll",
               "dissipation", "spin_moment", "rolling_resistance")
(D_LOAD, D_OVERLAP, D_ANGLE, D_A, D_B, D_PMAX, D_UR, D_HMIN, D_LAMBDA, D_REGIME, D_MU, D_SLIP, D_SRR,
 D_FRICTION, D_DEFECT, D_SPIN, D_ROLL, D_POWER, D_SPIN_MOMENT, D_ROLLRES) = range(len(DIAG_FIELDS))
#: Units of the per-contact diagnostics (regime: 0 boundary, 1 mixed, 2 full film, -1 no contact).
#: ``spin`` and ``roll``: the ball's angular velocity relative to the race
#: along the contact normal and along the in-plane tangent e_y = e_x x n
#: (e_x the rolling direction), their ratio the spin-to-roll ratio;
#: ``dissipation``: frictional power of the contact; ``spin_moment``: the
#: traction moment on the ball about the contact normal (ellipse level);
#: ``rolling_resistance``: power of the contact's rolling-resistance moment pair
#: (hysteresis and EHL rolling; 0 without ``Scenario.rolling_resistance``).
DIAG_UNITS = {"load": "N", "overlap": "m", "contact_angle": "rad", "a": "m", "b": "m", "p_max": "Pa",
              "u_r": "m/s", "h_min": "m", "lambda": "-", "regime": "code", "mu": "-", "slip_speed": "m/s",
              "srr": "-", "friction_force": "N", "defect_drop": "m", "spin": "rad/s", "roll": "rad/s",
              "dissipation": "W", "spin_moment": "N m", "rolling_resistance": "W"}
NDIAG = len(DIAG_FIELDS)
#: Global diagnostics per sample, in order: inner-ring speed, force of the
#: balls on the inner ring and torque about its axis, total frictional power,
#: largest overlap / R_b, force of balls and cage balls on the outer ring and
#: torque about its axis.
#: The energy fields: ``damping_power`` the dissipation of the normal
#: damping of every contact (ball / race, ball / cage ball, cage ball /
#: guide: the damping force times the approach rate); ``drive_power`` the
#: power both rings put into the balls and cage balls (minus the power of
#: the ball and cage-ball forces on the rings, translation and rotation);
#: ``drive_work`` and ``dissipated_work`` their integrals over the run
#: (drive_power; friction_power + damping_power + ehl_rolling_power +
#: hysteresis_power + drag_power), accumulated by the engine
#: at every step; ``kinetic_energy`` of the balls (translation and rotation)
#: and cage balls (translation) in the world frame. Over a window,
#: drive_work = dissipated_work + kinetic_energy change + contact_energy
#: change (the tangential springs' energy is part of friction_power).
#: ``ehl_rolling_power``, ``hysteresis_power``: the dissipation of the
#: rolling-resistance moment pairs, split by their two sources;
#: ``drag_power``: that of the ball drag (0 when switched off; both part of
#: ``dissipated_work``). With the rigid cage: ``pocket_power`` the
#: dissipation of the ball / pocket contacts (friction and normal damping),
#: ``land_power`` that of the land film and contact (minus the power of their
#: forces and moments on cage and ring), both part of ``dissipated_work``;
#: ``land_fx``, ``land_fy`` the force of the land on the cage,
#: ``land_eccentricity`` the cage centre's offset from the land over the land
#: clearance (beyond ``land_crush_eccentricity`` the film is crushed),
#: ``cage_load_power`` the power of gravity and the unbalance force on the
#: rigid cage (part of ``drive_power``); ``contact_energy`` the elastic
#: energy stored in the normal contacts (ball / race, ball / cage ball, cage
#: ball / guide, ball / pocket and the land contact: the integral of the
#: elastic force over the overlap), whose change over a window belongs in the
#: balance beside the kinetic energy's (a transient that unloads the contacts
#: turns it into kinetic energy). The rigid
#: cage's state rides in the cage-ball arrays: ``xc[0]`` its centre,
#: ``xc[1, 0]`` its angle, ``vc[0]`` and ``vc[1, 0]`` their rates, the other
#: rows zero; its kinetic energy counts in ``kinetic_energy``.
#: ``friction_power_inner`` the inner race's part of ``friction_power``; the
#: ``*_work`` fields the integrals of the loss powers by component over the
#: run (the traction per race, the normal damping, the rolling resistance's
#: two parts, the drag, the pockets, the land; their sum is
#: ``dissipated_work``), so that a window's losses by component are exact,
#: not means of samples that may miss a pocket impact.
GLOBAL_FIELDS = ("omega", "ring_fx", "ring_fy", "ring_fz", "ring_torque", "friction_power",
                 "max_overlap_ratio", "outer_fx", "outer_fy", "outer_fz", "outer_torque", "damping_power",
                 "drive_power", "drive_work", "dissipated_work", "kinetic_energy", "ehl_rolling_power",
                 "hysteresis_power", "drag_power", "pocket_power", "land_power", "land_fx", "land_fy", "land_eccentricity",
                 "cage_load_power", "contact_energy", "friction_power_inner", "traction_work_inner",
                 "traction_work_outer", "damping_work", "ehl_rolling_work", "hysteresis_work", "drag_work",
                 "pocket_work", "land_work")
(G_OMEGA, G_RING_FX, G_RING_FY, G_RING_FZ, G_RING_TORQUE, G_POWER, G_WORST, G_OUTER_FX, G_OUTER_FY,
 G_OUTER_FZ, G_OUTER_TORQUE, G_DAMP_POWER, G_DRIVE_POWER, G_DRIVE_WORK, G_DISS_WORK,
 G_KINETIC, G_EHL_POWER, G_HYST_POWER, G_DRAG_POWER, G_POCKET_POWER, G_LAND_POWER, G_LAND_FX,
 G_LAND_FY, G_LAND_ECC, G_CAGE_LOAD_POWER, G_CONTACT_ENERGY, G_POWER_INNER, G_W_TRACTION_INNER,
 G_W_TRACTION_OUTER, G_W_DAMPING, G_W_EHL, G_W_HYST, G_W_DRAG, G_W_POCKET, G_W_LAND) = range(len(GLOBAL_FIELDS))
#: The run's cumulative works in ``glob`` (the engines carry them over a step's trial evaluations together).
ENERGY_WORKS = (G_DRIVE_WORK, G_DISS_WORK, G_W_TRACTION_INNER, G_W_TRACTION_OUTER, G_W_DAMPING, G_W_EHL, G_W_HYST,
                G_W_DRAG, G_W_POCKET, G_W_LAND)
GLOBAL_UNITS = {"omega": "rad/s", "ring_fx": "N", "ring_fy": "N", "ring_fz": "N", "ring_torque": "N m",
                "friction_power": "W", "max_overlap_ratio": "-", "outer_fx": "N", "outer_fy": "N", "outer_fz": "N",
                "outer_torque": "N m", "damping_power": "W", "drive_power": "W", "drive_work": "J",
                "dissipated_work": "J", "kinetic_energy": "J", "ehl_rolling_power": "W", "hysteresis_power": "W",
                "drag_power": "W", "pocket_power": "W", "land_power": "W", "land_fx": "N", "land_fy": "N", "land_eccentricity": "-",
                "cage_load_power": "W", "contact_energy": "J", "friction_power_inner": "W",
                "traction_work_inner": "J", "traction_work_outer": "J", "damping_work": "J", "ehl_rolling_work": "J",
                "hysteresis_work": "J", "drag_work": "J", "pocket_work": "J", "land_work": "J"}
NGLOBAL = len(GLOBAL_FIELDS)

# -- condition-monitoring signals --------------------------------------------
#: Columns of a signal row (``RunRecord.data["signal"]``, times in
#: ``data["signal_t"]``): each the mean over the force evaluations of one
#: sample interval ``Scenario.signal_dt`` (the evaluations at times t with
#: t_k - signal_dt < t <= t_k for the row at t_k): the force of balls and
#: cage balls on the outer ring (the housing force), the acceleration of the
#: inner ring's centre, and the inner ring's speed about its axis; world
#: frame (the outer-ring frame in the reference engine's scene).
SIGNAL_FIELDS = ("outer_fx", "outer_fy", "outer_fz", "inner_ax", "inner_ay", "inner_az", "omega")
SIGNAL_UNITS = {"outer_fx": "N", "outer_fy": "N", "outer_fz": "N", "inner_ax": "m/s^2", "inner_ay": "m/s^2",
                "inner_az": "m/s^2", "omega": "rad/s"}
NSIGNAL = len(SIGNAL_FIELDS)


def describe_parameters(p) -> dict:
    """``{name: (value, unit)}`` of a parameter vector, for reading and debugging."""
    return {e.name: (float(p[i]), e.unit) for i, e in enumerate(PARAMETERS)}
