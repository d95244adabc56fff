"""Observed shots from a rosbag: a calibration session recorded from the table node
(launch/calibration_record.launch), or any bag with the same topics.

Each strike on the strikes topic (cue_sim/ExecutedShot, the node's ~shots) starts a shot; its
track runs from `before` seconds ahead of the strike until the next shot's track begins, the
table is placed anew (~set_state or a reset: the table's state shows balls where they could not
have rolled), the bag ends, or `longest` seconds have passed. The balls' positions come from one source:

- ``ground_truth``: the simulated camera's cue_sim/CameraGroundTruth (each ball with its id, where
  it is in view);
- ``detections``: a detector's geometry_msgs/PoseArray in the table frame (scripts/detect_balls.py),
  anonymous: identities are found as cue_sim.calibrate.association says, the struck ball's from
  the strike and the others' from the table's state (cue_sim/TableState) when the bag has it;
- ``tf``: ball frames (``ball_frame_prefix`` and the id) in /tf whose parent is the table frame,
  from the node or from another tracker.

Times are seconds from the shot's strike stamp. What the track knows of the strike is the fields
named in `known` of the strike as requested (the commanded shot; always its ball); the whole
requested shot is kept as the track's `commanded` (what an execution-noise fit compares with).
"""
from __future__ import annotations

from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from cue_sim.calibrate.association import associate
from cue_sim.calibrate.tracks import STRIKE_FIELDS, Track

SOURCES = ("ground_truth", "detections", "tf")
#: Where the table node (in namespace table) and the example detector publish.
DEFAULT_TOPICS = {"ground_truth": "/table/camera/ground_truth", "detections": "/detect_balls/detections",
                  "tf": "/tf"}
SHOTS_TOPIC = "/table/shots"
#: The node's camera's shutter time by default (config/table_node.yaml, ~camera/exposure) [s].
NODE_EXPOSURE = 0.004
STATE_TOPIC = "/table/state"
#: A ball that moved between two table states further than its speed at either, sped up by
#: PLACEMENT_KICK over the interval, carries it, plus PLACEMENT_ROUNDING, was placed there.
#: [m/s^2]: far above the cloth's and cushions' decelerations, so a collision's kick is
#: counted in the states' speeds; [m]: the states' rounding.
PLACEMENT_KICK = 100.0
PLACEMENT_ROUNDING = 1e-4
#: A ball frame lower than this share of a radius above the cloth is a pocketed ball's (the node
#: puts those below the cloth): not seen.
POCKETED_HEIGHT_SHARE = 0.5


def _shot_fields(shot) -> Dict[str, float]:
    return {"ball": int(shot.ball_id), "speed": shot.speed, "phi": shot.phi, "theta": shot.theta, "a": shot.a,
            "b": shot.b}


def _read(bag, topics: Sequence[str]):
    return [(topic, message) for topic, message, _ in bag.read_messages(topics=list(topics))]


def _strikes(messages, shots_topic: str):
    return [(m.header.stamp.to_sec(), m) for topic, m in messages if topic == shots_topic]


def _frames(messages, source: str, topic: str, table_frame: str, prefix: str, radius: float):
    """(stamp, {id: (x, y)}) per message for ground_truth and tf; (stamp, (n, 2)) for detections."""
    out = []
    for name, m in messages:
        if name != topic:
            continue
        if source == "ground_truth":
            out.append((m.header.stamp.to_sec(),
                        {int(b.id): (b.position.x, b.position.y) for b in m.balls if b.visible}))
        elif source == "detections":
            if m.header.frame_id.lstrip("/") != table_frame:
                raise ValueError(f"{topic}: detections in frame '{m.header.frame_id}', not the table frame "
                                 f"'{table_frame}'")
            out.append((m.header.stamp.to_sec(), np.array([[p.position.x, p.position.y] for p in m.poses]).reshape(-1, 2)))
        else:
            for t in m.transforms:
                child = t.child_frame_id.lstrip("/")
                if t.header.frame_id.lstrip("/") != table_frame or not child.startswith(prefix):
                    continue
                suffix = child[len(prefix):]
                if not suffix.isdigit() or t.transform.translation.z < POCKETED_HEIGHT_SHARE * radius:
                    continue
                p = t.transform.translation
                out.append((t.header.stamp.to_sec(), {int(suffix): (p.x, p.y)}))
    out.sort(key=lambda item: item[0])
    return out


def _identified_track(frames, ids: List[int], strike: float, name: str) -> Optional[Track]:
    """One Track from (stamp, {id: xy}) frames; those with the same stamp are merged."""
    stamps = np.unique([s for s, _ in frames])
    if len(stamps) < 2:
        return None
    positions = np.full((len(stamps), len(ids), 2), np.nan)
    column = {b: j for j, b in enumerate(ids)}
    for stamp, balls in frames:
        k = int(np.searchsorted(stamps, stamp))
        for b, xy in balls.items():
            if b in column:
                positions[k, column[b]] = xy
    return Track(stamps - strike, ids, positions, name=name)


def _state_before(messages, state_topic: str, stamp: float) -> Optional[Dict[int, np.ndarray]]:
    """Each ball's position in the last table state before `stamp`, if the bag has one."""
    last = None
    for topic, m in messages:
        if topic == state_topic and m.header.stamp.to_sec() <= stamp:
            last = m
    if last is None:
        return None
    return {int(b.id): np.array([b.position.x, b.position.y]) for b in last.balls if not b.pocketed}


def _placements(messages, state_topic: str) -> List[Tuple[float, float]]:
    """Each placement (a table state whose balls stand where they could not have rolled to from
    the one before, or a different set of balls) as the stamps of the states either side of it."""
    last = None
    out = []
    for topic, m in messages:
        if topic != state_topic:
            continue
        if last is not None and _placed_between(last, m):
            out.append((last.header.stamp.to_sec(), m.header.stamp.to_sec()))
        last = m
    return out


def _placed_between(before, after) -> bool:
    dt = max(0.0, after.header.stamp.to_sec() - before.header.stamp.to_sec())
    earlier = {int(b.id): b for b in before.balls}
    later = {int(b.id): b for b in after.balls}
    if set(earlier) != set(later):
        return True
    for ball_id, b in later.items():
        a = earlier[ball_id]
        if a.pocketed != b.pocketed:
            return a.pocketed  # one back out of a pocket was placed; one going in fell
        if a.pocketed:
            continue
        moved = np.linalg.norm([b.position.x - a.position.x, b.position.y - a.position.y, b.position.z - a.position.z])
        speed = max(np.linalg.norm([a.velocity.x, a.velocity.y, a.velocity.z]),
                    np.linalg.norm([b.velocity.x, b.velocity.y, b.velocity.z]))
        if moved > (speed + PLACEMENT_KICK * dt) * dt + PLACEMENT_ROUNDING:
            return True
    return False


def tracks_from_bag(path, source: str = "detections", topic: Optional[str] = None, shots_topic: str = SHOTS_TOPIC,
                    state_topic: str = STATE_TOPIC, known: Sequence[str] = (), before: float = 0.5,
                    longest: float = 15.0, table_frame: str = "table", ball_frame_prefix: str = "ball_",
                    ball_radius: float = 0.028575, noise: float = 0.002,
                    exposure: Optional[float] = None) -> List[Track]:
    """The shots of the bag at `path`, one Track a strike (the module's text); `exposure` [s] is
    the camera's shutter time for the detections (Track.exposure; None: the node's default
    ~camera/exposure, NODE_EXPOSURE); the ground truth and /tf are at instants."""
    import rosbag
    if source not in SOURCES:
        raise ValueError(f"source: one of {', '.join(SOURCES)}, got '{source}'")
    unknown = set(known) - set(STRIKE_FIELDS)
    if unknown:
        raise ValueError(f"known: {sorted(unknown)} are not strike fields ({', '.join(STRIKE_FIELDS)})")
    topic = topic or DEFAULT_TOPICS[source]
    with rosbag.Bag(str(path)) as bag:
        topics = bag.get_type_and_topic_info().topics
        for needed in (shots_topic, topic):
            if needed not in topics:
                raise ValueError(f"{path}: no topic {needed} (it has {', '.join(sorted(topics)) or 'none'})")
        messages = _read(bag, [shots_topic, topic] + ([state_topic] if state_topic in topics else []))
        end = bag.get_end_time()
    strikes = _strikes(messages, shots_topic)
    frames = _frames(messages, source, topic, table_frame, ball_frame_prefix, ball_radius)
    placements = _placements(messages, state_topic)
    tracks = []
    for index, (stamp, shot) in enumerate(strikes):
        commanded = _shot_fields(shot.requested)
        begin = stamp - before
        finish = min(strikes[index + 1][0] - before if index + 1 < len(strikes) else end, stamp + longest)
        # A placement after the strike ends the track (the balls seen after it stand for the next
        # shot); one less than `before` ahead of it starts the track after it.
        finish = min([finish] + [last for last, _ in placements if last >= stamp])
        begin = max([begin] + [first for _, first in placements if first <= stamp])
        mine = [(s, f) for s, f in frames if begin <= s <= finish]
        name = f"{path} shot {index}"
        if source == "detections":
            track = associate([s - stamp for s, _ in mine], [f for _, f in mine], 0.0, commanded["ball"],
                              _state_before(messages, state_topic, stamp), noise, ball_radius,
                              commanded["phi"], name)
        else:
            ids = sorted({b for _, balls in mine for b in balls})
            track = _identified_track(mine, ids, stamp, name) if commanded["ball"] in ids else None
        if track is None:
            raise ValueError(f"{name}: the struck ball {commanded['ball']} is not seen on {topic}")
        track.strike = {"ball": commanded["ball"], **{f: commanded[f] for f in known if f != "ball"}}
        track.commanded = commanded
        track.truth = {"executed": _shot_fields(shot.executed), "noise": bool(shot.noise)}
        shutter = NODE_EXPOSURE if exposure is None else exposure
        track.exposure = shutter if source == "detections" else 0.0  # the others are at instants
        track.__post_init__()
        tracks.append(track)
    if not tracks:
        raise ValueError(f"{path}: no strike on {shots_topic}")
    return tracks
