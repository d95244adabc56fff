#!/usr/bin/env bash
# Instruction counts per shot of every bench scene, under callgrind: unlike wall time, they do
# not change with the machine's load. Only the run is counted (runScene: not the set-up).
#   scripts/callgrind_shots.sh [SCENE...]      (all scenes if none given)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
program="$CUE_SIM_DEVEL/lib/cue_sim/bench_scene"
[ -x "$program" ] || { echo "callgrind_shots: build first (scripts/build.sh): no $program" >&2; exit 1; }
command -v valgrind >/dev/null || { echo "callgrind_shots: valgrind is missing (scripts/install_deps.sh)" >&2; exit 1; }
if [ $# -eq 0 ]; then
  # The scene names, from the program's usage message.
  read -r -a scenes <<<"$("$program" 2>&1 | sed -n 's/^scenes: *//p')"
else
  scenes=("$@")
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
printf '| scene | balls | events | instructions per shot | instructions per event |\n|---|---|---|---|---|\n'
for scene in "${scenes[@]}"; do
  # LD_BIND_NOW: symbols are bound at start-up, not counted in the first shot.
  summary=$(LD_BIND_NOW=1 valgrind --tool=callgrind --callgrind-out-file="$out/$scene.out" \
    --toggle-collect='cue_sim::bench::runScene*' "$program" "$scene" 2>"$out/$scene.log")
  refs=$(sed -n 's/.*refs: *\([0-9,]*\).*/\1/p' "$out/$scene.log" | tr -d ,)
  balls=$(sed -n 's/.*: \([0-9]*\) balls, .*/\1/p' <<<"$summary")
  events=$(sed -n 's/.* balls, \([0-9]*\) events.*/\1/p' <<<"$summary")
  printf '| %s | %s | %s | %s | %s |\n' "$scene" "$balls" "$events" "$refs" "$((refs / (events > 0 ? events : 1)))"
done
