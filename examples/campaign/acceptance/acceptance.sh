#!/usr/bin/env bash
# The campaigns guide's acceptance run (docs/guide/campaign.md, "The 10,000-run check"): the
# campaign of campaign.toml on 1 thread, on 2 threads, as 4 shards merged, and on a Dask
# LocalCluster of 2 worker processes; then compares the stored bytes of the four runs.parquet.
#   bash examples/campaign/acceptance/acceptance.sh OUT_DIR
# POUNDING_BIN (default: pounding on PATH) is the CLI; PYTHON (default: python3) a Python with
# the pounding package, pyarrow and dask[distributed] (without them the Dask run is skipped, said).
# Each run's wall time and peak resident memory are printed (GNU time). A campaign whose runs
# partly failed exits 1 (their status is stored): that counts as done here. The stores are kept:
# run again, every stage resumes (nothing is run twice); remove OUT_DIR for fresh timings.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
out=${1:?usage: acceptance.sh OUT_DIR}
bin=${POUNDING_BIN:-pounding}
py=${PYTHON:-python3}
spec="$here/campaign.toml"
mkdir -p "$out"
# exit 0 (every run completed) or 1 (some runs failed, stored with their status) is done
timed() {
  local name=$1 rc=0; shift
  /usr/bin/time -f "$name: %e s wall, %M KB peak" "$@" || rc=$?
  [ "$rc" -le 1 ] || { echo "$name: exit $rc" >&2; exit "$rc"; }
}
load() { echo "load: $(cut -d' ' -f1-3 /proc/loadavg)"; }

load
timed threads-1 "$bin" campaign run "$spec" --out "$out/threads-1" --threads 1 > "$out/threads-1.log"
load
timed threads-2 "$bin" campaign run "$spec" --out "$out/threads-2" --threads 2 > "$out/threads-2.log"
load
start=$(date +%s.%N)
pids=()
for k in 1 2 3 4; do
  "$bin" campaign run "$spec" --out "$out/shards/$k" --shard "$k/4" --threads 1 \
    > "$out/shard-$k.log" 2>&1 &
  pids+=($!)
done
for p in "${pids[@]}"; do
  rc=0; wait "$p" || rc=$?
  [ "$rc" -le 1 ] || { echo "a shard exited $rc" >&2; exit "$rc"; }
done
echo "shards (4 processes at once): $(echo "$(date +%s.%N) - $start" | bc) s wall"
timed merge "$bin" campaign merge "$out"/shards/1 "$out"/shards/2 "$out"/shards/3 "$out"/shards/4 \
  --out "$out/shards-merged" > "$out/merge.log"
stores=(threads-1 threads-2 shards-merged)
if "$py" -c 'import pounding.campaign, pyarrow, dask.distributed' 2>/dev/null; then
  load
  # a file, not stdin: Dask's worker processes re-import the main module
  cat > "$out/dask_run.py" <<'PY'
import sys
from dask.distributed import Client, LocalCluster
import pounding.campaign

if __name__ == "__main__":
    spec, out = sys.argv[1], sys.argv[2]
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster, Client(cluster) as client:
        result = pounding.campaign.run(spec, client, out=out)
    print(f"dask: {result.runs} runs in {result.tasks} tasks, {result.statuses}")
PY
  # failed runs are stored with their status (exit 0); an exception is a failure here
  /usr/bin/time -f "dask: %e s wall, %M KB peak (the driver process)" \
    "$py" "$out/dask_run.py" "$spec" "$out/dask"
  stores+=(dask)
else
  echo "dask run skipped: $py cannot import pounding.campaign, pyarrow and dask.distributed"
fi
for s in "${stores[@]}"; do
  echo "$(sha256sum < "$out/$s/runs.parquet" | cut -c1-16)  $s/runs.parquet ($(stat -c %s "$out/$s/runs.parquet") bytes)"
done
for s in "${stores[@]:1}"; do
  cmp "$out/threads-1/runs.parquet" "$out/$s/runs.parquet"
done
echo "identical: ${stores[*]}"
