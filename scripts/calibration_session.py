#!/usr/bin/python3
"""A calibration session on the live table (ROS node): shots for cue_sim.calibrate to fit.

Sets the table (~set_state) for each shot, strikes it (~strike), and waits until every ball rests
(~state) before the next, so that a recording (launch/calibration_record.launch) holds each shot
whole. Two kinds of session:

- ``_repeat:=false`` (default): `~shots` shots, each from a random layout of `~balls` balls, the
  cue ball struck towards one of the others at 1 to 3 m/s with draw or follow
  (cue_sim.calibrate.synthetic.random_shot): cushion and ball-ball contacts for the physics fit;
- ``_repeat:=true``: the same layout and the same commanded shot `~shots` times (a robot's
  repeatability test): for the execution-noise fit.

  rosrun cue_sim calibration_session.py _shots:=20 _seed:=1 [_table:=7ft] [_repeat:=true]

On a real table the robot plays the shots; this script stands in for it on the simulated one.
"""
import sys
import threading

import numpy as np
import rospy

from cue_sim.msg import BallState, TableState
from cue_sim.srv import SetState, Strike, StrikeRequest


class RestWatch:
    """The table's last state, to wait until it rests after a given stamp."""

    def __init__(self, topic):
        self.condition = threading.Condition()
        self.last = None
        rospy.Subscriber(topic, TableState, self.on_state, queue_size=10)

    def on_state(self, state):
        with self.condition:
            self.last = state
            self.condition.notify_all()

    def wait_rest(self, after, deadline):
        """True once a state stamped after `after` shows no ball moving, before `deadline` (wall s)."""
        end = rospy.get_time() + deadline
        with self.condition:
            while not rospy.is_shutdown():
                if self.last is not None and self.last.header.stamp > after and not self.last.moving:
                    return True
                remaining = end - rospy.get_time()
                if remaining <= 0:
                    return False
                self.condition.wait(min(remaining, 0.5))
        return False


def ball_states(positions, radius):
    out = []
    for i, (x, y) in enumerate(positions):
        b = BallState()
        b.id = i
        b.position.x, b.position.y, b.position.z = float(x), float(y), radius
        out.append(b)
    return out


def main():
    rospy.init_node("calibration_session")
    from cue_sim.api import Engine
    from cue_sim.calibrate.synthetic import random_shot
    table_ns = rospy.get_param("~table_ns", "/table")
    shots = int(rospy.get_param("~shots", 10))
    balls = int(rospy.get_param("~balls", 3))
    repeat = bool(rospy.get_param("~repeat", False))
    rng = np.random.default_rng(int(rospy.get_param("~seed", 0)))
    engine = Engine(rospy.get_param("~table", "7ft"))
    radius = engine.params["ball_radius"]
    rospy.wait_for_service(table_ns + "/strike", timeout=60)
    set_state = rospy.ServiceProxy(table_ns + "/set_state", SetState)
    strike = rospy.ServiceProxy(table_ns + "/strike", Strike)
    watch = RestWatch(table_ns + "/state")
    shot = None
    for i in range(shots):
        if not repeat or shot is None:
            layout, commanded = random_shot(engine, rng, i, balls)
            shot = StrikeRequest(ball_id=0, theta=0.0, a=0.0, **commanded)
        placed = set_state(ball_states(layout, radius))
        if not placed.success:
            rospy.logerr("calibration_session: ~set_state refused: %s", placed.message)
            return 1
        # The strike comes once the placed table is on ~state, so a recording sees it stand.
        watch.wait_rest(placed.stamp, 30.0)
        rospy.sleep(0.5)
        answer = strike(shot)
        if not answer.success:
            rospy.logerr("calibration_session: ~strike refused: %s", answer.message)
            return 1
        print(f"calibration_session: shot {i + 1} of {shots}: {shot.speed:.2f} m/s, phi {shot.phi:.3f}, b {shot.b:.2f}; "
              f"{answer.num_events} events, {answer.time_to_rest:.1f} s to rest", flush=True)
        if not watch.wait_rest(answer.stamp, answer.time_to_rest + 60.0):
            rospy.logerr("calibration_session: the table did not come to rest")
            return 1
        rospy.sleep(0.3)  # a few frames of the balls at rest close the shot's track
    print("calibration_session: done", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
