#!/usr/bin/env bash
# scripts/fuzz.sh fails when it fuzzed nothing: run on stand-in targets
# (shell scripts printing libFuzzer's final stats) in a scratch build
# folder, with FUZZ_NO_BUILD=1. Run by ctest (test fuzz_script).
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d "${TMPDIR:-/tmp}/gridlock-fuzz-script.XXXXXX")
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/fuzz"
failures=0
# expect CASE WANTED_EXIT [TARGET_BODY]: no target when the body is empty.
expect() {
  rm -f "$work"/fuzz/*_fuzz
  if [ -n "${3:-}" ]; then
    printf '#!/bin/sh\n%s\n' "$3" >"$work/fuzz/stand_in_fuzz"
    chmod +x "$work/fuzz/stand_in_fuzz"
  fi
  FUZZ_NO_BUILD=1 FUZZ_BUILD_DIR="$work" bash "$root/scripts/fuzz.sh" 1 >"$work/out" 2>&1
  local got=$?
  if [ "$got" -ne "$2" ]; then
    echo "fuzz_script: $1: exit $got, expected $2; output:" >&2
    cat "$work/out" >&2
    failures=$((failures + 1))
  else
    echo "fuzz_script: $1: exit $got as expected"
  fi
}
expect "no target" 1 ""
expect "no input executed" 1 'echo "stat::number_of_executed_units: 0"'
expect "no stats" 1 'echo "INFO: nothing"'
expect "fuzzer error" 1 'echo "stat::number_of_executed_units: 50"; exit 3'
expect "fuzzed" 0 'echo "stat::number_of_executed_units: 50"'
[ "$failures" -eq 0 ]
