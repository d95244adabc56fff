#!/usr/bin/env bash
# The README's run command: installs what is missing, builds, starts the simulator and plays
# an 8-ball break. With a display, rviz shows it and stays open until Ctrl-C; without one,
# the demo prints what happened and exits.
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
bash "$here/install_deps.sh"
source "$here/env.sh"
# Only what the demo runs: the node and the messages its shell and watch_shot.py use (test.sh
# builds the rest).
mkdir -p "$CUE_SIM_BUILD"
echo "cue_sim demo: building the node (log: $CUE_SIM_BUILD/demo_build.log)"
bash "$here/build.sh" table_node cue_sim_generate_messages > "$CUE_SIM_BUILD/demo_build.log" 2>&1 \
  || { tail -40 "$CUE_SIM_BUILD/demo_build.log"; exit 1; }
cue_sim_source_devel
mkdir -p "$ROS_LOG_DIR"

rviz=false
if [ -n "${DISPLAY:-}" ]; then rviz=true; fi
if [ -n "${CUE_SIM_RVIZ:-}" ]; then rviz="$CUE_SIM_RVIZ"; fi
echo "cue_sim demo: starting the table (rviz: $rviz)"
roslaunch cue_sim table.launch rviz:="$rviz" table:="${TABLE:-7ft}" rack:=eight > "$ROS_LOG_DIR/demo_launch.log" 2>&1 &
launch=$!
trap 'kill $launch 2>/dev/null; wait $launch 2>/dev/null || true' EXIT
for _ in $(seq 100); do
  rosservice list 2>/dev/null | grep -q '^/table/strike$' && break
  kill -0 $launch 2>/dev/null || { cat "$ROS_LOG_DIR/demo_launch.log"; exit 1; }
  sleep 0.2
done
[ "$rviz" = true ] && sleep 5  # let rviz come up
echo "cue_sim demo: breaking (cue ball, V0 = 8 m/s, 0.002 rad off +x) into the node's rack, jittered as a real rack is (~rack_jitter, seeded: every run the same)"
rosservice call /table/strike "{ball_id: 0, speed: 8.0, phi: 0.002, theta: 0.0, a: 0.0, b: 0.0}"
python3 "$here/watch_shot.py" 60
if [ "$rviz" = true ]; then
  echo "cue_sim demo: rviz stays open; try another shot, e.g."
  echo "  rosservice call /table/rack \"{layout: eight}\" && rosservice call /table/strike \"{ball_id: 0, speed: 6.0, phi: 0.02}\""
  echo "Ctrl-C to quit."
  wait $launch
fi
