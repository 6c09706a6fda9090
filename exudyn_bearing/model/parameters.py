"""The compiled bearing model's inputs: a bearing, a lubricant and a
scenario's model switches and loads turned into the parameter vector of
:mod:`exudyn_bearing.model.layout`."""
from __future__ import annotations

import math

import numpy as np

from ..data import BallBearing, InputError, Lubricant, get_traction_model
from ..data.cages import GUIDANCES, POCKET_SHAPES
from ..data.traction import regularized
from ..physics import hertz
from ..physics.contact_slip import deformed_contact_radius
from ..physics.ehl import film_model_code
from ..physics.hertz import material_reduced_modulus
from ..physics.losses import OIL_DENSITY, mixture_density, mixture_viscosity
from ..physics.pocket_film import isoviscous_rigid_film_constant, pocket_film_radii
from . import layout as L
from .initial_state import ring_mass_estimate
from .operating_geometry import operating_geometry
from .scenario import FRICTION_MODELS, Scenario, ellipse_rolling_floor, resolve_cage

__all__ = ["scene_parameters", "fill_defects", "traction_vector", "dynamic_traction_model"]


def scene_parameters(bearing: BallBearing, scenario: Scenario, lubricant: Lubricant) -> np.ndarray:
    """Kernel parameter vector (layout ``kernels.P_*``) of a bearing, a
    scenario's model switches and loads, and a lubricant; shared by the
    reference engine and the Exudyn element."""
    b, s, lub = bearing, resolve_cage(scenario, bearing), lubricant
    p = np.zeros(L.N_PARAMS)
    em = material_reduced_modulus(b.material)
    rho_i, z_i = b.inner_groove_center
    rho_o, z_o = b.outer_groove_center
    cage = s.cage == "torus" and b.has_cage
    rz = b.cage_ball_radius if cage else b.ball_radius
    p[L.P_Z] = b.n_balls
    p[L.P_RB] = b.ball_radius
    p[L.P_RCI] = b.inner_groove_radius
    p[L.P_RCO] = b.outer_groove_radius
    p[L.P_RHO_I], p[L.P_ZG_I] = rho_i, z_i
    p[L.P_RHO_O], p[L.P_ZG_O] = rho_o, z_o
    p[L.P_RZ] = rz
    p[L.P_RP] = b.pitch_radius
    p[L.P_RGUIDE] = rz + s.guide_clearance
    p[L.P_EPRIME] = em
    p[L.P_MB] = b.ball_mass
    p[L.P_IB] = 0.4 * b.ball_mass * b.ball_radius ** 2
    p[L.P_MZ] = b.cage_ball_mass if cage else 1.0  # the rigid cage's m_c: _set_rigid_cage
    p[L.P_MR] = s.ring_mass if s.ring_mass is not None else ring_mass_estimate(b)
    p[L.P_ALPHA_E] = b.material.hysteretic_damping
    p[L.P_ETA] = lub.viscosity
    p[L.P_XI] = lub.pressure_viscosity
    p[L.P_SIGMA] = lub.composite_roughness
    p[L.P_L1] = lub.lambda_mixed
    p[L.P_L3] = lub.lambda_full_film
    p[L.P_MU_B] = lub.mu_boundary
    p[L.P_MU_F] = lub.mu_full_film
    p[L.P_HERTZ] = hertz.method_code(s.hertz)
    p[L.P_FILM] = film_model_code(s.film)
    p[L.P_LUB] = 1.0 if s.lubrication else 0.0
    p[L.P_MU_DRY] = s.mu_dry
    p[L.P_FRIC] = FRICTION_MODELS.index(s.friction)
    # the ellipse level's least rolling speed; the point level's regularised-Coulomb slip speed
    p[L.P_VREG] = ellipse_rolling_floor(b, s) if s.traction_level == "ellipse" else s.regularizing_speed
    p[L.P_KT_RATIO] = s.tangential_stiffness_ratio
    p[L.P_CAGE] = 1.0 if cage else 0.0
    p[L.P_FR] = s.Fr
    p[L.P_FA] = s.Fa
    p[L.P_W_MAX] = s.omega
    p[L.P_W_OUTER] = s.omega_outer
    p[L.P_T_UP] = s.t_ramp_up
    p[L.P_T_STEADY] = s.t_steady if math.isfinite(s.t_steady) else 1e300
    p[L.P_T_DOWN] = s.t_ramp_down
    p[L.P_K_BZ] = float(hertz.sphere_sphere_stiffness(b.ball_radius, rz, em))
    p[L.P_K_BB] = float(hertz.sphere_sphere_stiffness(b.ball_radius, b.ball_radius, em))
    p[L.P_K_GUIDE] = 2.0 / 3.0 * em * math.sqrt(rz)
    p[L.P_DT] = s.dt
    p[L.P_AXIAL_FREE] = 1.0
    p[L.P_MAX_OVERLAP] = 0.05
    p[L.P_KT_IMPLICIT] = 1.0 if s.tangential == "implicit" else 0.0
    p[L.P_CAGE_TAU] = s.dt if s.cage_damping == "implicit" else 0.0
    p[L.P_LAW] = L.LAW_POWER if s.contact_law == "power" else L.LAW_HERTZ
    p[L.P_LAW_K], p[L.P_LAW_N], p[L.P_LAW_D] = (float(x) for x in s.power_law)
    _set_traction(p, b, s)
    _set_losses(p, s, lub)
    _set_operating_geometry(p, b, s)
    fill_defects(p, b, s.defects)
    if s.cage == "rigid":
        _set_rigid_cage(p, b, s, lub)
    return p


def _set_rigid_cage(p, b, s, lub):
    """The rigid cage's entries (docs/theory/cage.md): mass and inertia, pocket and land; its geometry
    ``s.rigid_cage`` or the bearing's estimated cage. The cage balls' mass entry P_MZ becomes m_c (the
    integrators' common 1/m_c of the cage rows)."""
    rc = s.rigid_cage_of(b)
    rc.check_fits(b)
    mc, ic = rc.mass(b), rc.polar_inertia(b)
    p[L.P_RIGID] = 1.0
    p[L.P_MC] = mc
    p[L.P_MZ] = mc
    p[L.P_IC] = ic
    p[L.P_POCKET_GAP] = rc.pocket_clearance
    p[L.P_POCKET_SHAPE] = POCKET_SHAPES.index(rc.pocket_shape)
    p[L.P_POCKET_SPACING] = rc.pocket_spacing_error / b.pitch_radius
    p[L.P_CAGE_HALF_SECTION] = 0.5 * (rc.outer_radius - rc.inner_radius)
    e_pocket = hertz.reduced_modulus(b.material.youngs_modulus, b.material.poisson_ratio,
                                     rc.material.youngs_modulus, rc.material.poisson_ratio)
    p[L.P_K_POCKET] = float(hertz.ball_in_pocket_stiffness(b.ball_radius, rc.pocket_clearance,
                                                            rc.pocket_shape == "cylindrical", float(e_pocket), s.hertz))
    p[L.P_MU_POCKET] = rc.pocket_friction
    p[L.P_POCKET_VREG] = s.regularizing_speed
    if s.pocket_film:  # the ball / pocket oil film (physics/pocket_film.py)
        cylindrical = rc.pocket_shape == "cylindrical"
        r_x, alpha_r = pocket_film_radii(b.ball_radius, rc.pocket_clearance, cylindrical)
        p[L.P_POCKET_FILM] = 1.0
        p[L.P_POCKET_ETA] = lub.viscosity
        p[L.P_POCKET_FILM_RX] = r_x
        p[L.P_POCKET_FILM_HHAT] = float(isoviscous_rigid_film_constant(alpha_r))
        p[L.P_POCKET_FILM_FLOOR] = lub.composite_roughness
    p[L.P_GUIDANCE] = GUIDANCES.index(rc.guidance)
    p[L.P_GX], p[L.P_GY], p[L.P_GZ] = s.gravity
    p[L.P_CAGE_FRAME:L.P_CAGE_FRAME + 9] = np.eye(3).ravel()  # the bearing axis the world z (the element sets its own)
    p[L.P_UNBALANCE] = rc.unbalance
    if rc.guidance != "ball":
        p[L.P_LAND_R] = rc.guide_radius
        p[L.P_LAND_C] = rc.land_clearance
        p[L.P_LAND_L] = rc.land_width
        p[L.P_LAND_ETA] = lub.viscosity
        p[L.P_LAND_EPS] = max(0.5, 1.0 - lub.composite_roughness / rc.land_clearance)
        # the crushed land: a line contact over the land width, k ~ (pi/4) E' L (Johnson, Contact Mechanics,
        # ch. 5: the approach of a line contact grows about linearly with its load per length)
        p[L.P_K_LAND] = 0.25 * math.pi * float(e_pocket) * rc.land_width


def dynamic_traction_model(scenario: Scenario):
    """The scenario's traction model as the dynamic engines use it: a
    Coulomb-type law (``constant``, ``lambda``) without its own
    regularisation gets ``scenario.traction_regularizing_srr`` (a
    discontinuous law has no stable explicit step); others unchanged."""
    return regularized(get_traction_model(scenario.traction), scenario.traction_regularizing_srr)


def traction_vector(scenario: Scenario) -> np.ndarray:
    """Parameter vector of :func:`dynamic_traction_model`."""
    return np.array(dynamic_traction_model(scenario).vector, float)


def _set_traction(p, b, s):
    """Ellipse traction level: model code and parameters, strip counts, the
    pressed contact radii of the curvature-induced slip."""
    p[L.P_TRACTION_LEVEL] = 1.0 if s.traction_level == "ellipse" else 0.0
    p[L.P_TRACTION_CODE] = dynamic_traction_model(s).code
    p[L.P_N_STRIPS] = s.n_strips
    p[L.P_N_ACROSS] = s.n_across
    vec = traction_vector(s)
    p[L.P_TRACTION_PARAMS:L.P_TRACTION_PARAMS + vec.size] = vec
    p[L.P_RD_I] = float(deformed_contact_radius(p[L.P_RB], p[L.P_RCI]))
    p[L.P_RD_O] = float(deformed_contact_radius(p[L.P_RB], p[L.P_RCO]))


def _set_losses(p, s, lub):
    """Rolling resistance and ball drag switches (docs/theory/losses.md): the hysteresis loss factor,
    the oil-air mixture's density and viscosity (:func:`~exudyn_bearing.physics.losses.mixture_density`,
    :func:`~exudyn_bearing.physics.losses.mixture_viscosity`: the quasi-static losses' relations, oil of
    density :data:`~exudyn_bearing.physics.losses.OIL_DENSITY` and the lubricant's viscosity)."""
    p[L.P_ROLLRES] = 1.0 if s.rolling_resistance else 0.0
    p[L.P_ALPHA_H] = s.hysteresis_loss_factor
    p[L.P_DRAG] = 1.0 if s.ball_drag else 0.0
    p[L.P_RHO_MIX] = mixture_density(s.oil_volume_fraction, OIL_DENSITY)
    p[L.P_ETA_MIX] = mixture_viscosity(s.oil_volume_fraction, lub.viscosity)


def _set_operating_geometry(p, b, s):
    """Thermal growth of grooves and balls at the scenario's temperatures
    (fixed for the run) and the centrifugal growth coefficients (the groove
    radius grows by coefficient x omega^2 of its ring during the run), from
    :func:`~.operating_geometry.operating_geometry`; nothing changes without
    ``ring_growth`` and ``temperatures``."""
    if s.temperatures:
        g = operating_geometry(b, temperatures=s.temperatures)
        p[L.P_RB], p[L.P_RCI], p[L.P_RCO] = g.r_b, g.r_ci, g.r_co
        p[L.P_RHO_I], p[L.P_ZG_I], p[L.P_RHO_O], p[L.P_ZG_O] = g.rho_i, g.z_i, g.rho_o, g.z_o
        p[L.P_RD_I] = float(deformed_contact_radius(g.r_b, g.r_ci))
        p[L.P_RD_O] = float(deformed_contact_radius(g.r_b, g.r_co))
    if s.ring_growth:
        # u(omega) = u(1 rad/s) omega^2 for a rotating disc without a fit
        p[L.P_GROWTH_I] = operating_geometry(b, omega_inner=1.0).inner_ring_growth
        p[L.P_GROWTH_O] = operating_geometry(b, omega_outer=1.0).outer_ring_growth



def fill_defects(p: np.ndarray, bearing: BallBearing, defects) -> None:
    """Defect slots of the parameter vector (layout ``P_DEF0``, ``DF_*``):
    each :class:`~exudyn_bearing.data.Defect` checked against the bearing.

    A race spall is centred across the groove on the free contact angle. A
    ball spall gets its direction in the ball's body frame, which is the
    outer-ring frame at t = 0 (layout ``H_E1``, ``H_E2``): on the rolling
    circle of ball j (azimuth psi_j = 2 pi j / Z, the initial state's),
    cos(position) u_o + sin(position) e_psi, with u_o the direction of the
    outer contact at the free contact angle alpha_0, (cos alpha_0 e_r, sin
    alpha_0) in (r, z), and e_psi the orbital direction."""
    defects = tuple(defects)
    if len(defects) > L.MAX_DEFECTS:
        raise InputError(f"defects: at most {L.MAX_DEFECTS} defects per scene, got {len(defects)}")
    p[L.P_NDEF] = len(defects)
    a0 = bearing.free_contact_angle
    for k, d in enumerate(defects):
        d.check(bearing)
        base = L.P_DEF0 + k * L.DEF_N
        p[base + L.DF_RACE] = {"inner": L.DEF_INNER, "outer": L.DEF_OUTER, "ball": L.DEF_BALL}[d.race]
        p[base + L.DF_POS] = d.position
        p[base + L.DF_ACROSS] = a0
        p[base + L.DF_HL] = d.half_length
        p[base + L.DF_HW] = d.half_width
        p[base + L.DF_DEPTH] = d.depth
        p[base + L.DF_EDGE] = d.edge_radius
        p[base + L.DF_BALL] = d.ball
        if d.race == "ball":
            psi = 2.0 * math.pi * d.ball / bearing.n_balls
            u_o = np.array([math.cos(a0) * math.cos(psi), math.cos(a0) * math.sin(psi), math.sin(a0)])
            e_psi = np.array([-math.sin(psi), math.cos(psi), 0.0])
            p[base + L.DF_DIR:base + L.DF_DIR + 3] = math.cos(d.position) * u_o + math.sin(d.position) * e_psi
