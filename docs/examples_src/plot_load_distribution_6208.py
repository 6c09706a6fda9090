"""
Load distribution of the 6208 at speed
======================================

The quasi-static equilibrium of the 6208 under a radial load of 3000 N at 500 rad/s
(:func:`eb.solve_quasistatic <exudyn_bearing.solvers.quasistatic.solve.solve_quasistatic>`): the load of each
of the nine balls on the inner and the outer race against its azimuth psi (psi = 0 along the load), with
Stribeck's rigid-ring law Q_max cos(psi)^1.5 through the largest inner load for comparison. At speed the
centrifugal force of each ball adds to its outer-race load, so the outer loads lie above the inner ones and
the unloaded balls still press on the outer race.

Explained in :doc:`/howto/load_and_stiffness` and the theory pages :doc:`/theory/load_distribution` and
:doc:`/theory/quasistatic`.
"""
import matplotlib.pyplot as plt
import numpy as np

import exudyn_bearing as eb

s = eb.solve_quasistatic("6208", Fr=3000.0, omega=500.0)
psi = np.degrees(s.balls["psi"])
q_in, q_out = s.balls["q_inner"], s.balls["q_outer"]

print(f"6208, Fr = 3000 N, 500 rad/s: shaft displaced {s.displacement[0] * 1e6:.2f} um along the load")
print(" psi [deg]   Q inner [N]   Q outer [N]   centrifugal [N]")
for row in zip(psi, q_in, q_out, s.balls["centrifugal_force"]):
    print("  {:6.1f}    {:10.1f}    {:10.1f}    {:10.2f}".format(*row))

# %%
# The balls against azimuth (shown from -180 to 180 degrees), and Stribeck's law for comparison.
order = np.argsort((psi + 180.0) % 360.0)
psi_c = ((psi + 180.0) % 360.0 - 180.0)[order]
fine = np.linspace(-90.0, 90.0, 181)
fig, ax = plt.subplots(figsize=(6.4, 3.6))
ax.plot(psi_c, q_in[order], "o-", label="inner race")
ax.plot(psi_c, q_out[order], "s--", label="outer race")
ax.plot(fine, q_in.max() * np.cos(np.radians(fine)) ** 1.5, ":", color="0.4", label=r"$Q_{max}\,\cos^{1.5}\psi$")
ax.set_xlabel("azimuth psi [deg]")
ax.set_ylabel("ball load Q [N]")
ax.set_xticks(range(-180, 181, 60))
ax.set_title("6208, Fr = 3000 N, 500 rad/s")
ax.legend()
fig.tight_layout()
