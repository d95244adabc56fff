#!/usr/bin/python3
"""The same answers everywhere: scenes run through the Python module (cue_sim.simulate), the
`simulate` program and the node's ~predict give bit-identical events and states (rostest: a real
master and table node, see same_answers.test)."""
import json
import os
import subprocess
import sys
import unittest

import numpy as np
import rospy
import rostest
from geometry_msgs.msg import Point, Vector3

import cue_sim
from cue_sim.msg import BallState, Shot
from cue_sim.srv import Predict

SIMULATE = os.environ["CUE_SIM_SIMULATE"].split() if "CUE_SIM_SIMULATE" in os.environ else ["rosrun", "cue_sim",
                                                                                        "simulate"]


def scenes(engine):
    """(name, start State, strike, sample_period): breaks with and without spin, jittered racks, and
    balls already moving and spinning when the cue strikes."""
    moving = cue_sim.State.from_balls(
        [0, 3, 8, 12], [[-0.6, 0.1], [0.2, -0.25], [0.55, 0.05], [0.8, 0.3]],
        velocities=[[0.0, 0.0, 0.0], [0.4, 0.9, 0.0], [-0.3, 0.0, 0.0], [0.0, -1.2, 0.0]],
        spins=[[0.0, 0.0, 0.0], [5.0, -3.0, 20.0], [0.0, 10.5, 0.0], [42.0, 0.0, -7.0]])
    return [
        ("8-ball break", engine.rack("eight", gap=1e-5), dict(speed=8.0, phi=0.002), 0.0),
        ("9-ball break, follow and right English", engine.rack("nine", gap=1e-4, jitter=5e-5, seed=3),
         dict(speed=6.5, phi=-0.004, theta=0.12, a=0.21, b=0.28), 0.05),
        ("moving, spinning balls", moving, dict(speed=3.0, phi=0.3, theta=0.3, a=-0.3, b=-0.25), 0.02),
    ]


def ball_message(state, i):
    x, y, z = (float(v) for v in state.positions[i])
    vx, vy, vz = (float(v) for v in state.velocities[i])
    wx, wy, wz = (float(v) for v in state.spins[i])
    return BallState(id=int(state.ids[i]), position=Point(x, y, z), velocity=Vector3(vx, vy, vz),
                     angular_velocity=Vector3(wx, wy, wz))


def scene_yaml(start, strike):
    lines = ["table: 7ft", "balls:"]
    for i, ball in enumerate(start.ids):
        p, v, w = start.positions[i], start.velocities[i], start.spins[i]
        lines.append(f"  - {{id: {int(ball)}, position: [{p[0]!r}, {p[1]!r}], velocity: [{v[0]!r}, {v[1]!r}], "
                     f"angular_velocity: [{w[0]!r}, {w[1]!r}, {w[2]!r}]}}")
    lines.append("shot: {" + ", ".join(f"{k}: {float(v)!r}" for k, v in strike.items()) + "}")
    return "\n".join(lines) + "\n"


def as_floats(xyz):
    return [xyz.x, xyz.y, xyz.z]


class SameAnswers(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        rospy.init_node("same_answers", anonymous=True)
        rospy.wait_for_service("/table/predict", timeout=60)
        cls.predict = rospy.ServiceProxy("/table/predict", Predict)
        cls.engine = cue_sim.Engine("7ft")

    def check_states_equal(self, where, ids, positions, velocities, spins, motion, balls):
        by_id = {b.id: b for b in balls}
        self.assertEqual(sorted(by_id), sorted(int(i) for i in ids), where)
        for i, ball in enumerate(ids):
            theirs = by_id[int(ball)]
            self.assertEqual(list(positions[i]), as_floats(theirs.position), f"{where}: ball {ball} position")
            self.assertEqual(list(velocities[i]), as_floats(theirs.velocity), f"{where}: ball {ball} velocity")
            self.assertEqual(list(spins[i]), as_floats(theirs.angular_velocity), f"{where}: ball {ball} spin")
            self.assertEqual(int(motion[i]), theirs.motion, f"{where}: ball {ball} motion")

    def test_module_program_and_node_agree_bit_for_bit(self):
        for name, start, strike, period in scenes(self.engine):
            mine = cue_sim.simulate(self.engine, start, sample_period=period, **strike)
            self.assertTrue(mine.at_rest and len(mine.events) > 10, name)
            answer = self.predict(shot=Shot(ball_id=0, **strike), sample_period=period,
                                  balls=[ball_message(start, i) for i in range(len(start.ids))]).prediction
            self.assertTrue(answer.success, f"{name}: {answer.message}")

            # events: the node's and the module's
            self.assertEqual(len(answer.events), len(mine.events), name)
            for k, (e, theirs) in enumerate(zip(mine.events, answer.events)):
                where = f"{name}: event {k}"
                self.assertEqual(float(e["time"]), theirs.shot_time, where)
                self.assertEqual(int(e["kind"]), theirs.kind, where)
                self.assertEqual(int(e["ball"]), theirs.ball_id, where)
                self.assertEqual(int(e["other"]), theirs.other_ball_id, where)
                self.assertEqual(str(e["obstacle"]), theirs.obstacle, where)
            self.assertEqual(mine.time_to_rest, answer.time_to_rest, name)
            final = mine.final
            self.check_states_equal(f"{name}: final", final.ids, final.positions, final.velocities, final.spins,
                                    final.motion, answer.final_balls)

            # samples: every one
            if period > 0:
                self.assertEqual(answer.sample_period, period, name)
                self.assertEqual(len(answer.samples), len(mine.samples.times), name)
                for k, table in enumerate(answer.samples):
                    s = mine.samples
                    self.check_states_equal(f"{name}: sample {k}", final.ids, s.positions[k], s.velocities[k],
                                            s.spins[k], s.motion[k], table.balls)

            # the simulate program on the same scene
            out = subprocess.run(SIMULATE + ["-"], input=scene_yaml(start, strike), capture_output=True, text=True,
                                 timeout=60)
            self.assertEqual(out.returncode, 0, f"{name}: {out.stderr}")
            program = json.loads(out.stdout)
            self.assertEqual(len(program["events"]), len(mine.events), name)
            for k, (e, theirs) in enumerate(zip(mine.events, program["events"])):
                self.assertEqual(float(e["time"]), theirs["t"], f"{name}: program event {k}")
                self.assertEqual(int(e["ball"]), theirs["ball"], f"{name}: program event {k}")
            balls = {b["id"]: b for b in program["final_state"]["balls"]}
            for i, ball in enumerate(final.ids):
                self.assertEqual(list(final.positions[i]), balls[int(ball)]["position"], f"{name}: program ball {ball}")
            self.assertTrue(np.all(np.isfinite(final.positions)), name)


if __name__ == "__main__":
    rostest.rosrun("cue_sim", "same_answers", SameAnswers, sys.argv)
