#!/usr/bin/python3
"""Plays with the table as a new user would in rviz, for a given time (scripts/rviz_quiet.sh):
racks, breaks, predictions (their previews), strikes from a cue pose, the aim marker dragged,
released (a prediction) and its menu's Strike, a game started and ended, pause, step and reset.
Prints what it did."""
import sys
import time

import rospy
from geometry_msgs.msg import Pose
from std_srvs.srv import SetBool
from visualization_msgs.msg import InteractiveMarkerFeedback

from std_srvs.srv import Trigger

from cue_sim.msg import Shot
from cue_sim.srv import Predict, PredictRequest, Rack, RackRequest, StartGame, StartGameRequest, Step, Strike, \
    StrikeRequest


def aim(feedback_pub, event, x=0.0, y=0.0, menu_entry=0):
    f = InteractiveMarkerFeedback()
    f.header.frame_id = "table"
    f.header.stamp = rospy.Time.now()
    f.client_id = "/rviz_quiet"
    f.marker_name = "aim"
    f.control_name = "aim"
    f.event_type = event
    f.menu_entry_id = menu_entry
    f.pose = Pose()
    f.pose.position.x, f.pose.position.y = x, y
    f.pose.orientation.w = 1.0
    feedback_pub.publish(f)


def main():
    seconds = float(sys.argv[1]) if len(sys.argv) > 1 else 60.0
    rospy.init_node("rviz_quiet_client")
    for name in ("rack", "strike", "predict", "reset", "pause", "step", "start_game", "end_game"):
        rospy.wait_for_service("/table/" + name, 30)
    rack = rospy.ServiceProxy("/table/rack", Rack)
    strike = rospy.ServiceProxy("/table/strike", Strike)
    predict = rospy.ServiceProxy("/table/predict", Predict)
    reset = rospy.ServiceProxy("/table/reset", Trigger)
    pause = rospy.ServiceProxy("/table/pause", SetBool)
    step = rospy.ServiceProxy("/table/step", Step)
    start_game = rospy.ServiceProxy("/table/start_game", StartGame)
    end_game = rospy.ServiceProxy("/table/end_game", Trigger)
    feedback = rospy.Publisher("/table/aim/feedback", InteractiveMarkerFeedback, queue_size=10)
    end = time.time() + seconds
    rounds = 0
    while time.time() < end and not rospy.is_shutdown():
        rack(RackRequest(layout="eight"))
        predict(PredictRequest(shot=Shot(ball_id=0, speed=3.0, phi=0.05, b=-0.3)))  # a preview
        time.sleep(1.0)
        strike(StrikeRequest(ball_id=0, speed=8.0, phi=0.002))  # clears the preview
        time.sleep(2.0)
        pause(True)
        step(duration=0.5)
        pause(False)
        reset()
        rack(RackRequest(layout="nine"))
        time.sleep(1.0)
        # The aim marker: dragged, released (a prediction), and its menu's Strike.
        aim(feedback, InteractiveMarkerFeedback.POSE_UPDATE, -0.2, 0.1)
        aim(feedback, InteractiveMarkerFeedback.MOUSE_UP, -0.2, 0.1)
        time.sleep(1.0)
        aim(feedback, InteractiveMarkerFeedback.MENU_SELECT, -0.2, 0.1, menu_entry=1)
        time.sleep(2.0)
        response = start_game(StartGameRequest(rules="nine_ball", players=["ann", "bob"]))
        time.sleep(1.0)
        rounds += 1
        print(f"rviz_quiet_client: round {rounds}: racked, previewed, broke, stepped, aimed, struck, game "
              f"{'started' if response.success else 'refused: ' + response.message}", flush=True)
        end_game()
    print(f"rviz_quiet_client: {rounds} rounds in {seconds:.0f} s", flush=True)


if __name__ == "__main__":
    main()
