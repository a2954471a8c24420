#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) and runs each for
# SECONDS seconds (default 60) from its seed corpus. Reproducible: libFuzzer's
# seed is printed and fixed with SEED=...
# FUZZ_BUILD_DIR (default build-fuzz) is where the targets are built;
# FUZZ_NO_BUILD=1 runs the targets already there (tests/fuzz_script.sh).
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET=${1:-60}
SEED=${SEED:-1}
build=${FUZZ_BUILD_DIR:-build-fuzz}
if [ "${FUZZ_NO_BUILD:-0}" != 1 ]; then
  bash scripts/setup.sh
  CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRIDLOCK_FUZZ=ON -DGRIDLOCK_BENCH=OFF >/dev/null
  cmake --build "$build" -j "$(nproc)"
fi
# Fails when it fuzzed nothing: no target built, a target that did not run
# to its time limit (a crash of the fuzzer itself, a bad flag), or one that
# executed no input. libFuzzer's own exit code counts.
fuzzed=0
for target in "$build"/fuzz/*_fuzz; do
  [ -x "$target" ] || continue
  name=$(basename "$target" _fuzz)
  corpus=fuzz/corpus/$name
  work=$(mktemp -d)
  cp -r "$corpus"/. "$work"/ 2>/dev/null || true
  echo "fuzz: $name for ${SECONDS_PER_TARGET}s (seed $SEED)"
  log=$(mktemp)
  status=0
  "$target" -seed="$SEED" -max_total_time="$SECONDS_PER_TARGET" -max_len=4096 -print_final_stats=1 "$work" \
    >"$log" 2>&1 || status=$?
  grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)|ERROR|SUMMARY" "$log" || true
  if ls crash-* leak-* timeout-* oom-* >/dev/null 2>&1; then
    echo "fuzz: $name found a failing input:" >&2
    ls crash-* leak-* timeout-* oom-* >&2
    exit 1
  fi
  units=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  if [ "$status" -ne 0 ] || [ -z "$units" ] || [ "$units" -eq 0 ]; then
    echo "fuzz: $name fuzzed nothing (exit $status, ${units:-no} executed units); its output:" >&2
    tail -20 "$log" >&2
    exit 1
  fi
  rm -rf "$work" "$log"
  fuzzed=$((fuzzed + 1))
done
if [ "$fuzzed" -eq 0 ]; then
  echo "fuzz: no fuzz target in $build/fuzz/: nothing was fuzzed" >&2
  exit 1
fi
echo "fuzz: $fuzzed targets fuzzed, no failing input"
