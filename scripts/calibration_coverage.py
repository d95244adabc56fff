#!/usr/bin/env python3
"""How often the fit's intervals cover the truth (doc/calibration.md, "Coverage"): each trial draws
hidden coefficients in a lab's ranges, plays random shots with them (cushion and ball-ball contacts
among them), observes them with a tracker's noise, outliers and gaps (cue_sim.calibrate.synthetic),
fits, and counts whether the truth lies within one and two standard errors of each fitted value.
A fit whose errors are right covers near 68 % and 95 %. With --camera the shots are filmed by the
simulated camera at 30, 60 and 120 Hz in turn (960x600, 4 ms exposure, sensor noise) and found by the
example detector (cue_sim.calibrate.film) instead: what a lab's data is like.

    /usr/bin/python3 scripts/calibration_coverage.py [--trials 40] [--shots 8] [--noise 0.002] [--also NAMES]
        [--camera]
"""
import argparse
import sys
import time

import numpy as np

from cue_sim.api import Engine
from cue_sim.calibrate import calibrate
from cue_sim.calibrate.synthetic import LAB_RANGES as HIDDEN
from cue_sim.calibrate.synthetic import random_shots


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--trials", type=int, default=40)
    parser.add_argument("--shots", type=int, default=8)
    parser.add_argument("--noise", type=float, default=0.002, help="[m] each axis")
    parser.add_argument("--outliers", type=float, default=0.01)
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--also", default="", help="more coefficients to fit, comma-separated (their truth: the "
                        "defaults), e.g. f_cushion,mu_spin for the six of the issue's timing")
    parser.add_argument("--camera", action="store_true", help="film the shots and detect the balls")
    args = parser.parse_args()
    rng = np.random.default_rng(args.seed)
    within = {name: [0, 0] for name in HIDDEN}
    relative = {name: [] for name in HIDDEN}
    seconds = []
    for trial in range(args.trials):
        hidden = {name: float(rng.uniform(*bounds)) for name, bounds in HIDDEN.items()}
        if args.camera:
            from cue_sim.calibrate.film import filmed_shots
            tracks = filmed_shots(Engine("7ft", **hidden), args.shots, seed=int(rng.integers(2**32)),
                                  rates=(30.0, 60.0, 120.0), duration=3.0)
        else:
            tracks = random_shots(Engine("7ft", **hidden), args.shots, seed=int(rng.integers(2**32)),
                                  noise=args.noise, outliers=args.outliers, gaps=0.05)
        begin = time.perf_counter()
        result = calibrate(tracks, fit=list(HIDDEN) + [n for n in args.also.split(",") if n], noise=args.noise)
        seconds.append(time.perf_counter() - begin)
        signed = {}
        for name, value in hidden.items():
            signed[name] = (result.values[name] - value) / result.standard_errors[name]
            within[name][0] += abs(signed[name]) <= 1
            within[name][1] += abs(signed[name]) <= 2
            relative[name].append(abs(result.values[name] / value - 1))
        print(f"trial {trial + 1}/{args.trials}: {seconds[-1]:.1f} s, "
              + ", ".join(f"{n} {100 * (result.values[n] / hidden[n] - 1):+.2f} % ({signed[n]:+.1f} SE)"
                          for n in HIDDEN)
              + ("" if not result.warnings else f"; warnings: {result.warnings}"), flush=True)
    observed = ("filmed at 30/60/120 Hz and detected" if args.camera else
                f"noise {1e3 * args.noise:g} mm, {100 * args.outliers:g} % outliers")
    print(f"\n{args.trials} trials of {args.shots} shots, {observed}; a fit takes {np.median(seconds):.1f} s (median)")
    print(f"{'coefficient':<12} {'within 1 SE':>12} {'within 2 SE':>12} {'median error':>13} {'largest':>9}")
    for name in HIDDEN:
        print(f"{name:<12} {100 * within[name][0] / args.trials:11.0f}% {100 * within[name][1] / args.trials:11.0f}% "
              f"{100 * np.median(relative[name]):12.2f}% {100 * np.max(relative[name]):8.2f}%")
    return 0


if __name__ == "__main__":
    sys.exit(main())
