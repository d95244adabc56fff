#!/usr/bin/env bash
# What following a robot's cue costs table_node: its CPU while a cue frame comes at 1 kHz in /tf
# (a tip circling over the empty half of the table, touching nothing), with ~cue/frame set to it
# and without (the node then does not listen to /tf at all), each twice, in turn. CPU time is
# read from /proc over the window. (The node's own tf rate while it follows is checked by the
# followed_cue rostest.)
#   scripts/cue_frame_load.sh [seconds] [rate]        (default 10 s at 1000 Hz; CUE_FRAME_LOAD_ROUNDS=2 turns)
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
seconds="${1:-10}"
rate="${2:-1000}"
cue_sim_private_master 11399 cue_frame_load
ticks=$(getconf CLK_TCK)

python3 - "$rate" > "$ROS_LOG_DIR/cue_frame_load_robot.log" 2>&1 <<'PY' &
import math, sys
import rospy, tf2_ros
from geometry_msgs.msg import TransformStamped
rospy.init_node("circling_cue")
broadcaster = tf2_ros.TransformBroadcaster()
pace = rospy.Rate(float(sys.argv[1]))
t = TransformStamped()
t.header.frame_id, t.child_frame_id = "table", "cue_tip"
start = rospy.Time.now()
while not rospy.is_shutdown():
    t.header.stamp = rospy.Time.now()
    a = (t.header.stamp - start).to_sec()
    t.transform.translation.x, t.transform.translation.y, t.transform.translation.z = -0.5 + 0.2 * math.cos(a), 0.2 * math.sin(a), 0.05
    t.transform.rotation.w = 1.0
    broadcaster.sendTransform(t)
    pace.sleep()
PY
cue_sim_pids+=($!)

run() {  # label, extra node arguments
  local label="$1"; shift
  rosrun cue_sim table_node __name:=table _urdf_file:="$CUE_SIM_ROOT/urdf/table_7ft.urdf" _rack:=eight \
    _camera/enabled:=false "$@" > "$ROS_LOG_DIR/cue_frame_load_node.log" 2>&1 &
  local launched=$!
  cue_sim_pids+=("$launched")  # stopped on any exit, never left running
  # Ready when this node says so in its own log (rosrun execs it, so $launched is the node). The
  # master is no witness: the last run's node may still be listed there for a moment, and a
  # search by name could find rosrun before it execs (both once ended this script early, on
  # 2026-11-29, leaving the node running for its EXIT trap to wait on).
  for _ in $(seq 150); do grep -q "cue_sim: table '" "$ROS_LOG_DIR/cue_frame_load_node.log" && break; sleep 0.2; done
  local node="$launched"
  sleep 2
  local before after start end
  before=$(awk '{ print $14 + $15 }' "/proc/$node/stat"); start=$(date +%s.%N)
  sleep "$seconds"
  after=$(awk '{ print $14 + $15 }' "/proc/$node/stat"); end=$(date +%s.%N)
  awk -v b="$before" -v a="$after" -v s="$start" -v e="$end" -v t="$ticks" -v l="$label" \
    'BEGIN { printf "%s: %.2f%% of one core over %.0f s\n", l, 100 * (a - b) / t / (e - s), e - s }'
  kill "$launched" 2>/dev/null; wait "$launched" 2>/dev/null || true
}
echo "table_node at 100 Hz of tf, a cue frame in /tf at $rate Hz:"
for _ in $(seq "${CUE_FRAME_LOAD_ROUNDS:-2}"); do
  run "  not following it"
  run "  following it (~cue/frame cue_tip)" _cue/frame:=cue_tip
done
