"""``pounding.design``: retrofit variants of one bridge compared on common records
(``pounding design``)."""

from __future__ import annotations

import json
import os
import warnings
from dataclasses import dataclass
from typing import Any, Dict, List, Optional

from . import _core
from ._assess import path_arg
from ._common import csv_table, thread_count


@dataclass(frozen=True)
class DesignResult:
    """A retrofit comparison (the data outputs of ``pounding design``).

    Attributes:
        variants: the rows of ``variants.csv`` (per member and limit state: ``status``, the fit,
            ``stat`` — ``maf`` with a hazard, else ``theta`` — its ``value`` and interval, the
            ``diff`` to the as-built bridge with its paired and unpaired intervals).
        summary: ``variants.json`` as a dict (members with descriptions and overrides, the
            recommendation).
        members: the members' names, the as-built bridge first.
        search: the rows of ``search.csv`` (every value run by the ``[search]``), or ``None``
            without a search.
        search_verdict: the search's answer in words (``None`` without a search).
        search_found: the value found by the search (``None``: no answer, or no search).
        recommendation: the CLI's recommendation sentences.
        files: relative path → exact text of every data file the CLI writes: ``variants.csv``,
            ``variants.json``, ``search.csv`` and ``variants/<name>/`` ``runs.csv``,
            ``fragility.csv``, ``fragility.json`` (with a hazard ``maf.csv``, ``hazard.csv``).
        im: the intensity measure shared by every member.
        excluded: the message about runs that failed or are not trustworthy (excluded from the
            fits; the CLI exits 1), or ``None``.
        maf_failure: the message when a fitted MAF is not a finite number (status
            ``maf_not_finite``; the CLI exits 1), or ``None``.
    """

    variants: Any
    summary: Dict[str, Any]
    members: List[str]
    search: Any
    search_verdict: Optional[str]
    search_found: Optional[float]
    recommendation: List[str]
    files: Dict[str, str]
    im: str
    excluded: Optional[str]
    maf_failure: Optional[str]

    @property
    def ok(self) -> bool:
        """``True`` when every run completed and every fitted MAF is a number (the CLI's
        exit 0)."""
        return self.excluded is None and self.maf_failure is None

    def member_files(self, name: str) -> Dict[str, str]:
        """The files of member ``name`` (``variants/<name>/``): file name → text."""
        prefix = f"variants/{name}/"
        return {k[len(prefix):]: v for k, v in self.files.items() if k.startswith(prefix)}


def design(
    spec: Any,
    *,
    record_set: Any = None,
    hazard: Any = None,
    out: Any = None,
    threads: Optional[int] = None,
) -> DesignResult:
    """Compare retrofit variants of a bridge, as ``pounding design DESIGN.toml [--set M]
    [--hazard FILE] [--out DIR]``.

    Every variant of the design file (overrides of the as-built scenario's keys) runs on the
    same records, stripes and scale factors; each is fitted, and compared with the as-built
    bridge by its mean annual frequency (with a hazard curve) or median, with the paired
    bootstrap interval of the change; a ``[search]`` table searches one parameter for a target
    MAF. The numbers and files are the CLI's, byte for byte, for any ``threads``.

    Args:
        spec: the design file (a path; its ``scenario`` is relative to it).
        record_set: a record-set manifest instead of the scenario's (``--set``).
        hazard: a site hazard curve file instead of the design's or scenario's (``--hazard``).
        out: a directory to write the data files into (``--out``): ``variants.csv``,
            ``variants.json``, ``search.csv`` and each member's files in ``variants/<name>/``;
            an earlier run's files there are replaced and its variant folders removed (a folder
            holding other files is refused). ``design.png``, ``hazard.png``, ``report.html``
            and ``timing.json`` are the CLI's only (removed from ``out``, as the CLI replaces
            them). ``None``: nothing is written.
        threads: worker threads (``--threads``; default: all cores).

    Returns:
        A :class:`DesignResult`.

    Raises:
        ValueError: bad input, with the CLI's message (the design file, the variant, the key and
            its line), or an ``out`` in use.
        pounding.SolverError: a fit failed without a result.
        KeyboardInterrupt: Ctrl-C during the runs.
    """
    if not isinstance(spec, (str, os.PathLike)):
        raise TypeError(f"spec must be a design file path, not {type(spec).__name__}")
    p = os.fspath(spec)
    if not os.path.isfile(p):
        raise ValueError(f"cannot read design file {p}: no such file")
    d = _core.design_run(p, set=path_arg("record_set", record_set),
                         hazard=path_arg("hazard", hazard), out=path_arg("out", out),
                         threads=thread_count(threads))
    for e in (d["excluded"], d["maf_failure"]):
        if e is not None:
            warnings.warn(e, UserWarning, stacklevel=2)
    files = dict(d["files"])
    return DesignResult(
        variants=csv_table(files["variants.csv"]),
        summary=json.loads(files["variants.json"]),
        members=list(d["members"]),
        search=csv_table(files["search.csv"]) if "search.csv" in files else None,
        search_verdict=d["search_verdict"],
        search_found=d["search_found"],
        recommendation=list(d["recommendation"]),
        files=files,
        im=d["im"],
        excluded=d["excluded"],
        maf_failure=d["maf_failure"],
    )
