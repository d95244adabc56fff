#!/usr/bin/env bash
# Takes doc/rviz_break.png: rviz under Xvfb, the 8-ball break 0.35 s after the strike.
# Usage: scripts/screenshot.sh [output.png] [seconds after the strike]
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
out="$(realpath -m "${1:-$CUE_SIM_ROOT/doc/rviz_break.png}")"
delay="${2:-0.35}"
export ROS_MASTER_URI=http://localhost:11391
xvfb-run -a -s "-screen 0 1280x900x24" bash -c "
  roslaunch cue_sim table.launch rviz:=true > '$CUE_SIM_BUILD/screenshot_launch.log' 2>&1 &
  launch=\$!
  trap 'kill \$launch 2>/dev/null; wait \$launch 2>/dev/null' EXIT
  rosservice wait /table/strike >/dev/null 2>&1 || sleep 1
  for i in \$(seq 60); do rosservice list 2>/dev/null | grep -q /table/strike && break; sleep 0.5; done
  sleep 6   # rviz start-up
  rosservice call /table/strike '{ball_id: 0, speed: 8.0, phi: 0.0}' > /dev/null
  sleep $delay
  import -window root '$out'
"
echo "screenshot: $out"
