"""Tables of ISO 281:2007 and ISO 76:2006 for radial and angular-contact ball bearings (data).

The standards work in N and mm; the tables here are dimensionless or in the
standards' own units as stated per table, and
:mod:`exudyn_bearing.physics.rating_life` converts to SI. Rows are the
standards' values for single-row radial-contact groove (deep-groove) and
single-row angular-contact groove ball bearings; intermediate values are
found by linear interpolation, as both standards prescribe.

References
----------
.. [1] ISO 281:2007, Rolling bearings -- Dynamic load ratings and rating life
   (Table 2: f_c; Table 3: X, Y, e; Table 12: a_1; Table 13: e_C).
.. [2] ISO 76:2006, Rolling bearings -- Static load ratings (Table 1: f_0;
   Table 2: X_0, Y_0).
"""
from __future__ import annotations

__all__ = ["FC_TABLE", "F0_TABLE", "XYE_DEEP_GROOVE", "XYE_ANGULAR_15", "XYE_ANGULAR", "X0Y0_ANGULAR",
           "X0Y0_DEEP_GROOVE", "CONTAMINATION", "STANDARD_CONFORMITY"]

#: ISO 281:2007 Table 2, column of single-row radial-contact groove ball bearings and single- and double-row
#: angular-contact groove ball bearings: (D_w cos(alpha) / D_pw, f_c) with f_c in the standard's N and mm units.
FC_TABLE = (
    (0.01, 29.1), (0.02, 35.8), (0.03, 40.3), (0.04, 43.8), (0.05, 46.7), (0.06, 49.1), (0.07, 51.1),
    (0.08, 52.8), (0.09, 54.3), (0.10, 55.5), (0.12, 57.5), (0.14, 58.8), (0.16, 59.6), (0.18, 59.9),
    (0.20, 59.9), (0.22, 59.6), (0.24, 59.0), (0.26, 58.2), (0.28, 57.1), (0.30, 56.0), (0.32, 54.6),
    (0.34, 53.2), (0.36, 51.7), (0.38, 50.0), (0.40, 48.4),
)

#: The groove conformities the f_c and f_0 tables assume at most: inner r_i <= 0.52 D_w, outer r_e <= 0.53 D_w
#: (ISO 281:2007 clause 6.1.1 and ISO 76:2006 clause 5.1, radial and angular-contact groove ball bearings).
STANDARD_CONFORMITY = (0.52, 0.53)

#: ISO 76:2006 Table 1, radial- and angular-contact groove ball bearings: (D_w cos(alpha) / D_pw, f_0),
#: f_0 in N/mm^2 (the 4200 MPa contact stress of the most heavily loaded contact, Stribeck's factor 5).
F0_TABLE = (
    (0.00, 14.7), (0.01, 14.9), (0.02, 15.1), (0.03, 15.3), (0.04, 15.5), (0.05, 15.7), (0.06, 15.9),
    (0.07, 16.1), (0.08, 16.3), (0.09, 16.5), (0.10, 16.4), (0.11, 16.1), (0.12, 15.9), (0.13, 15.6),
    (0.14, 15.4), (0.15, 15.2), (0.16, 14.9), (0.17, 14.7), (0.18, 14.4), (0.19, 14.2), (0.20, 14.0),
    (0.21, 13.7), (0.22, 13.5), (0.23, 13.2), (0.24, 13.0), (0.25, 12.8), (0.26, 12.5), (0.27, 12.3),
    (0.28, 12.1), (0.29, 11.8), (0.30, 11.6), (0.31, 11.4), (0.32, 11.2), (0.33, 10.9), (0.34, 10.7),
    (0.35, 10.5), (0.36, 10.3), (0.37, 10.0), (0.38, 9.8), (0.39, 9.6), (0.40, 9.4),
)

#: ISO 281:2007 Table 3, single-row radial-contact groove ball bearings: rows (f_0 F_a / C_0r, e, Y) with
#: X = 0.56 for F_a / F_r > e (X = 1, Y = 0 otherwise).
XYE_DEEP_GROOVE = (
    (0.172, 0.19, 2.30), (0.345, 0.22, 1.99), (0.689, 0.26, 1.71), (1.03, 0.28, 1.55), (1.38, 0.30, 1.45),
    (2.07, 0.34, 1.31), (3.45, 0.38, 1.15), (5.17, 0.42, 1.04), (6.89, 0.44, 1.00),
)
#: X of the deep-groove rows for F_a / F_r > e.
X_DEEP_GROOVE = 0.56

#: ISO 281:2007 Table 3, single-row angular-contact groove ball bearings, alpha = 15 deg: rows
#: (f_0 F_a / C_0r, e, Y) with X = 0.44 for F_a / F_r > e.
XYE_ANGULAR_15 = (
    (0.178, 0.38, 1.47), (0.357, 0.40, 1.40), (0.714, 0.43, 1.30), (1.07, 0.46, 1.23), (1.43, 0.47, 1.19),
    (2.14, 0.50, 1.12), (3.57, 0.55, 1.02), (5.35, 0.56, 1.00), (7.14, 0.56, 1.00),
)
#: X of the 15 deg rows for F_a / F_r > e.
X_ANGULAR_15 = 0.44

#: ISO 281:2007 Table 3, single-row angular-contact groove ball bearings, alpha = 20 to 45 deg:
#: (alpha [deg], X, Y, e) for F_a / F_r > e (X = 1, Y = 0 otherwise).
XYE_ANGULAR = (
    (20.0, 0.43, 1.00, 0.57), (25.0, 0.41, 0.87, 0.68), (30.0, 0.39, 0.76, 0.80), (35.0, 0.37, 0.66, 0.95),
    (40.0, 0.35, 0.57, 1.14), (45.0, 0.33, 0.50, 1.34),
)

#: ISO 76:2006 Table 2, single-row radial-contact groove ball bearings: (X_0, Y_0); P_0r = max(X_0 F_r + Y_0 F_a,
#: F_r).
X0Y0_DEEP_GROOVE = (0.6, 0.5)
#: ISO 76:2006 Table 2, single-row angular-contact groove ball bearings: (alpha [deg], X_0, Y_0).
X0Y0_ANGULAR = (
    (15.0, 0.5, 0.46), (20.0, 0.5, 0.42), (25.0, 0.5, 0.38), (30.0, 0.5, 0.33), (35.0, 0.5, 0.29),
    (40.0, 0.5, 0.26), (45.0, 0.5, 0.22),
)

#: ISO 281:2007 Table 13, contamination factor e_C (ball and roller bearings): class -> ((lo, hi) for
#: D_pw < 100 mm, (lo, hi) for D_pw >= 100 mm). The standard gives ranges; the rating uses their midpoint
#: (:func:`exudyn_bearing.physics.rating_life.contamination_factor`).
CONTAMINATION = {
    "extreme-cleanliness": ((1.0, 1.0), (1.0, 1.0)),
    "high-cleanliness": ((0.6, 0.8), (0.8, 0.9)),
    "normal-cleanliness": ((0.5, 0.6), (0.6, 0.8)),
    "slight-contamination": ((0.3, 0.5), (0.4, 0.6)),
    "typical-contamination": ((0.1, 0.3), (0.2, 0.4)),
    "severe-contamination": ((0.0, 0.1), (0.0, 0.1)),
    "very-severe-contamination": ((0.0, 0.0), (0.0, 0.0)),
}
