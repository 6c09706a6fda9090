"""Every computed number quoted in docs/theory/, from the package's own functions.

The theory document quotes published values (with their source) and values
computed by the package; the computed ones that no test or doctest already
asserts are printed here, one section per theory page, each line labelled
as the document quotes it. No time integration: it runs in a few seconds.

    python validation/consistency/theory_numbers.py            # all sections
    python validation/consistency/theory_numbers.py lubrication hertz
"""
import math
import sys

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.data import default_lubricant
from exudyn_bearing.model.initial_state import ring_mass_estimate
from exudyn_bearing.model.stability import FAST_STEP_SHARE, explicit_step_factor, ring_stable_step, stable_step
from exudyn_bearing.physics import ehl, friction, hertz, kinematics
from exudyn_bearing.physics import load_distribution as ld
from exudyn_bearing.physics.geometry import raceway_radii
from exudyn_bearing.solvers.analytic import bearing_info, static_analysis

B6208 = eb.catalog["6208"]
B7208 = eb.catalog["7208"]
E_PRIME = hertz.material_reduced_modulus(B6208.material)


def line(label, value, fmt="{:.6g}", unit=""):
    text = fmt.format(value) if not isinstance(value, str) else value
    print(f"  {label}: {text}{(' ' + unit) if unit else ''}")


def _contact_radii(b, inner, alpha=0.0):
    ca = math.cos(alpha)
    r_c = b.pitch_radius + (-1.0 if inner else 1.0) * b.ball_radius * ca
    rc = b.inner_groove_radius if inner else b.outer_groove_radius
    rx, ry = raceway_radii(b.ball_radius, rc, r_c, alpha, inner)
    return float(rx), float(ry)


# -- geometry.md ---------------------------------------------------------------
def geometry():
    print("geometry.md")
    for b in (B6208, B7208):
        line(f"{b.name} pitch radius r_p", b.pitch_radius * 1e3, "{:.4f}", "mm")
        line(f"{b.name} diametral clearance P_d", b.diametral_clearance * 1e6, "{:.3g}", "um")
        line(f"{b.name} conformities f_i, f_o", f"{b.inner_conformity:.4f}, {b.outer_conformity:.4f}")
        line(f"{b.name} conformity sum B", b.conformity_sum, "{:.4f}")
        line(f"{b.name} groove-centre distance A", b.groove_distance * 1e3, "{:.4f}", "mm")
        rho_i, z_i = b.inner_groove_center
        rho_o, z_o = b.outer_groove_center
        line(f"{b.name} inner groove centre (rho_i, z_i)", f"({rho_i * 1e3:.4f}, {z_i * 1e3:.4f})", unit="mm")
        line(f"{b.name} outer groove centre (rho_o, z_o)", f"({rho_o * 1e3:.4f}, {z_o * 1e3:.4f})", unit="mm")
        line(f"{b.name} chord 2 r_p sin(pi/(2Z))", 2 * b.pitch_radius * math.sin(math.pi / (2 * b.n_balls)) * 1e3,
             "{:.5f}", "mm")
        line(f"{b.name} cage pocket clearance (R_z = {b.cage_ball_radius * 1e3:.2f} mm)",
             b.cage_pocket_clearance * 1e6, "{:.2f}", "um")
        line(f"{b.name} ball mass m_b", b.ball_mass * 1e3, "{:.3f}", "g")
        line(f"{b.name} cage-ball mass m_z", b.cage_ball_mass * 1e3, "{:.4f}", "g")
    alt = 2 * B7208.pitch_radius * math.sin(math.pi / 26) - (B7208.ball_radius + 1.01e-3)
    line("7208 pocket clearance with the source's R_z = 1.01 mm", alt * 1e6, "{:.2f}", "um")
    for pd in (12.6e-6, 25.2e-6):
        b = B6208.with_clearance(pd)
        line(f"6208 free contact angle at P_d = +{pd * 1e6:.1f} um", math.degrees(b.free_contact_angle_max),
             "{:.2f}", "deg")


# -- hertz.md --------------------------------------------------------------------
def hertz_numbers():
    print("hertz.md")
    line("E' of the catalogue steel", E_PRIME / 1e9, "{:.2f}", "GPa")
    for race, inner in (("inner", True), ("outer", False)):
        rx, ry = _contact_radii(B6208, inner)
        line(f"6208 {race} R_x, R_y", f"{rx * 1e3:.4f}, {ry * 1e3:.2f}", unit="mm")
        line(f"6208 {race} R_y/R_x", ry / rx, "{:.2f}")
        exact = hertz.hertz_contact(rx, ry, E_PRIME, load=1461.7)
        for m in hertz.METHODS:
            k, f, e = (float(x) for x in hertz.ellipticity(rx, ry, m))
            kst = float(hertz.hertz_stiffness(rx, ry, E_PRIME, m))
            line(f"6208 {race} {m}: k, F, E, K",
                 f"{k:.3f}, {f:.3f}, {e:.4f}, {kst:.4g} N/m^1.5 ({100 * (kst / float(exact.stiffness) - 1):+.1f} %)")
        line(f"6208 {race} at Q = 1461.7 N (exact): a, b, p_max, delta",
             f"{float(exact.a) * 1e3:.3f} mm, {float(exact.b) * 1e3:.3f} mm, {float(exact.p_max) / 1e9:.2f} GPa, "
             f"{float(exact.overlap) * 1e6:.2f} um")
    rx, ry = _contact_radii(B6208, True)
    ar = ry / rx
    k_s, f_s, e_s = (float(x) for x in hertz.ellipticity(rx, ry, "simplified"))
    f_typo = 1.0 + (math.pi / 2 - 1.0) * math.log(ar)
    k_exact = float(hertz.hertz_stiffness(rx, ry, E_PRIME))
    k_typo = float(hertz.hertz_stiffness(rx, ry, E_PRIME, "simplified")) * (f_s / f_typo) ** 1.5
    line("printed (typo) F at the 6208 inner contact", f_typo, "{:.3f}")
    line("K with the printed F / exact K", k_typo / k_exact, "{:.3f}")
    nu = B6208.material.poisson_ratio
    g = B6208.material.shear_modulus
    line("2 pi k G / (pi k E') (the dropped 1/(1 - nu))", 2 * g / E_PRIME, "{:.3f}")
    k_bz = float(hertz.sphere_sphere_stiffness(B6208.ball_radius, B6208.cage_ball_radius, E_PRIME))
    req = B6208.ball_radius * B6208.cage_ball_radius / (B6208.ball_radius + B6208.cage_ball_radius)
    line("6208 ball / cage-ball K", k_bz, "{:.4g}", "N/m^1.5")
    line("same without the 1/3 (4 G sqrt(R_eq)/(1 - nu)) / K", 4 * g * math.sqrt(req) / (1 - nu) / k_bz, "{:.3f}")
    line("6208 ball / ball K (no cage)", float(hertz.sphere_sphere_stiffness(
        B6208.ball_radius, B6208.ball_radius, E_PRIME)), "{:.4g}", "N/m^1.5")
    line("6208 cage-ball / guide K (2/3 E' sqrt(R_z))", 2 / 3 * E_PRIME * math.sqrt(B6208.cage_ball_radius),
         "{:.4g}", "N/m^1.5")
    ki, ko, kn = ld.race_stiffness(B6208)
    line("6208 K_i, K_o, K_n (series)", f"{ki:.4g}, {ko:.4g}, {kn:.4g}", unit="N/m^1.5")


# -- lubrication.md ----------------------------------------------------------------
def lubrication():
    print("lubrication.md")
    lub = default_lubricant()
    line("composite roughness 1.25 sqrt(sigma_1^2 + sigma_2^2)", lub.composite_roughness * 1e6, "{:.3f}", "um")
    line("G = xi E'", lub.pressure_viscosity * E_PRIME, "{:.1f}")
    res = {film: static_analysis(B6208, 3000.0, omega=500.0, film=film) for film in ("hd", "mk")}
    r = res["hd"]
    k_out, k_in = float(r["kappa_outer"][0]), float(r["kappa_inner"][0])
    line("6208 psi = 0 at 500 rad/s, 3000 N: u_r", float(r["u_r_outer"][0]), "{:.4f}", "m/s")
    line("6208 psi = 0: U outer, inner", f"{lub.viscosity * r['u_r_outer'][0] / (E_PRIME * r['r_x_outer'][0]):.4g}, "
         f"{lub.viscosity * r['u_r_inner'][0] / (E_PRIME * r['r_x_inner'][0]):.4g}")
    line("6208 psi = 0: W outer, inner", f"{r['q'][0] / (E_PRIME * r['r_x_outer'][0] ** 2):.4g}, "
         f"{r['q'][0] / (E_PRIME * r['r_x_inner'][0] ** 2):.4g}")
    line("6208 psi = 0: k outer, inner", f"{k_out:.4f}, {k_in:.4f}")
    for film in ("hd", "mk"):
        rr = res[film]
        line(f"6208 psi = 0 {film}: h_min outer, inner",
             f"{rr['h_min_outer'][0] * 1e6:.3f}, {rr['h_min_inner'][0] * 1e6:.3f}", unit="um")
        line(f"6208 psi = 0 {film}: Lambda outer, inner",
             f"{rr['lambda_outer'][0]:.3f}, {rr['lambda_inner'][0]:.3f}")
    # exponents of the film models, fitted from the functions
    rx = float(r["r_x_outer"][0])
    u = np.geomspace(0.5, 20.0, 9)
    q = np.geomspace(100.0, 5000.0, 9)
    for name, fn in (("hd", ehl.film_thickness_hamrock_dowson), ("mk", ehl.film_thickness_masjedi_khonsari)):
        for race, kap in (("outer", k_out), ("inner", k_in)):
            su = np.polyfit(np.log(u), np.log(fn(u, 1461.7, rx, kap, E_PRIME, 0.04, 2.3e-8)), 1)[0]
            sq = np.polyfit(np.log(q), np.log(fn(7.2475, q, rx, kap, E_PRIME, 0.04, 2.3e-8)), 1)[0]
            line(f"{name} speed and load exponent at the {race} k = {kap:.3f}", f"{su:.4f}, {sq:.4f}")
    line("MK G exponent 0.65 k^-0.045 at the outer, inner k", f"{0.65 * k_out ** -0.045:.4f}, {0.65 * k_in ** -0.045:.4f}")
    line("MK reading before the correction: load exponent -0.09 k^+0.15 at the outer k",
         -0.09 * k_out ** 0.15, "{:.4f}")
    line("MK printed literally: speed exponent 0.711 k - 0.023 at the outer k", 0.711 * k_out - 0.023, "{:.3f}")
    # slopes through the quasi-static lubrication map (no centrifugal load), as tests/test_load_distribution.py
    w = np.arange(100.0, 1701.0, 200.0)
    for film in ("hd", "mk"):
        lam = [static_analysis(B6208, 3000.0, omega=x, film=film)["lambda_outer"][0] for x in w]
        line(f"quasi-static map {film}: slope ln Lambda_out / ln omega (100..1700 rad/s)",
             np.polyfit(np.log(w), np.log(lam), 1)[0], "{:.4f}")
        fr = np.geomspace(750.0, 7500.0, 6)
        rs = [static_analysis(B6208, x, omega=500.0, film=film) for x in fr]
        line(f"quasi-static map {film}: slope ln Lambda_out / ln Q_max (750..7500 N)",
             np.polyfit(np.log([x["q_max"] for x in rs]), np.log([x["lambda_outer"][0] for x in rs]), 1)[0],
             "{:.4f}")
    # estimate of the DEM speed sweep: the outer load at psi = 0 grows by the centrifugal force
    q0 = ld.static_equilibrium(B6208, 3000.0).q_max
    wc = kinematics.cage_speed(w, 0.0, B6208.ball_radius, B6208.pitch_radius)
    q_out = q0 + kinematics.centrifugal_force(B6208.ball_mass, B6208.pitch_radius, wc)
    s_q = np.polyfit(np.log(w), np.log(q_out), 1)[0]
    line("estimate: slope ln(Q_static + m r_p omega_c^2) / ln omega", s_q, "{:.4f}")
    a_u = 0.711 * k_out ** -0.023
    for label, a_w in (("hd", -0.073), ("mk", -0.09 * k_out ** -0.15), ("mk before the correction",
                                                                          -0.09 * k_out ** 0.15)):
        a = 0.68 if label == "hd" else a_u
        line(f"estimate of the DEM speed slope, {label}: a_U + a_W * that slope", a + a_w * s_q, "{:.4f}")
    # what 0.7105 would need
    line("k at which 0.711 k^-0.023 = 0.7105", (0.7105 / 0.711) ** (-1 / 0.023), "{:.3f}")
    a_needed = 0.7105 - (-0.09 * k_out ** -0.15) * s_q
    line("U exponent needed for a fitted slope 0.7105 with the MK load term and that load rise", a_needed, "{:.4f}")
    line("k at which 0.711 k^-0.023 equals that U exponent", (a_needed / 0.711) ** (-1 / 0.023), "{:.3f}")
    line("k at which the literal 0.711 k - 0.023 equals that U exponent", (a_needed + 0.023) / 0.711, "{:.3f}")
    # damping of the psi = 0 outer contact at 500 rad/s
    ko = ld.race_stiffness(B6208)[1]
    qq = float(r["q"][0])
    d = (qq / ko) ** (2 / 3)
    c_h = 1.5 * B6208.material.hysteretic_damping * qq
    c_f = 3 * math.pi * lub.viscosity * float(r["a_outer"][0]) / math.sqrt(2) * (
        B6208.ball_radius / float(r["h_min_outer"][0])) ** 1.5
    c_crit = 2 * math.sqrt(B6208.ball_mass * 1.5 * ko * math.sqrt(d))
    line("6208 outer psi = 0, 500 rad/s: C_hyst, C_fluid, series", f"{c_h:.1f}, {c_f:.1f}, {c_h * c_f / (c_h + c_f):.1f}",
         unit="N s/m")
    line("same contact: 2 sqrt(m_b dQ/d delta) (critical, ball on one race)", c_crit, "{:.0f}", "N s/m")
    line("same contact: mu(Lambda)", float(friction.friction_coefficient(
        r["lambda_outer"][0], 0.1, 0.01, 1.0, 3.0)), "{:.4f}")


# -- tangential.md ---------------------------------------------------------------------
def tangential():
    print("tangential.md")
    mb = B6208.ball_mass
    mt = friction.sphere_tangential_mass(mb)
    line("6208 ball tangential mass m_t = m_b/3.5", mt * 1e3, "{:.4f}", "g")
    ki, ko, _ = ld.race_stiffness(B6208)
    q = ld.static_equilibrium(B6208, 3000.0).q_max
    kn = float(hertz.tangent_stiffness(ki, q))
    kt = 2 / 3 * kn
    line("6208 inner contact at Q_max: K_n = dQ/d delta, K_t = 2/3 K_n", f"{kn:.4g}, {kt:.4g}", unit="N/m")
    nu = B6208.material.poisson_ratio
    line("Mindlin no-slip ratio K_t/K_n = 2 (1 - nu)/(2 - nu) for nu = 0.3", 2 * (1 - nu) / (2 - nu), "{:.4f}")
    for dt in (1e-6, 5e-6, 8e-6):
        line(f"implicit K_t / K_t at dt = {dt * 1e6:g} us",
             float(friction.implicit_tangential_stiffness(kt, dt, mt)) / kt, "{:.4f}")


# -- dynamics.md -------------------------------------------------------------------------
def dynamics():
    print("dynamics.md")
    line("Verlet step factor, zeta = 0 and 1", f"{explicit_step_factor(0.0):.4f}, {explicit_step_factor(1.0):.4f}")
    line("RK4 step factor, zeta = 0 and 1",
         f"{explicit_step_factor(0.0, 'rk4'):.4f}, {explicit_step_factor(1.0, 'rk4'):.4f}")
    f_impl = explicit_step_factor(1.0, "verlet", "implicit")
    line("Verlet step factor, zeta = 1, implicit damping; ratio to explicit",
         f"{f_impl:.4f}; {f_impl / explicit_step_factor(1.0):.3f}")
    line("damping ratio at the implicit limit, zeta = 1", 1.0 / (1.0 + 2.0 * f_impl), "{:.3f}")
    # the estimate's cage mode, omega^2 = 2 k / m, with each of its two contacts critically damped on its own:
    # zeta = sqrt 2 in the mode, and C dt / m = sqrt 2 omega dt for the implicit coefficient
    lo, hi = 0.0, 2.0
    for _ in range(200):
        x = 0.5 * (lo + hi)
        z = math.sqrt(2.0) / (1.0 + math.sqrt(2.0) * x)
        lo, hi = (x, hi) if x < 2.0 * (math.sqrt(1.0 + z * z) - z) else (lo, x)
    line("two-contact cage mode (zeta = sqrt 2): Verlet limit explicit, implicit damping",
         f"{explicit_step_factor(math.sqrt(2.0)):.3f}, {0.5 * (lo + hi):.3f}")
    line("6208 ring-mass estimate", ring_mass_estimate(B6208) * 1e3, "{:.1f}", "g")
    # the table of dynamics.md: the 6208 in its protocol from rest (cage limit at a tenth of the ball load), the
    # 7208 from the analytic state (unequal contact angles: a tenth too)
    protocol = eb.Scenario(Fr=3000.0, omega=500.0, t_ramp_up=0.05, initial="rest")
    scenes = {
        "6208 3000 N 500 rad/s protocol, explicit spring": ("6208", protocol),
        "6208 3000 N 500 rad/s protocol, implicit spring": ("6208", protocol.replace(tangential="implicit")),
        "6208 3000 N 500 rad/s protocol, implicit spring and cage damping": ("6208", protocol.replace(
            tangential="implicit", cage_damping="implicit")),
        "6208 protocol, regularized friction, rk4": ("6208", protocol.replace(friction="regularized",
                                                                               integrator="rk4")),
        "7208 3000 + 3000 N 500 rad/s": ("7208", eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0)),
        "7208 3000 + 3000 N 500 rad/s, implicit cage damping": ("7208", eb.Scenario(
            Fr=3000.0, Fa=3000.0, omega=500.0, cage_damping="implicit")),
        "6208 3000 N 500 rad/s steady from the analytic state, implicit spring": ("6208", eb.Scenario(
            Fr=3000.0, omega=500.0, tangential="implicit")),
    }
    for label, (name, sc) in scenes.items():
        s = stable_step(eb.catalog[name], sc)
        line(f"stable step {label}", f"{s.dt * 1e6:.3f} us (normal {s.normal * 1e6:.2f}, tangential "
             f"{s.tangential * 1e6:.2f}, friction {s.friction * 1e6:.2f}, cage {s.cage * 1e6:.2f} us; "
             f"limited by {s.limited_by})")
    for label, mass in (("81 g estimate", ring_mass_estimate(B6208)), ("1.25 kg", 1.25)):
        h = ring_stable_step(B6208, eb.Scenario(Fr=3000.0, omega=500.0), mass)
        line(f"6208 ring stable step ({label}, 3000 N); fast-mode limit, 5 us sub-steps",
             f"{h * 1e6:.1f} us; {FAST_STEP_SHARE * h * 1e6:.1f} us, {max(1, int(FAST_STEP_SHARE * h / 5e-6))}")


# -- load_distribution.md -----------------------------------------------------------------
def load_distribution():
    print("load_distribution.md")
    for e in (0.4, 0.5, 0.684, 1.0):
        line(f"J_r, J_a at eps = {e}", f"{float(ld.load_integral_radial(e)):.4f}, {float(ld.load_integral_axial(e)):.4f}")
    line("6208 continuous Q_max at 3000 N", ld.stribeck_solution(9, 3000.0).q_max, "{:.1f}", "N")
    for pd in (-12.6e-6, 0.0, 12.6e-6):
        s = ld.static_equilibrium(B6208.with_clearance(pd), 3000.0)
        line(f"6208 discrete, 3000 N, P_d = {pd * 1e6:+.1f} um: Q_max, delta_r, eps",
             f"{s.q_max:.1f} N, {s.delta_r * 1e6:.2f} um, {s.eps:.3f}")
    s = ld.static_equilibrium(B7208, 3000.0, 3000.0)
    loaded = s.q > 0
    line("7208 discrete, F_r = F_a = 3000 N: Q_max, eps, delta_r, delta_a",
         f"{s.q_max:.1f} N, {s.eps:.3f}, {s.delta_r * 1e6:.2f} um, {s.delta_a * 1e6:.2f} um")
    line("7208 contact angles of the loaded balls",
         f"{np.degrees(s.contact_angle[loaded]).min():.2f} .. {np.degrees(s.contact_angle[loaded]).max():.2f}",
         unit="deg")
    st = ld.stribeck_solution(13, 3000.0, 3000.0, B7208.free_contact_angle)
    line("7208 continuous fixed-angle (40 deg): eps, Q_max", f"{st.eps:.3f}, {st.q_max:.1f} N")
    # the digital-twin paper's eps = 2.46 at F_r = F_a: the fixed contact angle that gives it
    ratio = float(ld.load_integral_radial(2.46) / ld.load_integral_axial(2.46))
    line("fixed contact angle giving eps = 2.46 at F_r = F_a (tan a = J_r/J_a)", math.degrees(math.atan(ratio)),
         "{:.1f}", "deg")


# -- kinematics.md ------------------------------------------------------------------------------
def kinematics_numbers():
    print("kinematics.md")
    for b in (B6208, B7208):
        info = bearing_info(b, 500.0)
        line(f"{b.name} at 500 rad/s: cage, ball spin (absolute), ball spin (relative to cage)",
             f"{info['cage_speed']:.2f}, {info['ball_spin']:.2f}, {info['ball_spin_relative']:.2f}", unit="rad/s")
        line(f"{b.name} at 500 rad/s: FTF, BPFO, BPFI, BSF",
             f"{info['ftf']:.3f}, {info['bpfo']:.3f}, {info['bpfi']:.3f}, {info['bsf']:.3f}", unit="Hz")
        line(f"{b.name} at 500 rad/s: rolling speed u_r", info["rolling_speed"], "{:.4f}", "m/s")
    for deg in (0.0, 10.7, 40.0):
        line(f"7208 geometry at 500 rad/s, contact angle {deg:g} deg: absolute ball spin",
             float(kinematics.ball_spin_absolute(500.0, 0.0, B7208.ball_radius, B7208.pitch_radius,
                                                 math.radians(deg))), "{:.2f}", "rad/s")
    for w in (100.0, 500.0, 1700.0):
        wc = float(kinematics.cage_speed(w, 0.0, B6208.ball_radius, B6208.pitch_radius))
        line(f"6208 centrifugal force m r_p omega_c^2 at {w:.0f} rad/s",
             float(kinematics.centrifugal_force(B6208.ball_mass, B6208.pitch_radius, wc)), "{:.2f}", "N")


SECTIONS = {"geometry": geometry, "hertz": hertz_numbers, "lubrication": lubrication, "tangential": tangential,
            "dynamics": dynamics, "load_distribution": load_distribution, "kinematics": kinematics_numbers}


def main(argv=None):
    names = (argv if argv is not None else sys.argv[1:]) or list(SECTIONS)
    for n in names:
        if n not in SECTIONS:
            raise SystemExit(f"unknown section {n!r} (valid: {', '.join(SECTIONS)})")
        SECTIONS[n]()


if __name__ == "__main__":
    main()
