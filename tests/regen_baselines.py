"""Regression baselines: numbers the program itself computed at a reviewed
state of the model, kept in one place (tests/baselines.json) so that a
change of them shows up in the tests.

They are NOT validation: nothing independent says they are right. Tests that
use them say so (``baseline(...)`` in tests/conftest.py), and every value
that a published number, a closed form or a hand calculation can check is
checked that way instead (tests/test_published_values.py and the physics
test files).

After a reviewed change of the model, regenerate them (from the repository
root) and commit tests/baselines.json with the change::

    python tests/regen_baselines.py            # prints old -> new, writes the file
    python tests/regen_baselines.py --check    # prints only, exit 1 if one moved beyond its tolerance
"""
import argparse
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PATH = Path(__file__).with_name("baselines.json")


def static_6208_tilt_y_reaction():
    """Reaction moment [N m] of the held tilt_y of a 6208 under F_r = 3000 N, F_a = 1000 N
    (``exudyn-bearing static 6208 --Fr 3000 --Fa 1000 --json``, key reactions.tilt_y)."""
    import exudyn_bearing as eb
    from exudyn_bearing.cli.static import static_result

    return float(static_result(eb.catalog["6208"], 3000.0, 1000.0)["reactions"]["tilt_y"])


def rotor_ring_spin_loss():
    """Spin the 6208's light rotor ring (J_z = 1e-5 kg m^2, 3000 N, 500 rad/s) loses to the
    bearing's friction torque in 5 ms [rad/s] (tests/test_element.py, Rxyz node)."""
    sys.path.insert(0, str(ROOT / "tests"))
    from test_element import rotor_spin_after_5_ms

    return 500.0 - rotor_spin_after_5_ms()


#: name -> (function, unit, relative tolerance, why that tolerance)
BASELINES = {
    "static_6208_tilt_y_reaction": (
        static_6208_tilt_y_reaction, "N m", 3e-4,
        "the CLI prints it to 0.01 N m (2.6e-4 of 18.93); the solve itself converges to 1e-9"),
    "rotor_ring_spin_loss": (
        rotor_ring_spin_loss, "rad/s", 0.05,
        "a 5 ms explicit run: round-off differences between CPUs move the spin loss by far less "
        "than 1 %; 5 % flags a change of the friction torque on the ring"),
}


def load():
    return json.loads(PATH.read_text())


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--check", action="store_true", help="compare only; do not write")
    args = ap.parse_args(argv)
    old = load() if PATH.exists() else {}
    new, moved = {}, []
    for name, (fn, unit, rel, why) in BASELINES.items():
        value = fn()
        new[name] = {"value": value, "unit": unit, "rel": rel, "why_tolerance": why,
                     "source": (fn.__doc__ or "").split("\n\n")[0].replace("\n    ", " ").strip(),
                     "regenerate": "python tests/regen_baselines.py"}
        before = old.get(name, {}).get("value")
        if before is None or abs(value - before) > rel * abs(before):
            moved.append(name)
        print(f"{name}: {before!r} -> {value!r} {unit} (tolerance rel {rel:g})")
    if args.check:
        return 1 if moved else 0
    PATH.write_text(json.dumps(new, indent=2) + "\n")
    print(f"wrote {PATH.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
