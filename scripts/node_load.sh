#!/usr/bin/env bash
# How much of one core table_node uses while it publishes tf and ~state at 1 kHz: with the 16
# balls of a break moving (rolling resistance lowered to 0.001 so that they keep moving), and
# with nothing moving. CPU time is read from /proc; a tf subscriber runs, as rviz would.
#   scripts/node_load.sh [seconds]        (default 4: most of the break is still moving)
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
seconds="${1:-4}"
cue_sim_private_master 11397 node_load
rosrun cue_sim table_node __name:=table _urdf_file:="$CUE_SIM_ROOT/urdf/table_7ft.urdf" _publish_rate:=1000 \
  _mu_roll:=0.001 _rack:=eight \
  > "$ROS_LOG_DIR/node_load_node.log" 2>&1 &
cue_sim_pids+=($!)
for _ in $(seq 100); do rosservice list 2>/dev/null | grep -q '^/table/strike$' && break; sleep 0.2; done
node=$(pgrep -f 'cue_sim/table_node' | head -1)
rostopic hz /tf > /dev/null 2>&1 &
cue_sim_pids+=($!)
sleep 2

ticks=$(getconf CLK_TCK)
cpu() { awk '{ print $14 + $15 }' "/proc/$node/stat"; }
moving() {
  python3 - <<'PY'
import rospy
from cue_sim.msg import BallState, TableState
rospy.init_node("node_load_probe", anonymous=True)
msg = rospy.wait_for_message("/table/state", TableState, timeout=5)
print(sum(1 for b in msg.balls if b.motion in (BallState.SLIDING, BallState.ROLLING, BallState.SPINNING)))
PY
}
measure() {  # label
  local before after start end
  before=$(cpu); start=$(date +%s.%N)
  sleep "$seconds"
  after=$(cpu); end=$(date +%s.%N)
  awk -v b="$before" -v a="$after" -v s="$start" -v e="$end" -v t="$ticks" -v l="$1" \
    'BEGIN { printf "%s: %.1f%% of one core over %.0f s\n", l, 100 * (a - b) / t / (e - s), e - s }'
}
echo "table_node at 1 kHz (tf and ~state), 16 balls:"
measure "  nothing moving"
rosservice call /table/strike "{ball_id: 0, speed: 5.3, phi: 0.0, theta: 0.0, a: 0.0, b: 0.0}" > /dev/null
sleep 1
echo "  balls moving when the window opens: $(moving)"
measure "  after the break"
echo "  balls moving when the window closes: $(moving)"
