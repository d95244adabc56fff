"""Games from Python: the referee's rulings as `simulate` gives them for the same scene, ball in
hand checked by the rules, and whole games that end with every ball accounted for."""
import json
import math
import os
import subprocess

import numpy as np
import pytest

import cue_sim

SIMULATE = os.environ.get("CUE_SIM_SIMULATE", "simulate")


@pytest.fixture(scope="module")
def engine():
    return cue_sim.Engine("7ft")


def test_a_scratch_is_ruled_as_simulate_rules_it_and_ball_in_hand_is_checked(engine):
    scene = ("table: 7ft\nballs:\n  - {id: 0, position: [0.0, 0.1]}\n  - {id: 1, position: [0.3, -0.3]}\n"
             "  - {id: 9, position: [0.6, -0.3]}\nshot: {speed: 2.0, phi: 1.5707963267948966}\n"
             "game: {rules: nine_ball, break: false}\n")
    program = json.loads(subprocess.run([SIMULATE, "-"], input=scene, capture_output=True, text=True, check=True,
                                        timeout=60).stdout)
    game = cue_sim.Game(engine, "nine_ball", ("ann", "bob"))
    game.set_position(cue_sim.State.from_balls([0, 1, 9], [[0.0, 0.1], [0.3, -0.3], [0.6, -0.3]]))
    ruling, events = game.shoot(2.0, math.pi / 2)
    assert ruling.foul and ruling.rule == program["ruling"]["rule"] == "WPA 6.1"
    assert ruling.reason == program["ruling"]["reason"]
    assert ruling.ball_in_hand == "anywhere" and ruling.next_player == 1
    assert events[-1]["kind"] == 13 and events[-1]["ball"] == 0  # the cue ball dropped
    assert game.state["turn"] == 1 and game.state["fouls"] == [1, 0]
    with pytest.raises(ValueError, match="overlap"):
        game.place_cue_ball(0.3, -0.3 + 0.02)
    with pytest.raises(ValueError, match="pocket must be one of"):
        game.call(1, "corner")
    game.place_cue_ball(-0.5, 0.2)
    table = game.table
    assert list(table.positions[list(table.ids).index(0)][:2]) == [-0.5, 0.2]


def ghost_ball_shots(game, engine):
    """Every legal ball into every pocket, from where the cue ball stands, at two speeds."""
    table = game.table
    where = {int(i): p[:2] for i, p, pocket in zip(table.ids, table.positions, table.pocket) if pocket < 0}
    cue = where[0]
    radius = engine.params["ball_radius"]
    shots = []
    for ball in game.legal_first:
        b = where[ball]
        for px, py, _ in engine.pockets.values():
            d = np.hypot(px - b[0], py - b[1])
            ghost = (b[0] - 2 * radius * (px - b[0]) / d, b[1] - 2 * radius * (py - b[1]) / d)
            for speed in (1.5, 3.0):
                shots.append((speed, math.atan2(ghost[1] - cue[1], ghost[0] - cue[0])))
    return shots


def test_whole_games_end_with_every_ball_accounted_for(engine):
    for seed, rules, balls in ((1, "nine_ball", 10), (2, "eight_ball", 16)):
        game = cue_sim.Game(engine, rules, seed=seed)
        game.set_shot_cap(150)
        shots = 0
        while not game.state["over"]:
            best, choice = -1e9, (8.0, 0.0)
            if game.state["break"]:
                cue = game.table.positions[list(game.table.ids).index(0)]
                choice = (8.0, math.atan2(-cue[1], 0.4953 - cue[0]))
            else:
                for speed, phi in ghost_ball_shots(game, engine):
                    ruling, _ = game.copy().shoot(speed, phi)
                    score = (1000 if ruling.game_over and ruling.winner == game.state["turn"] else
                             100 if ruling.continues and not ruling.foul else 10 if not ruling.foul else 0) - speed
                    if score > best:
                        best, choice = score, (speed, phi)
            game.shoot(*choice)
            shots += 1
            table = game.table
            assert len(table.ids) == balls and len(set(table.ids)) == balls  # every ball on the table or down
            assert np.all(np.isfinite(table.positions))
        assert game.state["winner"] in (0, 1), game.state
        assert shots < 150


def test_a_ten_ball_game_counts_only_called_balls_and_ends(engine):
    """10-ball from Python: each ghost-ball shot is tried under its own call; a called ball in its
    called pocket continues the inning, and the game ends with every ball accounted for."""
    game = cue_sim.Game(engine, "ten_ball", seed=3)
    assert "ten_ball" in cue_sim.rules()
    assert sorted(int(i) for i in game.table.ids) == list(range(11))
    game.set_shot_cap(150)
    radius = engine.params["ball_radius"]
    continued = 0
    while not game.state["over"]:
        best, choice, call = -1e9, (8.0, 0.0), None
        table = game.table
        cue = table.positions[list(table.ids).index(0)]
        if game.state["break"]:
            choice = (8.0, math.atan2(-cue[1], 0.4953 - cue[0]))
        else:
            where = {int(i): p[:2] for i, p, pocket in zip(table.ids, table.positions, table.pocket) if pocket < 0}
            for ball in game.legal_first:
                b = where[ball]
                for name, (px, py, _) in engine.pockets.items():
                    d = np.hypot(px - b[0], py - b[1])
                    ghost = (b[0] - 2 * radius * (px - b[0]) / d, b[1] - 2 * radius * (py - b[1]) / d)
                    for speed in (1.5, 3.0):
                        trial = game.copy()
                        trial.call(ball, name)
                        ruling, _ = trial.shoot(speed, math.atan2(ghost[1] - cue[1], ghost[0] - cue[0]))
                        score = (1000 if ruling.game_over and ruling.winner == game.state["turn"] else
                                 100 if ruling.continues and not ruling.foul else 10 if not ruling.foul else 0) - speed
                        if score > best:
                            best, call = score, (ball, name)
                            choice = (speed, math.atan2(ghost[1] - cue[1], ghost[0] - cue[0]))
        if call is not None:
            game.call(*call)
        ruling, _ = game.shoot(*choice)
        if ruling.rule == "WPA 9.5":
            continued += 1
        table = game.table
        assert len(table.ids) == 11 and len(set(table.ids)) == 11
    assert game.state["winner"] in (0, 1), game.state
    assert continued > 0  # called balls went down and kept the inning


def test_a_three_cushion_race_is_played_with_each_players_own_ball():
    """Three-cushion from Python on the carom table: each player strikes their own cue ball (the
    other's is refused as a foul, the red as a strike), a point continues the inning, the scores
    add up the rulings' points and the race ends the game."""
    carom = cue_sim.Engine("carom")
    with pytest.raises(ValueError, match="without pockets"):
        cue_sim.Game(cue_sim.Engine("7ft"), "three_cushion")
    with pytest.raises(ValueError, match="target"):
        cue_sim.Game(carom, "three_cushion", target=-1)
    game = cue_sim.Game(carom, "three_cushion", target=2, first_player=1)
    assert game.cue_ball == 1 and game.legal_first == [2]
    assert sorted(int(i) for i in game.table.ids) == [0, 1, 2]
    assert game.state["target"] == 2 and game.state["ball_in_hand"] == "none"
    with pytest.raises(ValueError, match="ball 2 is not struck"):
        game.copy().shoot(2.0, 0.0, ball=2)
    wrong, _ = game.copy().shoot(2.0, 0.0, ball=0)
    assert wrong.foul and wrong.rule == "UMB Art. 41"
    scores = [0, 0]
    while not game.state["over"] and game.state["shots"] < 200:
        shooter = game.state["turn"]
        assert game.cue_ball == shooter
        best, choice = -1e9, None
        for k in range(0, 180):  # every 2 degrees, as the carom planner tries
            for speed in (3.0, 4.5):
                ruling, _ = game.copy().shoot(speed, 2 * math.pi * k / 180)
                score = (100 if ruling.points else 0) - speed
                if score > best:
                    best, choice = score, (speed, 2 * math.pi * k / 180)
        ruling, events = game.shoot(*choice)
        scores[shooter] += ruling.points
        assert ruling.continues == (ruling.points == 1 and not ruling.game_over)
        assert list(game.state["score"]) == scores
        assert len(events) > 0
    assert game.state["over"] and max(scores) == 2 and game.state["winner"] == scores.index(2)


def test_a_snooker_frame_keeps_score_with_penalties_and_plays_from_the_d():
    """Snooker from Python on the snooker table: the rack of 22 balls in their colours, the cue
    ball in hand in the D, the reds on first; a foul gives the opponent at least 4; the scores
    are the points and penalties ruled; and a frame played by a simple potter ends."""
    snooker = cue_sim.Engine("snooker")
    assert snooker.ball_set == "snooker" and snooker.params["ball_radius"] == 0.02625
    assert cue_sim.ball_colour(7, ball_set="snooker") == cue_sim.ball_colour(1, ball_set="snooker")  # the reds
    assert not cue_sim.is_numbered(21, ball_set="snooker")
    game = cue_sim.Game(snooker, "snooker", seed=3)
    assert sorted(int(i) for i in game.table.ids) == list(range(22))
    assert game.state["ball_in_hand"] == "in_d" and game.legal_first == list(range(1, 16))
    with pytest.raises(ValueError, match="in the D"):
        game.copy().place_cue_ball(0.0, 0.0)
    missed, _ = game.copy().shoot(1.0, math.pi)  # away from every ball: a foul of 4
    assert missed.foul and missed.penalty == 4 and missed.points == 0 and "no miss is called" in missed.reason
    scores = [0, 0]
    positions = {int(i): tuple(p[:2]) for i, p in zip(game.table.ids, game.table.positions)}
    while not game.state["over"] and game.state["shots"] < 400:
        shooter = game.state["turn"]
        table = game.table
        cue = [p for i, p in zip(table.ids, table.positions) if i == 0][0]
        best, choice = -1e9, None
        for ball in game.legal_first:
            target = [p for i, p in zip(table.ids, table.positions) if i == ball][0]
            for offset in (-0.6, -0.3, 0.0, 0.3, 0.6):
                phi = math.atan2(target[1] - cue[1], target[0] - cue[0]) + offset * 0.05
                for speed in (1.5, 3.0):
                    ruling, _ = game.copy().shoot(speed, phi)
                    score = ruling.points * 10 - ruling.penalty * 10 - speed
                    if score > best:
                        best, choice = score, (speed, phi)
        ruling, _ = game.shoot(*choice)
        scores[shooter] += ruling.points
        scores[1 - shooter] += ruling.penalty
        assert list(game.state["score"]) == scores
        assert ruling.foul == (ruling.penalty >= 4)
    assert game.state["over"], game.state
    assert game.state["winner"] == scores.index(max(scores)) and scores[0] != scores[1]
    assert positions[21] != ()  # the black was racked
