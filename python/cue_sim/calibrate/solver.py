"""The fit's solver: robust least squares over the coefficients and every shot's unknowns, by Ceres
(cue_sim._core.solve_arrow, include/cue_sim/calibration/arrow_least_squares.hpp).

The problem is shaped like an arrow: each shot's residuals depend on the coefficients and on that
shot's own unknowns only. Ceres' Levenberg-Marquardt eliminates each shot's unknowns by their
Schur complement (DENSE_SCHUR), so that a step is a small dense solve per shot and one of the
coefficients' size, exact, where scipy's least_squares with lsmr iterated over the whole Jacobian
for up to as many products as there are unknowns (a shot's own block is rank-deficient and badly
conditioned: doc/calibration.md). The Jacobian is differenced here, in column groups over the
problem's sparsity, every group one batch of simulations on every core; the robust loss is soft L1
per residual, as scipy's loss="soft_l1". What a solve returns reads as least_squares' result (x,
cost, fun, jac scaled for the loss, nfev, status, success, message), which the stages and the
uncertainty take.
"""
from __future__ import annotations

from functools import cached_property
from typing import Callable, Sequence, Tuple

import numpy as np

from cue_sim._interpreter import core
from cue_sim.calibrate import uncertainty

_core = core()


class SparseDifferences:
    """The residuals' Jacobian by forward differences over the sparsity's column groups, with
    scipy's steps and grouping (its approx_derivative with `sparsity`), where each group's entries
    lie worked out once a solve. `blocks` lays the entries out as the solver takes them (each shot's
    dense block, rows x (shared + own), row-major, one after another); `matrix` as a sparse matrix
    without the entries that came out zero (more than half of the pattern: a ball's rows before it
    moves depend only on where it stood)."""

    def __init__(self, residuals: Callable[[np.ndarray], np.ndarray], sparsity, bounds, shared: int,
                 groups: Sequence[Tuple[int, int, int, int]]):
        from scipy.optimize._numdiff import group_columns  # least_squares' own column grouping
        self._residuals, self.bounds = residuals, bounds
        structure = sparsity.tocsc()
        structure.sort_indices()
        self.shape, self._indptr = structure.shape, structure.indptr
        self._rows = structure.indices
        self._entry_columns = np.repeat(np.arange(structure.shape[1]), np.diff(structure.indptr))
        column_groups = group_columns(structure)
        #: per column group: its columns, and the pattern's entries in them (their places in the CSC data)
        self._members = [(np.flatnonzero(column_groups == g), np.flatnonzero(column_groups[self._entry_columns] == g))
                         for g in range(int(column_groups.max()) + 1 if len(column_groups) else 0)]
        self._flat = self._block_places(shared, groups)
        self._blocks_size = sum(rows * (shared + columns) for _, columns, _, rows in groups)
        self._last = None  # (x, residuals there): the solver asks for the Jacobian where it just evaluated
        self._last_jacobian = None  # (x, CSC data there)

    def _block_places(self, shared: int, groups) -> np.ndarray:
        """Per entry of the pattern: its place in the shots' dense blocks laid one after another."""
        group_of_row = np.empty(self.shape[0], dtype=np.int64)
        offsets, widths, firsts, own_columns = [], [], [], []
        offset = 0
        for g, (column, columns, row, rows) in enumerate(groups):
            group_of_row[row:row + rows] = g
            offsets.append(offset)
            widths.append(shared + columns)
            firsts.append(row)
            own_columns.append(column)
            offset += rows * (shared + columns)
        g = group_of_row[self._rows]
        offsets, widths, firsts, own_columns = (np.array(a, dtype=np.int64) for a in (offsets, widths, firsts,
                                                                                      own_columns))
        local_column = np.where(self._entry_columns < shared, self._entry_columns,
                                shared + self._entry_columns - own_columns[g])
        if np.any((local_column < 0) | (local_column >= widths[g])):
            raise ValueError("the sparsity has an entry outside its shot's block")
        return offsets[g] + (self._rows - firsts[g]) * widths[g] + local_column

    def residuals(self, free: np.ndarray) -> np.ndarray:
        """The residuals at free, kept for the Jacobian there."""
        if self._last is not None and np.array_equal(self._last[0], free):
            return self._last[1]
        r = self._residuals(free)
        self._last = (free.copy(), r)
        return r

    def _data(self, free: np.ndarray) -> np.ndarray:
        from scipy.optimize._numdiff import _adjust_scheme_to_bounds, _compute_absolute_step
        if self._last_jacobian is not None and np.array_equal(self._last_jacobian[0], free):
            return self._last_jacobian[1]
        f0 = self.residuals(free)
        h = _compute_absolute_step(None, free, f0, "2-point")
        h, _ = _adjust_scheme_to_bounds(free, h, 1, "1-sided", self.bounds[0], self.bounds[1])
        data = np.empty(len(self._rows))
        for columns, entries in self._members:
            x = free.copy()
            x[columns] += h[columns]
            dx = x - free
            df = self._residuals(x) - f0
            data[entries] = df[self._rows[entries]] / dx[self._entry_columns[entries]]
        self._last_jacobian = (free.copy(), data)
        return data

    def blocks(self, free: np.ndarray) -> np.ndarray:
        out = np.zeros(self._blocks_size)
        out[self._flat] = self._data(free)
        return out

    def matrix(self, free: np.ndarray):
        from scipy.sparse import csc_matrix
        jac = csc_matrix((self._data(free).copy(), self._rows.copy(), self._indptr.copy()), shape=self.shape)
        jac.eliminate_zeros()
        return jac


class Solution:
    """A solve's result, read as scipy's least_squares result: x, cost (1/2 sum of the loss),
    fun (the raw residuals at x), jac (the Jacobian at x scaled for the robust loss, so that J^T J
    is the Gauss-Newton Hessian of the robust cost: uncertainty.robust_jacobian), nfev and njev
    (the solver's evaluations of the residuals and of the Jacobian), status (0: out of evaluations;
    2: converged; -1: failed), success and message. fun and jac are worked out once, when first read
    (the execution-noise fit reads jac once a shot)."""

    def __init__(self, summary: dict, differences: SparseDifferences, scale: float):
        self.x = np.asarray(summary["x"], dtype=float)
        self.cost = float(summary["cost"])
        self.nfev, self.njev = int(summary["residual_evaluations"]), int(summary["jacobian_evaluations"])
        self.status = 2 if summary["converged"] else (-1 if summary["failed"] else 0)
        self.success = self.status > 0
        self.message = summary["message"]
        self._differences, self._scale = differences, scale

    @cached_property
    def fun(self) -> np.ndarray:
        return self._differences.residuals(self.x)

    @cached_property
    def jac(self):
        return uncertainty.robust_jacobian(self._differences.matrix(self.x), self.fun, self._scale)


def solve(residuals: Callable[[np.ndarray], np.ndarray], x0: np.ndarray, bounds, sparsity, shared: int,
          groups: Sequence[Tuple[int, int, int, int]], scale: float, max_evaluations: int,
          tolerance: float) -> Solution:
    """Minimises 1/2 sum of soft_l1(residuals(x)) with f_scale `scale` within `bounds` from x0.
    x = [shared, each group's own]; `groups` (column, columns, row, rows) per shot, in order;
    `sparsity` the Jacobian's pattern (rows x len(x0)); stops when a step changes the cost by less
    than `tolerance` of it, x by less than 1e-8 of its norm, or after max_evaluations."""
    differences = SparseDifferences(residuals, sparsity, bounds, shared, groups)

    def evaluate(free, jacobian):
        r = differences.residuals(free)
        return r, (differences.blocks(free) if jacobian else None)

    summary = _core.solve_arrow(evaluate, x0, bounds[0], bounds[1], shared, [list(g) for g in groups],
                                loss_scale=scale, max_evaluations=max(int(max_evaluations), 1),
                                function_tolerance=tolerance, parameter_tolerance=1e-8)
    return Solution(summary, differences, scale)
