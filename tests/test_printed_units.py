"""Units on the printed tables of the quasi-static commands: the held DOFs' reactions (--fix) and the thermal
print's losses and friction torque (issue 35)."""
import re

import pytest

from exudyn_bearing.cli import main
from exudyn_bearing.solvers.quasistatic import solve_quasistatic

ARGS = ["7208", "--Fr", "3000", "--Fa", "1000", "--omega", "500", "--fix", "delta_a=0"]
THERMAL = ["--thermal", "--oil-inlet-temperature", "323", "--oil-flow", "1e-5"]


def _reaction_units(out):
    """{DOF: unit} of the 'held' lines of a print."""
    lines = [x for x in out.splitlines() if " held (" in x]
    assert lines, out
    units = {}
    for x in lines:
        m = re.fullmatch(r"(\w+) held \(\w+\)[;:] reaction [-+0-9.e]+ (N m|N)\b.*", x)
        assert m, x
        units[m.group(1)] = m.group(2)
    return units


@pytest.mark.filterwarnings("ignore::exudyn_bearing.BallInertiaWarning")  # the 7208's balls under race control
@pytest.mark.parametrize("thermal", [False, True])
def test_quasistatic_prints_reactions_with_units_and_the_friction_torque(capsys, thermal):
    assert main(["quasistatic", *ARGS, *(THERMAL if thermal else [])]) == 0
    out = capsys.readouterr().out
    assert _reaction_units(out) == {"tilt_x": "N m", "tilt_y": "N m", "delta_a": "N"}
    loss = next(x for x in out.splitlines() if x.startswith("power loss "))
    assert re.search(r"power loss [0-9.e+]+ W \(.* W\), friction torque [0-9.e+-]+ N m", loss), loss
    assert ("heat out: oil" in loss) == thermal


def test_the_solution_summary_gives_the_reactions_units():
    s = solve_quasistatic("7208", 3000.0, 1000.0, omega=0.0, fixed={"delta_a": 0.0, "tilt_x": 0.0, "tilt_y": 0.0},
                          stiffness=False)
    assert _reaction_units(s.summary()) == {"delta_a": "N", "tilt_x": "N m", "tilt_y": "N m"}
