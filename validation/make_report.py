"""Regenerate validation/REPORT.md: run every validation script, then join the sections the scripts write.

    python validation/make_report.py --fresh    # run everything from scratch (about 23 minutes on 2 cores), then write
    python validation/make_report.py            # the same, but sweeps resume from validation/out
    python validation/make_report.py --no-run   # write from the outputs already in validation/out (seconds)
    python validation/make_report.py --start-at bench_levels.py   # run from that script on, keep the earlier outputs

Each script with a section defines ``report_section(run) -> str`` next to the code that writes its data
(validation/README.md; helpers in validation/_report.py): this file runs the scripts (SCRIPTS, in run
order, each after a host-speed probe), records the machine and the wall times, and joins the sections in the
report's order (SECTIONS) under a head naming the machine, the probes and the wall times. The machines are
shared and noisy: wall times are medians where a script repeats runs, and ratios matter more than absolute
values.

The figures the report shows are copied from validation/out into validation/report_figures (tracked;
64-colour PNGs, a few tens of kB each) and embedded with a sentence each; figures no longer shown are removed.
"""
from __future__ import annotations

import argparse
import importlib
import json
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

import _report
from _report import PROBE_REPEAT, PROBE_T, Run, machine_sentence, probe_sentence

HERE = Path(__file__).resolve().parent
#: The scripts in run order: Run(script, arguments, tag); a tag names a second run of a script under other
#: arguments (its printout "<stem>_<tag>.stdout.txt", its section SECTIONS' (script, tag)).
SCRIPTS = [
    Run("bench_reference.py"),
    Run("bench_element.py", ("--ga",)),
    Run("cross_engine.py"),
    Run("peer_builtin.py"),
    Run("figures.py"),
    Run("work_precision.py"),
    Run("bench_sweep.py"),
    Run("fast_mode_checks.py"),
    Run("fast_mode_limits.py"),
    Run("fast_mode_limits.py", ("--Fr", "600", "--masses", "0.081", "1.25"), "600N"),
    Run("cage_step_checks.py"),
    Run("bench_overhead.py"),
    Run("profile_element.py"),
    Run("bench_element_ab.py"),
    Run("round_off_sensitivity.py"),
    Run("three_dof.py"),
    Run("quasistatic_acbb120.py"),
    Run("bench_quasistatic.py"),
    Run("bench_defects.py"),
    Run("stiffness_checks.py"),
    Run("bench_stiffness.py"),
    Run("highspeed_acbb120.py"),
    Run("bench_traction.py"),
    Run("consistency_matrix.py"),
    Run("traction_convergence.py"),
    Run("losses_6208_7208.py"),
    Run("losses_dynamic.py"),
    Run("reduced_engine.py"),
    Run("reduced_work_precision.py"),
    Run("reduced_level.py"),
    Run("thermal_nasa_d7870.py"),
    Run("bench_thermal.py"),
    Run("anomaly_checks.py"),
    Run("levels_checks.py"),
    Run("levels_published_vc.py"),
    Run("levels_work_precision.py"),
    Run("mutation_run.py", ("--quick",)),
    Run("profile_reference.py"),
    Run("profile_suite.py", ("--startup", "--repeat", "3")),
    Run("bench_levels.py", ("--repeat", "3")),
    Run("bench_qs_rotor.py", ("--repeat", "7")),
    Run("bench_kernel_ab.py"),
    Run("bench_kernel_ab.py", ("--cold", "3", "--baseline", "58652e8"), "cold"),
    Run("bench_kernel_ab.py", ("--baseline", "58652e8"), "session"),
    Run("bench_element_ab.py", ("--baseline", "58652e8"), "session"),
    Run("bench_element_ab.py", ("--baseline", "58652e8", "--mode", "fast"), "session_fast"),
]
#: The report's sections in order: the script whose ``report_section`` writes each, (script, tag) for a tagged
#: run. A script without one here (fast_mode_checks.py, bench_overhead.py) is read by another's section.
SECTIONS = [
    "bench_reference.py", "cage_step_checks.py", "bench_element.py", "fast_mode_limits.py",
    ("fast_mode_limits.py", "600N"), "cross_engine.py", "peer_builtin.py", "figures.py", "work_precision.py",
    "bench_sweep.py", "quasistatic_acbb120.py", "bench_quasistatic.py", "three_dof.py", "bench_defects.py",
    "stiffness_checks.py", "bench_stiffness.py", "highspeed_acbb120.py", "bench_traction.py",
    "consistency_matrix.py", "traction_convergence.py", "losses_6208_7208.py", "losses_dynamic.py",
    "reduced_engine.py", "reduced_work_precision.py", "reduced_level.py", "profile_element.py", "bench_element_ab.py", "levels_checks.py", "bench_levels.py",
    "bench_qs_rotor.py", "levels_published_vc.py", "levels_work_precision.py", "thermal_nasa_d7870.py", "bench_thermal.py", "anomaly_checks.py",
    "bench_kernel_ab.py", ("bench_kernel_ab.py", "session"), ("bench_element_ab.py", "session"),
    ("bench_element_ab.py", "session_fast"), ("bench_kernel_ab.py", "cold"), "profile_reference.py",
    "profile_suite.py", "round_off_sensitivity.py", "mutation_run.py",
]


def section_run(entry):
    """The run of SCRIPTS a SECTIONS entry names."""
    script, tag = (entry, None) if isinstance(entry, str) else entry
    found = [r for r in SCRIPTS if r.script == script and r.tag == tag]
    if len(found) != 1:
        raise SystemExit(f"SECTIONS names {entry!r}: {len(found)} runs of SCRIPTS match it (one is needed)")
    return found[0]


def script_module(script):
    """The module of validation script ``script`` (imported from its folder, which goes on sys.path: scripts
    import their neighbours)."""
    path = _report.script_path(script)
    if str(path.parent) not in sys.path:
        sys.path.insert(0, str(path.parent))
    module = importlib.import_module(path.stem)
    if Path(module.__file__).resolve() != path:
        raise SystemExit(f"{script}: 'import {path.stem}' finds {module.__file__}, not {path}")
    return module


def sections():
    """The sections of the report in order, each ``report_section(run)`` of its script (empty ones left out)."""
    out = []
    for entry in SECTIONS:
        run = section_run(entry)
        text = script_module(run.script).report_section(run)
        if text:
            out.append(text)
    return out


def machine_facts():
    """The machine a run measured on: CPU model (/proc/cpuinfo where there is one), logical cores, and the
    load average now (os.getloadavg; None where the system has none)."""
    cpu = platform.processor() or platform.machine()
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                cpu = line.split(":", 1)[1].strip()
                break
    except OSError:
        pass
    try:
        load = [round(x, 2) for x in os.getloadavg()]
    except (AttributeError, OSError):
        load = None
    return {"cpu": cpu, "cores": os.cpu_count(), "load": load, "time": time.strftime("%Y-%m-%d %H:%M")}


_probe_warm = []


def host_probe():
    """Steps per second of wall time of a short reference-engine run (PROBE_T, median of PROBE_REPEAT), in this
    process: how fast the shared host runs the engine right now (other jobs on it slow every script alike).
    The first call loads (or compiles) the kernels with a 1 ms run first."""
    import warnings

    import exudyn_bearing as eb
    from exudyn_bearing.solvers.reference import ReferenceEngine

    scene = dict(Fr=3000.0, omega=500.0, dt=8e-6, tangential="implicit", sample_dt=1e-3)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        if not _probe_warm:
            ReferenceEngine("6208", eb.Scenario(t_end=1e-3, **scene)).run()
            _probe_warm.append(True)
        steps = round(PROBE_T / scene["dt"])
        rates = [steps / ReferenceEngine("6208", eb.Scenario(t_end=PROBE_T, **scene)).run().wall_s
                 for _ in range(PROBE_REPEAT)]
    return float(np.median(rates))


def _record(name, resume):
    """The JSON record ``name`` under validation/out of a run being resumed ({} for a new run)."""
    path = _report.OUT / name
    return json.loads(path.read_text()) if resume and path.exists() else {}


def run_all(skip=(), start_at=None):
    """Run SCRIPTS (from ``start_at`` on, without those in ``skip``), each after a host-speed probe, keeping
    what each printed; write the wall times, the probes and the machine's facts under validation/out."""
    out = _report.OUT
    walls, machine = _record("make_report_walls.json", start_at), _record("make_report_machine.json", start_at)
    machine.setdefault("start", machine_facts())
    machine.pop("end", None)
    (out / "make_report_machine.json").write_text(json.dumps(machine, indent=2))
    (out / "make_report_walls.json").write_text(json.dumps(walls, indent=2))
    first = [r.script for r in SCRIPTS].index(start_at) if start_at else 0
    probe = _record("make_report_probe.json", start_at) or {"probes": []}
    probe.pop("end", None)
    for run in SCRIPTS[first:]:
        if run.script in skip:
            continue
        probe["probes"] = [p for p in probe["probes"] if p[0] != run.key] + [[run.key, host_probe()]]
        (out / "make_report_probe.json").write_text(json.dumps(probe, indent=2))
        t0 = time.perf_counter()
        print(f"running {run.script} {' '.join(run.args)}", flush=True)
        proc = subprocess.run([sys.executable, str(run.path), *run.args], check=True, stdout=subprocess.PIPE,
                              text=True)
        print(proc.stdout, end="", flush=True)
        run.printout.write_text(proc.stdout)  # what Run.printed quotes
        walls[run.key] = time.perf_counter() - t0
        (out / "make_report_walls.json").write_text(json.dumps(walls, indent=2))  # kept for --start-at after a stop
    probe["end"] = host_probe()
    (out / "make_report_probe.json").write_text(json.dumps(probe, indent=2))
    machine["end"] = machine_facts()
    (out / "make_report_machine.json").write_text(json.dumps(machine, indent=2))


def head():
    """The report's title and the paragraphs on its run: the machine, the host-speed probes, the wall times."""
    lines = ["# Validation report", "",
             "Generated by `python validation/make_report.py` on "
             f"{time.strftime('%Y-%m-%d %H:%M')} ({platform.processor() or platform.machine()}, "
             f"Python {platform.python_version()}); every number below was printed by the command named in its "
             "section. The machines are shared and noisy: wall times are medians where repeated, ratios matter "
             "more than absolute values.", ""]
    walls = _record("make_report_walls.json", True)
    for sentence in (machine_sentence(_record("make_report_machine.json", True)),
                     probe_sentence(_record("make_report_probe.json", True))):
        if sentence:
            lines += [sentence, ""]
    if walls:
        lines += [f"Wall time of this regeneration: {sum(walls.values()) / 60:.0f} min in all; of each script: " +
                  ", ".join(f"{k} {v:.0f} s" for k, v in walls.items()) + ".", ""]
    return lines


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--no-run", action="store_true", help="only write the report from existing outputs")
    ap.add_argument("--fresh", action="store_true", help="delete validation/out first (sweeps otherwise resume)")
    ap.add_argument("--start-at", metavar="SCRIPT", choices=[r.script for r in SCRIPTS],
                    help="run the scripts from this one on (the earlier ones' outputs kept)")
    args = ap.parse_args(argv)
    if args.fresh and _report.OUT.exists():
        import shutil

        shutil.rmtree(_report.OUT)
    if not args.no_run:
        _report.OUT.mkdir(exist_ok=True)
        run_all(start_at=args.start_at)
    (HERE / "REPORT.md").write_text("\n".join(head() + sections()))
    _report.remove_unpublished()
    print(f"written {HERE / 'REPORT.md'}")


if __name__ == "__main__":
    main()
