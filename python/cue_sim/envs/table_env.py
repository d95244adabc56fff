"""One table as a Gymnasium environment: a task played one shot a step (cue_sim._core.Env)."""
from __future__ import annotations

from typing import Any, Optional

import numpy as np

from cue_sim._interpreter import core
from cue_sim.envs.spaces import space_classes

_core = core()

try:  # Gymnasium's own base class when it is there, so that its wrappers and checks accept the env
    import gymnasium as _gymnasium
    _EnvBase = _gymnasium.Env
except ImportError:
    _gymnasium = None
    _EnvBase = object

#: The size render() draws at [px].
RENDER_SIZE = (640, 360)

#: Every option and its default, as env_options.def declares them (doc/learning.md's table of options).
DEFAULT_OPTIONS = dict(_core.default_options())


def engine_of(engine=None, table: Optional[str] = None, task: str = "pot"):
    """The _core engine of a cue_sim.Engine, or of the bundled table `table` with default physics;
    without one, the table `task` is played on (a game's own, cue_sim.rules_table(); else 7ft)."""
    if engine is None:
        from cue_sim.api import Engine
        engine = Engine(table or (_core.rules_table(task) if isinstance(task, str) else "") or "7ft")
    return engine._engine


def checked_seed(seed, tables: int = 1) -> int:
    """`seed` as the engine takes it: an integer with seed + tables - 1 below 2**64, else ValueError."""
    return _core.checked_seed(seed, tables)


def spaces_of(spec: dict):
    """(observation space, action space) from _core's description of an environment's spaces."""
    Box, Dict = space_classes()
    action = spec["action"]
    action_space = Box(np.array(action["low"]), np.array(action["high"]), dtype=np.float64)
    parts = {}
    if spec["state"]["names"]:
        state = spec["state"]
        parts["state"] = Box(np.array(state["low"], dtype=np.float32), np.array(state["high"], dtype=np.float32),
                             dtype=np.float32)
    if spec["pixel_width"]:
        parts["pixels"] = Box(0, 255, shape=(spec["pixel_height"], spec["pixel_width"], 3), dtype=np.uint8)
    observation_space = Dict(parts) if len(parts) == 2 else next(iter(parts.values()))
    return observation_space, action_space


class TableEnv(_EnvBase):
    """A task on one table (Gymnasium's Env API; Gymnasium itself is not needed).

    task: one of task_names(): pot, position, break, and a game per ruleset (eight_ball, nine_ball,
    ten_ball; three_cushion on the carom table). The options and their defaults are DEFAULT_OPTIONS, each declared once in env_options.def with its range and
    meaning (cue_sim._core.env_options(); doc/learning.md's table of options): balls, target,
    max_shots, rack, action ("absolute": phi [rad], speed [m/s]; "relative": ball, pocket,
    cut_offset [rad], speed), spin (theta, tip_right, tip_up too), opponent, opponent_skill,
    opponent_noise, shaping, noise, observation, pixel_width, pixel_height. Games add place_x,
    place_y (the cue ball in hand) and, in 9- and 10-ball, push_out to the action.
    Three-cushion adds race (the points that win; 0 for 40).
    engine: a cue_sim.Engine (its table, physics and models); else the bundled `table`, by default
    the one the task is played on (7ft; carom for three_cushion).
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 4}

    def __init__(self, task: str = "pot", engine=None, table: Optional[str] = None, render_mode: Optional[str] = None,
                 **options: Any):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode: must be None or 'rgb_array', got {render_mode!r}")
        self.render_mode = render_mode
        self.task = task
        self._env = _core.Env(engine_of(engine, table, task), dict(options, task=task))
        self.observation_space, self.action_space = spaces_of(self._env.spaces)
        self.action_names = list(self._env.spaces["action"]["names"])
        self.observation_names = list(self._env.spaces["state"]["names"])
        self._rng, self._rng_seed, self._rng_seeding = None, -1, None
        # A learner's loop calls step and reset millions of times: they go to the C++ methods
        # themselves, without a Python frame between (a cheap shot's step costs some 10 us), unless
        # a subclass has its own.
        if type(self).step is TableEnv.step:
            self.step = self._env.step
        if type(self).reset is TableEnv.reset:
            self.reset = self._env.reset

    def _synced_rng(self):
        """Gymnasium's generator brought up to date: a fresh one from each reset given a seed (and
        from a fresh environment's first reset, which draws one); else the one there is."""
        seeding = self._env.seeding
        if seeding[0] and seeding != self._rng_seeding:
            self._rng, self._rng_seed, self._rng_seeding = np.random.default_rng(seeding[1]), seeding[1], seeding
        elif self._rng is None:
            self._rng_seed = int(np.random.default_rng().integers(2**63))
            self._rng = np.random.default_rng(self._rng_seed)
        return self._rng

    @property
    def _np_random(self) -> np.random.Generator:
        return self._synced_rng()

    @_np_random.setter
    def _np_random(self, value: np.random.Generator):
        self._rng, self._rng_seed, self._rng_seeding = value, -1, self._env.seeding

    @property
    def np_random(self) -> np.random.Generator:
        """A generator for the learner's own draws (Gymnasium's): seeded by each reset given a
        seed; the episodes have their own stream in C++."""
        return self._synced_rng()

    @np_random.setter
    def np_random(self, value: np.random.Generator):
        self._np_random = value

    @property
    def np_random_seed(self) -> int:
        """np_random's seed, as Gymnasium has it: the last seeded reset's, or -1 once np_random
        was set directly."""
        self._synced_rng()
        return self._rng_seed

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        """A new episode: (observation, {}). From `seed` if given, an integer in [0, 2**64) (the same
        seed, the same episode), else the environment's stream goes on (a fresh environment's first
        reset draws one). `options` must be None or empty: the options are the environment's."""
        return self._env.reset(seed=seed, options=options)

    def step(self, action):
        """Plays one shot: (observation, reward, terminated, truncated, info). A NaN, a value
        outside the action space or a wrong shape raises ValueError naming the component."""
        return self._env.step(action)

    def render(self):
        """The table now as the overhead camera sees it: an RGB array (360 x 640 x 3)."""
        if self.render_mode != "rgb_array":
            return None
        return self._env.render(*RENDER_SIZE)

    def table(self):
        """The balls now, as a cue_sim.State."""
        from cue_sim.api import State
        return State._of(self._env.table())

    def close(self):
        pass

    @property
    def unwrapped(self):
        return self

    def __str__(self) -> str:
        return f"<TableEnv {self.task}>"
