#!/usr/bin/python3
"""cue_sim.envs.live: a task's episodes played on the live table node (rostest: a real master and
table node, see live_env.test). Every step's strike goes to the node through ~strike, and the node's
balls must come to rest exactly where the environment's twin has them."""
import sys
import unittest

import numpy as np
import rospy
import rostest

from cue_sim.envs.live import LiveTableEnv


class LiveEpisodes(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("live_env", anonymous=True)

    def play(self, env, episodes, seed):
        """Episodes of seeded random actions; the rewards and the steps taken."""
        env.action_space.seed(seed)
        rewards, steps = [], 0
        obs, _ = env.reset(seed=seed)
        for _ in range(episodes):
            done = False
            while not done:
                obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
                self.assertTrue(obs in env.observation_space)
                self.assertTrue(info["reason"])
                rewards.append(reward)
                steps += 1
                done = terminated or truncated
            obs, _ = env.reset()
        return rewards, steps

    def test_pot_runs_on_the_node_as_in_the_twin(self):
        env = LiveTableEnv("pot", balls=5, action="relative", max_shots=3, timeout=120)
        rewards, steps = self.play(env, 4, seed=2)
        self.assertGreaterEqual(steps, 4)
        env.close()

    def test_a_break_on_the_node(self):
        env = LiveTableEnv("break", rack="nine", timeout=120)
        obs, _ = env.reset(seed=5)
        # Full on the apex ball, hard: the node's 10 balls end where the twin's do (checked inside).
        table = env._twin.table()
        cue = table.positions[list(table.ids).index(0)]
        apex = table.positions[list(table.ids).index(1)]
        _, reward, terminated, _, info = env.step([np.arctan2(apex[1] - cue[1], apex[0] - cue[0]), 9.0])
        self.assertTrue(terminated)
        self.assertIn("WPA", info["reason"])
        env.close()

    def test_games_are_refused_with_a_reason(self):
        with self.assertRaisesRegex(ValueError, "live table plays"):
            LiveTableEnv("nine_ball")


if __name__ == "__main__":
    rostest.rosrun("cue_sim", "live_env", LiveEpisodes, sys.argv)
