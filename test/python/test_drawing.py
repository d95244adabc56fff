"""Pictures from Python: draw_shot writes a PNG of the table, and the paths it draws are the
shot's: from the start to the final state, bending exactly where the events happened (balls 2R
apart at a contact, R from a cushion's nose when they hit it, on the capture circle as they drop)."""
import os
import subprocess
import sys

import numpy as np
import pytest

import cue_sim

matplotlib = pytest.importorskip("matplotlib")
from cue_sim import drawing  # noqa: E402

EXACT = 1e-7  # [m]: event positions come from the exact trajectories, not from the samples


@pytest.fixture(scope="module")
def a_break():
    engine = cue_sim.Engine("7ft")
    start = engine.rack("eight", gap=1e-5)
    return engine, start, cue_sim.simulate(engine, start, speed=8.0, phi=0.002)


def distance_to_segment(p, a, b):
    a, b = np.asarray(a), np.asarray(b)
    t = np.clip(np.dot(p - a, b - a) / np.dot(b - a, b - a), 0.0, 1.0)
    return np.linalg.norm(p - (a + t * (b - a)))


def test_writes_a_png_of_the_table(a_break, tmp_path):
    engine, start, shot = a_break
    out = tmp_path / "break.png"
    figure = cue_sim.draw_shot(engine, start, shot, str(out), dpi=100, size=(8.0, 5.0))
    image = matplotlib.image.imread(str(out))
    assert image.shape[:2] == (500, 800)
    greens = (image[..., 1] > image[..., 0] + 0.2) & (image[..., 1] > image[..., 2] + 0.1)
    assert greens.mean() > 0.3  # mostly cloth
    axes = figure.axes[0]
    assert len(axes.lines) >= 10  # the paths of the balls that moved, and the event markers


def test_paths_run_from_start_to_the_final_state(a_break):
    engine, start, shot = a_break
    times, positions, _ = drawing.paths(engine, start, shot)
    assert np.all(np.diff(times) >= 0) and times[0] == 0.0
    assert np.array_equal(positions[0], start.positions[:, :2])
    on_table = shot.final.motion != 4
    assert np.array_equal(positions[-1][on_table], shot.final.positions[on_table, :2])
    assert np.all(np.isnan(positions[-1][~on_table]))
    assert (~on_table).sum() >= 1


def test_events_are_drawn_where_they_happened(a_break):
    engine, start, shot = a_break
    _, _, at = drawing.paths(engine, start, shot)
    radius = engine.params["ball_radius"]
    index = {int(b): i for i, b in enumerate(start.ids)}
    cushions = {name: (a, b) for name, a, b in engine.geometry.cushions}
    counts = {"ball_ball": 0, "ball_cushion": 0, "pocketed": 0}
    for event in shot.events:
        kind = cue_sim.EVENT_KINDS[int(event["kind"])]
        p = at[float(event["time"])][index[int(event["ball"])]]
        if kind == "ball_ball":
            q = at[float(event["time"])][index[int(event["other"])]]
            assert abs(np.linalg.norm(p - q) - 2 * radius) < EXACT
        elif kind == "ball_cushion":
            assert abs(distance_to_segment(p, *cushions[str(event["obstacle"])]) - radius) < EXACT
        elif kind == "pocketed":
            x, y, r = engine.pockets[str(event["obstacle"])]
            assert abs(np.hypot(p[0] - x, p[1] - y) - r) < 1e-6  # 1 ns before it crossed
        else:
            continue
        counts[kind] += 1
    assert counts["ball_ball"] > 10 and counts["ball_cushion"] > 10 and counts["pocketed"] >= 1


def test_draws_into_a_given_axes_and_refuses_a_shot_without_a_strike(a_break):
    engine, start, shot = a_break
    figure = matplotlib.figure.Figure()
    ax = figure.subplots()
    assert cue_sim.draw_shot(engine, start, shot, ax=ax) is figure
    bare = cue_sim.Shot(shot.events, shot.final, shot.time_to_rest, shot.at_rest)
    with pytest.raises(ValueError, match="strike"):
        cue_sim.draw_shot(engine, start, bare)


def test_geometry_and_colours():
    g = cue_sim.Engine("9ft").geometry
    assert g.cloth_length == pytest.approx(2.54, abs=0.01) and g.cloth_width == pytest.approx(1.27, abs=0.01)
    assert len(g.pockets) == 6 and len(g.cushions) == 6
    assert cue_sim.ball_colour(9) == cue_sim.ball_colour(1) and cue_sim.is_striped(9) and not cue_sim.is_striped(1)
    assert max(cue_sim.ball_colour(8)) < 0.1 and min(cue_sim.ball_colour(0)) > 0.9


def test_the_readme_picture_script_runs_and_its_caption_holds(tmp_path):
    # The README's caption: the best of search_breaks.py's million pots 9 object balls, cue ball up.
    script = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "draw_break.py")
    out = subprocess.run([sys.executable, script, "--out", str(tmp_path / "b.png")], capture_output=True, text=True,
                         timeout=120)
    assert out.returncode == 0, out.stderr
    assert "9 object balls potted, cue ball up" in out.stdout
    assert (tmp_path / "b.png").stat().st_size > 10000
