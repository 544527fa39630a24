#!/usr/bin/env bash
# Builds every fuzz target with libFuzzer on the stable toolchain and runs each for a bounded time.
#
#   fuzz/run.sh [SECONDS_PER_TARGET] [TARGET...]      (default: 15 s each, every target)
#
# No nightly and no cargo-fuzz: libfuzzer-sys builds with stable rustc when the SanitizerCoverage
# flags are passed directly (RUSTFLAGS below; `--target` keeps them off build scripts and proc
# macros). Debug assertions and overflow checks are on, so any overflow is a crash.
#
# Each target first replays its regression inputs (fuzz/regressions/TARGET/*), then fuzzes from the
# committed seed corpus (fuzz/corpus/TARGET, read only) into a scratch corpus under
# $FUZZ_WORK (default: fuzz-work/ in the instrumented target directory, kept between runs so a
# longer campaign resumes).
# Exit status: 0 when nothing crashed, 1 otherwise; every crash input is copied to
# $FUZZ_WORK/artifacts/TARGET/ and its path printed as `CRASH TARGET PATH`.
set -euo pipefail
cd "$(dirname "$0")"
SECS=${1:-15}
shift || true
TARGETS=("$@")
if [ ${#TARGETS[@]} -eq 0 ]; then
    TARGETS=(lcp_io lcp_solve record study_toml impact_json sim_model)
fi
TRIPLE=$(rustc -vV | sed -n 's/^host: //p')
# Instrumented builds never share a target directory with normal builds (different RUSTFLAGS
# would rebuild everything each time): $FUZZ_TARGET_DIR, else $CARGO_TARGET_DIR-sancov, else fuzz/target.
if [ -n "${FUZZ_TARGET_DIR:-}" ]; then
    export CARGO_TARGET_DIR=$FUZZ_TARGET_DIR
elif [ -n "${CARGO_TARGET_DIR:-}" ]; then
    export CARGO_TARGET_DIR=$CARGO_TARGET_DIR-sancov
else
    export CARGO_TARGET_DIR=$PWD/target
fi
export RUSTFLAGS="--cfg fuzzing -Cpasses=sancov-module -Cllvm-args=-sanitizer-coverage-level=4 \
-Cllvm-args=-sanitizer-coverage-inline-8bit-counters -Cllvm-args=-sanitizer-coverage-pc-table \
-Cllvm-args=-sanitizer-coverage-trace-compares -Cdebug-assertions -Coverflow-checks"
WORK=${FUZZ_WORK:-$CARGO_TARGET_DIR/fuzz-work}
start=$(date +%s)
cargo build --release --locked --target "$TRIPLE" $(printf -- '--bin %s ' "${TARGETS[@]}")
echo "fuzz: build took $(( $(date +%s) - start )) s"
BIN=$CARGO_TARGET_DIR/$TRIPLE/release
failed=0
for t in "${TARGETS[@]}"; do
    mkdir -p "$WORK/corpus/$t" "$WORK/artifacts/$t" "corpus/$t"
    # -timeout: one sim_model input (200 steps whose contact LCPs each take Lemke to its retries and
    # the enumeration fallback) needs about 1.3 s optimised and 7-11 s instrumented (found 2026-11-24)
    common=(-rss_limit_mb=2048 -max_len=16384 -timeout=30 -artifact_prefix="$WORK/artifacts/$t/")
    if [ -d "regressions/$t" ] && [ -n "$(ls -A "regressions/$t")" ]; then
        if ! "$BIN/$t" "${common[@]}" regressions/"$t"/* >"$WORK/$t.replay.log" 2>&1; then
            tail -n 30 "$WORK/$t.replay.log"
            echo "CRASH $t regression input (see $WORK/$t.replay.log)"
            failed=1
            continue
        fi
    fi
    log=$WORK/$t.log
    if "$BIN/$t" "${common[@]}" -max_total_time="$SECS" -print_final_stats=1 \
        "$WORK/corpus/$t" "corpus/$t" >"$log" 2>&1; then
        execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
        echo "fuzz: $t ok: ${execs:-?} inputs in ${SECS} s, corpus $(ls "$WORK/corpus/$t" | wc -l) files"
    else
        tail -n 40 "$log"
        for f in $(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log"); do
            echo "CRASH $t $f"
        done
        failed=1
    fi
done
exit $failed
