#!/usr/bin/env bash
# Figures of docs/performance.md, "NO certificates for instances with
# vertical operations": for each lattice instance (a .grid, or a .cnf that
# goes through `cnf to-lsat` and `compile --model continuous`, which is a
# NO instance in discrete time iff the formula is UNSAT), CPU seconds (user
# + system, of each whole command, reading the instance included) of
# `solve` (default engine, no certificate), `solve --certificate` and
# `certify`, certify's exit code, the certificate's kind, and the sizes of
# the .grid and the certificate. One CSV line per instance.
# MODEL=continuous: the continuous model (solve and certify --model
# continuous; certificates of kind bounds, docs/certificates.md).
# reason_lines: clauses with a reason (x lines; i, e, f and t lines).
#   usage: [MODEL=continuous] scripts/certify_pairs_figures.sh GRIDLOCK OUT.csv FILE...
set -euo pipefail
bin=$1; out=$2; shift 2
model=${MODEL:-discrete}
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
cpu() { /usr/bin/time -f "%U %S" -o "$work/t" "$@" >/dev/null 2>&1 || true; tail -1 "$work/t" | awk '{print $1 + $2}'; }
echo "instance,solve_s,solve_cert_s,certify_s,certify_exit,kind,grid_bytes,cert_bytes,reason_lines,o_lines,l_lines" > "$out"
for f in "$@"; do
  g=$f
  if [[ $f == *.cnf ]]; then
    "$bin" cnf to-lsat "$f" -o "$work/l.cnf" >/dev/null
    "$bin" compile "$work/l.cnf" --model continuous -o "$work/i.grid" >/dev/null
    g=$work/i.grid
  fi
  rm -f "$work/c"
  s=$(cpu "$bin" solve "$g" --model "$model")
  sc=$(cpu "$bin" solve "$g" --model "$model" --certificate "$work/c")
  [[ -f $work/c ]] || touch "$work/c"
  ch=$(cpu "$bin" certify "$g" "$work/c" --model "$model")
  rc=$(grep -o 'status [0-9]*' "$work/t" | cut -d' ' -f2); rc=${rc:-0}
  kind=$(awk '$1=="breaker"||$1=="gaps"||$1=="pairs"||$1=="bounds"||$1~/^final-/{print $1; exit}' "$work/c")
  echo "$(basename "$f"),$s,$sc,$ch,$rc,${kind:-none},$(stat -c %s "$g"),$(stat -c %s "$work/c"),$(grep -c '^[xieft] ' "$work/c" || true),$(grep -c '^o' "$work/c" || true),$(grep -c '^l' "$work/c" || true)" >> "$out"
  tail -1 "$out" >&2
done
