#!/usr/bin/python3
"""Searches break shots for the one that pots the most object balls (the cue ball staying up), on a
Dask cluster through cue_sim.distributed, and times the same search with the local batch.

Each shot strikes the cue ball (on the head spot behind an 8-ball rack) at a random speed in
[4, 10] m/s, heading within +-0.05 rad of the rack's apex, elevation in [0, 0.2] rad and the tip
anywhere within 0.4 radii of the ball's centre; shot i is the same whatever the chunking. Only a
score a shot (object balls potted, -1 for a scratch) comes back from the workers.

    python3 scripts/search_breaks.py                         # a million shots, a LocalCluster
    python3 scripts/search_breaks.py --shots 100000 --address tcp://scheduler:8786
    python3 scripts/search_breaks.py --shots 2000 --chunk 500 --no-local   # quick

Prints the best shot and both throughputs (shots per second, Dask's overhead against the local
batch on the same machine). After the README's build, with devel/setup.bash sourced or PYTHONPATH
at the devel space's dist-packages. With --address, every worker needs the same cue_sim importable.
"""
import argparse
import sys
import time

import numpy as np

import cue_sim
import cue_sim.distributed

SPEED = (4.0, 10.0)  # m/s
HEADING = 0.05  # rad either side of the apex
ELEVATION = 0.2  # rad at most
TIP = 0.4  # ball radii from the centre at most


def break_shots(n: int, seed: int) -> np.ndarray:
    """(n, 6) shots of the cue ball (id 0), drawn from a seeded generator."""
    rng = np.random.default_rng(seed)
    radius = TIP * np.sqrt(rng.uniform(0.0, 1.0, n))  # uniform over the disc
    angle = rng.uniform(0.0, 2.0 * np.pi, n)
    return np.column_stack([np.zeros(n), rng.uniform(*SPEED, n), rng.uniform(-HEADING, HEADING, n),
                            rng.uniform(0.0, ELEVATION, n), radius * np.cos(angle), radius * np.sin(angle)])


def score(outcome: cue_sim.Batch) -> np.ndarray:
    """Object balls potted by each shot, -1 where the cue ball (column 0) went down or the shot was
    refused. Runs on the workers: only these bytes come back."""
    potted = (outcome.pocket >= 0).sum(axis=1) - (outcome.pocket[:, 0] >= 0)
    refused = np.array([bool(e) for e in outcome.error], dtype=bool)
    return np.where((outcome.pocket[:, 0] >= 0) | refused, -1, potted).astype(np.int8)


def local_scores(engine, start, shots, chunk: int) -> np.ndarray:
    """The same search with cue_sim.batch on every core, chunk by chunk (memory stays bounded)."""
    parts = []
    for first in range(0, len(shots), chunk):
        parts.append(score(cue_sim.batch(engine, start, shots[first:first + chunk])))
        done = min(first + chunk, len(shots))
        print(f"\rlocal batch: {done}/{len(shots)} shots", end="\n" if done == len(shots) else "", file=sys.stderr,
              flush=True)
    return np.concatenate(parts)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--shots", type=int, default=1_000_000)
    parser.add_argument("--chunk", type=int, help="shots a task (default: cue_sim.distributed.default_chunk)")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--address", help="a Dask scheduler's address (default: a LocalCluster of this machine)")
    parser.add_argument("--no-local", action="store_true", help="skip the local batch's timing")
    args = parser.parse_args()
    if args.shots < 1 or (args.chunk is not None and args.chunk < 1):
        parser.error("--shots and --chunk must be at least 1")

    engine = cue_sim.Engine("7ft")
    start = engine.rack("eight", gap=1e-4, jitter=5e-5, seed=args.seed)
    shots = break_shots(args.shots, args.seed)

    from dask.distributed import Client, LocalCluster
    begin = time.perf_counter()
    cluster = None if args.address else LocalCluster(threads_per_worker=1, processes=True, dashboard_address=None)
    client = Client(args.address or cluster)
    workers = len(client.scheduler_info()["workers"])
    print(f"dask: {workers} workers at {client.scheduler.address}, up in {time.perf_counter() - begin:.1f} s",
          file=sys.stderr)
    chunk = args.chunk or cue_sim.distributed.default_chunk(len(shots), workers)
    begin = time.perf_counter()
    scores = np.concatenate(cue_sim.distributed.map_batch(score, engine, start, shots, chunk=chunk, client=client))
    dask_seconds = time.perf_counter() - begin
    client.close()
    if cluster is not None:
        cluster.close()

    best = int(np.argmax(scores))
    ball, speed, phi, theta, a, b = (float(x) for x in shots[best])
    print(f"best of {len(shots)} breaks: shot {best} pots {scores[best]} object balls: speed {speed:.3f} m/s, "
          f"phi {phi:.4f} rad, theta {theta:.3f} rad, a {a:.3f}, b {b:.3f}")
    print(f"  exactly (a break is chaotic): speed={speed!r}, phi={phi!r}, theta={theta!r}, a={a!r}, b={b!r}")
    counts = np.bincount(scores + 1, minlength=2)
    print("shots by balls potted: scratch " + str(counts[0]) + ", " +
          ", ".join(f"{k - 1}: {c}" for k, c in enumerate(counts) if k > 0 and c))
    print(f"dask ({workers} workers, chunks of {chunk}): {len(shots) / dask_seconds:,.0f} shots/s "
          f"({dask_seconds:.1f} s)")
    if args.no_local:
        return
    begin = time.perf_counter()
    local = local_scores(engine, start, shots, cue_sim.distributed.DEFAULT_CHUNK)
    local_seconds = time.perf_counter() - begin
    if not np.array_equal(local, scores):
        sys.exit("search_breaks: the local batch scored the shots differently from the cluster")
    print(f"local batch (every core): {len(shots) / local_seconds:,.0f} shots/s ({local_seconds:.1f} s); "
          f"dask takes {100 * (dask_seconds / local_seconds - 1):+.1f} % time against it (same scores)")


if __name__ == "__main__":
    main()
