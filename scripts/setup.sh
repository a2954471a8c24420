#!/usr/bin/env bash
# Installs what gridlock needs from Debian, if it is missing. Safe to re-run.
# Uses apt-get directly as root, or through sudo otherwise.
set -euo pipefail

PACKAGES=(
  cmake g++ make clang libclang-rt-14-dev   # build; clang for libFuzzer targets
  libcadical-dev                            # the SAT solver, linked as a library
  libjemalloc-dev                           # the command line's allocator (campaigns allocate per formula)
  libboost-program-options-dev              # the command line
  nlohmann-json3-dev                        # --json output, manifests
  libgtest-dev                              # tests
  libbenchmark-dev                          # bench/
  librsvg2-bin                              # rsvg-convert: look at the SVGs as PNG
  ccache                                    # shared objects between the builds
  jq                                        # tests/chaos.sh reads the JSON it checks
  libz3-dev z3                              # exact linear real arithmetic: continuous solver, twins
  libssl-dev                                # SHA-256 of inputs (run identity of shards and sets)
  chromium                                  # headless browser for the viewer's page tests
  nodejs                                    # node --check: the viewer's JavaScript (scripts/lint.sh, ctest)
  clang-format clang-tidy                   # scripts/lint.sh
  parallel                                  # GNU parallel: the sharded-campaign recipe test
  pybind11-dev python3-pybind11 python3-dev # the Python module (python/, docs/python.md)
  python3-pytest python3-matplotlib         # its tests (tests/python) and example (examples/python)
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  exit 0
fi
echo "setup: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
