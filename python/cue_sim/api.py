"""The engine from Python: tables, physics, table states, shots and batches, as NumPy arrays.

Units are SI throughout and frames are the table's (x towards the foot, y left, z up), as on the
node. Values a user can get wrong raise ValueError naming them.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

from cue_sim._interpreter import core

_core = core()  # first: it says which Python to use if this one cannot load the engine or NumPy
import numpy as np  # noqa: E402

#: Event kinds by number (the `kind` column of Shot.events), as cue_sim/Event.msg numbers them.
EVENT_KINDS: Dict[int, str] = {0: "slide_to_roll", 1: "roll_to_spin", 2: "roll_to_stop", 3: "spin_to_stop",
                               4: "slide_to_spin", 5: "slide_to_stop", 10: "ball_ball", 11: "ball_cushion",
                               12: "ball_jaw", 13: "pocketed", 14: "ball_slate",
                               15: "off_table"}
#: Ball motion states by number (State.motion), as cue_sim/BallState.msg numbers them.
MOTION: Dict[int, str] = {0: "stationary", 1: "spinning", 2: "sliding", 3: "rolling", 4: "pocketed", 5: "airborne",
                          6: "off_table", 7: "held",
                          8: "supported", 9: "bearing"}

#: The dtype of Shot.events.
EVENT_DTYPE = np.dtype([("time", "f8"), ("kind", "i4"), ("ball", "i4"), ("other", "i4"), ("obstacle", "U32")])


def tables() -> List[str]:
    """The bundled tables' names ("7ft", "9ft", "carom", "snooker"); Engine also takes a URDF file's path."""
    return list(_core.table_names())


def models() -> Dict[str, List[str]]:
    """The contact models by kind, the default first: {"ball_ball": [...], "cushion": [...],
    "ball_table": [...], "cue": [...]}."""
    return {"ball_ball": list(_core.ball_ball_models()), "cushion": list(_core.cushion_models()),
            "ball_table": list(_core.ball_table_models()), "cue": list(_core.cue_models())}


def parameters() -> Dict[str, dict]:
    """Every physics coefficient: its default, unit, accepted range (min, max) and description."""
    return dict(_core.param_fields())


@dataclass
class State:
    """A table state, one row a ball: ids (N,), positions, velocities, spins (N, 3) [m, m/s, rad/s],
    motion (N,) (MOTION), pocket (N,) (the pocket's index, -1 on the table, -2 off it)."""
    ids: np.ndarray
    positions: np.ndarray
    velocities: np.ndarray
    spins: np.ndarray
    motion: np.ndarray
    pocket: np.ndarray

    @staticmethod
    def from_balls(ids, positions, velocities=None, spins=None) -> "State":
        """Balls on the cloth at `positions` ((N, 2) or (N, 3); z is ignored), at rest unless
        velocities or spins ((N, 3)) are given."""
        ids = np.asarray(ids, dtype=np.int32)
        n = len(ids)
        xyz = np.zeros((n, 3))
        positions = np.asarray(positions, dtype=float)
        if positions.ndim != 2 or positions.shape[0] != n or positions.shape[1] not in (2, 3):
            raise ValueError(f"positions must have shape ({n}, 2) or ({n}, 3), got {positions.shape}")
        xyz[:, :positions.shape[1]] = positions
        return State(ids, xyz, _rows(velocities, n, "velocities"), _rows(spins, n, "spins"),
                     np.zeros(n, dtype=np.uint8), np.full(n, -1, dtype=np.int32))

    def _arrays(self):
        a = _core.StateArrays()
        a.ids = np.ascontiguousarray(self.ids, dtype=np.int32)
        a.positions = np.ascontiguousarray(self.positions, dtype=float)
        a.velocities = np.ascontiguousarray(self.velocities, dtype=float)
        a.spins = np.ascontiguousarray(self.spins, dtype=float)
        a.motion = np.ascontiguousarray(self.motion, dtype=np.uint8)
        a.pocket = np.ascontiguousarray(self.pocket, dtype=np.int32)
        return a

    @staticmethod
    def _of(a) -> "State":
        return State(np.asarray(a.ids), np.asarray(a.positions), np.asarray(a.velocities), np.asarray(a.spins),
                     np.asarray(a.motion), np.asarray(a.pocket))


def _rows(values, n: int, name: str) -> np.ndarray:
    if values is None:
        return np.zeros((n, 3))
    values = np.asarray(values, dtype=float)
    if values.shape != (n, 3):
        raise ValueError(f"{name} must have shape ({n}, 3), got {values.shape}")
    return values


@dataclass
class TableGeometry:
    """A table's shape: the cloth's centre (x, y), length and width [m]; each straight cushion's
    nose line (name, start, end), the play on its left from start to end; each jaw or cushion end
    (name, centre, radius; a ball touches it at radius + R from the centre); each pocket's capture
    circle by name (x, y, radius)."""
    cloth_centre: Tuple[float, float]
    cloth_length: float
    cloth_width: float
    cushions: List[Tuple[str, Tuple[float, float], Tuple[float, float]]]
    jaws: List[Tuple[str, Tuple[float, float], float]]
    pockets: Dict[str, Tuple[float, float, float]]


def ball_colour(ball: int, carom: bool = False, ball_set: Optional[str] = None) -> Tuple[float, float, float]:
    """A ball's colour (r, g, b in [0, 1]) as rviz shows it: standard pool colours, 9-15 the
    stripes of 1-7, 0 the cue ball; with `carom` (a table without pockets) carom's set, 0 white,
    1 yellow, 2 red. `ball_set` ("pool", "carom", "snooker"; Engine.ball_set) names the set
    instead: snooker's 1-15 are the reds, 16-21 yellow, green, brown, blue, pink and black."""
    return tuple(_core.ball_colour(int(ball), bool(carom), ball_set or ""))


def is_striped(ball: int, carom: bool = False, ball_set: Optional[str] = None) -> bool:
    return bool(_core.is_striped(int(ball), bool(carom), ball_set or ""))


def is_numbered(ball: int, carom: bool = False, ball_set: Optional[str] = None) -> bool:
    """Whether the ball carries its number: pool's object balls; no carom or snooker ball does."""
    return bool(_core.is_numbered(int(ball), bool(carom), ball_set or ""))


class Engine:
    """The physics model: a table, its coefficients and contact models. Immutable; share it.

    table: a bundled table's name (tables()) or a URDF file's path.
    ball_ball_model, cushion_model, ball_table_model, cue_model: models()' names; None for the
    defaults.
    params: coefficients by name over the table's defaults (parameters(); a table that names its
    balls, as snooker and carom do, sets ball_radius and ball_mass), e.g. mu_slide=0.2.
    """

    def __init__(self, table: str = "7ft", ball_ball_model: Optional[str] = None,
                 cushion_model: Optional[str] = None, ball_table_model: Optional[str] = None,
                 cue_model: Optional[str] = None, **params: float):
        self._spec = (table, ball_ball_model, cushion_model, ball_table_model, cue_model, dict(params))
        self._engine = _core.Engine(table, {k: float(v) for k, v in params.items()}, ball_ball_model or "",
                                    cushion_model or "", ball_table_model or "", cue_model or "")

    def with_params(self, **params: float) -> "Engine":
        """This engine with the given coefficients changed (checked as the constructor checks
        them), on the same table, read once: cheap enough to make at every step of a fit."""
        *models, given = self._spec
        out = Engine.__new__(Engine)
        out._spec = (*models, dict(given, **params))
        out._engine = self._engine.with_params({k: float(v) for k, v in params.items()})
        return out

    def __reduce__(self):
        # Pickled as what it was made from (for Dask's workers, which build their own).
        return (_engine_from_spec, self._spec)

    @property
    def table(self) -> str:
        return self._engine.table_name

    @property
    def params(self) -> Dict[str, float]:
        """Every coefficient's value."""
        return dict(self._engine.params)

    @property
    def ball_set(self) -> str:
        """The balls the table is played with, for pictures: "pool", "carom" or "snooker"."""
        return self._engine.ball_set

    @property
    def pockets(self) -> Dict[str, Tuple[float, float, float]]:
        """Each pocket by its URDF link name: the centre (x, y) [m] and radius [m] of its capture
        circle (a ball whose centre enters it drops)."""
        return {name: (x, y, r) for name, x, y, r in self._engine.pockets}

    @property
    def geometry(self) -> "TableGeometry":
        """The table's shape in its frame (REP 103: x along the table towards the foot, y across,
        metres): the cloth, the cushions' nose lines, the jaws and the pockets."""
        cx, cy, length, width = self._engine.cloth
        return TableGeometry((cx, cy), length, width,
                             [(name, (x0, y0), (x1, y1)) for name, x0, y0, x1, y1 in self._engine.cushions],
                             [(name, (x, y), r) for name, x, y, r in self._engine.jaws], self.pockets)

    @property
    def models(self) -> Dict[str, str]:
        return {"ball_ball": self._engine.ball_ball_model, "cushion": self._engine.cushion_model,
                "ball_table": self._engine.ball_table_model, "cue": self._engine.cue_model}

    def rack(self, layout: str = "eight", gap: float = 1e-5, jitter: float = 0.0, seed: int = 0) -> State:
        """A standard rack ("eight", "nine", "ten", "carom", "snooker" or "empty": the cue ball only) with `gap` [m] between
        neighbouring balls and each ball but the apex moved by up to `jitter` [m] (from `seed`)."""
        return State._of(self._engine.rack(layout, gap, jitter, seed))

    def check(self, state: State) -> None:
        """Raises ValueError if the balls cannot stand so on this table (which ball, and why)."""
        self._engine.check(state._arrays())

    def __repr__(self) -> str:
        return f"cue_sim.Engine({self.table!r}, {self.models['ball_ball']!r}, {self.models['cushion']!r})"


@dataclass
class Samples:
    """The balls every `period` seconds from the strike: times (K,) [s], positions, velocities,
    spins (K, N, 3), motion and pocket (K, N); ball j is row j of the starting State."""
    period: float
    times: np.ndarray
    positions: np.ndarray
    velocities: np.ndarray
    spins: np.ndarray
    motion: np.ndarray
    pocket: np.ndarray


def _engine_from_spec(table, ball_ball_model, cushion_model, ball_table_model, cue_model, params):
    return Engine(table, ball_ball_model, cushion_model, ball_table_model, cue_model, **params)


@dataclass
class Shot:
    """What a shot did: every event in order (EVENT_DTYPE, times from the strike), the table where
    it left it, the time from the strike to its last event [s], whether every ball came to rest,
    the samples asked for (None without a sample_period), and the strike and `until` it was
    simulated with (so that the shot can be run again, as draw_shot() does)."""
    events: np.ndarray
    final: State
    time_to_rest: float
    at_rest: bool
    samples: Optional[Samples] = None
    strike: Dict[str, float] = field(default_factory=dict)
    until: Optional[float] = None


def simulate(engine: Engine, start: State, ball: int = 0, speed: float = 1.0, phi: float = 0.0,
             theta: float = 0.0, a: float = 0.0, b: float = 0.0, until: Optional[float] = None,
             sample_period: float = 0.0) -> Shot:
    """Strikes `ball` on `start` and runs the shot to rest, or for `until` seconds.

    speed: the cue's speed at impact [m/s], in (0, 12]. phi: heading [rad] in the table frame.
    theta: elevation [rad], in [0, pi/2]. a, b: where the tip meets the ball, right and up from its
    centre, in ball radii (sqrt(a^2 + b^2) <= 0.5); a > 0 is right English.
    sample_period: 0, or in [0.001, 10] s: the balls every sample_period from the strike
    (Shot.samples), at most 10000 samples.
    To rest, this is exactly what the node's ~predict answers for the same table and shot.
    """
    out = engine._engine.simulate(start._arrays(), ball, speed, phi, theta, a, b,
                                  float("inf") if until is None else float(until), float(sample_period))
    e = out["events"]
    events = np.empty(len(e["time"]), dtype=EVENT_DTYPE)
    for column in ("time", "kind", "ball", "other"):
        events[column] = e[column]
    events["obstacle"] = e["obstacle"]
    samples = None
    if sample_period > 0:
        sampled = out["samples"]
        count = sampled["positions"].shape[0]
        samples = Samples(float(sample_period), np.arange(count) * float(sample_period), sampled["positions"],
                          sampled["velocities"], sampled["spins"], sampled["motion"], sampled["pocket"])
    strike = {"ball": int(ball), "speed": float(speed), "phi": float(phi), "theta": float(theta), "a": float(a),
              "b": float(b)}
    return Shot(events, State._of(out["state"]), float(out["time_to_rest"]), bool(out["at_rest"]), samples, strike,
                None if until is None else float(until))


@dataclass
class Batch:
    """Many shots' outcomes, one row a shot: the strikes as executed (N, 6), final positions
    (N, balls, 3), pocket (N, balls) (-1 on the table), motion (N, balls), the events' count,
    time to rest and whether at rest (N,), and why a shot was refused ("" when it ran)."""
    executed: np.ndarray
    positions: np.ndarray
    pocket: np.ndarray
    motion: np.ndarray
    events: np.ndarray
    time_to_rest: np.ndarray
    at_rest: np.ndarray
    error: List[str]


def shot_rows(shots) -> np.ndarray:
    """shots as a contiguous (N, 6) float array of ball, speed, phi, theta, a, b, or ValueError."""
    shots = np.ascontiguousarray(shots, dtype=float)
    if shots.ndim != 2 or shots.shape[1] != 6:
        raise ValueError(f"shots must be an (N, 6) array of ball, speed, phi, theta, a, b; got {shots.shape}")
    return shots


def batch(engine: Engine, start: State, shots, noise: bool = False, seed: int = 0, threads: int = 0) -> Batch:
    """Runs shots, an (N, 6) array of ball, speed, phi, theta, a, b, each from `start`, on
    `threads` threads (0: every core), the GIL released. With `noise`, shot i gets the
    tournaments' execution noise from seed + i alone, so any split of a batch gives the same shots.
    Each outcome is what simulate() gives for that shot (with its noise)."""
    shots = shot_rows(shots)
    out = engine._engine.batch(start._arrays(), shots, bool(noise), int(seed), int(threads))
    return Batch(np.asarray(out["executed"]), np.asarray(out["positions"]), np.asarray(out["pocket"]),
                 np.asarray(out["motion"]), np.asarray(out["events"]), np.asarray(out["time_to_rest"]),
                 np.asarray(out["at_rest"]), list(out["error"]))
