#!/usr/bin/env bash
# Takes doc/rviz_game.png: rviz under Xvfb, an 8-ball game (or another ruleset's) in progress. The
# break, then the first player's next shot chosen from ~predict_batch as the game rostest's planner
# would (a legal pot if there is one), then a call for the shot after it, shown with the game's
# markers.
# Three-cushion runs the carom table, snooker the snooker table.
# Usage: scripts/screenshot_game.sh [output.png] [shots before the picture, default 3] [rules, default eight_ball]
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
out="$(realpath -m "${1:-$CUE_SIM_ROOT/doc/rviz_game.png}")"
shots="${2:-3}"
rules="${3:-eight_ball}"
launch_args=""
if [ "$rules" = three_cushion ]; then launch_args="table:=carom rack:=carom"; fi
if [ "$rules" = snooker ]; then launch_args="table:=snooker rack:=snooker"; fi
cue_sim_rviz_screenshot 11393 "$launch_args" "
  rosrun cue_sim play_game.py --rules $rules --shots $shots --preview > '$CUE_SIM_BUILD/screenshot_game_play.log' 2>&1
  sleep 1.5
" "$out"
