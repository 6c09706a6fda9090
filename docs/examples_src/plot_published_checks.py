"""
Two published checks: defect frequencies and load integrals
===========================================================

Two short validation cases against published numbers (the test suite asserts both, in
``tests/test_published_values.py``):

* the defect frequencies of the drive-end SKF 6205 of the Case Western Reserve University bearing data
  centre (9 balls, ball diameter 0.3126 in, pitch diameter 1.537 in), as multiples of the shaft speed, from
  :func:`defect_frequencies <exudyn_bearing.physics.kinematics.defect_frequencies>` against the data centre's
  published BPFI 5.4152, BPFO 3.5848 and BSF 2.357;
* the radial load integral J_r(eps) of a point-contact bearing (Sjovall's integral: the radial load over
  Z Q_max), from :func:`load_integral_radial <exudyn_bearing.physics.load_distribution.load_integral_radial>`
  against Harris & Kotzalas' Table 7.1 (*Rolling Bearing Analysis*, 5th ed.), where eps is the load-zone
  parameter (0.5: half the bearing loaded, 1: the zero-clearance case).

The relations: :doc:`/theory/kinematics` and :doc:`/theory/load_distribution`.
"""
import math

import matplotlib.pyplot as plt
import numpy as np

from exudyn_bearing.physics import kinematics
from exudyn_bearing.physics import load_distribution as ld

inch = 0.0254
f = kinematics.defect_frequencies(2.0 * math.pi, 0.0, 9, 0.3126 * inch / 2.0, 1.537 * inch / 2.0)
published = {"bpfi": 5.4152, "bpfo": 3.5848, "bsf": 2.357}
print("CWRU 6205, multiples of the shaft speed [-]")
print("line   computed  published  difference")
for key, value in published.items():
    print(f"{key:5s} {f[key]:9.4f} {value:10.4f} {f[key] - value:+11.1e}")

# %%
# Harris' table of J_r against the computed integral.
harris = {0.1: 0.1156, 0.3: 0.1892, 0.5: 0.2288, 0.8: 0.2559, 1.0: 0.2546, 1.25: 0.2289, 2.5: 0.1339,
          5.0: 0.0711}
print("\neps   J_r computed  J_r Harris Table 7.1")
for eps, j in harris.items():
    print(f"{eps:4.2f} {float(ld.load_integral_radial(eps)):12.4f} {j:12.4f}")

eps = np.linspace(0.05, 5.0, 200)
fig, (ax0, ax1) = plt.subplots(1, 2, figsize=(8.0, 3.4))
names = list(published)
ax0.bar(np.arange(3) - 0.2, [f[k] for k in names], width=0.4, label="computed")
ax0.bar(np.arange(3) + 0.2, [published[k] for k in names], width=0.4, label="CWRU, published")
ax0.set_xticks(range(3), [k.upper() for k in names])
ax0.set_ylabel("frequency / shaft speed [-]")
ax0.set_title("6205 defect frequencies")
ax0.legend(fontsize=8)
ax1.plot(eps, [float(ld.load_integral_radial(e)) for e in eps], label="computed")
ax1.plot(list(harris), list(harris.values()), "o", label="Harris Table 7.1")
ax1.set_xlabel("load-zone parameter eps [-]")
ax1.set_ylabel("J_r [-]")
ax1.set_title("radial load integral")
ax1.legend(fontsize=8)
fig.tight_layout()
plt.show()
