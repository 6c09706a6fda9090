"""
A bearing in an Exudyn model at the quasi-static level
======================================================

A rigid steel shaft (2.5 kg, turning at 500 rad/s) held by one 6208 whose outer ring is fixed to the ground,
under a static force of 1000 N along x and a force of 300 N turning with the shaft (an unbalance; its
amplitude rises over the first 5 ms so that it does not set the shaft ringing on the bearing). The bearing is
the quasi-static level of ``eb.CreateBallBearing`` (``model="quasistatic"``: the quasi-static ball equilibrium
at every evaluation, no ball degrees of freedom), solved by Exudyn's implicit GeneralizedAlpha at 1e-4 s. The
shaft starts at the operating point under the static force (``bearing.initialCoordinates``) and runs along an
orbit about it. The table compares the orbit with the linearised bearing: the stiffness along and across the
load (:func:`eb.bearing_coefficients <exudyn_bearing.solvers.quasistatic.coefficients.bearing_coefficients>`)
gives the semi-axes 300 N / k_xx and 300 N / k_yy of an ellipse.

The three bearing levels, their options, costs and checks: :doc:`/howto/rotor` and :doc:`/theory/levels`.
"""
import math

import exudyn as exu
import matplotlib.pyplot as plt
import numpy as np
from exudyn.utilities import InertiaCylinder, LoadForceVector, MarkerBodyRigid, ObjectGround

import exudyn_bearing as eb

OMEGA, F_STATIC, F_TURN = 500.0, 1000.0, 300.0  # rad/s, N, N

SC = exu.SystemContainer()
mbs = SC.AddSystem()
shaft = mbs.CreateRigidBody(inertia=InertiaCylinder(7850.0, 0.25, 0.02, axis=2),  # 2.5 kg steel shaft
                            nodeType=exu.NodeType.RotationRotationVector, initialAngularVelocity=[0, 0, OMEGA])
mShaft = mbs.AddMarker(MarkerBodyRigid(bodyNumber=shaft))
mHousing = mbs.AddMarker(MarkerBodyRigid(bodyNumber=mbs.AddObject(ObjectGround())))
mbs.AddLoad(LoadForceVector(markerNumber=mShaft, loadVector=[F_STATIC, 0, 0]))
mbs.AddLoad(LoadForceVector(markerNumber=mShaft, loadVector=[0, 0, 0], loadVectorUserFunction=lambda mbs, t, load: [
    F_TURN * min(t / 0.005, 1.0) * math.cos(OMEGA * t), F_TURN * min(t / 0.005, 1.0) * math.sin(OMEGA * t), 0.0]))
bearing = eb.CreateBallBearing(mbs, "6208", markerInnerRing=mShaft, markerOuterRing=mHousing, model="quasistatic",
                               initialOmega=OMEGA, initialLoad=(F_STATIC, 0.0))
node = mbs.GetObject(shaft)["nodeNumber"]
mbs.SetNodeParameter(node, "initialCoordinates", list(bearing.initialCoordinates))  # at the operating point
mbs.Assemble()
settings = bearing.SimulationSettings(endTime=0.04)  # GeneralizedAlpha at 1e-4 s
with eb.filter_exudyn_notes():
    mbs.SolveDynamic(settings, solverType=settings.timeIntegration.solverType)

out = bearing.samples()
t, x, y = out["t"], out["displacement"][:, 0], out["displacement"][:, 1]
last = t >= 0.015  # after the rise of the turning force: two revolutions of the shaft
k = eb.bearing_coefficients("6208", [OMEGA], Fr=F_STATIC).stiffness[0]
print(f"{'':28s} {'Exudyn':>9s} {'linearised':>11s}")
print(f"{'orbit centre x [um]':28s} {1e6 * (x[last].max() + x[last].min()) / 2:9.3f} "
      f"{1e6 * bearing.initialCoordinates[0]:11.3f}")
print(f"{'half width along x [um]':28s} {1e6 * np.ptp(x[last]) / 2:9.3f} {1e6 * F_TURN / k[0, 0]:11.3f}")
print(f"{'half width along y [um]':28s} {1e6 * np.ptp(y[last]) / 2:9.3f} {1e6 * F_TURN / k[1, 1]:11.3f}")
print(f"largest inner ball load {out['q_max_inner'][last].min():.0f} - {out['q_max_inner'][last].max():.0f} N; "
      f"{out['evaluations']} evaluations of the bearing in {len(t) - 1} samples")

# %%
# The orbit of the shaft centre (after the rise of the turning force) and its x against time.
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(8.0, 3.6))
ax1.plot(1e6 * x[last], 1e6 * y[last])
ax1.plot(1e6 * bearing.initialCoordinates[0], 1e6 * bearing.initialCoordinates[1], "k+", label="operating point")
ax1.set_aspect("equal", "datalim")
ax1.set_xlabel("x [um]")
ax1.set_ylabel("y [um]")
ax1.legend(fontsize="small", loc="upper right")
ax2.plot(1e3 * t, 1e6 * x)
ax2.set_xlabel("t [ms]")
ax2.set_ylabel("x [um]")
fig.suptitle("2.5 kg shaft on a 6208 at 500 rad/s: 1000 N + 300 N turning")
fig.tight_layout()
