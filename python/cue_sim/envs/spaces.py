"""Spaces with Gymnasium's names and fields (Box, Discrete, Dict), for when Gymnasium is absent.

When gymnasium is importable the environments use its own spaces instead (`space_classes()`), so
that its wrappers and checks see what they expect; these follow the same contract: `shape`,
`dtype`, `low`, `high`, `sample()`, `contains(x)` (and `x in space`), `seed(seed)`.
"""
from __future__ import annotations

from typing import Dict as DictType, Optional, Sequence

import numpy as np


class Space:
    def __init__(self, shape, dtype, seed=None):
        self.shape = None if shape is None else tuple(shape)
        self.dtype = None if dtype is None else np.dtype(dtype)
        self._np_random = None
        if seed is not None:
            self.seed(seed)

    @property
    def np_random(self) -> np.random.Generator:
        if self._np_random is None:
            self.seed()
        return self._np_random

    def seed(self, seed: Optional[int] = None):
        self._np_random = np.random.default_rng(seed)
        return [seed]

    def __contains__(self, x) -> bool:
        return self.contains(x)


class Box(Space):
    """Reals (or bytes) between `low` and `high`, elementwise."""

    def __init__(self, low, high, shape: Optional[Sequence[int]] = None, dtype=np.float32, seed=None):
        dtype = np.dtype(dtype)
        if shape is None:
            shape = np.broadcast(np.asarray(low), np.asarray(high)).shape
        self.low = np.broadcast_to(np.asarray(low, dtype=dtype), shape).copy()
        self.high = np.broadcast_to(np.asarray(high, dtype=dtype), shape).copy()
        if np.any(self.low > self.high):
            raise ValueError("Box: low must not exceed high")
        super().__init__(shape, dtype, seed)

    def sample(self) -> np.ndarray:
        if np.issubdtype(self.dtype, np.integer):
            return self.np_random.integers(self.low, self.high, endpoint=True, dtype=self.dtype)
        return self.np_random.uniform(self.low, self.high).astype(self.dtype)

    def contains(self, x) -> bool:
        if not isinstance(x, np.ndarray):
            try:
                x = np.asarray(x, dtype=self.dtype)
            except (ValueError, TypeError):
                return False
        return bool(x.shape == self.shape and np.can_cast(x.dtype, self.dtype)
                    and np.all(x >= self.low) and np.all(x <= self.high))

    def __repr__(self) -> str:
        return f"Box({self.low.min()}, {self.high.max()}, {self.shape}, {self.dtype})"

    def __eq__(self, other) -> bool:
        return (isinstance(other, Box) and self.shape == other.shape and self.dtype == other.dtype
                and np.array_equal(self.low, other.low) and np.array_equal(self.high, other.high))


class Discrete(Space):
    """The integers start, start + 1, ..., start + n - 1."""

    def __init__(self, n: int, seed=None, start: int = 0):
        if n < 1:
            raise ValueError(f"Discrete: n must be at least 1, got {n}")
        self.n = np.int64(n)
        self.start = np.int64(start)
        super().__init__((), np.int64, seed)

    def sample(self) -> np.int64:
        return np.int64(self.start + self.np_random.integers(self.n))

    def contains(self, x) -> bool:
        if isinstance(x, (int, np.integer)) or (isinstance(x, np.ndarray) and x.shape == ()
                                                 and np.issubdtype(x.dtype, np.integer)):
            return bool(self.start <= int(x) < self.start + self.n)
        return False

    def __repr__(self) -> str:
        return f"Discrete({self.n})" if self.start == 0 else f"Discrete({self.n}, start={self.start})"

    def __eq__(self, other) -> bool:
        return isinstance(other, Discrete) and self.n == other.n and self.start == other.start


class Dict(Space):
    """Named spaces; a sample is a dict of their samples."""

    def __init__(self, spaces: DictType[str, Space], seed=None):
        self.spaces = dict(spaces)
        super().__init__(None, None, None)
        if seed is not None:
            self.seed(seed)

    def seed(self, seed: Optional[int] = None):
        super().seed(seed)
        seeds = self._np_random.integers(2**32, size=len(self.spaces))
        for space, s in zip(self.spaces.values(), seeds):
            space.seed(int(s))
        return [seed]

    def sample(self) -> dict:
        return {key: space.sample() for key, space in self.spaces.items()}

    def contains(self, x) -> bool:
        return (isinstance(x, dict) and x.keys() == self.spaces.keys()
                and all(space.contains(x[key]) for key, space in self.spaces.items()))

    def __getitem__(self, key: str) -> Space:
        return self.spaces[key]

    def keys(self):
        return self.spaces.keys()

    def __repr__(self) -> str:
        return "Dict(" + ", ".join(f"{k!r}: {v}" for k, v in self.spaces.items()) + ")"

    def __eq__(self, other) -> bool:
        return isinstance(other, Dict) and self.spaces == other.spaces


def space_classes():
    """(Box, Dict): Gymnasium's when it is importable, else this module's."""
    try:
        from gymnasium import spaces as gym_spaces
        return gym_spaces.Box, gym_spaces.Dict
    except ImportError:
        return Box, Dict
