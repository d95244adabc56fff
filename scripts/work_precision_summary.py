#!/usr/bin/env python3
"""Prints the README's summary of a work-precision run (results.csv) as a Markdown table.

    scripts/work_precision_summary.py doc/work_precision/results.csv
"""
import csv
import sys

METHODS = [("symplectic_euler", "symplectic Euler", "h"), ("rk4", "RK4", "h"), ("dopri54", "Dormand-Prince", "tol")]


def g(x):
    return f"{float(x):.2g}"


def main(path):
    rows = list(csv.DictReader(open(path)))
    scenes = list(dict.fromkeys(r["scene"] for r in rows))
    head = ["scene", "event engine: time, largest error"] + [f"{label}: fastest within 1 mm" for _, label, _ in METHODS]
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for scene in scenes:
        mine = [r for r in rows if r["scene"] == scene]
        event = next(r for r in mine if r["method"] == "event")
        cells = [scene, f"{g(float(event['seconds']) * 1e6)} us, {g(event['max_error_m'])} m"]
        for method, _, name in METHODS:
            good = [r for r in mine if r["method"] == method and float(r["max_error_m"]) <= 1e-3]
            if good:
                best = min(good, key=lambda r: float(r["seconds"]))
                cells.append(f"{name} = {g(best['step_s_or_tolerance'])}: {g(float(best['seconds']) * 1e3)} ms")
            else:
                cells.append("never, down to the finest run")
        print("| " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "doc/work_precision/results.csv")
