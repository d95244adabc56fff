"""The calibrate command (scripts/calibrate) as a user runs it: tracks in, progress on stderr, the
summary on stdout, a YAML the module loads; the execution noise from a CSV with its command; bad
input refused with exit status 1 and the reason, a bad command line with 2."""
import math
import os
import subprocess
import sys

import numpy as np
import yaml

from cue_sim.api import Engine
from cue_sim.calibrate import save_tracks
from cue_sim.calibrate.synthetic import random_shots, repeated_strikes

COMMAND = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "calibrate")


def run(*args):
    return subprocess.run([sys.executable, COMMAND, *map(str, args)], capture_output=True, text=True, timeout=600)


def test_a_fit_from_a_csv_writes_a_yaml_the_module_loads(tmp_path):
    truth = Engine("7ft", mu_roll=0.012)
    save_tracks(tmp_path / "shots.csv", random_shots(truth, 3, seed=2, duration=3.0))
    done = run(tmp_path / "shots.csv", "--fit", "mu_roll", "--out", tmp_path / "fitted.yaml", "--figure",
               tmp_path / "fit.png")
    assert done.returncode == 0, done.stderr
    assert "stage" in done.stderr and "simulations of the 3 shots" in done.stderr  # progress
    assert "mu_roll" in done.stdout and (tmp_path / "fit.png").stat().st_size > 10000
    fitted = yaml.safe_load((tmp_path / "fitted.yaml").read_text())
    assert abs(Engine("7ft", **fitted).params["mu_roll"] - 0.012) < 0.05 * 0.012


def test_execution_noise_from_a_csv_and_its_command(tmp_path):
    engine = Engine("7ft")
    command = {"speed": 2.0, "phi": 0.4, "theta": 0.0, "a": 0.1, "b": 0.2}
    deviations = {"speed": 0.1, "phi": math.radians(0.5), "a": 1e-3, "b": 1e-3}
    tracks = repeated_strikes(engine, [0, 1], np.array([[-0.5, -0.2], [0.3, 0.1]]), command, deviations, 6, seed=1,
                              duration=2.0)
    save_tracks(tmp_path / "repeats.csv", tracks)
    done = run(tmp_path / "repeats.csv", "--execution-noise", "--command", ",".join(f"{k}={v}" for k, v in
                                                                                     command.items()),
               "--out", tmp_path / "noise.yaml")
    assert done.returncode == 0, done.stderr
    noise = yaml.safe_load((tmp_path / "noise.yaml").read_text())["noise"]
    assert noise["enabled"] is True and noise["speed"] > 0
    missing = run(tmp_path / "repeats.csv", "--execution-noise")
    assert missing.returncode == 1 and "commanded" in missing.stderr


def test_bad_input_and_a_bad_command_line_are_refused(tmp_path):
    (tmp_path / "bad.csv").write_text("t,ball,x\n0,0,0.1\n")
    refused = run(tmp_path / "bad.csv")
    assert refused.returncode == 1 and "no column y" in refused.stderr
    save_tracks(tmp_path / "good.csv", random_shots(Engine("7ft"), 1, seed=1, duration=1.0))
    unknown = run(tmp_path / "good.csv", "--fit", "ball_radius")  # good tracks, a coefficient not fittable
    assert unknown.returncode == 1 and "fit: ball_radius" in unknown.stderr
    assert run("--no-such-flag").returncode == 2
