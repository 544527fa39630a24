"""``pounding.study``: the paper's parametric stick/slip study."""

from __future__ import annotations

import json
import warnings
from dataclasses import dataclass
from typing import Any, Dict, List, Optional

from . import _core
from ._common import csv_table, scenario_args, table, thread_count


@dataclass(frozen=True)
class StudyResult:
    """A computed study (the numeric outputs of ``pounding study``).

    Attributes:
        rows: one row per ``bounds.csv`` row, its columns in order: a ``pandas.DataFrame``, or a
            numpy structured array when pandas is absent. Floats are float64 (the same bits as
            the CSV's shortest round-trip text), ``first_contact``/``end_closes``/``lcp_agrees``
            are bool, ``case`` (and ``shape``) are str.
        summary: the rows of ``summary.csv`` (same container type).
        summary_json: ``summary.json`` as a dict.
        columns: the column names of ``bounds.csv`` in order.
        lcp_disagreements: cells where Lemke's LCP solution does not give the analytic mode
            (the CLI exits 1 when > 0).
        notes: the CLI's ``note:`` lines (e.g. deprecated keys).
        scenario_text: the scenario's TOML text.
    """

    rows: Any
    summary: Any
    summary_json: Dict[str, Any]
    columns: List[str]
    lcp_disagreements: int
    notes: List[str]
    scenario_text: str


def study(scenario: Any = None, *, threads: Optional[int] = None) -> StudyResult:
    """Run the parametric study of ``pounding study`` (no figures, no files).

    Args:
        scenario: ``None`` (the built-in default, the paper's study), a path to a scenario file
            (TOML), a TOML string, or a dict with the file's keys.
        threads: worker threads (default: all cores); the rows do not depend on it.

    Returns:
        A :class:`StudyResult`; ``rows`` holds exactly the numbers of ``bounds.csv``.

    Raises:
        ValueError: bad scenario (the CLI's message: key, value, reason, line).
        pounding.SolverError: an internal failure without a result.
    """
    d = _core.study(threads=thread_count(threads), **scenario_args(scenario, "study"))
    for n in d["notes"]:
        warnings.warn(n, UserWarning, stacklevel=2)
    columns = d["header"].split(",")
    return StudyResult(
        rows=table(columns, d["columns"]),
        summary=csv_table(d["summary_csv"]),
        summary_json=json.loads(d["summary_json"]),
        columns=columns,
        lcp_disagreements=d["lcp_disagreements"],
        notes=list(d["notes"]),
        scenario_text=d["scenario_text"],
    )


def default_study_scenario() -> str:
    """The built-in default study scenario as commented TOML (``pounding study --print-default``)."""
    return _core.default_study_scenario()
