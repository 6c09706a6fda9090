"""The compilation options of exudyn_bearing._jit.kernel (no simulation)."""
from __future__ import annotations

import math

import numpy as np
import pytest

from exudyn_bearing._jit import kernel


@kernel(cache=False)
def _signed_root(x, negative):
    r = math.sqrt(x)
    return -r if negative else r


@kernel(cache=False)
def _literal_and_runtime_flag(x, flag):
    # one call with the literal False, one with a runtime bool: numba's own dispatcher compiled two copies
    return _signed_root(x, False) + _signed_root(x, flag)


@kernel(cache=False, inline="always")
def _inlined_square(a, j):
    return a[j] * a[j]


@kernel(cache=False, no_runtime=True)
def _sum_of_squares(a):
    s = 0.0
    for j in range(a.shape[0]):
        s += _inlined_square(a, j)
    return s


@kernel(cache=False, internal=True)
def _internal_twice(x):
    return 2.0 * x


@kernel(cache=False)
def _calls_internal(x):
    return _internal_twice(x) + 1.0


def test_a_literal_argument_compiles_no_second_specialisation():
    assert _literal_and_runtime_flag(4.0, False) == 4.0  # 2 + 2
    assert _literal_and_runtime_flag(9.0, True) == 0.0   # 3 - 3
    assert len(_signed_root.overloads) == 1


def test_inlined_helpers_compute_what_they_say():
    # the inlining patch (one deep-copy memo per scope) is installed and the inlined code is right
    from numba.core.inline_closurecall import InlineWorker

    assert getattr(InlineWorker.inline_ir, "_eb_one_memo", False)
    a = np.array([1.0, 2.0, 3.0])
    assert _sum_of_squares(a) == 14.0


def test_an_internal_kernel_runs_in_kernels_and_refuses_python_calls():
    assert _calls_internal(3.0) == 7.0
    with pytest.raises(TypeError, match="compiled kernels only"):
        _internal_twice(3.0)
