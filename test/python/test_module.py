"""The Python module: imported without ROS, refusing bad input by name, and giving the engine's own
answers bit for bit: the `simulate` program's for a scene, and simulate()'s for every row of a
batch, however the batch is split or threaded."""
import json
import os
import pickle
import subprocess
import sys

import numpy as np
import pytest

import cue_sim

SIMULATE = os.environ.get("CUE_SIM_SIMULATE", "simulate")
BREAK_SCENE = "table: 7ft\nrack: eight\nrack_gap: 1.0e-5\nshot: {speed: 8.0, phi: 0.002}\n"


@pytest.fixture(scope="module")
def engine():
    return cue_sim.Engine("7ft")


def test_another_python_is_told_which_one_to_run():
    # A python3 without Debian's NumPy (as a pyenv shim first on PATH): the import names the
    # interpreter the module was built for instead of failing inside NumPy or the extension.
    from cue_sim import _built_for
    package_parent = os.path.dirname(os.path.dirname(_built_for.__file__))
    env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": package_parent, "HOME": os.environ.get("HOME", "/tmp")}
    out = subprocess.run([sys.executable, "-S", "-c", "import cue_sim; cue_sim.Engine('7ft')"], env=env,
                         capture_output=True, text=True, timeout=60)
    assert out.returncode != 0
    assert f"cue_sim was built for {_built_for.EXECUTABLE} (Python {_built_for.VERSION}" in out.stderr, out.stderr
    assert f"run {_built_for.EXECUTABLE} instead" in out.stderr, out.stderr


def test_imports_and_runs_without_ros():
    # Only the package's own directory on the path: no ROS variables, no setup files sourced.
    package_parent = os.path.dirname(os.path.dirname(cue_sim.__file__))
    env = {"PATH": "/usr/bin:/bin", "PYTHONPATH": package_parent, "HOME": os.environ.get("HOME", "/tmp")}
    code = ("import cue_sim; e = cue_sim.Engine(); s = cue_sim.simulate(e, e.rack(), speed=8.0, phi=0.002); "
            "print(len(s.events), s.at_rest)")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=60)
    assert out.returncode == 0, out.stderr
    count, at_rest = out.stdout.split()
    assert int(count) > 50 and at_rest == "True"


def test_lists_the_registry():
    assert {"7ft", "9ft", "carom", "snooker"} <= set(cue_sim.tables())
    models = cue_sim.models()
    assert models["ball_ball"][0] == "frictional" and "mathavan2014" in models["ball_ball"]
    assert models["cushion"][0] == "han2005" and "stronge2018" in models["cushion"]
    mu = cue_sim.parameters()["mu_slide"]
    assert mu["min"] <= mu["default"] <= mu["max"] and mu["unit"] == "-"


@pytest.mark.parametrize("kwargs, named", [
    ({"mu_slyde": 0.2}, "mu_slyde"),
    ({"mu_slide": -1.0}, "mu_slide"),
    ({"e_ball": float("nan")}, "e_ball"),
    ({"ball_ball_model": "elastic"}, "elastic"),
    ({"cushion_model": "rubber"}, "rubber"),
    ({"table": "8ft"}, "8ft"),
])
def test_bad_physics_is_refused_by_name(kwargs, named):
    with pytest.raises(ValueError, match=named):
        cue_sim.Engine(**kwargs)


def test_bad_states_and_shots_are_refused_by_name(engine):
    start = engine.rack("eight")
    with pytest.raises(ValueError, match="layout"):
        engine.rack("eleven")
    with pytest.raises(ValueError, match="speed"):
        cue_sim.simulate(engine, start, speed=-1.0)
    with pytest.raises(ValueError, match="ball"):
        cue_sim.simulate(engine, start, ball=99, speed=1.0)
    overlapping = cue_sim.State.from_balls([0, 1], [[0.0, 0.0], [0.01, 0.0]])
    with pytest.raises(ValueError, match="overlap"):
        engine.check(overlapping)
    twice = cue_sim.State.from_balls([0, 0], [[0.0, 0.0], [0.3, 0.0]])
    with pytest.raises(ValueError, match="twice|once"):
        engine.check(twice)
    nan = cue_sim.State.from_balls([0], [[float("nan"), 0.0]])
    with pytest.raises(ValueError, match="finite"):
        engine.check(nan)
    with pytest.raises(ValueError, match="shape"):
        cue_sim.State.from_balls([0, 1], [[0.0, 0.0]])
    with pytest.raises(ValueError, match=r"\(N, 6\)"):
        cue_sim.batch(engine, start, np.zeros((3, 5)))


def test_a_break_is_the_simulate_programs_bit_for_bit(engine):
    program = json.loads(subprocess.run([SIMULATE, "-"], input=BREAK_SCENE, capture_output=True, text=True,
                                        check=True, timeout=60).stdout)
    shot = cue_sim.simulate(engine, engine.rack("eight", gap=1e-5), speed=8.0, phi=0.002)
    assert len(shot.events) == len(program["events"]) > 50
    for mine, theirs in zip(shot.events, program["events"]):
        assert mine["time"] == theirs["t"]
        assert cue_sim.EVENT_KINDS[int(mine["kind"])] == theirs["kind"]
        assert mine["ball"] == theirs["ball"]
    final = {b["id"]: b for b in program["final_state"]["balls"]}
    for i, ball in enumerate(shot.final.ids):
        assert list(shot.final.positions[i]) == final[int(ball)]["position"]
    assert shot.at_rest == program["at_rest"]


def test_events_name_their_obstacles_and_kinds(engine):
    shot = cue_sim.simulate(engine, engine.rack("eight"), speed=8.0, phi=0.002)
    kinds = {cue_sim.EVENT_KINDS[int(k)] for k in shot.events["kind"]}
    assert {"ball_ball", "ball_cushion"} <= kinds
    cushions = shot.events[shot.events["kind"] == 11]
    assert all(name.startswith("cushion_") for name in cushions["obstacle"])
    assert np.all(np.diff(shot.events["time"]) >= 0)
    assert np.all(shot.events["obstacle"][shot.events["kind"] == 10] == "")


def test_until_stops_the_shot_part_way(engine):
    start = engine.rack("eight")
    whole = cue_sim.simulate(engine, start, speed=8.0, phi=0.002)
    part = cue_sim.simulate(engine, start, speed=8.0, phi=0.002, until=0.5)
    assert not part.at_rest
    assert len(part.events) == np.count_nonzero(whole.events["time"] <= 0.5)
    assert np.array_equal(part.events, whole.events[:len(part.events)])


def shots_around(n, rng):
    return np.column_stack([np.zeros(n), rng.uniform(0.5, 8, n), rng.uniform(-np.pi, np.pi, n),
                            rng.uniform(0, 0.2, n), rng.uniform(-0.3, 0.3, n), rng.uniform(-0.3, 0.3, n)])


def test_a_batch_is_simulate_shot_by_shot(engine):
    start = engine.rack("eight")
    shots = shots_around(40, np.random.default_rng(1))
    result = cue_sim.batch(engine, start, shots)
    assert result.error == [""] * 40
    assert np.array_equal(result.executed, shots)
    for i, (ball, speed, phi, theta, a, b) in enumerate(shots):
        alone = cue_sim.simulate(engine, start, int(ball), speed, phi, theta, a, b)
        assert result.events[i] == len(alone.events)
        assert np.array_equal(result.positions[i], alone.final.positions)
        assert np.array_equal(result.pocket[i], alone.final.pocket)
        assert result.time_to_rest[i] == alone.time_to_rest


def test_a_batch_is_the_same_however_split_or_threaded(engine):
    start = engine.rack("nine")
    shots = shots_around(60, np.random.default_rng(2))
    whole = cue_sim.batch(engine, start, shots, noise=True, seed=7, threads=4)
    one_thread = cue_sim.batch(engine, start, shots, noise=True, seed=7, threads=1)
    head = cue_sim.batch(engine, start, shots[:25], noise=True, seed=7)
    tail = cue_sim.batch(engine, start, shots[25:], noise=True, seed=7 + 25)
    for part in ("executed", "positions", "pocket", "events", "time_to_rest"):
        assert np.array_equal(getattr(whole, part), getattr(one_thread, part))
        assert np.array_equal(getattr(whole, part), np.concatenate([getattr(head, part), getattr(tail, part)]))
    assert not np.array_equal(whole.executed, shots)  # the noise is there
    assert np.all(np.abs(whole.executed[:, 1] - shots[:, 1]) < 0.075 * 6)


def test_a_refused_row_says_why_and_the_rest_run(engine):
    start = engine.rack("eight")
    shots = np.array([[0, 2.0, 0.1, 0, 0, 0], [99, 2.0, 0.1, 0, 0, 0], [0, 2.0, 0.2, 0, 0, 0]])
    result = cue_sim.batch(engine, start, shots)
    assert result.error[0] == "" and result.error[2] == ""
    assert "99" in result.error[1]
    assert result.events[0] > 0 and result.events[2] > 0


def test_samples_follow_the_shot_and_match_a_shot_stopped_there(engine):
    start = engine.rack("eight")
    shot = cue_sim.simulate(engine, start, speed=8.0, phi=0.002, sample_period=0.05)
    samples = shot.samples
    assert len(samples.times) == int(np.floor(shot.time_to_rest / 0.05)) + 1
    assert samples.positions.shape == (len(samples.times), 16, 3)
    assert np.array_equal(samples.positions[0], start.positions)  # the instant of the strike
    stopped = cue_sim.simulate(engine, start, speed=8.0, phi=0.002, until=0.5)
    assert np.array_equal(samples.positions[10], stopped.final.positions)
    assert np.array_equal(samples.velocities[10], stopped.final.velocities)
    with pytest.raises(ValueError, match="sample_period"):
        cue_sim.simulate(engine, start, speed=8.0, sample_period=1e-6)


def test_the_overhead_script_runs_and_reports_both_figures():
    script = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "python_overhead.py")
    out = subprocess.run([sys.executable, script, "200", "2"], capture_output=True, text=True, timeout=120)
    assert out.returncode == 0, out.stderr
    assert "200 breaks on 2 thread(s): engine" in out.stdout and "the Python layer adds" in out.stdout


def test_the_readme_example_runs(tmp_path, monkeypatch):
    readme = open(os.path.join(os.path.dirname(__file__), "..", "..", "README.md")).read()
    section = readme[readme.index("## From Python, without ROS"):]
    begin = section.index("```python\n") + len("```python\n")
    code = section[begin:section.index("\n```", begin)]
    monkeypatch.chdir(tmp_path)
    names = {}
    exec(compile(code, "README.md", "exec"), names)
    assert (tmp_path / "shot.png").stat().st_size > 10000
    assert names["out"].positions.shape == (1000, 16, 3) and 0 <= names["best"] < 1000


def test_each_table_plays_with_its_own_balls_unless_told_otherwise():
    assert cue_sim.Engine("7ft").params["ball_radius"] == cue_sim.parameters()["ball_radius"]["default"]
    snooker = cue_sim.Engine("snooker")
    assert snooker.params["ball_radius"] == 0.02625 and snooker.params["ball_mass"] == 0.142
    assert cue_sim.Engine("carom").params["ball_radius"] == 0.03075
    given = cue_sim.Engine("snooker", ball_radius=0.028575)
    assert given.params["ball_radius"] == 0.028575 and given.params["ball_mass"] == 0.142
    rack = snooker.rack("nine")
    assert np.all(rack.positions[:, 2] == 0.02625)


def test_a_table_from_its_urdf_file_is_the_named_table(tmp_path):
    urdf = os.path.join(os.path.dirname(__file__), "..", "..", "urdf", "table_9ft.urdf")
    by_file, by_name = cue_sim.Engine(urdf), cue_sim.Engine("9ft")
    assert by_file.pockets == by_name.pockets
    a = cue_sim.simulate(by_file, by_file.rack("nine"), speed=7.0, phi=0.003)
    b = cue_sim.simulate(by_name, by_name.rack("nine"), speed=7.0, phi=0.003)
    assert np.array_equal(a.events, b.events) and np.array_equal(a.final.positions, b.final.positions)
    broken = tmp_path / "broken.urdf"
    broken.write_text("<robot name='x'><link name='cloth'/>")
    for path in (str(tmp_path / "missing.urdf"), str(broken)):
        with pytest.raises(ValueError, match=path):
            cue_sim.Engine(path)


def test_a_jump_shot_flies_in_the_samples_with_the_sequential_cue():
    # Issue 33: the ball-table and cue models by name; a steep stroke with the sequential cue
    # leaves the cloth (motion "airborne", heights above R in the samples) and lands ("ball_slate"
    # events); the planar cue keeps the same stroke on the cloth.
    models = cue_sim.models()
    assert models["ball_table"] == ["frictional", "frictionless"]
    assert models["cue"] == ["planar", "sequential"]
    jumper = cue_sim.Engine(cue_model="sequential")
    assert jumper.models["cue"] == "sequential" and jumper.models["ball_table"] == "frictional"
    assert pickle.loads(pickle.dumps(jumper)).models == jumper.models
    start = cue_sim.State.from_balls([0, 1], [[-0.6, 0.0], [-0.3, 0.0]])
    radius = jumper.params["ball_radius"]
    shot = cue_sim.simulate(jumper, start, speed=3.0, theta=0.8, sample_period=0.005)
    kinds = [cue_sim.EVENT_KINDS[int(k)] for k in shot.events["kind"]]
    assert kinds[0] == "ball_slate" and kinds.count("ball_slate") > 3
    cue_ball = 0  # row 0 of the starting State
    heights = shot.samples.positions[:, cue_ball, 2] - radius
    assert heights.max() > 0.08
    airborne = [cue_sim.MOTION[int(m)] for m in shot.samples.motion[:, cue_ball]]
    assert "airborne" in airborne
    assert np.allclose(shot.final.positions[:, 2], radius, atol=1e-12)
    level = cue_sim.simulate(cue_sim.Engine(), start, speed=3.0, theta=0.8, sample_period=0.005)
    assert "ball_slate" not in [cue_sim.EVENT_KINDS[int(k)] for k in level.events["kind"]]
    assert np.all(level.samples.positions[:, :, 2] == radius)
    with pytest.raises(ValueError, match="rubber"):
        cue_sim.Engine(ball_table_model="rubber")
    with pytest.raises(ValueError, match="catapult"):
        cue_sim.Engine(cue_model="catapult")


def test_a_ball_that_flies_over_a_cushion_leaves_the_table_and_the_state_says_so():
    # Issue 33: too hard a jump clears the foot cushion: an "off_table" event naming where it lands,
    # the ball out of play ("off_table", pocket -2) where it landed, and a State that goes back in.
    jumper = cue_sim.Engine(cue_model="sequential")
    start = cue_sim.State.from_balls([0, 1], [[-0.6, 0.0], [-0.3, 0.0]])
    shot = cue_sim.simulate(jumper, start, speed=4.0, theta=0.8)
    last = shot.events[-1]
    assert cue_sim.EVENT_KINDS[int(last["kind"])] == "off_table"
    assert int(last["ball"]) == 0 and str(last["obstacle"]) in ("rail", "floor")
    assert cue_sim.MOTION[int(shot.final.motion[0])] == "off_table"
    assert int(shot.final.pocket[0]) == -2
    assert abs(shot.final.positions[0, 0]) > 0.9906  # beyond the foot cushion's nose
    jumper.check(shot.final)  # an off-table ball is a valid part of a state
    with pytest.raises(ValueError, match="off the table"):
        cue_sim.simulate(jumper, shot.final, speed=1.0)
