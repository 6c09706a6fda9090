"""Heat transfer relations of a lumped bearing thermal network: oil enthalpy flow, convection of the
oil-washed surfaces, conduction through the Hertz contacts, and the steady network itself.

docs/theory/thermal.md. SI units (W, K, m, s), plain numpy, one relation per function. The
network follows the lumped approach of Harris & Kotzalas [1]_ (Vol. 2, the chapter on friction
heat and bearing temperatures): nodes at uniform temperature, linked by thermal conductances
[W/K], heat sources at the nodes, the oil flow carrying heat out of the bearing.

References
----------
.. [1] T. A. Harris and M. N. Kotzalas, Rolling Bearing Analysis, 5th ed., Vol. 2: Advanced
   Concepts of Bearing Technology, CRC Press, 2006 (friction-generated heat and bearing
   temperatures: the thermal network, heat transfer coefficients of oil-lubricated bearings).
.. [2] F. P. Incropera, D. P. DeWitt, T. L. Bergman and A. S. Lavine, Fundamentals of Heat and
   Mass Transfer, 6th ed., Wiley, 2007 (sec. 7.2: the flat plate in parallel flow).
.. [3] M. M. Yovanovich, "Thermal constriction resistance of contacts on a half-space,"
   Progress in Astronautics and Aeronautics 39 (1975) 397-418; R. Holm, Electric Contacts,
   4th ed., Springer, 1967 (the isothermal disc: R = 1 / (4 k a)).
.. [4] H. Blok, "Theoretical study of temperature rise at surfaces of actual contact under
   oiliness lubricating conditions," Proc. General Discussion on Lubrication, IMechE, 2 (1937)
   222-235 (partition of frictional heat between the two surfaces of a moving contact).
.. [5] G. K. Batchelor and R. W. O'Brien, "Thermal or electrical conduction through a granular
   material," Proc. R. Soc. Lond. A 355 (1977) 313-333 (conduction through the fluid in the gap
   between near-touching spheres: each annulus conducts across its local gap).
"""
from __future__ import annotations

import numpy as np

__all__ = ["AIR_FREE_CONVECTION", "BEARING_STEEL_CONDUCTIVITY", "constriction_conductance", "contact_heat_share",
           "film_conductance", "flat_plate_heat_transfer", "network_heat_out", "network_temperatures",
           "oil_enthalpy_flow", "oil_through_flow_speed", "prandtl_number", "sphere_wall_gap_conductance"]

#: Thermal conductivity of through-hardened bearing steel [W/(m K)]: AISI 52100 about 43-46 and
#: M-50 about 36 near room temperature (Harris & Kotzalas [1]_, Vol. 1, bearing materials; handbook
#: values); 40 is the value used for both rings and balls.
BEARING_STEEL_CONDUCTIVITY = 40.0

#: Heat transfer coefficient of free convection to still air [W/(m^2 K)]: Incropera et al. [2]_
#: give 2-25 for gases in free convection (Table 1.1); 10 is used for a housing or a shaft end.
AIR_FREE_CONVECTION = 10.0


def oil_enthalpy_flow(mass_flow, specific_heat, t_out, t_in):
    """Heat carried out by the oil [W]: m_dot c_p (T_out - T_in) (steady flow energy balance, [1]_)."""
    q = np.asarray(mass_flow, dtype=float) * specific_heat * (np.asarray(t_out, dtype=float) - t_in)
    return q if np.ndim(q) else float(q)


def prandtl_number(viscosity, specific_heat, conductivity):
    """Pr = eta c_p / k [-] (eta [Pa s], c_p [J/(kg K)], k [W/(m K)])."""
    p = np.asarray(viscosity, dtype=float) * specific_heat / conductivity
    return p if np.ndim(p) else float(p)


def flat_plate_heat_transfer(conductivity, speed, kinematic_viscosity, prandtl, length):
    """Mean heat transfer coefficient h [W/(m^2 K)] of a surface of length L [m] in parallel flow
    at the relative speed u [m/s], Incropera et al. [2]_ eq. 7.30 and 7.38:

    Re_L = u L / nu; laminar (Re_L <= 5e5) Nu = 0.664 Re_L^(1/2) Pr^(1/3); mixed
    (Re_L > 5e5) Nu = (0.037 Re_L^(4/5) - 871) Pr^(1/3); h = Nu k / L.

    Harris & Kotzalas [1]_ treat the ring and ball surfaces washed by the oil in a jet-lubricated
    bearing as plates in parallel flow at their speed relative to the oil; the length over which
    the boundary layer grows is a choice of the caller (the solver uses the ball diameter: the
    balls renew the layer on the races). Validity: Pr >= 0.6, smooth surfaces, single-phase flow;
    an oil-air mixture is represented by the oil's properties (an upper bound on h).
    """
    re = np.abs(np.asarray(speed, dtype=float)) * length / kinematic_viscosity
    pr3 = np.asarray(prandtl, dtype=float) ** (1.0 / 3.0)
    nu_lam = 0.664 * np.sqrt(re) * pr3
    nu_mix = (0.037 * re ** 0.8 - 871.0) * pr3
    h = np.where(re <= 5e5, nu_lam, nu_mix) * conductivity / length
    return h if np.ndim(h) else float(h)


def oil_through_flow_speed(volume_flow, r_inner, r_outer, n_balls, ball_radius):
    """Mean axial speed [m/s] of the oil flowing through a bearing, u = Q / A, with A the free
    annulus between the raceways, pi (r_o^2 - r_i^2) minus the Z ball sections pi R_b^2 (mass
    conservation; volume flow Q [m^3/s], raceway radii r_i, r_o [m]).

    The oil of a jet-lubricated bearing washes the rings and the balls at this speed also when
    nothing turns: the solver takes the larger of it and the rotation-driven speed as the speed of
    :func:`flat_plate_heat_transfer` (an assumption of this package: a plug flow through the whole
    free annulus, the least speed a flow Q gives there; Harris & Kotzalas [1]_ give the convection
    of the rotating parts only, which vanishes at rest).
    """
    area = np.pi * (np.asarray(r_outer, dtype=float) ** 2 - np.asarray(r_inner, dtype=float) ** 2) \
        - n_balls * np.pi * np.asarray(ball_radius, dtype=float) ** 2
    u = np.asarray(volume_flow, dtype=float) / area
    return u if np.ndim(u) else float(u)


def constriction_conductance(a, b, k1, k2):
    """Thermal conductance [W/K] of a Hertz contact between two solids, Holm / Yovanovich [3]_:
    each half-space behind a disc of radius r_e = sqrt(a b) (the ellipse's equivalent radius)
    has the constriction resistance 1 / (4 k r_e); the two sides are in series:

    G = 1 / (1 / (4 k1 r_e) + 1 / (4 k2 r_e)).

    Validity: stationary isothermal contact spot, small against the bodies; a film of oil in the
    contact and the motion of the surfaces (Peclet number) are not represented (the moving
    contact conducts more heat, [4]_). a, b [m] semi-axes (0: no contact, G = 0).
    """
    r = np.sqrt(np.maximum(np.asarray(a, dtype=float), 0.0) * np.maximum(np.asarray(b, dtype=float), 0.0))
    g = 4.0 * r / (1.0 / k1 + 1.0 / k2)
    return g if np.ndim(g) else float(g)


def film_conductance(conductivity, area, thickness):
    """Thermal conductance [W/K] of a fluid film of uniform thickness h [m] over the area A [m^2]
    between two walls, conduction only (Fourier's law across the film): G = k A / h.

    Used for the oil film of a cage riding on its guiding ring land (A = 2 pi r_land w_land, h the
    radial land clearance). Validity: h small against the radius of the walls; convection inside
    the film (a Couette film carries its heat along the walls, not across) is left out, so the film
    is a pure conductor across its thickness; the viscous heat generated in the film is a heat
    source of the nodes, not of this relation. k [W/(m K)], A [m^2], h [m] > 0.
    """
    g = np.asarray(conductivity, dtype=float) * np.asarray(area, dtype=float) / np.asarray(thickness, dtype=float)
    return g if np.ndim(g) else float(g)


def sphere_wall_gap_conductance(conductivity, radius, gap):
    """Thermal conductance [W/K] of the fluid between a sphere of radius R [m] and a flat wall at the
    least gap c [m], Batchelor & O'Brien's [5]_ parallel-column integral: the annulus at the distance
    r from the axis conducts across its local gap h(r) = c + r^2 / (2 R) (parabolic sphere), out to
    r = R:

    G = int_0^R k 2 pi r dr / (c + r^2 / (2 R)) = 2 pi k R ln(1 + R / (2 c)).

    Used for a ball in its cage pocket (the pocket wall taken flat: a conforming pocket conducts
    more). Validity: c << R (the parabolic gap), the fluid conducting only; c -> infinity gives 0,
    c -> 0 diverges logarithmically (a touching sphere needs the solids' constriction as well).
    k [W/(m K)], R [m], c [m] > 0 (infinity allowed: no film).
    """
    r = np.asarray(radius, dtype=float)
    g = 2.0 * np.pi * np.asarray(conductivity, dtype=float) * r * np.log1p(r / (2.0 * np.asarray(gap, dtype=float)))
    return g if np.ndim(g) else float(g)


def contact_heat_share(speed_1, speed_2, conductivity_1=1.0, conductivity_2=1.0):
    """Share of a contact's frictional heat that enters surface 1 [-], Blok's partition [4]_ for two
    surfaces of equal diffusivity moving through the contact at high Peclet number:
    s_1 = k_1 sqrt(u_1) / (k_1 sqrt(u_1) + k_2 sqrt(u_2)); equal speeds and materials give 1/2.

    A ball rolling on a race moves both surfaces through the contact at the rolling speed, so the
    solver splits every contact's heat half and half between the ball and the ring.
    """
    w1 = conductivity_1 * np.sqrt(np.abs(np.asarray(speed_1, dtype=float)))
    w2 = conductivity_2 * np.sqrt(np.abs(np.asarray(speed_2, dtype=float)))
    tot = w1 + w2
    s = np.where(tot > 0.0, w1 / np.where(tot > 0.0, tot, 1.0), 0.5)
    return s if np.ndim(s) else float(s)


def network_temperatures(conductance, heat, boundary_conductance, boundary_temperature):
    """Steady temperatures [K] of a lumped thermal network [1]_.

    Node i: Q_i + sum_j G_ij (T_j - T_i) + sum_k g_ik (T_b,k - T_i) = 0, solved as the linear system
    (diag(sum_j G_ij + sum_k g_ik) - G) T = Q + g T_b.

    Parameters
    ----------
    conductance : (n, n) array
        Symmetric conductances between the nodes [W/K] (diagonal ignored).
    heat : (n,) array
        Heat generated at each node [W].
    boundary_conductance : (n, m) array
        Conductances from each node to m fixed temperatures [W/K] (ambient; the oil inlet, where
        m_dot c_p is the conductance of a fully mixed oil node to its inlet temperature).
    boundary_temperature : (m,) array
        The fixed temperatures [K].
    """
    g = np.array(conductance, dtype=float)
    np.fill_diagonal(g, 0.0)
    gb = np.asarray(boundary_conductance, dtype=float)
    a = np.diag(g.sum(axis=1) + gb.sum(axis=1)) - g
    rhs = np.asarray(heat, dtype=float) + gb @ np.asarray(boundary_temperature, dtype=float)
    return np.linalg.solve(a, rhs)


def network_heat_out(temperatures, boundary_conductance, boundary_temperature):
    """Heat leaving a network through each boundary [W], sum over the nodes of g_ik (T_i - T_b,k);
    in steady state its sum equals the heat generated (:func:`network_temperatures`)."""
    t = np.asarray(temperatures, dtype=float)
    gb = np.asarray(boundary_conductance, dtype=float)
    return (gb * (t[:, None] - np.asarray(boundary_temperature, dtype=float)[None, :])).sum(axis=0)
