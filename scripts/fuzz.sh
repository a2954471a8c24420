#!/usr/bin/env bash
# Builds the libFuzzer targets (clang, ASan + UBSan) and runs each for
# SECONDS seconds (default 60) from its seed corpus. Reproducible: libFuzzer's
# seed is printed and fixed with SEED=...
set -euo pipefail
cd "$(dirname "$0")/.."
SECONDS_PER_TARGET=${1:-60}
SEED=${SEED:-1}
bash scripts/setup.sh
CXX=clang++ cmake -S . -B build-fuzz -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRIDLOCK_FUZZ=ON -DGRIDLOCK_BENCH=OFF >/dev/null
cmake --build build-fuzz -j "$(nproc)"
for target in build-fuzz/fuzz/*_fuzz; do
  [ -x "$target" ] || continue
  name=$(basename "$target" _fuzz)
  corpus=fuzz/corpus/$name
  work=$(mktemp -d)
  cp -r "$corpus"/. "$work"/ 2>/dev/null || true
  echo "fuzz: $name for ${SECONDS_PER_TARGET}s (seed $SEED)"
  "$target" -seed="$SEED" -max_total_time="$SECONDS_PER_TARGET" -max_len=4096 -print_final_stats=1 "$work" 2>&1 \
    | grep -E "^(stat::number_of_executed_units|stat::peak_rss_mb|#[0-9]+ +DONE)|ERROR|SUMMARY" || true
  if ls crash-* leak-* timeout-* oom-* >/dev/null 2>&1; then
    echo "fuzz: $name found a failing input:" >&2
    ls crash-* leak-* timeout-* oom-* >&2
    exit 1
  fi
  rm -rf "$work"
done
