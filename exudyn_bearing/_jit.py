"""One place for the numba compilation options of every kernel.

``kernel`` is ``numba.njit`` with an on-disk cache (a second run starts
without recompiling) and the fast-math flags that keep IEEE NaN and inf
semantics (no ``nnan``/``ninf``: the kernels rely on NaN checks and on
infinite squeeze-film damping at zero film).
"""
from numba import njit

FASTMATH = {"contract", "arcp", "reassoc", "afn"}


def kernel(fn=None, **kw):
    """``numba.njit(cache=True, fastmath=FASTMATH)``, usable bare or with options."""
    opts = dict(cache=True, fastmath=FASTMATH, error_model="numpy")
    opts.update(kw)
    if fn is None:
        return njit(**opts)
    return njit(**opts)(fn)
