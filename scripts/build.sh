#!/usr/bin/env bash
# Configures and builds cue_sim into build/, outside the source tree: the targets given, or
# everything (the node, the libraries, the programs, the Python module and the tests).
#   scripts/build.sh [TARGET...]
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
mkdir -p "$CUE_SIM_BUILD"
cmake -S "$CUE_SIM_ROOT" -B "$CUE_SIM_BUILD" -DCMAKE_BUILD_TYPE=Release \
  -DCATKIN_DEVEL_PREFIX="$CUE_SIM_DEVEL" \
  -DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3 >"$CUE_SIM_BUILD/cmake.log" 2>&1 \
  || { cat "$CUE_SIM_BUILD/cmake.log"; exit 1; }
if [ $# -eq 0 ]; then set -- all tests; fi
cmake --build "$CUE_SIM_BUILD" -j"$(nproc)" --target "$@"
