#!/usr/bin/python3
# Plans a break-off shot with ~predict_batch: every heading round the cue ball at three speeds,
# all on the node's cores in one call; keeps the shot that pockets the most object balls without
# the cue ball, and strikes it. Run it next to a table: rosrun cue_sim plan_shots.py
import math

import rospy
from cue_sim.msg import Event, Shot
from cue_sim.srv import PredictBatch, Strike


def pocketed(prediction):  # object balls pocketed; -1 if the cue ball drops
    balls = [e.ball_id for e in prediction.events if e.kind == Event.POCKETED]
    return -1 if not prediction.success or 0 in balls else len(balls)


rospy.init_node("plan_shots")
rospy.wait_for_service("/table/predict_batch")
shots = [Shot(ball_id=0, speed=speed, phi=2 * math.pi * k / 72) for speed in (2.0, 4.0, 6.0) for k in range(72)]
answer = rospy.ServiceProxy("/table/predict_batch", PredictBatch)(shots=shots)
best = max(range(len(shots)), key=lambda i: pocketed(answer.predictions[i]))
shot = shots[best]
print("best of %d shots: speed %.1f m/s, phi %.3f rad, pockets %d"
      % (len(shots), shot.speed, shot.phi, pocketed(answer.predictions[best])))
result = rospy.ServiceProxy("/table/strike", Strike)(ball_id=0, speed=shot.speed, phi=shot.phi)
print(result.message)
