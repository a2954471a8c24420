#!/usr/bin/env bash
# The main job: sets up, builds, and verifies the reduction end to end on the
# bundled formulas (examples/formulas: small SAT and UNSAT ones and SATLIB
# uf20-91 samples). Prints the table (CaDiCaL vs exact discrete solver vs
# gap checker, certificates checked: witnesses of every YES, a NO
# certificate of every discrete NO), the continuous reduction on the small
# ones, the uf20 samples and an unsatisfiable random 15-variable formula
# (CaDiCaL vs the exact continuous solver, a NO certificate of every
# continuous NO), one NO certificate of each model through
# `gridlock certify`, then writes pictures of the small
# compiled instances and their witness schedules (or a collision) to out/,
# each with an animation beside it (NAME.html: open it in a browser).
#   MAIN_JOB_TIMEOUT  seconds the exact solver may spend per formula (default 60)
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=build bash scripts/build.sh >/dev/null
mkdir -p out
echo "== gridlock verify examples/formulas"
build/gridlock verify examples/formulas --timeout "${MAIN_JOB_TIMEOUT:-60}" \
  --pictures out/pictures --reproducers out/verify-failures
echo "== the continuous reduction (separation gadget), exact continuous solver: small formulas, SATLIB uf20, random-unsat-15"
build/gridlock verify examples/formulas/{tiny-sat,tiny-unsat,lsat-sat,unsat-3cnf,uf20-01,uf20-02,uf20-03,random-unsat-15}.cnf \
  --model continuous \
  --timeout "${MAIN_JOB_TIMEOUT:-60}" --reproducers out/verify-failures-continuous
echo "== a NO certificate of an UNSAT formula's instance, checked without the solvers (docs/certificates.md)"
build/gridlock cnf to-lsat examples/formulas/unsat-3cnf.cnf -o out/unsat-3cnf.lsat.cnf >/dev/null
build/gridlock compile out/unsat-3cnf.lsat.cnf -o out/unsat-3cnf.grid >/dev/null
build/gridlock solve out/unsat-3cnf.grid --certificate out/unsat-3cnf.nocert | grep -E '^(s|c cert)' || [ $? -eq 20 ]
build/gridlock certify out/unsat-3cnf.grid out/unsat-3cnf.nocert || [ $? -eq 20 ]
echo "== the same formula in continuous time: its NO certificate (kind bounds), checked without the solvers"
build/gridlock compile out/unsat-3cnf.lsat.cnf --model continuous -o out/unsat-3cnf-continuous.grid >/dev/null
build/gridlock solve out/unsat-3cnf-continuous.grid --model continuous --certificate out/unsat-3cnf-continuous.nocert |
  grep -E '^(s|c cert)' || [ $? -eq 20 ]
build/gridlock certify out/unsat-3cnf-continuous.grid out/unsat-3cnf-continuous.nocert --model continuous || [ $? -eq 20 ]
echo "== a gadget of each kind, and a labelled instance set"
for kind in variable clause order separation; do
  build/gridlock gadget "$kind" -o "out/gadget-$kind.grid" --svg "out/pictures/gadget-$kind.svg"
done
build/gridlock gen-instances -o out/instances --force --vars 8 --threshold 4 --lsat 2 --seed 1 | tail -n 1
echo "== animations of the worked cases of the model"
build/gridlock animate examples/instances/model-case2-order-gadget.grid --order "b a" \
  -o out/pictures/model-case2-order-gadget-collision.html | tail -n 2
printf 'g1 0\ng2 1/2\n' > out/model-case1-times.txt
build/gridlock animate examples/instances/model-case1-two-growths.grid --times out/model-case1-times.txt \
  -o out/pictures/model-case1-two-growths-collision.html | tail -n 2
echo "pictures: $(ls out/pictures/*.svg | wc -l) SVG files and $(ls out/pictures/*.html | wc -l) animations" \
  "(self-contained HTML) in out/pictures (open them in a browser)"
