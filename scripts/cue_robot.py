#!/usr/bin/python3
"""An example cue robot's controller (urdf/gantry_cue.urdf, launch/robot.launch).

Takes a shot on play (in its namespace: /cue_robot/play in robot.launch) (cue_sim/Strike: ball_id, speed, phi, theta, a, b), works out where the
cue must pass to make it (the axis through the ball's centre offset by a and b, as the table
node's ~strike_cue reads a pose), and drives the gantry there: it lifts the cue, travels over the
table, lowers it behind the ball, and strokes: a uniform acceleration to the speed at the touch,
then a follow-through that slows to a stop. It publishes joint_states at ~rate all the while
(robot_state_publisher turns them into tf, the table node follows the frame cue_tip), and, once
the cue is lifted clear again, answers with what the table reported of the touch (~cue_contacts).
~joint_noise adds Gaussian noise of that standard deviation [m or rad] to every joint position
published, as an encoder's would be;
~settle [s] is how long the cue rests behind the ball before it strokes.

  rosrun cue_sim cue_robot.py _rate:=1000
  rosservice call /cue_robot/play "{ball_id: 0, speed: 2.0, phi: 0.0, theta: 0.1, a: 0.0, b: 0.2}"
"""
import math
import threading

import numpy as np
import rospy
from cue_sim.msg import BallState, CueContact, TableState
from cue_sim.srv import Strike, StrikeResponse
from sensor_msgs.msg import JointState

JOINTS = ["gantry_x", "gantry_y", "gantry_z", "cue_yaw", "cue_pitch", "cue_stroke"]
# From the wrist (yaw over pitch) to the tip's end along the cue at cue_stroke 0 [m]: the URDF's
# cue_stroke origin.
REACH = 0.35
# The stroke joint's travel [m] (URDF limits), and the share of it a stroke may use either side.
STROKE_LOWER, STROKE_UPPER = -0.5, 0.3
PITCH_LOWER, PITCH_UPPER = -0.2, 1.5
Z_LOWER, Z_UPPER = 0.0, 1.5
# Where the cue waits and travels: the wrist this high over the cloth [m], the stroke drawn in.
PARKED = [0.0, -0.6, 1.0, 0.0, 0.3, -0.3]
# Durations of the moves around a stroke [s], each a smooth (cosine) blend of the joints; the cue
# rests behind the ball for ~settle (0.4 s) before it strokes.
LIFT, TRAVEL, LOWER, HOLD = 0.6, 1.2, 0.8, 0.4
# The stroke: accelerating over at most ACCELERATE s, following through over at most FOLLOW s,
# shorter for hard shots so that the stroke axis's travel holds them.
ACCELERATE, FOLLOW = 0.15, 0.10
# How long a shot waits for the table's ~state stamped after it was asked for [s].
STATE_PATIENCE = 5.0


def cue_line(ball, shot, R, r_tip):
    """The cue's axis u and the end of its tip when the tip (a sphere of r_tip, its front at the
    end) first touches the ball: the stroke reaches its speed there."""
    u = np.array([math.cos(shot.theta) * math.cos(shot.phi), math.cos(shot.theta) * math.sin(shot.phi),
                  -math.sin(shot.theta)])
    right = np.cross(u, [0.0, 0.0, 1.0])
    right = right / np.linalg.norm(right) if np.linalg.norm(right) > 1e-12 else np.array([0.0, -1.0, 0.0])
    up = np.cross(right, u)
    # The tip touches at a / (1 + r_tip / R) of the axis's offset from the centre (PHYSICS.md).
    offset = R * (1 + r_tip / R) * (shot.a * right + shot.b * up)
    # The sphere's centre, r_tip behind the end, is R + r_tip from the ball's centre.
    behind = math.sqrt(max(0.0, (R + r_tip) ** 2 - offset.dot(offset)))
    return u, ball + offset - u * (behind - r_tip)


class StrokePlan:
    """The stroke joint's position over time: drawn back, accelerating uniformly to `speed` at the
    touch (t = touch), then slowing uniformly to a stop."""

    def __init__(self, speed):
        self.speed = speed
        self.accelerate = min(ACCELERATE, 2 * 0.9 * -STROKE_LOWER / speed)
        self.follow = min(FOLLOW, 2 * 0.9 * STROKE_UPPER / speed)
        self.drawn = 0.5 * speed * self.accelerate
        self.touch = self.accelerate

    def at(self, t):
        if t < 0:
            return -self.drawn
        if t < self.touch:
            return -self.drawn + 0.5 * (self.speed / self.accelerate) * t * t
        u = min(t - self.touch, self.follow)
        return self.speed * u - 0.5 * (self.speed / self.follow) * u * u

    def duration(self):
        return self.touch + self.follow


def blend(a, b, s):
    """Joints a to b, s in [0, 1] of the way, starting and stopping smoothly."""
    w = 0.5 - 0.5 * math.cos(math.pi * min(max(s, 0.0), 1.0))
    return [x + (y - x) * w for x, y in zip(a, b)]


class Motion:
    """Joint positions as a function of time: a list of (duration, function of the time into it)."""

    def __init__(self, start):
        self.pieces = []
        self.end = list(start)

    def move(self, to, duration):
        origin = list(self.end)
        self.pieces.append((duration, lambda t: blend(origin, to, t / duration)))
        self.end = list(to)

    def stroke(self, joints, plan):
        def at(t):
            q = list(joints)
            q[5] = plan.at(t)
            return q
        self.pieces.append((plan.duration(), at))
        self.end = at(plan.duration())

    def hold(self, duration):
        q = list(self.end)
        self.pieces.append((duration, lambda t: q))

    def at(self, t):
        for duration, piece in self.pieces:
            if t < duration:
                return piece(t)
            t -= duration
        return list(self.end)

    def duration(self):
        return sum(d for d, _ in self.pieces)


class CueRobot:
    def __init__(self):
        self.rate = rospy.get_param("~rate", 1000.0)
        self.noise = rospy.get_param("~joint_noise", 0.0)
        self.table = rospy.get_param("~table", "/table")
        self.settle = rospy.get_param("~settle", 0.4)
        if not 1.0 <= self.rate <= 5000.0:
            raise ValueError("~rate must be in [1, 5000] Hz, got %s" % self.rate)
        if not 0.0 <= self.noise <= 0.01:
            raise ValueError("~joint_noise must be in [0, 0.01] m or rad, got %s" % self.noise)
        if not 0.0 <= self.settle <= 60.0:
            raise ValueError("~settle must be in [0, 60] s, got %s" % self.settle)
        self.R = rospy.get_param(self.table + "/ball_radius")
        self.r_tip = rospy.get_param(self.table + "/cue_tip_radius")
        self.random = np.random.default_rng(rospy.get_param("~seed", 0))
        self.lock = threading.Lock()
        self.motion = Motion(PARKED)
        self.motion_start = rospy.Time.now()
        self.state = None
        self.contacts = []
        self.joints = rospy.Publisher("joint_states", JointState, queue_size=10, tcp_nodelay=True)
        rospy.Subscriber(self.table + "/state", TableState, self.on_state, queue_size=1)
        rospy.Subscriber(self.table + "/cue_contacts", CueContact, self.on_contact, queue_size=100)
        self.busy = threading.Lock()
        rospy.Service("play", Strike, self.on_play)

    def on_state(self, message):
        self.state = message

    def on_contact(self, message):
        with self.lock:
            self.contacts.append(message)

    def publish_forever(self):
        pace = rospy.Rate(self.rate)
        message = JointState(name=JOINTS)
        while not rospy.is_shutdown():
            now = rospy.Time.now()
            with self.lock:
                q = self.motion.at((now - self.motion_start).to_sec())
            if self.noise > 0:
                q = [x + self.random.normal(0.0, self.noise) for x in q]
            message.header.stamp = now
            message.position = q
            self.joints.publish(message)
            try:
                pace.sleep()
            except rospy.ROSInterruptException:
                return

    def why_not(self, shot, ball):
        if ball is None:
            return "ball_id %d is not on the table" % shot.ball_id
        if not 0 < shot.speed <= 12:
            return "speed must be in (0, 12] m/s, got %g" % shot.speed
        if not 0 <= shot.theta <= PITCH_UPPER:
            return "theta must be in [0, %g] rad (the pitch joint's reach), got %g" % (PITCH_UPPER, shot.theta)
        if math.hypot(shot.a, shot.b) > 0.5:
            return "a and b must lie within 0.5 R of the centre, got (%g, %g)" % (shot.a, shot.b)
        return ""

    def plan(self, shot, ball):
        """The joints at the touch, and the stroke's plan, or why the gantry cannot reach them."""
        u, tip = cue_line(ball, shot, self.R, self.r_tip)
        wrist = tip - u * REACH
        if not Z_LOWER <= wrist[2] <= Z_UPPER:
            return None, None, "the wrist would be %.3f m over the cloth, outside [%g, %g]" % (wrist[2], Z_LOWER, Z_UPPER)
        return [wrist[0], wrist[1], wrist[2], shot.phi, shot.theta, 0.0], StrokePlan(shot.speed), ""

    def on_play(self, request):
        shot = request
        if not self.busy.acquire(blocking=False):
            return StrikeResponse(success=False, message="the robot is playing a shot")
        try:
            # The balls as they are now, not as a ~state from before the request had them (a table
            # racked or set just before the shot is asked for).
            asked = rospy.Time.now()
            deadline = rospy.get_time() + STATE_PATIENCE
            while (self.state is None or self.state.header.stamp <= asked) and rospy.get_time() < deadline:
                rospy.sleep(0.005)
            state = self.state
            if state is None or state.header.stamp <= asked:
                return StrikeResponse(success=False, message="no %s/state after the request in %g s"
                                      % (self.table, STATE_PATIENCE))
            if state.moving:
                return StrikeResponse(success=False, message="balls are still moving")
            balls = {b.id: b for b in state.balls if b.motion != BallState.POCKETED}
            b = balls.get(shot.ball_id)
            ball = None if b is None else np.array([b.position.x, b.position.y, b.position.z])
            why = self.why_not(shot, ball)
            if why:
                return StrikeResponse(success=False, message=why)
            touch, stroke, why = self.plan(shot, ball)
            if why:
                return StrikeResponse(success=False, message=why)
            ready = list(touch)
            ready[5] = stroke.at(-1.0)
            above = list(ready)
            above[2] = PARKED[2]
            with self.lock:
                here = self.motion.at((rospy.Time.now() - self.motion_start).to_sec())
                lifted = list(here)
                lifted[2] = PARKED[2]
                lifted[5] = PARKED[5]
                motion = Motion(here)
                motion.move(lifted, LIFT)
                motion.move(above, TRAVEL)
                motion.move(ready, LOWER)
                motion.hold(self.settle)
                motion.stroke(touch, stroke)
                motion.hold(HOLD)
                after = list(motion.end)
                after[2] = PARKED[2]
                after[5] = PARKED[5]
                motion.move(after, LIFT)
                start = rospy.Time.now()
                self.motion, self.motion_start = motion, start
                self.contacts = []
                touch_at = start + rospy.Duration(LIFT + TRAVEL + LOWER + self.settle + stroke.touch)
            rospy.loginfo("cue_robot: ball %d at %.2f m/s, phi %.3f, theta %.3f, a %.2f, b %.2f: touching in %.1f s",
                          shot.ball_id, shot.speed, shot.phi, shot.theta, shot.a, shot.b, (touch_at - start).to_sec())
            # The touch's report, or none within a second of when the stroke meets the ball.
            deadline = touch_at + rospy.Duration(1.0)
            contact = None
            while not rospy.is_shutdown() and rospy.Time.now() < deadline + rospy.Duration(motion.duration()):
                with self.lock:
                    if self.contacts:
                        contact = self.contacts[0]
                        break
                if rospy.Time.now() > deadline:
                    break
                rospy.sleep(0.01)
            # Answer once the cue is lifted clear: a caller that racks or places balls as soon as
            # the shot is answered must not put one under the follow-through or the retreating tip.
            done = start + rospy.Duration(motion.duration())
            while not rospy.is_shutdown() and rospy.Time.now() < done:
                rospy.sleep(0.01)
            if contact is None:
                return StrikeResponse(success=False, message="the table reported no touch of the cue")
            response = StrikeResponse(success=contact.struck, message=contact.message, stamp=contact.header.stamp)
            response.executed = contact.executed
            return response
        finally:
            self.busy.release()


def main():
    rospy.init_node("cue_robot")
    robot = CueRobot()
    rospy.loginfo("cue_robot: joint_states at %g Hz, joint noise %g; shots on %s", robot.rate, robot.noise,
                  rospy.resolve_name("play"))
    robot.publish_forever()


if __name__ == "__main__":
    main()
