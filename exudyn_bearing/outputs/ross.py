"""Export of linearised bearing coefficients to ROSS, the open-source
rotordynamics code (PyPI ``ross-rotordynamics``; optional extra
``pip install -e ".[ross]"``).

ROSS describes a bearing by a ``ross.BearingElement`` on a shaft node with
direct and cross-coupled stiffness and damping kxx, kyy, kxy, kyx, cxx,
cyy, cxy, cyx (and kzz, czz axially), each an array over the rotor speeds
given as ``frequency`` [rad/s], which it interpolates in speed; its
``BallBearingElement`` is an empirical fit without speed dependence.
:func:`to_ross_bearing` builds the first from a
:class:`~exudyn_bearing.model.coefficients.BearingCoefficients` record.

Mapping of axes and signs
-------------------------
* Rotor axis: ROSS's shaft elements run along z, with lateral x, y and
  axial z at each node (``BearingElement.dof_mapping``: x_0, y_0, z_0).
  Ours: bearing axis z, radial x, y. The axial axes coincide.
* Spin: at positive speed ROSS's rotor turns about +z (the gyroscopic
  matrix of a disk, I_p on the (alpha, beta) entries, is that of a spin
  about +z with alpha, beta the tilts about x, y); our inner ring turns
  about +z at positive speed. No sign change.
* Force sign: ROSS adds a bearing's K and C to the rotor's matrices,
  M q'' + (C + Omega G) q' + K q = f, so the bearing force on the shaft is
  -K q - C q'; our K = -dF/dq, C = -dF/dq' of the force on the shaft. No
  sign change.
* Radial load direction: our x is the direction of the radial load on the
  shaft (psi = 0). ``load_angle`` places it in ROSS's x-y plane, measured
  from ROSS's x towards its y (default 0: the load along ROSS's x; -pi/2
  for a load along -y). The lateral 2x2 blocks rotate as
  K_ross = R K R^T with R the rotation by ``load_angle`` about z, which
  keeps the spin direction.
* Not exported: the tilt rows and columns (ROSS's ``BearingElement`` has no
  moment stiffness) and the coupling of x, y to the axial and tilt axes
  (none in ``BearingElement``). A warning names them if they exceed 5 % of
  the geometric mean of the direct terms they couple.
"""
from __future__ import annotations

import contextlib
import io
import math
import os
import warnings

import numpy as np

from ..data import InputError
from ..model.coefficients import BearingCoefficients

__all__ = ["to_ross_bearing", "lateral_coefficients", "import_ross", "COUPLING_WARNING_RATIO"]

#: Dropped couplings above this fraction of the geometric mean of the two
#: direct terms trigger a warning.
COUPLING_WARNING_RATIO = 0.05


@contextlib.contextmanager
def _silenced():
    """Python's and the process's stdout and stderr, and warnings, silenced
    for the block (ROSS's import prints notes about its optional REFPROP
    fluid-property library, some of them from compiled code)."""
    with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()), \
            warnings.catch_warnings():
        warnings.simplefilter("ignore")
        saved = []
        try:
            for fd in (1, 2):
                try:
                    saved.append((fd, os.dup(fd)))
                except OSError:
                    continue
            null = os.open(os.devnull, os.O_WRONLY)
            for fd, _ in saved:
                os.dup2(null, fd)
            os.close(null)
            yield
        finally:
            for fd, dup in saved:
                os.dup2(dup, fd)
                os.close(dup)


def import_ross():
    """The ``ross`` module, imported without its notes on stdout and stderr;
    ImportError naming the extra to install."""
    try:
        with _silenced():
            import ross
    except ImportError as exc:
        raise ImportError("to_ross_bearing needs ROSS (ross-rotordynamics): pip install -e \".[ross]\" "
                          f"({exc})") from None
    return ross


def lateral_coefficients(coefficients: BearingCoefficients, load_angle: float = 0.0):
    """The lateral 2x2 blocks in ROSS's x-y frame and the axial terms.

    Parameters
    ----------
    coefficients : BearingCoefficients
    load_angle : float
        Direction of our x (the radial load on the shaft) in ROSS's x-y
        plane [rad], from x towards y.

    Returns
    -------
    dict with ``k`` and ``c`` (n, 2, 2) [N/m, N s/m] in ROSS's (x, y),
    ``kzz``, ``czz`` (n,) and ``frequency`` (n,) [rad/s].

    Examples
    --------
    A load along -y (gravity) turns our stiff load direction onto ROSS's y:

    >>> k = np.zeros((1, 5, 5)); k[0, 0, 0], k[0, 1, 1], k[0, 2, 2] = 3e8, 1e8, 5e7
    >>> lat = lateral_coefficients(BearingCoefficients([100.0], k, np.zeros((1, 5, 5))), -np.pi / 2)
    >>> np.round(np.diag(lat["k"][0]) / 1e8, 12).tolist(), float(lat["kzz"][0])
    ([1.0, 3.0], 50000000.0)
    """
    if not isinstance(coefficients, BearingCoefficients):
        raise InputError(f"coefficients: expected BearingCoefficients, got {type(coefficients).__name__}")
    a = float(load_angle)
    if not math.isfinite(a):
        raise InputError(f"load_angle: must be finite [rad], got {load_angle!r}")
    r = np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])
    k = np.einsum("ij,njk,lk->nil", r, coefficients.stiffness[:, :2, :2], r)
    c = np.einsum("ij,njk,lk->nil", r, coefficients.damping[:, :2, :2], r)
    return {"k": k, "c": c, "kzz": coefficients.stiffness[:, 2, 2].copy(),
            "czz": coefficients.damping[:, 2, 2].copy(), "frequency": coefficients.speeds.copy()}


def _warn_dropped(coefficients):
    worst, where = 0.0, None
    for name, mat in (("stiffness", coefficients.stiffness), ("damping", coefficients.damping)):
        d = np.abs(np.diagonal(mat, axis1=1, axis2=2))
        for i in (0, 1):
            for j in (2, 3, 4):
                for a, b in ((i, j), (j, i)):
                    scale = np.sqrt(d[:, a] * d[:, b])
                    ratio = np.where(scale > 0.0, np.abs(mat[:, a, b]) / np.where(scale > 0.0, scale, 1.0),
                                     np.where(np.abs(mat[:, a, b]) > 0.0, np.inf, 0.0))
                    if ratio.max() > worst:
                        worst, where = float(ratio.max()), f"{name}[{coefficients.axes[a]}, {coefficients.axes[b]}]"
    if worst > COUPLING_WARNING_RATIO:
        warnings.warn(f"coefficients: ROSS's BearingElement has no coupling of x, y to the axial and tilt axes; "
                      f"dropped {where} reaches {worst:.3g} of the direct terms", stacklevel=3)


def to_ross_bearing(coefficients: BearingCoefficients, n: int, load_angle: float = 0.0,
                    include_axial: bool = True, n_link=None, tag=None, **kwargs):
    """A ``ross.BearingElement`` with speed-dependent coefficients.

    Parameters
    ----------
    coefficients : BearingCoefficients
        Speeds [rad/s] and 5x5 stiffness and damping (axes x, y, axial,
        tilt x, tilt y).
    n : int
        ROSS node of the bearing (>= 0).
    load_angle : float
        Direction of our x (the radial load on the shaft) in ROSS's x-y plane
        [rad] (module docstring); default 0.
    include_axial : bool
        Pass the axial stiffness and damping as kzz, czz (default True).
    n_link : int, optional
        ROSS node the bearing connects to (None: ground), passed through.
    tag : str, optional
        Element tag.
    **kwargs
        Passed to ``ross.BearingElement`` (e.g. ``scale_factor``).

    Returns
    -------
    ross.BearingElement
        kxx, kyy, kxy, kyx [N/m], cxx, cyy, cxy, cyx [N s/m] (and kzz, czz)
        as arrays over ``frequency`` = the speeds [rad/s].

    Notes
    -----
    ROSS interpolates each coefficient in speed (a smoothing cubic spline
    for four or more speeds, interp1d for two or three); outside the speed
    range it extrapolates, so cover the rotor's speed range.
    """
    ross = import_ross()
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 0:
        raise InputError(f"n: expected a node number >= 0, got {n!r}")
    lat = lateral_coefficients(coefficients, load_angle)
    _warn_dropped(coefficients)
    k, c = lat["k"], lat["c"]
    coeff = {"kxx": k[:, 0, 0], "kxy": k[:, 0, 1], "kyx": k[:, 1, 0], "kyy": k[:, 1, 1],
             "cxx": c[:, 0, 0], "cxy": c[:, 0, 1], "cyx": c[:, 1, 0], "cyy": c[:, 1, 1]}
    if include_axial:
        coeff.update(kzz=lat["kzz"], czz=lat["czz"])
    coeff = {name: [float(x) for x in v] for name, v in coeff.items()}
    return ross.BearingElement(n=int(n), frequency=[float(w) for w in lat["frequency"]], n_link=n_link,
                               tag=tag, **coeff, **kwargs)
