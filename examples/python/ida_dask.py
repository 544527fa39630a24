"""Incremental dynamic analysis (records x scales) as Dask tasks, checked against
``pounding.batch``.

    pip install ./crates/pounding-py pandas "dask[distributed]"
    python examples/python/ida_dask.py                          # a LocalCluster on this machine
    python examples/python/ida_dask.py --scheduler tcp://host:8786   # any running scheduler
    python examples/python/ida_dask.py --records a.AT2 b.AT2 --scales 0.5,1,1.5,2 \\
        --scenario examples/opensees-1d.toml --out ida.csv

Every (record, scale) pair is one task: ``pounding.batch(scenario, [record], [scale])`` on a
worker (one run, one thread; the GIL is released while it runs). The rows are gathered into one
DataFrame in the order of ``batch.csv`` (run ``i = a * len(scales) + b``) and compared with
``pounding.batch(scenario, records, scales)`` computed locally: they must be equal row for row
(each run is deterministic, whatever the worker). Without ``--records`` three synthetic records
(decaying sine pulses, in g) are used. Record paths must be readable by every worker (a shared
file system on a cluster).
"""

from __future__ import annotations

import argparse
import sys

import numpy as np
import pandas as pd

import pounding


def synthetic_records(n: int = 3, dt: float = 0.01, seconds: float = 8.0):
    """``n`` deterministic ground motions ``(accelerations in g, dt, name)``."""
    t = np.arange(0.0, seconds, dt)
    out = []
    for k in range(n):
        f = 0.8 + 0.7 * k
        a = 0.35 * np.sin(2 * np.pi * f * t) * np.exp(-0.4 * t) * (1 - np.exp(-3 * t))
        out.append((a, dt, f"synthetic{k + 1}"))
    return out


def one_run(scenario, record, scale: float, index: int, duration=None) -> pd.DataFrame:
    """One IDA point on a worker: the batch row of ``record`` at ``scale``, with its global
    run index."""
    row = pounding.batch(scenario, [record], [scale], threads=1, duration=duration)
    row["index"] = np.int64(index)
    return row


def ida(client, scenario, records, scales, duration=None) -> pd.DataFrame:
    """Submits every (record, scale) run to the Dask ``client`` and gathers one DataFrame in the
    order of ``batch.csv``."""
    futures = []
    for a, rec in enumerate(records):
        for b, s in enumerate(scales):
            futures.append(client.submit(one_run, scenario, rec, s, a * len(scales) + b, duration,
                                         pure=False))
    rows = client.gather(futures)
    return pd.concat(rows, ignore_index=True)


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--scheduler", help="address of a running Dask scheduler (default: a LocalCluster)")
    ap.add_argument("--workers", type=int, default=2, help="LocalCluster workers (default 2)")
    ap.add_argument("--threads-only", action="store_true",
                    help="LocalCluster workers as threads of this process (no subprocesses)")
    ap.add_argument("--scenario", help="simulate scenario (TOML file); default: the built-in one")
    ap.add_argument("--records", nargs="*", help="record files (default: synthetic records)")
    ap.add_argument("--scales", default="0.5,1,1.5", help="scale factors, comma separated")
    ap.add_argument("--duration", type=float, help="run duration [s] (default: the record's)")
    ap.add_argument("--out", help="write the gathered rows to this CSV file")
    args = ap.parse_args(argv)
    from dask.distributed import Client, LocalCluster

    records = args.records or synthetic_records()
    scales = [float(s) for s in args.scales.split(",")]
    scenario = args.scenario
    if args.scheduler:
        client = Client(args.scheduler)
        cluster = None
    else:
        cluster = LocalCluster(n_workers=args.workers, threads_per_worker=1,
                               processes=not args.threads_only,
                               dashboard_address=None)
        client = Client(cluster)
    try:
        rows = ida(client, scenario, records, scales, args.duration)
    finally:
        client.close()
        if cluster is not None:
            cluster.close()
    local = pounding.batch(scenario, records, scales, duration=args.duration)
    same = rows.equals(local)
    print(f"{len(rows)} runs ({len(records)} records x {len(scales)} scales) on Dask; "
          f"equal to pounding.batch row for row: {same}")
    if args.out:
        rows.to_csv(args.out, index=False)
    if not same:
        diff = rows.compare(local) if rows.shape == local.shape else "different shapes"
        print(diff, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
