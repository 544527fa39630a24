"""``pounding.simulate`` and ``pounding.batch``: seismic time histories with pounding."""

from __future__ import annotations

import json
import warnings
from typing import Any, Dict, List, Optional, Sequence

import numpy as np

from . import _core
from ._common import csv_table, optional_float, parse_csv, record_arg, scenario_args

#: The energy columns of ``history.csv`` (the prefix ``E_``/``energy`` terms), by name.
_ENERGY_PREFIXES = ("e_", "energy", "w_in", "input_energy")


class SimulationResult:
    """One simulation (the numeric outputs of ``pounding simulate``).

    Attributes:
        summary: ``summary.json`` as a dict, exactly ``json.load`` of the CLI's file.
        status: how the run ended: ``"Completed"``, ``"CompletedWithLcpFailures"``,
            ``"Diverged"``, ``"CompletedWithNewtonFailures"`` or ``"CompletedWithEnergyError"``.
            Only ``"Completed"`` is trustworthy (the CLI exits 1 otherwise, after writing).
        warnings: the CLI's warnings for this run (also issued as ``UserWarning``).
    """

    def __init__(self, run) -> None:
        self._run = run
        self.summary: Dict[str, Any] = json.loads(run.summary_json())
        self.status: str = run.status
        self.warnings: List[str] = list(run.warnings())
        self._history: Optional[Dict[str, np.ndarray]] = None

    @property
    def ok(self) -> bool:
        """``True`` when ``status == "Completed"`` (the CLI's exit 0)."""
        return self.status == "Completed"

    @property
    def history(self) -> Dict[str, np.ndarray]:
        """The time histories of ``history.csv``: column name → float64 array of shape
        ``(steps stored,)`` (``t_s``, ground accelerations, displacements and rotations in
        degrees, velocities, gaps, slip, energies, contact forces...). Built on first access."""
        if self._history is None:
            names, data = self._run.history()
            self._history = {n: data[:, i] for i, n in enumerate(names)}
        return self._history

    @property
    def history_array(self) -> np.ndarray:
        """The history as one float64 array of shape ``(steps stored, columns)`` in
        ``history.csv``'s column order (see :attr:`history_columns`)."""
        return np.column_stack(list(self.history.values()))

    @property
    def history_columns(self) -> List[str]:
        """The column names of ``history.csv``, in order."""
        return list(self.history.keys())

    @property
    def t(self) -> np.ndarray:
        """Stored times [s], shape ``(steps stored,)``."""
        return self.history["t_s"]

    @property
    def energy(self) -> Dict[str, np.ndarray]:
        """The energy terms of ``history.csv`` (columns whose name ends in ``_J``)."""
        return {k: v for k, v in self.history.items() if k.endswith("_J")}

    @property
    def impacts(self):
        """The rows of ``impacts.csv`` (a ``pandas.DataFrame``, or a numpy structured array
        without pandas): one row per impacting contact."""
        return csv_table(self._run.impacts_csv())

    def history_csv(self) -> str:
        """The text of ``history.csv``, byte for byte the CLI's."""
        return self._run.history_csv()

    def impacts_csv(self) -> str:
        """The text of ``impacts.csv``, byte for byte the CLI's."""
        return self._run.impacts_csv()

    def summary_json(self) -> str:
        """The text of ``summary.json``, byte for byte the CLI's."""
        return self._run.summary_json()

    def __repr__(self) -> str:
        return f"<SimulationResult status={self.status} impacts={self.summary.get('impacts')}>"


def simulate(
    scenario: Any = None,
    record: Any = None,
    scale: Optional[float] = None,
    *,
    dt: Optional[float] = None,
    duration: Optional[float] = None,
    law: Optional[str] = None,
    csv_units: Optional[str] = None,
    record_dt: Optional[float] = None,
) -> SimulationResult:
    """Run one seismic time history, as ``pounding simulate`` (no files, no figures).

    Args:
        scenario: ``None`` (built-in default), a scenario file path (its record paths are
            relative to the file, as in the CLI), a TOML string or a dict with the file's keys.
            Two decks or a bridge of ``[[segment]]``s.
        record: replaces the scenario's records, as the only component along y: a file path
            (``--record``; PEER .AT2, CSV ``t, a``, columns ``t a``, or one column with
            ``record_dt``), or a tuple ``(accelerations, dt)`` / ``(accelerations, dt, name)``
            of a 1-D array in ``csv_units`` (default: the scenario's, g).
        scale: multiplies the ground-motion scale factors (``--scale``).
        dt, duration, law, csv_units, record_dt: the CLI's ``--dt``, ``--duration``, ``--law``,
            ``--csv-units``, ``--record-dt``.

    Returns:
        A :class:`SimulationResult`; a run ending ``Diverged`` (or another untrustworthy status)
        is returned with that status, as the CLI writes its outputs.

    Raises:
        ValueError: bad input, with the CLI's message (file, key, value, reason, line).
        pounding.SolverError: an internal failure without a result.
    """
    path, array = record_arg(record)
    run = _core.simulate_run(
        record=path, array=array, csv_units=csv_units,
        record_dt=optional_float("record_dt", record_dt), scale=optional_float("scale", scale),
        dt=optional_float("dt", dt), duration=optional_float("duration", duration), law=law,
        **scenario_args(scenario, "simulate"),
    )
    res = SimulationResult(run)
    for w in res.warnings:
        warnings.warn(w, UserWarning, stacklevel=2)
    return res


def batch(
    scenario: Any = None,
    records: Sequence[Any] = (),
    scales: Sequence[float] = (1.0,),
    *,
    dt: Optional[float] = None,
    duration: Optional[float] = None,
    law: Optional[str] = None,
    csv_units: Optional[str] = None,
    record_dt: Optional[float] = None,
    threads: Optional[int] = None,
):
    """Run every record at every scale (an incremental dynamic analysis), in parallel.

    The batch of ``pounding simulate SCENARIO --records ... --scales ...``: run
    ``i = a * len(scales) + b`` uses record ``a`` as the only component along y scaled by
    ``scales[b]``. Records are paths (files, not directories) or ``(accelerations, dt[, name])``
    tuples. A record that cannot be read gives rows with ``status == "error"`` and the message
    in ``error`` (the other runs are done), as in the CLI.

    Returns:
        The rows of ``batch.csv`` (same columns, order and numbers): a ``pandas.DataFrame``, or a
        numpy structured array without pandas. Integer columns are int64, floats float64
        (empty cells NaN), ``unseated`` bool, text columns str.

    Raises:
        ValueError: bad input for the whole batch (no records, a non-finite scale, the
            scenario).
    """
    paths, arrays = [], []
    for i, r in enumerate(records):
        p, a = record_arg(r, i)
        paths.append(p)
        arrays.append(a)
    text = batch_csv_text(scenario, paths, arrays, scales, dt, duration, law, csv_units,
                          record_dt, threads)
    return csv_table(text)


def batch_csv_text(scenario, paths, arrays, scales, dt=None, duration=None, law=None,
                   csv_units=None, record_dt=None, threads=None) -> str:
    """The text of ``batch.csv`` for :func:`batch` (internal; byte for byte the CLI's)."""
    return _core.batch_run(
        records=paths, arrays=arrays, scales=[float(s) for s in scales], csv_units=csv_units,
        record_dt=optional_float("record_dt", record_dt), dt=optional_float("dt", dt),
        duration=optional_float("duration", duration), law=law, threads=threads,
        **scenario_args(scenario, "simulate"),
    )


def default_simulate_scenario() -> str:
    """The built-in default simulate scenario as commented TOML (``--print-default``)."""
    return _core.default_simulate_scenario()


__all__ = ["SimulationResult", "simulate", "batch", "default_simulate_scenario", "parse_csv"]
