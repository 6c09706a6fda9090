"""
Bearing stiffness against speed
===============================

The 5x5 stiffness and damping matrices of the 6208 under F_r = 3000 N for rotordynamics, at shaft speeds from
rest to 1500 rad/s
(:func:`eb.bearing_coefficients <exudyn_bearing.solvers.quasistatic.coefficients.bearing_coefficients>`: the
quasi-static solver linearised at each speed, averaged over three ball-set positions within one ball pitch).
The figure shows the radial stiffness along the load (k_xx), across it (k_yy) and the axial stiffness against
speed, and their change from rest (the centrifugal ball loads and the ring growth at speed). The table adds
the damping c_xx and the spread of the matrices over the three ball-set positions (the largest difference of
an entry, over the largest entry: the ball-pass variation the average hides).

How to use the coefficients (and export them to ROSS): :doc:`/howto/load_and_stiffness`; axes, signs and
checks: :doc:`/theory/vibration`.
"""
import matplotlib.pyplot as plt
import numpy as np

import exudyn_bearing as eb

speeds = np.linspace(0.0, 1500.0, 11)  # rad/s
c = eb.bearing_coefficients("6208", speeds, Fr=3000.0)
k, d = c.stiffness, c.damping
spread = np.asarray(c.operating_point["phase_spread_stiffness"])

print(f"axes {c.axes}; k in {c.units['stiffness'][0][0]}, c in {c.units['damping'][0][0]}")
print("omega [rad/s]  k_xx [MN/m]  k_yy [MN/m]  k_zz [MN/m]  c_xx [N s/m]  spread of K")
for i, w in enumerate(speeds):
    print(f"{w:12.0f} {k[i, 0, 0] / 1e6:12.1f} {k[i, 1, 1] / 1e6:12.1f} {k[i, 2, 2] / 1e6:12.2f} {d[i, 0, 0]:12.1f}"
          f" {spread[i]:11.1%}")

# %%
# The diagonal stiffness entries of the translations against speed, and their change from rest.
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(8.0, 3.6))
for i, (label, marker) in enumerate([("k_xx (along the load)", "o-"), ("k_yy (across the load)", "s-"),
                                     ("k_zz (axial)", "^-")]):
    ax1.plot(speeds, k[:, i, i] / 1e6, marker, label=label)
    ax2.plot(speeds, 100.0 * (k[:, i, i] / k[0, i, i] - 1.0), marker, label=label)
ax1.set_xlabel("shaft speed [rad/s]")
ax1.set_ylabel("stiffness [MN/m]")
ax1.set_ylim(bottom=0.0)
ax2.set_xlabel("shaft speed [rad/s]")
ax2.set_ylabel("change from rest [%]")
ax2.legend(fontsize="small")
fig.suptitle("6208, Fr = 3000 N")
fig.tight_layout()
