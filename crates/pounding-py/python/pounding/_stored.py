"""The stored form of a :class:`pounding.SimulationResult` (what a pickled result holds): its
columns as numpy arrays, answering as the core's ``SimRun`` does (no public API)."""

from __future__ import annotations

from typing import Any, List, Optional, Sequence, Tuple

import numpy as np

from . import _core


class _StoredRun:
    """A run rebuilt from its columns (an unpickled :class:`SimulationResult`): the same methods
    as the core's ``SimRun``, answering from the arrays it was pickled with (no text parsed).
    ``history_csv()``/``impacts_csv()`` write the columns again with the library's CSV writer
    (``_core.table_csv``): the CLI's bytes."""

    def __init__(self, summary_json: str, status: str, warnings: List[str],
                 history: Tuple[List[str], np.ndarray], impacts: Sequence[Tuple[str, Any]],
                 tables: Sequence[Any] = (), accuracy_json: Optional[str] = None) -> None:
        self._summary, self.status, self._warnings = summary_json, status, list(warnings)
        self._history = (list(history[0]), history[1])
        self._impacts = [(h, v) for h, v in impacts]
        self._tables = [(n, list(h), a) for n, h, a in tables]
        self._accuracy = accuracy_json

    def accuracy_json(self) -> Optional[str]:
        return self._accuracy

    def tables(self):
        return [(n, list(h), a.copy()) for n, h, a in self._tables]

    def summary_json(self) -> str:
        return self._summary

    def impacts(self):
        return [(h, v.copy() if isinstance(v, np.ndarray) else list(v)) for h, v in self._impacts]

    def impacts_csv(self) -> str:
        return _core.table_csv([h for h, _ in self._impacts], [v for _, v in self._impacts])

    def history(self):
        names, data = self._history
        return list(names), data.copy()

    def history_csv(self) -> str:
        names, data = self._history
        return _core.table_csv(list(names), [data[:, i] for i in range(len(names))])

    def warnings(self) -> List[str]:
        return list(self._warnings)


def _same(a: Any, b: Any) -> bool:
    """``a`` and ``b`` equal bit for bit: arrays of one dtype and shape with the same bytes
    (NaN equals NaN, -0.0 differs from 0.0), sequences item by item, other values by ``==``."""
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return (isinstance(a, np.ndarray) and isinstance(b, np.ndarray) and a.dtype == b.dtype
                and a.shape == b.shape
                and (a.tolist() == b.tolist() if a.dtype == object else
                     np.ascontiguousarray(a).tobytes() == np.ascontiguousarray(b).tobytes()))
    if isinstance(a, (list, tuple)) and isinstance(b, (list, tuple)):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    return bool(a == b)
