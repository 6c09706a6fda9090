"""Linear vibration of M q'' + C q' + K q = f: eigen-analysis, frequency and
time response.

The second-order system of n coordinates is written as 2n first-order
equations in the state z = (q, q')::

    z' = A z + B f,   A = [[0, I], [-M^-1 K, -M^-1 C]],   B = [[0], [M^-1]]

and ``scipy.linalg.eig`` gives the 2n eigenvalues lambda and eigenvectors
(phi, lambda phi). Per eigenvalue: natural frequency f_n = |lambda| / (2 pi)
[Hz], damping ratio zeta = -Re(lambda) / |lambda| (1 for a real, overdamped
root, negative for a growing one), mode shape phi scaled so that its largest
entry is 1 (real). Underdamped modes come as conjugate pairs; they are
listed next to each other, the one with positive imaginary part first,
in the order of |lambda|.

The frequency response (receptance) is H(w) = (K - w^2 M + i w C)^-1 [m/N].
The time response integrates the state equation exactly for a force that is
linear between samples (first-order hold, Franklin, Powell & Workman [1]_):
with h the step and Phi = exp(A h), the matrices Gamma_1, Gamma_2 of
z_{k+1} = Phi z_k + Gamma_1 f_k + Gamma_2 (f_{k+1} - f_k) are blocks of the
exponential of an augmented matrix (Van Loan [2]_), so the step is limited
only by how finely the force must be sampled, not by the stiffness.

References
----------
.. [1] G. F. Franklin, J. D. Powell, M. L. Workman, Digital Control of
   Dynamic Systems, 3rd ed., Addison-Wesley, 1998, ch. 6 (triangle hold).
.. [2] C. F. Van Loan, "Computing integrals involving the matrix
   exponential," IEEE Trans. Autom. Control 23(3) (1978) 395-404.
   doi:10.1109/TAC.1978.1101743
.. [3] D. J. Inman, Engineering Vibration, 4th ed., Pearson, 2014, ch. 4
   (state-space form and damping ratios of viscously damped systems).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import scipy.linalg as sla

from ...data import InputError

__all__ = ["EIGENVALUE_SPAN", "ModalResult", "check_matrices", "state_matrix", "modal_analysis", "frequency_response",
           "time_response", "mechanical_energy"]


#: Largest ratio of the largest to the smallest |eigenvalue| that :func:`modal_analysis`
#: accepts: rounding (about 1e-16 of the largest) stays below 1e-4 of the smallest.
EIGENVALUE_SPAN = 1e12


def check_matrices(mass, damping, stiffness):
    """M, C, K as float arrays of one square shape; M symmetric positive
    definite, all finite. Raises InputError naming the matrix."""
    mats = []
    for name, m in (("mass", mass), ("damping", damping), ("stiffness", stiffness)):
        a = np.asarray(m, dtype=float)
        if a.ndim != 2 or a.shape[0] != a.shape[1]:
            raise InputError(f"{name}: must be a square matrix, got shape {a.shape}")
        if not np.all(np.isfinite(a)):
            raise InputError(f"{name}: entries must be finite")
        mats.append(a)
    if not mats[0].shape == mats[1].shape == mats[2].shape:
        raise InputError(f"damping: shapes differ (mass {mats[0].shape}, damping {mats[1].shape}, "
                         f"stiffness {mats[2].shape})")
    m = mats[0]
    if not np.allclose(m, m.T, rtol=1e-12, atol=0.0):
        raise InputError("mass: must be symmetric")
    try:
        np.linalg.cholesky(m)
    except np.linalg.LinAlgError:
        raise InputError("mass: must be positive definite") from None
    return mats


def state_matrix(mass, damping, stiffness):
    """A = [[0, I], [-M^-1 K, -M^-1 C]] of the first-order form [3]_ (2n x 2n)."""
    m, c, k = check_matrices(mass, damping, stiffness)
    n = m.shape[0]
    a = np.zeros((2 * n, 2 * n))
    a[:n, n:] = np.eye(n)
    a[n:, :n] = -np.linalg.solve(m, k)
    a[n:, n:] = -np.linalg.solve(m, c)
    return a


@dataclass
class ModalResult:
    """Eigen-analysis of the first-order system (one entry per eigenvalue).

    Attributes
    ----------
    eigenvalues : ndarray, complex (2n,)
        lambda [1/s].
    natural_frequencies : ndarray (2n,)
        |lambda| / (2 pi) [Hz].
    damping_ratios : ndarray (2n,)
        -Re(lambda) / |lambda| [-].
    mode_shapes : ndarray, complex (2n, n)
        Displacement part of each eigenvector, largest entry 1.
    """

    eigenvalues: np.ndarray
    natural_frequencies: np.ndarray
    damping_ratios: np.ndarray
    mode_shapes: np.ndarray

    @property
    def damped_frequencies(self) -> np.ndarray:
        """|Im(lambda)| / (2 pi) [Hz] (0 for real roots)."""
        return np.abs(self.eigenvalues.imag) / (2.0 * np.pi)

    def modes(self):
        """One row per mode: the underdamped pairs once (positive imaginary
        part) and every real root, as dicts with ``eigenvalue``,
        ``frequency_hz``, ``damping_ratio``, ``shape``."""
        rows = []
        for i, lam in enumerate(self.eigenvalues):
            if lam.imag < 0.0:
                continue
            rows.append({"eigenvalue": lam, "frequency_hz": float(self.natural_frequencies[i]),
                         "damping_ratio": float(self.damping_ratios[i]), "shape": self.mode_shapes[i],
                         "real_root": lam.imag == 0.0})
        return rows

    def to_dict(self) -> dict:
        """JSON-able: complex numbers as [re, im] pairs; units in ``units``."""
        pair = lambda z: [float(np.real(z)), float(np.imag(z))]  # noqa: E731
        return {
            "eigenvalues": [pair(z) for z in self.eigenvalues],
            "natural_frequencies": [float(f) for f in self.natural_frequencies],
            "damping_ratios": [float(d) for d in self.damping_ratios],
            "mode_shapes": [[pair(z) for z in row] for row in self.mode_shapes],
            "units": {"eigenvalues": "1/s ([re, im])", "natural_frequencies": "Hz",
                      "damping_ratios": "-", "mode_shapes": "- ([re, im], largest entry 1)"},
        }


def modal_analysis(mass, damping, stiffness) -> ModalResult:
    """Eigenvalues, natural frequencies, damping ratios and mode shapes of
    M q'' + C q' + K q = 0 (module docstring) with ``scipy.linalg.eig``.

    Raises InputError if the system has a zero eigenvalue (a singular
    stiffness matrix: a rigid-body or unconnected coordinate), whose damping
    ratio is undefined, or if its eigenvalues span more than
    :data:`EIGENVALUE_SPAN` (|lambda| largest / smallest): the rounding
    error of the largest, about 1e-16 |lambda_max|, then exceeds 1e-4 of the
    smallest, whose value (and sign of its real part) the double-precision
    eigen-solver no longer resolves (e.g. a damping so large against the
    stiffness that slow creep modes k/c sit next to fast ones c/m).

    Examples
    --------
    One mass on a spring and damper, m = 1 kg, k = 4e4 N/m, c = 40 N s/m:
    omega_n = 200 rad/s, zeta = c / (2 sqrt(k m)) = 0.1:

    >>> r = modal_analysis([[1.0]], [[40.0]], [[4e4]])
    >>> round(float(r.natural_frequencies[0]) * 2 * np.pi, 6), round(float(r.damping_ratios[0]), 6)
    (200.0, 0.1)
    """
    a = state_matrix(mass, damping, stiffness)
    n = a.shape[0] // 2
    k = np.asarray(stiffness, dtype=float)
    sv = np.linalg.svd(k, compute_uv=False)
    if sv.min() <= 1e-12 * max(sv.max(), 1e-300):
        raise InputError("stiffness: the system has a zero eigenvalue (a rigid-body mode or a coordinate "
                         "without stiffness); ground every body through some spring")
    lam, vec = sla.eig(a)
    mag = np.abs(lam)
    span = mag.max() / mag.min() if mag.min() > mag.max() * 1e-300 else np.inf
    if span > EIGENVALUE_SPAN:
        raise InputError(f"damping: the eigenvalues span {span:.2g} (|lambda| {mag.min():.3g} to {mag.max():.3g} 1/s), "
                         f"more than the {EIGENVALUE_SPAN:.0e} double precision resolves: the slow ones are "
                         "rounding noise (damping far too large or too small against the stiffness and masses)")
    # conjugate pairs together, the positive imaginary part first
    order = np.lexsort((-lam.imag, np.round(mag / mag.max(), 12)))
    lam, vec, mag = lam[order], vec[:, order], mag[order]
    shapes = vec[:n, :].T.copy()
    for i in range(shapes.shape[0]):
        j = int(np.argmax(np.abs(shapes[i])))
        shapes[i] = shapes[i] / shapes[i, j]
    # real roots have exactly real eigenvectors after scaling
    shapes[lam.imag == 0.0] = shapes[lam.imag == 0.0].real
    return ModalResult(lam, mag / (2.0 * np.pi), -lam.real / mag + 0.0, shapes)  # + 0.0: no -0.0


def frequency_response(mass, damping, stiffness, frequencies):
    """Receptance H(w) = (K - w^2 M + i w C)^-1 at the frequencies [Hz].

    Returns a complex array of shape (len(frequencies), n, n) [m/N]:
    ``H[k, i, j]`` is the displacement of coordinate i per unit harmonic
    force on coordinate j.

    Examples
    --------
    Static limit of a single spring, 1 / k:

    >>> float(frequency_response([[1.0]], [[0.0]], [[4e4]], [0.0])[0, 0, 0].real)
    2.5e-05
    """
    m, c, k = check_matrices(mass, damping, stiffness)
    f = np.atleast_1d(np.asarray(frequencies, dtype=float))
    if not np.all(np.isfinite(f)) or np.any(f < 0.0):
        raise InputError("frequencies: must be finite and >= 0 [Hz]")
    w = 2.0 * np.pi * f
    dyn = k[None] - (w * w)[:, None, None] * m[None] + 1j * w[:, None, None] * c[None]
    eye = np.broadcast_to(np.eye(m.shape[0], dtype=complex), dyn.shape)
    try:
        return np.linalg.solve(dyn, eye)
    except np.linalg.LinAlgError:
        raise InputError("frequencies: the dynamic stiffness is singular at one of the frequencies "
                         "(an undamped resonance)") from None


def _hold_matrices(a, b, h):
    """Phi, Gamma_1, Gamma_2 of the first-order-hold step (Van Loan [2]_)."""
    ns, ni = b.shape
    z = np.zeros((ns + 2 * ni, ns + 2 * ni))
    z[:ns, :ns] = a * h
    z[:ns, ns:ns + ni] = b * h
    z[ns:ns + ni, ns + ni:] = np.eye(ni)
    e = sla.expm(z)
    return e[:ns, :ns], e[:ns, ns:ns + ni], e[:ns, ns + ni:]


def time_response(mass, damping, stiffness, t, force, q0=None, v0=None):
    """Displacements and velocities under a sampled force, exact for a force
    linear between samples (first-order hold, module docstring).

    Parameters
    ----------
    mass, damping, stiffness : array (n, n)
        M [kg], C [N s/m], K [N/m].
    t : array (N,)
        Uniformly spaced times [s].
    force : array (N, n)
        Force on each coordinate at each time [N].
    q0, v0 : array (n,), optional
        Initial displacement [m] and velocity [m/s] (default zero).

    Returns
    -------
    q, v : arrays (N, n) [m], [m/s]

    Examples
    --------
    Free vibration of one undamped mass released from 1 mm: q(T/2) = -1 mm.

    >>> t = np.linspace(0.0, np.pi / 200.0, 101)
    >>> q, v = time_response([[1.0]], [[0.0]], [[4e4]], t, np.zeros((101, 1)), q0=[1e-3])
    >>> round(float(q[-1, 0]) * 1e3, 9)
    -1.0
    """
    m, c, k = check_matrices(mass, damping, stiffness)
    n = m.shape[0]
    t = np.asarray(t, dtype=float)
    if t.ndim != 1 or t.size < 2 or not np.all(np.isfinite(t)):
        raise InputError("t: must be a 1-D array of at least two finite times")
    h = (t[-1] - t[0]) / (t.size - 1)
    if h <= 0.0 or not np.allclose(np.diff(t), h, rtol=1e-9, atol=0.0):
        raise InputError("t: times must be increasing and uniformly spaced")
    f = np.asarray(force, dtype=float)
    if f.shape != (t.size, n) or not np.all(np.isfinite(f)):
        raise InputError(f"force: must be a finite array of shape ({t.size}, {n}), got {f.shape}")
    a = state_matrix(m, c, k)
    b = np.vstack([np.zeros((n, n)), np.linalg.inv(m)])
    phi, g1, g2 = _hold_matrices(a, b, h)
    z = np.zeros((t.size, 2 * n))
    z[0, :n] = 0.0 if q0 is None else np.asarray(q0, float)
    z[0, n:] = 0.0 if v0 is None else np.asarray(v0, float)
    if not np.all(np.isfinite(z[0])):
        raise InputError("q0: initial state must be finite")
    # the input terms do not depend on the state: add them all at once
    drive = f[:-1] @ g1.T + (f[1:] - f[:-1]) @ g2.T
    for i in range(t.size - 1):
        z[i + 1] = phi @ z[i] + drive[i]
    return z[:, :n], z[:, n:]


def mechanical_energy(mass, stiffness, q, v):
    """Kinetic plus potential energy 1/2 v^T M v + 1/2 q^T K_s q [J] along a
    trajectory (K_s the symmetric part of K); q, v of shape (N, n)."""
    m = np.asarray(mass, float)
    ks = 0.5 * (np.asarray(stiffness, float) + np.asarray(stiffness, float).T)
    q = np.atleast_2d(q)
    v = np.atleast_2d(v)
    return 0.5 * np.einsum("ti,ij,tj->t", v, m, v) + 0.5 * np.einsum("ti,ij,tj->t", q, ks, q)
