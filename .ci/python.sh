#!/usr/bin/env bash
# The Python part of CI (called by .ci/run after the cargo tests): builds the Python package
# crates/pounding-py with maturin into a fresh venv and runs its pytest suite against the CLI
# binary the cargo tests just built (docs/guide/python.md).
#
# Where Python >= 3.9, venv or the packages from PyPI (network) are unavailable, it says why,
# lists the skip in $POUNDING_SKIP_LOG and exits 0. A build failure of the crate or a failing
# test is a CI failure.
set -euo pipefail
cd "$(dirname "$0")/.."
skip() {
  echo "Python part skipped: $1"
  if [ -n "${POUNDING_SKIP_LOG:-}" ]; then
    printf 'python (crates/pounding-py/tests)\t%s\n' "$1" >> "$POUNDING_SKIP_LOG"
  fi
  exit 0
}
t0=$(date +%s)
py=$(command -v python3 || true)
[ -n "$py" ] || skip "no python3 on PATH"
"$py" -c 'import sys; sys.exit(sys.version_info < (3, 9))' \
  || skip "python3 is $("$py" -V 2>&1), the package needs >= 3.9"
venv=$(mktemp -d -t pounding-venv.XXXXXX)
trap 'rm -rf "$venv"' EXIT
"$py" -m venv "$venv" >/dev/null 2>&1 || skip "python3 -m venv failed (install python3-venv)"
export PATH="$venv/bin:$PATH"  # maturin's PEP 517 hook runs the maturin binary from PATH
# Third-party packages first: failing here means no network / no PyPI, a skip.
if ! "$venv/bin/pip" install -q "maturin>=1.5,<2" pytest pandas pyarrow "dask[distributed]" \
  > "$venv/pip.log" 2>&1; then
  tail -3 "$venv/pip.log" | sed 's/^/  pip: /'
  skip "pip could not install maturin, pytest, pandas, pyarrow, dask[distributed] (no network or PyPI?)"
fi
# Our package: a build failure here is a real failure (no build isolation: the maturin above).
export CARGO_TARGET_DIR="${CARGO_TARGET_DIR:-$PWD/target}"
"$venv/bin/pip" install -q --no-build-isolation ./crates/pounding-py
t1=$(date +%s)
export POUNDING_BIN="${POUNDING_BIN:-$CARGO_TARGET_DIR/debug/pounding}"
# --basetemp: pytest's tmp_path directories go with the venv (removed on exit), not $TMPDIR.
"$venv/bin/python" -m pytest -q -p no:cacheprovider --basetemp "$venv/pytest" crates/pounding-py/tests
t2=$(date +%s)
echo "Python part: install $((t1 - t0)) s, tests $((t2 - t1)) s"
