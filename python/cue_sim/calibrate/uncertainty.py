"""How well a fit knows what it found: covariances at the least-squares solution.

Three estimates, all from the Jacobian that scipy's least_squares returns (scaled for the robust
loss, so that J^T J is the Gauss-Newton Hessian of the robust cost and J^T f its gradient):

- `gauss_newton`: s^2 (J^T J)^+, right when every position's error is independent;
- `shot_sandwich`: the cluster-robust covariance with the shots as clusters (CR1), right also
  when a detector errs alike through a shot;
- `shot_jackknife`: the coefficients refitted without each shot in turn, one Newton step from the
  solution with that shot's own unknowns profiled out (CR3, the delete-one-cluster jackknife):
  the sandwich's small-sample correction, larger when one shot carries much of what is known.

The columns are scaled to unit norm first, so that what counts as unseen does not depend on units
(a spin in rad/s beside a friction coefficient); a component the data does not see (a column of
zeros, or one along a direction the others leave free) gets an infinite variance.
"""
from __future__ import annotations

from typing import List, Sequence, Tuple

import numpy as np

#: Singular values below this share of the largest count as zero: a direction the data leaves free.
RANK_SHARE = 1e-8
#: A column whose unit vector has more than this of its length in the free directions is unseen.
UNSEEN_SHARE = 1e-3


def _dense(jacobian) -> np.ndarray:
    return jacobian.toarray() if hasattr(jacobian, "toarray") else np.asarray(jacobian, dtype=float)


def _pseudo_inverse(j: np.ndarray) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """((J^T J)^+ of the unit-norm columns, the column norms, which columns are unseen)."""
    norms = np.linalg.norm(j, axis=0)
    scale = np.where(norms > 0, norms, 1.0)
    _, singular, vt = np.linalg.svd(j / scale, full_matrices=False)
    keep = singular > max(singular[0], 1e-300) * RANK_SHARE
    inverse = (vt[keep].T / singular[keep] ** 2) @ vt[keep]
    unseen = (norms == 0) | (np.sqrt(np.sum(vt[~keep] ** 2, axis=0)) > UNSEEN_SHARE)
    return inverse, scale, unseen


def _mark_unseen(cov: np.ndarray, unseen: np.ndarray) -> np.ndarray:
    cov[unseen, :] = np.inf
    cov[:, unseen] = np.inf
    return cov


def robust_residuals(residuals: np.ndarray, scale: float) -> np.ndarray:
    """The residuals as least_squares scales them for the soft_l1 loss of f_scale `scale`, so that
    with its returned Jacobian J^T f is the robust cost's gradient."""
    z = (residuals / scale) ** 2
    first, second = (1 + z) ** -0.5, -0.5 * (1 + z) ** -1.5 / scale ** 2
    weight = np.maximum(first + 2 * second * residuals ** 2, np.finfo(float).eps)
    return residuals * first / np.sqrt(weight)


def gauss_newton(jacobian, cost: float, observations: int) -> np.ndarray:
    """s^2 (J^T J)^+, s^2 the residuals' variance per degree of freedom (the robust cost's)."""
    j = _dense(jacobian)
    s2 = 2 * cost / max(observations - j.shape[1], 1)
    inverse, scale, unseen = _pseudo_inverse(j)
    return _mark_unseen(s2 * inverse / np.outer(scale, scale), unseen)


def shot_sandwich(jacobian, residuals: np.ndarray, scale: float, shot_rows: Sequence[int]) -> np.ndarray:
    """B (sum over shots of g_s g_s^T) B G / (G - 1): B the Gauss-Newton inverse, g_s a shot's
    gradient of the robust cost, G the shots. `residuals` are least_squares' raw ones, `scale` the
    loss's f_scale, `shot_rows` each shot's number of residuals, in order."""
    j = _dense(jacobian)
    f = robust_residuals(residuals, scale)
    inverse, column, unseen = _pseudo_inverse(j)
    js = j / column
    meat = np.zeros_like(inverse)
    start = 0
    for rows in shot_rows:
        g = js[start:start + rows].T @ f[start:start + rows]
        meat += np.outer(g, g)
        start += rows
    clusters = len(shot_rows)
    cov = inverse @ meat @ inverse * (clusters / max(clusters - 1, 1)) / np.outer(column, column)
    return _mark_unseen(cov, unseen)


def _profiled(a: np.ndarray, b: np.ndarray, f: np.ndarray):
    """A shot's coefficient columns `a` and residuals `f` with its own unknowns' columns `b`
    projected out: what the shot says of the coefficients whatever its own unknowns are."""
    if b.shape[1] == 0:
        return a, f
    q, r = np.linalg.qr(b)
    keep = np.abs(np.diag(r)) > max(np.abs(np.diag(r)).max(), 1e-300) * RANK_SHARE
    q = q[:, keep]
    return a - q @ (q.T @ a), f - q @ (q.T @ f)


def shot_jackknife(jacobian, residuals: np.ndarray, scale: float, shot_rows: Sequence[int],
                   shot_columns: Sequence[Sequence[int]], coefficients: int) -> np.ndarray:
    """The covariance of the first `coefficients` components of x by the delete-one-shot jackknife:
    (G - 1)/G sum over shots of (d_s - mean d)(d_s - mean d)^T, with d_s = -(H - H_s)^+ g_s the
    Newton step that takes the solution to the fit without shot s (H and g with each shot's own
    unknowns, `shot_columns`, profiled out). A coefficient that some single shot alone determines
    gets an infinite variance."""
    j = _dense(jacobian)
    f = robust_residuals(residuals, scale)
    norms = np.linalg.norm(j[:, :coefficients], axis=0)
    column = np.where(norms > 0, norms, 1.0)
    pieces: List[Tuple[np.ndarray, np.ndarray]] = []
    start = 0
    for rows, columns in zip(shot_rows, shot_columns):
        a, r = _profiled(j[start:start + rows, :coefficients] / column, j[start:start + rows, list(columns)],
                         f[start:start + rows])
        pieces.append((a.T @ a, a.T @ r))
        start += rows
    total = sum(h for h, _ in pieces)
    steps = []
    unseen = np.zeros(coefficients, dtype=bool)
    for h, g in pieces:
        _, singular, vt = np.linalg.svd(total - h)
        keep = singular > max(singular[0], 1e-300) * RANK_SHARE
        unseen |= np.sqrt(np.sum(vt[~keep] ** 2, axis=0)) > UNSEEN_SHARE
        steps.append(-(vt[keep].T / singular[keep]) @ (vt[keep] @ g))
    steps = np.array(steps)
    clusters = len(steps)
    deviation = steps - steps.mean(axis=0)
    cov = (clusters - 1) / clusters * deviation.T @ deviation / np.outer(column, column)
    return _mark_unseen(cov, unseen | (norms == 0))
