#!/usr/bin/env bash
# Runs the tests again and again on a fresh clone of HEAD, with both cores kept busy by other
# work, and prints each run's result: a test that fails by chance shows here, not in CI.
#   scripts/flake_hunt.sh [--runs N] [--ros-only] [--catkin M] [--no-load]
#     --runs N     ctest runs of the build route, scripts/test.sh's ctest (default 10)
#     --ros-only   only the tests that go through a ROS master (rostest, rviz) and pytest
#     --catkin M   then M runs of the README's catkin route (scripts/catkin_route.sh; default 0)
#     --no-load    no competing work
# The load: one busy process per core at normal priority (stress-ng --cpu when installed, a
# shell loop otherwise). Logs stay in the clone's build/flake_hunt/. Exits non-zero if any run
# failed.
set -euo pipefail
runs=10 catkin=0 load=1 filter=()
while [ $# -gt 0 ]; do
  case "$1" in
    --runs) runs="$2"; shift 2 ;;
    --catkin) catkin="$2"; shift 2 ;;
    --ros-only) filter=(-R "rostest|pytest|rviz"); shift ;;
    --no-load) load=0; shift ;;
    *) echo "flake_hunt: unknown argument $1" >&2; exit 2 ;;
  esac
done
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
clone="$(mktemp -d /tmp/cue_sim_flake.XXXXXX)"
git clone -q "$root" "$clone"
echo "flake_hunt: $(git -C "$clone" log --oneline -1) in $clone"
cd "$clone"
bash scripts/build.sh > "$clone/build.log" 2>&1 || { tail -30 "$clone/build.log"; exit 1; }
source scripts/env.sh
cue_sim_source_devel
logs="$CUE_SIM_BUILD/flake_hunt"
mkdir -p "$logs"

hogs=()
stop_load() { [ ${#hogs[@]} -eq 0 ] || kill "${hogs[@]}" 2> /dev/null || true; }
trap stop_load EXIT
if [ "$load" = 1 ]; then
  cores="$(nproc)"
  if command -v stress-ng > /dev/null; then
    stress-ng --cpu "$cores" --quiet & hogs+=($!)
  else
    for _ in $(seq "$cores"); do (while :; do :; done) & hogs+=($!); done
  fi
  echo "flake_hunt: $cores busy processes beside the tests"
fi

failed_runs=0
report() {  # name, status, log
  local failing=""
  [ "$2" = 0 ] || failing="$(grep -E '\(Failed\)|\(Timeout\)|\*\*\*Failed|FAILURE\]|^(FAILED|ERROR)' "$3" | sort -u | head -8 | tr '\n' ' ')"
  printf 'flake_hunt: %-12s %s %s\n' "$1" "$([ "$2" = 0 ] && echo pass || echo FAIL)" "$failing"
  [ "$2" = 0 ] || failed_runs=$((failed_runs + 1))
}
for i in $(seq "$runs"); do
  start=$(date +%s)
  status=0
  (cd "$CUE_SIM_BUILD" && ctest --output-on-failure -j2 "${filter[@]}") > "$logs/ctest_$i.log" 2>&1 || status=$?
  report "ctest $i/$runs" "$status" "$logs/ctest_$i.log"
  echo "flake_hunt:   $(( $(date +%s) - start )) s, $(grep -Eo '[0-9]+% tests passed, [0-9]+ tests failed out of [0-9]+' "$logs/ctest_$i.log" || true)"
done
for i in $(seq "$catkin"); do
  status=0
  bash scripts/catkin_route.sh > "$logs/catkin_$i.log" 2>&1 || status=$?
  report "catkin $i/$catkin" "$status" "$logs/catkin_$i.log"
  echo "flake_hunt:   $(grep -E 'Summary:' "$logs/catkin_$i.log" || true)"
done
echo "flake_hunt: $failed_runs of $((runs + catkin)) runs failed (logs: $logs)"
[ "$failed_runs" = 0 ]
