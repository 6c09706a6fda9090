"""Sweep runner: many scenarios in parallel, each result in its own file.

Cases run on local processes (all cores by default) or, given a scheduler
address, on a Dask distributed cluster (``pip install exudyn-bearing[dask]``).
Every finished case is written atomically (temporary file, then rename) to
``<out>/<name>.json`` and ``<out>/<name>.npz``, so an interrupted sweep
resumes where it stopped: cases whose JSON exists are not run again, and a
case is never half-written or duplicated. A progress line on stderr counts
the finished cases.

::

    cases = {f"Fr{fr:g}": dict(bearing="6208", scenario=dict(Fr=fr, omega=500, t_end=0.05, dt=5e-6))
             for fr in (750, 1500, 3000)}
    results = run_sweep(cases, "out/load_sweep")
    results["Fr3000"]["summary"]["q_max_outer"]
"""
from __future__ import annotations

import io
import json
import os
import sys
import tempfile
import time
from concurrent.futures import ProcessPoolExecutor, as_completed
from pathlib import Path

import numpy as np

from .data import Lubricant, load_bearing
from .model.scenario import Scenario
from .outputs.jsonio import to_jsonable
from .simulate import simulate

__all__ = ["run_sweep", "run_case", "load_case"]


def _atomic_write_bytes(path: Path, data: bytes) -> None:
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
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


def run_case(name: str, spec: dict, out_dir: str) -> str:
    """Run one case and write its files; returns the case name.

    ``spec``: ``bearing`` (name, JSON path or dict), ``scenario`` (Scenario
    keyword arguments), optional ``engine`` ('reference' or 'exudyn') and
    ``lubricant`` (Lubricant keyword arguments). The NPZ holds the last half
    of the sampled series needed for azimuth plots (and the whole signal
    series ``signal_t``, ``signal`` when the scenario records them); the JSON
    the summary and the spec.
    """
    out = Path(out_dir)
    lub = Lubricant(**spec["lubricant"]) if spec.get("lubricant") else None
    t0 = time.perf_counter()
    run = simulate(load_bearing(spec["bearing"]), Scenario(**spec["scenario"]),
                   engine=spec.get("engine", "reference"), lubricant=lub)
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
    record = {"name": name, "spec": spec, "summary": run.summary(), "wall_case_s": wall}
    # the JSON goes last: its presence marks the case as done
    _atomic_write_bytes(out / f"{name}.json", json.dumps(to_jsonable(record), indent=2).encode())
    return name


def load_case(out_dir, name: str) -> dict:
    """The JSON record of a finished case plus its arrays under ``arrays``."""
    out = Path(out_dir)
    rec = json.loads((out / f"{name}.json").read_text())
    with np.load(out / f"{name}.npz") as f:
        rec["arrays"] = {k: f[k] for k in f.files}
    return rec


def _progress(done, total, t0, stream):
    el = time.perf_counter() - t0
    width = 30
    n = int(width * done / max(total, 1))
    print(f"\r[sweep] |{'#' * n}{'.' * (width - n)}| {done}/{total} cases, {el:6.1f} s", end="", file=stream,
          flush=True)


def run_sweep(cases: dict, out_dir, workers: int | None = None, scheduler: str | None = None,
              progress: bool = True) -> dict:
    """Run every case of ``cases`` (name -> spec, see :func:`run_case`) not
    yet finished in ``out_dir``; returns name -> record for all cases.

    Parameters
    ----------
    workers : int, optional
        Local processes (default: all cores); 1 runs in this process.
    scheduler : str, optional
        Address of a Dask distributed scheduler (``tcp://host:8786``) or a
        ``distributed.Client``; the cases then run on its workers.
    """
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    for name in cases:
        if not name or any(c in name for c in "/\\") or name.startswith("."):
            raise ValueError(f"cases: invalid case name {name!r}")
    todo = [n for n in cases if not (out / f"{n}.json").exists()]
    total = len(cases)
    done = total - len(todo)
    t0 = time.perf_counter()
    stream = sys.stderr
    if progress:
        _progress(done, total, t0, stream)
    if todo:
        if scheduler is not None:
            from distributed import Client, as_completed as dask_completed

            client = scheduler if isinstance(scheduler, Client) else Client(scheduler)
            futures = [client.submit(run_case, n, cases[n], str(out), key=f"exudyn-bearing-{n}-{time.time_ns()}",
                                     pure=False) for n in todo]
            for fut in dask_completed(futures):
                fut.result()
                done += 1
                if progress:
                    _progress(done, total, t0, stream)
        elif (workers or os.cpu_count() or 1) == 1:
            for n in todo:
                run_case(n, cases[n], str(out))
                done += 1
                if progress:
                    _progress(done, total, t0, stream)
        else:
            with ProcessPoolExecutor(max_workers=workers or os.cpu_count()) as pool:
                futures = [pool.submit(run_case, n, cases[n], str(out)) for n in todo]
                for fut in as_completed(futures):
                    fut.result()
                    done += 1
                    if progress:
                        _progress(done, total, t0, stream)
    if progress:
        print(file=stream)
    return {n: load_case(out, n) for n in cases}
