"""``pounding.campaign``: campaigns of many runs (``pounding campaign``) on this machine or on a
Dask cluster, stored as Parquet parts that a killed campaign resumes from.

    import pounding.campaign
    from dask.distributed import Client, LocalCluster

    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True) as cluster, \\
            Client(cluster) as client:
        result = pounding.campaign.run("campaign.toml", client, out="store")
    runs = pounding.campaign.read(result.path)          # a pandas DataFrame

Each Dask task runs a batch of whole parts (``runs_per_part`` runs each) in Rust without the
GIL and writes them into the store itself (a directory every worker can write: a shared file
system on a cluster); the scheduler sees a few tasks per worker, not one per run. A failed task
is retried (``retries``); parts already stored are never run again, also when ``run`` is called
again after an interruption. The stored bytes are those of ``pounding campaign run`` on any
number of threads or shards.
"""

from __future__ import annotations

import functools
import os
from dataclasses import dataclass
from typing import Any, Dict, List, Optional

from . import _core

__all__ = ["CampaignResult", "run", "read", "merge", "load"]


@dataclass(frozen=True)
class CampaignResult:
    """A finished campaign.

    Attributes:
        path: the merged ``runs.parquet`` (one row per run, sorted by ``run``).
        runs: the number of runs.
        statuses: status -> number of runs (``Completed``, another run status, ``error``).
        tasks: the Dask tasks submitted (0 without a client or when nothing was left to run).
    """

    path: str
    runs: int
    statuses: Dict[str, int]
    tasks: int

    @property
    def ok(self) -> bool:
        """``True`` when every run completed (the CLI's exit 0)."""
        return set(self.statuses) <= {"Completed"}


@functools.lru_cache(maxsize=4)
def _load(spec: str, stamp: Any) -> "_core.Campaign":
    return _core.Campaign(spec)


def load(spec: str) -> "_core.Campaign":
    """The campaign of ``spec``, read and planned once per process while the spec file is
    unchanged (workers reuse it; an edited spec is read again — its scenario and records are
    checked by the store's fingerprint)."""
    spec = os.fspath(spec)
    try:
        st = os.stat(spec)
        stamp = (st.st_mtime_ns, st.st_size, st.st_ino)
    except OSError:
        stamp = None  # the reader reports the missing file
    return _load(spec, stamp)


def _run_batch(spec: str, out: str, parts: List[int], threads: int) -> int:
    """A Dask task: runs ``parts`` of the campaign ``spec`` into the store ``out``."""
    return load(spec).run_parts(out, list(parts), threads)


def _batches(pending: List[int], workers: int, parts_per_task: Optional[int]) -> List[List[int]]:
    """Whole parts per task: ``parts_per_task``, else about 4 tasks per worker (load balance)
    and never more than 64 parts per task (bounded loss when a task fails)."""
    if not pending:
        return []
    k = parts_per_task or max(1, min(64, len(pending) // (4 * max(1, workers))))
    return [pending[i:i + k] for i in range(0, len(pending), k)]


def run(spec, client=None, out="out/campaign", *, parts_per_task: Optional[int] = None,
        retries: int = 2, threads: Optional[int] = None) -> CampaignResult:
    """Runs the campaign ``spec`` (a TOML file) into the store ``out`` and merges it.

    Args:
        spec: the campaign spec (paths in it relative to its directory; every worker must be
            able to read it and its files).
        client: a ``dask.distributed.Client``; ``None`` runs on this process's threads.
        out: the store directory (created; resumed when it holds parts of the same campaign).
        parts_per_task: parts per Dask task (default: about 4 tasks per worker, at most 64).
        retries: how many times Dask retries a failed task.
        threads: threads per task (default 1 with a client: Dask runs a task per worker
            thread) or of the local run (default: all cores).

    Returns:
        a :class:`CampaignResult`; the rows are in ``result.path`` (:func:`read`).
    """
    spec = os.path.abspath(os.fspath(spec))
    out = os.path.abspath(os.fspath(out))
    if threads is not None and (not isinstance(threads, int) or threads < 1):
        raise ValueError(f"threads = {threads!r}: give a whole number >= 1 (or None)")
    # read afresh: an edited scenario or record must not run from a cached campaign (workers
    # use the cache; a stale one is refused by the store's fingerprint)
    c = _core.Campaign(spec)
    # the store is locked for the whole run, as by `pounding campaign run`: a second run into it
    # (another process, the CLI, or this process) is refused; the workers write parts unlocked
    with _core.StoreLock(out) as lock:
        pending = c.prepare(out, lock)
        tasks = 0
        if client is None:
            if pending:
                c.run_parts(out, pending, threads)
        else:
            workers = len(client.scheduler_info().get("workers", {})) or 1
            batches = _batches(pending, workers, parts_per_task)
            futures = [
                client.submit(_run_batch, spec, out, b, threads or 1, retries=retries,
                              pure=False, key=f"pounding-campaign-{c.fingerprint}-{b[0]}")
                for b in batches
            ]
            client.gather(futures)
            tasks = len(futures)
        return _merge([out], out, tasks)


def merge(stores, out, *, tasks: int = 0) -> CampaignResult:
    """Merges the parts of ``stores`` (e.g. the stores of ``pounding campaign run --shard``)
    into ``out/runs.parquet``; refused when a part is missing or two stores disagree, and while
    another run holds ``out``."""
    with _core.StoreLock(os.fspath(out)):
        return _merge(stores, out, tasks)


def _merge(stores, out, tasks: int) -> CampaignResult:
    m = _core.campaign_merge([os.fspath(s) for s in stores], os.fspath(out))
    return CampaignResult(path=m["path"], runs=m["rows"], statuses=dict(m["statuses"]),
                          tasks=tasks)


def read(path) -> Any:
    """The stored runs as a ``pandas.DataFrame`` (``pandas.read_parquet``; needs pyarrow):
    ``path`` is a ``runs.parquet`` or a store directory (its merged file, else its parts)."""
    import pandas as pd

    path = os.fspath(path)
    if os.path.isdir(path):
        merged = os.path.join(path, "runs.parquet")
        path = merged if os.path.exists(merged) else os.path.join(path, "parts")
    df = pd.read_parquet(path)
    return df.sort_values("run", kind="stable").reset_index(drop=True)
