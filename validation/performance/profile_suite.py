"""Where the test suite's time goes: wall and CPU time of every test, with a
cold and a warm numba cache.

The suite (or the pytest arguments given after ``--``) runs in a fresh
process with this file loaded as a pytest plugin (``-p profile_suite``),
which times each test's whole protocol (set-up, call, tear-down: a fixture
of a wider scope is charged to the first test that needs it): wall clock,
the process's CPU time and the CPU time of the child processes the test
waited for (the CLI and script tests run subprocesses).

Cold: ``NUMBA_CACHE_DIR`` a new temporary folder outside the repository,
so that every kernel compiles (as on CI's fresh clone, where only the
README's first ``simulate`` ran before pytest); warm: the same folder again,
now filled. Prints the top ``--top`` tests of each run and the totals, and
writes validation/out/profile_suite_{cold,warm}.csv (one row per test) and
pytest's output beside it (.log).
The machine's load (``os.getloadavg``) is printed before and after each run:
on a shared machine the wall clock counts the time other processes hold the
cores, the CPU times do not.

With ``--startup`` it times instead the start of fresh processes (median of
``--repeat``, wall and CPU, warm caches): ``import exudyn_bearing``, the
import of everything ``simulate`` and ``solve_quasistatic`` need,
``python -m exudyn_bearing --help`` and ``... info 6208``.

    python validation/performance/profile_suite.py [--runs cold warm] [--top 25] [-- tests/test_x.py -k y]
    python validation/performance/profile_suite.py --startup [--repeat 5]
"""
from __future__ import annotations

import argparse
import csv
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "validation" / "out"
FIELDS = ("nodeid", "outcome", "wall_s", "cpu_s", "child_cpu_s")

# ---------------------------------------------------------------- the plugin (runs inside pytest)
_rows = []


def _children_cpu():
    r = resource.getrusage(resource.RUSAGE_CHILDREN)
    return r.ru_utime + r.ru_stime


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item, nextitem):
    w0, c0, k0 = time.perf_counter(), time.process_time(), _children_cpu()
    outcomes = []
    item.stash[_OUTCOMES] = outcomes
    yield
    _rows.append({"nodeid": item.nodeid, "outcome": "+".join(o for o in outcomes if o != "passed") or "passed",
                  "wall_s": time.perf_counter() - w0, "cpu_s": time.process_time() - c0,
                  "child_cpu_s": _children_cpu() - k0})


_OUTCOMES = pytest.StashKey[list]()


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    report = (yield).get_result()
    outcomes = item.stash.get(_OUTCOMES, None)
    if outcomes is not None and (report.when == "call" or report.outcome != "passed"):
        outcomes.append(report.outcome)


def pytest_sessionfinish(session):
    path = os.environ.get("PROFILE_SUITE_CSV")
    if path:
        write_csv(Path(path), _rows)


# ---------------------------------------------------------------- the driver
def write_csv(path, rows):
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.3f}" if isinstance(v, float) else v) for k, v in r.items()})


def read_csv(path):
    with open(path, newline="") as f:
        return [dict(r, wall_s=float(r["wall_s"]), cpu_s=float(r["cpu_s"]), child_cpu_s=float(r["child_cpu_s"]))
                for r in csv.DictReader(f)]


def load():
    return "load average %.2f %.2f %.2f" % os.getloadavg()


def run(name, cache, pytest_args, top):
    """One pytest run with ``NUMBA_CACHE_DIR=cache``; prints its table, returns (wall, exit status)."""
    csv_path = OUT / f"profile_suite_{name}.csv"
    raw = Path(cache).parent / f"profile_suite_{name}_{os.getpid()}.csv"  # outside the tree (the tree guard)
    env = dict(os.environ, NUMBA_CACHE_DIR=str(cache), PROFILE_SUITE_CSV=str(raw),
               PYTHONPATH=os.pathsep.join([str(Path(__file__).parent), str(ROOT), os.environ.get("PYTHONPATH", "")]))
    print(f"\n== {name} numba cache ({cache}); before: {load()}", flush=True)
    k0 = _children_cpu()
    w0 = time.perf_counter()
    proc = subprocess.run([sys.executable, "-m", "pytest", "-q", "-p", "profile_suite", *pytest_args],
                          cwd=ROOT, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - w0
    cpu = _children_cpu() - k0
    OUT.mkdir(parents=True, exist_ok=True)
    (OUT / f"profile_suite_{name}.log").write_text(proc.stdout + proc.stderr)
    tail = proc.stdout.strip().splitlines()[-1:] or [proc.stderr.strip()[-300:]]
    print(f"pytest exit {proc.returncode}: {tail[0]}")
    rows = read_csv(raw) if raw.exists() else []
    raw.unlink(missing_ok=True)
    write_csv(csv_path, rows)
    rows.sort(key=lambda r: r["wall_s"], reverse=True)
    print(f"after: {load()}")
    print(f"{'test':92s} {'wall s':>7s} {'CPU s':>6s} {'child':>6s}")
    for r in rows[:top]:
        nodeid = r["nodeid"] if len(r["nodeid"]) <= 92 else r["nodeid"][:89] + "..."
        print(f"{nodeid:92s} {r['wall_s']:7.2f} {r['cpu_s']:6.2f} {r['child_cpu_s']:6.2f}")
    tests_wall = sum(r["wall_s"] for r in rows)
    print(f"{len(rows)} tests: {tests_wall:.1f} s wall in tests ({sum(r['cpu_s'] for r in rows):.1f} s CPU "
          f"+ {sum(r['child_cpu_s'] for r in rows):.1f} s in subprocesses); whole pytest process "
          f"{wall:.1f} s wall, {cpu:.1f} s CPU; csv: {csv_path.relative_to(ROOT)}")
    return wall, proc.returncode


#: ``--startup``: label -> the Python command line of one fresh process.
STARTUP = {"import exudyn_bearing": ["-c", "import exudyn_bearing"],
           "import + eb.simulate, eb.solve_quasistatic": ["-c", "import exudyn_bearing as eb; eb.simulate; "
                                                                  "eb.solve_quasistatic"],
           "python -m exudyn_bearing --help": ["-m", "exudyn_bearing", "--help"],
           "python -m exudyn_bearing info 6208": ["-m", "exudyn_bearing", "info", "6208"]}


def startup(repeat):
    """Median wall and CPU time of fresh processes (the :data:`STARTUP` command lines)."""
    import statistics

    env = dict(os.environ, PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")]))
    print(f"fresh processes, median of {repeat}; before: {load()}")
    for label, argv in STARTUP.items():
        walls, cpus = [], []
        for _ in range(repeat):
            k0, w0 = _children_cpu(), time.perf_counter()
            subprocess.run([sys.executable, *argv], cwd=ROOT, env=env, capture_output=True, check=True)
            walls.append(time.perf_counter() - w0)
            cpus.append(_children_cpu() - k0)
        print(f"{label:48s} wall {statistics.median(walls):5.2f} s  CPU {statistics.median(cpus):5.2f} s")
    print(f"after: {load()}")


def main(argv=None):
    argv = sys.argv[1:] if argv is None else argv
    extra = []
    if "--" in argv:
        i = argv.index("--")
        argv, extra = argv[:i], argv[i + 1:]
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--runs", nargs="+", choices=("cold", "warm"), default=["cold", "warm"],
                    help="cold: an empty numba cache; warm: the same cache again (after cold) or, alone, "
                         "a cache filled by one unreported run first")
    ap.add_argument("--top", type=int, default=25)
    ap.add_argument("--startup", action="store_true", help="time the start of fresh processes instead")
    ap.add_argument("--repeat", type=int, default=5, help="with --startup: processes per command")
    args = ap.parse_args(argv)
    if args.startup:
        startup(args.repeat)
        return 0
    status = 0
    with tempfile.TemporaryDirectory(prefix="numba_cache_") as cache:
        if args.runs == ["warm"]:
            print("filling the numba cache (one unreported run) ...", flush=True)
            subprocess.run([sys.executable, "-m", "pytest", "-q", *extra], cwd=ROOT, capture_output=True,
                           env=dict(os.environ, NUMBA_CACHE_DIR=cache,
                                    PYTHONPATH=os.pathsep.join([str(ROOT), os.environ.get("PYTHONPATH", "")])))
        for name in args.runs:
            _, rc = run(name, cache, extra, args.top)
            status = status or rc
    return status


def report_section(run):
    """The report's section: what this script printed in the report's run, introduced."""
    return run.printed(
        "Start-up of a fresh process",
        "Wall and CPU time of fresh processes with warm caches (medians): `import exudyn_bearing` (lazy: "
        "nothing loads until a public name is used), the imports `simulate` and `solve_quasistatic` need, "
        "`python -m exudyn_bearing --help` and `info 6208`. The suite's per-test profile, cold and warm numba "
        "cache: `python validation/performance/profile_suite.py` (not part of this run: it runs the whole suite twice).",
        last_lines=12)


if __name__ == "__main__":
    sys.exit(main())
