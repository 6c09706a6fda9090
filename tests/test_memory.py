"""Memory of the sampled series: the estimate against a run's real arrays, the refusal naming the sample_dt that
fits, the CLI's one-line error."""
import re

import pytest

import exudyn_bearing as eb
from exudyn_bearing import InputError
from exudyn_bearing.cli import main
from exudyn_bearing.model.memory import check_sample_memory, sample_bytes, signal_bytes

STATE_KEYS = ("t", "glob", "diag", "cage_load", "xb", "vb", "wb", "xc", "vc", "ring")


def test_estimate_is_the_bytes_a_run_keeps():
    # the estimate counts what the engine really stores: 20 state samples and 2 ms of 48 kHz signals
    sc = eb.Scenario(Fr=1000.0, omega=100.0, t_end=2e-3, dt=1e-6, sample_dt=1e-4, signal_dt=1e-5)
    run = eb.simulate("6208", sc)
    n = len(run.data["t"])
    assert n == 20
    assert sum(run.data[k].nbytes for k in STATE_KEYS) == n * sample_bytes(9)
    n_sig = len(run.data["signal_t"])
    assert n_sig == 200
    assert run.data["signal_t"].nbytes + run.data["signal"].nbytes == n_sig * signal_bytes()
    assert check_sample_memory("6208", sc) == n * sample_bytes(9) + n_sig * signal_bytes()


def test_refusal_names_sample_dt_and_a_value_that_fits():
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=1e6, dt=1e-6)
    budget = 2 ** 30
    with pytest.raises(InputError) as e:
        check_sample_memory("6208", sc, budget=budget)
    msg = str(e.value)
    assert msg.startswith("sample_dt:") and "t_end" in msg
    fit = float(re.search(r"--sample-dt (\S+)\)", msg).group(1))
    # the value it names fits, and one a third smaller would not: the suggestion is close to the limit
    assert check_sample_memory("6208", eb.Scenario(Fr=3000.0, omega=500.0, t_end=1e6, dt=1e-6, sample_dt=fit), budget=budget) <= budget
    with pytest.raises(InputError):
        check_sample_memory("6208", eb.Scenario(Fr=3000.0, omega=500.0, t_end=1e6, dt=1e-6, sample_dt=fit / 1.5), budget=budget)


def test_signals_that_do_not_fit_name_signal_dt():
    sc = eb.Scenario(Fr=3000.0, omega=500.0, t_end=1e4, dt=1e-6, sample_dt=1.0, signal_dt=1e-6)
    with pytest.raises(InputError, match="^signal_dt:"):
        check_sample_memory("6208", sc, budget=2 ** 30)


def test_cli_refuses_before_any_work(capsys):
    # 1e9 s at the default 0.1 ms samples: 1e13 samples, more than any machine holds
    assert main(["simulate", "--Fr", "3000", "--omega", "500", "--t-end", "1e9", "--dt", "1e-6"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "sample_dt" in err[0] and "--sample-dt" in err[0]
