import importlib.util
import os
import sys
from pathlib import Path

import pytest

from exudyn_bearing import catalog
from exudyn_bearing._jit import COMPILE_NOTICE

ROOT = Path(__file__).resolve().parents[1]
#: Paths a test may write in the working tree: Python and numba caches (numba
#: writes its compiled kernels beside the sources), pytest's cache, the
#: editable install's metadata and the virtual environment.
_CACHE_PARTS = ("__pycache__", ".pytest_cache", ".venv", ".egg-info")
#: Audit events that write a path (their first argument; os.rename and
#: os.replace also their second). "open" is judged by its mode or flags.
_WRITE_EVENTS = ("os.mkdir", "os.rename", "os.replace", "os.remove", "os.rmdir", "shutil.rmtree", "os.symlink",
                 "os.link", "os.truncate", "os.chmod", "os.utime")
_WRITE_FLAGS = os.O_WRONLY | os.O_RDWR | os.O_CREAT | os.O_APPEND | os.O_TRUNC


class TreeWrites:
    """The paths under ``root`` that THIS process writes while ``active``,
    each with the id of the test that was running (``writes``), seen through
    a Python audit hook (PEP 578: every ``open`` for writing, ``os.mkdir``,
    ``os.remove``, ``os.rename``, ... raises an event with the path).

    The rule of the session guard, and why it is sound: every test runs with
    its own ``tmp_path`` as the current directory (:func:`tests_run_in_their_tmp_path`),
    so whatever a test, the package or Exudyn's C++ core writes under a
    relative name (Exudyn's default ``solution/coordinatesSolution.txt``, the
    command line's ``--out``, a figure) and every subprocess the test starts
    without its own ``cwd`` lands in pytest's temporary directories; the only
    way left into the clone is a path built from the clone's own location
    (``ROOT / ...``, ``__file__``), and that goes through Python's file calls,
    which this hook sees. A file that someone else writes into the clone
    during the run (the user running a README example from the repository
    root, an editor, another process) raises no event in this process and is
    not blamed on the tests. Caches (:data:`_CACHE_PARTS`) are allowed."""

    def __init__(self, root):
        self.root = os.path.join(os.path.abspath(root), "")
        self.active = False
        self.current = None
        self.writes = []

    def __call__(self, event, args):
        if not self.active:
            return
        if event == "open":
            path, mode, flags = args
            writing = any(c in mode for c in "wax+") if isinstance(mode, str) else bool((flags or 0) & _WRITE_FLAGS)
            paths = (path,) if writing else ()
        elif event in _WRITE_EVENTS:
            paths = args[:2] if event in ("os.rename", "os.replace") else args[:1]
        else:
            return
        for path in paths:
            if not isinstance(path, (str, bytes, os.PathLike)):
                continue  # a file descriptor: opened (and judged) before
            full = os.path.abspath(os.fsdecode(path))
            if full.startswith(self.root) and not any(part in full for part in _CACHE_PARTS):
                self.writes.append((self.current, full))


#: The session's guard; an audit hook cannot be removed, so it is installed once.
TREE_WRITES = TreeWrites(ROOT)
sys.addaudithook(TREE_WRITES)


@pytest.fixture(scope="session", autouse=True)
def no_writes_into_the_working_tree():
    """Fail the session when a test wrote into the working tree (outputs
    belong in ``tmp_path``): the paths :data:`TREE_WRITES` saw the tests write
    (see :class:`TreeWrites` for the rule). EXUDYN_BEARING_ALLOW_TREE_WRITES=1
    switches the check off (validation/consistency/mutation_run.py, whose copies of the
    tree are meant to change)."""
    TREE_WRITES.active = True
    yield
    TREE_WRITES.active = False
    if os.environ.get("EXUDYN_BEARING_ALLOW_TREE_WRITES"):
        return
    new = sorted({f"{test}: {os.path.relpath(path, ROOT)}" for test, path in TREE_WRITES.writes})
    assert not new, f"the tests wrote into the working tree {ROOT}: {new}"


@pytest.fixture(autouse=True)
def tests_run_in_their_tmp_path(request, tmp_path, monkeypatch):
    """Each test runs with its ``tmp_path`` as the current directory (relative
    outputs land there, not in the clone) and with the clone first on
    PYTHONPATH (a subprocess ``python -m exudyn_bearing`` started from there
    imports the package under test, not another installed copy)."""
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(p for p in (str(ROOT), os.environ.get("PYTHONPATH")) if p))
    TREE_WRITES.current = request.node.nodeid
    yield
    TREE_WRITES.current = None


def manual_pages(root=ROOT):
    """The pages a user reads: README.md (the front page) and docs/**/*.md (the
    guides and the theory; the README's former sections live there), not the
    built site under docs/_build."""
    return [root / "README.md", *sorted(p for p in (root / "docs").rglob("*.md") if "_build" not in p.parts)]


def manual_text(root=ROOT):
    """The text of :func:`manual_pages`, one after the other (a test that runs
    an example finds it by its first lines, wherever it lives)."""
    return "\n".join(p.read_text() for p in manual_pages(root))


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
