"""
Load ratings and rating life
============================

The load ratings of the catalogue's radial ball bearings from their geometry (ISO 281's C, ISO 76's C_0, the
fatigue load limit C_u; for grooves looser than the standards assume, as the 7208's, C is scaled by the
conformity relation of ISO/TR 1281-1 and C_0 is the load that puts 4.2 GPa on a contact: the table's last
column says which) and the rating life of the 6208 against its radial load at 500 rad/s
(:func:`eb.rating_life <exudyn_bearing.physics.rating_life.rating_life>`): ISO 281's basic life L10h, its
modified life L10mh (a_ISO from the film parameter kappa of the bearing's oil, normal cleanliness) and, at a
few loads, ISO/TS 16281's modified reference life L10mrh from the computed load distribution
(:func:`eb.solve_quasistatic <exudyn_bearing.solvers.quasistatic.solve.solve_quasistatic>` at zero speed, the
standard's).

The relations, their sources and the comparison with the manufacturers' ratings: :doc:`/theory/rating_life`.
"""
import matplotlib.pyplot as plt
import numpy as np

import exudyn_bearing as eb

print("bearing    C [kN]   C0 [kN]   C_u [kN]   C0 from")
for name in ("6004", "6205", "6208", "7208"):
    r = eb.rating_life(name, (0.0, 0.0))
    print(f"{name:8s} {r.C / 1e3:8.2f} {r.C0 / 1e3:9.2f} {r.C_u / 1e3:10.3f}   {r.C0_method.split(' (')[0]}")

# %%
# The 6208's lives against the radial load at 500 rad/s.
omega = 500.0
loads = np.linspace(1000.0, 10000.0, 37)
lives = [eb.rating_life("6208", (fr, 0.0), omega=omega) for fr in loads]
reference_loads = [2000.0, 4000.0, 6000.0, 8000.0]
reference = [eb.rating_life("6208", eb.solve_quasistatic("6208", Fr=fr), omega=omega) for fr in reference_loads]

print(f"\n6208 at {omega:.0f} rad/s ({lives[0].n:.0f} r/min)")
print("Fr [N]    L10h [h]   L10mh [h]  L10mrh [h]")
for fr, r in zip(reference_loads, reference):
    print(f"{fr:6.0f} {r.L10h:11.0f} {r.L10mh:11.0f} {r.L10mrh:11.0f}")

fig, ax = plt.subplots(figsize=(6.4, 3.8))
ax.loglog(loads, [r.L10h for r in lives], label="L10h (ISO 281)")
ax.loglog(loads, [r.L10mh for r in lives], label="L10mh (ISO 281, a_ISO)")
ax.loglog(reference_loads, [r.L10mrh for r in reference], "o", label="L10mrh (ISO/TS 16281)")
ax.set_xlabel("radial load Fr [N]")
ax.set_ylabel("rating life [h]")
ax.set_title(f"6208 at {omega:.0f} rad/s, 90 % reliability")
ax.grid(True, which="both", alpha=0.3)
ax.legend()
fig.tight_layout()
