"""Mutation run: plant small errors in the physics and see whether the tests catch them.

Each mutant is one planted error of 1-5 % (or a sign error) in one relation
of ``exudyn_bearing/physics/`` or the contact kernel
(``exudyn_bearing/model/contact.py``), given as (file, exact source snippet,
replacement). For every mutant the script copies the repository's tracked
files into a temporary directory (the working tree is never modified),
replaces the snippet there, and runs the test files that check that relation
against the copy, with a fresh ``NUMBA_CACHE_DIR`` per run (the kernels
compile from the mutated source). A mutant is

* ``caught`` when pytest fails (exit status 1),
* ``MISSED`` when the tests pass,
* ``not applied`` when its snippet is not found exactly once (the source
  moved on: refresh the snippet), or ``error`` for any other pytest status.

A baseline run of the unmutated copy comes first: if its tests fail, every
mutant would look caught, and the run stops.

The score is caught / applied. Every planted error of 2 % or more must be
caught (the tests run here are part of the default test command,
``python -m pytest``, so a mutant caught here is caught there).

Usage (from the repository root)::

    python validation/consistency/mutation_run.py           # all mutants (about 20-40 min on the 2-core machine)
    python validation/consistency/mutation_run.py --quick   # the representative set (marked q below)
    python validation/consistency/mutation_run.py --only ehl_mk_prefactor traction_pressure_two_thirds
    python validation/consistency/mutation_run.py --quick --strict   # exit status 1 if a mutant is missed (CI)

It writes validation/out/mutation_run.json; validation/make_report.py runs
the ``--quick`` set and prints the score in the report's last section.

Re-run it when physics changes (``python validation/consistency/mutation_run.py --quick``).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
PHYS = "exudyn_bearing/physics/"
KERNEL = "exudyn_bearing/model/contact.py"
PUB = "tests/test_published_values.py"

#: (name, quick, size, file, snippet, replacement, test files)
MUTANTS = [
    # -- film thickness (ehl.py)
    ("ehl_mk_prefactor", True, "-2 %", PHYS + "ehl.py",
     "return on * (1.637 * np.exp(", "return on * (0.98 * 1.637 * np.exp(", [PUB, "tests/test_lubrication.py"]),
    ("ehl_hd_prefactor", True, "+2 %", PHYS + "ehl.py",
     "return 3.63 * exp_e", "return 1.02 * 3.63 * exp_e", [PUB, "tests/test_lubrication.py"]),
    ("ehl_hd_central_prefactor", False, "-2 %", PHYS + "ehl.py",
     "return on * (2.69 * np.exp(", "return on * (0.98 * 2.69 * np.exp(", [PUB, "tests/test_lubrication.py"]),
    ("ehl_film_parameter", False, "+2 %", PHYS + "ehl.py",
     "return h_min / composite_roughness", "return 1.02 * h_min / composite_roughness",
     [PUB, "tests/test_lubrication.py"]),
    # -- Hertz (hertz.py)
    ("hertz_stiffness", True, "+2 %", PHYS + "hertz.py",
     "return math.pi * kappa * e_prime * math.sqrt(", "return 1.02 * math.pi * kappa * e_prime * math.sqrt(",
     [PUB, "tests/test_hertz.py"]),
    ("hertz_p_max", True, "+2 %", PHYS + "hertz.py",
     "pmax = 1.5 * load / (math.pi * a * b)", "pmax = 1.53 * load / (math.pi * a * b)",
     [PUB, "tests/test_hertz.py"]),
    # -- damping (damping.py)
    ("damping_hunt_crossley", True, "+2 %", PHYS + "damping.py",
     "return 1.5 * alpha_e * stiffness * d * np.sqrt(d)", "return 1.53 * alpha_e * stiffness * d * np.sqrt(d)",
     [PUB, "tests/test_lubrication.py"]),
    ("damping_fluid", False, "-2 %", PHYS + "damping.py",
     "return 3.0 * math.pi * eta * a / math.sqrt(2.0) * x * np.sqrt(x)",
     "return 2.94 * math.pi * eta * a / math.sqrt(2.0) * x * np.sqrt(x)", [PUB, "tests/test_lubrication.py"]),
    ("damping_series", False, "+2 %", PHYS + "damping.py",
     "return c_hyst * c_fluid / s if s > 0.0 else 0.0", "return 1.02 * c_hyst * c_fluid / s if s > 0.0 else 0.0",
     [PUB, "tests/test_lubrication.py"]),
    # -- friction (friction.py)
    ("friction_stribeck_fit", True, "+2 % of the slope", PHYS + "friction.py",
     "return mu_boundary + s * (mu_full_film - mu_boundary)",
     "return mu_boundary + 1.02 * s * (mu_full_film - mu_boundary)", [PUB, "tests/test_lubrication.py"]),
    # -- kinematics (kinematics.py)
    ("kinematics_cage_speed", True, "-2 % of g", PHYS + "kinematics.py",
     "return 0.5 * omega_inner * (1.0 - g) + 0.5 * omega_outer * (1.0 + g)",
     "return 0.5 * omega_inner * (1.0 - 1.02 * g) + 0.5 * omega_outer * (1.0 + g)",
     [PUB, "tests/test_kinematics.py"]),
    ("kinematics_ball_spin_sign", False, "sign of g^2", PHYS + "kinematics.py",
     "* (1.0 - g * g) * (omega_inner - omega_outer)", "* (1.0 + g * g) * (omega_inner - omega_outer)",
     [PUB, "tests/test_kinematics.py"]),
    ("kinematics_centrifugal", False, "+2 %", PHYS + "kinematics.py",
     "return ball_mass * pitch_radius * np.square(cage_speed)",
     "return 1.02 * ball_mass * pitch_radius * np.square(cage_speed)", [PUB, "tests/test_kinematics.py"]),
    # -- load distribution (load_distribution.py)
    ("load_stribeck_exponent", True, "exponent 1.5 -> 1.53", PHYS + "load_distribution.py",
     "return q_max * np.where(x > 0.0, np.abs(x) ** 1.5, 0.0)",
     "return q_max * np.where(x > 0.0, np.abs(x) ** 1.53, 0.0)", [PUB, "tests/test_load_distribution.py"]),
    ("load_zone_clearance_sign", False, "sign of P_d", PHYS + "load_distribution.py",
     "(delta_a * np.sin(contact_angle) - 0.5 * diametral_clearance)",
     "(delta_a * np.sin(contact_angle) + 0.5 * diametral_clearance)", [PUB, "tests/test_load_distribution.py"]),
    # -- ring growth (ring_growth.py)
    ("ring_growth_disc", True, "+2 %", PHYS + "ring_growth.py",
     "return (3.0 + nu) * (1.0 - nu) * density", "return 1.02 * (3.0 + nu) * (1.0 - nu) * density",
     ["tests/test_ring_growth.py"]),
    # -- traction laws (traction.py)
    ("traction_curve_slope", True, "+2 % of B", PHYS + "traction.py",
     "return (a + b * srr) * math.exp(-c * srr) + d", "return (a + 1.02 * b * srr) * math.exp(-c * srr) + d",
     [PUB, "tests/test_traction.py"]),
    ("traction_ehl_barus", False, "+2 % in xi p", PHYS + "traction.py",
     "ln_tn = math.log(viscosity * slip / film) + pressure_viscosity * pressure",
     "ln_tn = math.log(viscosity * slip / film) + 1.02 * pressure_viscosity * pressure",
     [PUB, "tests/test_traction.py"]),
    # -- traction over the ellipse (contact_slip.py)
    ("traction_pressure_two_thirds", True, "pressure x 2/3", PHYS + "contact_slip.py",
     "pressure = p0 * sm * sk", "pressure = p0 * sm * sk * (2.0 / 3.0)", [PUB]),
    ("traction_pressure_2pc", True, "pressure +2 %", PHYS + "contact_slip.py",
     "pressure = p0 * sm * sk", "pressure = 1.02 * p0 * sm * sk", [PUB]),
    ("traction_strip_loads", True, "+2 %", PHYS + "contact_slip.py",
     "wscale = 0.75 * load * (2.0 / math.pi) * theta", "wscale = 0.765 * load * (2.0 / math.pi) * theta", [PUB]),
    ("traction_spin_lever", False, "+2 % lever", PHYS + "contact_slip.py",
     "mz += x * ty - y * tx", "mz += 1.02 * (x * ty - y * tx)", [PUB]),
    # -- the contact kernel (model/contact.py)
    ("kernel_normal_law", True, "+2 %", KERNEL,
     "return kst * delta * sq, 1.5 * kst * sq,", "return 1.02 * kst * delta * sq, 1.5 * kst * sq,", [PUB]),
    ("kernel_lambda", True, "+2 %", KERNEL,
     "lam = h * (1.0 / p[P_SIGMA])", "lam = 1.02 * h * (1.0 / p[P_SIGMA])", [PUB]),
    ("kernel_fluid_damping", True, "+2 % eta", KERNEL,
     "c_fl = _damping_fluid(p[P_ETA], major,", "c_fl = _damping_fluid(1.02 * p[P_ETA], major,", [PUB]),
    ("kernel_traction_slip_sign", True, "sign of v0", KERNEL,
     "v0 = sx * exx + sy * exy + sz * exz", "v0 = -(sx * exx + sy * exy + sz * exz)", [PUB]),
]


def tracked_files():
    out = subprocess.run(["git", "ls-files", "-z"], cwd=ROOT, capture_output=True, text=True, check=True)
    return [f for f in out.stdout.split("\0") if f]


def make_copy(dest):
    for rel in tracked_files():
        src = ROOT / rel
        if src.is_file():
            target = dest / rel
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(src, target)
    # a git repository, so that the tests that read `git status` / `git ls-files` see a clean tree
    for cmd in (["init", "-q"], ["add", "-A"], ["-c", "user.name=mutation", "-c", "user.email=m@localhost",
                                                 "commit", "-q", "-m", "copy"]):
        subprocess.run(["git", *cmd], cwd=dest, check=True, capture_output=True)


def run_tests(copy, files, timeout):
    """pytest exit status of ``files`` in ``copy`` with a fresh numba cache, and the wall time."""
    with tempfile.TemporaryDirectory(prefix="numba-mut-") as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache, PYTHONPATH=str(copy), EXUDYN_BEARING_ALLOW_TREE_WRITES="1")
        t0 = time.perf_counter()
        try:
            rc = subprocess.run([sys.executable, "-m", "pytest", "-x", "-q", "-p", "no:cacheprovider", *files],
                                cwd=copy, env=env, capture_output=True, text=True, timeout=timeout).returncode
        except subprocess.TimeoutExpired:
            rc = "timeout"
    return rc, time.perf_counter() - t0


def apply(copy, path, snippet, replacement):
    f = copy / path
    text = f.read_text()
    if text.count(snippet) != 1:
        return False
    f.write_text(text.replace(snippet, replacement))
    return True


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="the representative set only")
    ap.add_argument("--only", nargs="+", metavar="NAME", help="these mutants only")
    ap.add_argument("--timeout", type=float, default=900.0, help="per pytest run [s]")
    ap.add_argument("--strict", action="store_true", help="exit status 1 when a mutant is missed")
    args = ap.parse_args(argv)
    chosen = [m for m in MUTANTS if (not args.quick or m[1]) and (not args.only or m[0] in args.only)]
    files = sorted({f for m in chosen for f in m[6]})
    with tempfile.TemporaryDirectory(prefix="mutation-") as tmp:
        base = Path(tmp) / "base"
        make_copy(base)
        rc, wall = run_tests(base, files, args.timeout)
        print(f"baseline (no mutation): {' '.join(files)}: pytest status {rc}, {wall:.0f} s", flush=True)
        if rc != 0:
            print("the unmutated tests do not pass in the copy: no mutant can be judged")
            return 2
        rows = []
        for name, _quick, size, path, snippet, replacement, tests in chosen:
            copy = Path(tmp) / name
            shutil.copytree(base, copy)
            if not apply(copy, path, snippet, replacement):
                rows.append((name, size, path, "not applied", 0.0))
            else:
                rc, wall = run_tests(copy, tests, args.timeout)
                rows.append((name, size, path, {0: "MISSED", 1: "caught"}.get(rc, f"error ({rc})"), wall))
            shutil.rmtree(copy, ignore_errors=True)
            print(f"{rows[-1][0]:32s} {rows[-1][1]:22s} {rows[-1][3]:12s} {rows[-1][4]:5.0f} s", flush=True)
    applied = [r for r in rows if r[3] in ("caught", "MISSED")]
    caught = [r for r in applied if r[3] == "caught"]
    print()
    print("| mutant | planted error | file | result |")
    print("|---|---|---|---|")
    for name, size, path, result, _w in rows:
        print(f"| {name} | {size} | {path.replace('exudyn_bearing/', '')} | {result} |")
    print()
    out = ROOT / "validation" / "out"
    out.mkdir(exist_ok=True)
    (out / "mutation_run.json").write_text(json.dumps({
        "set": "quick" if args.quick else "all", "caught": len(caught), "applied": len(applied), "total": len(rows),
        "rows": [{"mutant": r[0], "error": r[1], "file": r[2], "result": r[3], "wall_s": r[4]} for r in rows]},
        indent=2))
    print(f"score: {len(caught)} of {len(applied)} applied mutants caught"
          f"{'' if len(applied) == len(rows) else f' ({len(rows) - len(applied)} not applied or errors)'}"
          f" ({'--quick' if args.quick else 'all'} set)")
    return 1 if args.strict and len(caught) < len(applied) else 0


def report_section(run):
    """The report's mutation-run section, from mutation_run.json (none without it)."""
    if not (run.out / "mutation_run.json").exists():
        return ""
    d = run.load("mutation_run.json")
    lines = ["## Mutation run", "",
             f"Command: `python validation/consistency/mutation_run.py{' --quick' if d['set'] == 'quick' else ''}`: planted errors "
             "of 2 % (and sign errors) in the relations of exudyn_bearing/physics/ and the contact kernel, each in "
             "a temporary copy of the repository with a fresh numba cache, against the test files that check the "
             f"relation. Score: **{d['caught']} of {d['applied']}** applied mutants caught"
             + (f" ({d['total'] - d['applied']} not applied: their source snippet moved)" if d['total'] > d['applied']
                else "") + ".", "", "| mutant | planted error | file | result |", "|---|---|---|---|"]
    lines += [f"| {r['mutant']} | {r['error']} | {r['file'].replace('exudyn_bearing/', '')} | {r['result']} |"
              for r in d["rows"]]
    return "\n".join(lines + [""])


if __name__ == "__main__":
    sys.exit(main())
