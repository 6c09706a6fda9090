"""Sweep runner: many scenarios in parallel, each result in its own file.

Cases run on local processes (all cores by default) or, given a scheduler
address, on a Dask distributed cluster (``pip install exudyn-bearing[dask]``).

Files in the output folder (each written atomically: a temporary file, then a
rename, with the usual permissions of the process umask, 0644 under umask
022):

``<name>.npz``, ``<name>.json``
    A finished case: the arrays, and the record ``{"name", "status": "done",
    "spec", "spec_hash", "summary", "wall_case_s", "warnings", "dt",
    "retries"}`` (written last: its presence marks the case as done).
``<name>.error.json``
    A failed case: ``{"name", "status": "failed", "spec", "spec_hash",
    "error": {"type", "message"}, "traceback", "wall_case_s", "warnings"}``
    (:data:`FAILED_RECORD_FIELDS`; ``wall_case_s`` null and ``warnings`` empty
    when the worker itself died, so that nothing was measured). It does not
    mark the case as done: the next run tries the case again (and removes the
    error record when the case then succeeds).
``index.json``, ``index.csv``
    Every case of the last call with its status (``done``, ``failed``, or
    ``pending`` when the sweep was stopped), ``spec_hash``, the error of a
    failed case, its warnings, and the parameters (``index.csv``: one row per
    case, the warning types separated by ``;`` in ``warnings``, the scenario
    parameters as ``scenario.<name>`` columns).

Resume: a case is done when its JSON exists and holds the hash of the same
spec (:func:`spec_hash`: the spec as written, with a bearing given as a JSON
file replaced by the file's content). A case whose spec changed under the
same name runs again: its old files are removed first and the change is
noted on stderr. A spec that changed only in how it is written (a default
spelled out) counts as changed; ``3000`` for ``3000.0`` does not.

A case that raises is recorded and the sweep goes on with the others; the
failures are listed on stderr at the end and in the index, and their
records come back with ``"status": "failed"``. The warnings of a case
(``{"type", "message"}`` in its record) go into the index with the case
(``index.json``: the list; ``index.csv``: their types) and are summarised at
the end on stderr, one line per warning type with the number of cases, the
first cases' names and the first line of one message (:func:`warning_summary`),
so that they do not break up the progress line. Ctrl-C or SIGTERM stop the sweep: queued cases are
cancelled, the worker processes terminated, the index written with the
unfinished cases ``pending``, and :class:`SweepInterrupted` (a
KeyboardInterrupt with the signal and the conventional exit status 130 or
143) raised. The workers end with the sweep's process even when it is
killed (SIGKILL): a death signal on Linux (``prctl(PR_SET_PDEATHSIG)``), a
watchdog thread elsewhere. A progress line on stderr counts the finished
cases.

::

    cases = {f"Fr{fr:g}": dict(bearing="6208", scenario=dict(Fr=fr, omega=500, t_end=0.05, dt=5e-6))
             for fr in (750, 1500, 3000)}
    results = run_sweep(cases, "out/load_sweep")
    results["Fr3000"]["summary"]["q_max_outer"]
"""
from __future__ import annotations

import csv
import dataclasses
import hashlib
import io
import json
import os
import signal
import sys
import threading
import time
import traceback
import uuid
import warnings
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

import numpy as np

import exudyn_bearing._jit as _jit  # its once-per-process compile notice (the workers leave it to the sweep)

from .data import InputError, catalog
from .model.contact import forces
from .model.scenario import Scenario
from .model.stability import SimulationError, StepSizeWarning
from .outputs.jsonio import to_jsonable
from .simulate import simulate, spec_inputs

__all__ = ["INDEX", "SweepInterrupted", "load_case", "run_case", "run_sweep", "spec_hash", "warning_summary",
           "warning_types"]

#: Index files of the last sweep in the output folder.
INDEX = ("index.json", "index.csv")


class SweepInterrupted(KeyboardInterrupt):
    """The sweep was stopped (Ctrl-C or SIGTERM); finished cases are kept and
    a later run resumes. ``signum``: the signal (``signal.SIGINT`` or
    ``signal.SIGTERM``); ``exit_status``: the conventional status of a
    process it stops, 128 + signum (130, 143)."""

    def __init__(self, message="sweep stopped", signum=signal.SIGINT):
        super().__init__(message)
        self.signum = int(signum)

    @property
    def exit_status(self) -> int:
        return 128 + self.signum


def _atomic_write_bytes(path: Path, data: bytes) -> None:
    """Write ``data`` to a temporary file beside ``path`` (created with mode
    0666 less the umask, as ``open`` does), then rename it to ``path``."""
    tmp = path.parent / f".{path.name}.{os.getpid()}.{uuid.uuid4().hex[:12]}.tmp"
    fd = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666)
    try:
        with os.fdopen(fd, "wb") as f:
            f.write(data)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def _write_json(path: Path, obj) -> None:
    _atomic_write_bytes(path, json.dumps(to_jsonable(obj), indent=2).encode())


def _canonical(obj):
    """JSON-like ``obj`` with integers as floats (3000 and 3000.0 are the same
    load) and tuples as lists."""
    if isinstance(obj, dict):
        return {str(k): _canonical(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [_canonical(v) for v in obj]
    if isinstance(obj, (int, np.integer)) and not isinstance(obj, (bool, np.bool_)):
        return float(obj)
    return to_jsonable(obj)


def _fields(obj):
    """A dataclass instance (a Scenario, its Defects and RigidCage, ...) as nested dicts of its fields."""
    if dataclasses.is_dataclass(obj) and not isinstance(obj, type):
        return {f.name: _fields(getattr(obj, f.name)) for f in dataclasses.fields(obj)}
    if isinstance(obj, (list, tuple)):
        return [_fields(v) for v in obj]
    return obj


def spec_hash(spec: dict) -> str:
    """SHA-256 (hex) of a case spec: its canonical JSON (sorted keys, numbers
    as floats), with a bearing given as a path to a JSON file replaced by the
    file's content, so that an edited bearing file re-runs its cases, and the
    scenario with every field (the defaults filled in), so that a case
    computed under other defaults (a changed default of the package) runs
    again rather than counting as done."""
    spec = dict(spec)
    scenario = spec.get("scenario", {})
    try:
        full = Scenario.from_dict(scenario)
        spec["scenario"] = _fields(full)
    except (InputError, TypeError):
        pass  # an invalid scenario: hashed as written (its case fails and is recorded)
    bearing = spec.get("bearing")
    if isinstance(bearing, (str, os.PathLike)) and str(bearing) not in catalog and Path(bearing).is_file():
        try:
            spec["bearing"] = json.loads(Path(bearing).read_text())
        except (OSError, ValueError):
            pass
    text = json.dumps(_canonical(spec), sort_keys=True, separators=(",", ":"))
    return hashlib.sha256(text.encode()).hexdigest()


def run_case(name: str, spec: dict, out_dir: str) -> str:
    """Run one case and write its files; returns the case name (raises what
    the case raises; :func:`run_sweep` records that instead).

    ``spec``: ``bearing`` (name, JSON path or dict), ``scenario`` (Scenario
    keyword arguments), optional ``engine`` ('reference', 'exudyn' or 'reduced'),
    ``lubricant`` (Lubricant keyword arguments) and ``refine`` (default 0):
    how many times a run that blows up (SimulationError) or warns that its
    step was unstable (StepSizeWarning, e.g. the cage loads it reached) is
    run again at half the step; the record holds the step of the kept run
    (``dt``), the ``retries`` (step and reason) and the kept run's
    ``warnings``. The NPZ holds the last half
    of the sampled series needed for azimuth plots (and the whole signal
    series ``signal_t``, ``signal`` when the scenario records them); the JSON
    the summary, the spec and its :func:`spec_hash`.
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        return _run_case(name, spec, out_dir, caught)


def _run_case(name, spec, out_dir, caught) -> str:
    """:func:`run_case` with the warnings caught so far in the list ``caught``
    (its record lists them under ``warnings``)."""
    out = Path(out_dir)
    key = spec_hash(spec)
    refine = spec.get("refine", 0)
    if not (isinstance(refine, int) and not isinstance(refine, bool) and 0 <= refine <= 6):
        raise InputError(f"refine: must be an integer in [0, 6] (times the step may be halved), got {refine!r}")
    # the one validation path of API, CLI, files and sweeps (unknown keys refused, lubricant by name/file/dict)
    inputs = spec_inputs({k: v for k, v in spec.items() if k != "refine"})
    bearing, sc, engine, lub = inputs["bearing"], inputs["scenario"], inputs["engine"], inputs["lubricant"]
    retries = []
    t0 = time.perf_counter()
    while True:
        mark = len(caught)
        try:
            # no progress line of the case's own: the sweep keeps one for all cases, and the automatic lines
            # of long cases on parallel workers would overwrite each other and the sweep's
            run = simulate(bearing, sc, engine=engine, lubricant=lub, progress=False)
            why = next((str(w.message) for w in caught[mark:] if issubclass(w.category, StepSizeWarning)), None)
        except SimulationError as exc:
            if len(retries) == refine:
                raise
            why = str(exc)
        if why is None or len(retries) == refine:
            break
        # a blow-up or a step the run found unstable: again at half the step (signals stay an integer multiple)
        retries.append({"dt": sc.dt, "reason": why})
        del caught[mark:]
        sc = sc.replace(dt=0.5 * sc.dt)
    wall = time.perf_counter() - t0
    w = run.window(0.5)
    arrays = {"t": run.t[w], "psi": run.azimuth()[w], "omega": run.global_series("omega")[w]}
    for race in ("inner", "outer"):
        for field in ("load", "overlap", "contact_angle", "h_min", "lambda", "regime", "srr", "u_r"):
            arrays[f"{field}_{race}"] = run.contact(field, race)[w]
    if "signal" in run.data:  # condition-monitoring signals (Scenario.signal_dt), whole: datasets.py
        arrays.update(signal_t=run.data["signal_t"], signal=run.data["signal"])
    buf = io.BytesIO()
    np.savez_compressed(buf, **arrays)
    _atomic_write_bytes(out / f"{name}.npz", buf.getvalue())
    record = {"name": name, "status": "done", "spec": spec, "spec_hash": key, "summary": run.summary(),
              "wall_case_s": wall, "warnings": _warning_list(caught), "dt": sc.dt, "retries": retries}
    # the JSON goes last: its presence marks the case as done
    _write_json(out / f"{name}.json", record)
    try:
        (out / f"{name}.error.json").unlink()
    except FileNotFoundError:
        pass
    return name


def warning_types(warns) -> str:
    """The distinct types of a case's warnings, in order, separated by ``;`` (a cell of ``index.csv``)."""
    return ";".join(dict.fromkeys(w["type"] for w in warns))


def _warning_list(caught) -> list:
    """The distinct warnings of a case as ``{"type", "message"}`` dicts, in order."""
    out = []
    for w in caught:
        item = {"type": w.category.__name__, "message": str(w.message)}
        if item not in out:
            out.append(item)
    return out


#: Fields of a failed case's record (``<name>.error.json``).
FAILED_RECORD_FIELDS = ("name", "status", "spec", "spec_hash", "error", "traceback", "wall_case_s", "warnings")


def _error_record(name, spec, exc, wall=None, warning_list=()):
    """The record of a failed case (:data:`FAILED_RECORD_FIELDS`); ``wall`` [s] None and no warnings when the
    worker died before it could report them."""
    return dict(zip(FAILED_RECORD_FIELDS, (
        name, "failed", spec, spec_hash(spec), {"type": type(exc).__name__, "message": str(exc)},
        "".join(traceback.format_exception(type(exc), exc, exc.__traceback__)), wall, list(warning_list))))


def _run_case_recorded(name: str, spec: dict, out_dir: str):
    """:func:`run_case`; an exception becomes ``<name>.error.json``.
    Returns (name, None, warnings) or (name, error record, warnings), the
    warnings of the case as in its record."""
    t0 = time.perf_counter()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        try:
            _run_case(name, spec, out_dir, caught)
            return name, None, _warning_list(caught)
        except Exception as exc:  # noqa: BLE001 - every failure of a case is recorded, the sweep goes on
            rec = _error_record(name, spec, exc, time.perf_counter() - t0, _warning_list(caught))
            _write_json(Path(out_dir) / f"{name}.error.json", rec)
            return name, rec, rec["warnings"]


def load_case(out_dir, name: str) -> dict:
    """The JSON record of a finished case plus its arrays under ``arrays``."""
    out = Path(out_dir)
    rec = json.loads((out / f"{name}.json").read_text())
    with np.load(out / f"{name}.npz") as f:
        rec["arrays"] = {k: f[k] for k in f.files}
    return rec


def _is_done(out: Path, name: str, key: str) -> bool:
    """The case's JSON exists and was written for the spec with hash ``key``
    (records from before the hash was stored: the hash of their spec)."""
    try:
        rec = json.loads((out / f"{name}.json").read_text())
        if not (out / f"{name}.npz").exists():
            return False
        stored = rec.get("spec_hash") or spec_hash(rec["spec"])
    except (OSError, ValueError, KeyError, TypeError, AttributeError):
        return False
    return stored == key


def _progress(done, total, t0, stream, failed=0):
    el = time.perf_counter() - t0
    width = 30
    n = int(width * done / max(total, 1))
    fail = f", {failed} failed" if failed else ""
    print(f"\r[sweep] |{'#' * n}{'.' * (width - n)}| {done}/{total} cases{fail}, {el:6.1f} s", end="",
          file=stream, flush=True)


def _record_warnings(out: Path, name: str) -> list:
    """The warnings kept in the record of a case finished by an earlier call (empty if unreadable)."""
    try:
        return list(json.loads((out / f"{name}.json").read_text()).get("warnings") or [])
    except (OSError, ValueError, AttributeError):
        return []


def warning_summary(case_warnings: dict, width: int = 200) -> list:
    """One line per warning type of a sweep: ``case_warnings`` maps a case
    name to its warnings (``{"type", "message"}``, as in its record); a line
    names the type, how many of the cases warned, the first of them, and the
    first line of its first message of that type (the line cut at ``width``
    characters; the index holds every case's messages)."""
    by_type = {}
    for name, warns in case_warnings.items():
        for w in warns:
            cases, _ = by_type.setdefault(w["type"], ([], w["message"]))
            if name not in cases:
                cases.append(name)
    lines = []
    for kind, (cases, message) in by_type.items():
        first = (message.strip().splitlines() or [""])[0]
        line = f"{kind} in {len(cases)} of {len(case_warnings)} cases (first {cases[0]}): {first}"
        lines.append(line if len(line) <= width else line[:width - 3] + "...")
    return lines


def _write_index(out: Path, cases: dict, keys: dict, status: dict, errors: dict, case_warnings: dict) -> None:
    entries = {}
    for n, spec in cases.items():
        e = {"status": status.get(n, "pending"), "spec_hash": keys[n], "spec": spec,
             "warnings": case_warnings.get(n, [])}
        if n in errors:
            e["error"] = errors[n]["error"]
        entries[n] = e
    failed = [n for n, e in entries.items() if e["status"] == "failed"]
    counts = {s: sum(e["status"] == s for e in entries.values()) for s in ("done", "failed", "pending")}
    _write_json(out / INDEX[0], {"counts": counts, "failed": failed, "cases": entries})
    scen_keys = sorted({k for spec in cases.values() if isinstance(spec.get("scenario"), dict)
                        for k in spec["scenario"]})
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["name", "status", "error_type", "error_message", "engine", "bearing", "spec_hash", "warnings"]
               + [f"scenario.{k}" for k in scen_keys])
    for n, spec in cases.items():
        e = entries[n]
        bearing = spec.get("bearing")
        scen = spec.get("scenario") if isinstance(spec.get("scenario"), dict) else {}
        w.writerow([n, e["status"], e.get("error", {}).get("type", ""), e.get("error", {}).get("message", ""),
                    spec.get("engine", "reference"),
                    bearing.get("name", "dict") if isinstance(bearing, dict) else bearing, keys[n],
                    warning_types(e["warnings"])]
                   + [to_jsonable(scen.get(k, "")) for k in scen_keys])
    _atomic_write_bytes(out / INDEX[1], buf.getvalue().encode())


class _StopOnSignal:
    """While active (main thread only): SIGTERM raises :class:`SweepInterrupted`
    like Ctrl-C raises KeyboardInterrupt."""

    def __enter__(self):
        self._installed = False
        if threading.current_thread() is threading.main_thread():
            def handler(signum, frame):
                raise SweepInterrupted(f"sweep stopped by {signal.Signals(signum).name}", signum)

            self._old = signal.signal(signal.SIGTERM, handler)
            self._installed = True
        return self

    def __exit__(self, *exc):
        if self._installed:  # None: a handler not set from Python; the default is the closest
            signal.signal(signal.SIGTERM, signal.SIG_DFL if self._old is None else self._old)
        return False


#: Seconds between two looks of a worker's watchdog at its parent.
WATCHDOG_INTERVAL = 0.5
_PR_SET_PDEATHSIG = 1  # linux/prctl.h


def _die_with_parent() -> bool:
    """Ask the kernel to SIGKILL this process when its parent dies (Linux
    ``prctl(PR_SET_PDEATHSIG)``); False where that is not available."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        import ctypes

        libc = ctypes.CDLL(None, use_errno=True)
        return libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0) == 0
    except (OSError, AttributeError):
        return False


def _parent_gone(parent: int, ppid: int) -> bool:
    """This process was re-parented (its parent ``ppid`` at start died) or the
    sweep's process ``parent`` no longer exists."""
    if os.getppid() != ppid:
        return True
    try:
        os.kill(parent, 0)
    except ProcessLookupError:
        return True
    except OSError:  # exists, another user's: not ours to judge
        pass
    return False


def _watch_parent(parent: int, ppid: int) -> None:
    """Watchdog thread of a worker (the fallback where no death signal is
    set): end the process once its parent is gone."""
    while not _parent_gone(parent, ppid):
        time.sleep(WATCHDOG_INTERVAL)
    os._exit(1)


def _worker_init(parent: int):
    """Worker initialiser: end with the sweep's process ``parent`` (a death
    signal on Linux, a watchdog thread as fallback), leave Ctrl-C to the
    parent (it reaches the whole process group; the parent terminates the
    workers) and take SIGTERM with its default action (the parent's handler
    is inherited at fork)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    _jit._announced = True  # the sweep said it once, on a line of its own (run_sweep), not over the progress line
    ppid = os.getppid()
    _die_with_parent()
    if _parent_gone(parent, ppid):  # the parent died before the death signal was set
        os._exit(1)
    threading.Thread(target=_watch_parent, args=(parent, ppid), name="sweep-parent-watchdog", daemon=True).start()


def _terminate_pool(pool: ProcessPoolExecutor) -> None:
    """Cancel the queued cases and terminate the worker processes now."""
    procs = list((getattr(pool, "_processes", None) or {}).values())
    pool.shutdown(wait=False, cancel_futures=True)
    for p in procs:
        if p.is_alive():
            p.terminate()
    for p in procs:
        p.join(5.0)
        if p.is_alive():
            p.kill()
            p.join(5.0)


def run_sweep(cases: dict, out_dir, workers: int | None = None, scheduler: str | None = None,
              progress: bool = True) -> dict:
    """Run every case of ``cases`` (name -> spec, see :func:`run_case`) not
    yet done in ``out_dir`` (see the module docstring: resume by spec hash,
    failure records, index); returns name -> record for all cases: the JSON
    record with its ``arrays`` for a finished case, the error record
    (``"status": "failed"``, ``"error": {"type", "message"}``) for a failed one.

    Parameters
    ----------
    workers : int, optional
        Local processes (default: all cores); 1 runs in this process.
    scheduler : str, optional
        Address of a Dask distributed scheduler (``tcp://host:8786``) or a
        ``distributed.Client``; the cases then run on its workers.
    progress : bool
        Progress line on stderr (the list of failures is printed regardless).

    Raises
    ------
    InputError
        An invalid case name (empty, with a path separator, or starting with a dot).
    SweepInterrupted
        Ctrl-C or SIGTERM; finished cases are kept, the index lists the rest as pending.
    """
    out = Path(out_dir)
    for name in cases:
        if not isinstance(name, str) or not name or any(c in name for c in "/\\") or name.startswith("."):
            raise InputError(f"cases: invalid case name {name!r} (non-empty, no path separator, no leading dot)")
    out.mkdir(parents=True, exist_ok=True)
    keys = {n: spec_hash(spec) for n, spec in cases.items()}
    status = {n: "done" for n in cases if _is_done(out, n, keys[n])}
    errors = {}
    case_warnings = {n: _record_warnings(out, n) for n in status}
    todo = [n for n in cases if n not in status]
    total = len(cases)
    t0 = time.perf_counter()
    stream = sys.stderr
    changed = [n for n in todo if (out / f"{n}.json").exists()]
    for n in changed:  # a result of another spec under this name: no longer valid
        for suffix in (".json", ".npz"):
            (out / f"{n}{suffix}").unlink(missing_ok=True)
    if changed:
        print(f"[sweep] {len(changed)} case(s) changed their spec since their record and run again: "
              + ", ".join(changed[:10]) + (" ..." if len(changed) > 10 else ""), file=stream)

    def finished(name, err, warns=()):
        status[name] = "failed" if err else "done"
        if err:
            errors[name] = err
        case_warnings[name] = list(warns)  # into the index and the summary at the end, not over the progress line
        if progress:
            _progress(len(status), total, t0, stream, len(errors))

    if todo:  # a cold numba cache: said once here, before the progress line, not by every worker over it
        _jit.announce_compilation(forces)
    if progress:
        _progress(len(status), total, t0, stream)
    try:
        with _StopOnSignal():
            if not todo:
                pass
            elif scheduler is not None:
                _run_dask(cases, todo, out, scheduler, finished)
            elif (workers or os.cpu_count() or 1) == 1:
                for n in todo:
                    finished(*_run_case_recorded(n, cases[n], str(out)))
            else:
                _run_pool(cases, todo, out, workers or os.cpu_count(), finished)
    except SweepInterrupted:
        raise
    except KeyboardInterrupt:
        raise SweepInterrupted("sweep stopped by SIGINT", signal.SIGINT) from None
    finally:
        if progress:
            print(file=stream)
        _write_index(out, cases, keys, status, errors, case_warnings)
    summary = warning_summary({n: case_warnings.get(n, []) for n in cases if n in status})
    if summary:
        print(f"[sweep] warnings (each case's in {INDEX[0]} and <name>.json in {out}):", file=stream)
        for line in summary:
            print(f"  {line}", file=stream)
    if errors:
        print(f"[sweep] {len(errors)} of {total} cases failed (records <name>.error.json and {INDEX[0]} in "
              f"{out}):", file=stream)
        for n, e in errors.items():
            print(f"  {n}: {e['error']['type']}: {e['error']['message']}", file=stream)
    return {n: errors[n] if n in errors else load_case(out, n) for n in cases}


def _run_pool(cases, todo, out, workers, finished):
    pool = ProcessPoolExecutor(max_workers=workers, initializer=_worker_init, initargs=(os.getpid(),))
    try:
        futures = {pool.submit(_run_case_recorded, n, cases[n], str(out)): n for n in todo}
        for fut in as_completed(futures):
            n = futures[fut]
            try:
                finished(*fut.result())
            except Exception as exc:  # noqa: BLE001 - the worker died (killed, out of memory): record it
                rec = _error_record(n, cases[n], exc)
                _write_json(out / f"{n}.error.json", rec)
                finished(n, rec)
    except BaseException:
        _terminate_pool(pool)
        raise
    pool.shutdown(wait=True)


def _run_dask(cases, todo, out, scheduler, finished):
    from distributed import Client, as_completed as dask_completed

    client = scheduler if isinstance(scheduler, Client) else Client(scheduler)
    futures = {client.submit(_run_case_recorded, n, cases[n], str(out), key=f"exudyn-bearing-{n}-{time.time_ns()}",
                             pure=False): n for n in todo}
    try:
        for fut in dask_completed(list(futures)):
            n = futures[fut]
            try:
                finished(*fut.result())
            except Exception as exc:  # noqa: BLE001 - the worker was lost: record it
                rec = _error_record(n, cases[n], exc)
                _write_json(out / f"{n}.error.json", rec)
                finished(n, rec)
    except BaseException:
        client.cancel(list(futures))
        raise
