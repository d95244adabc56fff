#!/usr/bin/env bash
# rviz without complaints: rviz (rviz/table.rviz) under Xvfb next to the table node for N seconds
# (default 60) while scripts/rviz_quiet_client.py racks, breaks, previews, steps, aims, strikes and
# starts games; then fails if rviz printed any error or warning, showing them.
# Usage: scripts/rviz_quiet.sh [seconds]
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
source "$here/env.sh"
cue_sim_source_devel
seconds="${1:-60}"
port=11394
log="$CUE_SIM_BUILD/rviz_quiet_rviz.log"
client_log="$CUE_SIM_BUILD/rviz_quiet_client.log"
ROS_MASTER_URI="http://localhost:$port" xvfb-run -a -s "-screen 0 1280x900x24" bash -c "
  roslaunch -p $port cue_sim table.launch rviz:=false > '$CUE_SIM_BUILD/rviz_quiet_node.log' 2>&1 &
  launch=\$!
  trap 'kill \$rviz \$launch 2>/dev/null; wait \$launch 2>/dev/null' EXIT
  for i in \$(seq 60); do rosservice list 2>/dev/null | grep -q /table/predict_batch && break; sleep 0.5; done
  rosrun rviz rviz -d '$CUE_SIM_ROOT/rviz/table.rviz' > '$log' 2>&1 &
  rviz=\$!
  # rviz started: subscribed to the table's markers (up to two minutes on a busy machine).
  for i in \$(seq 240); do rostopic info /table/markers 2>/dev/null | grep -q '/rviz' && break; sleep 0.5; done
  rostopic info /table/markers 2>/dev/null | grep -q '/rviz' || { echo 'rviz_quiet: rviz never subscribed'; cat '$log'; exit 1; }
  python3 '$here/rviz_quiet_client.py' '$seconds' > '$client_log' 2>&1 || { cat '$client_log'; exit 1; }
  sleep 2   # what rviz says about the last messages (a window to listen in, not a wait for a state)
  kill -0 \$rviz || { echo 'rviz_quiet: rviz died'; cat '$log'; exit 1; }
"
tail -n 1 "$client_log"
complaints="$(grep -iE 'error|warn' "$log" || true)"
if [ -n "$complaints" ]; then
  echo "rviz_quiet: rviz complained in $seconds s:"
  echo "$complaints" | sort | uniq -c | sort -rn | head -40
  exit 1
fi
echo "rviz_quiet: rviz printed no error or warning in $seconds s ($(wc -l < "$log") lines, $log)"
