"""cue_sim.envs: Gymnasium's environment contract without Gymnasium (spaces, seeds, resets, bad
actions), the vector environment against single ones, and gymnasium's own check_env when it is
installed."""
import copy
import inspect
import math
import pathlib
import re

import numpy as np
import pytest

from cue_sim.envs import DEFAULT_OPTIONS, Box, Dict, Discrete, TableEnv, TableVectorEnv, task_names


def play(env, seed, steps, action_seed=1):
    """Observations and rewards of `steps` seeded random actions, resetting when an episode ends."""
    env.action_space.seed(action_seed)
    obs, _ = env.reset(seed=seed)
    trace = [obs]
    for _ in range(steps):
        obs, reward, terminated, truncated, info = env.step(env.action_space.sample())
        trace.append((obs, reward, terminated, truncated))
        if terminated or truncated:
            obs, _ = env.reset()
            trace.append(obs)
    return trace


def observed(obs, space):
    """Gymnasium's checks of an observation: inside its space, of the space's dtype (each part of a Dict)."""
    if isinstance(space, Dict):
        return obs.keys() == space.spaces.keys() and all(observed(obs[k], space[k]) for k in obs)
    return isinstance(obs, np.ndarray) and obs.dtype == space.dtype and obs in space


def same(a, b):
    if isinstance(a, dict):
        return a.keys() == b.keys() and all(same(a[k], b[k]) for k in a)
    if isinstance(a, (tuple, list)):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return np.array_equal(a, b)


@pytest.mark.parametrize("options", [dict(task="pot", balls=3), dict(task="pot", target="lowest", max_shots=5, balls=4),
                                     dict(task="pot", action="relative", spin=True), dict(task="position", balls=4, action="relative"),
                                     dict(task="break", rack="eight"), dict(task="break", rack="ten"),
                                     dict(task="ten_ball", opponent="planner", action="relative"),
                                     dict(task="nine_ball", opponent="self", action="relative"),
                                     dict(task="eight_ball", opponent="planner", opponent_skill=0.5),
                                     dict(task="three_cushion", opponent="self", race=1, max_shots=20),
                                     dict(task="pot", observation="both", pixel_width=96, pixel_height=48)])
def test_the_contract(options):
    env = TableEnv(**options)
    assert options["task"] in task_names()
    obs, info = env.reset(seed=3)
    assert observed(obs, env.observation_space) and isinstance(info, dict)
    ends = 0
    for _ in range(40):
        action = env.action_space.sample()
        assert action in env.action_space
        obs, reward, terminated, truncated, info = env.step(action)
        assert observed(obs, env.observation_space)
        assert isinstance(reward, float) and math.isfinite(reward)
        assert isinstance(terminated, bool) and isinstance(truncated, bool)
        assert {"shots", "pocketed", "scratch", "foul", "reason"} <= info.keys() and info["reason"]
        if terminated or truncated:
            ends += 1
            obs, _ = env.reset()
            assert observed(obs, env.observation_space)
    assert ends > 0
    assert same(play(env, 7, 30), play(TableEnv(**options), 7, 30))
    frame = TableEnv(render_mode="rgb_array", **options)
    frame.reset(seed=1)
    picture = frame.render()
    assert picture.shape == (360, 640, 3) and picture.dtype == np.uint8 and picture.std() > 10


def test_seeds_fix_episodes_and_streams_go_on():
    env = TableEnv("pot", balls=5)
    first, _ = env.reset(seed=11)
    again, _ = env.reset(seed=11)
    assert np.array_equal(first, again)
    other, _ = env.reset(seed=12)
    assert not np.array_equal(first, other)
    following, _ = env.reset()
    assert not np.array_equal(following, other)
    # A fresh environment's first reset without a seed draws one: two fresh ones differ.
    assert not np.array_equal(TableEnv("pot", balls=5).reset()[0], TableEnv("pot", balls=5).reset()[0])


@pytest.mark.parametrize("action, field", [([float("nan"), 2.0], "phi"), ([0.1, 0.0], "speed"),
                                           ([0.1, 13.0], "speed"), ([0.1], "2 values"),
                                           ([[0.1, 2.0]], "shape"), ([4.0, 1.0], "phi")])
def test_bad_actions_are_refused_and_change_nothing(action, field):
    env = TableEnv("pot", balls=3)
    obs, _ = env.reset(seed=5)
    before = env.table().positions.copy()
    with pytest.raises(ValueError, match=field):
        env.step(action)
    assert np.array_equal(env.table().positions, before)
    env.step([0.2, 1.0])  # the episode is still playable


def test_bad_options_name_the_option():
    for options, field in [(dict(task="bagatelle"), "task"), (dict(balls=0), "balls"), (dict(colour=1), "colour"),
                           (dict(observation="rgb"), "observation"), (dict(balls="two"), "balls"),
                           (dict(render_mode="human"), "render_mode")]:
        with pytest.raises(ValueError, match=field):
            TableEnv(**options)
    with pytest.raises(ValueError, match="pockets"):
        TableEnv("pot", table="carom")


def test_the_options_table_is_the_declaration():
    """doc/learning.md's table of options against env_options.def, as _core reads it."""
    from cue_sim import _core
    doc = (pathlib.Path(__file__).resolve().parents[2] / "doc" / "learning.md").read_text()
    rows = {m.group(1): (m.group(2), m.group(3)) for m in re.finditer(r"^\| `(\w+)` \| ([^|]+) \| ([^|]+) \|", doc, re.M)}
    declared = _core.env_options()
    assert [o["name"] for o in declared] == list(DEFAULT_OPTIONS)
    for option in declared:
        default, values = rows[option["name"]]
        assert default.strip() == (f'"{option["default"]}"' if option["kind"] == "text" else repr(option["default"]))
        if "choices" in option:
            assert values.strip() == ", ".join(option["choices"])
        elif "range" in option:
            assert values.strip() == "[{:g}, {:g}]".format(*option["range"])
        assert DEFAULT_OPTIONS[option["name"]] == option["default"]
    for name, value in [("balls", True), ("noise", 1), ("opponent_skill", "high"), ("task", 3)]:
        with pytest.raises(ValueError, match=f"{name}: .* wrong type"):
            TableEnv(**{name: value}) if name != "task" else TableEnv(task=value)
    TableEnv(noise=np.False_, opponent_skill=np.float32(0.5), balls=np.int64(3))


def test_bad_seeds_are_refused():
    env, envs = TableEnv("pot"), TableVectorEnv(3, "pot")
    for bad in (-1, 2**64, 1.5, "7", True):
        with pytest.raises(ValueError, match="seed"):
            env.reset(seed=bad)
        with pytest.raises(ValueError, match="seed"):
            envs.reset(seed=bad)
    with pytest.raises(ValueError, match="seed"):
        envs.reset(seed=2**64 - 2)  # its third table's seed would not fit
    env.reset(seed=2**64 - 1)
    envs.reset(seed=2**64 - 3)


def test_refused_resets_change_nothing():
    env, twin = TableEnv("pot", balls=4), TableEnv("pot", balls=4)
    env.reset(seed=21)
    twin.reset(seed=21)
    for bad in (dict(seed=-3), dict(options={"balls": 2}), dict(options=[1])):
        with pytest.raises(ValueError, match="seed" if "seed" in bad else "options"):
            env.reset(**bad)
    with pytest.raises(TypeError, match="keyword"):
        env.reset(3)
    with pytest.raises(TypeError, match="colour"):
        env.reset(colour=1)
    # The episode goes on as its twin's, and so do the next episodes of the stream.
    assert same(env.step([0.3, 1.5]), twin.step([0.3, 1.5]))
    assert same(env.reset(), twin.reset())
    env.reset(options={})  # no options is allowed, as Gymnasium's checker tries


def test_reset_is_gymnasiums_as_its_checker_reads_it():
    """What gymnasium.utils.env_checker checks of reset, without Gymnasium: the signature and the
    generator Gymnasium keeps (the same seed, the same generator; another seed, another)."""
    env = TableEnv("pot")
    parameters = inspect.signature(env.reset).parameters
    assert parameters["seed"].default is None and parameters["options"].default is None
    assert all(p.kind is inspect.Parameter.KEYWORD_ONLY for p in parameters.values())
    assert list(inspect.signature(env.step).parameters) == ["action"]
    env.reset(seed=123)
    seeded = copy.deepcopy(env.unwrapped._np_random)
    env.np_random.random(5)  # the learner's own draws move it on ...
    env.reset(seed=123)  # ... and the same seed starts it again
    assert env.unwrapped._np_random.bit_generator.state == seeded.bit_generator.state
    env.reset()  # a reset without a seed leaves it
    assert env.unwrapped._np_random.bit_generator.state == seeded.bit_generator.state
    env.reset(seed=456)
    assert env.unwrapped._np_random.bit_generator.state != seeded.bit_generator.state
    assert env.np_random_seed == 456
    mine = np.random.default_rng(9)
    env.np_random = mine
    env.reset()
    assert env.np_random is mine and env.np_random_seed == -1
    env.reset(seed=7)
    assert env.np_random is not mine and env.np_random_seed == 7


def test_a_subclass_step_and_reset_are_its_own():
    class Counting(TableEnv):
        steps = 0

        def step(self, action):
            self.steps += 1
            return super().step(action)

        def reset(self, *, seed=None, options=None):
            return super().reset(seed=seed, options=options)

    env = Counting("pot")
    env.reset(seed=1)
    env.step([0.0, 2.0])
    assert env.steps == 1


def test_step_after_the_end_needs_a_reset():
    env = TableEnv("pot")
    env.reset(seed=0)
    env.step([0.0, 1.0])
    with pytest.raises(RuntimeError, match="reset"):
        env.step([0.0, 1.0])


@pytest.mark.parametrize("options", [dict(task="pot", balls=4, max_shots=3),
                                     dict(task="pot", observation="both", pixel_width=32, pixel_height=16)])
def test_the_vector_environment_is_single_environments(options):
    n = 5
    vector = TableVectorEnv(n, threads=2, **options)
    singles = [TableEnv(**options) for _ in range(n)]
    assert vector.single_action_space == singles[0].action_space
    obs, _ = vector.reset(seed=40)
    assert obs in vector.observation_space
    pick = (lambda o, i: {k: v[i] for k, v in o.items()}) if isinstance(obs, dict) else (lambda o, i: o[i])
    for i, env in enumerate(singles):
        assert same(pick(obs, i), env.reset(seed=40 + i)[0])
    ended = [False] * n
    rng = np.random.default_rng(2)
    autoresets = 0
    for _ in range(12):
        actions = np.stack([singles[0].action_space.low + rng.random(2) * (singles[0].action_space.high -
                                                                           singles[0].action_space.low)
                            for _ in range(n)])
        obs, rewards, terminated, truncated, info = vector.step(actions)
        assert obs in vector.observation_space
        for i, env in enumerate(singles):
            assert info["autoreset"][i] == ended[i]
            if ended[i]:
                single = env.reset()[0]
                reward, term, trunc = 0.0, False, False
                autoresets += 1
            else:
                single, reward, term, trunc, _ = env.step(actions[i])
            assert same(pick(obs, i), single)
            assert (rewards[i], terminated[i], truncated[i]) == (reward, term, trunc)
            ended[i] = term or trunc
    assert autoresets > 0
    with pytest.raises(ValueError, match="row 2: action: speed"):
        bad = actions.copy()
        bad[2, 1] = np.nan
        vector.step(bad)
    with pytest.raises(ValueError, match="consecutive"):
        vector.reset(seed=[1, 5, 2, 3, 4])


def test_spaces_follow_gymnasium():
    box = Box(np.array([0.0, -1.0]), np.array([1.0, 1.0]), dtype=np.float64)
    box.seed(0)
    assert box.shape == (2,) and box.dtype == np.float64
    assert all(box.sample() in box for _ in range(100))
    assert np.array([2.0, 0.0]) not in box and np.array([0.5]) not in box
    pixels = Box(0, 255, shape=(4, 8, 3), dtype=np.uint8)
    assert pixels.sample() in pixels and pixels.sample().dtype == np.uint8
    d = Discrete(6)
    assert all(d.sample() in d for _ in range(50)) and 6 not in d and -1 not in d
    both = Dict({"state": box, "pixels": pixels})
    assert both.sample() in both and {"state": box.sample()} not in both


def test_every_task_has_an_id_and_the_games_come_from_the_rulesets():
    import cue_sim
    from cue_sim.envs import TASK_IDS
    assert sorted(TASK_IDS.values()) == sorted(task_names())
    assert TASK_IDS["cue_sim/Pot-v0"] == "pot" and TASK_IDS["cue_sim/NineBall-v0"] == "nine_ball"
    assert TASK_IDS["cue_sim/TenBall-v0"] == "ten_ball"
    assert TASK_IDS["cue_sim/ThreeCushion-v0"] == "three_cushion"
    assert set(cue_sim.rules()) <= set(task_names())
    # Each game is made on its own table without being told: three-cushion on the carom table,
    # whose observation says whose cue ball is struck and the scores, and whose info the points.
    carom = TableEnv("three_cushion", race=3, opponent="self")
    assert carom.observation_names[-3:] == ["cue_ball_1", "own_score", "opponent_score"]
    obs, _ = carom.reset(seed=2)
    _, _, _, _, info = carom.step(carom.action_space.sample())
    assert info["points"] in (0, 1)
    with pytest.raises(ValueError, match="table without pockets"):
        TableEnv("three_cushion", table="7ft")
    # Snooker on the snooker table: a slot for each of its 22 balls, the D, and the penalty a foul gives.
    assert TASK_IDS["cue_sim/Snooker-v0"] == "snooker"
    snooker = TableEnv("snooker", opponent="self")
    assert "ball21_on_table" in snooker.observation_names and "in_hand_d" in snooker.observation_names
    obs, _ = snooker.reset(seed=1)
    assert obs[snooker.observation_names.index("in_hand_d")] == 1.0
    _, _, _, _, info = snooker.step(snooker.action_space.sample())
    assert info["foul"] == (info["penalty"] >= 4)
    # The push-out is in the action of the games whose rules have one.
    assert TableEnv("ten_ball", action="relative").action_names[-1] == "push_out"
    assert "push_out" not in TableEnv("eight_ball", action="relative").action_names


def test_gymnasium_check_env():
    gymnasium = pytest.importorskip("gymnasium", reason="gymnasium is not installed (not packaged in Debian)")
    from gymnasium.utils.env_checker import check_env
    for env_id in ("cue_sim/Pot-v0", "cue_sim/Position-v0", "cue_sim/Break-v0", "cue_sim/EightBall-v0", "cue_sim/NineBall-v0"):
        check_env(gymnasium.make(env_id).unwrapped)
