# Sourced by the scripts: the environment a catkin build and ROS tools need on Debian 12.
# Debian's python modules live under /usr/bin/python3; a pyenv python3 first on PATH lacks them.
CUE_SIM_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export CUE_SIM_ROOT
export CUE_SIM_BUILD="${CUE_SIM_BUILD:-$CUE_SIM_ROOT/build}"
# The devel space sits beside build/, not in it: rosrun ignores executables under <package>/build/.
export CUE_SIM_DEVEL="${CUE_SIM_DEVEL:-$CUE_SIM_ROOT/devel}"
export PATH="/usr/bin:$PATH"
export ROS_MASTER_URI="${ROS_MASTER_URI:-http://localhost:11311}"
export ROS_HOSTNAME="${ROS_HOSTNAME:-localhost}"
export ROS_HOME="${ROS_HOME:-$CUE_SIM_BUILD/ros_home}"
export ROS_LOG_DIR="${ROS_LOG_DIR:-$ROS_HOME/log}"
export ROSCONSOLE_STDOUT_LINE_BUFFERED=1

cue_sim_source_devel() {
  # The generated setup reads unset variables.
  set +u
  # shellcheck disable=SC1091
  source "$CUE_SIM_DEVEL/setup.bash"
  set -u
  # A standalone package build leaves its source out of ROS_PACKAGE_PATH: add it.
  case ":${ROS_PACKAGE_PATH:-}:" in
    *":$CUE_SIM_ROOT:"*) ;;
    *) export ROS_PACKAGE_PATH="$CUE_SIM_ROOT${ROS_PACKAGE_PATH:+:$ROS_PACKAGE_PATH}" ;;
  esac
}

# A ROS master of the calling script's own on port $1 ($2 names its log), and everything the
# script adds to cue_sim_pids, stopped when the script exits.
cue_sim_private_master() {
  export ROS_MASTER_URI="http://localhost:$1"
  mkdir -p "$ROS_LOG_DIR"
  cue_sim_pids=()
  trap cue_sim_stop_all EXIT
  roscore -p "$1" > "$ROS_LOG_DIR/$2_core.log" 2>&1 &
  cue_sim_pids+=($!)
  for _ in $(seq 100); do rosparam list > /dev/null 2>&1 && break; sleep 0.2; done
}
cue_sim_stop_all() {
  # The last started first, the master last: a rospy node whose master dies beside it can hang in
  # its shutdown, unregistering (cue_frame_load.sh's tf publisher did, stalling CI on 2026-11-29).
  local k p s state
  for ((k = ${#cue_sim_pids[@]} - 1; k >= 0; k--)); do kill "${cue_sim_pids[k]}" 2>/dev/null || true; done
  # Each gets 10 s to end, then SIGKILL: a script never waits for ever.
  for _ in $(seq 100); do
    state=""
    for p in "${cue_sim_pids[@]}"; do
      s=$(awk '{ print $3 }' "/proc/$p/stat" 2>/dev/null || true)
      [ -n "$s" ] && [ "$s" != Z ] && state=running
    done
    [ -z "$state" ] && break
    sleep 0.1
  done
  for p in "${cue_sim_pids[@]}"; do kill -9 "$p" 2>/dev/null || true; done
  # Only those: a child the script did not list must not hold its exit for ever.
  wait "${cue_sim_pids[@]}" 2>/dev/null || true
}

# A screenshot of rviz: the table launched with rviz under Xvfb (its master on port $1, more
# launch arguments in $2), once its services and rviz are up the commands $3 run in that
# display's shell, then the screen goes to $4. $CUE_SIM_SCREENSHOT_LAUNCH names another launch
# file that starts the table with rviz (robot.launch).
cue_sim_rviz_screenshot() {
  local port="$1" launch_args="$2" commands="$3" out="$4"
  local launch_file="${CUE_SIM_SCREENSHOT_LAUNCH:-table.launch}"
  ROS_MASTER_URI="http://localhost:$port" xvfb-run -a -s "-screen 0 1280x900x24" bash -c "
    roslaunch cue_sim $launch_file rviz:=true $launch_args > '$CUE_SIM_BUILD/screenshot_$port.log' 2>&1 &
    launch=\$!
    trap 'kill \$launch 2>/dev/null; wait \$launch 2>/dev/null' EXIT
    for i in \$(seq 60); do rosservice list 2>/dev/null | grep -q /table/predict_batch && break; sleep 0.5; done
    sleep 6   # rviz start-up
    $commands
    import -window root '$out'
  "
  echo "screenshot: $out"
}
