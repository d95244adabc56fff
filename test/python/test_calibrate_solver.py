"""The calibration's solver (cue_sim.calibrate.solver: Ceres with each shot's unknowns eliminated)
against scipy's least_squares on the same robust problem: the same minimum, the same scaled
Jacobian for the standard errors, bounds and a budget kept. The problem: groups of decays
y = A_g exp(-k t) + c_g sharing the rate k (the shots sharing a table's coefficients), with
outliers."""
import numpy as np
import pytest
from scipy.optimize import least_squares
from scipy.sparse import lil_matrix

from cue_sim.calibrate import solver, uncertainty

RATE = 1.3
GROUPS = [(1.0, 0.2), (2.5, -0.4), (0.7, 1.1), (1.8, 0.0), (1.2, 0.5)]
TIMES = np.linspace(0, 2, 40)
NOISE = 0.01


def _data(seed=3):
    rng = np.random.default_rng(seed)
    observed = []
    for a, c in GROUPS:
        y = a * np.exp(-RATE * TIMES) + c + rng.normal(0, NOISE, TIMES.size)
        y[rng.choice(TIMES.size, 4, replace=False)] += rng.choice([-1, 1], 4) * 0.3  # outliers
        observed.append(y)
    return observed


def _problem(observed):
    """residuals(x) in noises, the Jacobian (dense), the sparsity and the groups."""
    n, m = 1 + 2 * len(GROUPS), len(GROUPS) * TIMES.size

    def residuals(x):
        return np.concatenate([(x[1 + 2 * g] * np.exp(-x[0] * TIMES) + x[2 + 2 * g] - y) / NOISE
                               for g, y in enumerate(observed)])

    def jacobian(x):
        j = np.zeros((m, n))
        for g in range(len(GROUPS)):
            rows = slice(g * TIMES.size, (g + 1) * TIMES.size)
            e = np.exp(-x[0] * TIMES)
            j[rows, 0] = -x[1 + 2 * g] * TIMES * e / NOISE
            j[rows, 1 + 2 * g] = e / NOISE
            j[rows, 2 + 2 * g] = 1 / NOISE
        return j

    sparsity = lil_matrix((m, n), dtype=int)
    groups = []
    for g in range(len(GROUPS)):
        rows = slice(g * TIMES.size, (g + 1) * TIMES.size)
        sparsity[rows, 0] = 1
        sparsity[rows, 1 + 2 * g:3 + 2 * g] = 1
        groups.append((1 + 2 * g, 2, g * TIMES.size, TIMES.size))
    return residuals, jacobian, sparsity, groups


def _start():
    return np.array([0.5] + [1.0, 0.0] * len(GROUPS))


@pytest.mark.parametrize("scale", [1.0, 3.0])
def test_the_same_minimum_as_scipy(scale):
    residuals, jacobian, sparsity, groups = _problem(_data())
    bounds = (np.full(_start().size, -np.inf), np.full(_start().size, np.inf))
    ours = solver.solve(residuals, _start(), bounds, sparsity, 1, groups, scale, 200, 1e-12)
    theirs = least_squares(residuals, _start(), jac=jacobian, loss="soft_l1", f_scale=scale, method="trf",
                           ftol=1e-14, xtol=1e-14, gtol=1e-14)
    assert ours.success, ours.message
    assert ours.cost == pytest.approx(theirs.cost, rel=1e-9)
    np.testing.assert_allclose(ours.x, theirs.x, rtol=1e-5, atol=1e-7)
    assert abs(ours.x[0] / RATE - 1) < 0.02  # and it is the truth, within the noise
    # The residuals it reports are the raw ones at its x; the cost is the soft-L1 cost of them.
    np.testing.assert_array_equal(ours.fun, residuals(ours.x))
    assert ours.cost == pytest.approx(float(np.sum(scale ** 2 * (np.sqrt(1 + (ours.fun / scale) ** 2) - 1))), rel=1e-12)


def test_the_scaled_jacobian_is_scipys():
    """What the standard errors are computed from: the Jacobian scaled for the robust loss as
    least_squares returns it, from the raw one (differenced here, analytic there)."""
    residuals, jacobian, sparsity, groups = _problem(_data())
    theirs = least_squares(residuals, _start(), jac=jacobian, loss="soft_l1", f_scale=2.0, method="trf",
                           ftol=1e-14, xtol=1e-14, gtol=1e-14)
    np.testing.assert_allclose(uncertainty.robust_jacobian(jacobian(theirs.x), theirs.fun, 2.0), theirs.jac,
                               rtol=1e-12, atol=1e-12)
    bounds = (np.full(_start().size, -np.inf), np.full(_start().size, np.inf))
    ours = solver.solve(residuals, theirs.x.copy(), bounds, sparsity, 1, groups, 2.0, 200, 1e-12)
    np.testing.assert_allclose(ours.jac.toarray(), theirs.jac, rtol=2e-5, atol=1e-6 * np.abs(theirs.jac).max())


def test_bounds_and_the_budget_are_kept():
    residuals, _, sparsity, groups = _problem(_data())
    low, high = np.full(_start().size, -np.inf), np.full(_start().size, np.inf)
    high[0] = 1.0  # the rate held below its truth
    x = solver.solve(residuals, _start(), (low, high), sparsity, 1, groups, 1.0, 200, 1e-12).x
    assert x[0] == 1.0
    free = (np.full(_start().size, -np.inf), np.full(_start().size, np.inf))
    spent = solver.solve(residuals, _start(), free, sparsity, 1, groups, 1.0, 3, 1e-15)
    assert spent.status == 0 and not spent.success and spent.nfev == 3
    assert "spent" in spent.message
    # A step out of the bounds is projected back and searched along: its iteration may take a few
    # more evaluations, and the solve stops at its end.
    spent = solver.solve(residuals, _start(), (low, high), sparsity, 1, groups, 1.0, 3, 1e-15)
    assert spent.status == 0 and 3 <= spent.nfev <= 8


def test_groups_alone():
    """With nothing shared (a shot fitted alone, the coefficients held), each group is its own
    problem: the rate as each group's own unknown."""
    observed = _data()
    m = len(GROUPS) * TIMES.size

    def residuals(x):
        return np.concatenate([(x[1 + 3 * g] * np.exp(-x[3 * g] * TIMES) + x[2 + 3 * g] - y) / NOISE
                               for g, y in enumerate(observed)])

    sparsity = lil_matrix((m, 3 * len(GROUPS)), dtype=int)
    groups = []
    for g in range(len(GROUPS)):
        sparsity[g * TIMES.size:(g + 1) * TIMES.size, 3 * g:3 * g + 3] = 1
        groups.append((3 * g, 3, g * TIMES.size, TIMES.size))
    start = np.array([0.5, 1.0, 0.0] * len(GROUPS))
    bounds = (np.full(start.size, -np.inf), np.full(start.size, np.inf))
    ours = solver.solve(residuals, start, bounds, sparsity, 0, groups, 1.0, 200, 1e-12)
    for g in range(len(GROUPS)):
        assert ours.x[3 * g] == pytest.approx(RATE, rel=0.05)
