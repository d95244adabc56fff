"""How well a fit knows what it found: the coefficients' covariance at the least-squares solution.

The problem is block-arrow shaped: every shot's residuals depend on the coefficients and on that
shot's own unknowns only. Each shot's own unknowns are profiled out of its block (its coefficient
columns and residuals projected off its own columns), which leaves what the shot says of the
coefficients whatever its own unknowns are; the coefficients' information is the sum of those over
the shots (the Schur complement of J^T J: the coefficient block of its inverse, without forming
it). Three estimates, from the Jacobian at the solution scaled for the robust loss as scipy's
least_squares scales it (robust_jacobian), so that J^T J is the Gauss-Newton Hessian of the robust
cost and J^T f its gradient:

- `gauss_newton`: s^2 H^+, right when every position's error is independent;
- `shot_sandwich`: H^+ (sum over shots of g_s g_s^T) H^+ G/(G-1), the cluster-robust covariance
  with the shots as clusters (CR1), right also when a detector errs alike through a shot;
- `shot_jackknife`: the coefficients refitted without each shot in turn, one Newton step from the
  solution (CR3, the delete-one-cluster jackknife): the sandwich's small-sample correction, larger
  when one shot carries much of what is known.

The coefficients' columns are scaled to unit norm first, so that what counts as unseen does not
depend on units; a coefficient the data does not see (no information, or only along a direction
the others leave free) gets an infinite variance.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import List, Sequence

import numpy as np

#: Singular values of J below this share of the largest count as zero (of J^T J: its square).
RANK_SHARE = 1e-8
#: A coefficient whose unit vector has more than this of its length in the free directions is unseen.
UNSEEN_SHARE = 1e-3


def _robust_weight(residuals: np.ndarray, scale: float):
    """soft_l1's first derivative and sqrt of its Gauss-Newton weight (the loss's curvature in),
    as scipy's least_squares scales residuals and Jacobian rows for it."""
    z = (residuals / scale) ** 2
    first, second = (1 + z) ** -0.5, -0.5 * (1 + z) ** -1.5 / scale ** 2
    return first, np.sqrt(np.maximum(first + 2 * second * residuals ** 2, np.finfo(float).eps))


def robust_residuals(residuals: np.ndarray, scale: float) -> np.ndarray:
    """The residuals as least_squares scales them for the soft_l1 loss of f_scale `scale`, so that
    with the Jacobian robust_jacobian gives J^T f is the robust cost's gradient."""
    first, root = _robust_weight(residuals, scale)
    return residuals * first / root


def robust_jacobian(jacobian, residuals: np.ndarray, scale: float):
    """The raw residuals' Jacobian (sparse or dense) with each row scaled as least_squares scales
    it for the soft_l1 loss, so that J^T J is the Gauss-Newton Hessian of the robust cost."""
    _, root = _robust_weight(residuals, scale)
    if hasattr(jacobian, "multiply"):
        from scipy.sparse import diags
        return (diags(root) @ jacobian).tocsc()
    return np.asarray(jacobian) * root[:, None]


@dataclass
class Profiled:
    """The coefficients' information with the shots' own unknowns profiled out, in units where
    each coefficient's column has unit norm (`scale` the norms)."""
    information: np.ndarray  # H, n x n
    per_shot: List[np.ndarray]  # H_s
    gradients: List[np.ndarray]  # g_s of the robust cost
    scale: np.ndarray
    unseen: np.ndarray  # which coefficients the data does not see


def _own_columns_out(a: np.ndarray, b: np.ndarray, f: np.ndarray):
    """`a` and `f` projected off the span of `b`'s columns."""
    if b.shape[1] == 0:
        return a, f
    q, r = np.linalg.qr(b)
    diagonal = np.abs(np.diag(r))
    q = q[:, diagonal > max(diagonal.max(initial=0.0), 1e-300) * RANK_SHARE]
    return a - q @ (q.T @ a), f - q @ (q.T @ f)


def _inverse(h: np.ndarray):
    """(H^+, which coefficients lie in H's null space)."""
    _, singular, vt = np.linalg.svd(h)
    keep = singular > max(singular[0] if len(singular) else 0.0, 1e-300) * RANK_SHARE ** 2
    unseen = np.sqrt(np.sum(vt[~keep] ** 2, axis=0)) > UNSEEN_SHARE
    return (vt[keep].T / singular[keep]) @ vt[keep], unseen


def profile(jacobian, residuals: np.ndarray, loss_scale: float, shot_rows: Sequence[int],
            shot_columns: Sequence[Sequence[int]], coefficients: int) -> Profiled:
    """The profiled information of the first `coefficients` components of x: `jacobian` and the raw
    `residuals` are a solve's (its jac and fun), `loss_scale` its f_scale; `shot_rows` each shot's
    number of residuals in order, `shot_columns` its own unknowns' columns."""
    j = jacobian.tocsr() if hasattr(jacobian, "tocsr") else np.asarray(jacobian, dtype=float)
    f = robust_residuals(residuals, loss_scale)
    blocks = []
    start = 0
    for rows, columns in zip(shot_rows, shot_columns):
        block = j[start:start + rows]
        block = block.toarray() if hasattr(block, "toarray") else block
        blocks.append((block[:, :coefficients], block[:, list(columns)], f[start:start + rows]))
        start += rows
    norms = np.sqrt(sum(np.sum(a ** 2, axis=0) for a, _, _ in blocks)) if blocks else np.zeros(coefficients)
    scale = np.where(norms > 0, norms, 1.0)
    per_shot, gradients = [], []
    for a, b, r in blocks:
        a, r = _own_columns_out(a / scale, b, r)
        per_shot.append(a.T @ a)
        gradients.append(a.T @ r)
    information = sum(per_shot) if per_shot else np.zeros((coefficients, coefficients))
    _, unseen = _inverse(information)
    return Profiled(information, per_shot, gradients, scale, unseen | (norms == 0))


def _in_units(cov: np.ndarray, profiled: Profiled) -> np.ndarray:
    cov = cov / np.outer(profiled.scale, profiled.scale)
    cov[profiled.unseen, :] = np.inf
    cov[:, profiled.unseen] = np.inf
    return cov


def gauss_newton(profiled: Profiled, cost: float, observations: int, unknowns: int) -> np.ndarray:
    """s^2 H^+, s^2 the residuals' variance per degree of freedom (the robust cost's)."""
    s2 = 2 * cost / max(observations - unknowns, 1)
    inverse, _ = _inverse(profiled.information)
    return _in_units(s2 * inverse, profiled)


def shot_sandwich(profiled: Profiled) -> np.ndarray:
    """H^+ (sum over shots of g_s g_s^T) H^+ G/(G-1)."""
    inverse, _ = _inverse(profiled.information)
    meat = sum(np.outer(g, g) for g in profiled.gradients)
    clusters = len(profiled.gradients)
    return _in_units(inverse @ meat @ inverse * clusters / max(clusters - 1, 1), profiled)


def shot_jackknife(profiled: Profiled) -> np.ndarray:
    """(G - 1)/G sum over shots of (d_s - mean d)(d_s - mean d)^T, d_s = -(H - H_s)^+ g_s the
    Newton step that takes the solution to the fit without shot s. A coefficient that some single
    shot alone determines gets an infinite variance."""
    steps = []
    unseen = profiled.unseen.copy()
    for h, g in zip(profiled.per_shot, profiled.gradients):
        inverse, alone = _inverse(profiled.information - h)
        unseen |= alone
        steps.append(-inverse @ g)
    steps = np.array(steps)
    clusters = len(steps)
    deviation = steps - steps.mean(axis=0)
    cov = (clusters - 1) / clusters * deviation.T @ deviation
    cov[unseen, :] = np.inf
    cov[:, unseen] = np.inf
    return _in_units(cov, profiled)


def shot_block(jacobian, cost: float, observations: int, rows: slice, columns: Sequence[int]) -> np.ndarray:
    """s^2 (B^T B)^+ of one shot's own unknowns (`columns`, its residuals `rows`) with nothing shared
    fitted: the shots are then independent, and this is each one's Gauss-Newton covariance."""
    j = jacobian.tocsr() if hasattr(jacobian, "tocsr") else np.asarray(jacobian, dtype=float)
    b = j[rows][:, list(columns)]
    b = b.toarray() if hasattr(b, "toarray") else b
    s2 = 2 * cost / max(observations - j.shape[1], 1)
    norms = np.linalg.norm(b, axis=0)
    scale = np.where(norms > 0, norms, 1.0)
    inverse, unseen = _inverse((b / scale).T @ (b / scale))
    cov = s2 * inverse / np.outer(scale, scale)
    unseen |= norms == 0
    cov[unseen, :] = np.inf
    cov[:, unseen] = np.inf
    return cov
