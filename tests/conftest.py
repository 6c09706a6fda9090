import importlib.util
import os
import subprocess
import sys
from pathlib import Path

import pytest

from exudyn_bearing import catalog
from exudyn_bearing._jit import COMPILE_NOTICE

ROOT = Path(__file__).resolve().parents[1]
#: Paths a test run may touch in the working tree: Python and numba caches
#: (numba writes its compiled kernels beside the sources), pytest's cache,
#: the editable install's metadata and the virtual environment.
_CACHE_PARTS = ("__pycache__", ".pytest_cache", ".venv", ".egg-info")


def working_tree_changes(root=ROOT):
    """Set of (``git status --porcelain`` line, mtime) of the changed,
    untracked and ignored files (one by one) outside the caches; None outside
    a git work tree."""
    try:
        out = subprocess.run(["git", "-C", str(root), "status", "--porcelain=v1", "--untracked-files=all",
                              "--ignored=traditional", "-z"], capture_output=True, text=True, timeout=60)
    except (OSError, subprocess.SubprocessError):
        return None
    if out.returncode != 0:
        return None
    entries = [e for e in out.stdout.split("\0") if e and not any(part in e for part in _CACHE_PARTS)]

    def mtime(entry):
        try:
            return (root / entry[3:]).stat().st_mtime_ns
        except OSError:
            return None
    return {(e, mtime(e)) for e in entries}


@pytest.fixture(scope="session", autouse=True)
def no_writes_into_the_working_tree():
    """Fail the session when a test wrote into the working tree (outputs
    belong in ``tmp_path``; Exudyn's default SimulationSettings, for one,
    write solution/coordinatesSolution.txt)."""
    before = working_tree_changes()
    yield
    if before is None or os.environ.get("EXUDYN_BEARING_ALLOW_TREE_WRITES"):
        return
    after = working_tree_changes()
    new = sorted({e for e, _ in (after or set()) - before})
    assert not new, f"the tests wrote into the working tree {ROOT}: {new}"


@pytest.fixture
def b6208():
    return catalog["6208"]


@pytest.fixture
def b7208():
    return catalog["7208"]


@pytest.fixture(scope="session")
def load_script():
    """Import a script of the repository (e.g. ``load_script("scenarios/papers_6208.py")``) as a module, with its
    folder on sys.path so that it finds its neighbours."""
    def load(relative):
        path = ROOT / relative
        spec = importlib.util.spec_from_file_location(path.stem, path)
        mod = importlib.util.module_from_spec(spec)
        sys.path.insert(0, str(path.parent))
        spec.loader.exec_module(mod)
        return mod
    return load


def error_lines(err):
    """The lines a command wrote on stderr, without numba's once-per-process
    compile notice (printed when the test happens to be the process's first
    run on a cold cache: a test must not depend on its place in the order)."""
    return [line for line in err.strip().splitlines() if line.strip() != COMPILE_NOTICE]


@pytest.fixture
def runaway(monkeypatch):
    """Every dynamic run (reference engine and Exudyn element) built while the
    fixture is active stops as runaway at its first check: the runaway limit
    on overlap / R_b is set below zero. A deterministic blow-up for the error
    path: whether a too-long step grows past the limit, and when, depends on
    the CPU's last bits (a 6-sub-step fast-mode run blew up on one machine
    and finished on another)."""
    from exudyn_bearing.model import layout
    from exudyn_bearing.solvers.element import element
    from exudyn_bearing.solvers.reference import engine

    def planted(scene_parameters):
        def build(*args, **kw):
            p = scene_parameters(*args, **kw)
            p[layout.P_MAX_OVERLAP] = -1.0
            return p
        return build

    for module in (element, engine):
        monkeypatch.setattr(module, "scene_parameters", planted(module.scene_parameters))


def stribeck_loads(radial_load, psi):
    """Ball loads [N] of a zero-clearance radial ball bearing under ``radial_load``
    with balls at the azimuths ``psi`` (psi = 0 along the load), from Stribeck's
    equations by hand: Q_i = Q_0 max(cos psi_i, 0)^1.5 (Hertz, rigid rings) and
    the force balance F_r = sum Q_i cos psi_i give Q_0 = F_r / sum max(cos psi_i, 0)^2.5;
    the contact stiffness cancels (Harris & Kotzalas ch. 7)."""
    import numpy as np

    c = np.clip(np.cos(np.asarray(psi, float)), 0.0, None)
    return radial_load * c ** 1.5 / np.sum(c ** 2.5, axis=-1, keepdims=True)


def hertz_stiffness_by_hand(r_x, r_y, e_prime):
    """K of Q = K delta^1.5 [N/m^1.5] by hand: k from Harris & Kotzalas eq. 6.27 with
    scipy's complete elliptic integrals, K = pi k E' sqrt(2 E R / (9 F^3)) (Hamrock & Brewe),
    R = R_x R_y / (R_x + R_y). Returns (K, k, F, E)."""
    import math

    from scipy import optimize, special

    target = (r_y / r_x - 1.0) / (r_y / r_x + 1.0)

    def g(k):
        m = 1.0 - 1.0 / k ** 2
        return ((k * k + 1.0) * special.ellipe(m) - 2.0 * special.ellipk(m)) / ((k * k - 1.0) * special.ellipe(m)) \
            - target
    k = optimize.brentq(g, 1.0 + 1e-9, 100.0, xtol=1e-14)
    m = 1.0 - 1.0 / k ** 2
    f, e = special.ellipk(m), special.ellipe(m)
    rr = r_x * r_y / (r_x + r_y)
    return math.pi * k * e_prime * math.sqrt(2.0 * e * rr / (9.0 * f ** 3)), k, f, e


def baseline(name):
    """``pytest.approx`` of the regression baseline ``name`` of tests/baselines.json, with
    its tolerance: a number the program computed at a reviewed state, NOT validation
    (tests/regen_baselines.py regenerates the file and says why each tolerance)."""
    import json

    entry = json.loads((ROOT / "tests" / "baselines.json").read_text())[name]
    return pytest.approx(entry["value"], rel=entry["rel"])
