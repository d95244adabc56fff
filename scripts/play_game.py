#!/usr/bin/python3
"""Plays a game on table_node through its services, both players the same planner, or replays a
game the self_play program recorded.

In pool, each turn it asks ~predict_batch for the ghost-ball shot at every ball the player may hit
first into every pocket, at two speeds (and full at 8 m/s on a break), and strikes the one whose
predicted ruling is best: a win, then a legal pot, then a shot without a foul; the slower among
equals. The cue ball is played where the referee leaves it. In three-cushion (on the carom table)
it asks for the shooter's own cue ball struck every 2 degrees round, at two speeds and three side
spins, and strikes the best: a win, then a point, then a shot that meets a ball. With --preview
it then calls the next shot (the first ball it pots, in its pocket) and draws its prediction in
rviz without striking it.

With --replay RECORD_DIR (a directory `self_play --out` wrote) it starts the game with the record's
rack seed and first player, and for every shot places the cue ball where the record had it (when
the player had it in hand), makes the record's call and strikes the record's executed strike. The
node must rule on every shot as the record says, and leave the cue ball where the record has it;
it stops, exit code 1, at the first shot that differs. The node must run the record's table and
physics, with execution noise off (~noise/enabled false).

Usage: rosrun cue_sim play_game.py [--rules eight_ball|nine_ball|ten_ball|three_cushion] [--shots N] [--seed S]
                                   [--target POINTS] [--preview]
       rosrun cue_sim play_game.py --replay RECORD_DIR
"""
import argparse
import json
import math
import os
import sys
import time
import xml.etree.ElementTree as ET

import rospy
from cue_sim.msg import Event, GameState, Shot, TableState
from cue_sim.srv import CallShot, PlaceCueBall, Predict, PredictBatch, StartGame, Strike
from geometry_msgs.msg import Point

#: Shorter than this [m] from where a record had it, the cue ball is already in place.
PLACED = 1e-12
#: A record's note when the shot cap stopped its game (the node has no cap).
CAP_NOTE = "; the game is stopped at the cap of "


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


#: A carom game's candidates: headings round the cue ball, speeds [m/s] and side spins [R].
CAROM_HEADINGS = 180
CAROM_SPEEDS = (3.0, 4.5)
CAROM_SIDE = (-0.4, 0.0, 0.4)


def carom_candidates(game):
    """(shot, -1, "") for each heading, speed and side spin of the shooter's own cue ball."""
    return [(Shot(ball_id=game.cue_ball, speed=speed, phi=2 * math.pi * k / CAROM_HEADINGS, a=side), -1, "")
            for speed in CAROM_SPEEDS for side in CAROM_SIDE for k in range(CAROM_HEADINGS)]


def candidates(game, balls, pockets, radius):
    """(shot, ball, pocket) for each ghost-ball aim; pocket is empty for a full hit."""
    if game.target > 0:
        return carom_candidates(game)
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
        value = 100 if (not ruling.foul and (ruling.continues or ruling.points > 0)) else 10 if not ruling.foul else 0
    return value - speed


def predicted_rulings(game, tried, predict_batch, call_shot):
    """The node's prediction of each (shot, ball, pocket). Where only a called pot counts
    (game.must_call, 10-ball), each aim is predicted under its own call."""
    if not game.must_call or game.break_shot:
        batch = predict_batch(shots=[shot for shot, _, _ in tried])
        return batch.predictions, batch.message
    predictions, message = [None] * len(tried), ""
    for aim in sorted({(ball, pocket) for _, ball, pocket in tried}):
        called = call_shot(ball=aim[0] if aim[1] else -1, pocket=aim[1])
        if not called.success:
            raise RuntimeError("the call of ball %d in '%s' is refused: %s" % (aim[0], aim[1], called.message))
        chosen = [i for i, (_, ball, pocket) in enumerate(tried) if (ball, pocket) == aim]
        batch = predict_batch(shots=[tried[i][0] for i in chosen])
        message = message or batch.message
        for i, p in zip(chosen, batch.predictions):
            predictions[i] = p
    return [p for p in predictions if p is not None], message


def best_shot(game, balls, pockets, radius, predict_batch, call_shot):
    """The best (shot, ball, pocket) by its predicted ruling; where only called pots count, the
    game is left with its call made."""
    tried = candidates(game, balls, pockets, radius)
    predictions, message = predicted_rulings(game, tried, predict_batch, call_shot)
    if len(predictions) != len(tried) or not any(p.success for p in predictions):
        raise RuntimeError("no shot could be predicted: " + (predictions[0].message if predictions else message))
    scored = [(score(p.ruling, game.turn, shot.speed), i) for i, (p, (shot, _, _)) in enumerate(zip(predictions, tried))
              if p.success]
    chosen = tried[max(scored)[1]]
    if game.must_call and not game.break_shot:
        call_shot(ball=chosen[1] if chosen[2] else -1, pocket=chosen[2])
    return chosen


def same_ruling(node, recorded):
    """The node's ruling against the record's: the same foul, next player, points, penalty and
    reason (a capped game's last reason carries the cap's note, which the node does not add)."""
    reason = recorded["reason"].split(CAP_NOTE)[0]
    return (node.foul == recorded["foul"] and node.next_player == recorded["next_player"] and node.reason == reason
            and node.points == recorded.get("points", 0) and node.penalty == recorded.get("penalty", 0))


def replay(record_dir, services, game_state, table_state):
    """Replays the record in `record_dir`; 0 if the node ruled on every shot as recorded."""
    with open(os.path.join(record_dir, "game.json")) as f:
        record = json.load(f)
    if rospy.get_param("/table/noise/enabled", False):
        print("play_game: ~noise/enabled is on: a replay strikes exactly as recorded; turn it off", file=sys.stderr)
        return 2
    start_game, place_cue_ball, call_shot, strike = services
    started = start_game(rules=record["rules"], players=record["players"], first_player=record["first_player"],
                         seed=record["rack_seed"], target=record.get("target", 0))
    if not started.success:
        print("play_game: " + started.message, file=sys.stderr)
        return 1
    print(f"{record['rules']} game {record['game']} on {record['table']}: {len(record['shots'])} shots", flush=True)
    for k, shot in enumerate(record["shots"]):
        game = game_state.when(lambda g: g.active and g.rules == record["rules"] and g.shots == k
                               and not g.shot_in_progress)
        balls = table_state.when(lambda s: not s.moving and s.header.stamp >= game.header.stamp)
        ball = shot.get("ball", 0)
        cue = next(b.position for b in balls.balls if b.id == ball)
        x, y = shot["cue_ball"]
        if math.hypot(cue.x - x, cue.y - y) > PLACED:
            if not game.ball_in_hand:  # where the last shot left it: the physics must agree
                print(f"shot {k}: the cue ball is at ({cue.x}, {cue.y}), the record has it at ({x}, {y})")
                return 1
            placed = place_cue_ball(position=Point(x=x, y=y, z=0.0))
            if not placed.success:
                print(f"shot {k}: the cue ball cannot go where the record had it: {placed.message}")
                return 1
        called = call_shot(ball=shot["called_ball"], pocket=shot["called_pocket"], push_out=shot["push_out"])
        if not called.success:
            print(f"shot {k}: the record's call is refused: {called.message}")
            return 1
        s = shot["strike"]
        struck = strike(ball_id=ball, speed=s["speed"], phi=s["phi"], theta=s["theta"], a=s["a"], b=s["b"])
        if not struck.success:
            print(f"shot {k}: refused: {struck.message}")
            return 1
        if not same_ruling(struck.ruling, shot["ruling"]):
            print(f"shot {k}: the node ruled '{struck.ruling.reason}', the record '{shot['ruling']['reason']}'")
            return 1
        print(f"shot {k}: {struck.ruling.reason}", flush=True)
    game = game_state.when(lambda g: g.shots == len(record["shots"]) and not g.shot_in_progress)
    print(f"replayed {len(record['shots'])} shots on the node: every ruling as recorded", flush=True)
    return 0


def main():
    parser = argparse.ArgumentParser(description="Plays a game on table_node through its services.")
    parser.add_argument("--rules", default="eight_ball",
                        help="a ruleset the node knows: eight_ball, nine_ball, ten_ball on a table with pockets, "
                             "three_cushion on the carom table, snooker (~start_game refuses others)")
    parser.add_argument("--target", type=int, default=0,
                        help="the points that win a game that keeps a score (three_cushion; 0: its 40)")
    parser.add_argument("--shots", type=int, default=-1, help="stop after this many shots (default: at the game's end)")
    parser.add_argument("--seed", type=int, default=0, help="the rack's jitter")
    parser.add_argument("--preview", action="store_true", help="at the end, call and preview the next shot")
    parser.add_argument("--replay", metavar="RECORD_DIR", help="replay a game self_play recorded, checking each ruling")
    args = parser.parse_args(rospy.myargv()[1:])
    rospy.init_node("play_game", anonymous=True)
    for name in ("start_game", "place_cue_ball", "call_shot", "strike", "predict", "predict_batch"):
        rospy.wait_for_service("/table/" + name, timeout=30)
    start_game = rospy.ServiceProxy("/table/start_game", StartGame)
    call_shot = rospy.ServiceProxy("/table/call_shot", CallShot)
    strike = rospy.ServiceProxy("/table/strike", Strike)
    predict = rospy.ServiceProxy("/table/predict", Predict)
    predict_batch = rospy.ServiceProxy("/table/predict_batch", PredictBatch)
    game_state = Latest("/table/game_state", GameState)
    table_state = Latest("/table/state", TableState)
    if args.replay:
        place_cue_ball = rospy.ServiceProxy("/table/place_cue_ball", PlaceCueBall)
        return replay(args.replay, (start_game, place_cue_ball, call_shot, strike), game_state, table_state)
    pockets = pocket_centres()
    radius = rospy.get_param("/table/ball_radius")

    started = start_game(rules=args.rules, players=["ann", "bob"], seed=args.seed, target=args.target)
    if not started.success:
        print("play_game: " + started.message, file=sys.stderr)
        return 1
    print(started.message, flush=True)
    game = game_state.when(lambda g: g.active and g.rules == args.rules and g.shots == 0 and not g.over)
    while not game.over and (args.shots < 0 or game.shots < args.shots):
        balls = table_state.when(lambda s: not s.moving and s.header.stamp >= game.header.stamp)
        shot, ball, pocket = best_shot(game, balls, pockets, radius, predict_batch, call_shot)
        shooter = game.players[game.turn]
        struck = strike(ball_id=shot.ball_id, speed=shot.speed, phi=shot.phi, a=shot.a)
        if not struck.success:
            print("play_game: " + struck.message, file=sys.stderr)
            return 1
        aim = (f"ball {ball}" + (f" into {pocket}" if pocket else " full") if ball >= 0
               else f"its ball {shot.ball_id} at {math.degrees(shot.phi):.0f} degrees, side {shot.a:+.1f}")
        verdict = "foul" if struck.ruling.foul else "point" if struck.ruling.points else \
            "no point" if game.target else "legal"
        print(f"shot {game.shots + 1}: {shooter} at {aim}, {shot.speed:.1f} m/s: {verdict}: {struck.ruling.reason}",
              flush=True)
        shots = game.shots + 1
        game = game_state.when(lambda g: g.shots >= shots and not g.shot_in_progress)
    if game.over:
        winner = game.players[game.winner] if game.winner >= 0 else "nobody"
        score = f", {game.score[0]} to {game.score[1]} in {game.innings[0]} and {game.innings[1]} innings" \
            if game.target else ""
        print(f"game over after {game.shots} shots: {winner} won{score}", flush=True)
    elif args.preview:
        balls = table_state.when(lambda s: not s.moving and s.header.stamp >= game.header.stamp)
        shot, ball, pocket = best_shot(game, balls, pockets, radius, predict_batch, call_shot)
        # Call what the shot pots first (the aim may pot another ball), except on a break (WPA 3.3).
        pots = [(e.ball_id, e.obstacle) for e in predict(shot=shot).prediction.events
                if e.kind == Event.POCKETED and e.ball_id != 0]
        if pots and not game.break_shot:
            call_shot(ball=pots[0][0], pocket=pots[0][1])
        predicted = predict(shot=shot).prediction
        print(f"next: {game.players[game.turn]} aims at ball {ball} into {pocket or 'no pocket'}"
              f"{f', calls ball {pots[0][0]} in {pots[0][1]}' if pots and not game.break_shot else ''}; "
              f"the referee would say: {predicted.ruling.reason}", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
