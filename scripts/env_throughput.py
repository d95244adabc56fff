#!/usr/bin/env python3
"""How fast the learning environments step (doc/learning.md, "Throughput"), each figure beside
the engine's own cost for the same work:

  - the vector environment of each task, state observations (and pot with 96x48 pixels), steps per
    second on every core, beside one C++ environment's steps per second times the cores;
  - a single environment's Python overhead: TableEnv.step and reset from Python against the same
    episodes stepped in C++ alone (cue_sim._core.Env.time_steps);
  - the built-in opponent's cost per turn (eight_ball against the planner, less self-play);
  - with --instructions, the single environment's Python overhead in instructions, which a busy or
    drifting machine does not change: callgrind counts a loop of TableEnv.step and reset and the
    same episodes in C++ alone, each at two lengths, and the difference per step is the figure.

    /usr/bin/python3 scripts/env_throughput.py [--quick] [--threads N] [--instructions]
"""
import argparse
import os
import re
import shutil
import statistics
import subprocess
import sys
import time

import numpy as np

from cue_sim.envs import TableEnv, TableVectorEnv


def random_actions(space, count, seed):
    rng = np.random.default_rng(seed)
    return space.low + rng.random((count,) + space.shape) * (space.high - space.low)


def vector_rate(num_envs, threads, steps, **options):
    """Steps per second of a vector environment over `steps` calls of random actions."""
    envs = TableVectorEnv(num_envs, threads=threads, **options)
    envs.reset(seed=0)
    actions = [random_actions(envs.single_action_space, num_envs, k) for k in range(steps + 1)]
    envs.step(actions[0])  # warm: every table has had its first episode drawn
    begin = time.perf_counter()
    for a in actions[1:]:
        envs.step(a)
    return steps * num_envs / (time.perf_counter() - begin)


class _NoTable:
    """An environment that does nothing: what a learner's own loop costs around step and reset."""

    def __init__(self, observation):
        self._result = (observation, 0.0, True, False, {})

    def step(self, action):
        return self._result

    def reset(self):
        return self._result[0], {}


def _python_loop(env, actions):
    """Seconds per step of a learner's loop: step, and reset when an episode ends."""
    begin = time.perf_counter()
    for a in actions:
        _, _, terminated, truncated, _ = env.step(a)
        if terminated or truncated:
            env.reset()
    return (time.perf_counter() - begin) / len(actions)


def single_costs(steps, repeats, **options):
    """Per step [s]: the C++ environment alone, TableEnv from Python (step, and reset when an
    episode ends) on the same episodes, and the same loop around an environment that does nothing.
    They run in turns, `repeats` times each, on chunks of `steps` steps; the figures are medians,
    and Python's overhead the median of the turns' ratios (a machine's speed drifts over seconds,
    so that only runs side by side compare): with the learner's loop, and without it."""
    env = TableEnv(**options)
    actions = random_actions(env.action_space, steps, 1)
    nothing = _NoTable(env.reset(seed=0)[0])
    native, python, loop, ratios, own_ratios = [], [], [], [], []
    for _ in range(repeats):
        native.append(env._env.time_steps(actions, 5) / steps)
        env.reset(seed=5)
        python.append(_python_loop(env, actions))
        loop.append(_python_loop(nothing, actions))
        ratios.append(python[-1] / native[-1] - 1)
        own_ratios.append((python[-1] - loop[-1]) / native[-1] - 1)
    return statistics.median(native), statistics.median(ratios), statistics.median(own_ratios)


#: The tasks measured: (name, options, tables of the vector environment).
TASKS = [("pot", dict(task="pot"), 1024), ("pot, 96x48 pixels", dict(task="pot", observation="pixels"), 512),
         ("position", dict(task="position", balls=4), 512), ("break", dict(task="break"), 256),
         ("nine_ball self-play", dict(task="nine_ball", opponent="self"), 512),
         ("eight_ball self-play", dict(task="eight_ball", opponent="self"), 512),
         ("eight_ball vs planner", dict(task="eight_ball", opponent="planner"), 128)]


def run_counted_loop(name, mode, steps):
    """What the child under callgrind runs: `steps` steps of task `name`, in C++ alone (mode
    "native") or from Python (mode "python")."""
    options = next(o for n, o, _ in TASKS if n == name)
    env = TableEnv(**options)
    actions = random_actions(env.action_space, steps, 1)
    if mode == "native":
        env._env.time_steps(actions, 5)
    else:
        env.reset(seed=5)
        _python_loop(env, actions)


def counted_instructions(name, mode, steps):
    """Instructions callgrind counts in a child that runs run_counted_loop(name, mode, steps)."""
    command = ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", sys.executable, __file__,
               "--counted-loop", name, mode, str(steps)]
    # Symbols bound at load: lazy binding would count a lookup at each first call.
    done = subprocess.run(command, capture_output=True, text=True, env=dict(os.environ, LD_BIND_NOW="1"))
    found = re.search(r"I\s+refs:\s+([\d,]+)", done.stderr)
    if done.returncode != 0 or not found:
        raise RuntimeError(f"callgrind on {name} ({mode}) failed:\n{done.stderr[-2000:]}")
    return int(found.group(1).replace(",", ""))


def instruction_overheads(quick):
    """Per task: instructions a step in C++ alone, and Python's share over them (a fraction)."""
    if shutil.which("valgrind") is None:
        raise SystemExit("--instructions needs valgrind (scripts/install_deps.sh installs it)")
    print(f"{'task':<24} {'C++ alone [instr/step]':>23} {'Python overhead':>16}")
    for name, options, _ in TASKS[:1] if quick else TASKS:
        if "planner" in name:
            continue  # its turn costs a million instructions; Python's share is lost in them
        cheap = options["task"] in ("pot", "position")
        lengths = (100, 300) if quick else ((500, 3000) if cheap else (100, 600))
        print(f"{name:<24}", end=" ", flush=True)
        per_step = {}
        for mode in ("native", "python"):
            short, long = (counted_instructions(name, mode, n) for n in lengths)
            per_step[mode] = (long - short) / (lengths[1] - lengths[0])
        print(f"{per_step['native']:23,.0f} {100 * (per_step['python'] / per_step['native'] - 1):15.1f}%", flush=True)
    print("(callgrind's instruction counts: TableEnv.step and reset in a learner's loop, against the same episodes"
          " in cue_sim._core.Env.time_steps; each the difference of two loop lengths, so that loading is not counted)")


def opponent_turns(options, steps):
    """Mean opponent shots per agent step."""
    env = TableEnv(**options)
    env.reset(seed=3)
    env.action_space.seed(3)
    shots = 0
    for _ in range(steps):
        _, _, terminated, truncated, info = env.step(env.action_space.sample())
        shots += info["opponent_shots"]
        if terminated or truncated:
            env.reset()
    return shots / steps


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="a few steps of each (CI: that it runs)")
    parser.add_argument("--threads", type=int, default=0, help="threads of the vector environments (0: every core)")
    parser.add_argument("--instructions", action="store_true",
                        help="the single environment's Python overhead in callgrind's instruction counts")
    parser.add_argument("--counted-loop", nargs=3, metavar=("TASK", "MODE", "STEPS"), help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.counted_loop:
        name, mode, steps = args.counted_loop
        run_counted_loop(name, mode, int(steps))
        return 0
    if args.instructions:
        instruction_overheads(args.quick)
        return 0
    cores = args.threads or os.cpu_count()
    vector_steps, single_steps, repeats = (3, 500, 2) if args.quick else (20, 2000, 31)
    print(f"{'task':<24} {'vector steps/s':>15} {'C++ alone x ' + str(cores) + ' cores':>22} "
          f"{'Python overhead':>16} {'without the loop':>17}")
    costs = {}
    for name, options, num_envs in TASKS:
        print(f"{name:<24}", end=" ", flush=True)
        rate = vector_rate(num_envs if not args.quick else 16, args.threads, vector_steps, **options)
        native, overhead, own = single_costs(single_steps // (10 if "planner" in name else 1), repeats, **options)
        costs[name] = native
        print(f"{rate:15,.0f} {cores / native:22,.0f} {100 * overhead:15.0f}% {100 * own:16.0f}%", flush=True)
    per_turn = opponent_turns(dict(task="eight_ball", opponent="planner"), 20 if args.quick else 400)
    planner = (costs["eight_ball vs planner"] - costs["eight_ball self-play"]) / max(per_turn, 1e-9)
    print(f"the planner opponent: {per_turn:.2f} turns per agent step, {1e3 * planner:.2f} ms a turn "
          f"(one core), beside {1e6 * costs['eight_ball self-play']:.0f} us for a self-play step")
    print("(C++ alone: cue_sim._core.Env.time_steps, the same episodes without Python. Python overhead: TableEnv.step"
          " and reset in a learner's loop over that; without the loop: less the same loop around an environment that"
          " does nothing)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
