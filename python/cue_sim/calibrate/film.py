"""Shots filmed by the simulated camera and found by the example detector: tracks made as a lab's
would be, for proving a fit end to end (test_calibrate_camera.py, scripts/calibration_coverage.py
--camera).

Each frame is the node's camera (cue_sim._core.ShotFilm: the same renderer, lens and motion blur
as ~camera/image_raw) with sensor noise; the example detector (cue_sim.detection) finds the balls
in it and takes them onto the plane of the balls' centres through the lens; the anonymous
detections are followed into tracks (cue_sim.calibrate.association). Nothing of the simulation
reaches the track but the pixels.
"""
from __future__ import annotations

from typing import List, Optional

import numpy as np

from cue_sim.calibrate.association import associate
from cue_sim.calibrate.synthetic import random_shot
from cue_sim.calibrate.tracks import Track


class Camera:
    """The simulated camera over `engine`'s table: the default overhead calibration read out at
    `width` x `height`, an `exposure` [s] shutter and `noise` [8-bit levels] of sensor noise."""

    def __init__(self, engine, width: int = 960, height: int = 600, exposure: float = 0.004, noise: float = 2.0,
                 seed: int = 0):
        from cue_sim._interpreter import core
        self.engine = engine
        self.exposure = exposure
        self.film = core().ShotFilm(engine._engine, "", width, height, None, exposure, noise, seed)
        self.matrix, self.distortion, pose = self.film.lens
        self.rotation, self.translation = pose[:3, :3], pose[:3, 3]
        self.radius = engine.params["ball_radius"]
        # a ball's apparent radius [px] on the cloth, straight below
        self.pixel_radius = self.matrix[0, 0] * self.radius / (self.translation[2] - self.radius)
        self.region = None

    def detections(self, time: float) -> np.ndarray:
        """(n, 2): where the detector finds balls [m, table frame] in the frame centred on `time`."""
        from cue_sim import detection
        image, _ = self.film.frame(time)
        if self.region is None:  # the camera does not move
            self.region = detection.cloth_region(image, detection.cloth_colour(image))
        pixels = detection.detect_balls(image, self.pixel_radius, self.region)
        return detection.table_positions(pixels, self.matrix, self.distortion, self.rotation, self.translation,
                                         self.radius)[:, :2]


def filmed(camera: Camera, ids, positions, strike: dict, rate: float = 60.0, duration: float = 4.0,
           seed: int = 0, name: str = "", noise: float = 0.002) -> Track:
    """The track of the shot `strike` (speed, phi, theta, a, b; ball 0 unless it says) from the balls
    `ids` at `positions`, filmed at `rate` Hz from some frames before the strike (at a random
    phase of the frame clock) until `duration` s after it, and found by the detector; `noise` [m]
    is the detector's error the association assumes. The track's `truth` holds the strike's time on
    the track's clock and the shot's contacts."""
    from cue_sim._interpreter import core
    from cue_sim.api import State
    rng = np.random.default_rng(seed)
    ball = int(strike.get("ball", 0))
    fields = [float(strike.get(k, 0.0)) for k in ("speed", "phi", "theta", "a", "b")]
    start = State.from_balls(np.asarray(ids, dtype=int), np.asarray(positions, dtype=float))._arrays()
    phase = float(rng.uniform(0, 1 / rate))
    before = int(rng.integers(int(0.2 * rate), int(0.5 * rate) + 1))
    times = phase + np.arange(-before, int(duration * rate)) / rate
    camera.film.begin(camera.engine._engine, start, (ball, *fields))
    frames = [camera.detections(t) for t in times]
    # The balls' identities at the start are known, as a lab's table state says them (bags.py).
    known = {int(b): p for b, p in zip(ids, np.asarray(positions, dtype=float))}
    track = associate(times, frames, 0.0, ball, known=known, noise=noise, radius=camera.radius, heading=fields[1],
                      name=name)
    after = times > 0
    exact = core().predict_tracks(camera.engine._engine, [start], [(ball, *fields)], [times[after]])[0]
    # Where each of the track's balls truly was at each frame's middle (NaN once pocketed).
    order = [list(ids).index(b) for b in track.ball_ids]
    truth = np.repeat(np.asarray(positions, dtype=float)[order][None], len(times), axis=0)
    truth[after] = np.where(exact["on_table"][:, order, None], exact["positions"][:, order], np.nan)
    clock = float(rng.uniform(0, 100))  # the observer's clock starts anywhere
    track.times = track.times + clock
    track.exposure = camera.exposure
    track.truth = {"t0": clock, "phi": fields[1], "ball_ball": exact["ball_ball"], "cushion": exact["cushion"],
                   "positions": truth}
    return track


def filmed_shots(engine, count: int, seed: int = 0, balls: int = 3, rates=(60.0,), duration: float = 4.0,
                 threads: int = 0, **camera) -> List[Track]:
    """`count` shots (cue_sim.calibrate.synthetic.random_shot), each filmed at
    one of `rates` in turn by its own Camera(engine, **camera) and found by the detector, on
    `threads` threads (0: every core; the renderer, OpenCV and numpy leave the GIL)."""
    import os
    from concurrent.futures import ThreadPoolExecutor
    rng = np.random.default_rng(seed)
    plans = []
    for i in range(count):
        positions, strike = random_shot(engine, rng, i, balls)
        plans.append((positions, strike, rates[i % len(rates)], int(rng.integers(2**32)), f"shot {i}"))

    def film(plan):
        positions, strike, rate, shot_seed, name = plan
        return filmed(Camera(engine, seed=shot_seed, **camera), list(range(balls)), positions, strike, rate=rate,
                      duration=duration, seed=shot_seed, name=name)

    with ThreadPoolExecutor(max_workers=threads or os.cpu_count() or 1) as pool:
        return list(pool.map(film, plans))
