#!/usr/bin/env bash
# Lint: clang-format (no change allowed) and clang-tidy (.clang-tidy's checks,
# every finding an error) on the given C++ files, or on every .cpp and .hpp
# of the repository outside tests/data when none are given (tracked files in
# a git checkout; otherwise every such file outside build*/ and out/, as in
# scripts/test.sh's copy).
#   scripts/lint.sh [--format-only|--tidy-only] [--no-function-size] [FILE...]
# --no-function-size: every check but readability-function-size (the
# 80-line limit; scripts/test.sh's TIDY_FUNCTION_SIZE switch).
# clang-tidy needs a compile database: it uses BUILD_DIR (default build/),
# configuring it if needed. Headers are checked through the .cpp files that
# include them (HeaderFilterRegex in .clang-tidy).
# JavaScript files (the viewer, render/viewer/*.js; every tracked one when
# no file is given) are parsed with node --check (Debian's nodejs, no npm),
# with the format check (not under --tidy-only).
# scripts/test.sh runs both as CI gates.
set -euo pipefail
cd "$(dirname "$0")/.."
format=1
tidy=1
tidy_args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --format-only) tidy=0 ;;
    --tidy-only) format=0 ;;
    --no-function-size) tidy_args+=(--checks=-readability-function-size) ;;
    *) break ;;
  esac
  shift
done
if [ $# -gt 0 ]; then
  files=("$@")
elif git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' | grep -v '^tests/data/')
else
  mapfile -t files < <(find . \( -path './build*' -o -path './out' -o -path './.git' -o -path './tests/data' \) -prune \
    -o \( -name '*.cpp' -o -name '*.hpp' \) -type f -print | sed 's#^\./##' | sort)
fi
# The viewer's scripts: given ones, or every tracked one when none is given.
if [ $# -gt 0 ]; then
  mapfile -t scripts < <(printf '%s\n' "${files[@]}" | grep '\.js$' || true)
  mapfile -t files < <(printf '%s\n' "${files[@]}" | grep -v '\.js$' || true)
elif git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  mapfile -t scripts < <(git ls-files '*.js')
else
  mapfile -t scripts < <(find render -name '*.js' -type f | sort)
fi
status=0
if [ $format -eq 1 ] && [ ${#scripts[@]} -gt 0 ]; then
  if command -v node >/dev/null; then
    echo "== node --check (${#scripts[@]} scripts)"
    for js in "${scripts[@]}"; do node --check "$js" || status=1; done
  else
    echo "lint.sh: node is not installed (scripts/setup.sh): JavaScript not checked" >&2
    status=1
  fi
fi
if [ $format -eq 1 ] && [ ${#files[@]} -gt 0 ]; then
  echo "== clang-format (${#files[@]} files)"
  clang-format --dry-run -Werror "${files[@]}" || status=1
fi
if [ $tidy -eq 1 ]; then
  BUILD_DIR=${BUILD_DIR:-build}
  if [ ! -f "$BUILD_DIR/compile_commands.json" ]; then
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  fi
  mapfile -t sources < <(printf '%s\n' "${files[@]}" | grep '\.cpp$' || true)
  echo "== clang-tidy (${#sources[@]} translation units${tidy_args[*]:+, ${tidy_args[*]}})"
  if [ ${#sources[@]} -gt 0 ]; then
    # Findings are errors (WarningsAsErrors in .clang-tidy); -quiet drops the
    # per-file "N warnings generated" chatter.
    printf '%s\n' "${sources[@]}" | xargs -P "$(nproc)" -n 4 \
      clang-tidy -p "$BUILD_DIR" --quiet "${tidy_args[@]}" || status=1
  fi
fi
exit $status
