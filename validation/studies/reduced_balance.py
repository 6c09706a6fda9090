"""Why the reduced engine's ball balance stops at its iteration limit: every Newton iterate of every balance logged.

The reduced engine (docs/theory/reduced.md) puts each ball centre on its normal force balance at every step by a
modified Newton iteration (``solvers/reduced/stepper.py``, ``_balance_sampled``); a balance that does not reach its
tolerance within ``MAX_ITER`` iterations is counted in the summary's ``unconverged_steps``. This study runs the
engine's own step loop and balance from their Python sources (``run_reduced.py_func``, ``_balance_sampled.py_func``:
the same code, no copy) over the compiled contact kernel, with the kernel's evaluation wrapped so that each
evaluation inside a balance is logged (the centres, the residual with the centres' inertia, the race overlaps, the
lubrication regimes, each ball's pocket force). For every balance at its limit it names the balls that did not
converge and classifies each by what its last iterates show:

* ``pocket onset``: the ball's pocket contact closes and opens between iterates;
* ``regime switch``: a race contact's lubrication regime (docs/theory/lubrication.md, the normal damping's table)
  changes between iterates;
* ``trust region``: its corrections are bounded by ``STEP_MAX`` (the balance asked for more);
* ``contact open``: a race contact is open in the last iterates;
* ``other``.

(a ball may have several), and prints the first ``--show`` of them iterate by iterate. Slow: the step loop runs in
Python (about a minute per thousand steps on the 2-core test host, after a few minutes of compilation).

    python validation/studies/reduced_balance.py [--case 7208|6208] [--dt 2e-5] [--t-end 0.02] [--show 2]
"""
from __future__ import annotations

import argparse
import math
import types
import warnings
from collections import Counter

import numba
import numpy as np

import exudyn_bearing as eb
from exudyn_bearing._jit import FASTMATH, InternalKernelDispatcher
from exudyn_bearing.model.layout import D_LOAD, D_REGIME, HZ_GEO, P_MB
from exudyn_bearing.solvers.reduced import engine as reduced_engine
from exudyn_bearing.solvers.reduced import stepper as st

#: The cases: the caged 7208 under combined load from its caged quasi-static equilibrium, and the 6208 radial with
#: its rigid cage (validation/consistency/reduced_engine.py)
CASES = {
    "7208": ("7208", dict(Fr=3000.0, Fa=3000.0, omega=500.0, cage="rigid", initial="quasistatic",
                          control="equilibrium")),
    "6208": ("6208", dict(Fr=3000.0, omega=500.0, cage="rigid")),
}
KINDS = ("pocket onset", "regime switch", "trust region", "contact open", "other")


def _callable(dispatcher):
    """A compiled copy of an internal kernel that Python can call (the internal one has no Python wrapper)."""
    return numba.njit(fastmath=FASTMATH, error_model="numpy")(dispatcher.py_func)


def _with_globals(fn, **names):
    """The Python function ``fn`` (its own code) with some of its module's names bound to others."""
    return types.FunctionType(fn.__code__, {**fn.__globals__, **names}, fn.__name__, fn.__defaults__,
                              fn.__closure__)


class BalanceLog:
    """The step loop and the balance from their Python sources, each evaluation inside a balance logged."""

    def __init__(self):
        self.balances = []  # per balance: dict(t, converged, iterations, evaluations=[...])
        self._current = None
        for name, obj in list(vars(st).items()):
            if isinstance(obj, InternalKernelDispatcher) and name not in ("_balance", "_balance_sampled"):
                setattr(st, name, _callable(obj))
        self._evaluate = st.reduced_evaluate
        # the balance's own code with the logging evaluation, the step loop's with the logging balance
        self._balance_sampled = _with_globals(st._balance_sampled.py_func, reduced_evaluate=self.evaluate)
        balance = _with_globals(st._balance.py_func, _balance_sampled=self.balance)
        reduced_engine.run_reduced = _with_globals(st.run_reduced.py_func, _balance=balance,
                                                   _balance_sampled=self.balance)

    def evaluate(self, t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb, tb, fc,
                 fr, fring, glob, diag, cage_load, want, res, acc, defect_path, ellipse_path, loss_path):
        worst = self._evaluate(t, dt, p, table, phi, om, wo, wb, q, q_old, ring, xb, vb, xc, vc, rings, hist, hz, fb,
                               tb, fc, fr, fring, glob, diag, cage_load, True, res, acc, defect_path, ellipse_path,
                               loss_path)
        c = self._current
        if c is not None:
            z = q.shape[0]
            r = res.copy()
            if c["inertia"] > 0.0:
                st._add_inertia(q, q_old, c["qref"], dt, c["inertia"] * p[P_MB], r)
            fbp, tbp, fcp = np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((z, 3))
            frp, globp, clp, sh = np.zeros((2, 6)), np.zeros(glob.shape[0]), np.zeros((z, 2)), np.zeros((z, 4))
            st._pocket_shares(p, xb, vb, wb, xc, vc, rings, fbp, tbp, fcp, frp, globp, clp, sh)
            c["evaluations"].append(dict(q=q.copy(), res=r, overlap=hz[:, :, HZ_GEO + 6].copy(),
                                         regime=diag[:, :, D_REGIME].copy(), load=diag[:, :, D_LOAD].copy(),
                                         pocket=np.linalg.norm(fbp, axis=1), phi=phi.copy()))
        return worst

    def balance(self, *args):
        """The balance (``_balance_sampled``'s arguments; before the balance carried the centres' inertia it took
        neither ``qref`` nor ``inertia``, so that the study runs on that code too), logged."""
        with_inertia = len(args) == 41
        qref, inertia = (args[-5], args[-4]) if with_inertia else (None, 0.0)
        self._current = dict(t=args[0], qref=None if qref is None else qref.copy(), inertia=inertia, evaluations=[])
        out = self._balance_sampled(*args)
        done = args[30]
        c, self._current = self._current, None
        c.update(converged=bool(out[1]), iterations=int(out[0]), open_balls=np.where(done < 0.5)[0])
        self.balances.append(c)
        return out


def iterates(balance):
    """The balance's iterates: its evaluations less those of its Jacobians (q perturbed by H_POS in one
    column from the iterate before)."""
    out = []
    for e in balance["evaluations"]:
        if out:
            d = np.abs(e["q"] - out[-1]["q"])
            if np.any(np.isclose(d, st.H_POS, rtol=1e-3)) and np.count_nonzero(d > 0.5 * st.H_POS) == d.shape[0]:
                continue
        out.append(e)
    return out


def kinds(its, j):
    """What the last iterates of ball j show (KINDS)."""
    last = its[-6:]
    found = []
    if len({bool(e["pocket"][j] > 0.0) for e in last}) > 1:
        found.append("pocket onset")
    if any(len({e["regime"][j, r] for e in last}) > 1 for r in range(2)):
        found.append("regime switch")
    steps = [np.linalg.norm(b["q"][j] - a["q"][j]) for a, b in zip(last, last[1:])]
    if steps and max(steps) > 0.99 * st.STEP_MAX:
        found.append("trust region")
    if any(np.any(e["overlap"][j] <= 0.0) for e in last):
        found.append("contact open")
    return found or ["other"]


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--case", choices=sorted(CASES), default="7208")
    ap.add_argument("--dt", type=float, default=2e-5, help="the reduced engine's step [s]")
    ap.add_argument("--t-end", type=float, default=0.02, help="simulated time [s]")
    ap.add_argument("--show", type=int, default=2, help="balances at the limit printed iterate by iterate")
    args = ap.parse_args(argv)
    log = BalanceLog()
    bearing, fields = CASES[args.case]
    sc = eb.Scenario(**fields, traction_level="ellipse", sample_dt=1e-4, t_end=args.t_end, dt=args.dt)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        res = eb.simulate(bearing, sc, engine="reduced")
    w = res.record.reduced_stats
    stuck = [b for b in log.balances if not b["converged"]]
    print(f"{bearing} {fields}, dt = {args.dt:g} s, {args.t_end:g} s: {res.steps} steps, {len(log.balances)} balances, "
          f"{len(stuck)} at the iteration limit (summary: unconverged_steps {w['unconverged_steps']}, "
          f"{w['evaluations_per_step']:.3g} evaluations and {w['newton_per_step']:.3g} Newton iterations per step)")
    count = Counter()
    largest = 0.0
    for b in log.balances:
        largest = max(largest, max(float(np.max(e["pocket"])) for e in b["evaluations"]))
    combos = Counter()
    for b in stuck:
        its = iterates(b)
        for j in b["open_balls"]:
            found = kinds(its, j)
            count.update(found)
            combos[" + ".join(found)] += 1
    print(f"balls at the limit by what their last iterates show: "
          + ", ".join(f"{k} {count[k]}" for k in KINDS)
          + f" (together: {'; '.join(f'{k} {n}' for k, n in combos.most_common()) or 'none'}); the largest pocket "
          f"force on a ball in any balance's iterates {largest:.4g} N")
    for b in stuck[:args.show]:
        its = iterates(b)
        for j in b["open_balls"]:
            psi = math.degrees(its[0]["phi"][j]) % 360.0
            print(f"\nt = {b['t'] * 1e3:.4f} ms, ball {j} (psi {psi:.1f} deg, inertia {b['inertia']:g}): "
                  f"{', '.join(kinds(its, j))}")
            for k, e in enumerate(its):
                print(f"  iterate {k:2d}: residual ({e['res'][j, 0]:+.4e}, {e['res'][j, 1]:+.4e}) N  overlaps "
                      f"({e['overlap'][j, 0] * 1e6:+.4f}, {e['overlap'][j, 1] * 1e6:+.4f}) um  loads "
                      f"({e['load'][j, 0]:.4g}, {e['load'][j, 1]:.4g}) N  regimes ({e['regime'][j, 0]:g}, "
                      f"{e['regime'][j, 1]:g})  pocket {e['pocket'][j]:.4g} N")


if __name__ == "__main__":
    main()
