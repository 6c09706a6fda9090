"""Command line conventions: negative numbers in any notation, the ramp sets the run
length, one spelling of the shared options (BEARING, --omega | --rpm, --lubricant),
defaults and help everywhere, units in every JSON, clean errors for bad input."""
import json
import math

import pytest

from exudyn_bearing import catalog
from exudyn_bearing.cli import COMMANDS, DESCRIPTION, _parser, main
from exudyn_bearing.cli.common import HelpFormatter
from exudyn_bearing.cli.simulate import scenario_from_args
from conftest import error_lines


def run_json(capsys, *argv):
    assert main(list(argv)) == 0
    return json.loads(capsys.readouterr().out)


def exit_code(argv):
    try:
        return main(argv)
    except SystemExit as exc:
        return exc.code


def sub_parsers():
    p = _parser()
    action = next(a for a in p._actions if a.dest == "command")
    return action.choices


@pytest.mark.parametrize("text, value", [("-12.6e-6", -12.6e-6), ("-1.26E-5", -1.26e-5), ("-5", -5.0),
                                         ("-.5e-6", -0.5e-6), ("12.6e-6", 12.6e-6)])
def test_negative_numbers_in_scientific_notation_are_values(text, value):
    # argparse took "-12.6e-6" for an option ("expected one argument")
    for argv in (["static", "6208", "--Fr", "3000", "--Pd", text], ["simulate", "--Pd", text]):
        args = _parser().parse_args(argv)
        assert args.Pd == value


def test_preload_from_the_command_line(capsys):
    d = run_json(capsys, "static", "6208", "--Fr", "3000", "--Pd", "-12.6e-6", "--json")
    assert d["Pd"] == pytest.approx(-12.6e-6) and d["eps"] > 0.6  # all balls loaded under preload


def test_ramp_sets_the_run_length_unless_t_end_is_given():
    args = _parser().parse_args(["simulate", "--Fr", "3000", "--omega", "500", "--ramp", "0.05", "0.2", "0.05"])
    sc = scenario_from_args(args)
    assert sc.t_end == pytest.approx(0.3) and sc.initial == "rest"
    args = _parser().parse_args(["simulate", "--Fr", "3000", "--omega", "500", "--ramp", "0.05", "0.2", "0.05", "--t-end", "0.1"])
    assert scenario_from_args(args).t_end == 0.1
    assert scenario_from_args(_parser().parse_args(["simulate", "--Fr", "3000", "--omega", "500"])).t_end == 0.02


def test_simulate_takes_the_bearing_like_info_and_static():
    for argv, name in ((["simulate"], "6208"), (["simulate", "7208"], "7208"), (["simulate", "--bearing", "6004"], "6004"),
                       (["simulate", "--Fr", "100", "ACBB-120"], "ACBB-120")):
        from exudyn_bearing.cli.common import bearing_from_args

        assert bearing_from_args(_parser().parse_args(argv)).name == name
    for cmd in ("info", "static"):
        assert _parser().parse_args([cmd, "7208", "--Fr", "1"] if cmd == "static" else [cmd, "7208"]).bearing == "7208"


def test_bearing_given_twice_differently_is_refused(capsys):
    assert exit_code(["simulate", "6208", "--bearing", "7208", "--omega", "500"]) == 2
    assert capsys.readouterr().err.startswith("exudyn-bearing: error: bearing: given twice")


def test_rpm_beside_omega(capsys):
    a = run_json(capsys, "info", "6208", "--rpm", "3000", "--json")
    b = run_json(capsys, "info", "6208", "--omega", str(3000 * 2 * math.pi / 60), "--json")
    assert a["cage_speed"] == pytest.approx(b["cage_speed"], rel=1e-12) and a["omega"] == pytest.approx(314.159, rel=1e-5)
    assert exit_code(["info", "6208", "--rpm", "3000", "--omega", "300"]) == 2  # one or the other
    assert "not allowed with" in capsys.readouterr().err


@pytest.mark.filterwarnings("ignore::exudyn_bearing.data.LubricantDefaultsWarning")  # a viscosity-only file
def test_lubricant_option_takes_a_name_or_a_file(tmp_path, capsys):
    base = run_json(capsys, "static", "6208", "--Fr", "3000", "--omega", "500", "--json")
    named = run_json(capsys, "static", "6208", "--Fr", "3000", "--omega", "500", "--lubricant", "guessasma2018", "--json")
    assert named["lambda_outer"] == base["lambda_outer"]
    f = tmp_path / "thin.json"
    f.write_text(json.dumps({"viscosity": 0.01}))  # a quarter of the default viscosity: thinner film
    thin = run_json(capsys, "static", "6208", "--Fr", "3000", "--omega", "500", "--lubricant", str(f), "--json")
    assert thin["h_min_outer"][0] < 0.5 * base["h_min_outer"][0]
    assert exit_code(["static", "6208", "--Fr", "3000", "--lubricant", "olive-oil"]) == 2
    assert capsys.readouterr().err.startswith("exudyn-bearing: error: lubricant: unknown lubricant 'olive-oil'")


def test_every_option_has_help_and_shows_its_default():
    import argparse

    def walk(p, path):
        assert isinstance(p.formatter_class, type) and issubclass(p.formatter_class, HelpFormatter), path
        for a in p._actions:
            if a.dest == "help":
                continue
            assert a.help, (path, a.dest)
            if isinstance(a, argparse._SubParsersAction):
                for name, sp in a.choices.items():
                    walk(sp, path + [name])
                continue
            shown = HelpFormatter("x")._get_help_string(a)
            if a.default is not None and a.default is not False and not a.required:
                assert "default" in shown, (path, a.dest)

    walk(_parser(), [])
    assert "``" not in DESCRIPTION and "``" not in _parser().format_help()


# a short run: its summary window is not steady, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_every_json_output_carries_units(capsys, tmp_path):
    info = run_json(capsys, "info", "6208", "--omega", "500", "--json")
    assert info["units"]["bpfo"] == "Hz" and info["units"]["cage_speed"] == "rad/s"
    assert info["units"]["K_inner"] == "N/m^1.5" and set(info["units"]) <= set(info)
    st = run_json(capsys, "static", "6208", "--Fr", "3000", "--omega", "500", "--json")
    assert st["units"]["q"] == "N" and st["units"]["psi"] == "rad" and st["units"]["h_min_outer"] == "m"
    assert st["regime_codes"] == {"-1": "no contact", "0": "boundary", "1": "mixed", "2": "full_film"}
    assert st["regime_codes"][str(st["regime_outer"][0])] == "mixed"
    sim = run_json(capsys, "simulate", "--Fr", "3000", "--omega", "500", "6208", "--t-end", "0.002", "--dt", "4e-6", "--tangential", "implicit",
                   "--out", str(tmp_path), "--json")
    assert sim["units"]["cage_speed"] == "rad/s" and sim["units"]["q_max_inner"] == "N"
    saved = json.loads((tmp_path / "run.json").read_text())
    assert saved["units"] == sim["units"]


# a short run: its summary window is not steady, as expected
@pytest.mark.filterwarnings("ignore::exudyn_bearing.SteadyStateWarning")
def test_simulate_table_shows_units_and_window(capsys):
    assert main(["simulate", "--Fr", "3000", "--omega", "500", "--t-end", "0.002", "--dt", "4e-6", "--tangential", "implicit"]) == 0
    out = capsys.readouterr().out
    lines = {line.split()[0]: line for line in out.splitlines()}
    assert lines["cage_speed"].endswith("rad/s") and lines["q_max_inner"].endswith("N")
    assert "last 25 % of the run" in lines["window"]


@pytest.mark.parametrize("argv, word", [
    (["simulate", "--Fr", "3000", "--omega", "500", "--t-end", "5e-5"], "t_end: must be >= sample_dt"),
    (["static", "6208", "--Fr", "1e9"], "Fr: "),
    (["static", "6208", "--Fr", "25000"], "above 4.2 GPa"),
    (["simulate", "--omega", "500", "--Fr", "1e9", "--t-end", "0.001"], "Fr: "),
    (["static", "6208", "--Fr", "3000", "--phase", "inf"], "phase"),
])
def test_bad_input_is_one_line_and_exit_2(argv, word, capsys):
    assert exit_code(argv) == 2
    err = error_lines(capsys.readouterr().err)
    assert len(err) == 1 and word in err[0] and "Traceback" not in err[0]


def test_static_phase_is_taken_modulo_two_pi(capsys):
    # --phase 1e20 gave a RuntimeError traceback (the ball spacing lost in cos/sin of 1e20)
    big = run_json(capsys, "static", "6208", "--Fr", "3000", "--phase", "1e20", "--json")
    same = run_json(capsys, "static", "6208", "--Fr", "3000", "--phase", repr(math.remainder(1e20, 2 * math.pi)),
                    "--json")
    assert big["q"] == pytest.approx(same["q"], rel=1e-9) and abs(big["phase"]) <= math.pi


def test_commands_are_modules_with_the_shared_options():
    assert set(COMMANDS) >= {"info", "static", "simulate"}
    for name in ("info", "static", "simulate"):
        dests = {a.dest for a in sub_parsers()[name]._actions}
        assert {"bearing", "omega", "rpm"} <= dests
        if name in ("static", "simulate"):
            assert "lubricant" in dests
    assert "6208" in catalog


def test_cold_numba_cache_is_announced_once(tmp_path, monkeypatch, capsys):
    # a first run compiled for 30-40 s without a word
    from types import SimpleNamespace

    from exudyn_bearing import _jit
    from exudyn_bearing.solvers.reference.integrators import run_verlet

    def dispatcher(path):
        return SimpleNamespace(_cache=SimpleNamespace(_cache_file=SimpleNamespace(_index_path=str(path))))

    warm = tmp_path / "kernel.nbi"
    warm.write_text("")
    monkeypatch.setattr(_jit, "_announced", False)
    assert not _jit.announce_compilation(dispatcher(warm))
    assert _jit.announce_compilation(dispatcher(warm), dispatcher(tmp_path / "missing.nbi"))
    assert not _jit.announce_compilation(dispatcher(tmp_path / "missing.nbi"))  # once per process
    err = capsys.readouterr().err
    assert err.count("compiling the numba kernels") == 1 and len(err.strip().splitlines()) == 1
    # numba's cache layout is the one read: a kernel that ran has its index on disk
    from exudyn_bearing import simulate, Scenario

    simulate("6208", Scenario(Fr=3000.0, omega=500.0, t_end=1e-4, dt=5e-6, sample_dt=1e-4))
    assert not _jit._cache_is_cold(run_verlet)


def test_readme_command_1_is_what_ci_runs_and_parses():
    from pathlib import Path

    root = Path(__file__).resolve().parents[1]
    readme = (root / "README.md").read_text()
    ci = (root / ".ci" / "run").read_text()
    line = next(x for x in readme.splitlines() if x.startswith('pip install -e ".[test]" && python -m exudyn_bearing'))
    assert line in ci.splitlines()
    argv = line.split("python -m exudyn_bearing ", 1)[1].split()
    args = _parser().parse_args(argv)
    assert args.bearing == "6208" and args.t_end is None  # the protocol sets the run length
    assert scenario_from_args(args).t_end == pytest.approx(0.3)


def test_help_lists_the_exit_statuses_main_returns(capsys):
    from exudyn_bearing.cli import EXIT_STATUSES

    assert exit_code(["--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    for status, meaning in EXIT_STATUSES.items():
        assert f"{status} {meaning}" in text
    for command in ("simulate", "quasistatic"):  # and every command's help
        assert exit_code([command, "--help"]) == 0
        assert "exit status: 0 done" in " ".join(capsys.readouterr().out.split())
    # the documented bad-input status is the one returned
    assert exit_code(["static", "6208", "--lubricant", "olive-oil"]) == 2


@pytest.mark.parametrize("kind", ["file", "unwritable"])
def test_a_bad_out_folder_is_refused_before_the_run(kind, tmp_path, capsys, monkeypatch):
    # the run used to go first and was lost when its folder could not be written (exit 2, no summary)
    import importlib

    def no_run(*args, **kwargs):
        raise AssertionError("simulated before --out was checked")

    monkeypatch.setattr(importlib.import_module("exudyn_bearing.cli.simulate"), "simulate", no_run)
    out = tmp_path / "taken.json"
    out.write_text("{}")
    target = out if kind == "file" else out / "below"  # a folder under a file cannot be made
    assert exit_code(["simulate", "6208", "--Fr", "3000", "--omega", "500", "--t-end", "0.002", "--out",
                      str(target)]) == 2
    assert "--out: " in capsys.readouterr().err
