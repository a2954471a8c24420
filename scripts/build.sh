#!/usr/bin/env bash
# Configures and builds gridlock in build/ (or the folder given in BUILD_DIR),
# passing any extra arguments to cmake. Uses every core (the machines have 2).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
BUILD_DIR=${BUILD_DIR:-build}
cmake -S . -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=${BUILD_TYPE:-RelWithDebInfo} "$@" >/dev/null
cmake --build "$BUILD_DIR" -j "$(nproc)"
