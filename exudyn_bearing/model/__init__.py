"""The compiled bearing model: array layouts, the scene's parameter vector,
the contact kernel shared by every dynamic solver, motion helpers, the
initial state, stable-step estimates, the experiment definition (Scenario)
and the record a run hands over."""
