#!/usr/bin/env python3
"""The calibration's demonstration (doc/calibration.md's figure): six shots played with the
mathavan2010 cushion model, observed at 60 Hz with 2 mm of noise, 1 % outliers and 5 % gaps
(cue_sim.calibrate.synthetic), written as a CSV, then fitted by the `calibrate` command under
han2005 and mathavan2010 cushions.

    /usr/bin/python3 scripts/calibration_demo.py [OUT_DIR]      (default build/calibration_demo)
"""
import pathlib
import subprocess
import sys

from cue_sim.api import Engine
from cue_sim.calibrate import save_tracks
from cue_sim.calibrate.synthetic import random_shots


def main():
    here = pathlib.Path(__file__).resolve().parent
    out = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else here.parent / "build" / "calibration_demo")
    out.mkdir(parents=True, exist_ok=True)
    truth = Engine("7ft", cushion_model="mathavan2010", mu_slide=0.22, mu_roll=0.011)
    save_tracks(out / "session.csv", random_shots(truth, 6, seed=5, outliers=0.01, gaps=0.05))
    print(f"calibration_demo: 6 shots with mu_slide 0.22, mu_roll 0.011, mathavan2010 cushions "
          f"(e_cushion_work 0.98, mu_cushion 0.14) in {out / 'session.csv'}", flush=True)
    return subprocess.call([sys.executable, str(here / "calibrate"), str(out / "session.csv"), "--fit",
                            "mu_slide,mu_roll,e_cushion,f_cushion,e_cushion_work,mu_cushion", "--cushion-models",
                            "han2005,mathavan2010", "--out", str(out / "physics_fitted.yaml"), "--figure",
                            str(out / "fit.png")])


if __name__ == "__main__":
    sys.exit(main())
