"""``pounding.spectrum``: elastic response spectra of records (``pounding spectrum``)."""

from __future__ import annotations

import os
from typing import Any, List, Optional, Sequence, Tuple

import numpy as np

from . import _core
from ._common import csv_table, optional_float, real_number


def _name(x: Any, what: str) -> str:
    if isinstance(x, (str, os.PathLike)):
        return os.fspath(x)
    raise TypeError(f"{what} must be a path or a builtin: name (str or os.PathLike), "
                    f"not {type(x).__name__}")


def _records(records: Any) -> List[str]:
    if records is None:
        return []
    if isinstance(records, (str, os.PathLike)):
        return [os.fspath(records)]  # one record, not its characters
    return [_name(r, "a record") for r in records]


def _pairs(pair: Any) -> List[Tuple[str, str]]:
    if isinstance(pair, (str, bytes, os.PathLike)):
        raise TypeError("pair must be an (X, Y) tuple of two records or a list of them, not one "
                        f"record {pair!r}: a single record goes in records")
    if pair is None:
        return []
    if isinstance(pair, tuple) and len(pair) == 2 and all(
        isinstance(p, (str, os.PathLike)) for p in pair
    ):
        pair = [pair]  # one pair
    out = []
    for p in pair:
        if not (isinstance(p, (tuple, list)) and len(p) == 2):
            raise TypeError(f"pair must be an (X, Y) tuple of two records or a list of them, "
                            f"not {p!r}")
        out.append((_name(p[0], "a pair's record"), _name(p[1], "a pair's record")))
    return out


def spectrum_csv_text(records: Any = (), *, pair: Any = None, damping: float = 0.05,
                      periods: Optional[Sequence[float]] = None, csv_units: str = "g",
                      record_dt: Optional[float] = None) -> str:
    """The text of ``spectrum.csv`` for :func:`spectrum` (byte for byte the CLI's)."""
    names, pairs = _records(records), _pairs(pair)
    if not names and not pairs:
        raise ValueError("give at least one record or pair (e.g. "
                         "pounding.spectrum(\"builtin:ELC180\"))")
    if periods is None:
        ts: List[float] = []  # the default periods
    else:
        if isinstance(periods, np.ndarray) and periods.ndim == 0:
            periods = [periods.item()]
        elif isinstance(periods, (int, float, np.integer, np.floating)):
            periods = [periods]
        elif isinstance(periods, (str, bytes)):
            raise TypeError(f"periods must be a number or a sequence of numbers [s], not the text "
                            f"{periods!r}")
        ts = [real_number("periods", t) for t in periods]
        if not ts:
            raise ValueError("invalid periods: the list is empty (None gives the default 100 "
                             "periods from 0.01 s to 10 s)")
    if not isinstance(csv_units, str):
        raise TypeError(f"csv_units must be a str (g or m/s2), not {type(csv_units).__name__}")
    return _core.spectrum_run(names, pairs, real_number("damping", damping), ts, csv_units,
                              optional_float("record_dt", record_dt))


def spectrum(
    records: Any = (),
    *,
    pair: Any = None,
    damping: float = 0.05,
    periods: Optional[Sequence[float]] = None,
    csv_units: str = "g",
    record_dt: Optional[float] = None,
):
    """Elastic response spectra, as ``pounding spectrum RECORDS [--pair X Y] ...`` (no figure).

    The exact peak response of a linear oscillator to the record (linear between samples,
    zero after the last) at each period; for a horizontal pair also RotD50 and RotD100 (the
    median and largest over the rotation angle of the pair's combined response).

    Args:
        records: records, component ``x`` each: a path (PEER ``.AT2``, CSV ``t, a``, columns
            ``t a``, one column with ``record_dt``) or ``"builtin:ELC180"`` /
            ``"builtin:ELC270"``; a list of them, or one.
        pair: a horizontal pair ``(X, Y)`` or a list of pairs (``--pair X Y``, repeatable):
            components ``x``, ``y``, ``rotd50``, ``rotd100``, the record named ``X+Y``.
        damping: damping ratio, a fraction of critical (``--damping``; 0.05 = 5 %).
        periods: periods [s] (``--periods``; default: 100 from 0.01 s to 10 s, even in log T).
        csv_units: units of text records, ``"g"`` or ``"m/s2"`` (an ``.AT2`` header names its
            own).
        record_dt: sample interval [s] of one-column records.

    Returns:
        The rows of ``spectrum.csv`` (same columns, order and numbers): ``record``,
        ``component``, ``period_s`` [s], ``damping``, ``psa_g`` (pseudo-spectral acceleration
        [g]), ``psv_m_s`` (pseudo-spectral velocity [m/s]), ``sd_m`` (spectral displacement
        [m]); a ``pandas.DataFrame``, or a numpy structured array without pandas.

    Raises:
        ValueError: bad input with the CLI's message, naming the argument or the record (no
            record, a damping outside [0, 1), a period given twice or out of range, an
            unreadable record, an unknown ``builtin:`` name).
        TypeError: a record that is not a path, a bool or complex number.
    """
    return csv_table(spectrum_csv_text(records, pair=pair, damping=damping, periods=periods,
                                       csv_units=csv_units, record_dt=record_dt))
