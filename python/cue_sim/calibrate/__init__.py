"""cue_sim.calibrate: the simulator fitted to a real table from observed shots.

    from cue_sim.calibrate import calibrate, load_tracks, tracks_from_bag
    tracks = load_tracks("session.csv")                 # t, ball, x, y, shot
    tracks = tracks_from_bag("session.bag")             # or a recorded session (calibration_record.launch)
    result = calibrate(tracks, fit=["mu_slide", "mu_roll", "e_cushion"])
    print(result.summary())
    open("physics_fitted.yaml", "w").write(result.to_yaml())

    noise = fit_execution_noise(repeats, params=result.params)   # a robot's repeatability test
    open("noise.yaml", "w").write(noise.to_yaml())               # the node's ~noise/*

doc/calibration.md says what it fits, how, what it assumes and where it fails.
"""
from cue_sim.calibrate.bags import tracks_from_bag
from cue_sim.calibrate.execution_noise import NoiseFit, fit_execution_noise
from cue_sim.calibrate.fit import DEFAULT_NOISE, FITTABLE, Calibration, ShotReport, calibrate, compare_models
from cue_sim.calibrate.tracks import STRIKE_FIELDS, Track, load_tracks, save_tracks

__all__ = ["calibrate", "compare_models", "Calibration", "ShotReport", "Track", "load_tracks", "save_tracks", "FITTABLE",
           "DEFAULT_NOISE", "STRIKE_FIELDS", "tracks_from_bag", "fit_execution_noise", "NoiseFit"]
