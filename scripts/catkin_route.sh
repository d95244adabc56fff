#!/usr/bin/env bash
# The README's catkin lines ("In a catkin workspace"), run as a new user runs them, on a fresh
# workspace, with a python3 first on PATH that lacks Debian's modules, as a pyenv shim would:
# catkin_make, catkin_make run_tests, catkin_test_results. Exits non-zero if any of them fails.
#   scripts/catkin_route.sh [--some] [workspace]     (default: a new one under /tmp, removed after)
# --some runs one test target of each kind instead of all of them (CI, which has run every test
# through the build route already and has 90 minutes for everything: the whole suite again took a
# quarter of them). What the catkin route adds is its own: the workspace's build, its devel space,
# the generated messages beside the module, and each kind of test target in it: a gtest, a rostest
# of the C++ node, a rostest of Python through the workspace's module, and a run_tests command.
set -euo pipefail
tests=(run_tests)
if [ "${1:-}" = "--some" ]; then
  tests=(run_tests_cue_sim_gtest_session_tests run_tests_cue_sim_rostest_test_node_table_node.test
         run_tests_cue_sim_rostest_test_node_same_answers.test run_tests_cue_sim_layers_check_layers)
  shift
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
ws="${1:-$(mktemp -d /tmp/cue_sim_ws.XXXXXX)}"
[ $# -ge 1 ] || trap 'rm -rf "$ws"' EXIT
shim="$ws/pyenv_shims"
mkdir -p "$ws/src" "$shim"
# A python3 without Debian's dist-packages: no catkin_pkg, no rospy.
printf '#!/bin/sh\nexec /usr/bin/python3 -S "$@"\n' > "$shim/python3"
chmod +x "$shim/python3"
export PATH="$shim:$PATH"
if python3 -c "import catkin_pkg" 2>/dev/null; then
  echo "catkin_route: the stand-in python3 should lack catkin_pkg" >&2
  exit 1
fi
ln -s "$root" "$ws/src/cue_sim"
cd "$ws"
python=(-DPYTHON_EXECUTABLE=/usr/bin/python3 -DPython3_EXECUTABLE=/usr/bin/python3)
echo "catkin_route: catkin_make in $ws (log: $ws/catkin_make.log)"
catkin_make "${python[@]}" > "$ws/catkin_make.log" 2>&1 || { tail -40 "$ws/catkin_make.log"; exit 1; }
echo "catkin_route: the Python module and the generated messages share the package cue_sim"
(set +u; source devel/setup.bash; /usr/bin/python3 -c "import cue_sim, cue_sim.msg, cue_sim.srv
e = cue_sim.Engine('9ft'); s = cue_sim.simulate(e, e.rack('nine'), speed=7.0, phi=0.003)
assert s.at_rest and len(s.events) > 20 and cue_sim.msg.BallState and cue_sim.srv.Predict, s
print('catkin_route: cue_sim imports from the workspace:', len(s.events), 'events in a 9-ball break')")
echo "catkin_route: catkin_make ${tests[*]} (log: $ws/run_tests.log)"
catkin_make "${tests[@]}" "${python[@]}" > "$ws/run_tests.log" 2>&1 || { tail -40 "$ws/run_tests.log"; exit 1; }
# --verbose: a failing test's whole result file (each failed assertion with its message) in the log.
catkin_test_results --verbose build/test_results
