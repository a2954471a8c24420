#!/usr/bin/env bash
# The main job: sets up, builds, and verifies the reduction end to end on the
# bundled formulas (examples/formulas: small SAT and UNSAT ones and SATLIB
# uf20-91 samples). Prints the table (CaDiCaL vs exact discrete solver vs
# gap checker, certificates checked), then writes pictures of the small
# compiled instances and their witness schedules (or a collision) to out/.
#   MAIN_JOB_TIMEOUT  seconds the exact solver may spend per formula (default 60)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=build bash scripts/build.sh >/dev/null
mkdir -p out
echo "== gridlock verify examples/formulas"
build/gridlock verify examples/formulas --timeout "${MAIN_JOB_TIMEOUT:-60}" \
  --pictures out/pictures --reproducers out/verify-failures
echo "== a gadget of each kind, and a labelled instance set"
for kind in variable clause order; do
  build/gridlock gadget "$kind" -o "out/gadget-$kind.grid" --svg "out/pictures/gadget-$kind.svg"
done
build/gridlock gen-instances -o out/instances --vars 8 --threshold 4 --lsat 2 --seed 1 | tail -n 1
echo "pictures: $(ls out/pictures | wc -l) SVG files in out/pictures (open them in a browser)"
