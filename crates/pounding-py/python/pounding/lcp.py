"""Linear complementarity problems: ``w = M z + q, z >= 0, w >= 0, z'w = 0``.

The solvers of ``pounding lcp solve`` on numpy arrays: :func:`solve` (lexicographic Lemke, one
solution or a failure *status*) and :func:`enumerate` (every solution, ``n <= 12``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from . import _core
from ._common import float_array

__all__ = ["LcpResult", "solve", "enumerate"]


@dataclass(frozen=True)
class LcpResult:
    """The outcome of :func:`solve`.

    Attributes:
        z: float64 array of shape ``(n,)`` (NaN-free only when ``status == "solved"``).
        w: float64 array of shape ``(n,)``, ``w = M z + q``.
        status: ``"solved"``, ``"ray"`` (secondary ray), ``"max_pivots"`` or
            ``"ill_conditioned"``: the CLI's status names. Only ``"solved"`` carries a verified
            solution.
        pivots: number of pivots taken.
        residual: ``max_i |min(z_i, w_i)|`` of the returned point.
    """

    z: np.ndarray
    w: np.ndarray
    status: str
    pivots: int
    residual: float

    @property
    def solved(self) -> bool:
        """``True`` when ``status == "solved"``."""
        return self.status == "solved"


def _arrays(M, q):
    return float_array(M, "M"), float_array(q, "q")


def solve(M, q) -> LcpResult:
    """Solve the LCP ``(M, q)`` with the lexicographic Lemke solver of ``pounding lcp solve``.

    Args:
        M: ``(n, n)`` array-like of floats.
        q: ``(n,)`` array-like of floats.

    Returns:
        An :class:`LcpResult`. A failed solve (ray termination, pivot limit, ill-conditioning) is
        reported in ``status``; it never raises.

    Raises:
        TypeError: complex, bool or masked arrays (never cast silently).
        ValueError: ``M`` not square, ``q`` of the wrong length, ``n = 0``, or a non-finite entry
            (the library's message, e.g. ``invalid LCP: M[0][1] is not finite``).
    """
    m, qq = _arrays(M, q)
    z, w, status, pivots, residual = _core.lcp_solve(m, qq)
    return LcpResult(z, w, status, pivots, residual)


def enumerate(M, q) -> np.ndarray:  # noqa: A001 - the CLI's solver name
    """Every solution of the LCP ``(M, q)`` by enumeration of complementary bases.

    The solver of ``pounding lcp solve --solver enum``.

    Args:
        M: ``(n, n)`` array-like of floats, ``n <= 12``.
        q: ``(n,)`` array-like of floats.

    Returns:
        A float64 array of shape ``(k, n)``: one solution ``z`` per row, ``k = 0`` when the
        problem has no solution.

    Raises:
        ValueError: bad shapes, non-finite entries, or ``n > 12``.
    """
    m, qq = _arrays(M, q)
    return _core.lcp_enumerate(m, qq)
