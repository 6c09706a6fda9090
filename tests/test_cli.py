"""Command line: JSON keys of info and static, plots, and bad input."""
import json
import math
import subprocess
import sys

import pytest

from exudyn_bearing.cli import main
from conftest import error_lines, hertz_stiffness_by_hand, stribeck_loads

#: Stribeck's Q_max of the zero-clearance 6208 (9 balls, one at psi = 0) under 3000 N, by hand
Q_MAX_6208 = float(stribeck_loads(3000.0, [2 * math.pi * i / 9 for i in range(9)]).max())


def run_json(capsys, *argv):
    assert main(list(argv)) == 0
    return json.loads(capsys.readouterr().out)


def test_info_6208_json(capsys):
    d = run_json(capsys, "info", "6208", "--omega", "500", "--json")
    for key in ("K_inner", "K_outer", "cage_speed", "ball_spin", "ftf", "bpfo", "bpfi", "bsf"):
        assert key in d
    assert d["ball_spin"] == pytest.approx(952.38, abs=0.01)
    assert d["cage_speed"] == pytest.approx(198.0, abs=0.05)
    # Hertz K by hand (scipy's elliptic integrals): 6208 ball R_b = 6.3 mm, grooves 6.552 mm, race
    # radii 24.0 / 36.6 mm at the contact: R_x = R_b r / (r +- R_b), R_y = R_b R_g / (R_g - R_b);
    # E' = 210 GPa / (1 - 0.3^2). The CLI prints K from the tabulated exact solution (interpolated,
    # 1e-6 relative): 1e-5
    rb, rg, e_prime = 6.3e-3, 6.552e-3, 210e9 / (1 - 0.3 ** 2)
    ry = rb * rg / (rg - rb)
    k_in = hertz_stiffness_by_hand(rb * 24.0e-3 / (24.0e-3 + rb), ry, e_prime)[0]
    k_out = hertz_stiffness_by_hand(rb * 36.6e-3 / (36.6e-3 - rb), ry, e_prime)[0]
    assert d["K_inner"] == pytest.approx(k_in, rel=1e-5) and d["K_outer"] == pytest.approx(k_out, rel=1e-5)


def test_static_6208_json(capsys):
    d = run_json(capsys, "static", "6208", "--Fr", "3000", "--Pd", "0", "--omega", "500", "--json")
    for key in ("psi", "q", "q_max", "delta_r", "eps", "h_min_inner", "h_min_outer",
                "lambda_inner", "lambda_outer"):
        assert key in d
    assert len(d["q"]) == 9 and d["psi"][0] == 0.0
    assert d["q_max"] == pytest.approx(Q_MAX_6208, rel=1e-6)  # Stribeck by hand; the solve converges to 1e-9
    assert d["eps"] == pytest.approx(0.5)
    # unloaded contacts are null in JSON, never NaN
    assert d["lambda_outer"][4] is None


def test_static_plot_writes_png_and_csv(tmp_path, capsys):
    png = tmp_path / "s.png"
    d = run_json(capsys, "static", "7208", "--Fr", "3000", "--Fa", "3000", "--omega", "500",
                 "--plot", str(png), "--json")
    assert png.stat().st_size > 10_000
    csv = (tmp_path / "s.csv").read_text().splitlines()
    assert csv[0].startswith("psi_rad,q_N") and len(csv) == 14
    assert d["plot"] == str(png)


def test_human_readable_tables(capsys):
    assert main(["info", "ACBB-120"]) == 0
    out = capsys.readouterr().out
    assert "K_inner" in out and "N/m^1.5" in out
    assert main(["static", "6208", "--Fr", "3000", "--omega", "500"]) == 0
    out = capsys.readouterr().out
    assert f"q_max = {Q_MAX_6208:.1f} N" in out and "mixed" in out  # Stribeck's 1461.7 N, by hand


@pytest.mark.parametrize("argv, word", [
    (["info", "6309"], "bearing"),
    (["static", "6208", "--Fr", "-5"], "Fr:"),
    (["static", "6208", "--Fr", "3000", "--Pd", "1e-3"], "Pd:"),
    (["static", "6208", "--Fr", "3000", "--omega", "nan"], "omega"),
    (["static", "no/such/file.json", "--Fr", "3000"], "no such file"),
])
def test_bad_input_exits_nonzero_with_a_message(argv, word, capsys):
    try:
        rc = main(argv)
    except SystemExit as exc:  # argparse rejects before main's handler
        rc = exc.code
    assert rc != 0
    err = capsys.readouterr().err
    assert word in err
    assert len(err.strip().splitlines()) <= 2


def test_module_entry_point_runs():
    out = subprocess.run([sys.executable, "-m", "exudyn_bearing", "info", "6004", "--json"],
                         capture_output=True, text=True, check=True).stdout
    assert json.loads(out)["n_balls"] == 9


# a short run: its summary window is not steady, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_simulate_reference_json_and_files(tmp_path, capsys):
    d = run_json(capsys, "simulate", "--bearing", "6208", "--Fr", "3000", "--omega", "500",
                 "--engine", "reference", "--t-end", "0.004", "--dt", "4e-6", "--tangential", "implicit",
                 "--json", "--out", str(tmp_path))
    for key in ("q_max_inner", "q_max_outer", "cage_speed", "ball_spin", "lambda_outer_psi0",
                "lambda_inner_psi0", "regime_fraction", "steps", "dt", "wall_s"):
        assert key in d
    assert d["steps"] == 1000 and d["dt"] == 4e-6
    assert d["cage_speed"] == pytest.approx(198.0, rel=5e-3)
    assert set(d["regime_fraction"]) == {"boundary", "mixed", "full_film"}
    for name in ("run.npz", "run.json", "run.png", "run.csv"):
        assert (tmp_path / name).stat().st_size > 0


def test_simulate_unstable_step_is_a_clean_error(capsys, runaway):
    # the warning comes from the estimate (deterministic); the blow-up is planted (``runaway``),
    # since whether a run at 10 x the estimate grows past the limit hangs on the CPU's last bits
    from exudyn_bearing.model.stability import StepSizeWarning

    with pytest.warns(StepSizeWarning):
        rc = main(["simulate", "--Fr", "3000", "--omega", "500", "--t-end", "0.005", "--dt", "5e-5"])
    assert rc == 3
    err = error_lines(capsys.readouterr().err)
    assert len(err) == 1 and err[0].startswith("exudyn-bearing: error: dt: ")


def test_cli_prints_a_warning_as_one_line_without_its_source(tmp_path):
    # a user of the command line sees the warning's kind and text, not the package's file and line
    out = subprocess.run([sys.executable, "-m", "exudyn_bearing", "simulate", "--Fr", "3000", "--omega", "500",
                          "--t-end", "2e-4", "--dt", "1e-5", "--out", str(tmp_path)],
                         capture_output=True, text=True, timeout=300)
    lines = [ln for ln in out.stderr.splitlines() if "StepSizeWarning" in ln]
    assert lines and all(ln.startswith("exudyn-bearing: warning (StepSizeWarning): dt = ") for ln in lines)
    assert ".py:" not in out.stderr and "warnings.warn" not in out.stderr


# a short run: its summary window is not steady, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_simulate_exudyn_engine_gives_the_same_keys(capsys):
    ref = run_json(capsys, "simulate", "--Fr", "3000", "--omega", "500", "--t-end", "0.004", "--dt", "5e-6", "--json")
    exd = run_json(capsys, "simulate", "--Fr", "3000", "--omega", "500", "--engine", "exudyn", "--t-end", "0.004", "--dt", "5e-6", "--json")
    assert set(ref) == set(exd)
    assert exd["engine"] == "exudyn" and exd["steps"] == ref["steps"] == 800
    assert exd["cage_speed"] == pytest.approx(ref["cage_speed"], rel=1e-3)
