"""The 7208 angular-contact bearing under F_r = F_a = 3000 N at 500 rad/s, both engines
====================================================================================

Runs the reference core and the Exudyn element on the same scene (analytic
start, torus cage, dt = 0.5 us) and draws the ball loads
and contact angles of the outer contacts against azimuth over the last half
of the run, with the discrete quasi-static solution (fixed outer ring,
combined load; docs/theory/reference_cases.md: the Stribeck law with
eps = (1 + delta_a tan(alpha)/delta_r)/2). Writes bearing_7208.png with a
CSV beside it and prints both summaries.

The 1 mm cage balls of the catalogue (33 mg, 4.5 um pocket clearance) set
the step: under the combined load the balls orbit at slightly different
speeds and press the cage balls with a few hundred newtons, so the run
needs dt <= 0.5 us (at 1 us it stops with a dt error after about 15 ms;
``python validation/consistency/fast_mode_checks.py`` measures both; the stable-step
estimate, which assumes cage loads of a tenth of the ball load, is
optimistic here).
``--no-cage`` runs without the cage (ball / ball contact) at 2 us.

Command::

    python scenarios/bearing_7208.py [--t-end 0.02]
"""
import argparse
from pathlib import Path

import numpy as np

import exudyn_bearing as eb
from exudyn_bearing.physics.load_distribution import static_equilibrium
from exudyn_bearing.outputs.plotting import label_azimuth_axes, pyplot, save_figure


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--t-end", type=float, default=0.02)
    ap.add_argument("--cage", action=argparse.BooleanOptionalAction, default=True, help="torus cage on/off")
    ap.add_argument("--out", default=str(Path(__file__).parent / "out" / "bearing_7208"))
    args = ap.parse_args(argv)
    sc = eb.Scenario(Fr=3000.0, Fa=3000.0, omega=500.0, t_end=args.t_end, dt=0.5e-6 if args.cage else 2e-6,
                     sample_dt=1e-4, cage=args.cage)
    runs = {e: eb.simulate("7208", sc, engine=e) for e in ("reference", "exudyn")}
    b = runs["reference"].bearing
    st = static_equilibrium(b, 3000.0, 3000.0)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    plt = pyplot()
    fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
    psi_a = np.degrees((st.psi + np.pi) % (2 * np.pi) - np.pi)
    order = np.argsort(psi_a)
    ax[0].plot(psi_a[order], st.q[order], "k-", label=f"quasi-static, eps = {st.eps:.3f}")
    ax[1].plot(psi_a[order], np.degrees(st.contact_angle[order]), "k-", label="quasi-static")
    cols = {}
    for e, m in (("reference", "o"), ("exudyn", "x")):
        r = runs[e]
        psi, q = r.azimuth_scatter("load", "outer")
        al = np.degrees(r.azimuth_scatter("contact_angle", "outer")[1])
        ax[0].plot(psi, q, m, ms=3, mfc="none", label=f"{e} engine")
        loaded = q > 0
        ax[1].plot(psi[loaded], al[loaded], m, ms=3, mfc="none", label=f"{e} engine")
        cols.update({f"psi_deg_{e}": psi, f"q_outer_N_{e}": q, f"alpha_outer_deg_{e}": al})
        s = r.summary()
        print(f"{e:9s}: q_max_inner {s['q_max_inner']:.0f} N, q_max_outer {s['q_max_outer']:.0f} N, "
              f"cage {s['cage_speed']:.2f} rad/s (kinematic {s['kinematic_cage_speed']:.2f}), "
              f"ball spin {s['ball_spin']:.1f} rad/s, Lambda_out(psi=0) {s['lambda_outer_psi0']:.2f}, "
              f"wall {s['wall_s']:.1f} s")
    print(f"quasi-static: q_max {st.q_max:.0f} N, eps {st.eps:.3f}, contact angles "
          f"{np.degrees(st.contact_angle[st.q > 0]).min():.1f}..{np.degrees(st.contact_angle[st.q > 0]).max():.1f} deg")
    label_azimuth_axes(ax, ("outer ball load Q [N]", "outer contact angle [deg]"))
    fig.suptitle("7208, Fr = Fa = 3000 N, 500 rad/s")
    save_figure(fig, out / "bearing_7208.png", cols, trim=True)
    print("figure:", out / "bearing_7208.png")


if __name__ == "__main__":
    main()
