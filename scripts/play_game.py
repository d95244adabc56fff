#!/usr/bin/python3
"""Plays a game of pool on table_node through its services, both players the same planner.

Each turn it asks ~predict_batch for the ghost-ball shot at every ball the player may hit first
into every pocket, at two speeds (and full at 8 m/s on a break), and strikes the one whose
predicted ruling is best: a win, then a legal pot, then a shot without a foul; the slower among
equals. The cue ball is played where the referee leaves it. With --preview it then calls the next
shot and draws its prediction in rviz without striking it.

Usage: rosrun cue_sim play_game.py [--rules eight_ball|nine_ball] [--shots N] [--seed S] [--preview]
"""
import argparse
import math
import sys
import time
import xml.etree.ElementTree as ET

import rospy
from cue_sim.msg import GameState, Shot, TableState
from cue_sim.srv import CallShot, Predict, PredictBatch, StartGame, Strike


def pocket_centres():
    """Each pocket's name and centre in the table frame, from the table description."""
    centres = {}
    for joint in ET.fromstring(rospy.get_param("/robot_description")).iter("joint"):
        child = joint.find("child").get("link")
        if child.startswith("pocket_"):
            x, y, _ = (float(v) for v in joint.find("origin").get("xyz").split())
            centres[child] = (x, y)
    return centres


class Latest:
    """The last message on a topic."""

    def __init__(self, topic, kind):
        self.msg = None
        rospy.Subscriber(topic, kind, self.keep)

    def keep(self, msg):
        self.msg = msg

    def when(self, ready, timeout=120.0):
        """The last message once `ready` says yes; the timeout is in wall time, as is the polling
        (with sim time as fast as possible, simulated seconds pass in milliseconds)."""
        deadline = time.monotonic() + timeout
        while not rospy.is_shutdown() and not (self.msg is not None and ready(self.msg)):
            if time.monotonic() > deadline:
                raise RuntimeError("timed out waiting for the table")
            time.sleep(0.01)
        return self.msg


def candidates(game, balls, pockets, radius):
    """(shot, ball, pocket) for each ghost-ball aim; pocket is empty for a full hit."""
    where = {b.id: (b.position.x, b.position.y) for b in balls.balls if not b.pocketed}
    cx, cy = where[0]
    shots = []
    for ball in game.legal_first:
        if ball not in where:
            continue
        bx, by = where[ball]
        for speed in ([8.0] if game.break_shot else []) + [2.0]:
            shots.append((Shot(ball_id=0, speed=speed, phi=math.atan2(by - cy, bx - cx)), ball, ""))
        for name, (px, py) in pockets.items():
            d = math.hypot(px - bx, py - by)
            gx, gy = bx - 2 * radius * (px - bx) / d, by - 2 * radius * (py - by) / d
            for speed in (1.5, 3.0):
                shots.append((Shot(ball_id=0, speed=speed, phi=math.atan2(gy - cy, gx - cx)), ball, name))
    return shots


def score(ruling, shooter, speed):
    if ruling.game_over:
        value = 1000 if ruling.winner == shooter else -1000
    else:
        value = 100 if (not ruling.foul and ruling.continues) else 10 if not ruling.foul else 0
    return value - speed


def best_shot(game, balls, pockets, radius, predict_batch):
    tried = candidates(game, balls, pockets, radius)
    batch = predict_batch(shots=[shot for shot, _, _ in tried])
    predictions = batch.predictions
    if not any(p.success for p in predictions):
        raise RuntimeError("no shot could be predicted: " + (predictions[0].message if predictions else batch.message))
    scored = [(score(p.ruling, game.turn, shot.speed), i) for i, (p, (shot, _, _)) in enumerate(zip(predictions, tried))
              if p.success]
    return tried[max(scored)[1]]


def main():
    parser = argparse.ArgumentParser(description="Plays a game of pool on table_node through its services.")
    parser.add_argument("--rules", default="eight_ball", choices=["eight_ball", "nine_ball"])
    parser.add_argument("--shots", type=int, default=-1, help="stop after this many shots (default: at the game's end)")
    parser.add_argument("--seed", type=int, default=0, help="the rack's jitter")
    parser.add_argument("--preview", action="store_true", help="at the end, call and preview the next shot")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("play_game", anonymous=True)
    for name in ("start_game", "call_shot", "strike", "predict", "predict_batch"):
        rospy.wait_for_service("/table/" + name, timeout=30)
    start_game = rospy.ServiceProxy("/table/start_game", StartGame)
    call_shot = rospy.ServiceProxy("/table/call_shot", CallShot)
    strike = rospy.ServiceProxy("/table/strike", Strike)
    predict = rospy.ServiceProxy("/table/predict", Predict)
    predict_batch = rospy.ServiceProxy("/table/predict_batch", PredictBatch)
    game_state = Latest("/table/game_state", GameState)
    table_state = Latest("/table/state", TableState)
    pockets = pocket_centres()
    radius = rospy.get_param("/table/ball_radius")

    started = start_game(rules=args.rules, players=["ann", "bob"], seed=args.seed)
    if not started.success:
        print("play_game: " + started.message, file=sys.stderr)
        return 1
    print(started.message, flush=True)
    game = game_state.when(lambda g: g.active and g.rules == args.rules and g.shots == 0 and not g.over)
    while not game.over and (args.shots < 0 or game.shots < args.shots):
        balls = table_state.when(lambda s: not s.moving and s.header.stamp >= game.header.stamp)
        shot, ball, pocket = best_shot(game, balls, pockets, radius, predict_batch)
        shooter = game.players[game.turn]
        struck = strike(ball_id=0, speed=shot.speed, phi=shot.phi)
        if not struck.success:
            print("play_game: " + struck.message, file=sys.stderr)
            return 1
        aim = f"ball {ball}" + (f" into {pocket}" if pocket else " full")
        print(f"shot {game.shots + 1}: {shooter} at {aim}, {shot.speed:.1f} m/s: "
              f"{'foul' if struck.ruling.foul else 'legal'}: {struck.ruling.reason}", flush=True)
        shots = game.shots + 1
        game = game_state.when(lambda g: g.shots >= shots and not g.shot_in_progress)
    if game.over:
        winner = game.players[game.winner] if game.winner >= 0 else "nobody"
        print(f"game over after {game.shots} shots: {winner} won", flush=True)
    elif args.preview:
        balls = table_state.when(lambda s: not s.moving and s.header.stamp >= game.header.stamp)
        shot, ball, pocket = best_shot(game, balls, pockets, radius, predict_batch)
        if not game.break_shot:  # nothing is called on a break (WPA 3.3)
            call_shot(ball=ball, pocket=pocket)
        predicted = predict(shot=shot).prediction
        print(f"next: {game.players[game.turn]} aims at ball {ball} into {pocket or 'no pocket'}; "
              f"the referee would say: {predicted.ruling.reason}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
