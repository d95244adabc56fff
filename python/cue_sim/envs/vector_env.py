"""N tables of one task stepped in one call on every core (cue_sim._core.VectorEnv), with
Gymnasium's vector API: batched spaces, seeds seed, seed + 1, ..., and next-step autoreset (a
table whose episode ended is reset by the next step, which ignores its action and reports reward
0, neither terminated nor truncated)."""
from __future__ import annotations

from typing import Any, Optional, Sequence, Union

import numpy as np

from cue_sim.envs.spaces import space_classes
from cue_sim.envs.table_env import _core, checked_seed, engine_of, spaces_of


def batched(space, n: int):
    """The space of n stacked observations or actions."""
    Box, Dict = space_classes()
    if isinstance(space, Dict):
        return Dict({key: batched(part, n) for key, part in space.spaces.items()})
    return Box(np.broadcast_to(space.low, (n,) + space.shape), np.broadcast_to(space.high, (n,) + space.shape),
               dtype=space.dtype)


class TableVectorEnv:
    """`num_envs` tables of one task (TableEnv's task and options), stepped on `threads` threads
    (0: every core) with the GIL released. Table i is exactly TableEnv seeded with seed + i."""

    metadata = {"autoreset_mode": "NextStep", "render_modes": []}

    def __init__(self, num_envs: int, task: str = "pot", engine=None, table: Optional[str] = None, threads: int = 0,
                 **options: Any):
        self._envs = _core.VectorEnv(engine_of(engine, table, task), dict(options, task=task), int(num_envs),
                                     int(threads))
        self.num_envs = int(num_envs)
        self.task = task
        self.single_observation_space, self.single_action_space = spaces_of(self._envs.spaces)
        self.observation_space = batched(self.single_observation_space, self.num_envs)
        self.action_space = batched(self.single_action_space, self.num_envs)
        self.action_names = list(self._envs.spaces["action"]["names"])
        self.observation_names = list(self._envs.spaces["state"]["names"])
        self.closed = False
        try:  # Gymnasium 1.x names the mode with its own enum
            from gymnasium.vector import AutoresetMode
            self.metadata = dict(self.metadata, autoreset_mode=AutoresetMode.NEXT_STEP)
        except ImportError:
            pass

    def reset(self, *, seed: Optional[Union[int, Sequence[int]]] = None, options: Optional[dict] = None):
        """Every table's new episode: table i from seed + i (an int), or from seed[i] (a list of
        one seed per table), else each stream goes on."""
        if options:
            raise ValueError(f"options: reset takes none, got {sorted(options)}")
        if seed is not None and isinstance(seed, (list, tuple, np.ndarray)):
            seeds = list(seed)
            if len(seeds) != self.num_envs or any(s is None for s in seeds):
                raise ValueError(f"seed: an int or {self.num_envs} ints, got {seed!r}")
            if seeds != [seeds[0] + i for i in range(self.num_envs)]:
                raise ValueError("seed: a list must be consecutive (seed, seed + 1, ...); give the first as an int")
            seed = seeds[0]
        return self._envs.reset(None if seed is None else checked_seed(seed, self.num_envs)), {}

    def step(self, actions):
        """Every table plays its row of `actions` ((num_envs, action size)): (observations,
        rewards, terminations, truncations, infos); infos holds one array per key and
        "autoreset", where the table was reset instead."""
        return self._envs.step(actions)

    def close(self):
        self.closed = True

    @property
    def unwrapped(self):
        return self

    def __repr__(self) -> str:
        return f"<TableVectorEnv {self.task} x{self.num_envs}>"
