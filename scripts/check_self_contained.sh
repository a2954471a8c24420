#!/usr/bin/env bash
# Fails if any file of the repository (outside tests/data, which holds vendored
# third-party samples) reaches into a folder beside the checkout, such as the
# project's private shared folder: the repository must build, test and explain
# itself alone. Run by ctest (test "self_contained") and by scripts/test.sh.
# Lists tracked files with git when it can, else every file but build trees.
set -euo pipefail
cd "$(dirname "$0")/.."
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
  list() { git ls-files -co --exclude-standard; }
else
  list() { find . -type f -not -path './build*' -not -path './.git/*' -not -path './out/*' | sed 's#^\./##'; }
fi
# A relative path climbing out to "shared/", or the shared folder's own files
# named as paths (the model page, the SATLIB copy, the paper).
pattern='(\.\./)+shared/|shared/(MODEL\.md|benchmarks/|paper/)'
hits=$(list | grep -v '^tests/data/' | while IFS= read -r f; do
  [ -f "$f" ] && grep -EnI -H "$pattern" "$f" || true
done)
if [ -n "$hits" ]; then
  echo "self_contained: these lines reach outside the repository:" >&2
  echo "$hits" >&2
  exit 1
fi
echo "self_contained: no file reaches outside the repository"
