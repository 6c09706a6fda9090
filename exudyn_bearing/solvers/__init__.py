"""Solvers of the bearing model: the numba DEM reference engine
(:mod:`.reference`), the Exudyn element (:mod:`.element`), analyses without
time integration (:mod:`.analytic`). No solver imports another solver."""
