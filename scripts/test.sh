#!/usr/bin/env bash
# The README's test command: installs what is missing, builds, and runs every test (gtest on
# the physics core and scene files, rostest on the node through a real ROS master).
set -euo pipefail
here="$(dirname "${BASH_SOURCE[0]}")"
bash "$here/install_deps.sh"
bash "$here/build.sh"
source "$here/env.sh"
cue_sim_source_devel
cd "$CUE_SIM_BUILD"
# Every rostest starts its own master on its own port.
ctest --output-on-failure -j2 "$@"
