"""``pounding.motion``: synthetic ground motions (``pounding motion``).

* :func:`synth` — a suite of synthetic accelerograms (``pounding motion synth``): the records as
  numpy arrays in g and, with ``out``, the CLI's files (the same bytes for the same seed).

Synthetic records are for trying the workflow; real assessments need real records.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Any, List, Optional, Tuple

import numpy as np

from . import _core
from ._common import optional_float, real_number


@dataclass(frozen=True)
class SynthSuite:
    """A synthetic suite (the records of ``pounding motion synth``).

    Attributes:
        ids: record ids, ``SYN001``, ``SYN002``, ... (zero-padded to the width of the count).
        x: per record, the first horizontal component [g], float64 of shape ``(samples,)``
            (``round(duration / dt) + 1`` samples at ``t = 0, dt, ...``): exactly the values of
            ``SYNnnn_x.AT2``.
        y: per record, the second component [g] (``pairs=True``), else ``None``.
        dt: the sample interval [s].
        out: the directory the files were written to, or ``None``.
    """

    ids: List[str]
    x: List[np.ndarray]
    y: Optional[List[np.ndarray]]
    dt: float
    out: Optional[str]

    @property
    def records(self) -> List[Tuple[np.ndarray, float, str]]:
        """The x components as ``(accelerations in g, dt, id)`` tuples, the record form
        :func:`pounding.simulate` and :func:`pounding.batch` take."""
        return [(a, self.dt, i) for i, a in zip(self.ids, self.x)]

    @property
    def t(self) -> np.ndarray:
        """Sample times [s], shape ``(samples,)``."""
        return np.arange(len(self.x[0])) * self.dt


def _integer(name: str, x: Any, hi: int, what: str) -> int:
    """``x`` as an int in ``[0, hi]`` (the library checks the rest and names the argument);
    ``TypeError`` for bool, float, str..."""
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)):
        raise TypeError(f"{name} must be an int, not {type(x).__name__}")
    if not 0 <= int(x) <= hi:
        raise ValueError(f"invalid {name} = {int(x)}: {what}")
    return int(x)


def synth(
    count: int,
    seed: int,
    *,
    out: Any = None,
    pga: Optional[float] = None,
    dt: float = 0.01,
    duration: float = 20.0,
    pairs: bool = False,
) -> SynthSuite:
    """Synthetic accelerograms, as ``pounding motion synth --count N --seed S [--out DIR] ...``.

    Kanai-Tajimi/Clough-Penzien filtered white noise times a Saragoni-Hart envelope, baseline
    corrected (zero final velocity and displacement). The same ``seed`` and parameters give the
    same records, for any number of threads.

    Args:
        count: number of records (``--count``, 1 to 10000).
        seed: random seed (``--seed``, an integer in [0, 2**64)).
        out: a directory to write the CLI's files into (``--out``; created if needed):
            ``SYNnnn_x.AT2`` (and ``_y``), ``SYNTHETIC.txt`` and the record-set manifest
            ``suite.toml`` last, byte for byte the CLI's. ``None``: nothing is written.
        pga: scale every component to this PGA [g] (``--pga``; default: unscaled).
        dt: sample interval [s] (``--dt``).
        duration: duration [s] (``--duration``; a whole number of steps of ``dt``).
        pairs: two independent horizontal components per record (``--pairs``).

    Returns:
        A :class:`SynthSuite` (accelerations in g).

    Raises:
        ValueError: bad input with the CLI's message naming the argument (nothing written).
        TypeError: a ``count`` or ``seed`` that is not an int, a bool or complex number.
    """
    count = _integer("count", count, 2**32, "must lie in 1..=10000")
    seed = _integer("seed", seed, 2**64 - 1, "must be an integer in [0, 2**64)")
    if not isinstance(pairs, (bool, np.bool_)):
        raise TypeError(f"pairs must be a bool, not {type(pairs).__name__}")
    if out is not None and not isinstance(out, (str, os.PathLike)):
        raise TypeError(f"out must be a path (str or os.PathLike) or None, not "
                        f"{type(out).__name__}")
    out_path = None if out is None else os.fspath(out)
    dt = real_number("dt", dt)
    ids, xs, ys = _core.motion_synth(count, seed, out=out_path, pga=optional_float("pga", pga),
                                     dt=dt, duration=real_number("duration", duration),
                                     pairs=bool(pairs))
    return SynthSuite(ids=list(ids), x=list(xs), y=list(ys) if pairs else None, dt=dt,
                      out=out_path)


__all__ = ["SynthSuite", "synth"]
