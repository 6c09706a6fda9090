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
