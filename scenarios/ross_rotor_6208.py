"""A flexible rotor on two 6208 bearings in ROSS
=============================================

Our speed-dependent bearing coefficients against ROSS's empirical
ball-bearing element.

Rotor (ROSS, 6 DOF per node, Timoshenko beam elements with rotary inertia
and gyroscopic terms): a solid steel shaft 40 mm (the 6208's bore) x 600 mm
in 12 elements, a steel disk 250 mm x 40 mm wide (bore 40 mm, 14.9 kg) at
mid-span, a 6208 at each end (nodes 0 and 12). ROSS's ``steel`` (E = 211
GPa, rho = 7810 kg/m^3). Shaft 5.9 kg, rotor 20.8 kg.

Bearing load: each 6208 carries the rotor's weight share (102 N) plus a
stated radial load of 1000 N along gravity (a belt pull, say), F = 1102 N
along ROSS's -y.

* **Ours**: :func:`exudyn_bearing.bearing_coefficients` (quasi-static
  5-DOF solver; stiffness by central differences, damping of the contact
  model condensed over each ball, averaged over three ball-set positions)
  at 12 speeds 0 ... 1050 rad/s (10,000 rpm), exported with
  :func:`exudyn_bearing.outputs.ross.to_ross_bearing` (``load_angle =
  -pi/2``: our load direction x onto ROSS's -y), axial kzz, czz included.
* **ROSS's** ``BallBearingElement(n_balls=9, d_balls=12.7 mm, fs=F,
  alpha=0)``: k_yy = 13e6 Z^(2/3) D^(1/3) F^(1/3) cos^(5/3) alpha (the
  empirical fit ROSS cites from Friswell et al., Dynamics of Rotating
  Machines, 2010, pp. 182-185), k_xx = 0.51 k_yy for 9 balls (ROSS
  interpolates 0.46, 0.64, 0.73 for 8, 12, 16 balls), c = 1.25e-5 k, no
  speed dependence, no axial stiffness.
* **Rigid bearings** (k = 1e12 N/m, the same rotor) for the limit.

Prints both bearings' coefficients, the first lateral natural frequencies at
rest (with whirl direction and which plane moves), the critical speeds
(ROSS's ``run_critical_speed``, crossings of the 1x line) and the bounds of
the first mode: below both the rigid-bearing frequency of the shaft and the
rigid rotor on the two bearings (sqrt(2 k / m)), above Dunkerley's lower
bound 1/w^2 = 1/w_rb^2 + 1/w_rr^2.

Writes (``--out``, default scenarios/out/ross_rotor_6208): campbell.png
(damped natural frequencies and logarithmic decrements against speed for
both rotors, with the 1x line and the critical speeds) + campbell.csv,
results.json.

Results (``python scenarios/ross_rotor_6208.py``, about 30 s; every number
below is printed by it or stored in results.json):

* Stiffness at rest, load direction (vertical): ours 1.302e8 N/m against
  ROSS's 1.352e8 (ours / ROSS 0.963); across it (horizontal) 0.857e8
  against 0.694e8 (1.235): the fit's k_xx / k_yy = 0.51 for 9 balls is
  softer across the load than the Hertz load distribution at this load
  (0.66, phase-averaged; P_d = 0). Ours adds k_zz = 2.6e6 N/m axially.
  Damping: ours 57.5 / 23.0 N s/m (vertical / horizontal; boundary-
  lubricated contacts at rest: hysteretic damping), ROSS's default
  1.25e-5 k = 1690 / 868 N s/m, 29 and 38 times more.
* First lateral modes at rest: the shaft's bending under the disk dominates
  (rigid bearings: 572.4 rad/s; the rigid rotor on our bearings: 2869
  horizontal / 3536 vertical rad/s, on ROSS's 2582 / 3603), so the bearing
  model moves them by 0.4 % (horizontal: ours 562.0, ROSS 559.7 rad/s) and
  0.05 % (vertical: 565.5 and 565.8 rad/s), each inside its bounds.
* First critical speeds (crossings of the 1x line): ours 562.1 rad/s
  backward and 565.6 forward (5368 and 5401 rpm); ROSS's element 559.7 and
  565.8 rad/s (5344 and 5403 rpm). The next crossings lie above the
  coefficients' speed range (1050 rad/s), where ROSS extrapolates ours.
* The difference is in the damping: the log decrement of the first two
  modes at rest is 1.7e-5 / 1.9e-5 with ours and 9.7e-4 / 5.1e-4 with
  ROSS's default (57 and 27 times more); ours rises about 2.5-fold between
  600 and 1050 rad/s, where the loaded contacts leave boundary lubrication
  (squeeze film in the mixed regime). The disk's conical modes at rest: ours
  2605.7 / 2632.7 rad/s, ROSS 2587.1 / 2634.7 rad/s.

Command::

    python scenarios/ross_rotor_6208.py [--speeds 22] [--extra-load 1000] [--out DIR]
"""
import argparse
import json
import math
import time
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.outputs.jsonio import to_jsonable
from exudyn_bearing.outputs.plotting import pyplot, save_figure
from exudyn_bearing.outputs.ross import to_ross_bearing

ROOT = Path(__file__).resolve().parent
SHAFT_LENGTH, SHAFT_DIAMETER, N_ELEMENTS = 0.6, 0.040, 12
DISK_DIAMETER, DISK_WIDTH = 0.25, 0.040
W_MAX = 1050.0        # rad/s, 10,000 rpm
G = 9.81


def import_ross():
    from exudyn_bearing.outputs.ross import import_ross as quiet_import

    return quiet_import()


def rotor_parts(rs):
    steel = rs.steel
    le = SHAFT_LENGTH / N_ELEMENTS
    shaft = [rs.ShaftElement(le, idl=0.0, odl=SHAFT_DIAMETER, material=steel, n=i, shear_effects=True,
                             rotary_inertia=True, gyroscopic=True) for i in range(N_ELEMENTS)]
    disk = rs.DiskElement.from_geometry(n=N_ELEMENTS // 2, material=steel, width=DISK_WIDTH, i_d=SHAFT_DIAMETER,
                                        o_d=DISK_DIAMETER)
    mass = float(disk.m + sum(s.m for s in shaft))
    return shaft, disk, mass


def lateral_modes(rotor, speed=0.0, n=4):
    """First n lateral modes at a speed: damped frequency [rad/s], log decrement, whirl and the share of
    the horizontal (ROSS x) motion in the mode (1: horizontal, 0: vertical)."""
    modal = rotor.run_modal(speed, num_modes=2 * n + 8)
    rows = []
    ndof = rotor.number_dof
    for k in range(len(modal.wd)):
        v = modal.evectors[:, k]
        x = np.abs(v[0::ndof]).sum()
        y = np.abs(v[1::ndof]).sum()
        z = np.abs(v[2::ndof]).sum() if ndof >= 3 else 0.0
        if x + y < z:      # axial mode
            continue
        rows.append({"wd": float(modal.wd[k]), "wn": float(modal.wn[k]), "log_dec": float(modal.log_dec[k]),
                     "horizontal_share": float(x / (x + y))})
        if len(rows) == n:
            break
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--speeds", type=int, default=22, help="speeds of the Campbell diagram (0 ... 1050 rad/s)")
    ap.add_argument("--extra-load", type=float, default=1000.0, help="radial load per bearing besides the weight [N]")
    ap.add_argument("--out", default=str(ROOT / "out" / "ross_rotor_6208"))
    ap.add_argument("--no-critical", action="store_true", help="skip ROSS's critical-speed search")
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    t0 = time.perf_counter()
    rs = import_ross()
    shaft, disk, mass = rotor_parts(rs)
    load = mass * G / 2.0 + args.extra_load
    b = eb.catalog["6208"]
    speeds = np.linspace(0.0, W_MAX, 12)
    coeff = eb.bearing_coefficients(b, speeds, Fr=load, n_phases=3)
    ours = [to_ross_bearing(coeff, 0, load_angle=-math.pi / 2, tag="A"),
            to_ross_bearing(coeff, N_ELEMENTS, load_angle=-math.pi / 2, tag="B")]
    theirs = [rs.BallBearingElement(n=n, n_balls=b.n_balls, d_balls=2 * b.ball_radius, fs=load,
                                    alpha=b.free_contact_angle, tag=t) for n, t in ((0, "A"), (N_ELEMENTS, "B"))]
    rigid = [rs.BearingElement(n=n, kxx=1e12, kyy=1e12, cxx=0.0, tag=t) for n, t in ((0, "A"), (N_ELEMENTS, "B"))]
    # ROSS frame: y vertical (the load direction, our x), x horizontal (our y)
    k_ours = {"vertical": float(coeff.stiffness[0, 0, 0]), "horizontal": float(coeff.stiffness[0, 1, 1]),
              "axial": float(coeff.stiffness[0, 2, 2])}
    c_ours = {"vertical": float(coeff.damping[0, 0, 0]), "horizontal": float(coeff.damping[0, 1, 1])}
    k_ross = {"vertical": float(np.ravel(theirs[0].kyy)[0]), "horizontal": float(np.ravel(theirs[0].kxx)[0])}
    c_ross = {"vertical": float(np.ravel(theirs[0].cyy)[0]), "horizontal": float(np.ravel(theirs[0].cxx)[0])}
    print(f"rotor {mass:.2f} kg (disk {disk.m:.2f} kg); load per bearing {load:.1f} N (weight share "
          f"{mass * G / 2:.1f} N + {args.extra_load:g} N)")
    print(f"6208 at rest, ours: k vertical {k_ours['vertical']:.4g}, horizontal {k_ours['horizontal']:.4g}, axial "
          f"{k_ours['axial']:.4g} N/m; c {c_ours['vertical']:.3g} / {c_ours['horizontal']:.3g} N s/m")
    print(f"6208, ROSS BallBearingElement: k vertical {k_ross['vertical']:.4g}, horizontal {k_ross['horizontal']:.4g} "
          f"N/m; c {c_ross['vertical']:.4g} / {c_ross['horizontal']:.4g} N s/m")
    ratio = {k: k_ours[k] / k_ross[k] for k in ("vertical", "horizontal")}
    print(f"ours / ROSS: vertical {ratio['vertical']:.3f}, horizontal {ratio['horizontal']:.3f}")

    res = {"rotor": {"mass": mass, "disk_mass": float(disk.m), "shaft_length": SHAFT_LENGTH,
                     "shaft_diameter": SHAFT_DIAMETER, "disk_diameter": DISK_DIAMETER, "disk_width": DISK_WIDTH,
                     "elements": N_ELEMENTS},
           "load_per_bearing": load, "extra_load": args.extra_load, "k_ours": k_ours, "c_ours": c_ours,
           "k_ross": k_ross, "c_ross": c_ross, "stiffness_ratio": ratio, "coefficients": coeff.to_dict()}
    rotors = {"ours": rs.Rotor(shaft, [disk], ours), "ross": rs.Rotor(shaft, [disk], theirs),
              "rigid": rs.Rotor(shaft, [disk], rigid)}
    for name, rotor in rotors.items():
        modes = lateral_modes(rotor)
        res.setdefault("modes_at_rest", {})[name] = modes
        print(f"{name:>5} at rest: " + ", ".join(
            f"{m['wd']:.1f} rad/s ({'horizontal' if m['horizontal_share'] > 0.5 else 'vertical'}, log dec "
            f"{m['log_dec']:.3g})" for m in modes))
    # bounds of the first mode in each plane
    w_rb = res["modes_at_rest"]["rigid"][0]["wd"]
    bounds = {}
    for plane, key in (("horizontal", "horizontal"), ("vertical", "vertical")):
        for name, k in (("ours", k_ours[key]), ("ross", k_ross[key])):
            w_rr = math.sqrt(2.0 * k / mass)
            w_d = 1.0 / math.sqrt(1.0 / w_rb ** 2 + 1.0 / w_rr ** 2)
            first = next(m["wd"] for m in res["modes_at_rest"][name]
                         if (m["horizontal_share"] > 0.5) == (plane == "horizontal"))
            bounds[f"{name}_{plane}"] = {"first": first, "rigid_bearings": w_rb, "rigid_rotor": w_rr,
                                         "dunkerley": w_d, "inside": bool(w_d <= first <= min(w_rb, w_rr))}
            print(f"{name:>5} {plane:>10}: first mode {first:.1f} rad/s; Dunkerley {w_d:.1f} <= it <= "
                  f"min(rigid bearings {w_rb:.1f}, rigid rotor {w_rr:.1f})")
    res["bounds"] = bounds
    # Campbell diagrams
    sp = np.linspace(0.0, W_MAX, args.speeds)
    camp = {}
    for name in ("ours", "ross"):
        c = rotors[name].run_campbell(sp, frequencies=8)
        camp[name] = {"wd": np.asarray(c.wd), "log_dec": np.asarray(c.log_dec), "whirl": np.asarray(c.whirl_values)}
    if not args.no_critical:
        for name in ("ours", "ross"):
            cs = rotors[name].run_critical_speed(num_modes=12)
            wd = np.asarray(cs.wd())
            whirl = list(np.asarray(cs.whirl_direction))
            # whirl None: the axial mode (ours only); above W_MAX ROSS extrapolates our coefficients
            rows = [{"wd": float(w), "rpm": float(w * 30 / math.pi), "whirl": str(d),
                     "kind": "axial" if str(d) == "None" else "lateral", "within_range": bool(w <= W_MAX)}
                    for w, d in zip(wd, whirl)]
            res.setdefault("critical_speeds", {})[name] = rows
            print(f"{name:>5} lateral critical speeds up to {W_MAX:g} rad/s: " + ", ".join(
                f"{r['wd']:.1f} rad/s ({r['rpm']:.0f} rpm, {r['whirl']})" for r in rows
                if r["kind"] == "lateral" and r["within_range"]) + "; above (coefficients extrapolated by ROSS "
                "for ours): " + ", ".join(f"{r['wd']:.0f}" for r in rows if r["kind"] == "lateral"
                                          and not r["within_range"]) + " rad/s"
                + "".join(f"; axial {r['wd']:.1f} rad/s" for r in rows if r["kind"] == "axial"))
    res["campbell"] = {"speeds": sp, **{f"{n}_{k}": v for n, d in camp.items() for k, v in d.items()}}
    png = plot_campbell(sp, camp, res.get("critical_speeds", {}), out / "campbell.png")
    res["plot"] = str(png)
    res["wall_s"] = time.perf_counter() - t0
    (out / "results.json").write_text(json.dumps(to_jsonable(res), indent=1))
    print(f"written {png} (+ csv), {out / 'results.json'}; wall {res['wall_s']:.0f} s")
    return res


def plot_campbell(sp, camp, crit, png):
    plt = pyplot()
    fig, ax = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
    cols = {"speed_rad_s": sp}
    for j, (name, title) in enumerate((("ours", "our 6208 coefficients (quasi-static)"),
                                       ("ross", "ROSS BallBearingElement"))):
        d = camp[name]
        for m in range(d["wd"].shape[1]):
            whirl = d["whirl"][:, m]
            if not np.isfinite(whirl).any():
                continue  # the axial mode (no whirl): not a lateral mode
            fwd = np.nanmean(whirl) < 0.5
            color = f"C{len([k for k in cols if k.startswith(name + '_wd')]) % 10}"
            ax[0, j].plot(sp, d["wd"][:, m], "-" if fwd else "--", color=color, lw=1.2)
            ax[1, j].plot(sp, d["log_dec"][:, m], "-" if fwd else "--", color=color, lw=1.2)
            cols[f"{name}_wd_{m}"] = d["wd"][:, m]
            cols[f"{name}_logdec_{m}"] = d["log_dec"][:, m]
            cols[f"{name}_whirl_{m}"] = whirl
        ax[0, j].plot(sp, sp, "k-", lw=0.8, label="1x")
        for c in crit.get(name, []):
            if c["wd"] <= sp[-1] and c["kind"] == "lateral":
                ax[0, j].plot(c["wd"], c["wd"], "ko", ms=5)
        ax[0, j].plot([], [], "k-", lw=1.2, label="forward")
        ax[0, j].plot([], [], "k--", lw=1.2, label="backward")
        ax[0, j].set_ylim(0, 3000)
        ax[0, j].set_title(title, fontsize=9)
        ax[0, j].set_ylabel("damped natural frequency [rad/s]")
        ax[1, j].set_ylabel("log decrement")
        ax[1, j].set_yscale("log")
        ax[1, j].set_ylim(1e-6, 1.0)
        ax[1, j].set_xlabel("rotor speed [rad/s]")
        for a in ax[:, j]:
            a.grid(alpha=0.3)
        ax[0, j].legend(fontsize=8, loc="center right")
    fig.suptitle("Rotor 40 x 600 mm with a 250 mm disk on two 6208 (ROSS): lateral modes, critical speeds (dots)",
                 fontsize=10)
    return save_figure(fig, png, cols)


if __name__ == "__main__":
    main()
