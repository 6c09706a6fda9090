"""Regenerate validation/REPORT.md: run every validation script, then write the report from their outputs.

    python validation/make_report.py --fresh    # run everything from scratch (a few minutes), then write
    python validation/make_report.py            # the same, but sweeps resume from validation/out
    python validation/make_report.py --no-run   # write from the JSON files already in validation/out

Each section names the command that produced it, the engine, the step and the
wall time. The machines are shared and noisy: wall times are medians where a
script repeats runs, and ratios matter more than absolute values.

The figures the report shows are copied from validation/out into
validation/report_figures (tracked; 64-colour PNGs, a few tens of kB each)
and embedded with a sentence each; figures no longer shown are removed.
"""
from __future__ import annotations

import argparse
import json
import math
import os
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from exudyn_bearing.physics.contact_slip import DEFAULT_N_ACROSS, DEFAULT_N_STRIPS

HERE = Path(__file__).resolve().parent
OUT = HERE / "out"
#: Tracked copies of the figures the report shows (REPORT.md links them relatively).
FIGURES = HERE / "report_figures"
#: Largest size of a published figure [bytes].
MAX_FIGURE_BYTES = 150_000
_published = []
SCRIPTS = [
    ("bench_reference.py", []),
    ("bench_element.py", ["--ga"]),
    ("cross_engine.py", []),
    ("peer_builtin.py", []),
    ("figures.py", []),
    ("work_precision.py", []),
    ("bench_sweep.py", []),
    ("fast_mode_checks.py", []),
    ("fast_mode_limits.py", []),
    ("fast_mode_limits.py", ["--Fr", "600", "--masses", "0.081", "1.25"], "600N"),
    ("cage_step_checks.py", []),
    ("bench_overhead.py", []),
    ("profile_element.py", []),
    ("bench_element_ab.py", []),
    ("round_off_sensitivity.py", []),
    ("three_dof.py", []),
    ("quasistatic_acbb120.py", []),
    ("bench_quasistatic.py", []),
    ("bench_defects.py", []),
    ("stiffness_checks.py", []),
    ("bench_stiffness.py", []),
    ("highspeed_acbb120.py", []),
    ("bench_traction.py", []),
    ("consistency_matrix.py", []),
    ("traction_convergence.py", []),
    ("losses_6208_7208.py", []),
    ("losses_dynamic.py", []),
    ("reduced_engine.py", []),
    ("thermal_nasa_d7870.py", []),
    ("bench_thermal.py", []),
    ("anomaly_checks.py", []),
    ("levels_checks.py", []),
    ("levels_published_vc.py", []),
    ("levels_work_precision.py", []),
    ("mutation_run.py", ["--quick"]),
    ("profile_reference.py", []),
    ("profile_suite.py", ["--startup", "--repeat", "3"]),
    ("bench_levels.py", ["--repeat", "3"]),
    ("bench_kernel_ab.py", []),
    # (script, arguments, tag): a second run of a script under another name (its printout "<stem>_<tag>")
    ("bench_kernel_ab.py", ["--cold", "3", "--baseline", "58652e8"], "cold"),
    ("bench_kernel_ab.py", ["--baseline", "58652e8"], "session"),
    ("bench_element_ab.py", ["--baseline", "58652e8"], "session"),
    ("bench_element_ab.py", ["--baseline", "58652e8", "--mode", "fast"], "session_fast"),
]


def script_path(script):
    """Path of the validation script named ``script``: in its purpose folder (validation/published,
    consistency, performance, studies; validation/README.md), or at the top level for one not yet sorted."""
    found = sorted(HERE.glob(f"*/{script}"))
    return found[0] if found else HERE / script


def script_command(script):
    """``validation/<folder>/<script>``, as a command names it (from the repository root)."""
    return script_path(script).relative_to(HERE.parent).as_posix()


def script_entry(entry):
    """(script, arguments, tag or None) of a SCRIPTS entry."""
    return (*entry, None) if len(entry) == 2 else tuple(entry)


def printout_name(script, tag=None):
    """File under OUT holding what ``script`` (run under ``tag``) printed in this run."""
    return f"{Path(script).stem}{'_' + tag if tag else ''}.stdout.txt"


def load(name):
    return json.loads((OUT / name).read_text())


def pct(x, digits=3):
    return "n/a" if x is None else f"{100 * x:.{digits}f} %"


def figure(src, sentence):
    """Markdown lines showing ``OUT / src`` (copied into FIGURES as a 64-colour
    PNG) with ``sentence`` below it; none if the script did not write it."""
    path = OUT / src
    if not path.exists():
        print(f"figure {src} missing: not in the report")
        return []
    from PIL import Image

    FIGURES.mkdir(exist_ok=True)
    target = FIGURES / path.name
    with Image.open(path) as im:
        small = im.convert("RGB").quantize(colors=64, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE)
        small.save(target, optimize=True)
    if target.stat().st_size > MAX_FIGURE_BYTES:
        raise SystemExit(f"{target}: {target.stat().st_size} bytes, above {MAX_FIGURE_BYTES}: lower the figure's dpi")
    _published.append(target.name)
    return [f"![{path.stem}]({FIGURES.name}/{target.name})", "", f"*{path.name}*: {sentence}", ""]


def remove_unpublished():
    """Delete figures of FIGURES that this report no longer shows."""
    if FIGURES.exists():
        for f in FIGURES.glob("*.png"):
            if f.name not in _published:
                f.unlink()


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


#: The host-speed probe (:func:`host_probe`): the reference engine on bench_reference.py's scene (6208,
#: F_r = 3000 N, 500 rad/s, implicit spring, dt 8 us) for PROBE_T simulated seconds, median of PROBE_REPEAT runs.
PROBE_T = 0.05
PROBE_REPEAT = 5
#: A script is named as disturbed when the probe before or after it is below this share of the run's fastest.
PROBE_SHARE = 0.85
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


def _probe_values(probes, end):
    """The probes of a run [steps/s]: each script's (``probes``: [(script, steps/s), ...]) and ``end`` (None:
    not taken)."""
    return [v for _s, v in probes] + ([end] if end is not None else [])


def disturbed_scripts(probes, end=None, share=PROBE_SHARE):
    """Scripts run while the host was slow: ``probes`` [(script, probe before it [steps/s]), ...] in run
    order, ``end`` the probe after the last one (None: not taken). A script's probes are the one before it
    and the next script's (or ``end``); it is named when the smaller is below ``share`` of the fastest probe
    of the run. Returns [(script, before, after), ...] (after None when not taken).

    >>> disturbed_scripts([("a", 100.0), ("b", 80.0), ("c", 99.0)], end=100.0)
    [('a', 100.0, 80.0), ('b', 80.0, 99.0)]
    """
    values = _probe_values(probes, end)
    if not values:
        return []
    best = max(values)
    out = []
    for i, (script, before) in enumerate(probes):
        after = probes[i + 1][1] if i + 1 < len(probes) else end
        low = before if after is None else min(before, after)
        if low < share * best:
            out.append((script, before, after))
    return out


def probe_sentence(record):
    """The report's sentence on the host-speed probes of a run (``record``: {"probes": [[script, steps/s],
    ...], "end": steps/s} as run_all writes it), or "" without probes."""
    probes = [tuple(p) for p in (record or {}).get("probes", [])]
    if not probes:
        return ""
    end = record.get("end")
    values = _probe_values(probes, end)
    bad = disturbed_scripts(probes, end)
    named = ("; ".join(f"{s} ({b:.3g} before, {'-' if a is None else f'{a:.3g}'} after)" for s, b, a in bad)
             if bad else "none")
    return (f"Host-speed probe (the reference engine on bench_reference.py's scene at 8 us, implicit spring, "
            f"{PROBE_T:g} s simulated, median of {PROBE_REPEAT} runs, steps per second of wall time, taken before "
            f"each script and at the end): fastest {max(values):.3g}, median {float(np.median(values)):.3g}, "
            f"slowest {min(values):.3g}. Scripts with a probe before or after them below {PROBE_SHARE:g} of the "
            f"fastest (the host was slower then: their wall times may be inflated, their ratios less so): {named}.")


def machine_sentence(machine):
    """The report's sentence naming the machine of a run (``machine``: {"start": facts, "end": facts} as
    run_all writes them), or "" without a record."""
    if not machine:
        return ""
    start, end = machine.get("start", {}), machine.get("end", {})
    load = "; load average (1, 5, 15 min) {} at the start ({}), {} at the end ({})".format(
        start.get("load"), start.get("time"), end.get("load"), end.get("time")) if end else ""
    return (f"Measured on: {start.get('cpu')}, {start.get('cores')} logical cores, shared with other jobs"
            f"{load}.")


def run_all(skip=(), start_at=None):
    walls_path = OUT / "make_report_walls.json"
    machine_path = OUT / "make_report_machine.json"
    walls = json.loads(walls_path.read_text()) if start_at and walls_path.exists() else {}
    machine = json.loads(machine_path.read_text()) if start_at and machine_path.exists() else {}
    machine.setdefault("start", machine_facts())
    machine.pop("end", None)
    machine_path.write_text(json.dumps(machine, indent=2))
    names = [script_entry(e)[0] for e in SCRIPTS]
    first = names.index(start_at) if start_at else 0
    probe_path = OUT / "make_report_probe.json"
    probe = json.loads(probe_path.read_text()) if start_at and probe_path.exists() else {"probes": []}
    probe.pop("end", None)
    for entry in SCRIPTS[first:]:
        script, args, tag = script_entry(entry)
        if script in skip:
            continue
        key = f"{script} {' '.join(args)}" if tag else script
        probe["probes"] = [p for p in probe["probes"] if p[0] != key] + [[key, host_probe()]]
        probe_path.write_text(json.dumps(probe, indent=2))
        t0 = time.perf_counter()
        print(f"running {script} {' '.join(args)}", flush=True)
        proc = subprocess.run([sys.executable, str(script_path(script)), *args], check=True, stdout=subprocess.PIPE,
                              text=True)
        print(proc.stdout, end="", flush=True)
        (OUT / printout_name(script, tag)).write_text(proc.stdout)  # what section_printed quotes
        walls[key] = time.perf_counter() - t0
    walls_path.write_text(json.dumps(walls, indent=2))
    probe["end"] = host_probe()
    probe_path.write_text(json.dumps(probe, indent=2))
    machine["end"] = machine_facts()
    machine_path.write_text(json.dumps(machine, indent=2))


def section_printed(title, script, intro, figures=(), last_lines=40, tag=None):
    """A report section quoting what ``script`` printed in this run (its last ``last_lines`` lines), with
    ``figures`` ((file under validation/out, sentence), ...) below; ``tag``: the SCRIPTS entry run under
    that tag (its arguments named in the command)."""
    path = OUT / printout_name(script, tag)
    args = next((" ".join(a) for e in SCRIPTS for sc, a, t in [script_entry(e)] if sc == script and t == tag), "")
    command = f"python {script_command(script)}{' ' + args if args else ''}"
    lines = [f"## {title}", "", intro, "", f"Command: `{command}`; what it printed in this run:", ""]
    if path.exists():
        printed = [ln for ln in path.read_text().splitlines() if ln.strip()][-last_lines:]
        lines += ["```text", *printed, "```", ""]
    else:
        lines += ["(not run for this report)", ""]
    for src, sentence in figures:
        lines += figure(src, sentence)
    return lines


def section_new_checks():
    """The traction convergence study, the power-loss comparison and the bearing levels in Exudyn."""
    return (section_printed(
        "Traction integration: strips and points across", "traction_convergence.py",
        "The quasi-static traction equilibrium of three high-speed cases at a grid of strips x points across, "
        "against a 64 x 8 integration; the default of every solver (16 x 4) is the cheapest setting within 1 % "
        "dissipation and 0.1 deg beta on every case.",
        [("traction_convergence.png", "dissipation and beta errors against the points per contact, per case and "
                                      "points across; dashed: the targets.")], last_lines=60)
        + section_printed(
            "Power loss against SKF's and Palmgren's models", "losses_6208_7208.py",
            "The quasi-static solver's loss components (traction, EHL rolling, hysteresis, drag; "
            "docs/theory/losses.md) for the 6208 (radial) and the 7208 (thrust) against SKF's catalogue friction "
            "model and Palmgren's M0 + M1 (per term: rolling, sliding, drag and churning, cage), the DEM papers' oil "
            "at its one temperature, for balls in air and in an oil bath; the dynamic energy check by component.",
            [("losses_6208_7208.png", "friction torque of the project's components, SKF's model and Palmgren's "
                                      "band over speed and load.")], last_lines=30)
        + section_printed(
            "Rolling resistance and ball drag in the dynamic engines", "losses_dynamic.py",
            "The switches `rolling_resistance` (hysteresis + EHL rolling force as a moment pair at every loaded "
            "ball / raceway contact) and `ball_drag` (drag of each ball in the oil-air mixture, oil volume "
            "fraction 0.05) of both dynamic engines against the quasi-static loss report of the same case "
            "(docs/theory/losses.md, \"In the dynamic engines\"), and their cost (switches off against on, run "
            "in turn, medians).",
            [("losses_dynamic.png", "EHL rolling, hysteresis and drag power of both engines against the "
                                    "quasi-static report, per case.")], last_lines=30)
        + section_printed(
            "The reduced engine against the reference engine", "reduced_engine.py",
            "The reduced engine (ball centres on their normal force balance, linearly implicit step; "
            "docs/theory/reduced.md) against the reference engine on the 6208 radial (the DEM papers' case) and "
            "under 3 kN thrust, no cage, traction over the ellipse: Q_max, orbital speed, dissipation and drive "
            "power, the criteria (0.5 %, 0.2 %, 1 %), and the wall time per simulated second of both engines "
            "in one session (medians).", last_lines=20)
        + section_printed(
            "Where the element's step time goes", "profile_element.py",
            "The Exudyn element's body mode on the bench_element scene (6208, 3000 N, 500 rad/s, VelocityVerlet "
            "5 us): per step, the compiled kernel, the Python user function around it, Exudyn's conversion of "
            "coordinates and forces, Exudyn's own step without a user function, against the reference engine's "
            "step on the same scene (medians of repeats).", last_lines=30)
        + section_printed(
            "Element body mode against the one-object layout", "bench_element_ab.py",
            "The body mode of this code against b8c12a7 (one ObjectGenericODE2 holding all balls), both in one "
            "process, interleaved rounds, medians; new/new is the noise floor; the sampled arrays compared bit "
            "for bit (equal on the branch that changed the layout; not since the contact kernel's divisions were "
            "reordered, whose summary differences bench_kernel_ab.py shows within the round-off floor).",
            last_lines=15)
        + section_printed(
            "Bearing levels in Exudyn", "levels_checks.py",
            "The ball element, the quasi-static level and the linear level in Exudyn (docs/theory/levels.md): "
            "static equilibrium against solve_quasistatic, the ball-pass varying compliance, the rotor scenario "
            "at the three levels.",
            [("levels/levels_vc.png", "varying-compliance vibration of the quasi-static level: spectrum with the "
                                      "ball-pass frequency and its harmonics."),
             ("levels/levels_rotor.png", "the rotor scenario at the three levels.")], last_lines=40)
        + section_printed(
            "Cost of the bearing levels", "bench_levels.py",
            "Wall time per simulated second of the ball element (body and fast mode) and of the two levels "
            "without ball degrees of freedom on a 2.5 kg shaft on one 6208 at 3000 N and 500 rad/s, medians of "
            "three runs, and the two-bearing run-up of scenarios/rotor_two_6208.py built with each level.",
            last_lines=60)
        + section_printed(
            "Varying compliance against the published theory", "levels_published_vc.py",
            "The quasi-static level's ball-pass motion against the rigid-ring Hertz theory of Sunnersjo (1978) "
            "in closed form (docs/theory/varying_compliance.md): the two boundary positions, the orbit over a "
            "ball passage, the first harmonic against speed, and a short ball-element run.",
            [("levels/levels_published_vc.png", "ring-centre motion over a ball passage and its first harmonic "
                                                "against speed, quasi-static level against the closed form.")],
            last_lines=30)
        + section_printed(
            "Work-precision of the bearing levels", "levels_work_precision.py",
            "Wall time against orbit error of the three levels on a loaded test shaft, against the ball element "
            "at 1 us; a plateau is the level's model error.",
            [("levels/levels_work_precision.png", "wall time against orbit error, per level and step.")],
            last_lines=25)
        + section_printed(
            "Thermal network: the 120-mm bearing of NASA TN D-7870", "thermal_nasa_d7870.py",
            "The quasi-static ACBB-120 solved with its lumped thermal network (docs/theory/thermal.md) over speed "
            "and thrust. Only the report's abstract was available here: the script checks its statements, not its "
            "measured values, and nothing is calibrated.",
            [("thermal_nasa_d7870.png", "power loss, outer-ring temperature and operating contact angles against "
                                        "speed at three thrust loads."),
             ("thermal_nasa_d7870_components.png", "losses by component and node temperatures against speed.")],
            last_lines=40)
        + section_printed(
            "Speed of the thermal solution", "bench_thermal.py",
            "One thermal quasi-static solution and a warm-started 20-speed sweep (medians).", last_lines=5)
        + section_printed(
            "Two results explained", "anomaly_checks.py",
            "The 6208's dissipation at 1 rad/s (the engines' least rolling speed, since fixed) and the 7208's "
            "orbital speed above half the ring speed under outer-race control (a real result, against the closed "
            "form).", last_lines=40)
        + section_printed(
            "Step time against the code before the kernel work", "bench_kernel_ab.py",
            "The reference engine's step on the two headline settings of bench_reference.py, this code against "
            "e61f1e5 (before the semi-axes from the overlap, ln(xi E') once per evaluation, the divisions off the "
            "dependency chains and the cached film ellipticity factor), both in one "
            "process, interleaved rounds, medians; the new/new control is the noise floor.", last_lines=20)
        + section_printed(
            "Step time against the start of this work", "bench_kernel_ab.py",
            "As above, against 58652e8: before the HD film's logarithms and exponential came from per-contact "
            "anchors (series near the anchor, equal to the library functions to round-off: "
            "tests/test_kernel_cache.py) and before the ball / raceway geometry was computed for all contacts "
            "first.", last_lines=20, tag="session")
        + section_printed(
            "Element step against the start of this work", "bench_element_ab.py",
            "The element's body and fast modes against 58652e8: before one compiled call on one structure of the "
            "element's arrays, views of Exudyn's coordinate vectors instead of copies, the element's kernels "
            "without numba's memory runtime and the scene's contact-kernel paths only; interleaved rounds, "
            "medians; sampled arrays compared bit for bit.", last_lines=20, tag="session")
        + section_printed(
            "Element fast mode against the start of this work", "bench_element_ab.py",
            "As above, the fast mode (one sub-step per Exudyn step).", last_lines=20, tag="session_fast")
        + section_printed(
            "Cold start against the start of this work", "bench_kernel_ab.py",
            "The README's first run on an empty numba cache (a fresh process with a new NUMBA_CACHE_DIR: import, "
            "then a 2 ms run of the 6208 scene, which compiles the kernels it uses), this code against 58652e8 "
            "(before numba's inlining copied a callee's scope once per block, before one specialisation per "
            "argument type and kernels without the wrappers nothing calls), the two alternately; medians of the "
            "wall and CPU seconds. Per compiled function: `python validation/performance/profile_reference.py --compile`.",
            last_lines=8, tag="cold")
        + section_printed(
            "Where the reference engine's step time goes", "profile_reference.py",
            "The bench_reference scene (6208, 3000 N, 500 rad/s, cage, lubrication, tangential history) in steady "
            "running: the compiled contact kernel timed with stages switched off through the parameter vector on "
            "a frozen state (CPU time per step, interleaved rounds, medians). The cold start is measured by "
            "`python validation/performance/profile_reference.py --compile` (a fresh process, empty numba cache).",
            last_lines=40)
        + section_printed(
            "Start-up of a fresh process", "profile_suite.py",
            "Wall and CPU time of fresh processes with warm caches (medians): `import exudyn_bearing` (lazy: "
            "nothing loads until a public name is used), the imports `simulate` and `solve_quasistatic` need, "
            "`python -m exudyn_bearing --help` and `info 6208`. The suite's per-test profile, cold and warm numba "
            "cache: `python validation/performance/profile_suite.py` (not part of this run: it runs the whole suite twice).",
            last_lines=12))


def section_reference():
    d = load("bench_reference.json")
    lines = ["## Reference core: speed against error", "",
             "Command: `python validation/performance/bench_reference.py` (engine: reference core; T = "
             f"{d['t_end']} s per run, median of {d['repeat']}). Scene: 6208, F_r = 3000 N, 500 rad/s, cage, "
             "lubrication and Cundall-Strack history on, analytic start. Errors: the summary over the last "
             "quarter against the same setting at a quarter of the step.", "",
             "| setting | wall s per simulated s | steps/s | err q_max_inner | err q_max_outer | err cage_speed | "
             "mean frictional power [W] |", "|---|---|---|---|---|---|---|"]
    for name, r in d["settings"].items():
        lines.append(f"| {name} | {r['wall_per_sim_s']:.3f} | {r['steps_per_s']:.3g} | {pct(r['err_q_max_inner'])} | "
                     f"{pct(r['err_q_max_outer'])} | {pct(r['err_cage_speed'])} | "
                     f"{r['summary']['friction_power']:.2g} |")
    est, meas = d["stable_step_estimate"], d["stable_step_measured"]
    ok = [f"{n} ({r['wall_per_sim_s']:.2f} s)" for n, r in d["settings"].items()
          if r["wall_per_sim_s"] <= 0.5 and max(r["err_q_max_inner"], r["err_q_max_outer"], r["err_cage_speed"]) <= 5e-3
          and r["summary"]["friction_power"] < 1.0]
    lines += ["", "- Requirement (at most 0.5 s per simulated second, errors of q_max and cage_speed <= 0.5 %, "
              "tangential springs resolved): met in this run by " + ("; ".join(ok) if ok else "no setting") + "."]
    lim = d["stable_step_limits"]

    def limits_text(t):
        names = {"normal": "normal Hertz mode of a ball between its races",
                 "tangential": "rocking mode of the Cundall-Strack springs", "friction": "regularised friction",
                 "cage": f"critically damped ball / cage-ball contacts at {lim[t]['cage_load']:.2f} N "
                         f"({lim[t]['cage_basis']})"}
        return ", ".join(f"{names[k]} {lim[t][k] * 1e6:.2f} us" for k in names
                         if lim[t][k] is not None and math.isfinite(lim[t][k]))  # inf is null in the JSON

    imp = lim["implicit"]
    lines += [
              f"- Stable step: estimate {est['explicit'] * 1e6:.2f} us (explicit spring, limited by "
              f"{lim['explicit']['limited_by']}) and {est['implicit'] * 1e6:.2f} us (implicit, limited by "
              f"{imp['limited_by']}): `stable_step`, the safety factor times the smallest of its limits (explicit "
              f"spring: {limits_text('explicit')}; implicit: {limits_text('implicit')}). The largest step that did "
              f"not blow up (bisection on 10 ms runs) was {meas['explicit'] * 1e6:.2f} and "
              f"{meas['implicit'] * 1e6:.2f} us. The explicit Cundall-Strack spring does not blow up above its "
              "rocking-mode limit because its force is capped at mu F_n, but it chatters at the cap (the large "
              "frictional power of the explicit 8 us row, against about 1e-4 W when resolved); the implicit spring "
              "(K_t / (1 + K_t dt^2 / m_t)) removes that limit. Beyond the normal mode the cage contacts come next, "
              f"at {imp['cage'] / imp['normal']:.2f} times its limit in this steady scene (their loads are small "
              "here; in start-up and slow-down they limit first: next section): a step twice as large needs both "
              "integrated implicitly.",
              "- Cost: one kernel call per force evaluation, the contact laws being scalar physics functions "
              "compiled into the force loop (no calls that pass arrays inside it), the exact Hertz level "
              "tabulated (relative error "
              "<= 1e-7) and re-evaluated per contact only when R_y/R_x moves by more than 1e-6.",
              "- RK4 (history-free friction only) costs four evaluations per step; it is the most accurate per "
              "step, not the fast choice.",
              f"- Numba cache: a second process starts and runs 1 ms in {d['second_start_s']:.2f} s.",
              f"- Memory does not grow with the number of steps: peak traced memory for 50 samples "
              f"{d['memory_bytes']['T=0.05'] / 1e6:.2f} MB for T = 0.05 s and "
              f"{d['memory_bytes']['T=0.2'] / 1e6:.2f} MB for T = 0.2 s.", ""]
    return lines


def section_fast_limits():
    """The fast mode's step limit against the ring mass (fast_mode_limits.py at two loads)."""
    intro = ("The element's fast mode: Exudyn integrates the ring with the step H = n x 5 us, the balls run n "
             "compiled sub-steps per Exudyn step (docs/theory/dynamics.md). The 6208 scene with the inner ring a "
             "point mass of 81 g (the bare ring) to 5 kg (a ring carrying a share of a rotor); errors of the summary "
             "(last quarter of 0.04 s) against the reference engine at 1.25 us with the same ring mass. The "
             "element warns above `fastStepLimit` = 0.25 of the ring's stable-step estimate (H/estimate below): "
             "the staggered coupling, not the ring's own Verlet limit, sets the step. The steady flag and the "
             "growth (rms ring-centre speed of the last 5 ms over the 5 ms before) are printed as measured; "
             "over 10 ms windows of a 0.04 s run both are noisy (a 5 kg ring is still settling).")
    return (section_printed("Fast-mode step limit against the ring mass", "fast_mode_limits.py", intro,
                            last_lines=90)
            + section_printed("Fast-mode step limit at a lighter load", "fast_mode_limits.py",
                              "As above at F_r = 600 N, for the bare ring and a 1.25 kg ring.", last_lines=40,
                              tag="600N"))


def section_element():
    d = load("bench_element.json")
    c = load("fast_mode_checks.json")
    rows = d["rows"]
    lim = load("fast_mode_limits.json")
    bare = lim["masses"][0]
    ov = load("bench_overhead.json")
    rotor = c["rotor_sub_steps"]
    whirl = c["rotor_scenario_whirl"]

    def light_txt(label, r):
        if "error" in r:
            return f"{label}: {r['error'].split(';')[0]}"
        return (f"{label} ({r.get('exudyn_step_us', 5):g} us) {100 * r['dev_cage_speed']:+.3f} / "
                f"{100 * r['dev_centre']:+.2f} %")

    def light_worst(rows, lo, hi, key="dev_centre", digits=2):
        """Largest |deviation| of the fast-mode rows whose Exudyn step lies in (lo, hi] us."""
        devs = [abs(v[key]) for k, v in rows.items()
                if k.startswith("fast") and "error" not in v and lo < v["exudyn_step_us"] <= hi]
        return pct(max(devs), digits) if devs else "n/a"

    def spread(runs):
        m = [v["mean_10_20ms"] for v in runs.values()]
        return max(m) / min(m) - 1
    lines = ["## Exudyn element against the reference core and Exudyn's built-in bearing", "",
             f"Command: `python validation/performance/bench_element.py --ga` (T = {d['t_end']} s, median of 3; the built-in "
             "bearing 0.02 s). Same scene, dt = 5 us, explicit spring; wall times are the solves alone. Errors of "
             "our engines against the reference core at 1.25 us; of the built-in bearing, of its cage speed "
             "against its own run at 5e-6 s.", "",
             "| engine | wall s per simulated s | err q_max_inner | err cage_speed |", "|---|---|---|---|"]
    for name, r in rows.items():
        lines.append(f"| {name} | {r['wall_per_sim_s']:.3g} | {pct(r.get('err_q_max_inner'))} | "
                     f"{pct(r.get('err_cage_speed'))} |")
    b = rows.get("built-in CreateBallBearing", {})
    lines += ["",
              f"- Body mode / built-in bearing: **{d['ratio_body_builtin']:.3f}** (target <= 0.5). The built-in "
              f"bearing (GeneralizedAlpha, best step {b.get('h', float('nan')):g} s, same Hertz stiffness "
              f"k = {d['k_builtin']:.3g} N/m^1.5, exponent 1.5) runs only with the load ramped in over 5 ms; with "
              "the load applied at once its solver stops at the minimum step size.",
              f"- Fast mode ({d['fast_sub_steps']} x 5 us sub-step{'s' if d['fast_sub_steps'] > 1 else ''}) / "
              f"reference core: **{d['ratio_fast_reference']:.2f}** (target <= 2); with a ring of "
              f"{d['heavy_ring']:g} kg (half of a 2.5 kg rotor; {d['heavy_sub_steps']} x 5 us sub-steps): "
              f"**{d['ratio_fast_reference_heavy']:.2f}**. Besides the compiled sub-steps, each Exudyn step "
              "pays Exudyn's Python user-function call, the conversion of its coordinate lists and numba's "
              "argument dispatch (a few us). The sub-steps of one Exudyn step are centred on its time and the "
              "ring gets their mean reaction, so ring and balls exchange equal impulses "
              "(tests/test_element.py). The number of sub-steps is limited by that staggered coupling "
              f"(`fastStepLimit`, {d['fast_step_share']:g} of the ring's stable-step estimate; next section): "
              f"on the {bare['ring_mass'] * 1e3:.0f} g ring of this scene (estimate "
              f"{bare['ring_stable_step'] * 1e6:.1f} us) one sub-step of 5 us.",
              "- Rotor on two 6208 bearings (2.5 kg, motor torque 5 N m from rest, same script), mean cage speed "
              "of bearing A over 10-20 ms [rad/s]: "
              + "; ".join(f"{load} N: " + ", ".join(f"{k} {v['mean_10_20ms']:.2f}" for k, v in r.items())
                          for load, r in rotor.items())
              + ". Loaded (600 and 3000 N), every mode and step lies within "
              f"{pct(max(spread(r) for k, r in rotor.items() if k != '24.5'), 1)} of each other. At 24.5 N the "
              "rotor rattles near the centre and the run-up is chaotic: the body mode alone spreads "
              f"{pct(spread({k: v for k, v in rotor['24.5'].items() if k.startswith('bodies')}), 0)} over its "
              "step sizes, and the fast-mode runs fall in the same band. With one sub-step the fast mode costs "
              f"{d['ratio_fast1_body']:.2f} of the body mode (bench_element.py).",
              "- Lightly loaded rotor (2.5 kg on two 6208, 500 rad/s, radial load at its centre, analytic start, "
              "same script), deviation of bearing A's cage speed / orbit-centre distance from the body mode at 5 us "
              "over 10-20 ms, by Exudyn step of the ring (sub-steps x sub-step): "
              + "; ".join(f"{load}: " + ", ".join(light_txt(k, v) for k, v in rows.items() if k != "bodies 5 us")
                          for load, rows in (("50 N", c["light_load_sub_steps"]), ("5 N", c.get("light_load_5N", {}))))
              + ". The body mode's own step error (2.5 against 5 us) is the yardstick. The deviation grows with the "
              "ring's Exudyn step (the rotor, integrated by Exudyn, feels the balls' mean reaction once per "
              "Exudyn step; the sub-steps only integrate the balls): largest orbit-centre deviation with Exudyn steps up to 20 us "
              + ", ".join(f"{load} {light_worst(rows, 0, 20)}" for load, rows in
                          (("50 N", c["light_load_sub_steps"]), ("5 N", c.get("light_load_5N", {}))))
              + "; with 40 us " + ", ".join(f"{load} {light_worst(rows, 20, 40)}" for load, rows in
                                            (("50 N", c["light_load_sub_steps"]), ("5 N", c.get("light_load_5N", {}))))
              + " (against the yardstick's " + ", ".join(
                  f"{load} {pct(abs(rows.get('bodies 2.5 us', {}).get('dev_centre', float('nan'))), 2)}"
                  for load, rows in (("50 N", c["light_load_sub_steps"]), ("5 N", c.get("light_load_5N", {}))))
              + "); cage speed, largest deviation over all of them: " + ", ".join(
                  f"{load} {light_worst(rows, 0, 1e9, 'dev_cage_speed', 3)}" for load, rows in
                  (("50 N", c["light_load_sub_steps"]), ("5 N", c.get("light_load_5N", {})))) + ".",
              "- The run-up of scenarios/rotor_two_6208.py (no load but gravity and unbalance) has two outcomes, "
              "a shaft rattling near the centre or a whirl (the 6208 has no clearance: the orbit is the contacts' "
              "compliance) from about 25 ms on; which one "
              "occurs is decided by round-off-level differences, not by the mode (same script, mean over 40-50 "
              "ms, orbit radius / largest outer ball load): " + "; ".join(
                  f"{k} {v['orbit_radius_um']:.1f} um / {v['q_max_outer_N']:.0f} N" for k, v in whirl.items()) + ".",
              "- Explicit solvers (same script, 6208 test scene, 10 ms at 2 us, errors of q_max_inner / cage speed "
              "against the reference core with the same friction model): " + "; ".join(
                  f"{k}: " + (v["error"].split(";")[0] if "error" in v else
                              f"{pct(v['q_max_inner'], 4)} / {pct(v['cage_speed'], 4)}")
                  for k, v in c["solvers_6208"].items())
              + ". VelocityVerlet (history friction) and RK44 (regularized friction) are the supported explicit "
              "solvers in both modes; ExplicitEuler is refused before the first step (not symplectic: unusable for stiff "
              "contact).",
              "- Where an Exudyn step goes (`python validation/performance/bench_overhead.py`, medians, us per Exudyn step): "
              + "; ".join(f"{k} {v * 1e6:.2f}" for k, v in ov.items() if k.endswith(("alone", "element")))
              + ". Converting Exudyn's coordinate lists to arrays: "
              f"{ov['list to array, body-mode coordinates'] * 1e6:.2f} us for the body mode's {ov['coordinates']} coordinates (twice per evaluation); one sample of the "
              f"element's state (compiled): {ov['one sample'] * 1e6:.2f} us.",
              "- GeneralizedAlpha (h = 10 us, regularized friction) works with the element (numerical Jacobian of "
              "the whole bearing object, modified Newton): "
              f"{rows.get('element body mode, GeneralizedAlpha 10 us', {}).get('wall_per_sim_s', float('nan')):.0f} "
              "s per simulated second, "
              f"{rows.get('element body mode, GeneralizedAlpha 10 us', {}).get('evaluations', 0)} force evaluations "
              "for 200 steps: usable for short checks, not recommended.",
              "- The body mode cannot use `computeMassMatrixInversePerBody` (not implemented for ObjectGenericODE2 "
              "in Exudyn 1.13.6); `BallBearingElement.SimulationSettings` sets the sparse linear solver.", ""]
    return lines


def section_cage_step():
    d = load("cage_step_checks.json")
    lines = ["## Stable step of the cage contacts", "",
             "Command: `python validation/studies/cage_step_checks.py`. The ball / cage-ball contacts are critically damped, "
             "and velocity Verlet with the damping force at the half-step velocity is stable up to "
             "2 (sqrt(1 + zeta^2) - zeta) / omega, 0.83 / omega at zeta = 1 (tests/test_reference.py checks this "
             "against the amplification matrix). Above it the cage loads chatter at about twice their value; from "
             "1.6 times the estimate runs blew up (`python validation/studies/step_limits.py`). With "
             "`cage_damping=\"implicit\"` the damping acts with C / (1 + C dt / m), backward Euler of the "
             "contact's own damping over the step: stable up to 1.58 / omega (tests/test_cage_damping.py checks it "
             "against the amplification matrix), 1.9 times the explicit limit; the main job's implicit runs take "
             "the implicit tangential spring too (the explicit one limits at 6.3 us). Sampled cage loads, and "
             "what the engine said (a priori: dt above "
             "`stable_step`; after the run: the loads reached put the contacts' stable step below dt), and the "
             "integration's wall time (one run each, on the machine of the header):", "",
             "| scene | cage damping | tangential spring | dt | dt / estimate | largest cage load [N] | "
             "99.9 % cage load [N] | q_max_inner [N] | cage [rad/s] | a-priori warning | cage-load warning | "
             "wall [s] |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for scene, rows in d.items():
        for r in rows["runs"].values():
            head = (f"| {scene} | {r['cage_damping']} | {r['tangential']} | {r['dt_s'] * 1e6:g} us | "
                    f"{r['dt_over_estimate']:.2f} |")
            if "blew_up" in r:
                lines.append(head + f" blew up: {r['blew_up']} | | | | | | |")
                continue
            lines.append(head + f" {r['max_cage_load_N']:.1f} | {r['p99_9_cage_load_N']:.1f} | "
                         f"{r['q_max_inner']:.1f} | {r['cage_speed']:.2f} | {'yes' if r['a_priori_warning'] else 'no'} "
                         f"| {'yes' if r['cage_load_warning'] else 'no'} | {r['wall_s']:.2f} |")

    def spread(scene_rows, key):
        v = [r[key] for r in scene_rows["runs"].values()
             if r["cage_damping"] == "explicit" and r["tangential"] == "explicit"]
        return 100.0 * (max(v) - min(v)) / min(v)

    def implicit(scene_rows):
        runs = [r for r in scene_rows["runs"].values() if r["cage_damping"] == "implicit"]
        quiet = [r for r in runs if "blew_up" not in r and not r["cage_load_warning"] and not r["a_priori_warning"]]
        text = "no run within the estimate without a warning"
        if quiet:
            dev = {k: 100.0 * max(abs(r["difference"][k]) for r in quiet)
                   for k in ("q_max_inner", "cage_speed", "p99_9_cage_load_N")}
            text = (f"up to {max(r['dt_s'] for r in quiet) * 1e6:g} us "
                    f"({max(r['dt_over_estimate'] for r in quiet):.2f} of its estimate) without a warning, at most "
                    f"{dev['q_max_inner']:.2f} % off in q_max_inner, {dev['cage_speed']:.3f} % in cage speed and "
                    f"{dev['p99_9_cage_load_N']:.1f} % in the 99.9 % cage load from the "
                    f"{quiet[0]['compared_with']} run")
        chatter = [r for r in runs if "blew_up" not in r and r["cage_load_warning"]]
        blown = [r for r in runs if "blew_up" in r]
        return (text + "; first cage-load warning at "
                + (f"{chatter[0]['dt_over_estimate']:.2f}" if chatter else "-") + ", first blow-up at "
                + (f"{blown[0]['dt_over_estimate']:.2f}" if blown else "- (none up to "
                   f"{max(r['dt_over_estimate'] for r in runs):.2f})") + " of the estimate")

    def drift(scene_rows):
        return 100 * max(abs(r["q_max_inner_drift"]) for r in scene_rows["runs"].values() if "blew_up" not in r)

    lines += ["", "Estimates (`stable_step`; cage contacts at a tenth of the ball load in start-up, slow-down, from "
              "rest and with the loaded balls at unequal contact angles, at 0.1 % in steady runs from the analytic "
              "state): " + "; ".join(
                  f"{scene}, {group}: {e['dt_s'] * 1e6:.2f} us (limited by the {e['limited_by']} contact)"
                  for scene, rows in d.items() for group, e in rows["estimates"].items())
              + ". The check of the loads a run reached flags the runs whose "
              "cage loads doubled. Over the explicit steps (explicit spring) q_max_inner (the largest ball load) "
              "spreads by "
              + ", ".join(f"{spread(rows, 'q_max_inner'):.2f} % ({scene})" for scene, rows in d.items())
              + " and the cage speed by "
              + ", ".join(f"{spread(rows, 'cage_speed'):.3f} % ({scene})" for scene, rows in d.items()) + ".", "",
              "Implicit cage damping: " + "; ".join(f"{scene}: {implicit(rows)}" for scene, rows in d.items())
              + ". Runs whose summary window is not steady (the steady-state check of the summary): "
              + "; ".join(f"{scene}: {sum(1 for r in rows['runs'].values() if r.get('steady') is False)} of "
                          f"{len(rows['runs'])}, q_max_inner drifting by up to {drift(rows):.2f} % over the window"
                          for scene, rows in d.items())
              + "; their differences include that drift.", ""]
    return lines


def section_cross():
    d = load("cross_engine.json")
    lines = ["## Cross-engine check", "",
             "Command: `python validation/consistency/cross_engine.py` (T = 0.05 s, dt = 5 us, both engines on each scene; "
             "figures `out/cross_engine_<scene>.png`, two of them below). Largest relative difference of "
             "q_max_inner, q_max_outer, "
             "cage_speed, ball_spin and lambda_outer_psi0:", "", "| scene | largest relative difference |",
             "|---|---|"]
    for scene, rows in d.items():
        lines.append(f"| {scene} | {max(r['rel_diff'] for r in rows.values()):.1e} |")
    lines += ["", "The engines share the contact kernel; the remaining differences come from Exudyn's "
              "VelocityVerlet and the element's ring coupling.", ""]
    lines += figure("cross_engine_500rad_s.png", "Outer ball loads of the last samples against azimuth, reference "
                    "core (blue) and Exudyn element (orange), 6208 at 3000 N and 500 rad/s: the points of the two "
                    "engines lie on each other.")
    lines += figure("cross_engine_1700rad_s.png", "The same at 1700 rad/s, where the balls outside the loaded zone "
                    "press on the outer race with their centrifugal force (the flat part of the curve).")
    return lines


def section_peer():
    d = load("peer_builtin.json")
    lines = ["## Peer check against Exudyn's built-in bearing", "",
             "Command: `python validation/consistency/peer_builtin.py` (T = 0.04 s). The element with Exudyn's "
             "ObjectContactSphereTorus law (`contact_law=\"power\"`: k delta^1.5 + d d(delta)/dt, k = 3.35e10, "
             "d = 200 N s/m, mu = 0.1 linear below 0.1 m/s) against `exudyn.machines.CreateBallBearing` on the "
             "same geometry (r_p = 30 mm), 500 rad/s, F_r = 3000 N; means over the last quarter:", "",
             "| quantity | built-in | element | difference |", "|---|---|---|---|"]
    for k, r in d.items():
        lines.append(f"| {k} | {r['builtin']:.2f} | {r['element']:.2f} | {pct(r['rel_diff'], 2)} |")
    own = load("fast_mode_checks.json")["builtin_own_inertia"]
    lines += ["", "Ball loads and cage speed agree within 1 % (target). The built-in inner ring is given a "
              "large polar inertia: with the 6208 ring's own inertia (`python validation/consistency/fast_mode_checks.py`) it "
              f"slows from 500 to {own['ring_speed']:.1f} rad/s while it spins the balls up from rest, and its cage "
              f"then runs at {own['cage_speed']:.1f} rad/s, the kinematic speed for that ring speed "
              f"({own['kinematic_cage_at_ring_speed']:.1f} rad/s), not a slip. The cages differ by design (rigid "
              "cylinder on springs against our torus cage).", ""]
    return lines


def section_figures():
    d = load("figures/figures.json")
    lines = ["## The papers' figures (docs/theory/reference_cases.md)", "",
             "Command: `python validation/published/figures.py` (figures and their CSV in `out/figures/`, shown below; "
             "sweeps through the sweep runner). Step 5 us, implicit tangential spring, unless said.", ""]
    if "item1" in d:
        lines += ["### 1. Quasi-static loads (omega = 1 rad/s)", "",
                  "Largest relative error of Q and delta at the loaded balls (Q > 5 % Q_max) against the discrete "
                  "analytic solution at the same ball phase (required: within 2 %):", "",
                  "| case | engine | err Q | err delta | Q_max | analytic Q_max | analytic eps | wall s |",
                  "|---|---|---|---|---|---|---|---|"]
        for k, v in d["item1"].items():
            if isinstance(v, dict):
                lines.append(f"| {k.split(' ', 1)[1]} | {v['engine']} | {pct(v['max_rel_err_Q'], 2)} | "
                             f"{pct(v['max_rel_err_delta'], 2)} | {v['q_max']:.1f} | {v['q_max_analytic']:.1f} | "
                             f"{v['eps_analytic']:.3f} | {v['wall_s']:.2f} |")
        lines.append("")
        lines += figure("figures/item1_quasi_static_load.png", "Quasi-static ball loads (left) and total overlaps "
                        "(right) against azimuth at F_r = 1000, 2000 and 3000 N: lines the discrete analytic "
                        "solution, circles the reference core, crosses the Exudyn element.")
        lines += figure("figures/item1_quasi_static_clearance.png", "The same at 3000 N for the clearances P_d = "
                        "-12.6, 0 and +12.6 um: preload widens the loaded zone, clearance narrows it.")
    if "item2" in d:
        lines += ["### 2. 500 rad/s protocol (start-up 0.05 s, steady 0.2 s, slow-down 0.05 s, from rest)", "",
                  "| engine | ball spin | kinematic | cage | kinematic | Lambda_out psi=0 | median SRR ball 0 "
                  "start-up / steady / slow-down | wall s |", "|---|---|---|---|---|---|---|---|"]
        for e, v in d["item2"].items():
            if isinstance(v, dict):
                srr = v["srr_ball0_median"]
                srr_s = " / ".join("n/a" if srr[k] is None else f"{srr[k]:.1e}"
                                   for k in ("start-up", "steady", "slow-down"))
                lines.append(f"| {e} | {v['ball_spin']:.2f} | {v['kinematic_ball_spin']:.2f} | "
                             f"{v['cage_speed']:.2f} | {v['kinematic_cage']:.2f} | {v['lambda_outer_psi0']:.3f} | "
                             f"{srr_s} | {v['wall_s']:.2f} |")
        lines += ["", "Steady values over 0.15-0.25 s. The slide-to-roll ratio of ball 0 is near zero in the "
                  "steady phase and not during start-up and slow-down (figure item2_srr_ball0.png).", ""]
        lines += figure("figures/item2_speeds_both_engines.png", "Shaft, mean ball spin and cage speed through the "
                        "protocol, reference core solid and Exudyn element dashed, with the kinematic ball spin "
                        "952.38 rad/s of docs/theory/reference_cases.md.")
        lines += figure("figures/item2_srr_ball0.png", "Slide-to-roll ratio of ball 0 at its inner and outer "
                        "contact (log scale): small in the steady phase, orders of magnitude larger in start-up and "
                        "slow-down.")
        lines += figure("figures/item2_film_outer_by_phase.png", "h_min (left) and Lambda (right) of the outer "
                        "contacts against azimuth by phase: in the steady phase both are lowest at psi = 0; the "
                        "dashed lines are the regime limits Lambda = 1 and 3.")
    if "item3" in d:
        v = d["item3"]
        lines += ["### 3. Load sweep 750 ... 7500 N (six loads, 500 rad/s)", "",
                  f"- slope of ln Lambda_out(psi = 0) against ln Q_max: **{v['slope_lambda_vs_qmax']:.4f} +- "
                  f"{v['se_slope_lambda']:.4f}** (standard error; expected near -0.073, the W exponent of Hamrock-Dowson)",
                  f"- slope of ln F_r against ln Q_max: **{v['slope_fr_vs_qmax']:.4f} +- {v['se_slope_fr']:.4f}** "
                  "(near 1; the centrifugal force on the outer race pulls it above 1)",
                  f"- engine {v['engine']}, dt {v['dt'] * 1e6:g} us, total wall {v['wall_s']:.2f} s", ""]
        lines += figure("figures/item3_lambda_outer_vs_psi.png", "Lambda of the outer contacts against azimuth for "
                        "the six loads: the higher the load, the lower the film parameter in the loaded zone.")
        lines += figure("figures/item3_fits.png", "The two log-log fits: Lambda_out at psi = 0 (left) and F_r "
                        "(right) against the outer Q_max, with the slopes above.")
    if "item4" in d:
        v = d["item4"]
        lines += ["### 4. Clearance sweep (3000 N, 500 rad/s)", "",
                  "| P_d [um] | loaded-zone half angle [deg] | Q_max inner [N] | eps (analytic) |",
                  "|---|---|---|---|"]
        for pd, z, q, e in zip(v["Pd_um"], v["loaded_zone_deg"], v["q_max_inner"], v["eps"]):
            lines.append(f"| {pd:+.1f} | {z:.1f} | {q:.1f} | {e:.3f} |")
        lines += ["", f"The loaded zone shrinks and Q_max grows from preload to clearance (monotonic: "
                  f"{v['zone_monotonic'] and v['q_max_monotonic']}); reference engine, total wall "
                  f"{v['wall_s']:.2f} s.", ""]
        lines += figure("figures/item4_zone_qmax_eps.png", "Loaded-zone half angle, Q_max and the analytic eps "
                        "against P_d (the table above).")
        lines += figure("figures/item4_lambda_outer_vs_psi.png", "Lambda of the outer contacts against azimuth "
                        "for the five clearances: the loaded zone, where the film is thinner, narrows with P_d.")
    if "item5" in d:
        v = d["item5"]
        lines += ["### 5. Speed sweep 100 ... 1700 rad/s (step 200, 3000 N)", "",
                  "| film / engine | slope Lambda_out | slope Lambda_in | Lambda_in < Lambda_out | wall s |",
                  "|---|---|---|---|---|"]
        for f in ("hd", "mk", "exudyn"):
            r = v[f]
            lines.append(f"| {f} / {r['engine']} | {r['slope_lambda_outer']:.4f} +- {r['se_outer']:.4f} | "
                         f"{r['slope_lambda_inner']:.4f} +- {r['se_inner']:.4f} | {r['lambda_in_below_out']} | "
                         f"{r['wall_s']:.2f} |")
        lines += ["", "Expected: the U exponent of the film model, 0.68 for Hamrock-Dowson (the source "
                  "fits 0.6797) and 0.711 k^-0.023 for the Masjedi-Khonsari reading, which is 0.679 at the outer "
                  "contact's k = 7.25; the source reports 0.7105 for MK, which our reading of the garbled formula "
                  "does not reproduce.", "",
                  "Hamrock-Dowson, reference engine:", "",
                  "| omega [rad/s] | Q_max outer [N] | Q_max inner [N] | m r_p omega_c^2 [N] | outer regimes "
                  "(boundary/mixed/full) | inner regimes |", "|---|---|---|---|---|---|"]
        hd = v["hd"]
        for i, w in enumerate(sorted(hd["regimes"], key=float)):
            ro, ri = hd["regimes"][w]["outer"], hd["regimes"][w]["inner"]
            lines.append(f"| {w} | {hd['q_max_outer'][i]:.0f} | {hd['q_max_inner'][i]:.0f} | "
                         f"{v['centrifugal_force'][i]:.1f} | {ro['boundary']:.2f}/{ro['mixed']:.2f}/"
                         f"{ro['full_film']:.2f} | {ri['boundary']:.2f}/{ri['mixed']:.2f}/{ri['full_film']:.2f} |")
        lines += ["", "The outer Q_max rises with speed (centrifugal load) while the inner stays near the static "
                  "value. At 100 rad/s the 20 ms averaging window is shorter than one ball passage, which biases "
                  "its Q_max upward.", ""]
        lines += figure("figures/item5_speed_sweep.png", "Lambda at psi = 0 against speed on log-log axes with "
                        "the fitted slopes (left), and Q_max of the outer and inner contacts against speed (right), "
                        "for both film models and both engines.")
    if "item6" in d:
        c7 = load("fast_mode_checks.json")["cage_7208"]
        lines += ["### 6. 7208, F_r = F_a = 3000 N, 500 rad/s, three conformity sums (torus cage, dt = 0.5 us)", "",
                  "| B | largest abs(Q - law) / Q_max | Q_max | analytic Q_max | contact angle [deg] | cage | "
                  "kinematic cage at that angle |", "|---|---|---|---|---|---|---|"]
        for k, r in d["item6"].items():
            if isinstance(r, dict):
                lines.append(f"| {k[2:]} | {pct(r['max_err_Q_over_qmax'], 1)} | {r['q_max']:.0f} | "
                             f"{r['q_max_analytic']:.0f} | {r['contact_angle_deg']:.2f} | {r['cage_speed']:.2f} | "
                             f"{r['kinematic_cage_at_alpha']:.2f} |")
        lines += ["", "Each ball is compared with the Stribeck law at its own azimuth (eps from the discrete "
                  "quasi-static solution at fixed angle per ball); one sample, so ring vibration and the passage "
                  "of balls through the zone edge enter the largest deviation.",
                  "The catalogue's 1 mm cage balls (33 mg) set the step (`python validation/consistency/fast_mode_checks.py`): "
                  f"at dt = 0.5 us their largest contact load over 50 ms is {c7['max_cage_load_N_dt0.5us']:.0f} N; "
                  f"at dt = 1 us the engine reports: \"{c7['dt1us']}\"", ""]
        lines += figure("figures/item6_7208.png", "7208 ball loads (left) against the Stribeck law at each ball's "
                        "azimuth and total overlaps (right) for the three conformity sums.")
    if "item7" in d:
        v = d["item7"]
        lines += ["### 7. Defect frequencies (500 rad/s, 0.2 s, samples every 20 us)", "",
                  "| frequency | simulated [Hz] | kinematic [Hz] | error | from |", "|---|---|---|---|---|"]
        for k, r in v.items():
            if isinstance(r, dict):
                lines.append(f"| {k} | {r['simulated']:.3f} | {r['kinematic']:.3f} | {r['error_pct']:+.3f} % | "
                             f"{r['how']} |")
        lines += ["", f"Engine {v['engine']}, dt {v['dt'] * 1e6:g} us, wall {v['wall_s']:.2f} s. The source "
                  "reports >= 99 % agreement; the largest error here is "
                  f"{max(abs(r['error_pct']) for r in v.values() if isinstance(r, dict)):.3f} %.", ""]
        lines += figure("figures/item7_ring_force_spectrum.png", "Spectrum of the radial ring reaction with the "
                        "kinematic BPFO dotted: the ball-pass peak and its harmonics.")
    return lines


def section_work_precision():
    d = load("work_precision.json")
    lines = ["## Speed against error (work-precision)", "",
             "Command: `python validation/performance/work_precision.py` (figure `out/work_precision.png`, below). Every setting "
             "against the reference core with the full model at dt = 0.5 us (T = 0.1 s).", "",
             "| family | dt [us] | wall s per simulated s | err q_max | err cage | err Q_max(t) (RMS) |",
             "|---|---|---|---|---|---|"]
    for r in d["rows"]:
        lines.append(f"| {r['family']} | {r['dt'] * 1e6:g} | {r['wall_per_sim_s']:.3f} | {pct(r['err_q_max'], 4)} | "
                     f"{pct(r['err_cage'], 4)} | {pct(r['err_trajectory'], 3)} |")
    worst = max(max(r["err_q_max"], r["err_cage"]) for r in d["rows"])
    best = min((r for r in d["rows"] if r["family"] == "reference, verlet, implicit spring"),
               key=lambda r: r["wall_per_sim_s"])
    lines += ["", f"Every setting stays within {pct(worst, 3)} of the converged run for q_max and cage speed, so "
              "speed decides. Recommended: the reference core with `tangential=\"implicit\"` at dt = "
              f"{best['dt'] * 1e6:g} us (fastest resolved setting, {best['wall_per_sim_s']:.2f} s per simulated "
              "second); the papers' explicit spring at 5-6 us; "
              "the Exudyn element (body mode) at 5 us (8 us with the implicit spring). The fitted Hertz levels "
              "change q_max by less than 0.01 % here (the load sharing is set by equilibrium); switching off "
              "lubrication or the cage is a model change, not an accuracy setting.", ""]
    lines += figure("work_precision.png", "Relative error of q_max_inner (left), cage speed (middle) and the "
                    "largest-ball-load trajectory (right) against wall seconds per simulated second, one line per "
                    "engine, integrator and model switch over its steps: lower left is better.")
    return lines


def section_sweep():
    d = load("bench_sweep.json")
    return ["## Sweep runner", "",
            f"Command: `python validation/performance/bench_sweep.py`: {d['cases']} cases (T = 0.1 s each) took "
            f"{d['walls']['1']:.2f} s with one worker and {d['walls']['2']:.2f} s with two: speed-up "
            f"**{d['speedup']:.2f}** on the 2-core machine. Cases are written atomically, so an interrupted "
            "sweep resumes (tests/test_sweep.py); a case whose spec changed runs again, a failing case is "
            "recorded with its error while the others finish; `scheduler=` sends them to a Dask cluster.", ""]


def section_mutation():
    if not (OUT / "mutation_run.json").exists():
        return []
    d = load("mutation_run.json")
    lines = ["## Mutation run", "",
             f"Command: `python validation/consistency/mutation_run.py{' --quick' if d['set'] == 'quick' else ''}`: planted errors "
             "of 2 % (and sign errors) in the relations of exudyn_bearing/physics/ and the contact kernel, each in "
             "a temporary copy of the repository with a fresh numba cache, against the test files that check the "
             f"relation. Score: **{d['caught']} of {d['applied']}** applied mutants caught"
             + (f" ({d['total'] - d['applied']} not applied: their source snippet moved)" if d['total'] > d['applied']
                else "") + ".", "", "| mutant | planted error | file | result |", "|---|---|---|---|"]
    lines += [f"| {r['mutant']} | {r['error']} | {r['file'].replace('exudyn_bearing/', '')} | {r['result']} |"
              for r in d["rows"]]
    return lines + [""]


def section_round_off():
    d = load("round_off_sensitivity.json")
    lines = ["## Round-off sensitivity: which numbers are reproducible", "",
             "Command: `python validation/consistency/round_off_sensitivity.py` (engine: reference core, dt = 5 us). The same "
             "scene with F_r perturbed by a relative 0, +-1e-15 and 1e-14 (the last bits of the input); the table "
             "gives the relative spread (max - min) / |unperturbed| of each reported quantity. A code change that "
             "only reorders floating-point operations moves a quantity by about this much: comparisons between code "
             "versions (and between engines) are meaningful only beyond it.", "",
             "| scene | quantity | relative spread |", "|---|---|---|"]
    for scene, r in d.items():
        for k, v in r["quantities"].items():
            lines.append(f"| {scene} | {k} | {v['relative_spread']:.1e} |")
    lines += ["", "- Steady runs from the analytic state are reproducible to round-off. The protocol from rest is "
              "chaotic in its transients (cage balls rattle in their pockets): slide-to-roll medians of one ball and "
              "the largest start-up cage load move by percent to tens of percent under a last-bit perturbation, the "
              "steady-window loads and speeds by about 1e-5.", ""]
    return lines


def section_three_dof():
    d = load("three_dof.json")
    s = d["source"]
    ev = lambda z: f"{z[0]:.4g} {'+' if z[1] >= 0 else '-'} {abs(z[1]):.5g}i"  # noqa: E731
    pair = s["inner_pair"]
    lines = ["## 3-DOF vibration model (El Had et al. 2014)", "",
             "Command: `python validation/published/three_dof.py` (figures `out/three_dof_frf.png`, "
             "`out/three_dof_time_response.png`, `out/three_dof_modes.png`, each with its CSV). Theory and "
             "readings: docs/theory/vibration.md.", "",
             "**Where the source's eigenvalues come from.** It prints V = "
             + ", ".join(f"{v:g}" for v in s["printed_eigenvalues"]) + " 1/s. Its printed state matrix L has "
             "eigenvalues " + ", ".join(f"{v:.5g}" for v in s["printed_state_matrix_eigenvalues"])
             + " (the printed values to their 4-5 digits; its characteristic polynomial starts "
             f"X^6 {s['printed_polynomial'][1]:+.6g} X^5, the source prints -5,363 X^5). L is "
             "[[0, I], [+A^-1 C, +A^-1 B]]: both lower blocks carry the wrong sign (M y'' + B y' + C y = 0 gives "
             "-A^-1 C and -A^-1 B), and A^-1 B holds 413.25 where 43.5 x 9.9 = "
             f"{s['rebuilt_vs_printed_entries']['A^-1 B [5,5] = 43.5 * 9.9']:.2f}. With +k/M a ring on its spring "
             "has lambda^2 = +k/M, real roots +-sqrt(k/M), instead of +-i sqrt(k/M): "
             + "; ".join(f"{k}: sqrt(k/M) = {v['sqrt_k_over_M']:.5g} 1/s ({v['f_hz']:.5g} Hz)"
                         for k, v in s["sqrt_k_over_M"].items())
             + f". The inner-ring pair of L, {pair['source_roots'][0]:.6g} and {pair['source_roots'][1]:.6g}, "
             f"solves r^2 - b r - k/M = 0: product {pair['product']:.5g} against |lambda|^2 = "
             f"{pair['correct_modulus_squared']:.5g} of the correct root {ev(pair['correct_eigenvalue'])}, sum "
             f"{pair['sum']:.4g} against -2 Re(lambda) = {pair['correct_minus_twice_real']:.4g} (the source's "
             "rounded A^-1 and its 413.25 make the difference).", "",
             "Correct eigenvalues of the printed matrices (scipy.linalg.eig of [[0, I], [-M^-1 K, -M^-1 C]]): "
             + ", ".join(ev(r["eigenvalue"]) for r in s["correct_printed_matrices"]) + " 1/s.", "",
             "Each reading of the source's printed values (ball links k21 = 0.9925 N/m, C21 = 9.9072 N s/m, "
             "masses 25, 2, 23 g):", "",
             "| reading | eigenvalues [1/s] | f_n [Hz] | zeta |", "|---|---|---|---|"]
    for name, r in s["readings"].items():
        lines.append(f"| {name} | " + ", ".join(ev(m["eigenvalue"]) for m in r["modes"]) + " | "
                     + ", ".join(f"{m['f_n_hz']:.5g}" for m in r["modes"]) + " | "
                     + ", ".join(f"{m['zeta']:.3g}" for m in r["modes"]) + " |")
    fv = d["source_film_values"]
    lines += ["", "Real roots have zeta = 1 and f_n = |lambda| / 2 pi. The readings: inner_ring printed_matrix "
              "k3 = 1e8 N/m (its numeric matrix), parameter_list 1e7; outer_link printed_matrix: no ball / outer "
              "race link (its numeric matrices), eq7: k22 = 0.9925 N/m, C22 = 9.9072 N s/m; damping_row "
              "eq7_literal: the ball row of eq. 7 as printed (C22 on y2' twice, no y1' term).", "",
              "The source's ball-race values are not dimensional film coefficients. Read as the dimensionless "
              "values of its eqs. 5-6 with its printed prefactor, 0.9925 needs eps_0 = "
              + ", ".join(f"{e:.4f}" for e in fv["printed prefactor"]["k 0.9925"]) + " and 9.9072 needs eps_0 = "
              + ", ".join(f"{e:.4f}" for e in fv["printed prefactor"]["C 9.9072"])
              + "; with the corrected prefactor 0.9925 is reached at no eccentricity ("
              + (", ".join(f"{e:.4f}" for e in fv["corrected prefactor"]["k 0.9925"]) or "none")
              + ") and 9.9072 at " + ", ".join(f"{e:.4f}" for e in fv["corrected prefactor"]["C 9.9072"])
              + ". No single film gives both.", ""]
    for key, title in (("contact_model", "contact-model damping"), ("short_bearing", "short-bearing film damping")):
        v = d["derived"][key]
        dv = v["derivation"]
        ci, co = dv["contacts"]["inner"], dv["contacts"]["outer"]
        lines += [f"**Derived 6004, {title}** (F_r = {dv['radial_load']:g} N, {dv['omega'] * 30 / 3.141592653589793:.0f} "
                  f"rpm, P_d = {dv['diametral_clearance'] * 1e6:g} um, eta = {dv['viscosity']:g} Pa s): "
                  f"outer ring {dv['outer_ring']['mass'] * 1e3:.2f} g, oval mode {dv['outer_ring']['f_2_hz']:.0f} Hz, "
                  f"k1 = {dv['outer_ring']['stiffness']:.4g} N/m; inner ring {dv['inner_ring']['mass'] * 1e3:.2f} g, "
                  f"{dv['inner_ring']['f_2_hz']:.0f} Hz, k3 = {dv['inner_ring']['stiffness']:.4g} N/m; ball "
                  f"{dv['ball_mass'] * 1e3:.3f} g, Q = {dv['q_max']:.1f} N; inner / outer contact: Hertz "
                  f"{ci['k_hertz']:.4g} / {co['k_hertz']:.4g} N/m, h_min {ci['h_min'] * 1e9:.0f} / "
                  f"{co['h_min'] * 1e9:.0f} nm, eps_0 {ci['eccentricity']:.4f} / {co['eccentricity']:.4f}, film "
                  f"{ci['k_film']:.3g} / {co['k_film']:.3g} N/m, series link {ci['k_link']:.4g} / "
                  f"{co['k_link']:.4g} N/m; damping short-bearing {ci['c_film']:.3g} / {co['c_film']:.3g} N s/m, "
                  f"contact model {ci['c_contact_model']:.3g} / {co['c_contact_model']:.3g} N s/m (Lambda "
                  f"{ci['film_parameter']:.2f} / {co['film_parameter']:.2f}).", "",
                  "| eigenvalue [1/s] | f_n [Hz] | zeta | abs(shape) outer, ball, inner |", "|---|---|---|---|"]
        for m in v["modes"]:
            lines.append(f"| {ev(m['eigenvalue'])} | {m['f_n_hz']:.6g} | {m['zeta']:.4g} | "
                         + ", ".join(f"{x:.3g}" for x in m["shape_abs"]) + " |")
        tr = v["time_response"]
        lines += ["", f"Ball-pass train at BPFO = {tr['bpfo_hz']:.2f} Hz (half-sine pulses of {tr['amplitude_N']:g} N, "
                  f"{tr['pulse_duration_s'] * 1e3:.3f} ms, pushing outer ring and ball apart): peak displacements "
                  + ", ".join(f"{x * 1e9:.1f}" for x in tr["peak_displacement_m"]) + " nm (outer, ball, inner).", ""]
    ci = d["derived"]["short_bearing"]["derivation"]["contacts"]["inner"]
    lines += ["The source's short-bearing film damping, normalised with the load, the radial clearance and the "
              f"shaft speed, is {ci['c_film']:.3g} N s/m at the inner contact, {ci['c_film'] / ci['c_contact_model']:.2g} "
              f"times the contact model's damping there ({ci['c_contact_model']:.3g} N s/m, hysteretic at Lambda < 1; "
              f"its squeeze-film term alone is {ci['c_squeeze']:.3g} N s/m): it locks the ball to the rings, leaves "
              "one oscillating mode (the two rings and the ball moving together on k1 + k3) and turns the rest into "
              "real roots. The contact-model run keeps three lightly damped modes.", ""]
    lines += figure("three_dof_frf.png", "Direct receptances of the outer ring, ball and inner ring against "
                    "frequency: the source's printed matrices (left), the derived 6004 with short-bearing film "
                    "damping (middle) and with the contact model's damping (right); thin vertical lines at the "
                    "natural frequencies.")
    lines += figure("three_dof_time_response.png", "Response of the derived 6004 to the ball-pass force train at "
                    "BPFO (top: force, bottom: displacements), short-bearing damping (left) and contact-model "
                    "damping (right).")
    lines += figure("three_dof_modes.png", "Mode shapes (largest entry 1, signed by the real part) with their "
                    "eigenvalues or natural frequencies and damping ratios, for the same three models.")
    return lines
def section_quasistatic():
    d = load("quasistatic_acbb120.json")
    bq = load("bench_quasistatic.json")
    lines = ["## Quasi-static solver: the ACBB-120 of Gupta (2020)", "",
             "Command: `python validation/published/quasistatic_acbb120.py` (solver: `solve_quasistatic`). ACBB-120, "
             "25,000 rpm, 22,240 N thrust, cageless, M-50, films with the MIL-L-23699 entry at 492 K. Traction: "
             "`ester_curve_illustrative` (the form of Gupta's traction curve with illustrative parameters, not his "
             "Fig. 6) and `ehl_mil_l_23699_492K` (this project's EHL parameters). Ball 0 (all balls are equal).", "",
             "| traction | case | control | alpha_i [deg] | alpha_o [deg] | Q_i [N] | Q_o [N] | omega_m [rad/s] | "
             "omega_b [rad/s] | beta [deg] | spin/roll i | spin/roll o | P_i [W] | P_o [W] | P total [W] |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for tr, v in d["tractions"].items():
        for case in ("rigid_race_control", "race_control", "inner_control", "min_energy", "rigid_min_energy",
                     "min_energy_492K"):
            r = v[case]
            lines.append(f"| {tr} | {case} | {r['control_used']} | {r['alpha_inner_deg']:.2f} | "
                         f"{r['alpha_outer_deg']:.2f} | {r['q_inner_N']:.0f} | {r['q_outer_N']:.0f} | "
                         f"{r['orbital_speed_rad_s']:.1f} | {r['ball_speed_rad_s']:.0f} | {r['beta_deg']:.3f} | "
                         f"{r['spin_roll_inner']:.4f} | {r['spin_roll_outer']:.4f} | {r['dissipation_inner_W']:.0f} | "
                         f"{r['dissipation_outer_W']:.0f} | {r['dissipation_total_W']:.0f} |")
    lines.append("")
    for tr, v in d["tractions"].items():
        me = v["min_energy"]
        lines.append(f"- {tr}: minimum energy changes the total dissipation by **{100 * v['min_energy_change']:+.1f} %** "
                     f"against race control ({v['race_control']['control_used']} race by Jones' criterion; Gupta "
                     f"reports about -24 % with his traction curve); minimum check: Hessian eigenvalues "
                     f"{', '.join(f'{x:.3g}' for x in me['minimum_check']['hessian_eigenvalues'])}, neighbours higher "
                     f"{me['minimum_check']['neighbours_higher']}; pure-rolling points x1/a = "
                     f"{me['x1_over_a_outer']:.3f} (outer), x2/a = {me['x2_over_a_inner']:.3f} (inner); net rolling-"
                     f"direction traction on a ball (zero in a cageless steady state) {v['race_control']['traction_drag_N']:.1f} N "
                     f"under race control, {me['traction_drag_N']:.1f} N under minimum energy; traction coefficient "
                     f"the outer race must supply for the gyroscopic moment under race control "
                     f"{v['race_control']['gyro_traction_outer']:.4f}. Plots: "
                     f"`{Path(v['beta_scan']['plot']).name}`, `{Path(v['plot_slip']).name}`.")
    cv = d["strip_convergence"]
    lines.append(f"- Strip integration (default {DEFAULT_N_STRIPS} strips x {DEFAULT_N_ACROSS} points): total dissipation with the curve, race control / "
                 "minimum energy: " + "; ".join(f"{c['n_strips']}x{c['n_across']}: {c['race_control_W']:.1f} / "
                                                f"{c['min_energy_W']:.1f} W ({100 * c['change']:+.2f} %)" for c in cv)
                 + ".")
    rc, rg = d["tractions"]["ester_curve_illustrative"]["rigid_race_control"], \
        d["tractions"]["ester_curve_illustrative"]["race_control"]
    c = d["combined"]
    lines += [f"- Inner-ring growth at 25,000 rpm: {rg['inner_ring_growth_um']:.1f} um (rotating annular disc); "
              f"contact angles rigid -> growing rings: inner {rc['alpha_inner_deg']:.2f} -> {rg['alpha_inner_deg']:.2f}"
              f" deg, outer {rc['alpha_outer_deg']:.2f} -> {rg['alpha_outer_deg']:.2f} deg "
              "(`qs_acbb120_rigid_vs_growing.png`).",
              f"- Combined case F_r = 3 kN, M_y = 150 N m with the thrust: tilt_y = {c['displacement'][4] * 1e3:.3f} "
              f"mrad, inner loads {min(c['q_inner_N']):.0f} to {max(c['q_inner_N']):.0f} N, inner contact angles "
              f"{min(c['alpha_inner_deg']):.1f} to {max(c['alpha_inner_deg']):.1f} deg (`qs_acbb120_combined.png`).",
              ""]
    for tr, v in d["tractions"].items():
        lines += figure(Path(v["beta_scan"]["plot"]).name, f"Dissipation of one ball against the spin-axis angle "
                        f"beta with traction {tr}: the least dissipation at each fixed beta, the race-control "
                        "solution and the minimum-energy solution.")
        lines += figure(Path(v["plot_slip"]).name, f"Slip of ball 0 against its race along the major axis of the "
                        f"outer (left) and inner (right) contact ellipse, race control and minimum energy, traction "
                        f"{tr}.")
    lines += figure("qs_acbb120_rigid_vs_growing.png", "Contact loads (left) and contact angles (right) of all balls "
                    "against azimuth with rigid and with growing rings.")
    lines += figure("qs_acbb120_combined.png", "Contact loads (left) and contact angles (right) against azimuth under "
                    "the thrust alone and with F_r = 3 kN and M_y = 150 N m added.")
    lines += ["Speed (`python validation/performance/bench_quasistatic.py`, medians, one run):", "",
              "| case | wall [ms] | target [ms] |", "|---|---|---|"]
    for k, v in bq.items():
        if k.endswith("_s") and isinstance(v, float):
            t = bq["targets_s"].get(k)
            lines.append(f"| {k[:-2]} | {1e3 * v:.1f} | {'' if t is None else f'{1e3 * t:.0f}'} |")
    lines += ["", "Compiled contact-slip integration (`physics.contact_slip._contact_traction`, one call, "
              "timed in a compiled loop):", "", "| traction model | strips x points across | ns per call |",
              "|---|---|---|"]
    for k, v in bq["kernel_ns_per_call"].items():
        name, grid = k.split("|")
        lines.append(f"| {name} | {grid} | {v:.0f} |")
    return lines + [""]
def section_defects():
    d = load("bench_defects.json")
    lines = ["## Localized defects and vibration signals", "",
             "Command: `python validation/performance/bench_defects.py` (engine: reference core; 6205 at 1797 rpm, F_r = 1000 N, "
             "1 x 1.5 x 0.1 mm spall of `datasets.fault_defects`, dt = 1/(4 x 48 kHz) = 5.21 us, implicit tangential "
             "spring, housing force and inner-ring acceleration at 48 kHz).", ""]
    if "speed" in d:
        lines += ["| defect | wall per simulated second (median) | runs |", "|---|---|---|"]
        for k, v in d["speed"].items():
            lines.append(f"| {k} | {v['median_wall_per_sim_s']:.3f} s | {', '.join(f'{w:.3f}' for w in v['walls'])} |")
        lines.append("")
    if "resolution" in d:
        lines += ["Resolution: the same cases over 0.5 s at 5.21 us and at half that step; the strongest envelope "
                  "line of the housing force (band chosen by energy, first 0.1 s left out) and its amplitude at the "
                  "defect frequency:", "",
                  "| defect | defect frequency | line at 5.21 us / 2.60 us | amplitude change | rms change |",
                  "|---|---|---|---|---|"]
        for k, v in d["resolution"].items():
            a, b = v["dt_5.21us"], v["dt_2.60us"]
            lines.append(f"| {k} | {a['defect_Hz']:.2f} Hz | {a['line_Hz']:.2f} / {b['line_Hz']:.2f} Hz | "
                         f"{100 * v['rel_change_line']:+.1f} % | {100 * v['rel_change_rms']:+.1f} % |")
        lines.append("")
    if "no_defect" in d:
        n = d["no_defect"]
        shape = [k for k, v in n["arrays"].items() if not v["equal"] and v["max_abs_diff"] is None]
        differ = {k: v["max_abs_diff"] for k, v in n["arrays"].items()
                  if not v["equal"] and v["max_abs_diff"] is not None}
        if not differ:
            eq = "bitwise equal"
        elif max(differ.values()) <= 1e-12:
            eq = ("bitwise equal except " + ", ".join(f"{k} (largest difference {d:.3g}, round-off of the code "
                                                      f"changed since)" for k, d in differ.items()))
        else:
            eq = ("not bitwise equal: " + ", ".join(f"{k} (max diff {d:.3g})" for k, d in differ.items())
                  + "; the compiled arithmetic changed since (energy bookkeeping, which functions the kernel "
                  "inlines), and this 0.5 s run is chaotic: last-bit differences grow as under the 1e-15 "
                  "perturbations of the round-off section")
        if shape:
            eq += (" (" + ", ".join(shape) + ": other shape, the global diagnostics gained the energy columns "
                   "since; not compared)")
        lines += [f"No defects: the 6208 scene ({n['scene']}, T = {n['t_end']} s) run by this code and by the code "
                  f"before the defect feature ({n['baseline']}), both in one process in rotating order: median wall "
                  f"{n['median_wall_s']['baseline']:.3f} s (before) and {n['median_wall_s']['new']:.3f} s (now), median "
                  f"per-round ratio {n['median_pair_ratio']:.3f}, against {n['median_control_ratio']:.3f} for the new "
                  f"code against itself (the noise floor); every sampled array {eq}.", ""]
    return lines


def section_stiffness():
    d = load("stiffness_checks.json")
    bs = load("bench_stiffness.json")
    lines = ["## Linearised bearing stiffness and damping (quasi-static solver)", "",
             "Command: `python validation/consistency/stiffness_checks.py` (figures below, each with its CSV in "
             "validation/out). Matrices: `solve_quasistatic(...).stiffness` "
             "(central differences) and `.damping` (the contact model's normal damping condensed over each ball's "
             "two contacts in series); theory: docs/theory/vibration.md, sec. 8.", "",
             f"**Stiffness against the DEM** (6208, F_r = 3000 N; reference engine, dt = {d['increments']['dt'] * 1e6:g} "
             f"us; static increments F_r -+ {d['increments']['dFr']:g} N and F_a as given; ring position averaged "
             "over whole ball-pass periods after settling). Quasi-static value: the compliance of the translational "
             "block (the DEM ring cannot tilt) averaged over Z ball-set positions, rigid rings. The target is agreement within "
             f"{100 * d['tolerance']:.0f} %.", "",
             "| case | friction | dF_a [N] | k_xx DEM [N/m] | k_xx QS [N/m] | diff | k_zz DEM [N/m] | k_zz QS [N/m] | diff "
             "| k_zz QS secant [N/m] | within | DEM wall [s] |", "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in d["stiffness"]:
        dm, q, e = r["dem"], r["quasistatic"], r["relative_difference"]
        lines.append(f"| {r['case']} | {r['friction']} | {r['dFa']:g} | {dm['k_xx']:.5g} | {q['k_xx']:.5g} | "
                     f"{100 * e['k_xx']:+.2f} % | {dm['k_zz']:.5g} | {q['k_zz']:.5g} | {100 * e['k_zz']:+.2f} % | "
                     f"{q['k_zz_secant']:.5g} | {'yes' if r['within_tolerance'] else '**no**'} | {dm['wall_s']:.1f} |")
    fast = [r for r in d["stiffness"] if r["omega"] == 3000.0]
    lines += ["", "The matrix holds the ball kinematics (and so the gyroscopic traction) at the operating point; the "
              "secant column re-solves them at F_a. At 100 and 500 rad/s DEM and matrix agree within "
              + f"{100 * max(max(abs(v) for v in r['relative_difference'].values()) for r in d['stiffness'] if r['omega'] < 3000):.2f} %. "
              "At 3000 rad/s the radial stiffness agrees; the DEM's axial stiffness depends on its friction: "
              + "; ".join(f"friction {r['friction']}, dF_a {r['dFa']:g} N: {r['dem']['k_zz']:.4g} N/m" for r in fast)
              + f" against the matrix's {fast[0]['quasistatic']['k_zz']:.4g} N/m. Without friction the DEM reproduces "
              "the matrix; with it, its axial stiffness depends on the increment, so its tangential contact forces "
              "(Cundall-Strack springs, Coulomb friction) take part in the axial balance at this speed, which the "
              "matrix (normal contact forces and the gyroscopic traction, kinematics held) does not model. The "
              "mechanism inside the DEM was not isolated.", "",
              "**Damping against the DEM** (free decay: the ring kicked with 0.02 m/s, minus the same run without "
              "kick; logarithmic decrement of 15 peaks; dt = 1 us; prediction zeta = C_ii / (2 sqrt(K_ii m)), "
              "omega_n = sqrt(K_ii / m), m the DEM's ring mass, phase 0):", "",
              "| omega [rad/s] | axis | friction | zeta DEM | zeta matrix | ratio | omega_n DEM [1/s] | omega_n matrix "
              "[1/s] | ratio |", "|---|---|---|---|---|---|---|---|---|"]
    for r in d["damping"]:
        lines.append(f"| {r['omega']:g} | {r['axis']} | {r['friction']} | {r['dem']['zeta']:.5f} | "
                     f"{r['quasistatic']['zeta']:.5f} | {r['zeta_ratio']:.3f} | {r['dem']['omega_n']:.0f} | "
                     f"{r['quasistatic']['omega_n']:.0f} | {r['omega_ratio']:.3f} |")
    none = [r for r in d["damping"] if r["friction"] == "none"]
    lines += ["", "The matrix holds the contacts' normal damping only. With friction off the DEM's damping ratio is "
              f"within {100 * max(abs(r['zeta_ratio'] - 1) for r in none):.1f} % of it; with the DEM's friction "
              "the ratio grows with speed (friction damps the ring through the balls' tangential forces). The "
              "DEM's frequencies are lower because the condensation neglects the balls' inertia (friction off: "
              f"{100 * (1 - min(r['omega_ratio'] for r in none)):.1f} % at most) and, with friction, the balls' "
              "rolling inertia that the tangential forces couple to the ring.", ""]
    lines += figure("stiffness_dem_check.png", "Relative difference of the DEM's radial (left) and axial (right) "
                    "stiffness from the quasi-static matrix for each case and increment, with the 5 % target band.")
    lines += figure("stiffness_decay_500.png", "Free decay of the kicked inner ring at 500 rad/s in the DEM (kicked "
                    "minus unkicked run) against the envelope of the matrix's damping ratio.")
    t = d["three_dof"]
    op = t["operating_point"]
    r_ring = t["ring"].get("radius", 0.011)
    scale = np.array([1.0, 1.0, 1.0, r_ring, r_ring])
    names = ("x", "y", "axial", "tilt_x", "tilt_y")

    def dominant(m):
        a = np.array(m["shape_abs"]) * scale    # tilts times the ring radius: lengths like the translations
        order = np.argsort(a)[::-1]
        return " + ".join(names[i] for i in order if a[i] > 0.3 * a[order[0]])

    def zeta(z):
        return f"{z:.3g}" if abs(z) > 1e-9 else "0"
    inner = t["three_dof_modes"][t["three_dof_inner_mode"]]
    lines += [f"**3-DOF model against the linearised full model** (6004, F_r = {op['Fr']:g} N, "
              f"{op['omega'] * 30 / np.pi:.0f} rpm, P_d = {op['Pd'] * 1e6:g} um, rigid rings): most loaded ball "
              f"Q = {t['q_max']['quasistatic']:.2f} N (3-DOF {t['q_max']['three_dof']:.2f} N); Hertz tangent "
              f"stiffness inner / outer {t['k_hertz']['quasistatic_inner']:.4g} / {t['k_hertz']['quasistatic_outer']:.4g} "
              f"N/m (3-DOF {t['k_hertz']['three_dof_inner']:.4g} / {t['k_hertz']['three_dof_outer']:.4g}); contact "
              f"damping {t['c_contact']['quasistatic_inner']:.4g} / {t['c_contact']['quasistatic_outer']:.4g} N s/m "
              f"(3-DOF contact-model reading {t['c_contact']['three_dof_inner']:.4g} / "
              f"{t['c_contact']['three_dof_outer']:.4g}; Lambda {t['c_contact']['lambda_quasistatic_inner']:.3f}). "
              f"One ball, inner and outer Hertz in series: {t['k_ball']['quasistatic_hertz']:.4g} N/m; the 3-DOF "
              f"link with the film in series {t['k_ball']['three_dof_series_film']:.4g} N/m. The bearing: K_xx = "
              f"{t['k_xx']:.4g} N/m (sum over the balls of the series stiffness times cos^2 psi: "
              f"{t['k_xx_sum_over_balls']:.4g}), K_yy = {t['k_yy']:.4g} N/m, C_xx = {t['c_xx']:.4g}, C_yy = "
              f"{t['c_yy']:.4g} N s/m: the 3-DOF model's one-ball line holds 1/{t['effective_balls']:.3f} of the "
              "bearing's radial stiffness.", "",
              f"Rigid inner ring of the 3-DOF model's mass ({t['ring']['mass'] * 1e3:.2f} g, diametral inertia "
              f"{t['ring']['inertia_diametral']:.3g} kg m^2) on the 5x5 matrices, outer ring fixed: "
              + ", ".join(f"{m['f_n_hz']:.0f} Hz ({dominant(m)}, zeta {zeta(m['zeta'])})" for m in t["full_modes"][::2])
              + f". The 3-DOF model's inner-ring mode: {inner['f_n_hz']:.0f} Hz (zeta {inner['zeta']:.3g}), carried "
              f"by its ring-bending spring to ground k3 and one ball link (sqrt((k3 + k_link)/M3) = "
              f"{t['ring_on_one_ball_hz']:.0f} Hz), where the rigid ring on the bearing's K_xx alone gives "
              f"{t['ring_on_bearing_x_hz']:.0f} Hz; all 3-DOF modes: "
              + ", ".join(f"{m['f_n_hz']:.0f} Hz" for m in t["three_dof_modes"][::2])
              + ". The full model adds the bearing's y, axial and tilt modes, which the 3-DOF line cannot have; its "
              "axial and tilt modes are undamped here (radial contact normals carry no damping across them).", "",
              "Speed (`python validation/performance/bench_stiffness.py`, medians, one run):", "",
              "| case | wall [ms] | target [ms] |", "|---|---|---|"]
    for k, v in bs.items():
        if k.endswith("_s") and isinstance(v, float):
            tg = bs["targets_s"].get(k)
            lines.append(f"| {k[:-2]} | {1e3 * v:.1f} | {'' if tg is None else f'{1e3 * tg:.0f}'} |")
    return lines + [""]


def section_highspeed():
    d = load("highspeed.json")
    t = load("bench_traction.json")
    lines = ["## High-speed dynamics: traction over the contact ellipse", "",
             "Command: `python validation/consistency/highspeed_acbb120.py` (both engines; ACBB-120 of Gupta 2020, 25,000 rpm, "
             "22,240 N thrust, cageless, growing inner ring, traction over each ellipse with 16 strips, "
             f"dt = {d['settings']['dt'] * 1e6:g} us, {d['settings']['t_end'] * 1e3:g} ms from a quasi-static start; "
             "steady state = mean of the last 5 ms, ball 0 for loads and ratios, the whole bearing for the "
             "dissipation). Quasi-static solutions of the same traction model: outer-race control (Jones), minimum "
             "energy (Gupta) and the traction equilibrium (the ball's steady Newton-Euler equations, yaw pivoting "
             "for the gyroscopic moment, no hypothesis; docs/theory/quasistatic.md sec. 4).", ""]
    keys = ("q_inner", "q_outer", "alpha_inner", "alpha_outer", "orbital_speed", "ball_speed", "beta",
            "spin_roll_inner", "spin_roll_outer", "dissipation")
    head = "| traction | solution | Q_i [N] | Q_o [N] | alpha_i [deg] | alpha_o [deg] | omega_m [rad/s] | " \
           "omega_b [rad/s] | beta [deg] | spin/roll i | spin/roll o | P [W] |"
    lines += [head, "|" + "---|" * 12]
    for model, e in d["acbb120"].items():
        rows = [(f"quasi-static, {c}", v) for c, v in e["quasistatic"].items()]
        rows += [(f"dynamic: {n}", v["steady"]) for n, v in e["dynamic"].items()]
        for name, v in rows:
            lines.append(f"| {model} | {name} | " + " | ".join(
                f"{v[k]:.4g}" if not k.startswith("spin") else f"{v[k]:.4f}" for k in keys) + " |")
    lines.append("")
    for model, e in d["acbb120"].items():
        worst_eq = {k: max(abs(v["vs_equilibrium"][k]) for v in e["dynamic"].values()) for k in keys}
        me = e["quasistatic"]["min-energy"]
        dyn = next(iter(e["dynamic"].values()))["steady"]
        lines.append(
            f"- {model}: every dynamic run (both starts{', both engines' if len(e['dynamic']) > 2 else ''}) settles "
            f"on one steady state, the traction equilibrium: largest differences {100 * worst_eq['q_inner']:.2f} % "
            f"(Q_i), {100 * worst_eq['q_outer']:.2f} % (Q_o), {100 * worst_eq['orbital_speed']:.3f} % (omega_m), "
            f"{100 * worst_eq['ball_speed']:.3f} % (omega_b), {100 * worst_eq['dissipation']:.2f} % (P), "
            f"{worst_eq['alpha_inner']:.3f} / {worst_eq['alpha_outer']:.3f} deg (alpha_i / alpha_o), "
            f"{worst_eq['beta']:.3f} deg (beta), {worst_eq['spin_roll_inner']:.4f} / "
            f"{worst_eq['spin_roll_outer']:.4f} (spin/roll). Against the minimum-energy solution the steady state "
            f"dissipates {dyn['dissipation'] / me['dissipation']:.2f} times as much ({dyn['dissipation']:.0f} W "
            f"against {me['dissipation']:.0f} W), its spin axis tilts {dyn['beta']:.2f} deg instead of "
            f"{me['beta']:.2f} deg and its outer spin-to-roll ratio is {dyn['spin_roll_outer']:.3f} instead of "
            f"{me['spin_roll_outer']:.3f}: the gyroscopic moment needs transverse (pivot) slip at both contacts, "
            "which the minimum-energy hypothesis does not have. Gupta's finding that the dynamics settle on the "
            "minimum-energy solution is not reproduced with this traction model; from the race-control start the "
            "dissipation rises to the steady value rather than falling to the minimum-energy one.")
    lines.append("")
    for model in d["acbb120"]:
        lines += figure(f"highspeed_acbb120_{model}.png", f"Spin-to-roll ratios at the outer and inner race and the "
                        f"bearing's dissipation against time from the race-control and minimum-energy starts "
                        f"(traction {model}), with the three quasi-static solutions as horizontal lines (the form "
                        "of Gupta's Figs. 15 and 16).")
    ax = d["6208_axial"]
    lines += ["6208 under 3000 N thrust at 500 rad/s, 100 ms, steady window 80-100 ms (cage speed, ball spin "
              "[rad/s], beta [deg], dissipation [W]):", "", "| level, start | cage | ball spin | beta | P_i | P_o |",
              "|---|---|---|---|---|---|"]
    for k, v in ax.items():
        if k == "quasistatic equilibrium":
            continue
        lines.append(f"| {k} | {v['cage_speed']:.2f} | {v['ball_spin']:.2f} | {v['beta']:.2f} | "
                     f"{v['dissipation_inner']:.3g} | {v['dissipation_outer']:.3g} |")
    q = ax["quasistatic equilibrium"]
    lines += ["", f"The point-contact law leaves two steady states (from the analytic and the rest start); the ellipse "
              f"level reaches one, that of the quasi-static traction equilibrium (orbital speed {q['orbital_speed']:.2f} "
              f"rad/s, ball speed {q['ball_spin']:.2f} rad/s, beta {q['beta']:.2f} deg).", ""]
    pp = d["6208_papers"]
    lines += ["The DEM papers' 6208 case (3000 N radial, 500 rad/s, 50 ms, steady window 25-50 ms) at both levels:", "",
              "| level | q_max_inner [N] | q_max_outer [N] | cage [rad/s] | ball spin [rad/s] | Lambda_out(psi=0) | "
              "P_i [W] | P_o [W] |", "|---|---|---|---|---|---|---|---|"]
    for lvl, v in pp.items():
        lines.append(f"| {lvl} | {v['q_max_inner']:.1f} | {v['q_max_outer']:.1f} | {v['cage_speed']:.3f} | "
                     f"{v['ball_spin']:.2f} | {v['lambda_outer_psi0']:.3f} | {v['dissipation_inner']:.3g} | "
                     f"{v['dissipation_outer']:.3g} |")
    lines += ["", "The papers' numbers are those of the point level (the tests keep them). The ellipse level adds the "
              "rolling friction of the curvature-induced (Heathcote) slip across each ellipse: tens of watts "
              "where the point law, with no slip at the contact centre, gives none; the cage and the ball turn "
              "slightly faster, loads and Lambda move by about 0.1 %.", ""]
    lines += ["Cost and strip count: `python validation/performance/bench_traction.py` (6208, 3000 N, 500 rad/s, dt = "
              f"{t['scene']['dt'] * 1e6:g} us, medians of {t['repeat']} interleaved runs):", ""]
    for eng, c in t["cost"].items():
        lines.append(f"- {eng}: point level {c['us_per_step']['point']:.2f} us per step, ellipse level (the default "
                     f"16 x 4 points) {c['us_per_step']['ellipse default']:.2f} us: ratio "
                     f"**{c['ratio_ellipse_point']:.2f}**.")
    lines += ["", "| strips x points | error P | error cage speed | error ball spin | us per step |", "|---|---|---|---|---|"]
    for k, v in t["strips"].items():
        e = v["errors"]
        lines.append(f"| {k} | {100 * e['dissipation']:.3f} % | {100 * e['cage_speed']:.4f} % | "
                     f"{100 * e['ball_spin']:.4f} % | {v['us_per_step']:.2f} |")
    lines += ["", "Errors against 64 x 8 points at the same step. The default, 16 strips x 4 points across, was "
              "chosen on the quasi-static traction equilibrium of three high-speed cases "
              "(`python validation/studies/traction_convergence.py`: dissipation within 1 % and beta within 0.1 deg of "
              "64 x 8); the points across resolve the spin's cross-slip, which one point (classical strip theory) "
              "misses.", ""]
    return lines


def consistency_findings(d):
    """The findings of the consistency matrix, with its numbers."""
    rows, dev, t = d["rows"], d["deviations"], d["terms_7208"]
    axi = ["6208 Fa 3000 N 500 rad/s", "ACBB-120 25000 rpm 22240 N ellipse"]
    radial = ["6208 Fr 3000 N 500 rad/s", "6208 Fr 3000 N 1700 rad/s", "6205 Fr 1000 N 1797 rpm"]
    c7, c1 = "7208 Fr = Fa = 3000 N 500 rad/s", "6208 Fr 3000 N 1 rad/s"
    keys = ("q_max_inner", "q_max_outer", "alpha_inner", "alpha_outer", "orbital_speed", "ball_speed", "beta",
            "dissipation")

    def worst(cases):
        return {k: max(dev[n][k] for n in cases) for k in keys}

    def summary(w):
        return (f"{100 * w['q_max_inner']:.3f} % / {100 * w['q_max_outer']:.3f} % (Q_i / Q_o), "
                f"{w['alpha_inner']:.3f} / {w['alpha_outer']:.3f} deg (alpha_i / alpha_o), "
                f"{100 * w['orbital_speed']:.3f} % / {100 * w['ball_speed']:.3f} % (omega_m / omega_b), "
                f"{w['beta']:.3f} deg (beta), {100 * w['dissipation']:.2f} % (P)")
    e7, r7 = dev[c7], rows[c7]
    q7 = r7["qs equilibrium, run's ball positions"]
    eq_res = max(abs(rows[n]["qs equilibrium"]["energy_residual"]) for n in axi + [c7])
    p_ac = rows["ACBB-120 25000 rpm 22240 N point"]["reference"]["dissipation"]
    e_ac = rows["ACBB-120 25000 rpm 22240 N ellipse"]["reference"]["dissipation"]
    c17 = rows["6208 Fr 3000 N 1700 rad/s"]
    r5 = rows["6208 Fr 3000 N 500 rad/s"]
    eq7 = r7["qs equilibrium"]
    out = [
        "Findings:", "",
        "- Static = quasi-static at zero speed: largest relative difference "
        f"{max(e['static'] for e in dev.values() if 'static' in e):.1e} (loads, contact angles; two solves to a "
        "residual of 1e-10).",
        "- The traction equilibrium converges on every case; where every ball is loaded at both races (6208 "
        f"thrust, 7208, ACBB-120) its energy residual is at most {eq_res:.0e}. Under radial load the balls with "
        "a contact without load (the unloaded half; at speed pressed on the outer race by centrifugal force) have "
        "no equilibrium: nothing drives them. The solver carries them at the cage speed (the mean orbital speed "
        "of the balls in equilibrium), rolling on the outer race (`control_used` 'cage'); their outer-contact "
        "dissipation is what a cage draws from the loaded balls, which a cageless balance does not carry, and "
        f"shows as the energy residual ({c17['qs equilibrium']['energy_residual']:.1e} for the 6208 at 1700 rad/s, "
        f"{c17['qs equilibrium']['balls_in_equilibrium']:.0f} of 9 balls in equilibrium).",
        "- Reference engine = traction equilibrium, axially loaded (6208 thrust, ACBB-120 at the ellipse level): "
        f"within {summary(worst(axi))}. Radially loaded 6208 and 6205 (against the equilibrium at the run's ball "
        f"positions): within {summary(worst(radial))}. All targets met.",
        f"- At 1 rad/s (6208) loads and speeds agree within {100 * dev[c1]['q_max_inner']:.2f} % and "
        f"{100 * dev[c1]['orbital_speed']:.2f} %, but the run dissipates {rows[c1]['reference']['dissipation']:.4f} W "
        f"against {rows[c1]['qs equilibrium']['dissipation']:.4f} W: not explained here (both are far below any "
        "other loss of the bearing; open).",
        "- Engines: largest relative difference of Q_i, Q_o, omega_m, P per case: "
        + ", ".join(f"{n} {100 * dev[n]['engines']:.2g} %" for n in dev)
        + ". Where every ball is loaded and the run steady (6208 thrust, ACBB-120 at the ellipse level) the two "
        "engines agree to 2e-5 or better; the point-level ACBB-120 run is not steady in 12 ms (window energy "
        f"residual {rows['ACBB-120 25000 rpm 22240 N point']['reference']['energy_residual']:.1f}: the balls are "
        "still changing speed) and the engines differ along that transient. In the cageless radial runs "
        "the balls of the unloaded half have no equilibrium (neutral: nothing sets their orbital speed), so "
        "the two engines' round-off moves them apart (the ball nearest psi = 0 in the last sample of the 6208 at "
        f"500 rad/s: {r5['reference']['psi_nearest_deg'][-1]:.1f} deg in the reference engine, "
        f"{r5['exudyn']['psi_nearest_deg'][-1]:.1f} deg in the element), and the loads read at psi = 0 differ "
        "with the position; each engine agrees with the quasi-static solution at its own ball positions.",
        f"- 7208 (F_r = F_a = 3000 N): the quasi-static equilibrium gives its balls their own orbital speeds, "
        f"{eq7['orbital_speed_min']:.1f} to {eq7['orbital_speed_max']:.1f} rad/s (the lightly loaded balls "
        "faster). Without a cage they close up on the balls ahead (the model has no ball-to-ball contact), the "
        "spacing changes and so do the loads: over 12 ms the cageless reference run moves "
        f"{100 * e7['q_max_inner']:.1f} % (Q_i) off the equilibrium at its ball positions and dissipates "
        f"{r7['reference']['dissipation']:.1f} W against {q7['dissipation']:.1f} W; the two engines, on this "
        f"non-steady path, differ by {100 * e7['engines']:.1f} %. The run with the cage, which removes the drift, "
        f"stays at Q_i = {r7['reference cage']['q_max_inner']:.1f} N against {q7['q_max_inner']:.1f} N "
        f"({100 * abs(r7['reference cage']['q_max_inner'] / q7['q_max_inner'] - 1):.1f} %), but dissipates "
        f"{r7['reference cage']['dissipation']:.1f} W: the cage holds the light balls at its speed against their "
        "own, and that sliding costs power the cageless quasi-static balance does not have. A quasi-static "
        "solution of this case with a cage (one orbital speed, cage forces on the balls) is the missing piece; "
        "until then the quasi-static answer for a radially loaded angular-contact bearing at speed is that of "
        "independent balls.",
        f"- Point against ellipse level (ACBB-120): the point law has no rolling losses; the reference engine "
        f"dissipates {p_ac:.0f} W at the point level against {e_ac:.0f} W at the ellipse level and its loads lie "
        f"{100 * dev['ACBB-120 25000 rpm 22240 N point']['q_max_inner']:.1f} % (Q_i) off the traction "
        "equilibrium, which is an ellipse-level solution: a different contact model, not a disagreement.",
        f"- The 7208 term by term: from {t['zero speed']['q_max_inner']:.1f} N at zero speed to "
        f"{t['500 rad/s equilibrium']['q_max_inner']:.1f} N in the traction equilibrium at 500 rad/s "
        f"(+{100 * (t['500 rad/s equilibrium']['q_max_inner'] / t['zero speed']['q_max_inner'] - 1):.1f} %). "
        f"Without centrifugal force {t['500 rad/s equilibrium, no centrifugal force']['q_max_inner']:.1f} N; "
        f"without the gyroscopic traction {t['500 rad/s equilibrium, no gyroscopic traction']['q_max_inner']:.1f} N; "
        f"without ring growth {t['500 rad/s equilibrium, no ring growth']['q_max_inner']:.1f} N; with Coulomb "
        f"traction (no film) {t['500 rad/s equilibrium, Coulomb traction 0.1 (no film)']['q_max_inner']:.1f} N. "
        f"The centrifugal force (up to {t['500 rad/s equilibrium']['centrifugal_force']:.1f} N per ball) does it: the balls of the unloaded half, loose at zero speed, "
        "are pressed outward and, as a single angular contact cannot hold a radial force, roll along the outer "
        "groove until they wedge against the inner race (smallest inner load from "
        f"{t['zero speed']['q_min_inner']:.0f} to {t['500 rad/s equilibrium']['q_min_inner']:.0f} N, inner "
        f"contact angles up to {t['500 rad/s equilibrium']['alpha_inner_max']:.1f} deg against "
        f"{t['zero speed']['alpha_inner_max']:.1f} deg); their reactions move the inner ring axially by "
        f"{t['500 rad/s equilibrium']['delta_a'] - t['zero speed']['delta_a']:.1f} um and load the loaded half. "
        "That is physics, and the caged run above keeps it. Race control moves the loads further, to "
        f"{t['500 rad/s outer']['q_max_inner']:.1f} N (outer) and {t['500 rad/s inner']['q_max_inner']:.1f} N "
        "(inner): the hypothesis puts the whole gyroscopic moment as a traction M_g / R_b on the controlling race "
        "(Jones' convention), a net transverse force on the ball that tilts the light balls' contact line, and "
        "it sets their orbital speed and so their centrifugal force (without the gyroscopic traction "
        f"{t['500 rad/s outer, no gyroscopic traction']['q_max_inner']:.1f} and "
        f"{t['500 rad/s inner, no gyroscopic traction']['q_max_inner']:.1f} N). The net traction a kinematic "
        "hypothesis leaves on the ball acts along the orbit and enters no load equation; it shows as the energy "
        f"residual ({t['500 rad/s outer']['energy_residual']:.2f} outer, "
        f"{t['500 rad/s inner']['energy_residual']:.2f} inner). The race-control loads are a hypothesis's; the "
        "physical answer is the traction equilibrium, which did not converge on this case before (balls of the "
        "unloaded half left the continuation in the ball's inertia for a spurious root) and now does, with an "
        "adaptive continuation. With the tilt free the solver refuses the case: "
        + (r7["qs equilibrium tilt free"].get("error", "").split(":", 1)[-1].strip() or "solved") + ".",
    ]
    return out


def section_consistency():
    d = load("consistency_matrix.json")
    rows, dev, terms = d["rows"], d["deviations"], d["terms_7208"]
    lines = ["## Consistency of the solvers", "",
             "Command: `python validation/consistency/consistency_matrix.py` (static, the quasi-static solver under each "
             "control, the reference engine and the Exudyn element on the same cases; ring growth on everywhere, "
             "tilt held; dynamic runs cageless at the ellipse traction level unless the row says otherwise, "
             f"{'4' if d['quick'] else '12'} ms from the quasi-static traction equilibrium with the step of "
             "`stable_step`; ring pose and powers are means over the second half, per-ball values those of the "
             "ball nearest psi = 0 at three samples of it; the quasi-static per-ball values are those of ball 0 at "
             "psi = 0, and under radial load also of the same balls as the run at the run's ball positions, row "
             "'qs equilibrium, run's ball positions', which the reference engine is compared with). Units: loads N, angles "
             "deg, ring displacement um, speeds rad/s (ball speed in the orbiting frame), powers W; the energy "
             "residual is (drive - dissipation [- change of kinetic energy]) / drive.", "",
             "| case | solver | Q_i | Q_o | alpha_i | alpha_o | delta_r | delta_a | omega_m | omega_b | beta | "
             "spin/roll i | spin/roll o | P | drive | energy residual |", "|" + "---|" * 16]
    keys = ("q_max_inner", "q_max_outer", "alpha_inner", "alpha_outer", "delta_r", "delta_a", "orbital_speed",
            "ball_speed", "beta", "spin_roll_inner", "spin_roll_outer", "dissipation", "drive_power",
            "energy_residual")

    def cell(v, k):
        x = v.get(k)
        if x is None or (isinstance(x, float) and math.isnan(x)):
            return ""
        if k == "energy_residual":
            return f"{x:.1e}"
        if k.startswith("spin"):
            return f"{x:.4f}"
        if k.startswith(("alpha", "delta", "beta")):
            return f"{x + 0.0:.3f}".replace("-0.000", "0.000")
        return f"{x:.1f}" if k.startswith("q_") else f"{x:.5g}"
    for name, r in rows.items():
        for solver, v in r.items():
            if "error" in v:
                lines.append(f"| {name} | {solver} | " + "refused: " + v["error"].split(":")[1].split("(")[0].strip()
                             + " |" * 14)
                continue
            lines.append(f"| {name} | {solver} | " + " | ".join(cell(v, k) for k in keys) + " |")
    lines += ["", "Reference engine against the quasi-static traction equilibrium (relative differences; angles in deg), "
              "the two engines against each other (largest relative difference of Q_i, Q_o, omega_m, P) and "
              "static against the quasi-static solver at zero speed (Q_i, alpha_i):", "",
              "| case | Q_i | Q_o | alpha_i [deg] | alpha_o [deg] | omega_m | omega_b | beta [deg] | P | engines | "
              "static |",
              "|" + "---|" * 11]
    for name, e in dev.items():
        cells = [f"{e[k]:.3f}" if k in ("alpha_inner", "alpha_outer", "beta") else f"{100 * e[k]:.3g} %" for k in
                 ("q_max_inner", "q_max_outer", "alpha_inner", "alpha_outer", "orbital_speed", "ball_speed", "beta",
                  "dissipation", "engines")]
        cells.append(f"{e['static']:.1e}" if "static" in e else "")
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    lines += [""] + figure("consistency_matrix.png", "Reference engine against the quasi-static traction "
                           "equilibrium, per case and quantity (beta in degrees), and the Exudyn element against "
                           "the reference engine, with the targets 1 % (dashed), 3 % (dotted) and 0.1 % "
                           "(dash-dotted).")
    lines += ["The 7208 (F_r = F_a = 3000 N, tilt held) term by term in the quasi-static solver: the largest "
              "inner load, the ring's axial displacement and the smallest inner load with one effect switched "
              "off at a time (the centrifugal force and the transverse traction that carries the gyroscopic "
              "moment are zeroed in the ring balance; 'centrifugal force only' also drops ring growth):", "",
              "| solution | Q_i,max [N] | delta_a [um] | Q_i,min [N] |", "|---|---|---|---|"]
    for k, v in terms.items():
        lines.append(f"| {k} | {v['q_max_inner']:.2f} | {v['delta_a']:.3f} | {v['q_min_inner']:.2f} |")
    lines += [""] + consistency_findings(d) + [""]
    return lines


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--no-run", action="store_true", help="only write the report from existing outputs")
    ap.add_argument("--fresh", action="store_true", help="delete validation/out first (sweeps otherwise resume)")
    ap.add_argument("--start-at", metavar="SCRIPT", choices=[script_entry(e)[0] for e in SCRIPTS],
                    help="run the scripts from this one on (the earlier ones' outputs kept)")
    args = ap.parse_args(argv)
    if args.fresh and OUT.exists():
        import shutil

        shutil.rmtree(OUT)
    if not args.no_run:
        OUT.mkdir(exist_ok=True)
        run_all(start_at=args.start_at)
    walls = json.loads((OUT / "make_report_walls.json").read_text()) if (OUT / "make_report_walls.json").exists() \
        else {}
    head = ["# Validation report", "",
            "Generated by `python validation/make_report.py` on "
            f"{time.strftime('%Y-%m-%d %H:%M')} ({platform.processor() or platform.machine()}, "
            f"Python {platform.python_version()}); every number below was printed by the command named in its "
            "section. The machines are shared and noisy: wall times are medians where repeated, ratios matter "
            "more than absolute values.", ""]
    machine_path = OUT / "make_report_machine.json"
    machine = machine_sentence(json.loads(machine_path.read_text()) if machine_path.exists() else {})
    if machine:
        head += [machine, ""]
    probe_path = OUT / "make_report_probe.json"
    probed = probe_sentence(json.loads(probe_path.read_text()) if probe_path.exists() else {})
    if probed:
        head += [probed, ""]
    if walls:
        head += [f"Wall time of this regeneration: {sum(walls.values()) / 60:.0f} min in all; of each script: " +
                 ", ".join(f"{k} {v:.0f} s" for k, v in walls.items()) + ".", ""]
    body = (section_reference() + section_cage_step() + section_element() + section_fast_limits() + section_cross()
            + section_peer()
            + section_figures()
            + section_work_precision() + section_sweep() + section_quasistatic() + section_three_dof()
            + section_defects() + section_stiffness() + section_highspeed() + section_consistency()
            + section_new_checks() + section_round_off() + section_mutation())
    (HERE / "REPORT.md").write_text("\n".join(head + body))
    remove_unpublished()
    print(f"written {HERE / 'REPORT.md'}")


if __name__ == "__main__":
    main()
