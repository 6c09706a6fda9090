"""Memory of a dynamic run's sampled series, checked before the run starts.

Both engines keep every sample in memory (arrays of :mod:`.layout`, float64):
per state sample the time, the global diagnostics, the contact diagnostics
and cage loads of every ball, five ball/cage vectors per ball and the ring
row; per signal sample (``Scenario.signal_dt``) the time and
``NSIGNAL`` signals. :func:`check_sample_memory` refuses a scenario whose
samples would not fit in :data:`MEMORY_FRACTION` of the memory available
now (``MemAvailable`` of ``/proc/meminfo`` on Linux, the free physical
pages elsewhere, :data:`FALLBACK_BUDGET` where neither is known) or of
the room the process's own limits leave (the address-space limit
``RLIMIT_AS``, ``ulimit -v``, less its virtual size ``VmSize``; the data
limit ``RLIMIT_DATA``, ``ulimit -d``, less ``VmData``), whichever is
smaller, and names the ``sample_dt`` that fits, instead of failing with
numpy's "Unable to allocate" after the start-up work.

The wall time of a run is said when it is long (:func:`wall_time_message`:
both engines measure the step cost over their first :data:`ESTIMATE_AFTER_S`
and print the estimate on stderr when it exceeds :data:`LONG_RUN_S`).
"""
from __future__ import annotations

import math
import os

from ..data import InputError, load_bearing
from .layout import NDIAG, NGLOBAL, NSIGNAL

__all__ = ["MEMORY_FRACTION", "FALLBACK_BUDGET", "sample_bytes", "signal_bytes", "available_memory",
           "limit_room", "memory_budget", "check_sample_memory", "LONG_RUN_S", "ESTIMATE_AFTER_S", "wall_time_message"]

#: Share of the available memory the samples of one run may take (the rest: the
#: interpreter, the engines' work arrays, the Results' derived series and other processes).
MEMORY_FRACTION = 0.5
#: Budget [bytes] where the available memory cannot be read (4 GiB).
FALLBACK_BUDGET = 4 * 2 ** 30
_FLOAT = 8  # bytes of a float64


def sample_bytes(n_balls: int) -> int:
    """Bytes of one state sample of a bearing with ``n_balls`` balls: t, glob
    (NGLOBAL), diag (Z, 2, NDIAG), cage_load (Z, 2), xb, vb, wb, xc, vc (Z, 3
    each), ring (6)."""
    z = int(n_balls)
    return _FLOAT * (1 + NGLOBAL + z * 2 * NDIAG + z * 2 + 5 * z * 3 + 6)


def signal_bytes() -> int:
    """Bytes of one signal sample: its time and the NSIGNAL signals."""
    return _FLOAT * (1 + NSIGNAL)


def _counts(scenario) -> tuple[int, int]:
    """(state samples, signal samples) of a scenario, as the engines count them."""
    n_steps = int(round(scenario.t_end / scenario.dt))
    every = max(1, int(round(scenario.sample_dt / scenario.dt)))
    sig_every = scenario.signal_every
    return n_steps // every, (n_steps // sig_every if sig_every else 0)


def _status_bytes(field: str) -> int | None:
    """``field`` (e.g. "VmSize") of ``/proc/self/status`` [bytes], or None where not readable."""
    try:
        with open("/proc/self/status") as f:
            for line in f:
                if line.startswith(field + ":"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return None


#: Process limits that bound a new allocation: (resource name, what the process already uses of it in
#: /proc/self/status, how the user sets it).
_LIMITS = (("RLIMIT_AS", "VmSize", "what the address-space limit (ulimit -v) leaves this process"),
           ("RLIMIT_DATA", "VmData", "what the data-segment limit (ulimit -d) leaves this process"))


def limit_room() -> tuple[int, str] | None:
    """(bytes, name) of the tightest of the process's own memory limits
    (``resource.getrlimit`` of RLIMIT_AS and RLIMIT_DATA, soft limits) less
    what the process already uses of it (VmSize, VmData; 0 where not
    readable); None where no limit is set or the platform has none."""
    try:
        import resource
    except ImportError:  # not on this platform
        return None
    best = None
    for name, field, what in _LIMITS:
        which = getattr(resource, name, None)
        if which is None:
            continue
        try:
            soft = resource.getrlimit(which)[0]
        except (OSError, ValueError):
            continue
        if soft == resource.RLIM_INFINITY or soft < 0:
            continue
        room = max(int(soft) - (_status_bytes(field) or 0), 0)
        if best is None or room < best[0]:
            best = (room, what)
    return best


def _available() -> tuple[int, str] | None:
    """(bytes, what bounds them) a new allocation may take now: the smaller of the free memory
    (:func:`_free_memory`) and :func:`limit_room`; None if neither is known."""
    free = _free_memory()
    found = [x for x in ((free, "the memory available now") if free is not None else None, limit_room())
             if x is not None]
    return min(found) if found else None


def available_memory() -> int | None:
    """Memory available to a new allocation now [bytes]: the free memory,
    or less where a process limit (:func:`limit_room`) leaves less; None if
    neither is known."""
    avail = _available()
    return None if avail is None else avail[0]


def _free_memory() -> int | None:
    """Free memory of the machine now [bytes] (MemAvailable, else the free physical pages), or None."""
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_AVPHYS_PAGES")) * int(os.sysconf("SC_PAGE_SIZE"))
    except (AttributeError, ValueError, OSError):
        return None


def memory_budget() -> int:
    """Bytes the samples of one run may take: MEMORY_FRACTION of the available memory
    (:func:`available_memory`, process limits included)."""
    return _budget()[0]


def _budget() -> tuple[int, str]:
    """(:func:`memory_budget`, what it is a share of)."""
    avail = _available()
    if avail is None:
        return FALLBACK_BUDGET, "a fixed budget: the available memory is unknown"
    return int(MEMORY_FRACTION * avail[0]), f"{MEMORY_FRACTION:g} of {avail[1]}"


def _gib(n: float) -> str:
    return f"{n / 2 ** 30:.3g} GiB" if n >= 2 ** 30 else f"{n / 2 ** 20:.3g} MiB"


def _round_up(x: float) -> float:
    """``x`` rounded up to two significant digits."""
    e = math.floor(math.log10(x)) - 1
    return math.ceil(x / 10.0 ** e * (1.0 - 1e-12)) * 10.0 ** e


def check_sample_memory(bearing, scenario, budget: int | None = None) -> int:
    """Bytes the sampled series of ``scenario`` on ``bearing`` will take;
    InputError naming ``sample_dt`` (with the value that fits) or
    ``signal_dt`` and ``t_end`` when they exceed ``budget`` [bytes]
    (default :func:`memory_budget`, which counts the process's limits:
    the message then names the one that binds)."""
    b = load_bearing(bearing)
    default = budget is None
    budget, source = _budget() if default else (int(budget), "")
    n_state, n_signal = _counts(scenario)
    per = sample_bytes(b.n_balls)
    state, signal = n_state * per, n_signal * signal_bytes()
    need = state + signal
    if need <= budget:
        return need
    where = f"the memory budget {_gib(budget)}" + (f" ({source})" if default else "")
    head = (f"t_end = {scenario.t_end:.6g} s sampled every sample_dt = {scenario.sample_dt:.3g} s: "
            f"{n_state:.3g} samples of {b.n_balls} balls")
    if signal:
        head += (f" ({_gib(state)}) and {n_signal:.3g} signal samples every signal_dt = {scenario.signal_dt:.3g} s "
                 f"({_gib(signal)})")
    head += f" need {_gib(need)}, more than {where}"
    if signal >= budget:
        raise InputError(f"signal_dt: {head}: use a larger signal_dt or a shorter t_end (--t-end)")
    fit = _round_up(max(scenario.t_end * per / (budget - signal), scenario.sample_dt))
    raise InputError(f"sample_dt: {head}: use sample_dt >= {fit:.2g} s (--sample-dt {fit:.2g}) or a shorter t_end "
                     "(--t-end)")


# -- wall time ---------------------------------------------------------------------------------------------
#: A run whose estimated wall time exceeds this [s] says so on stderr before it goes on (and shows its progress).
LONG_RUN_S = 60.0
#: Wall time [s] of integration over which the step cost is measured for the estimate (or the whole run if shorter).
ESTIMATE_AFTER_S = 0.2


def _duration(seconds: float) -> str:
    """``seconds`` in the largest unit that keeps it above 1 (s, min, h, d)."""
    for unit, size in (("d", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.3g} s"


def wall_time_message(n_steps: int, done: int, wall: float, scenario, stable_dt: float | None,
                      long_s: float | None = None) -> str | None:
    """The line that announces a long run of ``scenario``, or None:
    ``n_steps`` steps at the cost measured over the first ``done`` steps in
    ``wall`` [s] take longer than ``long_s`` [s] (None: :data:`LONG_RUN_S`);
    names the estimate, the step cost and what shortens the run (``t_end``,
    a larger ``dt`` up to the stable step ``stable_dt`` [s])."""
    long_s = LONG_RUN_S if long_s is None else long_s
    if done <= 0 or not wall > 0.0:
        return None
    per = wall / done
    est = per * n_steps
    if est <= long_s or done >= n_steps:
        return None
    larger = (f" or a larger dt (--dt; stable step estimate {stable_dt:.3g} s)"
              if stable_dt is not None and stable_dt > 1.05 * scenario.dt else "")
    return (f"{n_steps:.3g} steps of dt = {scenario.dt:.3g} s to t_end = {scenario.t_end:.6g} s: estimated wall time "
            f"{_duration(est)} ({per * 1e6:.3g} us per step over the first {done} steps); a shorter t_end "
            f"(--t-end){larger} shortens it, Ctrl-C stops it")
