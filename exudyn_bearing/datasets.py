"""Labelled condition-monitoring datasets: healthy and defective bearings over
a grid of speeds, loads and defect sizes, simulated on the sweep runner.

Every case is a reference-engine run that records the housing force and the
inner-ring acceleration at the sample rate ``fs`` (``Scenario.signal_dt``;
layout ``model.layout.SIGNAL_FIELDS``). :func:`build_dataset` runs the
cases through :func:`exudyn_bearing.sweep.run_sweep` (parallel, one
atomically written ``<case>.npz`` + ``<case>.json`` per case, resumable:
finished cases are not run again; progress on stderr, the cases' warnings
summarised at the end, one line per type) and writes ``index.csv``, one row
per finished case with its label, parameters and the types of its warnings
(``warnings``, separated by ``;``; the messages are in the sweep's
``index.json`` and the case's JSON)::

    from exudyn_bearing.datasets import build_dataset, load_case_signals
    rows = build_dataset("out/ds", speeds_rpm=(1797, 1750), loads=(500, 1000),
                         sizes=((1e-3, 1.5e-3, 1e-4),), t_end=0.2)
    t, x, row = load_case_signals("out/ds", rows[0]["name"], "outer_fx")

Each NPZ holds ``signal_t`` [s] and ``signal`` (n, NSIGNAL) besides the
sweep's per-contact series of the last half of the run; the JSON the
summary and the spec with its ``labels``. Faults (``FAULTS``, label codes in
``LABELS``): a healthy bearing, and one spall (:class:`exudyn_bearing.data.Defect`
of length x width x depth) in the middle of the outer race's load zone, on
the inner race (starting there and turning with the ring) or on ball 0.
"""
from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import numpy as np

from .data import Defect, InputError, load_bearing
from .model.layout import SIGNAL_FIELDS
from .model.scenario import Scenario
from .model.stability import stable_step
from .physics import kinematics
from .sweep import run_sweep, warning_types

__all__ = ["FAULTS", "LABELS", "INDEX_COLUMNS", "REFINE", "fault_defects", "signal_scenario", "dataset_cases",
           "build_dataset", "read_index", "load_case_signals"]

#: Fault kinds of a dataset, in label order.
FAULTS = ("healthy", "outer", "inner", "ball")
#: Integer label of each fault kind.
LABELS = {f: i for i, f in enumerate(FAULTS)}
#: Columns of ``index.csv``.
INDEX_COLUMNS = ("name", "file", "fault", "label", "bearing", "rpm", "load_N", "length_m", "width_m", "depth_m",
                 "fs_Hz", "t_end_s", "n_samples", "shaft_Hz", "ftf_Hz", "bpfo_Hz", "bpfi_Hz", "bsf_Hz",
                 "contact_angle_rad", "dt_s", "wall_s", "warnings")
#: Times a case that blows up or finds its step unstable is run again at half the step
#: (``refine`` of :func:`exudyn_bearing.sweep.run_case`).
REFINE = 2


def fault_defects(fault, length=1e-3, width=1.5e-3, depth=1e-4, position=None, ball=0, edge="sharp",
                  edge_radius=0.0) -> tuple:
    """The defects of a fault kind: () for "healthy", else one spall.

    ``position`` defaults to 0 on the races (the load direction: the middle
    of the load zone of the outer race, and where the inner-race spall starts)
    and to pi/2 on ball ``ball`` (a quarter turn before its outer contact,
    so that the run does not start with the spall under a contact).
    """
    if fault not in FAULTS:
        raise InputError(f"fault: must be one of {', '.join(FAULTS)}, got {fault!r}")
    if fault == "healthy":
        return ()
    if position is None:
        position = 0.5 * math.pi if fault == "ball" else 0.0
    return (Defect(fault, position, length, width, depth, edge=edge, edge_radius=edge_radius,
                   ball=ball if fault == "ball" else 0),)


def signal_scenario(fault="healthy", rpm=1797.0, load=1000.0, length=1e-3, width=1.5e-3, depth=1e-4, fs=48000.0,
                    t_end=0.5, steps_per_sample=4, **scenario) -> Scenario:
    """Scenario of one dataset case: inner ring at ``rpm`` [1/min] under the
    radial ``load`` [N] from the analytic start, the fault of
    :func:`fault_defects`, signals at ``fs`` [Hz] with ``steps_per_sample``
    steps per sample (dt = 1/(fs steps_per_sample); 4 at 48 kHz gives
    5.2 us), implicit tangential spring (lifts its step limit), state
    samples every millisecond. ``scenario``: further Scenario fields."""
    if not (isinstance(steps_per_sample, int) and steps_per_sample >= 1):
        raise InputError(f"steps_per_sample: must be an integer >= 1, got {steps_per_sample!r}")
    for name, v in (("rpm", rpm), ("fs", fs)):
        if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
            raise InputError(f"{name}: must be a number > 0, got {v!r}")
    signal_dt = 1.0 / float(fs)
    kw = dict(Fr=float(load), omega=float(rpm) * math.pi / 30.0, t_end=float(t_end),
              dt=signal_dt / steps_per_sample, signal_dt=signal_dt, sample_dt=max(1e-3, signal_dt),
              tangential="implicit", defects=fault_defects(fault, length, width, depth))
    kw.update(scenario)
    return Scenario(**kw)


def _case_name(fault, rpm, load, size):
    name = f"{fault}_rpm{rpm:g}_F{load:g}"
    if fault != "healthy":
        name += "_L{:g}_W{:g}_H{:g}".format(*(1e3 * v for v in size))  # mm
    return name.replace(".", "p")


def dataset_cases(bearing="6205", speeds_rpm=(1797.0,), loads=(1000.0,), sizes=((1e-3, 1.5e-3, 1e-4),),
                  faults=FAULTS, fs=48000.0, t_end=0.5, steps_per_sample=4, **scenario) -> dict:
    """Sweep cases (name -> spec for :func:`exudyn_bearing.sweep.run_sweep`) of
    the grid: every fault at every speed and load, the defective ones at
    every size (length, width, depth) [m], the healthy one once. Each spec
    carries its ``labels``.

    The step of a case is signal_dt / n with n the larger of
    ``steps_per_sample`` and what the case's own stable step
    (:func:`exudyn_bearing.model.stability.stable_step`) needs (unless
    ``scenario`` sets ``dt``); a case that blows up all the same (a large
    spall's impacts) or finds its step unstable during the run (the cage
    loads it reached) runs again at half the step, up to ``REFINE`` times
    (``refine`` of :func:`exudyn_bearing.sweep.run_case`)."""
    b = load_bearing(bearing)
    cases = {}
    for fault in faults:
        for rpm in speeds_rpm:
            for load in loads:
                for size in (sizes if fault != "healthy" else ((0.0, 0.0, 0.0),)):
                    size = tuple(float(v) for v in size)
                    if len(size) != 3:
                        raise InputError(f"sizes: each size is (length, width, depth) [m], got {size!r}")
                    geometry = dict(zip(("length", "width", "depth"), size)) if fault != "healthy" else {}
                    sc = signal_scenario(fault, rpm, load, fs=fs, t_end=t_end, steps_per_sample=steps_per_sample,
                                         **geometry, **scenario)
                    for d in sc.defects:
                        d.check(b)
                    if "dt" not in scenario:  # the case's own stable step, if below the one asked for
                        n = math.ceil(sc.signal_dt / stable_step(b, sc).dt * (1.0 - 1e-12))
                        if n > steps_per_sample:
                            sc = signal_scenario(fault, rpm, load, fs=fs, t_end=t_end, steps_per_sample=n,
                                                 **geometry, **scenario)
                    labels = {"fault": fault, "label": LABELS[fault], "rpm": float(rpm), "load_N": float(load),
                              "length_m": size[0], "width_m": size[1], "depth_m": size[2], "fs_Hz": float(fs),
                              "t_end_s": float(t_end)}
                    cases[_case_name(fault, rpm, load, size)] = dict(
                        bearing=bearing if isinstance(bearing, str) else b.to_dict(), scenario=_scenario_dict(sc),
                        labels=labels, refine=REFINE)
    return cases


def _scenario_dict(sc: Scenario) -> dict:
    """Scenario fields that differ from the defaults, JSON-able (defects as dicts)."""
    default = Scenario()
    out = {}
    for k in sc.__dataclass_fields__:
        v = getattr(sc, k)
        if k == "defects":
            if v:
                out[k] = [d.to_dict() for d in v]
        elif v != getattr(default, k):
            out[k] = list(v) if isinstance(v, tuple) else v
    return out


def build_dataset(out_dir, bearing="6205", speeds_rpm=(1797.0,), loads=(1000.0,), sizes=((1e-3, 1.5e-3, 1e-4),),
                  faults=FAULTS, fs=48000.0, t_end=0.5, steps_per_sample=4, workers=None, scheduler=None,
                  progress=True, **scenario) -> list:
    """Simulate the dataset grid (:func:`dataset_cases`) into ``out_dir`` and
    write ``index.csv``; returns its rows (dicts, ``INDEX_COLUMNS``), one
    per finished case.

    A case that fails is recorded as in a sweep (``<case>.error.json``, the
    sweep's ``index.json`` with its error, the list on stderr) and has no
    row; the index of the others is written all the same, and the next call
    runs the failed cases again. Resumable: cases whose files exist are not
    run again (run the same call after an interruption). ``workers``,
    ``scheduler``, ``progress``: see :func:`exudyn_bearing.sweep.run_sweep`.
    """
    cases = dataset_cases(bearing, speeds_rpm, loads, sizes, faults, fs, t_end, steps_per_sample, **scenario)
    records = run_sweep(cases, out_dir, workers=workers, scheduler=scheduler, progress=progress)
    b = load_bearing(bearing)
    rows = [_index_row(name, rec, b) for name, rec in records.items() if rec.get("status") == "done"]
    write_index(out_dir, rows)
    return rows


def _index_row(name, rec, bearing) -> dict:
    lab = rec["spec"]["labels"]
    arr = rec["arrays"]
    omega = float(np.mean(arr["omega"]))
    load, angle = arr["load_outer"], arr["contact_angle_outer"]
    alpha = float(np.mean(angle[load > 0.0])) if np.any(load > 0.0) else bearing.free_contact_angle
    f = kinematics.defect_frequencies(omega, 0.0, bearing.n_balls, bearing.ball_radius, bearing.pitch_radius, alpha)
    return {"name": name, "file": f"{name}.npz", "fault": lab["fault"], "label": lab["label"],
            "bearing": bearing.name, "rpm": lab["rpm"], "load_N": lab["load_N"], "length_m": lab["length_m"],
            "width_m": lab["width_m"], "depth_m": lab["depth_m"], "fs_Hz": lab["fs_Hz"],
            "t_end_s": lab["t_end_s"], "n_samples": int(len(arr["signal_t"])),
            "shaft_Hz": omega / (2.0 * math.pi), "ftf_Hz": f["ftf"], "bpfo_Hz": f["bpfo"], "bpfi_Hz": f["bpfi"],
            "bsf_Hz": f["bsf"], "contact_angle_rad": alpha,
            "dt_s": rec.get("dt", rec["spec"]["scenario"].get("dt")), "wall_s": rec.get("wall_case_s"),
            "warnings": warning_types(rec.get("warnings") or [])}


def write_index(out_dir, rows) -> Path:
    """Write ``index.csv`` (``INDEX_COLUMNS``) into ``out_dir``."""
    path = Path(out_dir) / "index.csv"
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=INDEX_COLUMNS)
        w.writeheader()
        for r in rows:
            w.writerow(r)
    return path


def read_index(out_dir) -> list:
    """Rows of a dataset's ``index.csv`` (numbers as floats, label as int)."""
    with open(Path(out_dir) / "index.csv", newline="") as f:
        rows = list(csv.DictReader(f))
    for r in rows:
        for k, v in r.items():
            if k in ("name", "file", "fault", "bearing", "warnings"):
                continue
            if k in ("label", "n_samples"):
                r[k] = int(v)
            else:
                r[k] = float(v) if v not in ("", "None") else None
    return rows


def load_case_signals(out_dir, name, signal="outer_fx"):
    """(t [s], series, labels) of one case's signal (``SIGNAL_FIELDS`` name)."""
    if signal not in SIGNAL_FIELDS:
        raise InputError(f"signal: unknown {signal!r} (valid: {', '.join(SIGNAL_FIELDS)})")
    out = Path(out_dir)
    with np.load(out / f"{name}.npz") as f:
        t, x = f["signal_t"], f["signal"][:, SIGNAL_FIELDS.index(signal)]
    labels = json.loads((out / f"{name}.json").read_text())["spec"]["labels"]
    return t, x, labels
