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

#: Every task's options and their defaults (doc/learning.md describes each), as the C++ declares them.
DEFAULT_OPTIONS = dict(_core.default_options())


def engine_of(engine=None, table: str = "7ft"):
    """The _core engine of a cue_sim.Engine, or of the bundled table `table` with default physics."""
    if engine is None:
        from cue_sim.api import Engine
        engine = Engine(table)
    return engine._engine


def checked_seed(seed, tables: int = 1) -> int:
    """`seed` as the engine takes it: an integer with seed + tables - 1 below 2**64, else ValueError."""
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)):
        raise ValueError(f"seed: an integer, got {seed!r}")
    seed = int(seed)
    if not 0 <= seed <= 2**64 - tables:
        raise ValueError(f"seed: must be in [0, 2**64 - {tables}], got {seed}")
    return seed


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

    task: "pot", "break", "eight_ball" or "nine_ball" (task_names()); the options
    (DEFAULT_OPTIONS, each described in doc/learning.md): balls, target, max_shots, rack, action
    ("absolute": phi [rad], speed [m/s]; "relative": ball, pocket, cut_offset [rad], speed),
    spin (theta, tip_right, tip_up too), opponent ("planner" or "self"), opponent_skill,
    opponent_noise, shaping, noise (the tournaments' execution noise, seeded by the episode),
    observation ("state", "pixels" or "both"), pixel_width, pixel_height. Games add place_x,
    place_y (the cue ball in hand) and, in 9-ball, push_out to the action.
    engine: a cue_sim.Engine (its table, physics and models); else the bundled `table`.
    """

    metadata = {"render_modes": ["rgb_array"], "render_fps": 4}

    def __init__(self, task: str = "pot", engine=None, table: str = "7ft", render_mode: Optional[str] = None,
                 **options: Any):
        if render_mode not in (None, "rgb_array"):
            raise ValueError(f"render_mode: must be None or 'rgb_array', got {render_mode!r}")
        self.render_mode = render_mode
        self.task = task
        self._env = _core.Env(engine_of(engine, table), dict(options, task=task))
        self.observation_space, self.action_space = spaces_of(self._env.spaces)
        self.action_names = list(self._env.spaces["action"]["names"])
        self.observation_names = list(self._env.spaces["state"]["names"])
        self._np_random = None

    @property
    def np_random(self) -> np.random.Generator:
        if self._np_random is None:
            self._np_random = np.random.default_rng()
        return self._np_random

    @np_random.setter
    def np_random(self, value: np.random.Generator):
        self._np_random = value

    def reset(self, *, seed: Optional[int] = None, options: Optional[dict] = None):
        """A new episode: from `seed` if given (the same seed, the same episode), else the
        environment's stream goes on (a fresh environment's first reset draws one)."""
        if seed is None and options is None and self._np_random is not None:
            return self._env.reset(None), {}  # the common case, kept short: a one-shot episode resets every step
        if options:
            raise ValueError(f"options: reset takes none (give them to the environment), got {sorted(options)}")
        if seed is not None:
            seed = checked_seed(seed)
            self._np_random = np.random.default_rng(seed)
        elif self._np_random is None:
            seed = int(self.np_random.integers(2**63))
        return self._env.reset(seed), {}

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
