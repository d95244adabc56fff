#!/usr/bin/env bash
# `pip install .` as a learner would: a fresh virtual environment (with Debian's NumPy from the
# system's site packages: nothing is downloaded), the module built by CMake without ROS, and the
# environments' tests run from it with no ROS on the path. CI runs this once.
#
#   scripts/pip_route.sh [VENV_DIR]     (default: a temporary directory, removed at the end)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
venv="${1:-$(mktemp -d /tmp/cue_sim_venv.XXXXXX)}"
[ -n "${1:-}" ] || trap 'rm -rf "$venv"' EXIT
/usr/bin/python3 -m venv --system-site-packages "$venv"
echo "pip_route: pip install . into $venv"
"$venv/bin/python" -m pip install --no-deps --no-input --progress-bar off . 2>&1 | grep -v "^  Building\|^  Created\|^  Stored"
# Nothing of ROS or of the catkin build: the module must come from the venv.
env -u PYTHONPATH -u ROS_PACKAGE_PATH -u CMAKE_PREFIX_PATH -u LD_LIBRARY_PATH "$venv/bin/python" - <<'PY'
import cue_sim, cue_sim.envs
assert "/site-packages/" in cue_sim.__file__, cue_sim.__file__
env = cue_sim.envs.TableEnv("pot")
obs, _ = env.reset(seed=0)
print("pip_route: cue_sim from", cue_sim.__file__, "- a pot step:", env.step([0.3, 2.0])[1:4])
PY
cd test/python
env -u PYTHONPATH -u ROS_PACKAGE_PATH -u CMAKE_PREFIX_PATH -u LD_LIBRARY_PATH "$venv/bin/python" -m pytest \
  test_envs.py -q -p no:cacheprovider
