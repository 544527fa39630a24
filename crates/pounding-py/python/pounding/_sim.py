"""``pounding.simulate`` and ``pounding.batch``: seismic time histories with pounding."""

from __future__ import annotations

import decimal
import json
import os
import warnings
from typing import Any, Dict, List, Optional, Sequence, Tuple

import numpy as np

from . import _core
from ._common import (csv_table, optional_float, parse_csv, record_arg, scenario_args,
                      real_number, table, thread_count)
from ._stored import _StoredRun, _same


def _restore_columns(summary_json, status, warnings_, history, impacts, tables=(),
                     accuracy_json=None) -> "SimulationResult":
    """A pickled :class:`SimulationResult` again, from its columns."""
    return SimulationResult(_StoredRun(summary_json, status, warnings_, history, impacts, tables,
                                       accuracy_json))


def _restore(summary_json, status, warnings_, history_csv, impacts_csv,
             tables=(), accuracy_json=None) -> "SimulationResult":
    """A result pickled by an earlier version (its texts), rebuilt by parsing them once."""
    names, cols = parse_csv(history_csv)
    data = np.empty((0, len(names)))
    if names and len(cols[names[0]]):
        data = np.column_stack([cols[n].astype(np.float64) for n in names])
    inames, icols = parse_csv(impacts_csv)
    impacts = [(n, icols[n].tolist() if icols[n].dtype == object else icols[n]) for n in inames]
    tables = [(n, list(h), np.array(a, dtype=np.float64)) for n, h, a in tables]
    return _restore_columns(summary_json, status, warnings_, (names, data), impacts, tables,
                            accuracy_json)


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
        self._history_data: Optional[Tuple[List[str], np.ndarray]] = None
        self._tables: Optional[Dict[str, Dict[str, np.ndarray]]] = None
        acc = run.accuracy_json()
        #: ``accuracy.json`` as a dict (``error_estimate`` / ``tol``), else ``None``: the step of
        #: the answer, whether ``tol`` was met, and per quantity its three values, estimated
        #: error, relative error, observed order and trust word.
        self.accuracy: Optional[Dict[str, Any]] = None if acc is None else json.loads(acc)

    @property
    def ok(self) -> bool:
        """``True`` when ``status == "Completed"`` (the CLI's exit 0)."""
        return self.status == "Completed"

    @property
    def history(self) -> Dict[str, np.ndarray]:
        """The time histories of ``history.csv``: column name → float64 array of shape
        ``(steps stored,)`` (``t_s``, ground accelerations, displacements and rotations in
        degrees, velocities, gaps, slip, energies, contact forces...). Built on first access;
        the arrays are read-only views (``.copy()`` one to modify it)."""
        if self._history is None:
            names, data = self._history_columns()
            self._history = {n: data[:, i] for i, n in enumerate(names)}
        return self._history

    def _history_columns(self) -> Tuple[List[str], np.ndarray]:
        """``(column names, read-only float64 array (rows, columns))`` of the history, made once."""
        if self._history_data is None:
            names, data = self._run.history()
            data.flags.writeable = False  # shared by every access: read-only views
            self._history_data = (names, data)
        return self._history_data

    @property
    def tables(self) -> Dict[str, Dict[str, np.ndarray]]:
        """The run's other tables, as the CLI's ``<name>.csv``: ``"bearings"`` (each bearing's
        deformation and the force it exerts on its segment), ``"restrainers"`` (each
        restrainer's elongation and tension), ``"joint_slip"`` (each joint's slip), and for a
        bridge that has them ``"piers"`` (each cap's displacement and its column's force),
        ``"backwalls"`` (each backwall's displacement, backfill and pile forces), ``"shear_keys"``
        (each abutment's deck-end transverse displacement and key force), and last
        ``"segment_forces"`` (every force on each segment by member kind — bearings, dashpots,
        restrainers, shear keys, contact — ``fx``, ``fy`` [N], ``mz`` [N m] about its centroid:
        the mean over the steps since the previous row, as the integrator applies it; their sum
        is the segment's mass times its absolute acceleration); name →
        column name → read-only float64 array of shape ``(steps stored,)``. The values come
        from the solver as they are (no text in between)."""
        if self._tables is None:
            out: Dict[str, Dict[str, np.ndarray]] = {}
            for name, heads, data in self._run.tables():
                data.flags.writeable = False
                out[name] = {h: data[:, i] for i, h in enumerate(heads)}
            self._tables = out
        return self._tables

    @property
    def bearings(self) -> Dict[str, np.ndarray]:
        """``tables["bearings"]``: ``t_s`` and, per bearing, ``segment<i>_bearing<j>_ux_m``,
        ``_uy_m`` (deformation) and ``_fx_N``, ``_fy_N`` (force on the segment)."""
        return self.tables["bearings"]

    @property
    def restrainers(self) -> Dict[str, np.ndarray]:
        """``tables["restrainers"]``: ``t_s`` and, per restrainer,
        ``joint<k>_restrainer<r>_elongation_m`` and ``_force_N``."""
        return self.tables["restrainers"]

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
        without pandas): one row per impacting contact, the CSV's columns in order. ``impact`` is
        int64, the names (``site``, ``contact``, ``mode``) str objects, every other column
        float64 (``nan`` where a value does not apply). The columns come from the solver as they
        are (no text in between); each access builds a new table."""
        cols = self._run.impacts()
        return table([h for h, _ in cols],
                     {h: np.array(v, dtype=object) if isinstance(v, list) else v
                      for h, v in cols})

    def history_csv(self) -> str:
        """The text of ``history.csv``, byte for byte the CLI's."""
        return self._run.history_csv()

    def impacts_csv(self) -> str:
        """The text of ``impacts.csv``, byte for byte the CLI's."""
        return self._run.impacts_csv()

    def summary_json(self) -> str:
        """The text of ``summary.json``, byte for byte the CLI's."""
        return self._run.summary_json()

    def __reduce__(self):
        """Pickles (and deep-copies) as the run's columns (numpy arrays; text only for the
        summary and the names), so a result can be a Dask task's value: the copy answers every
        attribute with the same values, its arrays the same bits, its ``history_csv()`` and
        ``impacts_csv()`` the same bytes, without parsing any text."""
        r = self._run
        return (_restore_columns, (r.summary_json(), self.status, list(self.warnings),
                                   self._history_columns(), r.impacts(), r.tables(),
                                   r.accuracy_json()))

    def __eq__(self, other: object) -> bool:
        """Equal when the status, warnings, summary, the columns of the history, the impacts and
        the tables are equal bit for bit (so are then the output texts)."""
        if not isinstance(other, SimulationResult):
            return NotImplemented
        return _same(self.__reduce__()[1], other.__reduce__()[1])

    __hash__ = None  # type: ignore[assignment]

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
    error_estimate: bool = False,
    tol: Any = None,
    max_refinements: Optional[int] = None,
    projection: bool = False,
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
        error_estimate: also run at dt/2 and dt/4 and estimate every summary quantity's
            discretisation error (``--error-estimate``): :attr:`SimulationResult.accuracy`.
        tol: halve dt until every governing quantity's estimated relative error is at most
            ``tol`` (``--tol``): ``"1%"``, ``"0.01"`` or ``0.01``; the result is the run at the
            step that met it (``accuracy["met"]`` says whether one did).
        max_refinements: with ``tol``, the most halvings of dt (default 3, at most 8).
        projection: project every rigid-law gap back to >= 0 at the end of each step
            (``--projection``, ``[time] projection``): the summary then has ``max_overlap_m``,
            ``energy_J["projection"]`` and ``projection``.

    Returns:
        A :class:`SimulationResult`; a run ending ``Diverged`` (or another untrustworthy status)
        is returned with that status, as the CLI writes its outputs.

    Raises:
        ValueError: bad input, with the CLI's message (file, key, value, reason, line); a
            missing scenario file; ``record_dt`` with an array record.
        TypeError: a complex, bool or masked record array, a bool ``scale``/``dt``.
        pounding.SolverError: an internal failure without a result.
        KeyboardInterrupt: Ctrl-C during the run (raised at once; the abandoned run finishes
            on a background thread and is discarded).
    """
    path, array = record_arg(record)
    _no_record_dt_for_arrays(record_dt, [array])
    if isinstance(tol, bool) or not (tol is None or isinstance(tol, (str, int, float))):
        raise TypeError(f"tol must be a number or a string such as '1%', not {type(tol).__name__}")
    if isinstance(error_estimate, bool) is False:
        raise TypeError("error_estimate must be True or False")
    if not isinstance(projection, bool):
        raise TypeError("projection must be True or False")
    if max_refinements is not None and (
        isinstance(max_refinements, bool) or not isinstance(max_refinements, int)
    ):
        raise TypeError("max_refinements must be an int")
    if max_refinements is not None and max_refinements < 0:
        raise ValueError(f"max_refinements = {max_refinements}: must be 0 or more")
    run = _core.simulate_run(
        error_estimate=error_estimate,
        tol=None if tol is None else (tol if isinstance(tol, str) else repr(float(tol))),
        max_refinements=max_refinements, projection=projection,
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
    errors: str = "raise",
    record_set: Any = None,
):
    """Run every record at every scale (an incremental dynamic analysis), in parallel.

    The batch of ``pounding simulate SCENARIO --records ... --scales ...``: run
    ``i = a * len(scales) + b`` uses record ``a`` as the only component along y scaled by
    ``scales[b]``. ``records`` is a list of paths (files, not directories) or
    ``(accelerations, dt[, name])`` tuples; a single path (str or ``os.PathLike``) or a single
    tuple is one record. ``scales`` is a list of numbers (a single number is one scale); an
    empty ``records`` or ``scales`` raises ``ValueError``.

    Horizontal pairs: ``record_set`` is the path of a record-set manifest (``.toml`` with
    ``[[record]]`` tables or ``[synth]``, or ``.csv``), the batch of ``pounding simulate
    SCENARIO --set MANIFEST --scales ...`` (give it instead of ``records``): each entry at each
    scale, a pair's ``x`` record along y with ``scale_y`` and its ``y`` record along x with
    ``scale_x`` (``incidence_deg`` applies; each scale multiplies both factors), a single record
    as with ``records``. The rows then also carry ``record_y``, ``record_x`` and the entries'
    metadata as ``meta_<name>`` after ``record`` (the entry's id); the bytes are the CLI's.
    A manifest that cannot be read (a missing file, an unknown key) raises ``ValueError`` naming
    the manifest, the key and its line.

    A run that fails (a record that cannot
    be read, an input error of that run) raises ``ValueError`` naming the record and the reason
    (after the other runs are done); with ``errors="rows"`` it is a row with
    ``status == "error"`` and the message in ``error`` instead, as in the CLI's ``batch.csv``.

    Returns:
        The rows of ``batch.csv`` (same columns, order and numbers): a ``pandas.DataFrame``, or a
        numpy structured array without pandas. Integer columns are int64, floats float64
        (empty cells NaN), ``unseated`` bool, text columns str. A failed run's row
        (``errors="rows"``, ``status == "error"``) keeps these types: its counts (``impacts``,
        ``steps``, ``lcp_failures``, …) are ``-1`` (``pounding._common.ERROR_COUNT``), its
        ``unseated`` ``False``, its numbers NaN; select ``rows[rows["status"] != "error"]``
        before aggregating.

    Raises:
        ValueError: bad input for the whole batch (no records, no scales, a non-finite scale,
            the scenario, ``record_dt`` with an array record or with ``record_set``, both
            ``records`` and ``record_set``, a bad manifest, an ``errors`` other than
            ``"raise"``/``"rows"``); a failed run unless ``errors="rows"``.
        TypeError: a record that is neither a path nor a tuple, a complex/bool/masked array, a
            ``threads`` that is not an int.
        KeyboardInterrupt: Ctrl-C during the batch (raised at once).
    """
    if isinstance(records, (str, bytes, os.PathLike)):
        records = [records]  # one record, not its characters
    elif isinstance(records, tuple) and len(records) in (2, 3) and isinstance(
        records[0], np.ndarray
    ):
        records = [records]  # one (accelerations, dt[, name]) record
    if isinstance(scales, (str, bytes)):
        raise TypeError(f"scales must be a number or a list of numbers, not "
                        f"{type(scales).__name__} {scales!r}")
    if isinstance(scales, np.ndarray) and scales.ndim == 0:
        scales = scales.item()  # a 0-d array is one scale
    if isinstance(scales, (int, float, np.integer, np.floating, decimal.Decimal)) and not isinstance(
        scales, bool
    ):
        scales = [scales]
    scales = list(scales)  # empty: ValueError from the library, as for records=[]
    paths, arrays = [], []
    for i, r in enumerate(records):
        p, a = record_arg(r, i)
        paths.append(p)
        arrays.append(a)
    _no_record_dt_for_arrays(record_dt, arrays)
    if errors not in ("raise", "rows"):
        raise ValueError(f'errors must be "raise" or "rows", not {errors!r}')
    if record_set is not None and not isinstance(record_set, (str, os.PathLike)):
        raise TypeError(f"record_set must be the path of a manifest (str or os.PathLike), not "
                        f"{type(record_set).__name__}")
    text = batch_csv_text(scenario, paths, arrays, scales, dt, duration, law, csv_units,
                          record_dt, threads,
                          None if record_set is None else os.fspath(record_set))
    rows = csv_table(text)
    if errors == "raise":
        failed = [i for i, st in enumerate(rows["status"]) if st == "error"]
        if failed:
            i = failed[0]
            raise ValueError(f"run {i} (record {rows['record'][i]}, scale "
                             f"{float(rows['scale'][i])!r}) failed: {rows['error'][i]}"
                             + (f" ({len(failed)} failed runs in all; errors=\"rows\" returns "
                                f"them as rows)" if len(failed) > 1 else ""))
    return rows


def _no_record_dt_for_arrays(record_dt, arrays) -> None:
    """``record_dt`` reads one-column record files; an array record carries its own dt, so the
    pair is refused as the CLI refuses ``--record-dt`` for a record with its own times."""
    if record_dt is not None and any(a is not None for a in arrays):
        raise ValueError(
            f"a sample interval of {record_dt!r} s is given by record_dt but the record is an "
            "array (accelerations, dt) with its own dt: it does not apply; remove it"
        )


def batch_csv_text(scenario, paths, arrays, scales, dt=None, duration=None, law=None,
                   csv_units=None, record_dt=None, threads=None, record_set=None) -> str:
    """The text of ``batch.csv`` for :func:`batch` (internal; byte for byte the CLI's)."""
    return _core.batch_run(
        records=paths, arrays=arrays, scales=[real_number("scale", s) for s in scales], csv_units=csv_units,
        record_dt=optional_float("record_dt", record_dt), dt=optional_float("dt", dt),
        duration=optional_float("duration", duration), law=law,
        threads=thread_count(threads), record_set=record_set,
        **scenario_args(scenario, "simulate"),
    )


def default_simulate_scenario() -> str:
    """The built-in default simulate scenario as commented TOML (``--print-default``)."""
    return _core.default_simulate_scenario()


__all__ = ["SimulationResult", "simulate", "batch", "default_simulate_scenario", "parse_csv"]


def check(scenario: Any = None) -> Dict[str, Any]:
    """The code check of a scenario's seats and joint gaps, as ``pounding check``.

    Args:
        scenario: a scenario file path, a TOML string or a dict with the file's keys (a bridge
            of ``[[segment]]``s or a two-deck file), its inputs in ``[code_check]``.

    Returns:
        A dict: ``"report"`` (``json.load(check.json)``), ``"ends"`` and ``"gaps"`` (the rows of
        ``check.csv`` and ``check_gaps.csv`` as DataFrames, or lists of dicts without pandas),
        ``"text"`` (the table the CLI prints) and ``"files"`` (each file's exact text).

    Raises:
        ValueError: bad input, with the CLI's message (file, key, line).
    """
    j, ends, gaps, text = _core.check_run(**scenario_args(scenario, "simulate"))
    return {
        "report": json.loads(j),
        "ends": csv_table(ends),
        "gaps": csv_table(gaps),
        "text": text,
        "files": {"check.json": j, "check.csv": ends, "check_gaps.csv": gaps},
    }
