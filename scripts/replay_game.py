#!/usr/bin/python3
"""Replays a recorded game (a directory `self_play --out` wrote) on table_node, shot by shot.

It starts the game with the record's rack seed and first player, and for every shot places the
cue ball where the record had it (when the player had it in hand), makes the record's call, and
strikes the record's executed strike. The node's referee must rule on every shot as the record
says: the script prints each ruling and exits 1 at the first that differs. The node must run the
record's table and physics, with execution noise off (~noise/enabled false).

Usage: rosrun cue_sim replay_game.py RECORD_DIR
"""
import json
import math
import os
import sys
import time

import rospy
from geometry_msgs.msg import Point
from cue_sim.msg import GameState, TableState
from cue_sim.srv import CallShot, PlaceCueBall, StartGame, Strike

#: Shorter than this [m] from where the record had it, the cue ball is already in place.
PLACED = 1e-12
#: The record's note when the shot cap stopped a game (the node has no cap).
CAP_NOTE = "; the game is stopped at the cap of "


class Latest:
    """The last message on a topic, waited for in wall time."""

    def __init__(self, topic, kind):
        self.msg = None
        rospy.Subscriber(topic, kind, self.keep)

    def keep(self, msg):
        self.msg = msg

    def when(self, ready, timeout=120.0):
        deadline = time.monotonic() + timeout
        while not rospy.is_shutdown() and not (self.msg is not None and ready(self.msg)):
            if time.monotonic() > deadline:
                raise RuntimeError("timed out waiting for the table")
            time.sleep(0.01)
        return self.msg


def same_ruling(node, recorded):
    """The node's ruling against the record's: the same foul, next player and reason (a capped
    game's last reason carries the cap's note, which the node does not add)."""
    reason = recorded["reason"].split(CAP_NOTE)[0]
    return node.foul == recorded["foul"] and node.next_player == recorded["next_player"] and node.reason == reason


def main():
    if len(rospy.myargv()) != 2:
        print(__doc__, file=sys.stderr)
        return 2
    record_dir = rospy.myargv()[1]
    with open(os.path.join(record_dir, "game.json")) as f:
        record = json.load(f)
    rospy.init_node("replay_game", anonymous=True)
    if rospy.get_param("/table/noise/enabled", False):
        print("replay_game: ~noise/enabled is on: a replay strikes exactly as recorded; turn it off", file=sys.stderr)
        return 2
    for name in ("start_game", "place_cue_ball", "call_shot", "strike"):
        rospy.wait_for_service("/table/" + name, timeout=30)
    start_game = rospy.ServiceProxy("/table/start_game", StartGame)
    place_cue_ball = rospy.ServiceProxy("/table/place_cue_ball", PlaceCueBall)
    call_shot = rospy.ServiceProxy("/table/call_shot", CallShot)
    strike = rospy.ServiceProxy("/table/strike", Strike)
    game_state = Latest("/table/game_state", GameState)
    table_state = Latest("/table/state", TableState)

    started = start_game(rules=record["rules"], players=record["players"], first_player=record["first_player"],
                         seed=record["rack_seed"])
    if not started.success:
        print("replay_game: " + started.message, file=sys.stderr)
        return 1
    print(f"{record['rules']} game {record['game']} on {record['table']}: {len(record['shots'])} shots", flush=True)
    for k, shot in enumerate(record["shots"]):
        game = game_state.when(lambda g: g.active and g.shots == k and not g.shot_in_progress)
        balls = table_state.when(lambda s: not s.moving and s.header.stamp >= game.header.stamp)
        cue = next(b.position for b in balls.balls if b.id == 0)
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
        struck = strike(ball_id=0, speed=s["speed"], phi=s["phi"], theta=s["theta"], a=s["a"], b=s["b"])
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


if __name__ == "__main__":
    sys.exit(main())
