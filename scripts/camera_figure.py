#!/usr/bin/python3
"""The README's camera figure: the simulated overhead camera 300 ms into a break (the balls smeared
by the 4 ms exposure), the example detector's finds circled, and its error against the ground
truth printed (and written into the picture's corner).

  python3 scripts/camera_figure.py [--out doc/camera_detections.png] [--after-ms 300]

Runs the camera_snapshot program (no ROS needed), then cue_sim.detection.
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile

import cv2
import numpy as np
import yaml

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "python"))
from cue_sim import detection  # noqa: E402

RADIUS = 0.028575
HEIGHT = 2.4  # camera_snapshot's default: the camera over the cloth's centre [m]
# The overhead pose (table.launch's default): optical x along the table's x, y along -y, z down.
ROTATION = np.diag([1.0, -1.0, -1.0])
CALIBRATION = os.path.join(HERE, "..", "config", "camera", "overhead_1920x1200.yaml")


def calibration(path):
    """The camera matrix and distortion of a calibration file (camera_info_manager's YAML)."""
    with open(path) as f:
        c = yaml.safe_load(f)
    return np.array(c["camera_matrix"]["data"]).reshape(3, 3), np.array(c["distortion_coefficients"]["data"])


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=os.path.join(HERE, "..", "doc", "camera_detections.png"))
    parser.add_argument("--after-ms", type=float, default=300)
    parser.add_argument("--snapshot", default=os.environ.get("CUE_SIM_CAMERA_SNAPSHOT", "camera_snapshot"),
                        help="the camera_snapshot program")
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as tmp:
        image_path, truth_path = os.path.join(tmp, "camera.png"), os.path.join(tmp, "truth.csv")
        subprocess.run([args.snapshot, "--after-ms", str(args.after_ms), "--calibration", CALIBRATION, "--out",
                        image_path, "--truth", truth_path], check=True)
        image = cv2.imread(image_path)
        with open(truth_path) as f:
            truth = [row for row in csv.DictReader(f) if row["visible"] == "1"]
    K, D = calibration(CALIBRATION)
    radius = K[0, 0] * RADIUS / (HEIGHT - RADIUS)
    pixels = detection.detect_balls(image, radius)
    positions = detection.table_positions(pixels, K, D, ROTATION, np.array([0, 0, HEIGHT]), RADIUS)
    true_xy = np.array([[float(r["x"]), float(r["y"])] for r in truth])
    errors, found = detection.match(positions[:, :2], true_xy, 2 * RADIUS)
    errors_mm = 1000 * errors
    summary = (f"{int(found.sum())} of {len(truth)} balls found, {len(pixels)} detections; error mean "
               f"{errors_mm.mean():.2f} mm, max {errors_mm.max():.2f} mm")
    print("camera_figure:", summary)
    out = image.copy()
    for u, v in pixels:
        cv2.circle(out, (int(round(u)), int(round(v))), int(round(radius + 3)), (255, 255, 0), 2, cv2.LINE_AA)
    for r in truth:
        cv2.drawMarker(out, (int(round(float(r["u"]))), int(round(float(r["v"])))), (0, 0, 255), cv2.MARKER_CROSS, 10, 1)
    cv2.putText(out, "detector (cyan) against ground truth (red): " + summary, (30, 1170), cv2.FONT_HERSHEY_SIMPLEX,
                0.9, (255, 255, 255), 2, cv2.LINE_AA)
    cv2.imwrite(args.out, cv2.resize(out, (1280, 800), interpolation=cv2.INTER_AREA))
    print("camera_figure: wrote", args.out)


if __name__ == "__main__":
    main()
