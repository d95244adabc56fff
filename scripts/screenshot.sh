#!/usr/bin/env bash
# Takes doc/rviz_break.png: rviz under Xvfb, the 8-ball break 0.35 s after the strike.
# Usage: scripts/screenshot.sh [output.png] [seconds after the strike]
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
out="$(realpath -m "${1:-$CUE_SIM_ROOT/doc/rviz_break.png}")"
delay="${2:-0.35}"
cue_sim_rviz_screenshot 11391 "" "
  rosservice call /table/strike '{ball_id: 0, speed: 8.0, phi: 0.002}' > /dev/null
  sleep $delay
" "$out"
