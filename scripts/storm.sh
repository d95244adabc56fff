#!/usr/bin/env bash
# Memory under a storm: table_node on a master of its own, its resident memory read from /proc
# before the storm, every half second during it (the peak) and 15 s after it, while
# scripts/storm_client.py sends mixed requests, good and hostile, from several threads.
#   scripts/storm.sh [minutes] [threads] [max_batch]     (default 10 minutes, 4 threads, 1000 shots)
# Prints progress, then "memory: before B MB, peak P MB, after A MB (A/B)"; exits 1 if the node
# died, a call went unanswered, or the memory after is more than 20 % above the memory before.
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
minutes="${1:-10}"
threads="${2:-4}"
max_batch="${3:-1000}"
cue_sim_private_master 11398 storm
rosparam set /robot_description -t "$CUE_SIM_ROOT/urdf/table_7ft.urdf"
rosparam load "$CUE_SIM_ROOT/config/physics.yaml" /table
rosparam load "$CUE_SIM_ROOT/config/table_node.yaml" /table
rosrun cue_sim table_node __name:=table _aim_marker:=false > "$ROS_LOG_DIR/storm_node.log" 2>&1 &
cue_sim_pids+=($!)
for _ in $(seq 100); do rosservice list 2>/dev/null | grep -q '^/table/strike$' && break; sleep 0.2; done
node=$(pgrep -f 'cue_sim/table_node' | head -1)
rss() { awk '/^VmRSS/ { print $2 }' "/proc/$node/status"; }  # [kB]
rostopic hz /tf > /dev/null 2>&1 &  # a tf subscriber, as rviz would be
cue_sim_pids+=($!)
sleep 15  # steady: the node's tf listener holds its 10 s of history
before=$(rss)
echo "storm: table_node (pid $node) at ${before} kB before the storm; $minutes min, $threads threads"
peak_file=$(mktemp)
echo "$before" > "$peak_file"
( while kill -0 "$node" 2>/dev/null; do
    r=$(rss 2>/dev/null || echo 0)
    [ "${r:-0}" -gt "$(cat "$peak_file")" ] && echo "$r" > "$peak_file"
    sleep 0.5
  done ) &
sampler=$!
cue_sim_pids+=($sampler)
status=0
python3 "$here/storm_client.py" "$(awk -v m="$minutes" 'BEGIN { print m * 60 }')" "$threads" "$max_batch" || status=1
if ! kill -0 "$node" 2>/dev/null; then
  echo "storm: table_node died" >&2
  exit 1
fi
sleep 15  # a measurement 15 s after, not a wait for a state: the node gives back what the last replies took (every 2 s after heavy requests)
after=$(rss)
kill "$sampler" 2>/dev/null || true
wait "$sampler" 2>/dev/null || true
peak=$(cat "$peak_file")
rm -f "$peak_file"
rosservice call /table/rack "{layout: eight}" > /dev/null || status=1
awk -v b="$before" -v p="$peak" -v a="$after" \
  'BEGIN { printf "memory: before %.1f MB, peak %.1f MB, after %.1f MB (%.2f of before)\n", b / 1024, p / 1024, a / 1024, a / b }'
if [ "$after" -gt $((before * 12 / 10)) ]; then
  echo "storm: the memory after the storm is more than 20 % above the memory before" >&2
  status=1
fi
exit $status
