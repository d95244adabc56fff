#!/usr/bin/env bash
# Takes doc/rviz_preview.png: rviz under Xvfb after ~predict (the paths of the prediction) and a
# strike from a cue pose (~strike_cue: the cue stick), taken while paused with sim time so that
# the picture holds the strike's instant. The table runs until rviz is up: rviz takes the
# balls' frames from tf, which a paused table does not publish.
# Usage: scripts/screenshot_preview.sh [output.png]
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
out="$(realpath -m "${1:-$CUE_SIM_ROOT/doc/rviz_preview.png}")"
cue_sim_rviz_screenshot 11392 "use_sim_time:=true" "
  rosservice call /table/pause '{data: true}' > /dev/null
  # A cut on the 1 ball, with draw and a little left English.
  rosservice call /table/predict '{shot: {ball_id: 0, speed: 3.0, phi: 0.05, theta: 0.1, a: -0.1, b: -0.3}}' > /dev/null
  # The cue ball sits at (-0.4953, 0) (the head spot); the cue comes in along phi = 0.05, its
  # tip 3 cm short, level with the centre.
  rosservice call /table/strike_cue '{cue: {header: {frame_id: table}, pose: {position: {x: -0.5538, y: -0.0029, z: 0.028575}, orientation: {x: 0, y: 0, z: 0.0249974, w: 0.9996875}}}, speed: 3.0}' > /dev/null
  rosservice call /table/step '{duration: 0.02}' > /dev/null
  sleep 2
" "$out"
