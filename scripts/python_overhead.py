#!/usr/bin/python3
"""What the Python layer adds to a batch: N 8-ball breaks (the cue ball's heading spread over
+-0.01 rad) run by cue_sim.batch(), against the engine's own time for the same shots on the same
threads without any array in or out. Prints both, per shot, and the overhead.

Usage: python3 scripts/python_overhead.py [N] [threads]   (default 20000 shots, 1 thread; after the
README's build, with devel/setup.bash sourced or PYTHONPATH at the devel space's dist-packages)
"""
import sys
import time

import numpy as np

import cue_sim


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 20000
    threads = int(sys.argv[2]) if len(sys.argv) > 2 else 1
    engine = cue_sim.Engine("7ft")
    start = engine.rack("eight", gap=1e-4, jitter=5e-5, seed=1)
    shots = np.column_stack([np.zeros(n), np.full(n, 8.0), np.linspace(-0.01, 0.01, n), np.zeros((n, 3))])
    best_engine = best_python = float("inf")
    for round_ in range(3):  # the best of three of each, alternated
        best_engine = min(best_engine, engine._engine.engine_seconds(start._arrays(), shots, threads))
        begin = time.perf_counter()
        cue_sim.batch(engine, start, shots, threads=threads)
        best_python = min(best_python, time.perf_counter() - begin)
        print(f"python_overhead: round {round_ + 1} of 3", file=sys.stderr, flush=True)
    print(f"{n} breaks on {threads} thread(s): engine {1e6 * best_engine / n:.2f} us a shot, "
          f"cue_sim.batch {1e6 * best_python / n:.2f} us a shot: the Python layer adds "
          f"{100 * (best_python / best_engine - 1):.1f} %")


if __name__ == "__main__":
    main()
