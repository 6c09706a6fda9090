"""``solve_pair``: two identical angular-contact bearings on one shaft (duplex pairs DB, DF, DT).

A layer on top of the single-bearing solver :func:`~.solve.solve_quasistatic`: the shaft (both inner
rings, one rigid body) has five DOFs u = (delta_x, delta_y, delta_a, tilt_x, tilt_y) at the pair's
centre, where the loads act; both outer rings sit in one rigid housing. Bearing k sits with its ball-set
plane at z_k on the shaft axis; its inner ring is held (``fixed=``, all five DOFs) at the pose the shaft
gives it in the bearing's own frame, T_k u + o_k, and the single-bearing solver returns the reactions R_k
(the load the shaft transmits to the bearing) and its 5x5 stiffness K_k = dR_k/du_k. The shaft is in
equilibrium when sum_k T_k^T R_k = F (the loads); Newton's method with the pair's stiffness
K = sum_k T_k^T K_k T_k (virtual work: T_k^T maps the bearing's generalized force to the shaft's).

Frames. A small rotation theta = (tilt_x, tilt_y) moves the ball-set centre of bearing k to
(delta_x + tilt_y z_k, delta_y - tilt_x z_k, delta_a). A bearing turned round (the second bearing of a
DB or DF pair) is described in a frame rotated by pi about x: (x, y, z) -> (x, -y, -z), which maps a
displacement and a rotation alike, (u_x, u_y, u_z) -> (u_x, -u_y, -u_z), and turns the ring speeds to
-omega (a proper rotation, so that the solver's right-handed azimuth and speeds stay valid). Its axial
load along its own +z is then the shaft's -z load.

Arrangements (Harris & Kotzalas [1]_, duplex bearings; SKF's catalogue [2]_): DB (back-to-back): the
contact lines diverge towards the outside, pressure centres outside the pair, effective spacing
L + 2 e; DF (face-to-face): they converge, pressure centres inside, L - 2 e; DT (tandem): both bearings
face the same way and carry axial load in one direction only, spacing L. Here L is the distance between
the two ball-set planes (``spacing``) and e = |z_pc| the distance of a bearing's pressure centre (where its
contact line through the groove centres meets the axis) from its ball-set plane, about
(d_m / 2) tan(alpha) (:func:`pressure_centre_offset`).
The single-bearing solver's radial / tilt coupling K_x,tilt_y = -k_r z_pc already carries e, so the
arrangement follows from where each bearing sits and which way it faces; no other term distinguishes DB
from DF.

Preload (DB, DF): a fixed axial interference between the two inner rings, set at rest without fit or
temperatures (catalogues state the preload of a set before mounting [2]_): each bearing's inner ring is
pushed along its own +z by d from the centred position. Given as a force F_0 [N], d is the single
bearing's axial displacement under F_0 (solve_quasistatic at rest); given as ("displacement", delta) [m],
the total interference of the set, d = a_0 + delta/2 with a_0 the axial position where the balls first
touch both grooves (zero for a bearing without clearance). At speed, with a fit or with temperatures the
position preload holds and the contact forces change. A tandem pair takes no preload of its own.

Lift-off (Harris & Kotzalas [1]_): with the Hertz law Q ~ delta^(3/2) and a fixed contact angle, a DB / DF
pair preloaded to F_0 per bearing under an axial load F_a moves by x: F_1 = F_0 (1 + x/d')^1.5,
F_2 = F_0 (1 - x/d')^1.5 (d' the preload deflection), F_1 - F_2 = F_a; the second bearing unloads at
x = d', where F_a = F_1 = 2^1.5 F_0 = 2.83 F_0. The contact angle grows with the load, so the computed
lift-off load (bearing 1 at twice its preload deflection) differs by a few per cent:
docs/theory/pairs.md.

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., CRC Press, 2006 (Essential
   Concepts: duplex bearings and preloading; Advanced Concepts: load distribution of bearing sets).
.. [2] SKF, Rolling bearings (catalogue PUB BU/P1 17000), single row angular contact ball bearings:
   bearings for universal matching, arrangements and preload classes GA, GB, GC.
"""
from __future__ import annotations

import math
import time
from dataclasses import dataclass, field

import numpy as np

from ...data import InputError, load_bearing
from ...data.errors import check_finite, check_nonnegative, check_positive
from ...model.operating_geometry import operating_geometry
from ...physics.load_distribution import check_axial_load
from .inertia import check_ball_inertia
from .ring import DOF_NAMES
from .solve import axial_load_as_fa, solve_quasistatic

__all__ = ["ARRANGEMENTS", "PAIR_UNITS", "PRELOAD_CLASSES", "PairSolution", "pressure_centre_offset", "solve_pair"]

ARRANGEMENTS = ("DB", "DF", "DT")
#: Manufacturer's preload classes: refused (no cited values are held; see :func:`_preload_offset`).
PRELOAD_CLASSES = ("light", "medium", "heavy")
_LOAD_NAMES = ("Fr", "Fy", "Fa", "Mx", "My")
#: Rating lives combined into the pair's system life (:meth:`PairSolution.rating`).
SYSTEM_LIFE_KEYS = ("L10", "L10h", "L10m", "L10r", "L10mr", "L10r_speed", "L10mr_speed")
#: Largest relative residual of the shaft equilibrium (scaled loads) that counts as converged.
_TOL = 1e-9
_MAX_IT = 60

PAIR_UNITS = {
    "arrangement": "DB back-to-back, DF face-to-face, DT tandem",
    "spacing": "m (distance between the two ball-set planes)",
    "pressure_centre_offset": "m (pressure centre from a bearing's ball-set plane, at the free contact angle)",
    "pressure_centre_spacing": "m (distance between the two pressure centres; DF negative when they cross)",
    "preload": "N (axial force per bearing at rest, unloaded set)",
    "preload_displacement": "m (axial interference of the set at rest: the sum of both bearings' deflections)",
    "shaft_displacement": "m, m, m, rad, rad (delta_x, delta_y, delta_a, tilt_x, tilt_y of the shaft at the "
                          "pair's centre)",
    "stiffness": "N/m, N/rad, N m/m, N m/rad (pair, shaft DOFs at the pair's centre; NaN where a DOF is held "
                 "without spacing)",
    "position": "m (ball-set plane on the shaft axis from the pair's centre)",
    "Fr": "N (radial load the bearing carries)", "Fa": "N (axial load the bearing carries, along its own "
                                                       "loaded direction)",
    "loads_global": "N, N, N, N m, N m (force the bearing exerts on the shaft, negated: the load it carries, "
                    "in the shaft frame, moments about its ball-set plane)",
    "unloaded": "no ball touches the inner race: the bearing carries no load (lift-off)",
}


def pressure_centre_offset(bearing) -> float:
    """Signed axial position z_pc [m] of the pressure centre of a bearing in its own frame: where the line
    through its groove centres (the contact line at the free contact angle, through the ball centre) meets
    the axis, z_pc = z_o - rho_o (z_i - z_o)/(rho_i - rho_o); magnitude r tan(alpha) (Harris & Kotzalas,
    duplex bearings). InputError for a bearing with both groove centres in one radial plane (deep groove)."""
    b = load_bearing(bearing)
    rho_i, z_i = b.inner_groove_center
    rho_o, z_o = b.outer_groove_center
    if abs(z_i - z_o) < 1e-15 or rho_i == rho_o:
        raise InputError(f"bearing: {b.name} has no pressure centre off its ball-set plane (free contact angle 0)")
    return z_o - rho_o * (z_i - z_o) / (rho_i - rho_o)


def _touch_position(b) -> float:
    """Axial position a_0 [m] of the inner ring (rings concentric, at rest, rigid) where the balls first
    touch both grooves on the bearing's loaded side (+z); InputError when the bearing has no axial play
    (negative clearance)."""
    g = operating_geometry(b, 0.0, 0.0, False, 0.0, None)
    a, dr = g.groove_distance, g.rho_i - g.rho_o
    if abs(dr) > a:
        raise InputError(f"preload: {b.name} has an interference of its own (diametral clearance "
                         f"{b.diametral_clearance:g} m): give the preload as a force")
    return math.sqrt(a * a - dr * dr) - (g.z_i - g.z_o)


#: A bearing turned round: its frame rotated by pi about x, (x, y, z) -> (x, -y, -z) (both ways).
_TURN = np.array([1.0, -1.0, -1.0, 1.0, -1.0])


def _transform(z_k, turned):
    """T (5, 5): shaft u at the pair's centre -> the bearing's inner-ring pose in its own frame."""
    t = np.eye(5)
    t[0, 4] = z_k       # delta_x + tilt_y z_k
    t[1, 3] = -z_k      # delta_y - tilt_x z_k
    if turned:          # rotation by pi about x: (x, y, z) -> (x, -y, -z) for displacements and rotations
        t = np.diag(_TURN) @ t
    return t


@dataclass
class PairSolution:
    """Equilibrium of a bearing pair: the shaft, each bearing's solution and the pair's stiffness."""

    bearing_name: str
    arrangement: str
    loads: np.ndarray               #: (Fr, Fy, Fa, Mx, My) on the shaft at the pair's centre [N, N m]
    displacement: np.ndarray        #: shaft (delta_x, delta_y, delta_a, tilt_x, tilt_y) [m, rad]
    held: dict                      #: shaft DOF -> why held ("fixed", "no spacing")
    reactions: dict                 #: shaft DOF -> reaction of the held DOF [N or N m]
    residual: np.ndarray            #: sum T^T R - F - reactions at the solution (5,)
    spacing: float | None           #: distance of the ball-set planes [m]
    pressure_centre_offset: float   #: |z_pc| [m]
    preload: float                  #: axial force per bearing at rest in the unloaded set [N]
    preload_displacement: float     #: axial interference of the set at rest [m]
    preload_given: str              #: "force", "displacement" or "none"
    positions: tuple                #: z_k of both bearings [m]
    turned: tuple                   #: whether bearing k is turned round (frame rotated by pi about x)
    solutions: list                 #: QuasiStaticSolution of each bearing (its own frame)
    transforms: list                #: T_k (5, 5)
    stiffness: np.ndarray           #: (5, 5) pair stiffness at the shaft DOFs
    omega: float = 0.0
    iterations: int = 0
    wall_s: float = 0.0
    notes: list = field(default_factory=list)
    bearing: object = None          #: the BallBearing of both positions

    @property
    def pressure_centre_spacing(self) -> float | None:
        """Distance between the two bearings' pressure centres [m]: L + 2e (DB), L - 2e (DF, negative when
        the pressure centres cross), L (DT); None without spacing."""
        if self.spacing is None:
            return None
        e = self.pressure_centre_offset
        return self.spacing + {"DB": 2.0 * e, "DF": -2.0 * e, "DT": 0.0}[self.arrangement]

    def bearing_loads(self, k) -> np.ndarray:
        """(Fx, Fy, Fa, Mx, My) bearing k carries, in its own frame (its reactions) [N, N m]."""
        r = self.solutions[k].reactions
        return np.array([r[n] for n in DOF_NAMES])

    def unloaded(self, k) -> bool:
        """No ball of bearing k touches its inner race: the bearing carries no load (lift-off)."""
        return bool(np.max(self.solutions[k].balls["q_inner"]) <= 0.0)

    def bearing_dict(self, k) -> dict:
        """Bearing k's own loads (``Fr``, ``Fa``) and results."""
        s = self.solutions[k]
        f = self.bearing_loads(k)
        sign = -1.0 if self.turned[k] else 1.0  # its torques in the shaft's sense of rotation
        bl = s.balls
        q = bl["q_inner"]
        loaded = q > 0.0
        d = {"index": k, "position": self.positions[k], "turned": self.turned[k],
             "Fr": float(math.hypot(f[0], f[1])), "Fa": float(f[2]) + 0.0, "loads": dict(zip(("Fx", "Fy", "Fa", "Mx", "My"),
                                                                                     map(float, f))),
             "loads_global": dict(zip(("Fx", "Fy", "Fa", "Mx", "My"), map(float, _to_global(f, self.turned[k])))),
             "unloaded": self.unloaded(k),
             "displacement": dict(zip(DOF_NAMES, map(float, s.displacement))),
             "q_max_inner": float(q.max()), "q_max_outer": float(np.max(bl["q_outer"])),
             "p_max_inner": float(np.max(bl["p_max_inner"])), "p_max_outer": float(np.max(bl["p_max_outer"])),
             "q_inner": q, "q_outer": bl["q_outer"], "psi": np.degrees(bl["psi"]),
             "alpha_inner": np.degrees(bl["alpha_inner"]), "alpha_outer": np.degrees(bl["alpha_outer"]),
             "alpha_inner_mean_loaded": float(np.degrees(np.mean(bl["alpha_inner"][loaded]))) if loaded.any()
             else None,
             "stiffness": s.stiffness,
             "friction_torque": sign * s.friction_torque, "dissipation_total": s.dissipation_total}
        return d

    def rating(self, reference=None, omega=None, **kwargs):
        """Load ratings and rating lives of each bearing (:func:`~exudyn_bearing.physics.rating_life.rating_life`
        of its solution, at the shaft speed or ``omega`` [rad/s]; ``reference``: a PairSolution of the same loads at rest, whose
        distributions give ISO/TS 16281's L10mr at speed; ``kwargs``: reliability, contamination,
        temperature, lubricant) and the system lives of the pair,
        L_sys = (L_1^(-e) + L_2^(-e))^(-1/e), e = 10/9 for ball bearings (the Weibull slope of Lundberg and
        Palmgren: the probability that both survive is the product of both; Harris & Kotzalas, Essential
        Concepts, on the fatigue life of a bearing system; an unloaded bearing has an infinite life and adds
        nothing). Returns (list of RatingLife, dict of system lives: None where a bearing's life is None)."""
        from ...physics.rating_life import rating_life

        b = self.bearing if self.bearing is not None else load_bearing(self.bearing_name)
        lives = []
        for k in range(2):
            ref = reference.solutions[k] if reference is not None else None
            w = abs(self.omega if omega is None else omega)
            lives.append(rating_life(b, self.solutions[k], w if w != 0.0 else None, reference=ref, **kwargs))
        system = {}
        for key in SYSTEM_LIFE_KEYS:
            vals = [getattr(r, key, None) for r in lives]
            if any(v is None for v in vals):
                system[key] = None
                continue
            inv = sum(v ** (-10.0 / 9.0) for v in vals if math.isfinite(v) and v > 0.0)
            system[key] = math.inf if inv == 0.0 else inv ** (-0.9)
        return lives, system

    def to_dict(self, full=False, rating=None) -> dict:
        """JSON-ready dict: the pair (arrangement, spacing, preload, shaft displacement and stiffness,
        held DOFs) and ``bearings``, one entry per bearing with its own loads and results
        (:meth:`bearing_dict`; ``full``: also each bearing's whole QuasiStaticSolution.to_dict as
        ``solution``). ``rating``: the result of :meth:`rating`, whose keys (``C``, ``C0``, ``s0``, ``L10``,
        ...) go into each bearing's entry and whose system lives are ``system_life``."""
        d = {"bearing": self.bearing_name, "arrangement": self.arrangement,
             "loads": dict(zip(_LOAD_NAMES, map(float, self.loads))), "omega": self.omega,
             "spacing": self.spacing, "pressure_centre_offset": self.pressure_centre_offset,
             "pressure_centre_spacing": self.pressure_centre_spacing, "preload": self.preload,
             "preload_displacement": self.preload_displacement, "preload_given": self.preload_given,
             "shaft_displacement": dict(zip(DOF_NAMES, map(float, self.displacement))),
             "held_dofs": dict(self.held), "reactions": dict(self.reactions),
             "residual": dict(zip(_LOAD_NAMES, map(float, self.residual))), "stiffness": self.stiffness,
             "iterations": self.iterations, "wall_s": self.wall_s, "notes": list(self.notes)}
        d["bearings"] = []
        for k in range(2):
            e = self.bearing_dict(k)
            if full:
                e["solution"] = self.solutions[k].to_dict()
            if rating is not None:
                e.update(rating[0][k].to_dict())
            d["bearings"].append(e)
        if rating is not None:
            from ...physics.rating_life import RATING_UNITS

            d["system_life"] = dict(rating[1])
            d["units"] = {**RATING_UNITS, "system_life": "10^6 revolutions (h for L10h): (sum L^(-10/9))^(-9/10)"}
        d["friction_torque"] = float(sum(e["friction_torque"] for e in d["bearings"]))
        d["dissipation_total"] = float(sum(e["dissipation_total"] for e in d["bearings"]))
        d["units"] = {**d.get("units", {}), **PAIR_UNITS}
        return d

    def summary(self) -> str:
        """A few lines for the command line."""
        u = self.displacement
        lines = [f"{self.bearing_name} pair {self.arrangement}: Fr = {self.loads[0]:g} N, Fy = {self.loads[1]:g} N, "
                 f"Fa = {self.loads[2]:g} N, Mx = {self.loads[3]:g} N m, My = {self.loads[4]:g} N m; preload "
                 f"{self.preload:.4g} N per bearing ({self.preload_displacement * 1e6:.3f} um set interference, "
                 f"given as {self.preload_given}); spacing "
                 + (f"{self.spacing * 1e3:.3f} mm, pressure centres {self.pressure_centre_spacing * 1e3:.3f} mm "
                    "apart" if self.spacing is not None else "not given (tilt held)"),
                 (f"shaft: delta_x = {u[0] * 1e6:.3f} um, delta_y = {u[1] * 1e6:.3f} um, delta_a = "
                  f"{u[2] * 1e6:.3f} um, tilt_x = {u[3] * 1e3:.4f} mrad, tilt_y = {u[4] * 1e3:.4f} mrad")]
        for k in range(2):
            e = self.bearing_dict(k)
            lines.append(f"bearing {k} at z = {e['position'] * 1e3:+.3f} mm ({'turned' if e['turned'] else 'as is'}): "
                         + ("unloaded (lift-off)" if e["unloaded"] else
                            f"Fr = {e['Fr']:.1f} N, Fa = {e['Fa']:.1f} N, q_max = {e['q_max_inner']:.1f} N, "
                            f"alpha = {e['alpha_inner_mean_loaded']:.2f} deg"))
        k = self.stiffness
        k_tilt = (f"{k[3, 3]:.4g} N m/rad" if np.isfinite(k[3, 3]) else
                  "n/a (the tilt is held without a spacing: give spacing / --spacing)")
        lines.append(f"stiffness at this ball-set position: k_xx = {k[0, 0]:.4g} N/m, k_aa = {k[2, 2]:.4g} N/m, "
                     f"k_tilt = {k_tilt}")
        for name, why in self.held.items():
            r = self.reactions.get(name, 0.0)
            r = 0.0 if abs(r) < 1e-9 * max(1.0, float(np.max(np.abs(self.loads)))) else r  # round-off shown as 0
            lines.append(f"{name} held ({why}); reaction {r:.6g} {'N m' if name.startswith('tilt') else 'N'}")
        lines.extend(self.notes)
        return "\n".join(lines)


def _to_global(f, turned):
    """The load a bearing carries (its own frame) in the shaft frame, moments about its ball-set plane."""
    return f * _TURN if turned else np.array(f, float)


def _preload_offset(b, arrangement, preload, hertz_method):
    """(offset d [m] of each inner ring along its own +z, preload force [N], interference [m], given)."""
    a0 = None
    if preload is None:
        if arrangement == "DT":
            return 0.0, 0.0, 0.0, "none"
        try:
            a0 = _touch_position(b)
        except InputError:
            raise InputError(f"preload: {b.name} has an interference of its own: give the pair's preload as a "
                             "force") from None
        return a0, 0.0, 0.0, "none"
    if arrangement == "DT":
        raise InputError("preload: a tandem (DT) pair takes no preload of its own (both bearings face the same "
                         "way); preload it against a third bearing, or use DB / DF")
    if isinstance(preload, str):
        if preload in PRELOAD_CLASSES:
            raise InputError(f"preload: the class {preload!r} needs the preload table of the bearing's maker "
                             "(classes are not standardized: SKF GA / GB / GC, Schaeffler UL / UM / UH differ by "
                             "size and series), and no cited values are held: give the preload as a force [N] from "
                             "that table, or as an axial displacement [m]")
        raise InputError(f"preload: expected a force [N], ('displacement', metres) or one of "
                         f"{', '.join(PRELOAD_CLASSES)}, got {preload!r}")
    if isinstance(preload, (tuple, list)):
        if len(preload) != 2 or preload[0] != "displacement":
            raise InputError(f"preload: expected ('displacement', metres), got {preload!r}")
        delta = check_nonnegative("preload_displacement", preload[1])
        if delta > 0.1 * b.ball_radius:
            raise InputError(f"preload_displacement: {delta:g} m exceeds 0.1 R_b ({0.1 * b.ball_radius:g} m): the "
                             "contacts would leave the elastic range (lengths are in metres)")
        a0 = _touch_position(b)
        d = a0 + 0.5 * delta
        f0 = 0.0
        if delta > 0.0:
            s = solve_quasistatic(b, fixed={"delta_x": 0.0, "delta_y": 0.0, "delta_a": d, "tilt_x": 0.0,
                                            "tilt_y": 0.0}, hertz_method=hertz_method, stiffness=False,
                                  resolution_check=False)
            f0 = s.reactions["delta_a"]
        return d, f0, delta, "displacement"
    f0 = check_nonnegative("preload", preload)
    if f0 == 0.0:
        return _preload_offset(b, arrangement, None, hertz_method)[0], 0.0, 0.0, "force"
    try:
        s = solve_quasistatic(b, Fa=f0, hertz_method=hertz_method, stiffness=False, resolution_check=False)
    except InputError as exc:
        raise InputError("preload:" + str(exc).partition(":")[2]) from None
    d = float(s.displacement[2])
    try:
        a0 = _touch_position(b)
        delta = 2.0 * (d - a0)
    except InputError:
        delta = math.nan
    return d, f0, delta, "force"


def solve_pair(bearing, arrangement="DB", Fr=0.0, Fa=0.0, Mx=0.0, My=0.0, *, Fy=0.0, preload=None, spacing=None,
               omega=0.0, omega_outer=0.0, fixed=None, stiffness=True, **options) -> PairSolution:
    """Two identical angular-contact bearings on one shaft, solved as one system (module docstring).

    Parameters
    ----------
    bearing : BallBearing or str
        The bearing of both positions (angular contact: a deep-groove bearing is refused, see below).
    arrangement : {"DB", "DF", "DT"}
        Back-to-back, face-to-face or tandem.
    Fr, Fy, Fa : float
        Loads on the shaft at the pair's centre [N]: radial along +x and +y, axial along +z (DT: the
        direction the set carries, Fa >= 0; DB / DF: either sign, bearing 0 carries +z).
    Mx, My : float
        Moments on the shaft about the pair's centre [N m] (need ``spacing``).
    preload : None, float, ("displacement", float) or str
        DB / DF only: the axial force per bearing at rest [N], or the set's axial interference [m]
        (``("displacement", delta)``); None: the bearings just touch (zero clearance, no preload). The
        manufacturer's classes "light", "medium", "heavy" are refused: no cited values are held.
    spacing : float, optional
        Distance between the two ball-set planes [m] (adjacent bearings without spacer: the bearing width;
        with a spacer: width + spacer). Without it the shaft's tilts are held at zero (as a single bearing's
        by default) and the pair's tilt stiffness is NaN; a moment then is refused.
    omega, omega_outer : float
        Shaft and housing speeds [rad/s].
    fixed : dict, optional
        Shaft DOFs to hold (names ``delta_x, delta_y, delta_a, tilt_x, tilt_y``); reactions reported.
    stiffness : bool
        The pair's 5x5 stiffness (each bearing's is computed anyway for the Newton steps).
    **options
        Passed to :func:`~.solve.solve_quasistatic` for both bearings (control, traction, lubricant,
        ring_growth, fit, temperatures, hertz_method, n_strips, ...); not ``fixed``, ``start``, loads.

    Returns
    -------
    PairSolution

    A deep-groove bearing (free contact angle 0) is refused: its groove centres lie in one radial plane,
    so it has no pressure centre and DB / DF are not defined; its contact angle would follow from the
    preload alone (a preloaded deep-groove pair is two single bearings with an axial load, solve_quasistatic).
    """
    t0 = time.perf_counter()
    b = load_bearing(bearing)
    if arrangement not in ARRANGEMENTS:
        raise InputError(f"arrangement: must be one of {', '.join(ARRANGEMENTS)}, got {arrangement!r}")
    if b.free_contact_angle <= 0.0:
        raise InputError(f"bearing: {b.name} is a deep-groove bearing (free contact angle 0): the arrangements "
                         f"{', '.join(ARRANGEMENTS)} are for angular-contact bearings (no pressure centre off the "
                         "ball-set plane); solve each bearing with solve_quasistatic and its axial load")
    for k in ("fixed", "start", "stiffness"):
        if k in options:
            raise InputError(f"{k}: not an option of the bearings of a pair")
    loads = np.array([check_finite(k, v) for k, v in zip(_LOAD_NAMES, (Fr, Fy, Fa, Mx, My))])
    w_i = check_finite("omega", omega)
    w_o = check_finite("omega_outer", omega_outer)
    hertz_method = options.get("hertz_method", "exact")
    if spacing is not None:
        spacing = check_positive("spacing", spacing)
        if spacing > 10.0:
            raise InputError(f"spacing: {spacing:g} m between the ball-set planes (lengths are in metres)")
    if arrangement == "DT":  # each bearing half the loads: the single bearing's axial-load checks
        if loads[2] <= 0.0:
            raise InputError(f"Fa: a tandem (DT) pair carries axial load along +z only and needs one to locate the "
                             f"shaft axially, got {loads[2]:g} N")
        with axial_load_as_fa():
            check_axial_load(b, 0.5 * math.hypot(loads[0], loads[1]), 0.5 * loads[2])
    held = {}
    fixed_vals = np.zeros(5)
    if fixed is not None:
        if not isinstance(fixed, dict):
            raise InputError(f"fixed: expected a dict of DOF name -> value, got {fixed!r}")
        for k, v in fixed.items():
            if k not in DOF_NAMES:
                raise InputError(f"fixed: unknown DOF {k!r} (valid: {', '.join(DOF_NAMES)})")
            fixed_vals[DOF_NAMES.index(k)] = check_finite(f"fixed.{k}", v)
            held[k] = "fixed"
    if spacing is None:
        if loads[3] != 0.0 or loads[4] != 0.0:
            raise InputError(f"spacing: a moment ({'Mx' if loads[3] != 0.0 else 'My'}) on a pair needs the "
                             "distance between the two bearings' ball-set planes [m] (the catalogue holds no "
                             "width for " + b.name + ")")
        for k in ("tilt_x", "tilt_y"):
            held.setdefault(k, "no spacing")
    for k, v in zip(("Mx", "My"), loads[3:]):
        if v != 0.0 and held.get("tilt_x" if k == "Mx" else "tilt_y") == "fixed":
            raise InputError(f"{k}: a moment load needs the free tilt (do not hold it in fixed)")

    d, f0, delta, given = _preload_offset(b, arrangement, preload, hertz_method)
    z_pc = pressure_centre_offset(b)
    sgn = 1.0 if z_pc > 0.0 else -1.0
    half = 0.5 * (spacing or 0.0)
    if arrangement == "DB":   # pressure centres outside: bearing 0's (at z_pc of its plane) on its far side
        positions, turned = (sgn * half, -sgn * half), (False, True)
    elif arrangement == "DF":
        positions, turned = (-sgn * half, sgn * half), (False, True)
    else:
        positions, turned = (-half, half), (False, False)
    offs = [np.array([0.0, 0.0, d, 0.0, 0.0])] * 2
    if arrangement == "DT":
        a0 = _touch_position(b)
        offs = [np.array([0.0, 0.0, a0, 0.0, 0.0])] * 2
    ts = [_transform(z, tu) for z, tu in zip(positions, turned)]
    kw = {k: v for k, v in options.items()}
    kw.setdefault("resolution_check", False)
    final_inertia = kw.pop("inertia_check", True)  # once, at the converged pose (below), not per Newton step
    kw["inertia_check"] = False
    arm = math.hypot(*b.inner_groove_center)
    wts = np.array([1.0, 1.0, 1.0, 1.0 / arm, 1.0 / arm])   # moments / arm ~ forces
    scale = max(float(np.max(np.abs(loads) * wts)), f0, 1.0)
    limit = 0.1 * b.ball_radius
    free = np.array([k not in held for k in DOF_NAMES])

    def bearing_solutions(u, with_k=True):
        sols = []
        for k in range(2):
            ul = ts[k] @ u + offs[k]
            fx = dict(zip(DOF_NAMES, map(float, ul)))
            sgn_w = -1.0 if turned[k] else 1.0
            sols.append(solve_quasistatic(b, omega=sgn_w * w_i + 0.0, omega_outer=sgn_w * w_o + 0.0, fixed=fx,
                                          stiffness=with_k, **kw))
        return sols

    def evaluate(u, with_k=True):
        sols = bearing_solutions(u, with_k)
        g = sum(ts[k].T @ np.array([sols[k].reactions[n] for n in DOF_NAMES]) for k in range(2))
        kk = sum(ts[k].T @ sols[k].stiffness @ ts[k] for k in range(2)) if with_k else None
        return sols, g, kk

    def local_size(u):
        return max(float(np.max(np.abs((ts[k] @ u + offs[k])[:3]))) for k in range(2))

    u = np.where(free, 0.0, fixed_vals)
    names = _name_of(loads, f0, given)
    it = 0
    try:
        sols, g, kk = evaluate(u)
        r = np.where(free, g - loads, 0.0)
        while np.max(np.abs(r) * wts) > _TOL * scale:
            it += 1
            if it > _MAX_IT:
                raise InputError(f"{names}: the pair's shaft equilibrium did not converge in {_MAX_IT} Newton steps "
                                 f"(scaled residual {np.max(np.abs(r) * wts) / scale:.2g})")
            step = np.zeros(5)
            step[free] = _newton_step(kk[np.ix_(free, free)], r[free], wts[free], b.ball_radius)
            # line search on the scaled residual; steps kept inside the elastic range of the contacts
            # (a trial pose that a bearing refuses, e.g. a contact over the shoulder, counts as too far)
            lam = 1.0
            r0 = np.max(np.abs(r) * wts)
            last = None
            while True:
                un = u + lam * step
                if local_size(un) <= limit:
                    try:
                        sols_n, g_n, kk_n = evaluate(un)
                    except InputError as exc:
                        last = exc
                    else:
                        rn = np.where(free, g_n - loads, 0.0)
                        if np.max(np.abs(rn) * wts) < r0 or lam < 1e-3:
                            break
                lam *= 0.5
                if lam < 1e-6:
                    if last is not None:
                        raise last
                    raise InputError(f"{names}: the pair's shaft equilibrium moves the rings beyond 0.1 R_b (the "
                                     "elastic range of the contacts): reduce the load")
            u, sols, g, kk, r = un, sols_n, g_n, kk_n, rn
    except InputError as exc:
        msg = str(exc)
        inner, _, rest = msg.partition(": ")
        if msg.startswith(names + ":") or inner not in ("fixed", *_LOAD_NAMES) and not inner.startswith("fixed."):
            # the pair's own name, or an input of both bearings (omega, fit, temperatures, control, ...)
            raise InputError(f"{msg} (in a bearing of the {arrangement} pair, held at its pose: its own loads "
                             "read 0)") from None
        raise InputError(f"{names}: {rest} (in a bearing of the {arrangement} pair, held at its pose: its own "
                         "loads read 0)") from None
    if final_inertia:
        for one in sols:
            one.inertia_check = check_ball_inertia(one, b)
    reactions = {k: float((g - loads)[DOF_NAMES.index(k)]) for k in held}
    kmat = np.array(kk, float)
    if spacing is None:
        kmat[3:, :] = np.nan
        kmat[:, 3:] = np.nan
    notes = []
    for k in range(2):
        if np.max(sols[k].balls["q_inner"]) <= 0.0:
            notes.append(f"bearing {k} is unloaded (lift-off): the other bearing carries the whole load")
    if given in ("force", "displacement") and (w_i != 0.0 or w_o != 0.0 or kw.get("fit", 0.0)
                                               or kw.get("temperatures")):
        notes.append("preload set at rest without fit and temperatures (position preload); speed, fit and "
                         "temperatures change the contact forces")
    sol = PairSolution(bearing_name=b.name, arrangement=arrangement, loads=loads, displacement=u, held=held,
                       reactions=reactions, residual=g - loads - np.array([reactions.get(k, 0.0) for k in DOF_NAMES]),
                       spacing=spacing, pressure_centre_offset=abs(z_pc), preload=f0, preload_displacement=delta,
                       preload_given=given, positions=positions, turned=turned, solutions=sols, transforms=ts,
                       stiffness=kmat if stiffness else np.full((5, 5), np.nan), omega=w_i, iterations=it,
                       wall_s=time.perf_counter() - t0, notes=notes, bearing=b)
    return sol


def _name_of(loads, f0, given):
    """The input to name when the pair is refused: the largest load (moments over 0.05 m), else the preload."""
    w = np.abs(loads) * np.array([1.0, 1.0, 1.0, 20.0, 20.0])
    if w.max() > 0.0 and w.max() >= f0:
        return _LOAD_NAMES[int(np.argmax(w))]
    return "preload_displacement" if given == "displacement" else "preload"


def _newton_step(k, r, w, r_b):
    """Newton step du of K du = -r in scaled units (moments / arm, tilts * arm). Where K is singular (no
    contact yet: no preload, clearance) the least-squares step, and where that vanishes a step of 1e-4 R_b
    along the residual's direction (the line search and the next steps take it from there)."""
    ks = k * np.outer(w, w)
    rs = -r * w
    if np.all(np.isfinite(ks)) and np.abs(ks).max() > 0.0:
        xs = np.linalg.lstsq(ks, rs, rcond=1e-10)[0]
        if np.linalg.norm(xs) > 0.0:
            return xs * w
    return 1e-4 * r_b * rs / np.linalg.norm(rs) * w
