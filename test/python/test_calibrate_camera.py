"""cue_sim.calibrate end to end through the simulated camera: coefficients drawn at random in a
lab's ranges, shots played with them (cushion and ball-ball contacts), filmed at 30, 60 and 120 Hz
with sensor noise and motion blur, the balls found by the example detector and followed into tracks,
then fitted: every coefficient (the sliding and rolling friction, the ball-ball restitution and the
cushion's) comes back within two standard errors and within 5 %, and the cushion model the shots
were made with (mathavan2010) is the one the fit prefers. Nothing of the simulation
reaches the fit but the pixels. scripts/calibration_coverage.py --camera runs it over many draws."""
import numpy as np
import pytest

from cue_sim.api import Engine
from cue_sim.calibrate import calibrate, compare_models
from cue_sim.calibrate.film import filmed_shots
from cue_sim.calibrate.synthetic import LAB_RANGES

SHOTS = 10
CUSHION_MODEL = "mathavan2010"


#: The coefficients hidden: a lab's ranges for the cloth and the balls, and mathavan2010's own
#: restitution (it does not use e_cushion) from a dead cushion to the 0.98 Mathavan et al. fitted.
HIDDEN = dict({name: LAB_RANGES[name] for name in ("mu_slide", "mu_roll", "e_ball")}, e_cushion_work=(0.88, 0.98))


@pytest.fixture(scope="module")
def session():
    rng = np.random.default_rng(31)
    hidden = {name: float(rng.uniform(*bounds)) for name, bounds in HIDDEN.items()}
    engine = Engine("7ft", cushion_model=CUSHION_MODEL, **hidden)
    tracks = filmed_shots(engine, SHOTS, seed=int(rng.integers(2**32)), rates=(30.0, 60.0, 120.0), duration=3.0)
    return hidden, tracks


def test_the_detector_finds_the_balls_to_a_millimetre(session):
    _, tracks = session
    errors = np.concatenate([np.linalg.norm(t.positions - t.truth["positions"], axis=2)[t.seen()] for t in tracks])
    assert np.median(errors) < 0.001 and np.percentile(errors, 99) < 0.006, np.percentile(errors, [50, 99, 100])
    seen_truth = sum(int(np.isfinite(t.truth["positions"][:, :, 0]).sum()) for t in tracks)
    assert len(errors) >= 0.98 * seen_truth  # nothing on the table left unfound
    rates = sorted({round(1 / np.median(np.diff(t.times))) for t in tracks})
    assert rates == [30, 60, 120]
    assert sum(t.truth["ball_ball"] > 0 for t in tracks) >= SHOTS // 2
    assert sum(t.truth["cushion"] > 0 for t in tracks) >= SHOTS // 2


def test_hidden_coefficients_come_back_from_the_pixels(session):
    hidden, tracks = session
    result = calibrate(tracks, fit=list(hidden), cushion_model=CUSHION_MODEL, noise=0.002)
    assert result.success and not result.warnings, result.summary()
    print(result.summary())
    for name, value in hidden.items():
        fitted, error = result.values[name], result.standard_errors[name]
        assert abs(fitted - value) <= 2 * error and abs(fitted - value) <= 0.05 * value, \
            (name, fitted, value, error, result.summary())


def test_the_cushion_model_the_shots_were_made_with_fits_best(session):
    _, tracks = session
    with_cushions = [t for t in tracks if t.truth["cushion"] > 0][:5]
    # each model with its own restitution free (e_cushion for the others, e_cushion_work for mathavan2010)
    results = compare_models(with_cushions, ["mu_slide", "mu_roll", "e_cushion", "e_cushion_work"],
                             cushion_models=["han2005", "mathavan2010", "stronge2018", "simple"], noise=0.002)
    ranking = [r.models["cushion"] for r in results]
    assert ranking[0] == CUSHION_MODEL, [(r.models["cushion"], r.cost) for r in results]
