#!/usr/bin/env bash
# The test command: sets up, builds, and runs the whole test suite twice:
# once optimised, once under AddressSanitizer + UndefinedBehaviorSanitizer.
# Then runs every libFuzzer target for a short fixed time.
#   --quick    only the optimised build (no sanitizers, no fuzzing)
set -euo pipefail
cd "$(dirname "$0")/.."
quick=0
[ "${1:-}" = "--quick" ] && quick=1

echo "== optimised build and tests"
BUILD_DIR=build bash scripts/build.sh
(cd build && ctest --output-on-failure -j "$(nproc)")

if [ $quick -eq 0 ]; then
  echo "== ASan + UBSan build and tests"
  BUILD_DIR=build-asan BUILD_TYPE=Debug bash scripts/build.sh -DGRIDLOCK_SANITIZE=ON -DGRIDLOCK_BENCH=OFF
  # Sanitized runs are slower: the randomized comparisons take fewer cases.
  (cd build-asan && GRIDLOCK_TEST_SCALE=0.3 ASAN_OPTIONS=detect_leaks=1 \
     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j "$(nproc)")
  echo "== fuzzing the readers"
  bash scripts/fuzz.sh 30
fi
