"""``pounding.compare``: one scenario under several contact laws, side by side."""

from __future__ import annotations

import warnings
from typing import Any, Dict, List, Optional, Sequence

from . import _core
from ._common import csv_table, optional_float, scenario_args

#: The laws ``compare`` runs by default (as the CLI's ``--laws``).
DEFAULT_LAWS = ("rigid", "kelvin", "hertz", "hertz-damp", "bilinear", "jankowski")


class ComparisonResult:
    """The comparison of one scenario under several contact laws (``pounding compare``'s
    numbers, without files or figures).

    Attributes:
        table: the rows of ``compare.csv`` (a ``pandas.DataFrame``, or a numpy structured array
            without pandas), one per law, in the order given: the same columns and numbers as
            the CLI's file. The compliance laws' computed force is ``peak_contact_force_N``
            (bridge: ``_n``); the rigid law's force is an *estimate* from the impulse in
            ``peak_force_estimate_N`` with the contact duration it assumes in
            ``contact_time_estimate_s``.
        sites: a bridge's ``compare_sites.csv`` rows (one per law and joint/abutment);
            ``None`` for the two-deck model.
        skipped: law → why it cannot run on this bridge (laws a bridge refuses; the two-deck
            model runs every law or raises).
        warnings: law → the warnings of its run (also issued as ``UserWarning``), for every law
            that ran.
        wall_time_s: law → wall time of its run in seconds.
        agreement: sentences answering "do the laws agree?" (pounding, the spread of peak force,
            closing, penetration, impacts and governing seat ratio between the laws).
        law_summaries: law → one sentence (pounded or not, peak force, closing, penetration,
            governing seat; or why it was skipped).
        text: the table the CLI prints on stdout.
        files: ``{"compare.csv": text}`` (and ``"compare_sites.csv"`` for a bridge), byte for
            byte the CLI's.
    """

    def __init__(self, out) -> None:
        csv, sites, text, skipped, warns, secs, (overall, per_law) = out
        self.files: Dict[str, str] = {"compare.csv": csv}
        if sites is not None:
            self.files["compare_sites.csv"] = sites
        self.table = csv_table(csv)
        self.sites = csv_table(sites) if sites is not None else None
        self.text: str = text
        self.skipped: Dict[str, str] = dict(skipped)
        self.warnings: Dict[str, List[str]] = {law: list(w) for law, w in warns}
        self.wall_time_s: Dict[str, float] = dict(secs)
        self.agreement: List[str] = list(overall)
        self.law_summaries: Dict[str, str] = dict(per_law)

    @property
    def ok(self) -> bool:
        """``True`` when every law that ran ended ``Completed`` (the CLI's exit 0)."""
        return all(s in ("Completed", "skipped") for s in self.table["status"])

    def __repr__(self) -> str:
        return (f"<ComparisonResult laws={list(self.table['law'])} "
                f"skipped={list(self.skipped)}>")


def compare(
    scenario: Any = None,
    laws: Sequence[str] = DEFAULT_LAWS,
    dt: Optional[float] = None,
    scale: Optional[float] = None,
    duration: Optional[float] = None,
) -> ComparisonResult:
    """Run one scenario once per contact law, as ``pounding compare`` (no files, no figures).

    Args:
        scenario: ``None`` (built-in default), a scenario file path, a TOML string or a dict
            with the file's keys; two decks or a bridge of ``[[segment]]``s (each law then
            replaces the law at every joint and abutment).
        laws: the laws to run (``--laws``): ``"rigid"`` or any law of ``[contact] law``, a list
            or one comma-separated string.
        dt, scale, duration: the CLI's ``--dt``, ``--scale``, ``--duration``, for every law.

    Returns:
        A :class:`ComparisonResult`; ``result.table`` holds the rows of ``compare.csv``. A run
        ending ``Diverged`` (or another untrustworthy status) is a row with that status, as the
        CLI writes it (``result.ok`` is then ``False``).

    Raises:
        ValueError: bad input, with the CLI's message: an unknown or repeated law, an empty
            list, a bad ``dt``/``scale``/``duration``, a scenario error, a law the two-deck
            model refuses, a bridge that refuses every law.
        TypeError: a bool ``dt``/``scale``/``duration``, ``laws`` that are not strings.
        KeyboardInterrupt: Ctrl-C during the runs.
    """
    if isinstance(laws, str):
        laws = laws.split(",")
    laws = list(laws)
    for law in laws:
        if not isinstance(law, str):
            raise TypeError(f"laws must be strings, not {type(law).__name__} {law!r}")
    out = _core.compare_run(
        laws=laws, dt=optional_float("dt", dt), scale=optional_float("scale", scale),
        duration=optional_float("duration", duration), **scenario_args(scenario, "simulate"),
    )
    res = ComparisonResult(out)
    for law, ws in res.warnings.items():
        for w in ws:
            warnings.warn(f"law {law}: {w}", UserWarning, stacklevel=2)
    return res
