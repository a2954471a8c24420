#!/usr/bin/env bash
# Figures of docs/performance.md, "NO certificates": for each UNSAT formula,
# to-lsat + compile, then (CPU seconds, user + system, of each whole command,
# reading the instance included) `solve` (default engine, no certificate),
# `solve --certificate` (the precedence engine writing its log), `certify`,
# and the sizes of the .grid and the certificate. One CSV line per formula.
#   usage: scripts/certify_figures.sh GRIDLOCK OUT.csv FORMULA.cnf...
set -euo pipefail
bin=$1; out=$2; shift 2
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cpu() { /usr/bin/time -f "%U %S" -o "$work/t" "$@" >/dev/null 2>&1 || true; tail -1 "$work/t" | awk '{print $1 + $2}'; }
echo "formula,solve_s,solve_cert_s,certify_s,certify_exit,grid_bytes,cert_bytes,lemmas" > "$out"
for f in "$@"; do
  "$bin" cnf to-lsat "$f" -o "$work/l.cnf" >/dev/null
  "$bin" compile "$work/l.cnf" -o "$work/i.grid" >/dev/null
  s=$(cpu "$bin" solve "$work/i.grid")
  sc=$(cpu "$bin" solve "$work/i.grid" --certificate "$work/c")
  ch=$(cpu "$bin" certify "$work/i.grid" "$work/c")
  rc=$(grep -o 'status [0-9]*' "$work/t" | cut -d' ' -f2); rc=${rc:-0}
  echo "$(basename "$f"),$s,$sc,$ch,$rc,$(stat -c %s "$work/i.grid"),$(stat -c %s "$work/c"),$(grep -c '^[lo]' "$work/c")" >> "$out"
  tail -1 "$out" >&2
done
