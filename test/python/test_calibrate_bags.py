"""cue_sim.calibrate.bags: a shot's track ends where the table is placed anew (~set_state or a reset),
whenever the next strike comes; the balls' identities are then those of the shot, not of the next
layout. Bags written here, without a master (rosbag writes offline)."""
import numpy as np
import pytest

rosbag = pytest.importorskip("rosbag")
import rospy  # noqa: E402  (rosbag brings it)
from geometry_msgs.msg import Pose, PoseArray  # noqa: E402

from cue_sim.calibrate.bags import _placed_between, tracks_from_bag  # noqa: E402
from cue_sim.msg import BallState, ExecutedShot, TableState  # noqa: E402

RADIUS = 0.028575
STRIKES = (10.0, 20.0)
#: The table is placed for the second shot here, long before its strike (a slow machine).
PLACED_AT = 14.0


def layout(t):
    """Each ball's (x, y) and velocity at time t: the cue ball rolls 0.5 s at 1 m/s from each
    strike; balls 1 and 2 stand, and change places at PLACED_AT."""
    cue = np.array([0.5, 0.5])
    velocity = np.zeros(2)
    for strike in STRIKES:
        if t >= strike:
            rolled = min(t - strike, 0.5)
            cue = np.array([0.5 + rolled, 0.5])
            velocity = np.array([1.0, 0.0]) if t - strike < 0.5 else np.zeros(2)
        if t >= PLACED_AT and strike == STRIKES[0] and t < STRIKES[1]:
            cue = np.array([0.5, 0.5])
            velocity = np.zeros(2)
    one, two = np.array([1.2, 0.3]), np.array([1.2, 0.7])
    if t >= PLACED_AT:
        one, two = two, one
    return {0: (cue, velocity), 1: (one, np.zeros(2)), 2: (two, np.zeros(2))}


def state_at(t):
    m = TableState()
    m.header.stamp = rospy.Time.from_sec(t)
    m.header.frame_id = "table"
    for ball_id, (xy, v) in layout(t).items():
        b = BallState(id=ball_id)
        b.position.x, b.position.y, b.position.z = xy[0], xy[1], RADIUS
        b.velocity.x, b.velocity.y = v[0], v[1]
        b.motion = BallState.ROLLING if np.any(v) else BallState.STATIONARY
        m.balls.append(b)
    m.moving = any(np.any(v) for _, v in layout(t).values())
    return m


def write_bag(path):
    with rosbag.Bag(str(path), "w") as bag:
        for t in np.arange(9.0, 21.5, 0.01):
            bag.write("/table/state", state_at(t), rospy.Time.from_sec(t))
        for t in np.arange(9.0, 21.5, 1.0 / 30):
            detections = PoseArray()
            detections.header.stamp = rospy.Time.from_sec(t)
            detections.header.frame_id = "table"
            for xy, _ in layout(t).values():
                pose = Pose()
                pose.position.x, pose.position.y, pose.position.z = xy[0], xy[1], RADIUS
                pose.orientation.w = 1.0
                detections.poses.append(pose)
            bag.write("/detect_balls/detections", detections, rospy.Time.from_sec(t))
        for strike in STRIKES:
            shot = ExecutedShot()
            shot.header.stamp = rospy.Time.from_sec(strike)
            shot.header.frame_id = "table"
            shot.source = "strike"
            for s in (shot.requested, shot.executed):
                s.ball_id, s.speed, s.phi = 0, 1.0, 0.0
            bag.write("/table/shots", shot, rospy.Time.from_sec(strike))


def test_a_placement_before_the_next_strike_ends_the_shots_track(tmp_path):
    bag = tmp_path / "placed.bag"
    write_bag(bag)
    tracks = tracks_from_bag(bag, "detections")
    assert len(tracks) == 2
    first, second = tracks
    # The first track stops at the last state before the placement (it ran to 19.5 s before).
    assert first.times[-1] <= PLACED_AT - STRIKES[0]
    assert first.times[-1] > PLACED_AT - STRIKES[0] - 0.05
    # Balls 1 and 2 keep the places they had in that shot, and in the next have the new ones.
    for track, places in ((first, {1: (1.2, 0.3), 2: (1.2, 0.7)}), (second, {1: (1.2, 0.7), 2: (1.2, 0.3)})):
        for ball, xy in places.items():
            j = list(track.ball_ids).index(ball)
            seen = track.seen()[:, j]
            assert seen.sum() > 10
            np.testing.assert_allclose(track.positions[seen, j], np.tile(xy, (seen.sum(), 1)), atol=1e-9)
    # The cue ball rolled 0.5 m in the first shot: its track shows it standing, then rolling.
    j = list(first.ball_ids).index(0)
    assert first.positions[first.seen()[:, j], j][-1][0] == pytest.approx(1.0)


def test_a_strike_a_collision_and_a_pocketing_are_not_placements():
    before, after = state_at(9.99), state_at(10.01)
    assert not _placed_between(before, after)  # the cue ball struck: 1 cm at 1 m/s in 20 ms
    assert _placed_between(state_at(PLACED_AT - 0.01), state_at(PLACED_AT))
    # A ball hit at rest goes at its new speed: the later state's speed allows the step.
    hit = state_at(12.0)
    kicked = state_at(12.01)
    kicked.balls[1].position.x += 0.05
    kicked.balls[1].velocity.x = 5.0
    assert not _placed_between(hit, kicked)
    kicked.balls[1].velocity.x = 0.5
    assert _placed_between(hit, kicked)  # 5 cm in 10 ms at 0.5 m/s: placed
    # A ball falling into a pocket drops below the cloth; one taken back out is placed.
    pocketed = state_at(12.02)
    pocketed.balls[2].pocketed = True
    pocketed.balls[2].position.z = -0.1
    assert not _placed_between(hit, pocketed)
    assert _placed_between(pocketed, hit)
