"""The soak campaign (doc/accuracy.md, "Soak campaign") sharded over a Dask cluster.

    python3 -m cue_sim.soak --shots 200000 --seed 7 --airborne          # a LocalCluster of this machine
    python3 -m cue_sim.soak --shots 1000000 --seed 7 --address tcp://host:8786

    import cue_sim.soak
    summary = cue_sim.soak.run(seed=7, shots=200000, airborne=True)

Shot k of a seed is the same scene wherever it runs, so a campaign gives the same shots, the same
events and the same violations whatever its sharding: shard i holds shots first + i * shard ..., each a
task running cue_sim._core.soak on one core of a worker. The shards' summaries are merged (counts
summed, violation reports kept in shot order) and printed with each regime's shots per second (per
core: a regime's shots over the time its checks took). A worker that dies loses no shot: the
scheduler runs its shards again elsewhere. Violations are written as scene files into `out` on the
worker that found them.
"""
from __future__ import annotations

import argparse
import contextlib
import re
import sys
import time
from typing import Dict, Iterator, List, Optional, Tuple

#: Shots a shard holds at most by default: a few seconds to a minute of a core, so that a task's own
#: cost stays small and a lost worker loses little.
DEFAULT_SHARD = 500
#: Shards a worker gets at least by default, so that the last round leaves few cores idle.
SHARDS_PER_WORKER = 8

_COUNTS = ("shots", "events", "scanned", "at_rest", "endless")
_TALLIES = ("by_table", "by_models", "by_balls", "regime_shots", "violations")


def shards(first: int, shots: int, shard: int) -> List[Tuple[int, int]]:
    """(first shot, shots) of each shard: first .. first + shots - 1 in pieces of `shard`."""
    if shots < 1:
        raise ValueError(f"shots must be at least 1, got {shots}")
    if first < 0:
        raise ValueError(f"first must not be negative, got {first}")
    if shard < 1:
        raise ValueError(f"shard must be at least 1 shot, got {shard}")
    return [(k, min(shard, first + shots - k)) for k in range(first, first + shots, shard)]


def empty_summary() -> dict:
    out = {name: 0 for name in _COUNTS}
    out.update({name: {} for name in _TALLIES})
    out.update(regime_seconds={}, reports=[], seconds=0.0, shards=0)
    return out


def merge(total: dict, part: dict) -> dict:
    """Adds a shard's summary into `total` (in place; returned)."""
    for name in _COUNTS:
        total[name] += part[name]
    for name in _TALLIES:
        for key, count in part[name].items():
            total[name][key] = total[name].get(key, 0) + count
    for key, seconds in part["regime_seconds"].items():
        total["regime_seconds"][key] = total["regime_seconds"].get(key, 0.0) + seconds
    total["reports"].extend(part["reports"])
    total["reports"].sort(key=_shot_number)
    total["shards"] += 1
    return total


def _shot_number(report: str) -> int:
    found = re.match(r"shot (\d+)", report)
    return int(found.group(1)) if found else -1


def _run_shard(seed: int, first: int, shots: int, airborne: bool, full_scan_every: int, out: str) -> dict:
    from cue_sim import _core
    return _core.soak(seed, first, shots, airborne, 1, full_scan_every, out)


def default_shard(shots: int, workers: int) -> int:
    wanted = -(-shots // (SHARDS_PER_WORKER * max(workers, 1)))
    return max(1, min(DEFAULT_SHARD, wanted))


@contextlib.contextmanager
def _client(address: Optional[str], workers: Optional[int]) -> Iterator:
    from dask.distributed import Client, LocalCluster
    cluster = None
    if address is None:
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, dashboard_address=None)
    try:
        with Client(cluster if cluster is not None else address) as client:
            yield client
    finally:
        if cluster is not None:
            cluster.close()


def _violation_count(summary: dict) -> int:
    return sum(summary["violations"].values())


def _show(summary: dict, total: int, begin: float, show: bool) -> None:
    if not show:
        return
    rate = summary["shots"] / max(time.perf_counter() - begin, 1e-9)
    left = (total - summary["shots"]) / rate if rate > 0 else 0.0
    rates = regime_rates(summary)
    slowest = min(rates, key=rates.get) if rates else None
    regime = f", slowest regime {slowest} {rates[slowest]:,.0f}/s a core" if slowest else ""
    print(f"\rcue_sim.soak: {summary['shots']}/{total} shots ({100.0 * summary['shots'] / total:.1f} %), "
          f"{rate:,.0f} shots/s{regime}, {summary['events']} events, {_violation_count(summary)} violations, "
          f"{left:.0f} s left   ", end="", file=sys.stderr, flush=True)


def run(seed: int = 1, shots: int = 1000, first: int = 0, airborne: bool = False, shard: Optional[int] = None,
        full_scan_every: int = 4, out: str = "soak_violations", address: Optional[str] = None,
        workers: Optional[int] = None, client=None, progress: bool = True) -> dict:
    """Shots first .. first + shots - 1 of the campaign, sharded over a Dask cluster: the merged
    summary (dict: counts, tallies, regime_shots and regime_seconds, violations by kind, reports,
    seconds of wall time, shards).

    address: a scheduler's address ("tcp://host:8786"); None with no client starts a LocalCluster of
    `workers` single-threaded worker processes (None: every core) for this call.
    client: a dask.distributed.Client to use instead (left open).
    shard: shots a task; None: default_shard() for the cluster's workers.
    """
    from dask.distributed import as_completed

    if full_scan_every < 1:
        raise ValueError(f"full_scan_every must be at least 1, got {full_scan_every}")
    begin = time.perf_counter()
    own = contextlib.nullcontext(client) if client is not None else _client(address, workers)
    with own as c:
        if shard is None:
            shard = default_shard(shots, len(c.scheduler_info()["workers"]))
        pieces = shards(first, shots, int(shard))
        futures = [c.submit(_run_shard, seed, k, n, airborne, full_scan_every, out, pure=False) for k, n in pieces]
        total = empty_summary()
        for future in as_completed(futures):
            merge(total, future.result())
            _show(total, shots, begin, progress)
        if progress:
            print(file=sys.stderr)
    total["seconds"] = time.perf_counter() - begin
    return total


def regime_rates(summary: dict) -> Dict[str, float]:
    """Each regime's shots per second of one core."""
    return {name: summary["regime_shots"][name] / max(seconds, 1e-12)
            for name, seconds in summary["regime_seconds"].items()}


def report(summary: dict, seed: int, first: int, shots: int) -> str:
    lines = [f"cue_sim.soak --seed {seed} --first {first} --shots {shots}: {summary['shots']} shots in "
             f"{summary['shards']} shards, {summary['events']} events, {summary['at_rest']} at rest, "
             f"{summary['endless']} that cannot end by physics (not counted), {summary['scanned']} compared with "
             f"the full scan, {summary['seconds']:.1f} s ({summary['shots'] / max(summary['seconds'], 1e-9):,.0f} "
             f"shots/s)"]
    for name in ("by_table", "by_models", "by_balls"):
        lines.append(name.replace("by_", "") + ": " + " ".join(f"{k} {v}" for k, v in sorted(summary[name].items())))
    lines.append("shots/s of a core by regime: " + ", ".join(
        f"{k} {v:,.0f}" for k, v in sorted(regime_rates(summary).items(), key=lambda kv: kv[1])))
    lines.append(f"violations: {_violation_count(summary)}")
    lines.append("by kind: " + " ".join(f"{k} {v}" for k, v in sorted(summary["violations"].items())))
    lines.extend("  " + r for r in summary["reports"])
    return "\n".join(lines)


def main(argv: Optional[List[str]] = None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m cue_sim.soak", description=__doc__.split("\n\n")[0])
    parser.add_argument("--seed", type=int, default=1, help="the campaign's seed: shot k of a seed is always the same")
    parser.add_argument("--first", type=int, default=0, help="the first shot's number")
    parser.add_argument("--shots", type=int, default=1000, help="how many shots")
    parser.add_argument("--airborne", action="store_true", help="scenes with balls in the air too")
    parser.add_argument("--shard", type=int, default=None, help="shots a task (default: by the cluster's size)")
    parser.add_argument("--full-scan-every", type=int, default=4,
                        help="the full scan on every this many shots of more than 40 balls (all smaller ones)")
    parser.add_argument("--out", default="soak_violations", help="where violations are written as scene files")
    parser.add_argument("--address", default=None, help="a Dask scheduler (tcp://host:8786); default: a LocalCluster")
    parser.add_argument("--workers", type=int, default=None, help="LocalCluster workers (default: every core)")
    parser.add_argument("--quiet", action="store_true", help="no progress line")
    args = parser.parse_args(argv)
    try:
        summary = run(seed=args.seed, shots=args.shots, first=args.first, airborne=args.airborne, shard=args.shard,
                      full_scan_every=args.full_scan_every, out=args.out, address=args.address,
                      workers=args.workers, progress=not args.quiet)
    except ValueError as e:
        print(f"cue_sim.soak: {e}", file=sys.stderr)
        return 2
    print(report(summary, args.seed, args.first, args.shots))
    return 1 if _violation_count(summary) else 0


if __name__ == "__main__":
    sys.exit(main())
