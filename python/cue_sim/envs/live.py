"""A task's episodes on the live table node (ROS): a policy trained in the vector environment,
played where rviz shows it and rosbag records it.

LiveTableEnv has TableEnv's API. Each reset draws the episode's table as TableEnv does and racks it
on the node (~rack, custom); each step works out the strike from the action (the execution noise
included), sends it to the node (~strike) and waits until the node's ~state says every ball is at
rest. A twin TableEnv on the node's own table and physics plays the same strike: the node's engine
is the same, so its balls must come to rest exactly where the twin's do, and the reward and the
rulings are the twin's. A table that differs raises, naming the ball.

In a game (eight_ball, nine_ball, ten_ball; three_cushion on a node running the carom table)
reset starts the same game on the node (~start_game: the rules, the rack's seed, who breaks, the
race) and every turn the twin plays, the opponent's too, goes to the node in order: the cue ball
placed in hand (~place_cue_ball), the call and push-out (~call_shot), the strike of the player's
own cue ball; each waits until the node's referee has finished the shot (~game_state). The node's table
must then be the twin's, the balls spotted and the cue ball returned as the twin's referee did.

Needs rospy and a running table_node with its noise off (~noise/enabled false: the noise is the
environment's).
"""
from __future__ import annotations

import threading
import time
from typing import Any, Optional

import numpy as np

from cue_sim.envs import task_names
from cue_sim.envs.table_env import TableEnv
from cue_sim.games import rules

#: The tasks the live table plays: every one; the games are the referee's rulesets.
LIVE_TASKS = tuple(task_names())
GAMES = tuple(rules())


class _Latest:
    """A topic's last message, and a condition to wait on for one that satisfies a test."""

    def __init__(self, topic, kind):
        import rospy
        self._condition = threading.Condition()
        self._msg = None
        self._subscriber = rospy.Subscriber(topic, kind, self._keep, queue_size=10)

    def _keep(self, msg):
        with self._condition:
            self._msg = msg
            self._condition.notify_all()

    def wait_for(self, ready, timeout):
        """The first ~state for which ready(msg) holds, within `timeout` seconds of wall time."""
        deadline = time.monotonic() + timeout
        with self._condition:
            while self._msg is None or not ready(self._msg):
                left = deadline - time.monotonic()
                if left <= 0:
                    raise TimeoutError(f"the table node did not come to the awaited state within {timeout} s")
                self._condition.wait(left)
            return self._msg

    def latest(self):
        with self._condition:
            return self._msg

    def close(self):
        self._subscriber.unregister()


def node_engine(namespace):
    """A cue_sim.Engine with the node's table, coefficients and contact models (its parameters)."""
    import rospy
    import cue_sim
    if rospy.has_param(namespace + "/urdf_file") and rospy.get_param(namespace + "/urdf_file"):
        table = rospy.get_param(namespace + "/urdf_file")
    else:
        table = rospy.get_param(namespace + "/table", "7ft")
    params = {name: float(rospy.get_param(f"{namespace}/{name}")) for name in cue_sim.parameters()
              if rospy.has_param(f"{namespace}/{name}")}
    return cue_sim.Engine(table, ball_ball_model=rospy.get_param(namespace + "/ball_ball_model", None),
                          cushion_model=rospy.get_param(namespace + "/cushion_model", None),
                          ball_table_model=rospy.get_param(namespace + "/ball_table_model", None),
                          cue_model=rospy.get_param(namespace + "/cue_model", None), **params)


class LiveTableEnv:
    """TableEnv's task, played on the table node at `namespace` (see the module's text)."""

    metadata = {"render_modes": []}

    def __init__(self, task: str = "pot", namespace: str = "/table", timeout: float = 120.0, **options: Any):
        import rospy
        from cue_sim.msg import GameState, TableState
        from cue_sim.srv import CallShot, PlaceCueBall, Rack, StartGame, Strike
        if task not in LIVE_TASKS:
            raise ValueError(f"task: the live table plays {', '.join(LIVE_TASKS)}, got {task!r}")
        if rospy.get_param(namespace + "/noise/enabled", False):
            raise ValueError(f"{namespace}/noise/enabled is true: the noise is the environment's; turn the node's off")
        self.namespace = namespace.rstrip("/")
        self.timeout = float(timeout)
        engine = node_engine(self.namespace)
        self._pocket_names = [name for name, _, _, _ in engine._engine.pockets]
        self._twin = TableEnv(task, engine=engine, **options)
        self._game = task in GAMES
        self.observation_space, self.action_space = self._twin.observation_space, self._twin.action_space
        self.action_names, self.observation_names = self._twin.action_names, self._twin.observation_names
        rospy.wait_for_service(self.namespace + "/rack", timeout=self.timeout)
        rospy.wait_for_service(self.namespace + "/strike", timeout=self.timeout)
        from std_srvs.srv import Trigger
        rospy.wait_for_service(self.namespace + "/end_game", timeout=self.timeout)
        self._end_game = rospy.ServiceProxy(self.namespace + "/end_game", Trigger)
        self._rack = rospy.ServiceProxy(self.namespace + "/rack", Rack)
        self._strike = rospy.ServiceProxy(self.namespace + "/strike", Strike)
        self._state = _Latest(self.namespace + "/state", TableState)
        if self._game:
            for name in ("start_game", "place_cue_ball", "call_shot"):
                rospy.wait_for_service(f"{self.namespace}/{name}", timeout=self.timeout)
            self._start_game = rospy.ServiceProxy(self.namespace + "/start_game", StartGame)
            self._place = rospy.ServiceProxy(self.namespace + "/place_cue_ball", PlaceCueBall)
            self._call = rospy.ServiceProxy(self.namespace + "/call_shot", CallShot)
            self._game_state = _Latest(self.namespace + "/game_state", GameState)

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        """The episode's table, drawn by the twin and racked on the node."""
        from geometry_msgs.msg import Point
        obs, info = self._twin.reset(seed=seed, options=options)
        if self._game:
            start = self._twin._env.game_start
            answer = self._start_game(rules=start["rules"], players=[], first_player=start["breaker"],
                                      seed=start["rack_seed"], target=start["target"], balls=[])
            if not answer.success:
                raise RuntimeError(f"{self.namespace}/start_game refused the episode's game: {answer.message}")
            self._shots = answer.state.shots
            self._play_turns()
        else:
            self._end_game()  # free play, if a game was on: the rack is the episode's
            table = self._twin.table()
            answer = self._rack(layout="custom", ids=[int(i) for i in table.ids],
                                positions=[Point(float(p[0]), float(p[1]), 0.0) for p in table.positions])
            if not answer.success:
                raise RuntimeError(f"{self.namespace}/rack refused the episode's table: {answer.message}")
        # The node's state before the rack may look alike (as many balls, at rest): wait for the
        # twin's table itself.
        try:
            self._state.wait_for(lambda msg: not msg.moving and self._difference(msg) is None, self.timeout)
        except TimeoutError:
            raise RuntimeError(f"{self.namespace} did not rack the episode's table: "
                               f"{self._difference(self._state.latest())}") from None
        return obs, info

    def step(self, action):
        """One strike on the node, to rest; the twin's observation, reward and info (equal to the
        node's table, which is checked)."""
        obs, reward, terminated, truncated, info = self._twin.step(action)
        if self._game:
            self._play_turns()
            return obs, reward, terminated, truncated, info
        struck = self._send_strike(self._twin._env.last_strike)
        # At rest in a state stamped after the strike: the shot is over on the node.
        msg = self._state.wait_for(lambda m: not m.moving and m.header.stamp > struck, self.timeout)
        difference = self._difference(msg)
        if difference is not None:
            raise RuntimeError(f"the node's table is not the twin's after the strike: {difference}")
        return obs, reward, terminated, truncated, info

    def _send_strike(self, strike, ball=0):
        speed, phi, theta, a, b = strike
        answer = self._strike(ball_id=ball, speed=speed, phi=phi, theta=theta, a=a, b=b)
        if not answer.success:
            raise RuntimeError(f"{self.namespace}/strike refused the strike: {answer.message}")
        return answer.stamp

    def _play_turns(self):
        """The turns the twin's last reset or step played, on the node's game in order; then the
        node's table must be the twin's."""
        from geometry_msgs.msg import Point
        for turn in self._twin._env.last_turns:
            if turn["placed"]:
                answer = self._place(position=Point(turn["x"], turn["y"], 0.0))
                if not answer.success:
                    raise RuntimeError(f"{self.namespace}/place_cue_ball refused the twin's placement: {answer.message}")
            if turn["called_ball"] >= 0 or turn["push_out"]:
                pocket = self._pocket_names[turn["called_pocket"]] if turn["called_pocket"] >= 0 else ""
                answer = self._call(ball=turn["called_ball"], pocket=pocket, push_out=turn["push_out"])
                if not answer.success:
                    raise RuntimeError(f"{self.namespace}/call_shot refused the twin's call: {answer.message}")
            struck = self._send_strike(turn["strike"], turn["ball"])
            self._shots += 1
            # The referee has ruled and the table is ready for the next shot, in a game state
            # stamped from the strike on: the last one seen may still be the last episode's game's.
            self._game_state.wait_for(lambda g, n=self._shots: g.header.stamp >= struck and g.shots >= n
                                      and not g.shot_in_progress, self.timeout)
        try:
            self._state.wait_for(lambda m: not m.moving and self._difference(m) is None, self.timeout)
        except TimeoutError:
            raise RuntimeError("the node's table is not the twin's after the game's turns: "
                               f"{self._difference(self._state.latest())}") from None

    def _difference(self, msg):
        """None if the node's balls in `msg` are the twin's as its last shot left them, exactly;
        else the first difference."""
        from cue_sim.api import State
        twin = State._of(self._twin._env.rest_table())
        by_id = {ball.id: ball for ball in msg.balls}
        if sorted(by_id) != sorted(int(i) for i in twin.ids):
            return f"the node has balls {sorted(by_id)}, the twin {sorted(int(i) for i in twin.ids)}"
        for i, ball in enumerate(twin.ids):
            theirs = by_id[int(ball)]
            pocketed = int(twin.motion[i]) == 4
            if theirs.pocketed != pocketed:
                return f"ball {ball} is {'' if theirs.pocketed else 'not '}pocketed on the node"
            where = np.array([theirs.position.x, theirs.position.y])
            if not pocketed and not np.array_equal(where, twin.positions[i][:2]):
                return f"ball {ball} rests at {where.tolist()} on the node and {twin.positions[i][:2].tolist()} on the twin"
        return None

    def close(self):
        """Leaves the node in free play (a game's episode ends its game) and stops listening."""
        if self._game:
            self._end_game()
            self._game_state.close()
        self._state.close()

    @property
    def unwrapped(self):
        return self
