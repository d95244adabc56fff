#!/usr/bin/env bash
# Takes doc/rviz_robot.png: robot.launch's gantry under Xvfb, its cue lowered behind the cue ball
# (the tip under `height` m in tf), resting there for 6 s before it strokes.
# Usage: scripts/screenshot_robot.sh [output.png] [height]
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
out="$(realpath -m "${1:-$CUE_SIM_ROOT/doc/rviz_robot.png}")"
height="${2:-0.12}"
CUE_SIM_SCREENSHOT_LAUNCH=robot.launch cue_sim_rviz_screenshot 11397 "settle:=6" "
  rosservice call /cue_robot/play '{ball_id: 0, speed: 6.0, phi: 0.0, theta: 0.12, a: 0.0, b: 0.1}' > /dev/null &
  python3 -c \"
import rospy, tf2_ros
rospy.init_node('await_cue', anonymous=True)
buffer = tf2_ros.Buffer()
tf2_ros.TransformListener(buffer)
while not rospy.is_shutdown():
    try:
        if buffer.lookup_transform('table', 'cue_tip', rospy.Time(0)).transform.translation.z < $height:
            break
    except tf2_ros.TransformException:
        pass
    rospy.sleep(0.01)
\"
  sleep 2   # rviz draws a frame a second on a busy machine
" "$out"
