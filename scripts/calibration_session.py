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
      [_tracker:=/detect_balls/detections]

With ``_tracker`` (a tracker's geometry_msgs/PoseArray detections, stamped with their images), each
shot waits until the tracker has caught up with the camera to the moment the last one came to rest:
a tracker slower than the camera on a busy machine then begins each shot with its queue empty, and
drops no image for want of room (seen without: 61 of a fourth shot's 285 images).

On a real table the robot plays the shots; this script stands in for it on the simulated one.
"""
import sys
import threading
import time

import numpy as np
import rospy

from geometry_msgs.msg import PoseArray

from cue_sim.msg import BallState, TableState
from cue_sim.srv import SetState, Strike, StrikeRequest


#: How long a shot waits for a lagging tracker [wall s]: a few shots' images at half speed.
TRACKER_PATIENCE = 120.0


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
        """The first state stamped after `after` that shows no ball moving, or None if none comes
        before `deadline` (s)."""
        end = rospy.get_time() + deadline
        with self.condition:
            while not rospy.is_shutdown():
                if self.last is not None and self.last.header.stamp > after and not self.last.moving:
                    return self.last
                remaining = end - rospy.get_time()
                if remaining <= 0:
                    return None
                self.condition.wait(min(remaining, 0.5))
        return None


class TrackerWatch:
    """The stamp of a tracker's latest detections, to wait until it has caught up with an instant."""

    def __init__(self, topic):
        self.condition = threading.Condition()
        self.latest = rospy.Time(0)
        rospy.Subscriber(topic, PoseArray, self.on_detections, queue_size=100)

    def on_detections(self, detections):
        with self.condition:
            self.latest = max(self.latest, detections.header.stamp)
            self.condition.notify_all()

    def wait_until(self, stamp, deadline):
        """True once detections stamped at or after `stamp` came, within `deadline` wall seconds (the
        tracker lags in wall time, whatever the table's clock does)."""
        end = time.monotonic() + deadline
        with self.condition:
            while not rospy.is_shutdown() and self.latest < stamp:
                remaining = end - time.monotonic()
                if remaining <= 0:
                    return False
                self.condition.wait(min(remaining, 0.5))
        return self.latest >= stamp


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
    tracker_topic = rospy.get_param("~tracker", "")
    tracker = TrackerWatch(tracker_topic) if tracker_topic else None
    rested = None
    shot = None
    for i in range(shots):
        if tracker is not None and rested is not None and not tracker.wait_until(rested, TRACKER_PATIENCE):
            rospy.logwarn("calibration_session: %s has not caught up with the camera in %.0f s; going on",
                          tracker_topic, TRACKER_PATIENCE)
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
        rest = watch.wait_rest(answer.stamp, answer.time_to_rest + 60.0)
        if rest is None:
            rospy.logerr("calibration_session: the table did not come to rest")
            return 1
        rested = rest.header.stamp
        rospy.sleep(0.3)  # a few frames of the balls at rest close the shot's track
    print("calibration_session: done", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
