"""The contact kernel's per-contact anchors of the film's logarithms and exponential
(``model.contact._ln_anchored``, ``_exp_anchored``, ``_film_hd_anchored``; cache columns of
``model.layout``): ln(1 + r) and exp(d) by their Taylor series about a cached anchor give the direct
relations (``math.log``, ``math.exp``, ``physics.ehl.film_hd_ln_g_k``) to round-off, within the reach
and out of it, from a zero cache and along drifting sequences, so do the Hertz constants re-evaluated from
their anchors (``_hertz_constants``: ln a_r, k, exp(-0.68 k)), and the kernel gives the same forces
from the anchors as from the direct relations (an empty cache, whose anchors all miss); a cache without
the geometry columns is refused."""
import math

import numpy as np
import pytest

from exudyn_bearing.model import layout as L
from exudyn_bearing.model.contact import (EXP_REACH, LN_REACH, _exp_anchored, _film_hd_anchored, _hertz_constants,
                                          _ln_anchored, scene_loss_path, scene_paths)
from exudyn_bearing.model.motion import ring_poses
from exudyn_bearing.physics import hertz
from exudyn_bearing.physics.hertz import _kfe_fast
from exudyn_bearing.physics.ehl import _film_hd_ln_g_k, film_hd_ellipticity_factor, film_thickness_hamrock_dowson
from exudyn_bearing.solvers.reference.engine import ReferenceEngine
from exudyn_bearing.solvers.reference.integrators import evaluate

import exudyn_bearing as eb

#: Round-off allowed between an anchored value and the direct one, as a multiple of the double-precision
#: unit round-off 2^-53 = 1.1e-16: the anchor's own rounding (half an ulp), the series' Horner steps (about
#: one ulp of the correction) and the final sum or product (half an ulp), against the direct function's
#: half ulp; 8 units leaves a factor 2 over the largest differences measured on the development machine
#: (2 units for ln, 4 for exp, over these arguments). The series' truncation (first omitted term below
#: 1.7e-17 at the reach) is under a fifth of one unit.
ULPS = 8 * 2.0 ** -53
#: Film from the anchors against the direct relation, relative: h = 3.63 exp(E) ... with |E| about 17-20,
#: where an ulp of E is 3.6e-15; each path rounds ln U (times 0.68), the products and the sums of E (a few
#: half-ulps of E each), so the two may lie up to about 1.2e-14 apart (5.6e-15 measured); the series
#: themselves are held to the ulp by the two tests before it, this one checks how the film uses the anchors.
FILM_REL = 2e-14


def _fresh():
    return np.zeros((1, 2, L.HZ_N))


def test_ln_anchored_equals_log_within_and_beyond_its_reach():
    for x0 in np.logspace(-299, 299, 41):
        hz = _fresh()
        assert _ln_anchored(x0, hz, 0, 1, L.HZ_LN_U) == pytest.approx(math.log(x0), rel=ULPS, abs=ULPS)
        anchor = hz[0, 1, L.HZ_LN_U:L.HZ_LN_U + 2].copy()
        for r in np.linspace(-0.999 * LN_REACH, 0.999 * LN_REACH, 37):
            x = x0 * (1.0 + r)
            # the error of ln x in absolute terms: half an ulp of |ln x| per rounding, and the product
            # x / x_0 to half an ulp of 1
            tol = ULPS * max(abs(math.log(x)), 1.0)
            assert abs(_ln_anchored(x, hz, 0, 1, L.HZ_LN_U) - math.log(x)) <= tol, (x0, r)
        assert np.array_equal(hz[0, 1, L.HZ_LN_U:L.HZ_LN_U + 2], anchor)  # all within reach: the anchor stays
        x = x0 * (1.0 + 1.5 * LN_REACH)  # beyond: math.log, and x the new anchor
        assert _ln_anchored(x, hz, 0, 1, L.HZ_LN_U) == pytest.approx(math.log(x), rel=ULPS, abs=ULPS)
        assert hz[0, 1, L.HZ_LN_U] == pytest.approx(1.0 / x, rel=ULPS)
    # a zero cache has no anchor: x = 1 (ln 0 would be the zero column) is a miss, not a hit at ln = 0 + r
    hz = _fresh()
    assert _ln_anchored(1.0 + 1e-3, hz, 0, 0, L.HZ_LN_W) == pytest.approx(math.log(1.0 + 1e-3), rel=ULPS)
    assert hz[0, 0, L.HZ_LN_W] != 0.0


def test_exp_anchored_equals_exp_within_and_beyond_its_reach():
    for e0 in np.linspace(-690.0, 690.0, 47):
        hz = _fresh()
        assert _exp_anchored(e0, hz, 0, 0, L.HZ_EXP) == pytest.approx(math.exp(e0), rel=ULPS)
        for d in np.linspace(-0.999 * EXP_REACH, 0.999 * EXP_REACH, 41):
            assert _exp_anchored(e0 + d, hz, 0, 0, L.HZ_EXP) == pytest.approx(math.exp(e0 + d), rel=ULPS), (e0, d)
        assert hz[0, 0, L.HZ_EXP] == e0
        e = e0 + 1.5 * EXP_REACH
        assert _exp_anchored(e, hz, 0, 0, L.HZ_EXP) == pytest.approx(math.exp(e), rel=ULPS)
        assert hz[0, 0, L.HZ_EXP] == e
    # a zero cache has no anchor: exp(0 + d) is not taken as 0 * (1 + d + ...)
    hz = _fresh()
    assert _exp_anchored(1e-3, hz, 0, 0, L.HZ_EXP) == pytest.approx(math.exp(1e-3), rel=ULPS)


E_PRIME, ETA, XI = 230.77e9, 0.04, 2.3e-8  # the 6208 example of physics.ehl (steel, the default oil)


def test_film_from_the_anchors_equals_the_hamrock_dowson_relation():
    # drifting speed and load of one contact, step by step (relative steps up to 3e-3 and jumps, so that
    # the anchors are hit, missed and moved), against the direct relation at every step. The film is
    # exp(E): both carry some ulps of E as relative round-off (FILM_REL)
    rng = np.random.default_rng(7)
    ln_g = math.log(XI * E_PRIME)
    for kappa, rx in ((7.29, 7.61e-3), (1.3, 2e-2), (12.0, 4e-3)):
        hz = _fresh()
        hz[0, 0, L.HZ_FILM_K] = film_hd_ellipticity_factor(kappa)
        u_r, q = 7.2475, 1457.0
        for step in range(3000):
            u_r *= 1.0 + 3e-4 * rng.standard_normal()
            q *= 1.0 + (0.3 if step % 500 == 0 else 3e-3) * rng.standard_normal()
            q = abs(q)
            h = _film_hd_anchored(hz, 0, 0, u_r, q, rx, E_PRIME, ETA, ln_g)
            direct = _film_hd_ln_g_k(u_r, q, rx, film_hd_ellipticity_factor(kappa), E_PRIME, ETA, ln_g)
            assert h == pytest.approx(direct, rel=FILM_REL), step
        # and the published form of the relation (the doctest's 6208 outer contact)
        ref = float(film_thickness_hamrock_dowson(u_r, q, rx, kappa, E_PRIME, ETA, XI))
        assert _film_hd_anchored(hz, 0, 0, u_r, q, rx, E_PRIME, ETA, ln_g) == pytest.approx(ref, rel=FILM_REL)
    # no load or no rolling: no film, as the direct relation
    hz = _fresh()
    assert _film_hd_anchored(hz, 0, 0, 0.0, 1000.0, 7.61e-3, E_PRIME, ETA, ln_g) == 0.0
    assert _film_hd_anchored(hz, 0, 0, 5.0, 0.0, 7.61e-3, E_PRIME, ETA, ln_g) == 0.0


def test_the_hertz_constants_from_the_anchors_equal_the_table_and_the_film_factor():
    # R_y/R_x of one contact drifting step by step (relative steps of 1e-4, as a contact angle under a
    # combined load, and jumps, so that the anchors of ln a_r, k and exp(-0.68 k) are hit, missed and
    # moved), for either orientation of the ellipse: k, F, E and the film's ellipticity factor against the
    # table's relation with the library's log and exp (hertz._kfe_fast) and ehl.film_hd_ellipticity_factor,
    # to FILM_REL (ln a_r's round-off times d(ln k)/d(ln a_r) reaches k; a wrong series term or anchor
    # would show at 1e-6 and above); a drift within the 1e-6 of the cache returns the cached constants
    table = hertz.exact_table()
    p = np.zeros(L.N_PARAMS)
    p[L.P_HERTZ] = hertz.EXACT
    rng = np.random.default_rng(11)
    for rx, ry in ((7.61e-3, 7.29 * 7.61e-3), (0.35, 4.2e-3), (1e-2, 1e-2)):
        hz = _fresh()
        hits = 0
        for step in range(2000):
            f = 1.0 + (0.2 if step % 400 == 399 else 1e-4) * rng.standard_normal()
            ry *= f
            before = hz[0, 0, L.HZ_LN_RATIO:L.HZ_EXP_FILM + 2].copy()
            ratio = hz[0, 0, L.HZ_RATIO]
            kappa, ell_f, ell_e = _hertz_constants(p, table, hz, 0, 0, rx, ry)
            if hz[0, 0, L.HZ_RATIO] == ratio:  # within the cache's 1e-6: the cached constants
                assert (kappa, ell_f, ell_e) == (hz[0, 0, L.HZ_K], hz[0, 0, L.HZ_F], hz[0, 0, L.HZ_E])
                continue
            hits += np.array_equal(before, hz[0, 0, L.HZ_LN_RATIO:L.HZ_EXP_FILM + 2])
            k0, f0, e0 = _kfe_fast(rx, ry, hertz.EXACT, table)
            assert (kappa, ell_f, ell_e) == pytest.approx((k0, f0, e0), rel=FILM_REL), step
            assert hz[0, 0, L.HZ_FILM_K] == pytest.approx(film_hd_ellipticity_factor(k0), rel=FILM_REL), step
        assert hits > 1500  # the steady drift runs on the anchors
        cached = _hertz_constants(p, table, hz, 0, 0, rx, ry * (1.0 + 5e-7))
        assert cached == (hz[0, 0, L.HZ_K], hz[0, 0, L.HZ_F], hz[0, 0, L.HZ_E])


@pytest.mark.parametrize("film", ["hd", "mk"])
def test_the_kernel_gives_the_same_forces_from_the_anchors_and_from_the_direct_relations(film):
    # the 6208 at 500 rad/s, analytic state: the film from the anchors (two evaluations on one cache, so
    # that the second hits them) against the direct relations (one evaluation on an empty cache: every
    # anchor misses and takes the library functions); every output within 1e-12 of its array's scale (the anchors' round-off,
    # 1e-14 of the film, reaches the forces through C_n; a wrong series term or anchor would show at the
    # scale of the lubrication's effect on the forces, 1e-3 and above)
    eng = ReferenceEngine("6208", eb.Scenario(Fr=3000.0, omega=500.0, dt=2e-6, film=film))
    st = eng.initial_state()
    z = eng.bearing.n_balls
    outs = []
    for calls in (2, 1):
        hz = np.zeros((z, 2, L.HZ_N))
        for _ in range(calls):
            out = {"fb": np.zeros((z, 3)), "tb": np.zeros((z, 3)), "fc": np.zeros((z, 3)), "fr": np.zeros((2, 6)),
                   "glob": np.zeros(L.NGLOBAL), "diag": np.zeros((z, 2, L.NDIAG)), "cage_load": np.zeros((z, 2))}
            evaluate(0.0, eng.params, eng.table, st["xb"].copy(), st["vb"].copy(), st["wb"].copy(), st["xc"].copy(),
                     st["vc"].copy(), st["ring"].copy(), ring_poses(), st["hist"].copy(), hz, out["fb"], out["tb"],
                     out["fc"], out["fr"], np.zeros(3), out["glob"], out["diag"], out["cage_load"], True,
                     *scene_paths(eng.params), scene_loss_path(eng.params))
        outs.append(out)
        if calls == 2 and film == "hd":
            assert np.any(hz[:, :, L.HZ_EXP + 1] > 0.0)  # the anchors were used
    a, b = outs
    assert np.any(a["diag"][:, :, L.D_HMIN] > 0.0)
    for k in ("fb", "tb", "fc", "fr", "glob", "diag"):
        scale = float(np.nanmax(np.abs(a[k])))
        assert np.allclose(a[k], b[k], rtol=1e-12, atol=1e-12 * scale, equal_nan=True), k


def test_a_cache_without_the_geometry_columns_is_refused_with_nan():
    # the kernel writes the contact geometry into the cache's HZ_GEO columns: a narrower cache would be
    # written beyond its end, so the kernel returns NaN (which every caller stops on) and leaves it alone
    eng = ReferenceEngine("6208", eb.Scenario(Fr=3000.0, omega=500.0, dt=2e-6))
    st = eng.initial_state()
    z = eng.bearing.n_balls
    hz = np.zeros((z, 2, L.HZ_GEO))
    worst = evaluate(0.0, eng.params, eng.table, st["xb"].copy(), st["vb"].copy(), st["wb"].copy(), st["xc"].copy(),
                     st["vc"].copy(), st["ring"].copy(), ring_poses(), st["hist"].copy(), hz, np.zeros((z, 3)),
                     np.zeros((z, 3)), np.zeros((z, 3)), np.zeros((2, 6)), np.zeros(3), np.zeros(L.NGLOBAL),
                     np.zeros((z, 2, L.NDIAG)), np.zeros((z, 2)), False, *scene_paths(eng.params),
                     scene_loss_path(eng.params))
    assert math.isnan(worst)
    assert not hz.any()
