#!/usr/bin/python3
"""cue_sim.envs.live: a task's episodes played on the live table node (rostest: a real master and
table node, see live_env.test). Every step's strike goes to the node through ~strike, and the node's
balls must come to rest exactly where the environment's twin has them."""
import sys
import threading
import time
import unittest
import xmlrpc.client

import numpy as np
import rospy
import rostest

import rosgraph
from cue_sim.envs.live import LiveTableEnv
from cue_sim.msg import Event

#: How long a condition is waited for, at most [s]: generous, for a busy machine.
GENEROUS_WAIT = 60.0


def messages_received_by(node, topic):
    """How many messages of `topic` the roscpp node `node` has received, by its own bus statistics
    (getBusStats, ROS's slave API); -1 if it has no connection for the topic yet."""
    try:
        uri = rosgraph.Master("/live_env").lookupNode(node)
        stats = xmlrpc.client.ServerProxy(uri).getBusStats("/live_env")
    except Exception:  # not registered yet
        return -1
    both = stats[2] if len(stats) == 3 and isinstance(stats[0], int) else stats
    for name, connections in both[1]:
        if name == topic:
            return sum(c[2] for c in connections) if connections else -1
    return -1


def wait_for(ready, timeout=GENEROUS_WAIT):
    deadline = time.monotonic() + timeout
    while not ready():
        if time.monotonic() > deadline:
            return False
        time.sleep(0.05)
    return True


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

    def test_pot_runs_on_the_node_as_in_the_twin_and_is_recorded(self):
        seen = []
        lock = threading.Lock()

        def keep(msg):
            with lock:
                seen.append(msg)
        subscriber = rospy.Subscriber("/table/events", Event, keep, queue_size=1000)
        self.assertTrue(wait_for(lambda: messages_received_by("/record", "/table/events") >= 0),
                        "rosbag's /record never connected to /table/events")
        self.assertTrue(wait_for(lambda: subscriber.get_num_connections() > 0))
        env = LiveTableEnv("pot", balls=5, action="relative", max_shots=3, timeout=120)
        rewards, steps = self.play(env, 4, seed=2)
        self.assertGreaterEqual(steps, 4)
        env.close()
        with lock:
            events = len(seen)
        self.assertGreater(events, steps, "every shot has events")
        # rosbag has every event this test saw (it writes what it receives).
        self.assertTrue(wait_for(lambda: messages_received_by("/record", "/table/events") >= events),
                        f"/record received {messages_received_by('/record', '/table/events')} of {events} events")
        subscriber.unregister()

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

    def test_games_play_on_the_node_as_in_the_twin(self):
        # Self-play 9-ball and 8-ball against the planner: placements, calls, push-outs and the
        # opponent's turns all go to the node's game, whose table must be the twin's after each step.
        for options in (dict(task="nine_ball", opponent="self", action="relative"),
                        dict(task="eight_ball", opponent="planner", action="relative", max_shots=12)):
            env = LiveTableEnv(timeout=120, **options)
            rewards, steps = self.play(env, 1, seed=4)
            self.assertGreater(steps, 1, options)
            env.close()

    def test_unknown_tasks_are_refused_with_a_reason(self):
        with self.assertRaisesRegex(ValueError, "live table plays"):
            LiveTableEnv("bagatelle")


if __name__ == "__main__":
    rostest.rosrun("cue_sim", "live_env", LiveEpisodes, sys.argv)
