"""``pounding.fragility``: fragility curves of a bridge over a record set (``pounding fragility``)."""

from __future__ import annotations

import json
import os
import warnings
from dataclasses import dataclass
from typing import Any, Dict, List, Optional

from . import _core
from ._common import csv_table, scenario_args, thread_count


@dataclass(frozen=True)
class FragilityResult:
    """A fragility study (the data outputs of ``pounding fragility``).

    Attributes:
        runs: the rows of ``runs.csv`` (one per record and stripe: ``im_g`` [g],
            ``scale_factor``, ``status``, and per limit state whether it was exceeded and the
            ratio demand / capacity): a ``pandas.DataFrame``, or a numpy structured array
            without pandas.
        fits: the rows of ``fragility.csv`` (one per limit state: the lognormal median
            ``theta`` [g] and dispersion ``beta``, their bootstrap intervals, the counts).
        fragility: ``fragility.json`` as a dict (the fits, the IM, the period, the counts of
            records, runs and excluded runs, the empirical fractions per stripe).
        files: name → exact text of ``runs.csv``, ``fragility.csv`` and ``fragility.json``,
            and with a hazard curve ``maf.csv`` and ``hazard.csv`` (byte for byte the CLI's
            files).
        maf: with a hazard curve (the scenario's ``[hazard]`` or ``hazard``), the rows of
            ``maf.csv`` (per limit state the mean annual frequency ``maf_per_year``, its
            interval, the return period); else ``None``.
        im: the intensity measure, e.g. ``"Sa(1.23 s, 5 %)"`` or ``"PGA"``.
        period: how the fundamental period was found (``period_s = "model"``), else ``None``.
        excluded: the message about runs that failed or are not trustworthy (excluded from the
            fit; the CLI exits 1), or ``None`` when every run completed.
        maf_failure: the message when a fitted limit state's mean annual frequency is not a
            finite number (status ``maf_not_finite``: the hazard's rates overflow the integral;
            the CLI exits 1), else ``None``.
        warnings: the CLI's warnings (records with an implausible PGA, unreliable intervals,
            runs with warnings); also issued as ``UserWarning``.
    """

    runs: Any
    fits: Any
    fragility: Dict[str, Any]
    files: Dict[str, str]
    im: str
    period: Optional[str]
    excluded: Optional[str]
    warnings: List[str]
    maf: Any = None
    maf_failure: Optional[str] = None

    @property
    def ok(self) -> bool:
        """``True`` when every run completed and every fitted MAF is a number (the CLI's
        exit 0)."""
        return self.excluded is None and self.maf_failure is None


def fragility(
    scenario: Any,
    record_set: Any = None,
    *,
    hazard: Any = None,
    out: Any = None,
    threads: Optional[int] = None,
) -> FragilityResult:
    """Run a fragility study, as ``pounding fragility SCENARIO [--set MANIFEST] [--hazard FILE]
    [--out DIR]``.

    Every record (pair) of the set is run on the bridge at every stripe of ``[fragility]``
    (IM levels in g, or IDA scale factors), the limit states are evaluated on each run and a
    lognormal fragility curve (median ``theta`` [g], dispersion ``beta``) is fitted per limit
    state, with bootstrap intervals over records. The numbers are the CLI's, bit for bit, for
    any ``threads``.

    Args:
        scenario: a bridge scenario (``[[segment]]``s) with ``[fragility]`` and
            ``[[limit_state]]`` tables: a file path (``[fragility] records`` is relative to the
            file's directory, as in the CLI), a TOML string or a dict with the file's keys
            (``records`` relative to the current directory).
        record_set: the record-set manifest (``.toml``, or ``.csv`` with a header row) instead
            of ``[fragility] records`` (``--set``). Entries may name ``builtin:ELC180`` /
            ``builtin:ELC270``.
        hazard: a site hazard curve file (``--hazard``: ``.csv`` with the header ``im_g,rate``,
            or ``.toml`` with a ``[hazard]`` table) instead of the scenario's ``[hazard]``: the
            mean annual frequency of every limit state (``maf``, ``maf.csv``, ``hazard.csv``).
        out: a directory to write ``runs.csv``, ``fragility.csv`` and ``fragility.json`` (and
            with a hazard ``maf.csv``, ``hazard.csv``) into
            (``--out``; created if needed, each file atomically; the figure, report and
            ``timing.json`` of a previous study there are removed, as the CLI replaces them).
            ``None``: nothing is written.
        threads: worker threads (``--threads``; default: all cores).

    Returns:
        A :class:`FragilityResult`; runs that failed or are not trustworthy are rows with their
        status (``excluded`` says how many), as the CLI writes them.

    Raises:
        ValueError: bad input, with the CLI's message (file, key, line; the CLI's flags named as
            these arguments): a two-deck scenario, no record set, a bad manifest or limit state,
            a record whose IM is 0 or needs a scale factor beyond 100, an ``out`` in use.
        pounding.SolverError: the fit failed without a result.
        KeyboardInterrupt: Ctrl-C during the runs (raised at once).
    """
    if scenario is None:
        raise ValueError("fragility needs a scenario: a bridge with [fragility] and "
                         "[[limit_state]] tables")
    set_path = path_arg("record_set", record_set)
    hazard_path = path_arg("hazard", hazard)
    out_path = path_arg("out", out)
    d = _core.fragility_run(set=set_path, hazard=hazard_path, out=out_path,
                            threads=thread_count(threads), **scenario_args(scenario, "fragility"))
    msgs = list(d["record_warnings"]) + list(d["maf_warnings"]) + list(d["warnings"])
    for w in msgs:
        warnings.warn(w, UserWarning, stacklevel=2)
    for e in (d["excluded"], d["maf_failure"]):
        if e is not None:
            warnings.warn(e, UserWarning, stacklevel=2)
    files = dict(d["files"])
    return FragilityResult(
        runs=csv_table(files["runs.csv"]),
        fits=csv_table(files["fragility.csv"]),
        fragility=json.loads(files["fragility.json"]),
        files=files,
        im=d["im"],
        period=d["period"],
        excluded=d["excluded"],
        warnings=msgs,
        maf=csv_table(files["maf.csv"]) if "maf.csv" in files else None,
        maf_failure=d["maf_failure"],
    )


def path_arg(name: str, p: Any) -> Optional[str]:
    """``p`` as a path string (``None`` stays ``None``); ``TypeError`` for anything else."""
    if p is None:
        return None
    if isinstance(p, (str, os.PathLike)):
        return os.fspath(p)
    raise TypeError(f"{name} must be a path (str or os.PathLike) or None, not {type(p).__name__}")
