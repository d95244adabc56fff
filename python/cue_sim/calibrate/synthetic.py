"""Observed shots made from the simulator itself, with a tracker's faults: what the fit's tests and
its coverage study (scripts/calibration_coverage.py) fit to, with the coefficients known.

A shot is struck on a table of a few balls and sampled at `rate` Hz from some frames before the
strike (at a random phase of the frame clock) until `duration` s after it; each position gets
Gaussian noise of `noise` [m] on each axis, a share `outliers` of them is thrown off by some
centimetres, a share `gaps` is lost, and a pocketed ball is not seen.
"""
from __future__ import annotations

from typing import List, Optional

import numpy as np

from cue_sim.calibrate.tracks import Track

#: Where a lab's coefficients lie, for hidden ones drawn at random (the tests, the coverage study):
#: cloth from slow to fast, cushions from dead to lively (Alciatore; Mathavan et al. 2009, 2010).
LAB_RANGES = {"mu_slide": (0.15, 0.35), "mu_roll": (0.006, 0.014), "e_cushion": (0.7, 0.9), "e_ball": (0.9, 0.97)}

#: How far an outlier is thrown [m], one standard deviation on each axis: a detection of
#: something else (a reflection, the other ball of a pair).
OUTLIER_THROW = 0.05


def random_layout(engine, rng: np.random.Generator, balls: int = 3, margin: float = 0.12) -> np.ndarray:
    """(balls, 2) positions on the cloth, `margin` [m] clear of the cushions and of each other."""
    cx, cy, length, width = engine._engine.cloth
    low = np.array([cx - length / 2 + margin, cy - width / 2 + margin])
    high = np.array([cx + length / 2 - margin, cy + width / 2 - margin])
    while True:
        pos = rng.uniform(low, high, size=(balls, 2))
        gaps = np.linalg.norm(pos[:, None] - pos[None], axis=2) + np.eye(balls)
        if gaps.min() > margin:
            return pos


def observe(engine, ids, positions, strike: dict, rate: float = 60.0, duration: float = 4.0, noise: float = 0.002,
            outliers: float = 0.0, gaps: float = 0.0, seed: int = 0, name: str = "") -> Track:
    """The track a camera at `rate` Hz would give of the shot `strike` (speed, phi, theta, a, b;
    ball 0 unless it says) from the balls `ids` at `positions`, on `engine` (the module's text).
    The track's `truth` holds the strike's time on the track's clock and the shot's contacts."""
    from cue_sim._interpreter import core
    from cue_sim.api import State
    rng = np.random.default_rng(seed)
    ids = np.asarray(ids, dtype=int)
    positions = np.asarray(positions, dtype=float)
    ball = int(strike.get("ball", 0))
    fields = [float(strike.get(k, 0.0)) for k in ("speed", "phi", "theta", "a", "b")]
    phase = float(rng.uniform(0, 1 / rate))  # the first frame after the strike, from it
    before = int(rng.integers(int(0.2 * rate), int(0.5 * rate) + 1))
    after = phase + np.arange(int(duration * rate)) / rate
    predicted = core().predict_tracks(engine._engine, [State.from_balls(ids, positions)._arrays()],
                                      [(ball, *fields)], [after])[0]
    if predicted["error"]:
        raise ValueError(f"the shot cannot be played: {predicted['error']}")
    times = np.concatenate([phase - np.arange(before, 0, -1) / rate, after])
    observed = np.concatenate([np.repeat(positions[None], before, axis=0), predicted["positions"]])
    visible = np.concatenate([np.ones((before, len(ids)), dtype=bool), predicted["on_table"]])
    observed = observed + rng.normal(0, noise, observed.shape)
    thrown = rng.random(observed.shape[:2]) < outliers
    observed[thrown] += rng.normal(0, OUTLIER_THROW, (int(thrown.sum()), 2))
    observed[(rng.random(observed.shape[:2]) < gaps) | ~visible] = np.nan
    clock = float(rng.uniform(0, 100))  # the observer's clock starts anywhere
    return Track(times + clock, ids, observed, strike={"ball": ball}, name=name,
                 truth={"t0": clock, "phi": fields[1], "ball_ball": predicted["ball_ball"], "cushion": predicted["cushion"]})


def random_shot(engine, rng: np.random.Generator, index: int, balls: int = 3):
    """One shot of a calibration session: a random layout of `balls` balls (random_layout) and the
    cue ball (0) struck towards ball 1 + index % (balls - 1), a little off, at 1 to 3 m/s, with draw
    or follow. Returns (positions (balls, 2), strike {speed, phi, b}). The same draws whoever plays
    it: random_shots, cue_sim.calibrate.film and scripts/calibration_session.py."""
    positions = random_layout(engine, rng, balls)
    target = positions[1 + index % (balls - 1)] - positions[0]
    strike = {"speed": rng.uniform(1.0, 3.0), "phi": float(np.arctan2(target[1], target[0]) + rng.normal(0, 0.05)),
              "b": rng.uniform(-0.3, 0.3)}
    return positions, strike


def random_shots(engine, count: int, seed: int = 0, balls: int = 3, **observation) -> List[Track]:
    """`count` shots (random_shot), observed as observe() does with `observation`'s options."""
    rng = np.random.default_rng(seed)
    tracks = []
    for i in range(count):
        positions, strike = random_shot(engine, rng, i, balls)
        tracks.append(observe(engine, list(range(balls)), positions, strike, seed=int(rng.integers(2**32)),
                              name=f"shot {i}", **observation))
    return tracks


def repeated_strikes(engine, ids, positions, commanded: dict, deviations: dict, count: int, seed: int = 0,
                     **observation) -> List[Track]:
    """`count` strikes of the same `commanded` shot (speed, phi, theta, a, b) from the same balls,
    each executed with Gaussian noise of `deviations` (the node's units: a and b in metres; the
    elevation folded at 0 as the node's cue folds it) and observed as observe() does: a robot's
    repeatability test with the noise known. Each track's `truth` holds its executed strike."""
    rng = np.random.default_rng(seed)
    radius = engine.params["ball_radius"]
    tracks = []
    for i in range(count):
        executed = {name: float(commanded.get(name, 0.0)) + rng.normal(0.0, deviations.get(name, 0.0))
                    / (radius if name in ("a", "b") else 1.0) for name in ("speed", "phi", "theta", "a", "b")}
        executed["theta"] = max(executed["theta"], 0.0)
        executed["ball"] = int(commanded.get("ball", 0))
        track = observe(engine, ids, positions, executed, seed=int(rng.integers(2**32)), name=f"strike {i}",
                        **observation)
        track.commanded = {"ball": executed["ball"], **{k: float(commanded.get(k, 0.0)) for k in
                                                       ("speed", "phi", "theta", "a", "b")}}
        track.truth["executed"] = executed
        tracks.append(track)
    return tracks
