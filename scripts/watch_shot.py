#!/usr/bin/python3
"""Follows /table/state until every ball rests, then prints where each ball ended up."""
import sys

import rospy
from cue_sim.msg import BallState, TableState

MOTION = {BallState.STATIONARY: "stationary", BallState.SPINNING: "spinning", BallState.SLIDING: "sliding",
          BallState.ROLLING: "rolling", BallState.POCKETED: "pocketed", BallState.AIRBORNE: "airborne",
          BallState.OFF_TABLE: "off the table", BallState.HELD: "held in the air",
          BallState.SUPPORTED: "on supports in the air", BallState.BEARING: "bearing a ball"}


def main():
    rospy.init_node("watch_shot", anonymous=True)
    timeout = float(sys.argv[1]) if len(sys.argv) > 1 else 60.0
    start = rospy.Time.now()
    last_report = [0.0]
    done = [None]

    def on_state(msg):
        t = (msg.header.stamp - start).to_sec()
        if t - last_report[0] >= 0.5:
            last_report[0] = t
            moving = sum(1 for b in msg.balls if b.motion in (BallState.SLIDING, BallState.ROLLING, BallState.AIRBORNE))
            pocketed = [b.id for b in msg.balls if b.pocketed]
            print(f"  t = {t:5.2f} s: {moving:2d} balls rolling, sliding or in the air, pocketed: {pocketed}", flush=True)
        if not msg.moving and t > 0.05:
            done[0] = msg

    rospy.Subscriber("/table/state", TableState, on_state)
    deadline = rospy.Time.now() + rospy.Duration(timeout)
    while not rospy.is_shutdown() and done[0] is None and rospy.Time.now() < deadline:
        rospy.sleep(0.05)
    if done[0] is None:
        print("watch_shot: the balls did not come to rest in time", file=sys.stderr)
        return 1
    print("  every ball at rest:")
    for b in sorted(done[0].balls, key=lambda b: b.id):
        where = f"in {b.pocket}" if b.pocketed else f"at ({b.position.x:+.3f}, {b.position.y:+.3f}) m"
        print(f"    ball {b.id:2d} {where}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
