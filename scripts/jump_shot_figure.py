#!/usr/bin/python3
"""doc/physics.md's jump-shot figure: the simulated overhead camera at five instants of a jump
shot (the sequential cue at 0.8 rad and 4 m/s from the head spot, over an 8-ball rack), each
frame's strip labelled with the cue ball's height and its radius in the image, both from the
camera's ground truth: nearer the camera, the flying ball looks larger.

  python3 scripts/jump_shot_figure.py [--out doc/jump_shot.png]

Runs the camera_snapshot program (no ROS needed); uses OpenCV to crop, label and stack.
"""
import argparse
import csv
import os
import shutil
import subprocess
import tempfile

import cv2
import numpy as np

FRAMES_MS = (1, 120, 240, 360, 440)
CROP = (640, 470, 1460, 730)  # x0, y0, x1, y1 [px] of the 1920 x 1200 image: the rack's half


def snapshot(program, ms, folder):
    image, truth = os.path.join(folder, f"{ms}.png"), os.path.join(folder, f"{ms}.csv")
    subprocess.run([program, "--rack", "eight", "--cue-model", "sequential", "--theta", "0.8", "--speed", "4",
                    "--phi", "0", "--after-ms", str(ms), "--exposure", "0", "--out", image, "--truth", truth],
                   check=True, stdout=subprocess.DEVNULL)
    with open(truth) as f:
        cue = next(row for row in csv.reader(f) if row and row[0] == "0")
    return cv2.imread(image), float(cue[3]), float(cue[7])


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--out", default=os.path.join(os.path.dirname(__file__), "..", "doc", "jump_shot.png"))
    args = parser.parse_args()
    program = shutil.which("camera_snapshot") or os.path.join(os.environ.get("CUE_SIM_DEVEL", "devel"), "lib",
                                                              "cue_sim", "camera_snapshot")
    strips = []
    with tempfile.TemporaryDirectory() as folder:
        for ms in FRAMES_MS:
            image, radius_px, z = snapshot(program, ms, folder)
            x0, y0, x1, y1 = CROP
            strip = image[y0:y1, x0:x1].copy()
            label = f"{ms if ms > 1 else 0} ms: cue ball centre {1000 * z:.0f} mm above the slate, {radius_px:.1f} px"
            cv2.putText(strip, label, (10, 24), cv2.FONT_HERSHEY_SIMPLEX, 0.6, (255, 255, 255), 1, cv2.LINE_AA)
            print(label, flush=True)
            strips.append(strip)
            strips.append(np.full((4, x1 - x0, 3), 30, np.uint8))
    cv2.imwrite(args.out, np.vstack(strips[:-1]))
    print(f"jump_shot_figure: wrote {args.out}")


if __name__ == "__main__":
    main()
