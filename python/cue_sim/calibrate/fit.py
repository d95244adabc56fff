"""The simulator fitted to observed shots: chosen coefficients of the registry, each shot's
unknowns with them, by robust nonlinear least squares (Ceres, each shot's unknowns eliminated by
their Schur complement: cue_sim.calibrate.solver).

Every observed position is compared with the engine's exact prediction at that instant
(cue_sim._core.predict_tracks: the events between two frames are where they happen, not at a
frame). A shot's unknowns are when it was struck on the observer's clock (t0) and either the
struck ball's velocity and spin just after the strike (vx, vy; the topspin w_top about the
horizontal axis across the motion, negative for draw; the side spin wz about the vertical: a level
cue's spins, nothing assumed of the cue's mass or tip) or, when the strike's speed is known, the strike's fields that are not (phi, theta, a, b;
the cue's model then turns them into the ball's motion). The balls that were not struck start
where they stood. The loss is robust (soft_l1 on residuals in units of the observation noise), so
that a detector's outliers do not drag the fit. Standard errors come from the Jacobian at the
solution (the Gauss-Newton covariance, scaled by the residuals' own variance), with the shots'
unknowns marginalised; doc/calibration.md says what the method assumes and where it fails.
"""
from __future__ import annotations

import copy
import math
import os
import time
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from cue_sim._interpreter import core
from cue_sim.calibrate import solver, uncertainty
from cue_sim.calibrate.tracks import CUE_FIELDS, Track

_core = core()

#: The coefficients the data of a shot can only determine through a contact of that kind.
NEEDS_BALL_BALL = ("e_ball", "mu_ball_a", "mu_ball_b", "mu_ball_c", "ball_impact_tolerance")
NEEDS_CUSHION = ("e_cushion", "f_cushion", "cushion_height", "e_cushion_work", "mu_cushion",
                 "cushion_frequency_ratio")
#: What a fit may ask for: the physics of the balls on the cloth and at their contacts (not the
#: table's or the balls' sizes, nor the integrators' tolerances).
FITTABLE = ("mu_slide", "mu_roll", "mu_spin", "e_ball", "mu_ball_a", "mu_ball_b", "mu_ball_c", "e_cushion",
            "f_cushion", "cushion_height", "e_cushion_work", "mu_cushion", "cushion_frequency_ratio")

#: The observation noise the residuals are measured in when none is given [m]: a detector's
#: typical error on a 1080p overhead camera over a 7 ft table (about a pixel).
DEFAULT_NOISE = 0.002
#: A ball has moved once it is this many noise deviations from where it stood (the start of a
#: shot is found so).
MOVED_IN_NOISES = 5.0
#: How far a residual goes, in noises, when a shot cannot be predicted at all (a strike refused,
#: balls overlapping): large, and the same everywhere, so that the solver backs away.
UNPREDICTABLE = 1000.0
#: A coefficient whose standard error is more than this share of its value is reported as not
#: determined by the data.
UNDETERMINED_SHARE = 0.5
#: A shot with more than this share of its positions beyond 5 noises at the solution is reported:
#: a tracker's outliers are a percent or two, a shot fitted to the wrong contacts a large share.
MISFIT_SHARE = 0.1
#: A stage that frees the coefficients and leaves a shot with more than this share of its window's
#: positions beyond 5 noises is begun again, that shot fitted alone first: a shot put on other
#: contacts than its data's as the window grows pulls the coefficients after it (seen: a second
#: ball-ball contact missed at 1.6 s took the sliding friction from 0.274 to 0.22 by 2.5 s). Above
#: a tracker's share of outliers (1 %), below what a lost contact leaves (5 % and more).
STAGE_MISFIT_SHARE = 0.03
#: A shot the joint fit left on other contacts is fitted again alone from its first guess, then,
#: while its first moments (the first stage's window) do not fit either, from the struck ball this
#: many times faster (a cushion model that cannot fit the shot misses later, and is not helped by
#: them; a model comparison then fits many shots again): a fast shot at a near ball, seen
#: once before the next ball moves, has its speed from one frame's way, short by the share of the
#: frame before the strike (seen at 30 Hz with frames dropped: 2.3 for 3.7 m/s); 0.7 for a guess
#: that took in the first contact.
FASTER_STARTS = (1.6, 2.5, 0.7)
#: How far a ball's fitted resting place may be from where it was first seen [m].
REST_SLACK = 0.02
#: The bounds of a fitted strike field: within the strike's own limits, and a and b inside the
#: disc of the largest tip offset (0.5 R) whatever their signs.
STRIKE_BOUNDS = {"speed": (0.05, 12.0), "phi": (-4 * math.pi, 4 * math.pi), "theta": (0.0, 1.4),
                 "a": (-0.35, 0.35), "b": (-0.35, 0.35)}
#: The bounds of a struck ball's fitted motion: speeds and spins a cue can give.
BALL_BOUNDS = {"vx": (-15.0, 15.0), "vy": (-15.0, 15.0), "w_top": (-600.0, 600.0), "wz": (-600.0, 600.0)}


@dataclass
class ShotReport:
    """What the fit says of one shot: its unknowns, its residuals' RMS overall and per ball [m]
    (outliers, beyond 5 noises, left out and counted), and its contacts in the fitted simulation."""
    name: str
    unknowns: Dict[str, float]
    rms: float
    rms_per_ball: Dict[int, float]
    outliers: int
    observations: int
    contacts: Dict[str, int]


@dataclass
class Calibration:
    """A fit's result: the coefficients with standard errors and correlations, each shot's report,
    warnings for what the data cannot determine, and the physics as a YAML the module, `simulate`
    and the node load as it is."""
    table: str
    models: Dict[str, str]
    values: Dict[str, float]
    standard_errors: Dict[str, float]
    correlations: np.ndarray
    fitted: List[str]
    shots: List[ShotReport]
    warnings: List[str]
    noise: float
    cost: float
    seconds: float
    evaluations: int
    success: bool
    message: str
    params: Dict[str, float] = field(default_factory=dict)
    residuals: Optional[np.ndarray] = None
    #: Per shot: the fitted simulation's positions (K, N, 2) at the track's instants.
    predicted: List[np.ndarray] = field(default_factory=list)

    def engine(self):
        """A cue_sim.Engine with the fitted physics."""
        from cue_sim.api import Engine
        return Engine(self.table, self.models["ball_ball"], self.models["cushion"], **self.params)

    def summary(self) -> str:
        lines = [f"fit of {', '.join(self.fitted)} to {len(self.shots)} shots on {self.table} "
                 f"({self.models['ball_ball']} ball-ball, {self.models['cushion']} cushions): {self.message}"]
        for name in self.fitted:
            lines.append(f"  {name:<24} {self.values[name]:.6g} +- {self.standard_errors[name]:.2g}")
        rms = np.sqrt(np.mean([s.rms ** 2 for s in self.shots]))
        lines.append(f"  residual RMS {1e3 * rms:.2f} mm over {sum(s.observations for s in self.shots)} positions, "
                     f"{sum(s.outliers for s in self.shots)} outliers; {self.evaluations} evaluations, "
                     f"{self.seconds:.1f} s")
        lines += [f"  warning: {w}" for w in self.warnings]
        return "\n".join(lines)

    def to_yaml(self) -> str:
        """The physics as config/physics.yaml has it: every coefficient, the fitted ones with their
        standard error, and the models."""
        from cue_sim.api import parameters
        declared = parameters()
        lines = [f"# cue_sim.calibrate: {', '.join(self.fitted)} fitted to {len(self.shots)} shots "
                 f"({self.message}); the others as given.",
                 "# Load with `rosparam load` into the table node's namespace, as a scene file's physics: block,",
                 "# or as cue_sim.Engine(table, **yaml.safe_load(...))."]
        for name, value in self.params.items():
            note = declared[name]["description"].split(";")[0]
            if name in self.fitted:
                note = f"fitted: +- {self.standard_errors[name]:.3g}; {note}"
            lines.append(f"{name}: {value!r}  # [{declared[name]['unit']}] {note}")
        lines.append(f"ball_ball_model: {self.models['ball_ball']}")
        lines.append(f"cushion_model: {self.models['cushion']}")
        return "\n".join(lines) + "\n"


def _coefficient_bounds(name: str, params: Dict[str, float]) -> Tuple[float, float]:
    from cue_sim.api import parameters
    declared = parameters()[name]
    low, high = declared["min"], declared["max"]
    if name == "cushion_height":  # strictly between R and 2R
        radius = params["ball_radius"]
        low, high = radius * 1.0001, radius * 1.9999
    return float(low), float(high)


class _ShotLayout:
    """Where a shot's unknowns lie in x and how its start is made from them: worked out once, used
    at every evaluation (a fit makes thousands; building each start from named unknowns took half
    of a 20-shot fit's time in Python)."""

    def __init__(self, track: Track, names: Sequence[str], offset: int):
        index = {name: offset + n for n, name in enumerate(names)}
        self.t0 = index["t0"]
        #: (N, 2): the columns of x that hold where each ball stood, -1 for a ball never seen
        self.rest_columns = np.array([[index.get(f"x{ball}", -1), index.get(f"y{ball}", -1)]
                                      for ball in track.ball_ids]).reshape(-1, 2)
        known = np.all(self.rest_columns >= 0, axis=1)
        #: per ball of the track: its index in the prediction (the balls seen), -1 if not in it
        self.column = np.where(known, np.cumsum(known) - 1, -1)
        ids = track.ball_ids[known]
        self.struck = int(np.flatnonzero(ids == track.struck_ball)[0])
        self.rest_known = self.rest_columns[known]
        #: the struck ball's motion (vx, vy, w_top, wz), or None when the strike's fields are fitted
        self.motion = [index[n] for n in ("vx", "vy", "w_top", "wz")] if "vx" in index else None
        #: the strike's fields: (column of x, or -1 for a value the track knows, that value)
        self.fields = [(index.get(name, -1), float(track.strike.get(name, 0.0))) for name in CUE_FIELDS]
        self.ball = int(track.struck_ball)
        self.arrays = _core.StateArrays()
        self.arrays.ids = ids.astype(np.int32)
        self.arrays.motion = np.zeros(len(ids), dtype=np.uint8)
        self.arrays.pocket = np.full(len(ids), -1, dtype=np.int32)
        self.count = len(ids)

    def rest(self, x) -> np.ndarray:
        """(N, 2): where each ball of the track stood before the shot, NaN for a ball never seen."""
        rest = np.full(self.rest_columns.shape, np.nan)
        rest[self.column >= 0] = x[self.rest_known]
        return rest

    def start(self, x):
        """The shot's start as _core.StateArrays (reused: made into the engine's state at once)."""
        positions = np.zeros((self.count, 3))
        positions[:, :2] = x[self.rest_known]
        velocities, spins = np.zeros((self.count, 3)), np.zeros((self.count, 3))
        if self.motion is not None:
            vx, vy, w_top, wz = (float(x[i]) for i in self.motion)
            speed = max(math.hypot(vx, vy), 1e-12)
            velocities[self.struck, :2] = vx, vy
            spins[self.struck] = -vy / speed * w_top, vx / speed * w_top, wz  # w_top about z x v: the rolling axis
        arrays = self.arrays
        arrays.positions, arrays.velocities, arrays.spins = positions, velocities, spins
        return arrays

    def faster(self, x, factor: float, first_moving: float):
        """x with the struck ball's speed (or the strike's, when fitted) times `factor` and the
        strike moved so that the ball still reaches where it was seen first moving at
        `first_moving` (t0's upper bound): the start of a shot struck at another moment of the
        frame before that sighting. Not clipped to the bounds."""
        y = x.copy()
        columns = self.motion[:2] if self.motion is not None else [i for (i, _), name in zip(self.fields, CUE_FIELDS)
                                                                   if name == "speed" and i >= 0]
        y[columns] *= factor
        y[self.t0] = first_moving - (first_moving - x[self.t0]) / factor
        return y

    def strike(self, x):
        """(ball, speed, phi, theta, a, b) when the strike's fields are fitted, else None."""
        if self.motion is not None:
            return None
        return (self.ball, *(float(x[i]) if i >= 0 else value for i, value in self.fields))


@dataclass
class _ShotPrediction:
    """A shot's prediction: predict_tracks' dict (None if it could not be made) for the instants
    from `first` on (after t0), made from x by the shot's layout."""
    result: Optional[dict]
    first: int
    layout: _ShotLayout
    x: np.ndarray

    @property
    def ok(self) -> bool:
        return self.result is not None

    @property
    def rest(self) -> np.ndarray:
        """(N, 2): where each ball stood before the strike, NaN for a ball never seen."""
        return self.layout.rest(self.x)

    @property
    def column(self) -> np.ndarray:
        return self.layout.column

    def at(self, k: np.ndarray, j: np.ndarray) -> np.ndarray:
        """(len(k), 2): ball j of the track at its instant k: where it stood before the strike,
        predicted after it (NaN for a ball never seen); where it stood if the shot has no prediction."""
        out = self.rest[j]
        if self.result is None:
            return out
        after = k >= self.first
        out[after] = self.result["positions"][k[after] - self.first, self.column[j[after]]]
        return out

    def positions(self, instants: int) -> np.ndarray:
        """(instants, N, 2): every ball at every instant of the track."""
        n = len(self.column)
        k, j = np.repeat(np.arange(instants), n), np.tile(np.arange(n), instants)
        return self.at(k, j).reshape(instants, n, 2)


class _Compared:
    """A shot's observations compared in a window, laid out so that the residuals are two slices
    and two gathers a shot (fancy indexing by instant and ball at every evaluation took half of a
    20-shot fit's evaluation time): the observations are in order of instant, so those before the
    strike are a head (the balls where they stood: columns of x) and the rest a tail (the
    prediction, flattened)."""

    def __init__(self, track: Track, layout: _ShotLayout, k: np.ndarray, j: np.ndarray):
        self.k, self.j = k, j
        self.observed = track.positions[k, j]
        #: where each observation lies in the flattened (instants, balls) of a prediction made
        #: from the first instant on: `flat - first * balls`
        self.balls = layout.count
        self.flat = k * self.balls + layout.column[j]
        #: the columns of x holding where each observation's ball stood
        self.rest = layout.rest_columns[j]

    def miss(self, predicted: _ShotPrediction, x, out: np.ndarray) -> None:
        """out (len(k), 2) = predicted - observed [m]."""
        head = int(self.k.searchsorted(predicted.first))
        np.take(x, self.rest[:head], out=out[:head])
        np.take(predicted.result["positions"].reshape(-1, 2), self.flat[head:] - predicted.first * self.balls, axis=0,
                out=out[head:])
        np.subtract(out, self.observed, out=out)


def _from_origin(track: Track, origin: float) -> Track:
    """The track with its times counted from `origin` (a shallow copy: the rest is shared)."""
    moved = copy.copy(track)
    moved.times = track.times - origin
    return moved


class _Problem:
    """The least-squares problem: x is the fitted coefficients, then each shot's unknowns."""

    def __init__(self, tracks: Sequence[Track], table: str, models: Dict[str, str], params: Dict[str, float],
                 fit: Sequence[str], noise: float, threads: int, unknowns: str = "motion"):
        #: Each shot's clock starts at its first instant: a lab's stamps may be seconds since 1970,
        #: where the Jacobian's difference step in t0 (relative to it) would be seconds and the
        #: solver's step tolerance (relative to x) a minute. `origins` puts the fitted strikes back
        #: on the observer's clock.
        self.origins = [float(track.times[0]) for track in tracks]
        self.tracks = [_from_origin(track, origin) for track, origin in zip(tracks, self.origins)]
        self.table, self.models = table, models
        self.unknowns = unknowns  # "motion": the struck ball's; "strike": the strike's fields not known
        self.params, self.fit, self.noise, self.threads = dict(params), list(fit), noise, threads
        self.evaluations = 0
        #: Shots a stage left on other contacts that leaving out and fitting again alone did not
        #: help: not tried again in the later stages (see _stages).
        self.given_up = set()
        self._engine_key, self._engine, self._base = None, None, None
        self.shot_names: List[List[str]] = []
        self._compared: List[_Compared] = []  # per shot: its observations compared in the window
        x0, low, high = [], [], []
        for name in self.fit:
            bounds = _coefficient_bounds(name, self.params)
            x0.append(min(max(self.params[name], bounds[0]), bounds[1]))
            low.append(bounds[0])
            high.append(bounds[1])
        self.layouts: List[_ShotLayout] = []
        for track in self.tracks:
            guess, names, bounds = self._shot_guess(track)
            self.layouts.append(_ShotLayout(track, names, len(x0)))
            self.shot_names.append(names)
            for name in names:
                x0.append(guess[name])
                low.append(bounds[name][0])
                high.append(bounds[name][1])
        self.x0, self.low, self.high = np.array(x0), np.array(low), np.array(high)
        self.x0 = np.clip(self.x0, self.low + 1e-12 * (self.high - self.low), self.high - 1e-12 * (self.high - self.low))
        self.set_window(math.inf, self.x0)

    def set_window(self, window: float, x, left_out=()) -> None:
        """Compares only the observations up to `window` seconds after each shot's strike (as x
        has it): a fit that starts from the first moments of each shot and takes in the rest as it
        goes does not lock onto a wrong sequence of contacts. The shots `left_out` (indices) are
        not compared at all."""
        self._compared = []
        for i, (track, unknowns, layout) in enumerate(zip(self.tracks, self.shot_unknowns(x), self.layouts)):
            k, j = np.nonzero(track.seen())
            inside = (track.times[k] <= unknowns["t0"] + window) & (i not in left_out)
            self._compared.append(_Compared(track, layout, k[inside], j[inside]))
        self.size = sum(len(c.k) for c in self._compared) * 2

    @property
    def rows(self) -> List[Tuple[np.ndarray, np.ndarray]]:
        """Per shot: the (instant, ball) pairs compared in the window."""
        return [(c.k, c.j) for c in self._compared]

    # -- a shot's unknowns and where it starts ------------------------------------------------
    def _first_motion(self, track: Track, j: int, rest: np.ndarray) -> Optional[int]:
        """The first instant ball j is seen away from where it stood, in that sighting and the next
        two (an outlier is one sighting), or None."""
        seen = track.seen()[:, j]
        away = seen & (np.linalg.norm(track.positions[:, j] - rest[j], axis=1) > MOVED_IN_NOISES * self.noise)
        sightings = np.flatnonzero(seen)
        for n, k in enumerate(sightings[:-2]):
            if away[sightings[n:n + 3]].all():
                return int(k)
        return None

    def _robust_velocity(self, times: np.ndarray, points: np.ndarray) -> np.ndarray:
        """The velocity of a straight, steady line through the points, an outlier or two left out."""
        keep = np.ones(len(times), dtype=bool)
        for _ in range(3):
            slope, offset = np.polyfit(times[keep], points[keep], 1)
            miss = np.linalg.norm(points - (np.outer(times, slope) + offset), axis=1)
            again = miss <= max(4 * self.noise, np.median(miss[keep]) * 4)
            if again.sum() < 2 or np.array_equal(again, keep):
                break
            keep = again
        return slope

    def _shot_guess(self, track: Track):
        """Initial unknowns of a shot, their names and bounds, from the struck ball's first motion
        before another ball moves."""
        j = int(np.flatnonzero(track.ball_ids == track.struck_ball)[0])
        rest = track.resting_positions()
        seen = track.seen()[:, j]
        k1 = self._first_motion(track, j, rest)
        if k1 is None:
            raise ValueError(f"{track.label}the struck ball {track.struck_ball} is never seen moving")
        others = [self._first_motion(track, i, rest) for i in range(len(track.ball_ids)) if i != j]
        others = [track.times[k] for k in others if k is not None and k > k1]
        alone_until = min(others) if others else math.inf
        # The struck ball alone, over its first 0.2 s at most: a straight line, near enough.
        alone = np.flatnonzero(seen & (track.times >= track.times[k1]) & (track.times < min(alone_until,
                                                                                                 track.times[k1] + 0.2)))
        if len(alone) >= 3:
            v = self._robust_velocity(track.times[alone], track.positions[alone, j])
        elif len(alone) == 2:
            # Two sightings before the next ball moves (a fast shot at a near ball, 30 Hz): the way
            # between them. From where it stood over a frame's time the speed is short by the share
            # of the frame before the strike (seen: 2.3 for 3.7 m/s, a start no stage came back from).
            v = np.diff(track.positions[alone, j], axis=0)[0] / np.diff(track.times[alone])[0]
        else:
            v = (track.positions[k1, j] - rest[j]) / max(track.times[k1] - track.times[max(k1 - 1, 0)], 1e-3)
        speed = max(float(np.linalg.norm(v)), 0.05)
        t0 = track.times[k1] - float(np.linalg.norm(track.positions[k1, j] - rest[j])) / speed
        # The strike came before the first frame that shows the ball moved: within the frame
        # before it for a fast shot, a few frames before for a slow one.
        period = float(np.median(np.diff(track.times)))
        t_low = track.times[k1] - max(3 * period, 0.1)
        # ... or before the last sighting of it standing, when frames were lost between (a busy
        # camera: seen, 0.2 s without a frame, the strike 0.17 s before the first that shows it).
        standing = np.flatnonzero(seen[:k1])
        if len(standing):
            t_low = min(t_low, track.times[standing[-1]] - period)
        guess = {"t0": min(max(t0, t_low + 1e-6), track.times[k1] - 1e-6)}
        bounds = {"t0": (t_low, track.times[k1])}
        names = ["t0"]
        if "speed" in track.strike or self.unknowns == "strike":
            commanded = track.commanded or {}
            if "speed" not in track.strike and "speed" not in commanded:
                raise ValueError(f"{track.label}the strike's fields are fitted from the commanded strike: "
                                 "the track has none (Track.commanded)")
            for name in CUE_FIELDS:
                if name not in track.strike:
                    names.append(name)
                    bounds[name] = STRIKE_BOUNDS[name]
                    guess[name] = commanded.get(name, math.atan2(v[1], v[0]) if name == "phi" else 0.0)
        else:
            names += ["vx", "vy", "w_top", "wz"]
            guess.update(vx=float(v[0]), vy=float(v[1]), w_top=0.0, wz=0.0)
            bounds.update(BALL_BOUNDS)
        # Where each ball stood before the shot is an unknown too, from where it was first seen:
        # a detector's noise on it would otherwise shift the whole track.
        rest = track.resting_positions(before=t0)
        for index, ball in enumerate(track.ball_ids):
            if np.all(np.isfinite(rest[index])):
                for axis, value in zip("xy", rest[index]):
                    names.append(f"{axis}{ball}")
                    guess[names[-1]] = float(value)
                    bounds[names[-1]] = (float(value) - REST_SLACK, float(value) + REST_SLACK)
        return guess, names, bounds

    def starts(self):
        """The starts of a one-shot problem's fit: its first guess, then the struck ball faster
        and slower by FASTER_STARTS (the strike earlier or later in the frame before it was first
        seen moving: with one sighting before the next ball moves the guess cannot tell)."""
        layout = self.layouts[0]
        yield self.x0.copy()
        for factor in FASTER_STARTS:
            yield np.clip(layout.faster(self.x0, factor, self.high[layout.t0]), self.low, self.high)

    def coefficients(self, x) -> Dict[str, float]:
        return dict(self.params, **{name: float(x[i]) for i, name in enumerate(self.fit)})

    def shot_unknowns(self, x) -> List[Dict[str, float]]:
        out, i = [], len(self.fit)
        for names in self.shot_names:
            out.append({name: float(x[i + n]) for n, name in enumerate(names)})
            i += len(names)
        return out

    def engine(self, x):
        from cue_sim.api import Engine
        key = tuple(float(v) for v in x[:len(self.fit)])
        if self._base is None:
            self._base = Engine(self.table, self.models["ball_ball"], self.models["cushion"], **self.params)
        if key != self._engine_key:  # a Jacobian's shot columns share the coefficients: one engine
            self._engine = self._base.with_params(**{name: float(x[i]) for i, name in enumerate(self.fit)})
            self._engine_key = key
        return self._engine

    def predict(self, x) -> List[_ShotPrediction]:
        """Per shot: its prediction from x at every instant of its track after its strike (t0)."""
        engine = self.engine(x)
        x = np.array(x, dtype=float)  # the predictions keep it: the solver's x may change in place
        starts, strikes, times, firsts = [], [], [], []
        for track, layout in zip(self.tracks, self.layouts):
            t0 = float(x[layout.t0])
            starts.append(layout.start(x))
            strikes.append(layout.strike(x))
            first = int(track.times.searchsorted(t0, side="right"))  # the first instant after t0
            times.append(track.times[first:] - t0)
            firsts.append(first)
        try:
            predictions = _core.predict_tracks(engine._engine, starts, strikes, times, self.threads,
                                               [track.exposure for track in self.tracks])
        except ValueError:
            predictions = [None] * len(self.tracks)
        self.evaluations += 1
        return [_ShotPrediction(p if p is not None and not p["error"] else None, first, layout, x)
                for p, first, layout in zip(predictions, firsts, self.layouts)]

    def residuals(self, x) -> np.ndarray:
        out, offset = np.empty(self.size), 0
        for predicted, compared in zip(self.predict(x), self._compared):
            part = out[offset:offset + 2 * len(compared.observed)].reshape(-1, 2)
            offset += part.size
            if predicted.ok:
                compared.miss(predicted, x, part)
                part /= self.noise
            else:
                part[:] = UNPREDICTABLE
        return out

    def sparsity(self):
        from scipy.sparse import lil_matrix
        pattern = lil_matrix((self.size, len(self.x0)), dtype=int)
        row, column = 0, len(self.fit)
        for names, (k, _) in zip(self.shot_names, self.rows):
            rows = slice(row, row + 2 * len(k))
            pattern[rows, :len(self.fit)] = 1
            pattern[rows, column:column + len(names)] = 1
            row += 2 * len(k)
            column += len(names)
        return pattern


#: The stages of a fit: (the seconds of each shot compared after its strike, whether the
#: coefficients move too, the robust loss's scale in noises). Each stage starts from the last; the
#: first runs twice (the solver started afresh from where it stopped, with a new trust region: in
#: the coverage trials a single run left some shots' starts short). The
#: loss is nearly quadratic out to 10 noises until the whole shots are in, so that a shot far from
#: its data still pulls the coefficients back (a loss flat beyond a noise lets a wrong start stand),
#: and then narrows to the noise itself, where a tracker's outliers weigh little.
STAGES = ((0.3, False, 10.0), (0.3, False, 10.0), (0.6, False, 10.0), (1.0, True, 10.0), (1.6, True, 10.0),
          (2.5, True, 10.0), (4.0, True, 10.0), (math.inf, True, 10.0), (math.inf, True, 3.0), (math.inf, True, 1.0))
#: The sliding friction's values a fit starts from when it is fitted: the first moments of the
#: shots are fitted from each, the best RANKED_STARTS go on through the first stage that frees the
#: coefficients, and the rest runs from the one whose shots fit best there. Its range on real
#: cloth (0.15 to 0.4) is wide enough that a start at one end leaves the shots' unknowns to make up
#: for it, and the fit then stands in a wrong place.
SLIDE_STARTS = (0.15, 0.2, 0.25, 0.3, 0.35)
#: How many of them go on past the first moments of the shots.
RANKED_STARTS = 2
#: An intermediate stage stops at this relative change of the cost (it is a start for the next);
#: the last at a hundredth of that: 20 shots' coefficients are then where a stop at 1e-8 puts them
#: to six digits (a tenth of a standard error), for a fifth less time.
STAGE_TOLERANCE = 1e-5
LAST_TOLERANCE = 1e-7
#: The last stage of a fit with coefficients runs in rounds of this many evaluations (_settle) ...
SETTLE_ROUND = 20
#: ... and stops once a round has moved no coefficient by more than this share of its standard
#: error: at a linear rate of 0.95 an evaluation (the slowest seen), what is left of its way is
#: then about half a round's move, under 1 % of a standard error.
SETTLED_SHARE = 0.01


def calibrate(tracks: Sequence[Track], fit: Sequence[str] = ("mu_slide", "mu_roll"), table: str = "7ft",
              ball_ball_model: Optional[str] = None, cushion_model: Optional[str] = None,
              params: Optional[Dict[str, float]] = None, noise: float = DEFAULT_NOISE, threads: int = 0,
              max_evaluations: int = 300, progress=None) -> Calibration:
    """Fits the coefficients named in `fit` (of FITTABLE, each within its registry range) and
    every shot's unknowns to `tracks`, on `table` with the given models, the other coefficients
    from `params` (else the defaults). `noise` [m] is the observations' standard deviation: the
    unit of the residuals and the robust loss's scale. `progress(stage, evaluations, cost)` is
    called as the solver goes. Returns a Calibration."""
    from cue_sim.api import Engine
    if not tracks:
        raise ValueError("tracks: at least one shot")
    unknown = [name for name in fit if name not in FITTABLE]
    if unknown or len(set(fit)) != len(fit):
        raise ValueError(f"fit: {', '.join(unknown) or 'a name twice'}; it takes distinct names of "
                         f"{', '.join(FITTABLE)}")
    if not (noise > 0 and math.isfinite(noise)):
        raise ValueError(f"noise: a positive standard deviation [m], got {noise}")
    base = Engine(table, ball_ball_model, cushion_model, **(params or {}))
    models = {"ball_ball": base.models["ball_ball"], "cushion": base.models["cushion"]}
    problem = _Problem(tracks, table, models, base.params, fit, noise, threads)
    begin = time.perf_counter()
    held = next(i for i, stage in enumerate(STAGES) if stage[1])  # the stages with the coefficients held
    starts = [problem.x0.copy()]
    if "mu_slide" in problem.fit:  # the sliding friction's range is wide, and a wrong start stands
        i = problem.fit.index("mu_slide")
        starts = []
        for value in SLIDE_STARTS:
            start = problem.x0.copy()
            start[i] = min(max(value, problem.low[i]), problem.high[i])
            starts.append(start)
    # Each start runs the first moments of its shots (the first stages' window, before most contacts),
    # whose cost ranks the starts; the best RANKED_STARTS run on through the first stage that frees
    # the coefficients, and the best of them there goes on. With the coefficients held at their
    # defaults a restitution far from the table's misfits every contact in a longer window alike,
    # and the held stages' costs over it do not rank the starts (seen: a start 10 % off ranked first,
    # then led the fit onto other contacts in three shots).
    first = next(i for i, stage in enumerate(STAGES) if stage[0] > STAGES[0][0])
    ranked = sorted((_stages(problem, start, range(first), max_evaluations, progress) for start in starts),
                    key=lambda run: run[1].cost)
    best = None
    for x, _ in ranked[:RANKED_STARTS]:
        x, result = _stages(problem, x, range(first, held + 1), max_evaluations, progress)
        if best is None or result.cost < best[1].cost:
            best = (x, result)
    # The whole shots in with the wide loss; then a shot left on other contacts than its data's is
    # fitted again alone (a narrow loss would leave it be, and take long about it); then the loss
    # narrows.
    narrow = next(i for i, stage in enumerate(STAGES) if stage[2] < STAGES[0][2])
    x, result = _stages(problem, best[0], range(held + 1, narrow), max_evaluations, progress)
    _refit_misfits(problem, x, max_evaluations)
    x, result = _stages(problem, x, range(narrow, len(STAGES)), max_evaluations, progress)
    return _report(problem, x, result, time.perf_counter() - begin)


def _misfit_shares(problem: _Problem, x) -> List[float]:
    """Per shot: the share of its positions beyond 5 noises of the prediction from x."""
    shares = []
    for predicted, track, (k, j) in zip(problem.predict(x), problem.tracks, problem.rows):
        miss = (np.linalg.norm(predicted.at(k, j) - track.positions[k, j], axis=1) if predicted.ok
                else np.full(len(k), np.inf))
        shares.append(float(np.mean(miss > 5 * problem.noise)) if len(k) else 0.0)
    return shares


def _refit_misfits(problem: _Problem, x, max_evaluations: int, window: float = math.inf,
                   share_limit: float = MISFIT_SHARE, only=None) -> bool:
    """Fits again, alone and with the coefficients as x has them, each shot (of `only`, if given)
    that the joint fit left on another sequence of contacts than its data's (more than
    `share_limit` of its positions up to `window` seconds after its strike beyond 5 noises), and
    keeps its new unknowns where they fit it better. Changes x; returns the shots that now fit
    (`share_limit` or less). Leaves the problem's window at `window`, every shot in."""
    problem.set_window(window, x)
    shares = _misfit_shares(problem, x)
    fitted = set()
    offset = len(problem.fit)
    reach = range(len(STAGES)) if window == math.inf else [i for i, s in enumerate(STAGES) if s[0] <= window]
    for i, (track, share) in enumerate(zip(problem.tracks, shares)):
        width = len(problem.shot_names[i])
        if share > share_limit and (only is None or i in only):
            alone = _Problem([track], problem.table, problem.models, problem.coefficients(x), [], problem.noise,
                             problem.threads, problem.unknowns)
            for y in alone.starts():
                y, _ = _stages(alone, y, reach, max_evaluations // 5, None)
                alone.set_window(window, y)
                refitted = _misfit_shares(alone, y)[0]
                if refitted < share:
                    x[offset:offset + width] = y
                    share = refitted
                alone.set_window(STAGES[0][0], y)
                if share <= share_limit or _misfit_shares(alone, y)[0] <= share_limit:
                    break  # fitted; or its first moments are, and what misses later is not the start's
            if share <= share_limit:
                fitted.add(i)
        offset += width
    problem.set_window(window, x)
    return fitted


def _stages(problem: _Problem, x, stages, max_evaluations: int, progress):
    """Runs the given STAGES from x: (x after them, the last stage's solver.Solution)."""
    x = x.copy()
    result = None
    for stage in stages:
        window, coefficients_too, scale = STAGES[stage]
        problem.set_window(window, x)
        active = np.ones(len(x), dtype=bool)
        active[:len(problem.fit)] = coefficients_too
        last = stage == len(STAGES) - 1

        def solve(start, stage=stage, scale=scale, active=active, last=last):
            """The stage's solve from `start`, which takes its result."""
            report = (lambda n, c: progress(stage, n, c)) if progress else (lambda n, c: None)
            if last and problem.fit:
                return _settle(problem, start, active, max_evaluations, scale, report)
            run = _solve(problem, start, active, max_evaluations if last else max_evaluations // 5,
                         LAST_TOLERANCE if last else STAGE_TOLERANCE, scale, report)
            start[active] = run.x
            return run

        before = x.copy()
        result = solve(x)
        shares = _misfit_shares(problem, x) if coefficients_too and problem.fit else [0.0]
        misfits = {i for i, share in enumerate(shares) if share > STAGE_MISFIT_SHARE} - problem.given_up
        if misfits and len(misfits) < len(problem.tracks):
            # A shot the longer window put on other contacts than its data's may pull the
            # coefficients after it: the stage runs again from where it began without that shot,
            # which is then fitted again alone with the coefficients the others give, and the stage
            # once more with every shot in; of the two ends, the one whose whole data's cost is lower
            # stands (leaving a shot out helps when it drags the others, not when it alone is hard).
            other = before
            problem.set_window(window, other, left_out=misfits)
            solve(other)
            fitted = _refit_misfits(problem, other, max_evaluations, window, STAGE_MISFIT_SHARE, only=misfits)
            # The stage runs again with every shot in only if fitting alone put one of them back on
            # its data's contacts: in 8 20-shot draws every rescue that lowered the cost had such a
            # shot and each that did not had none (seed 4's fourth draw: 16 s of 106 in two such runs).
            trial = solve(other) if fitted else None
            if os.environ.get("CUE_SIM_CALIBRATE_DEBUG"):
                print(f"stage {stage}: shots {sorted(misfits)} left out and fitted again ({sorted(fitted)} fit alone): "
                      f"cost {result.cost:.1f} -> {trial.cost if trial else math.nan:.1f}", flush=True)
            if trial is not None and trial.cost < result.cost:
                x, result = other, trial
            else:
                # Not rescued: each later stage would spend two runs and the shot's refits on it
                # again (seen: a 20-shot fit taking 5 minutes over one such shot, to no effect).
                problem.set_window(window, x)
                problem.given_up |= misfits
        if os.environ.get("CUE_SIM_CALIBRATE_DEBUG"):
            print(f"stage {stage}: nfev {result.nfev} njev {result.njev} cost {result.cost:.1f} {result.message} "
                  f"{x[:len(problem.fit)]}", flush=True)
    return x, result


def _settle(problem: _Problem, x, active, max_evaluations: int, scale: float, progress):
    """The last stage of a fit with coefficients: solves in rounds of SETTLE_ROUND
    evaluations, each from where the last stopped, until a round converges by LAST_TOLERANCE, moves
    no coefficient by more than SETTLED_SHARE of its standard error, or max_evaluations are spent.
    x takes the result. With the loss narrowed to the noise a solver's steps may converge only
    linearly: seen with scipy's least_squares, 300 evaluations in which the shots' unknowns crept by
    micrometres and the cost by 1e-5 of itself a step, never within its tolerance, while the
    coefficients moved by a millionth of themselves."""
    spent, n = 0, len(problem.fit)
    while True:
        before = x[:n].copy()
        run = _solve(problem, x, active, min(SETTLE_ROUND, max_evaluations - spent), LAST_TOLERANCE, scale, progress)
        x[active] = run.x
        spent += run.nfev
        if run.status != 0 or spent >= max_evaluations:  # converged by its own tolerances, or out of budget
            break
        errors = np.sqrt(np.abs(np.diag(uncertainty.gauss_newton(_profile(problem, run), run.cost, problem.size,
                                                                  len(x)))))
        if np.all(np.abs(x[:n] - before) <= SETTLED_SHARE * errors):
            run.status, run.success = 2, True
            run.message = (f"the coefficients moved less than {100 * SETTLED_SHARE:g} % of their standard errors in "
                           f"{run.nfev} evaluations")
            break
    run.nfev = spent
    return run


def _profile(problem: _Problem, result) -> uncertainty.Profiled:
    """The coefficients' information from a solve's result on the problem, its shots'
    unknowns profiled out (uncertainty.profile)."""
    rows = [2 * len(k) for k, _ in problem.rows]
    columns, start = [], len(problem.fit)
    for names in problem.shot_names:
        columns.append(list(range(start, start + len(names))))
        start += len(names)
    return uncertainty.profile(result.jac, result.fun, STAGES[-1][2], rows, columns, len(problem.fit))


def _solve(problem: _Problem, x, active, max_evaluations: int, tolerance: float, scale: float, progress):
    """The robust least squares over the active components of x (every shot's unknowns, and the
    coefficients or none of them), the others held (solver.solve: Ceres)."""
    full = x.copy()

    def residuals(free):
        full[active] = free
        r = problem.residuals(full)
        progress(problem.evaluations, float(np.sum(np.sqrt(1 + r ** 2) - 1)))  # soft_l1's cost
        return r

    shared = len(problem.fit) if active[:len(problem.fit)].all() else 0
    groups, column, row = [], shared, 0
    for names, (k, _) in zip(problem.shot_names, problem.rows):
        groups.append((column, len(names), row, 2 * len(k)))
        column += len(names)
        row += 2 * len(k)
    sparsity = problem.sparsity().tocsc()[:, np.flatnonzero(active)]
    bounds = (problem.low[active], problem.high[active])
    return solver.solve(residuals, x[active], bounds, sparsity, shared, groups, scale, max_evaluations, tolerance)


def _report(problem: _Problem, x, result, seconds: float) -> Calibration:
    n = len(problem.fit)
    profiled = _profile(problem, result)
    candidates = {"gauss_newton": uncertainty.gauss_newton(profiled, result.cost, problem.size, len(x))}
    if n and len(problem.tracks) > 1:
        candidates["shot_sandwich"] = uncertainty.shot_sandwich(profiled)
        candidates["shot_jackknife"] = uncertainty.shot_jackknife(profiled)
    # The largest: Gauss-Newton's holds for independent errors, the shots' sandwich and jackknife
    # also when a detector errs alike through a shot (doc/calibration.md, "Uncertainty").
    variances = np.max([np.abs(np.diag(c)) for c in candidates.values()], axis=0) if n else np.zeros(0)
    if os.environ.get("CUE_SIM_CALIBRATE_DEBUG"):
        for name, c in candidates.items():
            print(f"standard errors, {name}: {np.sqrt(np.abs(np.diag(c)))}", flush=True)
    errors = np.sqrt(variances)
    with np.errstate(invalid="ignore", divide="ignore"):
        widest = max(candidates.values(),
                     key=lambda c: float(np.nansum(np.abs(np.diag(c)) / np.maximum(variances, 1e-300))))
        corr = widest / np.sqrt(np.outer(np.abs(np.diag(widest)), np.abs(np.diag(widest))))
    values = problem.coefficients(x)
    shots, contacts = [], {"ball_ball": 0, "cushion": 0}
    predicted = problem.predict(x)
    for track, unknowns, shot, (k, j), origin in zip(problem.tracks, problem.shot_unknowns(x), predicted, problem.rows,
                                                     problem.origins):
        miss = np.linalg.norm(shot.at(k, j) - track.positions[k, j], axis=1)
        ok, p = shot.ok, shot.result
        inlier = miss <= 5 * problem.noise
        per_ball = {}
        for index, ball in enumerate(track.ball_ids):
            mine = (j == index) & inlier
            if mine.any():
                per_ball[int(ball)] = float(np.sqrt(np.mean(miss[mine] ** 2)))
        counts = {"ball_ball": p["ball_ball"], "cushion": p["cushion"], "pocketed": p["pocketed"]} if ok else {}
        for kind in contacts:
            contacts[kind] += counts.get(kind, 0)
        unknowns = dict(unknowns, t0=unknowns["t0"] + origin)  # on the observer's clock
        shots.append(ShotReport(track.name, unknowns, float(np.sqrt(np.mean(miss[inlier] ** 2))) if inlier.any()
                                else float("nan"), per_ball, int((~inlier).sum()), len(k), counts))
    warnings = _warnings(problem, values, errors, contacts, shots, result)
    return Calibration(problem.table, problem.models, {name: values[name] for name in problem.fit},
                       {name: float(e) for name, e in zip(problem.fit, errors)}, corr, list(problem.fit), shots,
                       warnings, problem.noise, float(result.cost), seconds, problem.evaluations,
                       bool(result.success), result.message, values, result.fun * problem.noise,
                       [shot.positions(len(track.times)) for shot, track in zip(predicted, problem.tracks)])


def _warnings(problem, values, errors, contacts, shots, result) -> List[str]:
    out = []
    for name, error in zip(problem.fit, errors):
        if name in NEEDS_BALL_BALL and contacts["ball_ball"] == 0:
            out.append(f"{name}: no shot has a ball-ball contact, so the data says nothing of it")
        elif name in NEEDS_CUSHION and contacts["cushion"] == 0:
            out.append(f"{name}: no shot meets a cushion, so the data says nothing of it")
        elif not np.isfinite(error) or error > UNDETERMINED_SHARE * abs(values[name]):
            out.append(f"{name}: not determined by the data (standard error {error:.2g} on {values[name]:.3g})")
    for shot in shots:
        if shot.observations and shot.outliers > MISFIT_SHARE * shot.observations:
            out.append(f"{shot.name}: {100 * shot.outliers / shot.observations:.0f} % of its positions miss by more than "
                       f"5 noises: the fit has it on another sequence of contacts than the table's (doc/calibration.md)")
    failed = [s.name or str(i) for i, s in enumerate(shots) if not s.contacts]
    if failed:
        out.append(f"shots that could not be simulated at the solution: {', '.join(failed)}")
    if not result.success:
        out.append(f"the solver stopped before converging: {result.message}")
    return out


def compare_models(tracks: Sequence[Track], fit: Sequence[str], cushion_models: Sequence[str] = (),
                   ball_ball_models: Sequence[str] = (), **options) -> List[Calibration]:
    """The same fit under each named cushion model (and each ball-ball model), best first by the
    robust cost at the solution: the model the data prefers. `fit` names each model's own
    coefficients as well as the shared ones; a coefficient a model does not use is reported as not
    determined under it."""
    cushions = list(cushion_models) or [options.pop("cushion_model", None)]
    ball_balls = list(ball_ball_models) or [options.pop("ball_ball_model", None)]
    results = []
    for cushion in cushions:
        for ball_ball in ball_balls:
            results.append(calibrate(tracks, fit, cushion_model=cushion, ball_ball_model=ball_ball, **options))
    return sorted(results, key=lambda r: r.cost)
