#!/usr/bin/env bash
# Installs the Debian 12 packages cue_sim needs, only those missing. Needs root or sudo.
set -euo pipefail

PACKAGES=(
  # build
  g++ cmake make catkin python3-catkin-pkg ros-message-generation libeigen3-dev liburdfdom-dev
  libyaml-cpp-dev nlohmann-json3-dev libcli11-dev libgtest-dev libbenchmark-dev
  # ROS 1 (Debian's own packages, no /opt/ros)
  ros-message-runtime libroscpp-dev ros-std-msgs ros-geometry-msgs libstd-msgs-dev libgeometry-msgs-dev
  libvisualization-msgs-dev libros-rosgraph-msgs-dev libstd-srvs-dev ros-std-srvs libtf2-ros-dev libtf2-geometry-msgs-dev
  librosbag-dev librostest-dev rosout python3-rostest python3-roslaunch python3-rosbag python3-rosservice
  python3-std-srvs python3-rosgraph-msgs python3-rospy python3-rostopic python3-rosnode rosbash python3-geometry-msgs python3-tf2-msgs python3-visualization-msgs
  liburdfdom-tools libdynamic-reconfigure-config-init-mutex-dev python3-dynamic-reconfigure python3-yaml
  libinteractive-markers-dev
  # the Python module (pybind11, NumPy) and its tests
  pybind11-dev python3-dev python3-numpy python3-pytest python3-dask python3-distributed python3-matplotlib
  # the calibration: its solver (Ceres, each shot's unknowns eliminated by their Schur complement) and
  # the rest of its numerics (scipy: sparse Jacobians, the robust loss's scaling)
  libceres-dev python3-scipy
  # `pip install .` into a virtual environment (CI checks it; python3-venv brings pip's wheel)
  python3-venv python3-pip
  # the camera: rendering with OpenCV, images and calibrations through image_transport and
  # camera_info_manager; the detector example reads images with cv_bridge
  libopencv-dev libimage-transport-dev libcamera-info-manager-dev libsensor-msgs-dev ros-sensor-msgs
  libcv-bridge-dev python3-opencv python3-cv-bridge python3-sensor-msgs python3-tf2-ros image-transport-tools
  # the table as a nodelet (cue_sim/TableNodelet), and image_proc's nodelets beside it in one manager
  # (Debian 12 ships image_proc's nodelet_plugins.xml in libimage-proc-dev, not in ros-image-proc:
  # without it pluginlib knows no image_proc/rectify)
  libnodelet-dev libnodeletlib-dev libnodeletlib-tools python3-nodelet pluginlib-dev ros-image-proc libimage-proc0d
  libimage-proc-dev
  # the example cue robot (urdf/gantry_cue.urdf): its links in tf from its joint states
  ros-robot-state-publisher
  # rviz, and rviz without a screen (screenshots)
  rviz xvfb xauth imagemagick
  # plots of the work-precision report
  gnuplot-nox
  # instruction counts of the benchmark shots (scripts/callgrind_shots.sh), and the node's CPU
  # (scripts/node_load.sh finds it with pgrep, which minimal images lack)
  valgrind procps
)

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#PACKAGES[@]} packages present"
  exit 0
fi
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install_deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO="sudo"
fi
echo "install_deps: installing ${#missing[@]} packages: ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
