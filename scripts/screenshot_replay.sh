#!/usr/bin/env bash
# Records an 8-ball break with record.launch, then replays the bag into rviz with
# `rosbag play --clock` and no table node, and takes doc/rviz_replay.png 0.5 s into the shot.
# Usage: scripts/screenshot_replay.sh [output.png]
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
out="$(realpath -m "${1:-$CUE_SIM_ROOT/doc/rviz_replay.png}")"
bag="$CUE_SIM_BUILD/replay_demo.bag"
rm -f "$bag"
export ROS_MASTER_URI=http://localhost:11396

# 1. Record: the table and the recorder, a break, 8 s of it.
roslaunch cue_sim table.launch rviz:=false record:=true bag:="$bag" > "$CUE_SIM_BUILD/replay_record.log" 2>&1 &
launch=$!
for i in $(seq 60); do rosservice list 2>/dev/null | grep -q /table/strike && break; sleep 0.5; done
sleep 2  # the recorder subscribes
rosservice call /table/strike '{ball_id: 0, speed: 8.0, phi: 0.002}' > /dev/null
sleep 8
kill -INT $launch
wait $launch || true

# 2. Replay: a master, sim time, the table's URDF, rviz, and the bag's clock.
xvfb-run -a -s "-screen 0 1280x900x24" bash -c "
  roscore -p 11396 > '$CUE_SIM_BUILD/replay_core.log' 2>&1 &
  core=\$!
  trap 'kill \$core 2>/dev/null; wait \$core 2>/dev/null' EXIT
  for i in \$(seq 40); do rosparam list > /dev/null 2>&1 && break; sleep 0.25; done
  rosparam set use_sim_time true
  rosparam set robot_description -t '$CUE_SIM_ROOT/urdf/table_7ft.urdf'
  rviz -d '$CUE_SIM_ROOT/rviz/table.rviz' > '$CUE_SIM_BUILD/replay_rviz.log' 2>&1 &
  sleep 6
  # Start 0.5 s before the first event (the cue ball meets the rack), and take the picture about
  # 1.5 s into the playback (rosbag play waits a little before it starts; the markers, sent
  # every second, come in on the way).
  start=\$(python3 - '$bag' <<'PY'
import sys, rosbag
bag = rosbag.Bag(sys.argv[1])
events = [t for _, _, t in bag.read_messages(topics=['/table/events'])]
first = bag.get_start_time()
print(max(0.0, min(t.to_sec() for t in events) - first - 0.5) if events else 0)
PY
)
  rosbag play --clock -s \$start '$bag' > '$CUE_SIM_BUILD/replay_play.log' 2>&1 &
  sleep 2.2
  import -window root '$out'
"
echo "screenshot: $out"
