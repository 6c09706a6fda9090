"""
Start-up of the 6208 in the reference engine
============================================

A short run of the numba DEM reference engine (:func:`eb.simulate <exudyn_bearing.simulate>`): the 6208 under
F_r = 3000 N, its inner ring run up from rest to 500 rad/s in 10 ms and held there for 60 ms. The figure shows
the cage speed against its kinematic value (pure rolling, 198.02 rad/s at 500 rad/s) and the largest inner
ball load, which varies as the nine balls pass the load line (one ball under the load, or two straddling it).
The table is the run's summary over the second half of the steady phase.

The papers' full protocol (0.3 s) is the repository's main job (README, :doc:`/getting_started`) and
``scenarios/papers_6208.py``. Settings, step limits and accuracy: :doc:`/reference_engine`; the model:
:doc:`/theory/dynamics`.
"""
import matplotlib.pyplot as plt

import exudyn_bearing as eb

sc = eb.Scenario(Fr=3000.0, omega=500.0, t_ramp_up=0.01, t_steady=0.06, t_end=0.07, dt=3e-6, sample_dt=1e-4)
run = eb.simulate("6208", sc)
s = run.summary()  # over the second half of the steady phase (s["window"]); s["steady"] judges it
u = s["units"]
print(f"window {s['window']['t0'] * 1e3:.1f} - {s['window']['t1'] * 1e3:.1f} ms, steady: {s['steady']['steady']}")
print(f"{'quantity':20s} {'run':>9s} {'pure rolling':>13s}")
print(f"{'cage speed':20s} {s['cage_speed']:9.2f} {s['kinematic_cage_speed']:13.2f}  {u['cage_speed']}")
print(f"{'ball spin':20s} {s['ball_spin']:9.2f} {s['kinematic_ball_spin']:13.2f}  {u['ball_spin']}")
print(f"{'q_max inner':20s} {s['q_max_inner']:9.1f} {'':13s}  {u['q_max_inner']}")
print(f"{'q_max outer':20s} {s['q_max_outer']:9.1f} {'':13s}  {u['q_max_outer']}")
print(f"{'Lambda_out at psi=0':20s} {s['lambda_outer_psi0']:9.3f}")
print(f"{int(s['steps'])} steps of {s['dt'] * 1e6:.0f} us in {s['wall_s']:.3f} s wall")

# %%
# Cage speed and the largest inner ball load against time.
t_ms = run.t * 1e3
fig, (ax1, ax2) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 4.8))
ax1.plot(t_ms, run.global_series("omega"), label="inner ring")
ax1.plot(t_ms, run.cage_speed_series(), label="cage")
ax1.axhline(s["kinematic_cage_speed"], ls=":", color="0.4", label="cage, pure rolling at 500 rad/s")
ax1.set_ylabel("speed [rad/s]")
ax1.legend(fontsize="small")
ax2.plot(t_ms, run.contact("load", "inner").max(axis=1))
ax2.set_xlabel("t [ms]")
ax2.set_ylabel("largest inner ball load [N]")
fig.suptitle("6208, Fr = 3000 N, 0 -> 500 rad/s in 10 ms, then steady")
fig.tight_layout()
