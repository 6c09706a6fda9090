"""README as a front page and the docs pages it links to: short, its links
resolve, its examples run as printed (shortened in time)."""
import re
import warnings

import pytest

import exudyn_bearing as eb

from conftest import ROOT, manual_pages


def _block(text, start):
    i = text.index(start)
    return text[i + len(start.split("\n")[0]) + 1:text.index("```\n", i + 1)]


def test_readme_is_a_front_page():
    text = (ROOT / "README.md").read_text()
    assert len(text.splitlines()) < 150
    # the two set-up commands come first, before any other block
    first = _block(text, "```bash\n")
    assert first.splitlines()[1].startswith('pip install -e ".[test]" && python -m exudyn_bearing simulate 6208')
    assert first.splitlines()[-1] == "python -m pytest -q"


def test_every_relative_link_of_the_pages_resolves():
    broken = []
    for page in manual_pages():
        for target in re.findall(r"\]\(([^)#\s]+)(?:#[^)]*)?\)", page.read_text()):
            if "://" not in target and not (page.parent / target).exists():
                broken.append(f"{page.relative_to(ROOT)}: {target}")
    assert broken == []


def test_readme_python_example_runs(tmp_path, capsys):
    code = _block((ROOT / "README.md").read_text(), "```python\nimport exudyn_bearing as eb\nrun = eb.simulate")
    assert "t_end=0.05" in code
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", eb.SteadyStateWarning)  # shortened to 5 ms: too short to judge
        exec(compile(code.replace("t_end=0.05", "t_end=0.005"), "README.md", "exec"), {})
    rows = {line.split()[0]: line.split()[1:] for line in capsys.readouterr().out.splitlines() if line.strip()}
    assert float(rows["q_max_inner"][0]) > 1000.0 and rows["q_max_inner"][1] == "N"
    assert float(rows["cage_speed"][0]) > 0.0 and rows["cage_speed"][1] == "rad/s"
    assert (tmp_path / "6208.png").stat().st_size > 0


@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_readme_rotor_example_runs_the_three_levels(capsys):
    code = _block((ROOT / "README.md").read_text(), "```python\nimport exudyn as exu\nimport exudyn_bearing as eb")
    assert "endTime=0.01" in code
    with warnings.catch_warnings():
        warnings.simplefilter("error", eb.StepSizeWarning)
        exec(compile(code.replace("endTime=0.01", "endTime=0.002"), "README.md", "exec"), {})
    lines = capsys.readouterr().out.strip().splitlines()[-3:]
    assert [x.split()[0] for x in lines] == ["linear", "quasistatic", "balls"]
    # the three levels hold the shaft where the 3000 N put it: about 25 um along x, within a micrometre
    x = [float(x.split("x = ")[1].split()[0]) for x in lines]
    assert max(x) - min(x) < 1.0 and 20.0 < x[0] < 30.0
