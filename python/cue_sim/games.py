"""Games under the WPA rules (8-ball, 9-ball, 10-ball), the UMB rules (three-cushion) and the WPBSA
rules (snooker): rules(), refereed as on the node and in `simulate`."""
from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Dict, List, Optional, Tuple

from cue_sim.api import EVENT_DTYPE, Engine, State, _core
import numpy as np  # noqa: E402 (after cue_sim.api, which checks this Python can load it)


@dataclass
class Ruling:
    """The referee's ruling on one shot: whether it was a foul, the rule it rests on (e.g.
    "WPA 6.1", "UMB Art. 83") and why, whether the shooter continues, who shoots next (0 or 1),
    ball in hand for the next shot ("anywhere", "behind_head_string", "in_d" or "none"), the balls
    spotted, a re-rack, whether the game is over and who won (-1 for nobody), each player's
    group, the points the shooter scored (three-cushion, snooker) and those a foul gave the
    opponent (snooker), and whether a colour is on next (snooker, after a red)."""
    foul: bool
    rule: str
    reason: str
    continues: bool
    next_player: int
    ball_in_hand: str
    respot: List[int]
    rerack: bool
    game_over: bool
    winner: int
    groups: Tuple[str, str]
    points: int = 0
    penalty: int = 0
    colour_next: bool = False

    @staticmethod
    def _of(text: str) -> "Ruling":
        r = json.loads(text)
        return Ruling(r["foul"], r["rule"], r["reason"], r["continues"], r["next_player"], r["ball_in_hand"],
                      list(r["respot"]), r["rerack"], r["game_over"], r["winner"], tuple(r["groups"]), r["points"],
                      r["penalty"], r["colour_next"])


class Game:
    """A game on an engine's table: racked for `first_player`'s break (0 or 1), the rack's jitter
    from `seed`; in pool the cue ball in hand behind the head string, in three-cushion the starting
    position. Copy it to try shots (copy()).

    rules: one of rules() ("eight_ball", "nine_ball", "ten_ball" on a table with pockets,
    "three_cushion" on one without: Engine(table="carom"); "snooker", best on Engine(table="snooker")).
    target: the points that win where the game is a race (three-cushion; 0 for the rules' 40).
    """

    def __init__(self, engine: Engine, rules: str = "eight_ball", players: Tuple[str, str] = ("player 1", "player 2"),
                 seed: int = 0, first_player: int = 0, target: int = 0):
        self._engine = engine
        self._game = _core.Game(engine._engine, rules, list(players), int(seed), int(first_player), int(target))

    def copy(self) -> "Game":
        """An independent game from the same position (what a planner tries shots on)."""
        other = Game.__new__(Game)
        other._engine = self._engine
        other._game = self._game.copy()
        return other

    @property
    def state(self) -> Dict:
        """The game: rules, players, turn, break, groups, called ball and pocket, ball_in_hand,
        fouls in a row, push_out_allowed, shots, score, target, innings, before_shot, over, winner
        (as `simulate` prints `game`)."""
        return json.loads(self._game.state_json())

    @property
    def table(self) -> State:
        """The balls as they stand for the next shot."""
        return State._of(self._game.table())

    @property
    def cue_ball(self) -> int:
        """The ball the player to shoot strikes: 0 in pool; 0 or 1, each player's own, in three-cushion."""
        return int(self._game.cue_ball())

    @property
    def legal_first(self) -> List[int]:
        """The object balls the player to shoot may contact first."""
        return list(self._game.legal_first())

    def place_cue_ball(self, x: float, y: float) -> None:
        """Moves the cue ball in hand to (x, y) [m]; ValueError says why it cannot go there."""
        self._game.place_cue_ball(float(x), float(y))

    def call(self, ball: int = -1, pocket: str = "") -> None:
        """Calls the next shot: an object ball on the table (-1: none) and a pocket by its URDF
        link name ("": none)."""
        self._game.call(int(ball), pocket)

    def shoot(self, speed: float, phi: float, theta: float = 0.0, a: float = 0.0, b: float = 0.0,
              push_out: bool = False, ball: int = -1) -> Tuple[Ruling, np.ndarray]:
        """Strikes the shooter's cue ball, or `ball` (three-cushion rules on the other cue ball),
        with the strike's fields as in simulate(); runs the shot to rest, and returns the ruling
        and the shot's events; the table is then ready for the next shot."""
        text, e = self._game.shoot(float(speed), float(phi), float(theta), float(a), float(b), bool(push_out),
                                   int(ball))
        events = np.empty(len(e["time"]), dtype=EVENT_DTYPE)
        for column in ("time", "kind", "ball", "other"):
            events[column] = e[column]
        events["obstacle"] = e["obstacle"]
        return Ruling._of(text), events

    def set_position(self, balls: State, break_shot: bool = False) -> None:
        """Plays on from these balls (at rest, the cue ball among them), the break played or not."""
        self._game.set_position(balls._arrays(), bool(break_shot))

    def set_shot_cap(self, shots: int) -> None:
        """A game not over after this many shots ends without a winner (0: no cap)."""
        self._game.set_shot_cap(int(shots))


def rules() -> List[str]:
    """The rulesets (the referee's registry): "eight_ball", "nine_ball", "ten_ball", "three_cushion", "snooker"."""
    return list(_core.rules_names())
