"""Which ball is which: identities for a detector's anonymous detections, frame to frame.

A detector that finds balls by their shape (cue_sim.detection, scripts/detect_balls.py) says where
balls are, not which. A fit needs one track per ball, and only the struck ball's identity matters
to the physics (every ball has the same mass and size), so: the balls are the detections that
stand still before the strike; each is followed through the frames by predicting where it goes
(its last velocity, and what it gives a standing ball it meets on the way) and assigning the detections to the predictions at least total distance
(scipy's linear_sum_assignment), first within a tight gate, then what is left within what a ball
can travel between the two frames; the struck ball is the one that moves first. A swap of two
balls at a close contact, or a false detection taken up, becomes a few outliers, which the fit's
robust loss weighs little. A ball that was not seen before the strike is not followed.
"""
from __future__ import annotations

from typing import Dict, Optional, Sequence

import numpy as np

from cue_sim.calibrate.tracks import Track

#: How far a detection may be from where a ball was predicted and still be taken for it, in the
#: first pass [m]: past a detector's error and the change of a frame's velocity at a contact,
#: short of the 57 mm between two touching balls' centres.
TIGHT_GATE = 0.04
#: The fastest a ball moves [m/s], for the second pass's gate: what a hard break gives a cue ball.
TOP_SPEED = 12.0
#: A ball's velocity is taken from its last two sightings if they are at most this far apart [s];
#: else it is taken as still.
VELOCITY_SPAN = 0.1
#: A ball moved between two sightings if they are this many detector errors apart; else it stood
#: (a standing ball's two sightings are that far apart once in some 10^4 pairs).
STILL_IN_NOISES = 6.0
#: A ball before the strike is a detection seen in at least this share of the frames before it.
REST_SHARE = 0.5


def _rest_balls(frames: Sequence[np.ndarray], before: np.ndarray) -> np.ndarray:
    """(M, 2): the balls standing before the strike, each the median of its sightings then."""
    indices = np.flatnonzero(before)
    if len(indices) == 0:
        indices = np.array([0])
    counts = [len(frames[k]) for k in indices]
    base = frames[indices[int(np.argmax(counts))]]
    sightings = [[] for _ in range(len(base))]
    for k in indices:
        if len(frames[k]) == 0:
            continue
        distance = np.linalg.norm(base[:, None] - frames[k][None], axis=2)
        for i in range(len(base)):
            j = int(np.argmin(distance[i]))
            if distance[i, j] < TIGHT_GATE and np.argmin(distance[:, j]) == i:
                sightings[i].append(frames[k][j])
    kept = [np.median(s, axis=0) for s in sightings if len(s) >= REST_SHARE * len(indices)]
    return np.array(kept).reshape(-1, 2)


def _contact_time(start: np.ndarray, velocity: np.ndarray, other: np.ndarray, reach: float, span: float):
    """When a ball from `start` at `velocity` first comes within `reach` of `other` (standing), within
    `span` [s]; None if it does not."""
    relative = start - other
    a = float(velocity @ velocity)
    b = float(relative @ velocity)
    c = float(relative @ relative) - reach * reach
    if a == 0 or b >= 0 or b * b - a * c < 0:
        return None
    t = (-b - np.sqrt(b * b - a * c)) / a
    return max(t, 0.0) if t <= span else None


def _predict(last: np.ndarray, velocity: np.ndarray, dt: np.ndarray, radius: float):
    """Where each ball is expected after dt: on at its velocity, except that a moving ball that meets
    a standing one on the way gives it the velocity along their line of centres and keeps the rest
    (equal masses, the spins left out). At the speeds of a shot a ball travels several centimetres
    between frames, more than the gap between two balls that have just met: without the contact,
    the nearer assignment after it swaps them. Returns the predictions and, for the balls of such a
    contact, where each was at it and how long before the frame: what their velocity after it is
    measured from."""
    predicted = last + velocity * dt[:, None]
    since = {}
    moving = np.flatnonzero(np.linalg.norm(velocity, axis=1) > 0)
    for i in moving:
        hits = []
        for j in range(len(last)):
            if j != i and not np.any(velocity[j]):
                t = _contact_time(last[i], velocity[i], last[j], 2 * radius, dt[i])
                if t is not None:
                    hits.append((t, j))
        if not hits:
            continue
        t, j = min(hits)
        contact = last[i] + velocity[i] * t
        normal = (last[j] - contact) / (2 * radius)
        along = float(velocity[i] @ normal) * normal
        after = dt[i] - t
        predicted[i] = contact + (velocity[i] - along) * after
        predicted[j] = last[j] + along * after
        since[i], since[j] = (contact, after), (last[j], after)
    return predicted, since


def _assign(predicted: np.ndarray, detections: np.ndarray, gates: np.ndarray, balls, free):
    """Pairs (ball, detection) among `balls` and the detections `free`, at least total distance, each
    within its ball's gate."""
    from scipy.optimize import linear_sum_assignment
    if not balls or not free:
        return []
    distance = np.linalg.norm(predicted[balls][:, None] - detections[free][None], axis=2)
    cost = np.where(distance <= gates[balls][:, None], distance, 1e6)
    rows, columns = linear_sum_assignment(cost)
    return [(balls[r], free[c]) for r, c in zip(rows, columns) if cost[r, c] < 1e6]


def associate(times, frames: Sequence[np.ndarray], strike_time: float, struck_ball: int = 0,
              known: Optional[Dict[int, np.ndarray]] = None, noise: float = 0.002, radius: float = 0.028575,
              heading: Optional[float] = None, name: str = "") -> Track:
    """The Track of anonymous detections: `frames[k]` (n_k, 2) the positions [m] seen at `times[k]`,
    the strike at `strike_time` on the same clock. The ball that moves first after it is
    `struck_ball`; the others take the ids of `known` (id: position before the shot) they stand at,
    else 1, 2, ... in the order of their distance from the struck ball. `noise` [m] is the
    detector's error, for telling a moving ball from a standing one; `radius` [m] the balls'; `heading` [rad] the cue's, when known, tells
    the struck ball from one it met within the first frame."""
    times = np.asarray(times, dtype=float)
    frames = [np.asarray(f, dtype=float).reshape(-1, 2) for f in frames]
    if len(times) != len(frames):
        raise ValueError(f"frames: one a time, {len(times)} times, got {len(frames)}")
    rest = _rest_balls(frames, times < strike_time)
    m = len(rest)
    if m == 0:
        raise ValueError(f"{name}: no ball stands still in the frames before the strike")
    positions = np.full((len(times), m, 2), np.nan)
    last, velocity, last_time = rest.copy(), np.zeros((m, 2)), np.full(m, -np.inf)
    for k, (t, seen) in enumerate(zip(times, frames)):
        dt = np.where(np.isfinite(last_time), t - last_time, 0.0)
        predicted, since = _predict(last, velocity, dt, radius)
        tight = np.full(m, TIGHT_GATE)
        wide = TIGHT_GATE + TOP_SPEED * np.maximum(dt, 1.0 / 30)
        pairs = _assign(predicted, seen, tight, list(range(m)), list(range(len(seen))))
        balls = [i for i in range(m) if i not in {p[0] for p in pairs}]
        free = [j for j in range(len(seen)) if j not in {p[1] for p in pairs}]
        pairs += _assign(predicted, seen, wide, balls, free)
        for i, j in pairs:
            start, span = since.get(i, (last[i], t - last_time[i]))
            step = seen[j] - start
            # Still, unless it moved past the detector's error: a standing ball's jitter is no velocity.
            moved = 0 < span <= VELOCITY_SPAN and np.linalg.norm(step) > STILL_IN_NOISES * noise
            velocity[i] = step / span if moved else 0.0
            last[i], last_time[i] = seen[j], t
            positions[k, i] = seen[j]
    # The struck ball: the first to stand away from where it stood.
    away = np.linalg.norm(positions - rest[None], axis=2) > max(5 * noise, 0.01)
    after = times >= strike_time - 1e-9
    first = [np.flatnonzero(away[:, i] & after) for i in range(m)]
    moved = [(f[0], i) for i, f in enumerate(first) if len(f)]
    if not moved:
        raise ValueError(f"{name}: no ball is seen moving after the strike")
    struck = min(moved)[1]
    earliest = [i for k, i in moved if k == min(moved)[0]]
    if len(earliest) > 1 and heading is not None:
        # Several balls first seen moving in the same frame (a contact within a frame of the
        # strike): the struck one set off along the cue.
        k = min(moved)[0]
        direction = np.array([np.cos(heading), np.sin(heading)])
        struck = max(earliest, key=lambda i: float((positions[k, i] - rest[i]) @ direction)
                     / float(np.linalg.norm(positions[k, i] - rest[i])))
    ids = np.full(m, -1)
    ids[struck] = struck_ball
    taken = {struck_ball}
    if known:
        for i in range(m):
            if i == struck:
                continue
            candidates = [(float(np.linalg.norm(rest[i] - np.asarray(p)[:2])), int(b)) for b, p in known.items()
                          if int(b) not in taken]
            if candidates and min(candidates)[0] < TIGHT_GATE:
                ids[i] = min(candidates)[1]
                taken.add(ids[i])
    order = sorted((float(np.linalg.norm(rest[i] - rest[struck])), i) for i in range(m) if ids[i] < 0)
    spare = (b for b in range(16) if b not in taken)
    for _, i in order:
        ids[i] = next(spare, -1)
    keep = ids >= 0
    return Track(times, ids[keep], positions[:, keep], strike={"ball": struck_ball}, name=name)
