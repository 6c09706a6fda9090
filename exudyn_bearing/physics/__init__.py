"""Physics relations of docs/theory/: one pure function per relation, SI units.

Modules: :mod:`hertz` (elliptic and sphere contact), :mod:`geometry`
(ball in a torus groove), :mod:`ehl` (film thickness, film parameter),
:mod:`damping`, :mod:`friction`, :mod:`kinematics`,
:mod:`load_distribution` (quasi-static Stribeck/Harris), :mod:`ring_growth`
(rings at speed and temperature), :mod:`traction` (traction models),
:mod:`contact_slip` (slip and traction over the Hertz ellipse), :mod:`pocket_film` (the oil film between a
ball and its cage pocket).
"""
