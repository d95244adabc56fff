#!/usr/bin/python3
"""The example cue robot strikes as asked (rostest: robot_agreement_100hz.test, _1khz.test).

robot.launch's gantry (urdf/gantry_cue.urdf, scripts/cue_robot.py, robot_state_publisher) plays
shots over the range of speed, elevation and offsets; the table node follows its cue_tip frame
in tf at the rate the test's launch file sets and strikes at the touch. Each strike must be the
one ~strike_cue makes for the cue's pose and velocity at the touch: the shot the controller aimed
(its kinematics put the cue there), speed within 1 %, angles within 1 mrad, offsets within 0.01 R.
"""
import math
import unittest

import rospy
import rostest
from geometry_msgs.msg import Point
from cue_sim.msg import CueContact, ExecutedShot, TableState
from cue_sim.srv import Rack, Strike

SPEED_SHARE, ANGLE, OFFSET = 0.01, 1e-3, 0.01
# (speed [m/s], phi [rad], theta [rad], a, b [R]): soft to a break's speed, level to steep, centre
# to the miscue limit's edge.
SHOTS = [
    (0.6, 0.3, 0.0, 0.0, 0.0),
    (2.0, -0.5, 0.1, 0.3, 0.2),
    (4.0, 2.8, 0.3, -0.35, 0.15),
    (7.0, 0.05, 0.05, 0.0, -0.4),
    (1.5, -2.2, 0.6, 0.2, 0.3),
]
BALL = (-0.2, 0.1)  # the cue ball, alone on the table


class RobotAgreement(unittest.TestCase):
    def setUp(self):
        rospy.wait_for_service("/table/rack", 60)
        rospy.wait_for_service("/cue_robot/play", 60)
        self.rack = rospy.ServiceProxy("/table/rack", Rack)
        self.play = rospy.ServiceProxy("/cue_robot/play", Strike)
        self.contacts, self.shots = [], []
        self.state = None
        subscribers = [rospy.Subscriber("/table/cue_contacts", CueContact, self.contacts.append),
                       rospy.Subscriber("/table/shots", ExecutedShot, self.shots.append),
                       rospy.Subscriber("/table/state", TableState, lambda m: setattr(self, "state", m))]
        # Connected before the first shot: a touch published before then would be missed.
        self.assertTrue(self.wait_for(lambda: all(s.get_num_connections() > 0 for s in subscribers)))

    def wait_for(self, condition, timeout=60.0):
        deadline = rospy.get_time() + timeout
        while not condition():
            if rospy.get_time() > deadline or rospy.is_shutdown():
                return condition()
            rospy.sleep(0.01)
        return True

    def touches_since(self, stamp):
        return [c for c in self.contacts if c.header.stamp > stamp]

    def test_each_strike_is_the_shot_the_robot_aimed(self):
        rate = rospy.get_param("~rate")
        for speed, phi, theta, a, b in SHOTS:
            # Each message says which shot (rosunit's report drops a subTest's).
            which = "at %g Hz, %g m/s, phi %g, theta %g, a %g, b %g: " % (rate, speed, phi, theta, a, b)
            racked = self.rack(layout="custom", ids=[0], positions=[Point(x=BALL[0], y=BALL[1], z=0.0)])
            self.assertTrue(racked.success, which + racked.message)
            self.assertTrue(self.wait_for(lambda: self.state is not None and self.state.header.stamp > racked.stamp
                                          and not self.state.moving), which + "the racked ball at rest")
            before = len(self.shots)
            answer = self.play(ball_id=0, speed=speed, phi=phi, theta=theta, a=a, b=b)
            self.assertTrue(answer.success, which + answer.message)
            # The robot answers from its own subscription to ~cue_contacts: this one's copy may come later.
            self.assertTrue(self.wait_for(lambda: self.touches_since(racked.stamp)), which + "a touch reported")
            touches = self.touches_since(racked.stamp)
            contact = touches[0]
            self.assertTrue(contact.struck, which + contact.message)
            shot = contact.shot
            self.assertEqual(shot.ball_id, 0, which)
            self.assertLess(abs(shot.speed - speed), SPEED_SHARE * speed, which + "speed %g" % shot.speed)
            self.assertLess(abs(math.remainder(shot.phi - phi, 2 * math.pi)), ANGLE, which + "phi %g" % shot.phi)
            self.assertLess(abs(shot.theta - theta), ANGLE, which + "theta %g" % shot.theta)
            self.assertLess(abs(shot.a - a), OFFSET, which + "a %g" % shot.a)
            self.assertLess(abs(shot.b - b), OFFSET, which + "b %g" % shot.b)
            self.assertTrue(self.wait_for(lambda: any(s.source == "cue_frame" for s in self.shots[before:])),
                            which + "the strike on ~shots from cue_frame")
            rospy.loginfo("robot at %g Hz: asked %.2f m/s theta %.3f a %.2f b %.2f; struck %.4f m/s phi %+.1e "
                          "theta %+.1e a %+.1e b %+.1e off", rate, speed, theta, a, b, shot.speed,
                          math.remainder(shot.phi - phi, 2 * math.pi), shot.theta - theta, shot.a - a, shot.b - b)

if __name__ == "__main__":
    rospy.init_node("robot_agreement")
    rostest.rosrun("cue_sim", "robot_agreement", RobotAgreement)
