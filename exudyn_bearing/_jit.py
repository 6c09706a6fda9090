"""One place for the numba compilation options of every kernel.

``kernel`` is ``numba.njit`` with an on-disk cache (a second run starts
without recompiling) and the fast-math flags that keep IEEE NaN and inf
semantics (no ``nnan``/``ninf``: the kernels rely on NaN checks and on
infinite squeeze-film damping at zero film).

Numba invalidates a cached function only when its own source file changes,
not when a kernel it calls (in another file) changes. So that a stale
compiled copy of the shared contact kernel can never survive an edit or an
upgrade, :func:`_drop_stale_caches` hashes all kernel sources at import and
clears the package's numba cache files when the hash differs from the one
stored beside them.

Compiling the kernels a run needs takes about 15-30 s of CPU time on the 2-core
test machine (once per installation and after every update; ``python
validation/performance/bench_kernel_ab.py --cold 3`` measures it, ``python
validation/performance/profile_reference.py --compile`` lists what compiles); :func:`announce_compilation` says so on
stderr when a run is about to compile instead of load them.
"""
from __future__ import annotations

import copy
import functools
import hashlib
import inspect
import os
import sys
from pathlib import Path

from numba import types
from numba.core import config
from numba.core.extending import overload
from numba.core.registry import CPUDispatcher

FASTMATH = {"contract", "arcp", "reassoc", "afn"}

_PACKAGE = Path(__file__).resolve().parent


def _drop_stale_caches() -> None:
    sources = sorted(_PACKAGE.rglob("*.py"))
    digest = hashlib.sha256()
    for path in sources:
        try:
            digest.update(path.read_bytes())
        except OSError:
            return
    stamp = _PACKAGE / "__pycache__" / "kernels.sha256"
    value = digest.hexdigest()
    try:
        if stamp.exists() and stamp.read_text() == value:
            return
        for pattern in ("*.nbi", "*.nbc"):
            for f in _PACKAGE.rglob(pattern):
                f.unlink(missing_ok=True)
        stamp.parent.mkdir(exist_ok=True)
        stamp.write_text(value)
    except OSError:  # read-only install: numba falls back to its own cache checks
        pass


_drop_stale_caches()


def _copy_inlined_blocks_with_one_memo() -> bool:
    """Make numba's inlining of ``inline="always"`` kernels copy a callee's
    IR in time linear in its size; returns whether it applied.

    numba's ``InlineWorker.inline_ir`` copies the callee's IR block by block,
    each block with a ``copy.deepcopy`` of its own; every variable refers to
    the function's scope (which lists all its variables), so every block
    copied the whole scope again: time blocks x variables. For the contact
    kernel's ball / raceway contact (itself built of inlined helpers) that
    copying was about 2 s of the cold start's compilation (numba issue
    #8989). Here the blocks of one scope are copied with one memo, so the
    scope is copied once and shared by the copied blocks, as it is by the
    originals; the copy is otherwise the same deep copy (the compiled code is
    unchanged). Only for the untyped inlining (no argument types) of the
    package's own kernels; left alone where numba's layout differs.
    """
    try:
        from numba.core import inline_closurecall as icc
        from numba.core import ir
    except ImportError:  # pragma: no cover - another numba layout
        return False
    worker = getattr(icc, "InlineWorker", None)
    inline_ir = getattr(worker, "inline_ir", None)
    if inline_ir is None or getattr(icc, "copy", None) is not copy or getattr(inline_ir, "_eb_one_memo", False):
        return False
    memos = []  # a stack: one dict (scope id -> memo) per active inlining of a package kernel

    class _Copy:
        """The ``copy`` module as ``inline_closurecall`` sees it."""

        def __getattr__(self, name):
            return getattr(copy, name)

        @staticmethod
        def deepcopy(x, memo=None):
            if memo is None and memos and memos[-1] is not None and type(x) is ir.Block:
                memo = memos[-1].setdefault(id(x.scope), {})  # the memo keeps x.scope alive: its id stays unique
            return copy.deepcopy(x, memo)

    try:
        signature = inspect.signature(inline_ir)
    except (TypeError, ValueError):  # pragma: no cover
        return False
    if "callee_ir" not in signature.parameters:  # pragma: no cover - another numba layout
        return False

    @functools.wraps(inline_ir)
    def patched(*args, **kwargs):
        try:
            bound = signature.bind(*args, **kwargs).arguments
            func = getattr(bound["callee_ir"].func_id, "func", None)
            ours = bound.get("arg_typs") is None and (getattr(func, "__module__", None) or "").startswith(
                __package__ + ".")
        except (TypeError, AttributeError, KeyError):
            ours = False
        memos.append({} if ours else None)
        try:
            return inline_ir(*args, **kwargs)
        finally:
            memos.pop()

    patched._eb_one_memo = True
    icc.copy = _Copy()
    worker.inline_ir = patched
    return True


_copy_inlined_blocks_with_one_memo()


#: The line :func:`announce_compilation` prints (measured with an empty cache on the 2-core
#: test machine: 15.3-28.5 s from import to the end of the README's first reference run in
#: single fresh processes, 15.4 s the median of three in validation/REPORT.md's last run (25.8 s in
#: a run on a busier day); several times that when the machine is busy; a warm start takes 1-3 s).
COMPILE_NOTICE = ("exudyn_bearing: compiling the numba kernels (first run after installing or updating; about 15-30 s, "
                  "up to a minute on a busy machine; later runs load them from the cache)")
_announced = False


def _cache_is_cold(dispatcher) -> bool:
    """True when numba has no cache index for ``dispatcher`` (it will compile, not load)."""
    return not os.path.exists(dispatcher._cache._cache_file._index_path)


def announce_compilation(*dispatchers) -> bool:
    """Print :data:`COMPILE_NOTICE` on stderr (once per process) when any of
    the compiled ``dispatchers`` has no on-disk cache yet; returns whether it
    printed. Silent where numba's cache layout differs (or JIT is disabled)."""
    global _announced
    if _announced:
        return False
    try:
        cold = any(_cache_is_cold(d) for d in dispatchers)
    except (AttributeError, TypeError, OSError):
        return False
    if cold:
        _announced = True
        print(COMPILE_NOTICE, file=sys.stderr, flush=True)
    return cold


def _runtime_option_supported() -> bool:
    try:
        from numba.core.cpu import CPUTargetOptions

        return hasattr(CPUTargetOptions, "_nrt")
    except ImportError:  # pragma: no cover - another numba layout
        return False


#: numba accepts ``_nrt=False`` (compile without its memory runtime).
NO_RUNTIME_SUPPORTED = _runtime_option_supported()


class KernelDispatcher(CPUDispatcher):
    """numba's CPU dispatcher, typing calls from compiled code on the
    non-literal argument types.

    numba compiles a separate specialisation of a called kernel for every
    literal argument a call site passes (``_groove_geometry(..., False)``
    beside ``_groove_geometry(..., inner)``: the same code compiled twice,
    once with ``Literal[bool](False)``); no kernel of the package depends on
    a literal argument, so every call types as a call from Python does (one
    specialisation per argument type; ``None`` stays the ``none`` type that
    prunes the optional code paths).
    """

    def get_call_template(self, args, kws):
        return super().get_call_template(tuple(types.unliteral(a) for a in args),
                                         {k: types.unliteral(v) for k, v in kws.items()})


class InternalKernelDispatcher(KernelDispatcher):
    """A :class:`KernelDispatcher` compiled without the wrapper that makes it
    callable from Python (``kernel(internal=True)``): a call from Python
    raises (without the wrapper numba's call would crash the interpreter)."""

    def __call__(self, *args, **kwargs):
        raise TypeError(f"{self.py_func.__module__}.{self.py_func.__qualname__} is compiled for calls from "
                        "compiled kernels only (kernel(internal=True)); call it from a kernel")


def _njit(fn, options):
    """``numba.njit(**options)(fn)`` with :class:`KernelDispatcher` (numba's own ``jit`` wrapper, minus the
    options the package does not use)."""
    if config.DISABLE_JIT:
        return fn
    options = dict(options)
    cache = options.pop("cache", False)
    options.update(nopython=True, boundscheck=None)
    cls = InternalKernelDispatcher if options.get("no_cpython_wrapper") else KernelDispatcher
    disp = cls(py_func=fn, locals={}, targetoptions=options)
    if cache:
        disp.enable_caching()
    return disp


def kernel(fn=None, *, no_runtime=False, internal=False, **kw):
    """``numba.njit(cache=True, fastmath=FASTMATH)``, usable bare or with options.

    ``no_runtime=True`` compiles without numba's memory runtime (numba's
    ``_nrt=False``) for kernels that allocate no array: numba then emits no
    reference counting for the arrays they pass to inlined helpers. The
    contact kernel is split into per-contact functions inlined into its
    loop; with the runtime, every inlined array argument costs an atomic
    increment and decrement per call, which made a reference-engine step
    about 45 % slower (measured on the 6208 scene, 3.6 against 5.3 us per
    step). Where a numba version does not offer the option it is dropped
    (the kernels stay correct, only slower).

    Every kernel is compiled without numba's C-callable wrapper
    (``no_cfunc_wrapper``: it serves only first-class function values, which
    the package does not use, and is a sizeable share of the compilation of
    a small kernel). ``internal=True`` also leaves out the wrapper that makes
    the kernel callable from Python (``no_cpython_wrapper``), for helpers
    only compiled code calls: that wrapper unboxes every argument (for a
    helper that takes eleven arrays, about a quarter of its compilation in
    ``validation/performance/profile_reference.py --compile``); such a kernel raises
    when called from Python. The dispatcher is a :class:`KernelDispatcher`
    (one specialisation per argument type, literal or not).

    Small helpers with one or two call sites in the step loop (the
    integrators' ring force and sampling, the kick-drift, the kinetic energy
    and the global diagnostics) are ``inline="always"``: numba copies them
    into their caller instead of running its compilation pipeline once more
    for each (about 0.1-0.7 s apiece; the cold start of the README's scene
    15.7 against 16.4 s, ``validation/performance/bench_kernel_ab.py --cold 3 --baseline
    95cba4f``), with bitwise equal results and step time
    (``validation/performance/bench_kernel_ab.py --baseline 95cba4f``). Inlining the small
    physics relations as well saved nothing measurable.
    """
    opts = dict(cache=True, fastmath=FASTMATH, error_model="numpy", no_cfunc_wrapper=True)
    if no_runtime and NO_RUNTIME_SUPPORTED:
        opts["_nrt"] = False
    if internal:
        opts["no_cpython_wrapper"] = True
    opts.update(kw)
    if fn is None:
        return functools.partial(_njit, options=opts)
    return _njit(fn, opts)


class LazyUfunc:
    """A scalar relation as a NumPy ufunc built on its first Python call, and
    in compiled code the scalar function itself.

    ``numba.vectorize`` with signatures builds (LLVM-compiles) its ufunc
    loop at import, in every process, even with ``cache=True`` (about 0.3 s
    per function). This object defers that to the first call from Python,
    where it behaves as that ufunc (broadcasting, ``out=``, NaN in, NaN or
    the ufunc's value out); compiled kernels that call it with scalars get
    ``fn`` through :func:`numba.core.extending.overload`, compiled as the
    ufunc's kernel is (NumPy error model, no fast-math flags), so a kernel
    computes what the ufunc computes. One source, ``fn``, for both.
    """

    def __init__(self, fn, signature):
        functools.update_wrapper(self, fn)
        self.signature = signature
        self._ufunc = None
        n_args = fn.__code__.co_argcount

        def typer(*args):
            if len(args) == n_args and all(isinstance(a, (types.Number, types.Boolean)) for a in args):
                return fn
            return None

        overload(self, jit_options={"error_model": "numpy"}, strict=False)(typer)

    @property
    def ufunc(self):
        """The NumPy ufunc (``numba.vectorize([signature], cache=True)`` of ``fn``), built on first use."""
        if self._ufunc is None:
            from numba import vectorize

            self._ufunc = vectorize([self.signature], cache=True)(self.__wrapped__)
        return self._ufunc

    def __call__(self, *args, **kwargs):
        return self.ufunc(*args, **kwargs)

    def __get__(self, obj, objtype=None):  # a routine for doctest's finder, as the ufunc was; never bound
        return self

    def __reduce__(self):  # pickled by reference to its module attribute
        return self.__qualname__

    def __repr__(self):
        return f"<lazy ufunc {self.__module__}.{self.__qualname__} {self.signature}>"


def lazy_ufunc(signature):
    """Decorator: ``LazyUfunc(fn, signature)`` (a ``numba.vectorize`` signature string)."""
    return functools.partial(LazyUfunc, signature=signature)
