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
