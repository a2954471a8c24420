#!/usr/bin/env bash
# Chaos test of the interruption guarantees (docs/errors.md): interrupts
# `gridlock fuzz`, `gridlock verify` and `gridlock gen-instances` with SIGINT
# or SIGTERM at random moments and checks what is left behind:
#   - the exit code is 130 (SIGINT) / 143 (SIGTERM), or 0/1 if the run had
#     already finished;
#   - --json output is one valid JSON object whose "interrupted" matches;
#   - no temporary file (*.tmp.*) is left anywhere;
#   - every .grid parses (gridlock render --tikz), every .cnf parses (gridlock cnf
#     check), every .svg is complete, every YES instance's schedule is
#     collision-free (gridlock check);
#   - gen-instances: manifest.json lists exactly the .grid files in the folder;
#   - compile / render (default dispositions, as on a terminal: `env
#     --default-signal`, since a background job of a script ignores SIGINT):
#     no temporary file, the output absent or whole.
#
# usage: tests/chaos.sh GRIDLOCK [ROUNDS]   (ctest runs it: see tests/CMakeLists.txt)
# The random choices (commands, signals, delays) come from CHAOS_SEED, 1 by
# default, so every run (ctest's too) makes the same choices; set another
# seed to explore. It is printed first, so a failure replays. (The moment a
# signal lands in the program still depends on the machine's speed.)
# Bounded: each round waits at most 2.5 s before its signal and 60 s after.
set -uo pipefail
GRIDLOCK=${1:?usage: chaos.sh GRIDLOCK [ROUNDS]}
ROUNDS=${2:-${CHAOS_ROUNDS:-6}}
SEED=${CHAOS_SEED:-1}
DATA=$(cd "$(dirname "$0")" && pwd)/data/satlib
echo "chaos: seed $SEED, $ROUNDS rounds (replay: CHAOS_SEED=$SEED $0 $GRIDLOCK $ROUNDS)"
RANDOM=$SEED
WORK=$(mktemp -d "${TMPDIR:-/tmp}/gridlock-chaos.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
failures=0
# A formula whose compiled instance is tens of MB: its write takes long
# enough to be hit.
BIG="$WORK/big.cnf"
{ echo "p cnf 40000 40000"; for v in $(seq 1 40000); do echo "$v -$(( v % 40000 + 1 )) 0"; done; } >"$BIG"

fail() {
  echo "chaos: FAIL (seed $SEED, round $round, $what): $*" >&2
  failures=$((failures + 1))
}

# Every file under $1 must be whole and parse.
check_files() {
  local dir=$1 f
  [ -d "$dir" ] || return 0
  while IFS= read -r f; do fail "temporary file left behind: $f"; done < <(find "$dir" -name '*.tmp.*')
  while IFS= read -r f; do
    "$GRIDLOCK" render --tikz "$f" -o /dev/null 2>/dev/null || fail "does not parse: $f"
    local sched="${f%.grid}.schedule"
    if [ -f "$sched" ]; then
      "$GRIDLOCK" check "$f" --order-file "$sched" >/dev/null 2>&1
      [ $? -eq 10 ] || fail "schedule not collision-free: $sched"
    fi
  done < <(find "$dir" -name '*.grid')
  while IFS= read -r f; do
    "$GRIDLOCK" cnf check "$f" >/dev/null 2>&1
    local rc=$?
    [ $rc -eq 10 ] || [ $rc -eq 20 ] || fail "does not parse: $f"
  done < <(find "$dir" -name '*.cnf')
  while IFS= read -r f; do
    tail -c 16 "$f" | grep -q '</svg>' || fail "incomplete picture: $f"
  done < <(find "$dir" -name '*.svg')
}

for round in $(seq 1 "$ROUNDS"); do
  dir="$WORK/r$round"
  mkdir -p "$dir"
  # Every draw in this shell: bash reseeds RANDOM inside $(...), so a draw
  # there would not replay from the seed.
  kind=$((RANDOM % 4))
  r_sig=$((RANDOM % 2)) delay_ms=$((50 + RANDOM % 2450)) r_json=$((RANDOM % 2)) r_broken=$((RANDOM % 2))
  sig=$([ $r_sig -eq 0 ] && echo INT || echo TERM)
  json=$([ $r_json -eq 0 ] && echo --json || echo "")
  broken=$([ $r_broken -eq 0 ] && echo "--break-gadget clause-loose" || echo "")
  case $kind in
    0) what="fuzz $json $broken"
       cmd=("$GRIDLOCK" fuzz --seed "$RANDOM" --count 100000 --keep-going --out "$dir/out" $json $broken) ;;
    1) what="verify $json $broken"
       cmd=("$GRIDLOCK" verify "$DATA/uf20-91" --pictures "$dir/out/pictures" --reproducers "$dir/out/repro" $json $broken) ;;
    2) what="gen-instances"
       json=""
       cmd=("$GRIDLOCK" gen-instances -o "$dir/out" --vars $((8 + RANDOM % 40)) --threshold 30 --lsat 30 --seed "$RANDOM") ;;
    3) what="compile (terminal dispositions)"
       json=""
       mkdir -p "$dir/out"
       cmd=(env --default-signal=INT,TERM,HUP "$GRIDLOCK" compile "$BIG" -o "$dir/out/big.grid") ;;
  esac
  what="$what, SIG$sig after $delay_ms ms"
  "${cmd[@]}" >"$dir/stdout" 2>"$dir/stderr" &
  pid=$!
  sleep "$(printf '%d.%03d' $((delay_ms / 1000)) $((delay_ms % 1000)))"
  kill -s "$sig" "$pid" 2>/dev/null
  # Bounded wait: a run that ignores the signal for 60 s is a failure.
  for _ in $(seq 1 600); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  if kill -0 "$pid" 2>/dev/null; then
    fail "still running 60 s after the signal"
    kill -KILL "$pid"
  fi
  wait "$pid"
  rc=$?
  want=$([ "$sig" = INT ] && echo 130 || echo 143)
  interrupted=false
  if [ $rc -eq "$want" ]; then  # compile: killed by the signal itself (128 + N), as on a terminal
    interrupted=true
  elif [ $rc -ne 0 ] && [ $rc -ne 1 ]; then
    fail "exit code $rc (want $want, or 0/1 if it had finished); stderr: $(head -c 300 "$dir/stderr")"
  fi
  if [ -n "$json" ]; then
    # (jq -e alone would fail on "interrupted": false, a run that finished.)
    if jq -e -s 'length == 1 and (.[0] | type == "object" and has("interrupted"))' "$dir/stdout" >/dev/null 2>&1; then
      got=$(jq -r '.interrupted' "$dir/stdout")
    else
      got=""
      fail "stdout is not one JSON object with \"interrupted\""
    fi
    [ "${got:-}" = "$interrupted" ] || fail "\"interrupted\": ${got:-missing}, exit code $rc"
  fi
  check_files "$dir/out"
  if [ $kind -eq 2 ] && [ -d "$dir/out" ] && { [ -f "$dir/out/manifest.json" ] || [ $rc -eq 0 ]; }; then
    listed=$(jq -r '.instances[].instance' "$dir/out/manifest.json" 2>/dev/null | sort)
    present=$(cd "$dir/out" && ls -- *.grid 2>/dev/null | sort)
    [ "$listed" = "$present" ] || fail "manifest lists [$listed], folder holds [$present]"
    [ "$(jq -r .interrupted "$dir/out/manifest.json")" = "$interrupted" ] || fail "manifest \"interrupted\" vs exit $rc"
  fi
  echo "chaos: round $round: $what: exit $rc$([ "$interrupted" = true ] && echo ' (interrupted)')"
done
if [ $failures -gt 0 ]; then
  echo "chaos: $failures failure(s); replay with CHAOS_SEED=$SEED" >&2
  exit 1
fi
echo "chaos: all $ROUNDS rounds left only whole, parseable files"
