"""Observed shots: each ball's positions at the instants a camera or a tracker saw them.

A `Track` is one shot: `times` (K,) ascending on the observer's clock [s], `ball_ids` (N,), and
`positions` (K, N, 2) in the table frame [m], NaN where a ball was not seen (out of view, a gap, a
missed detection). Outliers stay in: the fit's loss is robust to them. What is known of the strike
goes in `strike` (any of ball, speed, phi, theta, a, b; the struck ball is 0 unless it says).

Files: CSV with a header naming at least t, ball, x, y (and shot, when one file holds several), or
NPZ with arrays of the same names, one row an observation.
"""
from __future__ import annotations

import csv
import pathlib
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence

import numpy as np

#: The strike's fields, as ~strike and cue_sim.simulate name them.
#: The cue's fields of a strike: what the cue does (and what the node's noise model perturbs).
CUE_FIELDS = ("speed", "phi", "theta", "a", "b")
STRIKE_FIELDS = ("ball",) + CUE_FIELDS


@dataclass
class Track:
    """One observed shot (the module's text)."""
    times: np.ndarray
    ball_ids: np.ndarray
    positions: np.ndarray
    strike: Dict[str, float] = field(default_factory=dict)
    name: str = ""
    #: [s] how long the shutter was open around each instant (0: instants). A detector finds a
    #: smeared ball's centre at its mean position over the exposure, which the fit then predicts:
    #: at a contact within it, the middle's position is up to v x exposure / 8 off, always on one side.
    exposure: float = 0.0
    #: What made a synthetic track (cue_sim.calibrate.synthetic), None for an observed one.
    truth: Optional[dict] = None
    #: The strike as it was commanded (all of STRIKE_FIELDS), when a record says: what an
    #: execution-noise fit compares the executed strike with. Not a fact of the shot: `strike` is.
    commanded: Optional[Dict[str, float]] = None

    def __post_init__(self):
        self.times = np.asarray(self.times, dtype=float)
        self.ball_ids = np.asarray(self.ball_ids, dtype=int)
        self.positions = np.asarray(self.positions, dtype=float)
        k, n = len(self.times), len(self.ball_ids)
        if self.times.ndim != 1 or k < 2:
            raise ValueError(f"{self.label}times: at least 2 instants, got shape {self.times.shape}")
        if not np.all(np.isfinite(self.times)) or np.any(np.diff(self.times) <= 0):
            raise ValueError(f"{self.label}times: finite and strictly ascending")
        if self.positions.shape != (k, n, 2):
            raise ValueError(f"{self.label}positions: shape ({k}, {n}, 2) for {k} instants and {n} balls, "
                             f"got {self.positions.shape}")
        if len(set(self.ball_ids.tolist())) != n or np.any(self.ball_ids < 0) or np.any(self.ball_ids > 15):
            raise ValueError(f"{self.label}ball_ids: distinct ids in [0, 15], got {self.ball_ids.tolist()}")
        if not (0.0 <= self.exposure <= 0.1):
            raise ValueError(f"{self.label}exposure: {self.exposure} s is outside [0, 0.1]")
        if k > 1 and self.exposure > float(np.min(np.diff(self.times))):
            raise ValueError(f"{self.label}exposure: {self.exposure} s is longer than the shortest time between two "
                             f"instants ({float(np.min(np.diff(self.times)))} s)")
        unknown = set(self.strike) - set(STRIKE_FIELDS)
        if unknown:
            raise ValueError(f"{self.label}strike: unknown fields {sorted(unknown)}; they are {', '.join(STRIKE_FIELDS)}")
        if self.struck_ball not in self.ball_ids.tolist():
            raise ValueError(f"{self.label}strike: ball {self.struck_ball} is not among the tracked balls")

    @property
    def label(self) -> str:
        return f"{self.name}: " if self.name else ""

    @property
    def struck_ball(self) -> int:
        return int(self.strike.get("ball", 0))

    def seen(self) -> np.ndarray:
        """(K, N): whether each ball was seen at each instant."""
        return np.all(np.isfinite(self.positions), axis=2)

    def resting_positions(self, before: Optional[float] = None) -> np.ndarray:
        """(N, 2): each ball where it stood before the shot: the median of its first sightings
        (up to `before` on the track's clock when given; else its first five)."""
        out = np.full((len(self.ball_ids), 2), np.nan)
        seen = self.seen()
        for j in range(len(self.ball_ids)):
            rows = np.flatnonzero(seen[:, j] & ((self.times <= before) if before is not None else True))[:5]
            if len(rows) == 0:
                rows = np.flatnonzero(seen[:, j])[:1]
            if len(rows):
                out[j] = np.median(self.positions[rows, j], axis=0)
        return out


def _columns_to_tracks(columns: Dict[str, np.ndarray], source: str, exposure: float = 0.0) -> List[Track]:
    missing = [c for c in ("t", "ball", "x", "y") if c not in columns]
    if missing:
        raise ValueError(f"{source}: no column {', '.join(missing)} (it needs t, ball, x, y; shot optional)")
    t = np.asarray(columns["t"], dtype=float)
    ball = np.asarray(columns["ball"], dtype=float)
    x, y = np.asarray(columns["x"], dtype=float), np.asarray(columns["y"], dtype=float)
    shot = np.asarray(columns["shot"]) if "shot" in columns else np.zeros(len(t), dtype=int)
    if not (len(t) == len(ball) == len(x) == len(y) == len(shot)):
        raise ValueError(f"{source}: the columns differ in length")
    if not np.all(np.isfinite(t)) or not np.all(np.isfinite(ball)) or np.any(ball != np.round(ball)):
        raise ValueError(f"{source}: t and ball must be finite numbers (ball an integer id)")
    tracks = []
    for name in sorted(set(shot.tolist()), key=str):
        rows = shot == name
        times = np.unique(t[rows])
        ids = np.unique(ball[rows]).astype(int)
        positions = np.full((len(times), len(ids), 2), np.nan)
        k = np.searchsorted(times, t[rows])
        j = np.searchsorted(ids, ball[rows].astype(int))
        positions[k, j, 0], positions[k, j, 1] = x[rows], y[rows]
        label = int(name) if isinstance(name, float) and name.is_integer() else name
        tracks.append(Track(times, ids, positions, name=f"{source} shot {label}", exposure=float(exposure)))
    return tracks


def load_tracks(path, strikes: Optional[Sequence[Dict[str, float]]] = None, exposure: float = 0.0) -> List[Track]:
    """The shots of a CSV or NPZ file (the module's text), one Track a shot in the order of their
    `shot` values; `strikes`, one dict a shot, says what is known of each strike; `exposure` [s]
    the camera's (Track.exposure)."""
    path = pathlib.Path(path)
    if path.suffix == ".npz":
        with np.load(path, allow_pickle=False) as data:
            columns = {name: data[name] for name in data.files}
    else:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(row for row in f if not row.lstrip().startswith("#")))
        if not rows:
            raise ValueError(f"{path}: no observations")
        columns = {}
        for name in rows[0]:
            values = [row[name] for row in rows]
            try:
                columns[name.strip()] = np.array([float(v) if v not in ("", None) else np.nan for v in values])
            except ValueError:
                columns[name.strip()] = np.array(values)
    tracks = _columns_to_tracks(columns, path.name, exposure)
    if strikes is not None:
        if len(strikes) != len(tracks):
            raise ValueError(f"strikes: one a shot, {len(tracks)} shots, got {len(strikes)}")
        for track, strike in zip(tracks, strikes):
            track.strike = dict(strike)
            track.__post_init__()
    return tracks


def save_tracks(path, tracks: Sequence[Track]) -> None:
    """Writes tracks as load_tracks reads them: CSV (t, ball, x, y, shot; the balls not seen left
    out) or NPZ, by the path's suffix."""
    t, ball, x, y, shot = [], [], [], [], []
    for index, track in enumerate(tracks):
        seen = track.seen()
        for k, j in zip(*np.nonzero(seen)):
            t.append(track.times[k])
            ball.append(track.ball_ids[j])
            x.append(track.positions[k, j, 0])
            y.append(track.positions[k, j, 1])
            shot.append(index)
    path = pathlib.Path(path)
    if path.suffix == ".npz":
        np.savez(path, t=np.array(t), ball=np.array(ball), x=np.array(x), y=np.array(y), shot=np.array(shot))
        return
    with open(path, "w", newline="") as f:
        writer = csv.writer(f)
        writer.writerow(["t", "ball", "x", "y", "shot"])
        for row in zip(t, ball, x, y, shot):
            writer.writerow([repr(float(row[0])), int(row[1]), repr(float(row[2])), repr(float(row[3])), int(row[4])])
