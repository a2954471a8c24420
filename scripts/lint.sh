#!/usr/bin/env bash
# Lint: clang-format (no change allowed) and clang-tidy (.clang-tidy's checks,
# every finding an error) on the given C++ files, or on every tracked .cpp and
# .hpp outside tests/data when none are given.
#   scripts/lint.sh [--format-only|--tidy-only] [FILE...]
# clang-tidy needs a compile database: it uses BUILD_DIR (default build/),
# configuring it if needed. Headers are checked through the .cpp files that
# include them (HeaderFilterRegex in .clang-tidy).
# scripts/test.sh runs the format check as a CI gate (no change allowed).
set -euo pipefail
cd "$(dirname "$0")/.."
format=1
tidy=1
case "${1:-}" in
  --format-only) tidy=0; shift ;;
  --tidy-only) format=0; shift ;;
esac
if [ $# -gt 0 ]; then
  files=("$@")
else
  mapfile -t files < <(git ls-files '*.cpp' '*.hpp' | grep -v '^tests/data/')
fi
status=0
if [ $format -eq 1 ]; then
  echo "== clang-format (${#files[@]} files)"
  clang-format --dry-run -Werror "${files[@]}" || status=1
fi
if [ $tidy -eq 1 ]; then
  BUILD_DIR=${BUILD_DIR:-build}
  if [ ! -f "$BUILD_DIR/compile_commands.json" ]; then
    cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
  fi
  mapfile -t sources < <(printf '%s\n' "${files[@]}" | grep '\.cpp$' || true)
  echo "== clang-tidy (${#sources[@]} translation units)"
  if [ ${#sources[@]} -gt 0 ]; then
    # Findings are errors (WarningsAsErrors in .clang-tidy); -quiet drops the
    # per-file "N warnings generated" chatter.
    printf '%s\n' "${sources[@]}" | xargs -P "$(nproc)" -n 4 \
      clang-tidy -p "$BUILD_DIR" --quiet || status=1
  fi
fi
exit $status
