#!/usr/bin/env bash
# The test command (CI runs exactly this). In order:
#  1. no file of the repository reaches beside it (scripts/check_self_contained.sh),
#     and clang-format would change nothing (scripts/lint.sh --format-only);
#  2. the optimised build, clang-tidy on its compile database with zero
#     findings (scripts/lint.sh --tidy-only; switches below), and the whole
#     suite, in a copy of the repository in a fresh temporary folder with
#     nothing beside it: this proves the suite needs nothing outside the
#     repository;
#  3. that build installed into a temporary prefix, and examples/api built
#     against it with find_package(gridlock) and run on two formulas;
#  4. the suite under AddressSanitizer + UndefinedBehaviorSanitizer (build-asan/),
#     then the parallel campaigns' tests under ThreadSanitizer (build-tsan/);
#  5. every libFuzzer target for a short fixed time.
# Every build treats warnings as errors (GRIDLOCK_WERROR).
#   --quick    steps 1 to 3 only
set -euo pipefail
cd "$(dirname "$0")/.."
# Gates: 1 on, 0 off. TIDY: clang-tidy's .clang-tidy checks (bugprone,
# performance, ...). TIDY_FUNCTION_SIZE: its readability-function-size limit
# (80 lines of body outside tests/) too.
TIDY=1
TIDY_FUNCTION_SIZE=1
quick=0
[ "${1:-}" = "--quick" ] && quick=1
bash scripts/setup.sh

echo "== self-contained: no file reaches outside the repository"
bash scripts/check_self_contained.sh

echo "== format: clang-format changes nothing (.clang-format)"
bash scripts/lint.sh --format-only

echo "== optimised build and tests, from a copy of the repository with nothing beside it"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
copy="$work/gridlock"
mkdir "$copy"
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  # Tracked files plus new ones not yet committed (never build trees or out/).
  git ls-files -co --exclude-standard -z | xargs -0 cp --parents -t "$copy"
else
  tar --exclude='./build*' --exclude='./out' --exclude='./.git' -cf - . | tar -xf - -C "$copy"
fi
if [ -e "$work/shared" ]; then
  echo "test.sh: $work/shared exists; the copy must have nothing beside it" >&2
  exit 1
fi
# ccache keys on paths relative to the copy, so repeated runs reuse objects.
export CCACHE_BASEDIR="$copy" CCACHE_NOHASHDIR=1
(cd "$copy" && BUILD_DIR=build bash scripts/build.sh -DGRIDLOCK_WERROR=ON)
if [ "$TIDY" -eq 1 ]; then
  echo "== tidy: clang-tidy finds nothing (.clang-tidy; function size: $([ "$TIDY_FUNCTION_SIZE" -eq 1 ] && echo on || echo off))"
  size_flag=$([ "$TIDY_FUNCTION_SIZE" -eq 1 ] || echo --no-function-size)
  (cd "$copy" && BUILD_DIR=build bash scripts/lint.sh --tidy-only $size_flag)
fi
(cd "$copy/build" && ctest --output-on-failure -j "$(nproc)")

echo "== the API example against the installed package"
cmake --install "$copy/build" --prefix "$work/prefix" >/dev/null
# The installed headers include only installed headers (no internal/ one).
python3 scripts/check_public_headers.py --prefix "$work/prefix"
# The package names its dependencies by target (CaDiCaL::cadical, Z3::z3),
# found again by its config: no library path of this machine is installed.
if grep -nE '/[^";]*lib(z3|cadical)[^";]*' "$work/prefix/lib/cmake/gridlock/"*.cmake | grep -v 'find_library'; then
  echo "test.sh: the installed package names a library path of the build machine (above)" >&2
  exit 1
fi
cmake -S "$copy/examples/api" -B "$work/api" -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_CXX_FLAGS="-Wall -Wextra -Wshadow -Wconversion -Wno-sign-conversion -Werror" >/dev/null
cmake --build "$work/api" -j "$(nproc)" >/dev/null
for case in "tiny-sat.cnf 10" "tiny-unsat.cnf 20" "uf20-01.cnf 10"; do
  set -- $case
  status=0
  "$work/api/gridlock_api" "examples/formulas/$1" >"$work/api.out" || status=$?
  if [ "$status" -ne "$2" ]; then
    cat "$work/api.out"
    echo "test.sh: examples/api on $1 exited $status, expected $2" >&2
    exit 1
  fi
  echo "examples/api $1: exit $status, $(tail -n 1 "$work/api.out" | cut -c1-60)"
done
# The Python module (when built) imports from the prefix, with the interpreter it was built for.
python=$(sed -n 's/^Python_EXECUTABLE:[A-Z]*=//p' "$copy/build/CMakeCache.txt")
if [ -n "$python" ] && [ -d "$copy/build/python/gridlock" ]; then
  (cd "$work" && PYTHONPATH=$(echo "$work"/prefix/lib/python3*/*-packages) "$python" -c \
    "import gridlock; assert gridlock.__file__.startswith('$work/prefix/'), gridlock.__file__; \
print('python module from the prefix:', gridlock.solve(gridlock.Instance.read('$copy/examples/instances/tiny-sat.grid')).status)")
fi
unset CCACHE_BASEDIR CCACHE_NOHASHDIR

if [ $quick -eq 0 ]; then
  echo "== ASan + UBSan build and tests"
  BUILD_DIR=build-asan BUILD_TYPE=Debug bash scripts/build.sh -DGRIDLOCK_SANITIZE=ON -DGRIDLOCK_BENCH=OFF \
    -DGRIDLOCK_WERROR=ON
  # Sanitized runs are slower: the randomized comparisons take fewer cases.
  (cd build-asan && GRIDLOCK_TEST_SCALE=0.3 ASAN_OPTIONS=detect_leaks=1 \
     UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1 ctest --output-on-failure -j "$(nproc)")
  echo "== ThreadSanitizer: the parallel campaigns (--jobs), parallel_tests only"
  # Only the libraries and tests/parallel_*_test.cpp are built (no CLI, no
  # benchmarks, no Python): a few minutes on CI's 2 cores.
  cmake -S . -B build-tsan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DGRIDLOCK_TSAN=ON -DGRIDLOCK_BENCH=OFF \
    -DGRIDLOCK_PYTHON=OFF -DGRIDLOCK_WERROR=ON >/dev/null
  cmake --build build-tsan -j "$(nproc)" --target parallel_tests
  GRIDLOCK_TEST_SCALE=0.3 TSAN_OPTIONS=halt_on_error=1:second_deadlock_stack=1 build-tsan/tests/parallel_tests
  echo "== fuzzing the readers"
  bash scripts/fuzz.sh 30
fi
