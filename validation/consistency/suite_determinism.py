"""Run the test suite in a shuffled order on a cold numba cache.

A test must pass in any order and whether or not the numba kernels are
already compiled (the first compiling run prints a notice on stderr, once per
process, which a test that counts stderr lines sees only when it happens to
run first). This script checks both at once:

* ``NUMBA_CACHE_DIR`` points at a fresh temporary directory, so every kernel
  compiles in this process (a cold cache, as on a fresh clone);
* the collected tests run in an order shuffled with a seeded random generator
  (no pytest plugin needed; the seed is printed, and ``--seed`` repeats an
  order). Module- and session-scoped fixtures stay valid: pytest sets them up
  again where a shuffled order leaves and re-enters a module.

Usage (from the repository root; about 10 min on the 2-core machine, the
compilation included)::

    python validation/consistency/suite_determinism.py            # a random seed
    python validation/consistency/suite_determinism.py --seed 7   # repeat an order
    python validation/consistency/suite_determinism.py --seed 7 -- tests/test_cli.py -x

Arguments after ``--`` go to pytest (default: the whole suite, ``-q``). The
exit status is pytest's.
"""
import argparse
import os
import random
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


class ShuffledOrder:
    """pytest plugin: shuffle the collected items with a seeded generator."""

    def __init__(self, seed):
        self.seed = seed

    def pytest_collection_modifyitems(self, session, config, items):
        random.Random(self.seed).shuffle(items)

    def pytest_report_header(self, config):
        return f"suite_determinism: tests shuffled with seed {self.seed}, NUMBA_CACHE_DIR={os.environ.get('NUMBA_CACHE_DIR')}"


def inner(seed, pytest_args):
    import pytest

    return pytest.main(pytest_args, plugins=[ShuffledOrder(seed)])


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--seed", type=int, default=None, help="shuffle seed (default: a random one, printed)")
    ap.add_argument("--inner", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("pytest_args", nargs="*", help="arguments for pytest (after --)")
    args = ap.parse_args(argv)
    pytest_args = args.pytest_args or ["-q", "-p", "no:cacheprovider"]
    if args.inner:
        return inner(args.seed, pytest_args)
    seed = args.seed if args.seed is not None else random.SystemRandom().randrange(2 ** 31)
    with tempfile.TemporaryDirectory(prefix="numba-cold-") as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache, PYTHONPATH=os.pathsep.join(
            p for p in (str(ROOT), os.environ.get("PYTHONPATH", "")) if p))
        print(f"suite_determinism: seed {seed}, cold numba cache in {cache}", flush=True)
        rc = subprocess.call([sys.executable, __file__, "--inner", "--seed", str(seed), "--", *pytest_args],
                             cwd=ROOT, env=env)
    print(f"suite_determinism: seed {seed}: pytest exit status {rc}", flush=True)
    return rc


if __name__ == "__main__":
    sys.exit(main())
