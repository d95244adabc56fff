"""Big batches on a Dask cluster (dask.distributed): the shots split into chunks, each chunk a
cue_sim.batch() on a worker, the results put back in order.

    import cue_sim, cue_sim.distributed
    result = cue_sim.distributed.batch(engine, start, shots, noise=True, seed=1)            # a LocalCluster
    result = cue_sim.distributed.batch(engine, start, shots, address="tcp://host:8786")     # a cluster
    scores = cue_sim.distributed.map_batch(score, engine, start, shots)   # score(Batch) on the workers

The result is identical to cue_sim.batch() on the same arguments, in order, whatever the chunking:
shot i's noise comes from seed + i alone. A worker that dies mid-batch loses no shot: the scheduler
runs its chunks again elsewhere. Each worker builds its own engine from the Engine's table, models
and coefficients (a table given as a URDF path must be at that path on every worker).
"""
from __future__ import annotations

import contextlib
import sys
import time
from typing import Any, Callable, List, Optional

import numpy as np

from cue_sim.api import Batch, Engine, State, batch as local_batch, shot_rows

#: Shots a chunk holds at most by default: about a second of breaks on one core, so that a task's
#: own cost (a few milliseconds to ship and schedule it) stays below 1 %.
DEFAULT_CHUNK = 20000
#: Chunks a worker gets at least by default, so that the last round of chunks leaves workers idle
#: for a small part of the batch (with 2 chunks a worker, a third of a batch's time could be one
#: chunk running alone).
CHUNKS_PER_WORKER = 10
#: Shots a chunk holds at least by default (unless the batch is smaller).
MIN_CHUNK = 200


def default_chunk(shots: int, workers: int) -> int:
    """The chunk size used when none is given: CHUNKS_PER_WORKER chunks a worker, within
    [MIN_CHUNK, DEFAULT_CHUNK] shots."""
    wanted = -(-shots // (CHUNKS_PER_WORKER * max(workers, 1)))
    return max(1, min(DEFAULT_CHUNK, max(MIN_CHUNK, wanted)))


def _run_chunk(engine: Engine, start: State, shots: np.ndarray, noise: bool, seed: int, threads: int) -> Batch:
    return local_batch(engine, start, shots, noise=noise, seed=seed, threads=threads)


def _join(parts) -> Batch:
    return Batch(*(np.concatenate([getattr(p, f) for p in parts]) for f in
                   ("executed", "positions", "pocket", "motion", "events", "time_to_rest", "at_rest")),
                 [e for p in parts for e in p.error])


class _Progress:
    """A text progress bar on stderr: chunks done, shots per second."""

    def __init__(self, chunks: int, shots: int, show: bool):
        self.chunks, self.shots, self.show, self.done, self.begin = chunks, shots, show, 0, time.perf_counter()

    def step(self):
        self.done += 1
        if not self.show:
            return
        width = 30
        filled = width * self.done // self.chunks
        rate = self.shots * self.done / self.chunks / max(time.perf_counter() - self.begin, 1e-9)
        print(f"\rcue_sim.distributed: [{'#' * filled}{'.' * (width - filled)}] {self.done}/{self.chunks} chunks, "
              f"{rate:,.0f} shots/s", end="" if self.done < self.chunks else "\n", file=sys.stderr, flush=True)


@contextlib.contextmanager
def _connected(address: Optional[str], client):
    """The client a call uses: `client` as it is (left open); else one to `address`, or to a
    LocalCluster of this machine's cores (one single-threaded worker process each) started for the
    call, both closed when it ends."""
    if client is not None:
        yield client
        return
    from dask.distributed import Client, LocalCluster
    cluster = None
    if address is None:
        cluster = LocalCluster(threads_per_worker=1, processes=True, dashboard_address=None)
        address = cluster
    try:
        with Client(address) as own:
            yield own
    finally:
        if cluster is not None:
            cluster.close()


def _map_chunk(fn, engine: Engine, start: State, shots: np.ndarray, noise: bool, seed: int, threads: int):
    return fn(_run_chunk(engine, start, shots, noise, seed, threads))


def map_batch(fn: Callable[[Batch], Any], engine: Engine, start: State, shots, noise: bool = False, seed: int = 0,
              chunk: Optional[int] = None, address: Optional[str] = None, client=None, threads_per_chunk: int = 1,
              progress: bool = True) -> List[Any]:
    """fn applied, on the workers, to each chunk's Batch: [fn(chunk 0), fn(chunk 1), ...] in order.

    For searches too big to bring every outcome home: fn keeps what matters (a score a shot, say)
    and only that crosses the network. Chunk k holds shots[k * chunk:(k + 1) * chunk] and its noise
    comes from seed + k * chunk onwards, as in cue_sim.batch() on the whole array. fn must be
    picklable (a module's function, or one defined in the script: Dask pickles it by value).
    Other arguments as for batch().
    """
    from dask.distributed import as_completed

    shots = shot_rows(shots)
    if chunk is not None and int(chunk) < 1:
        raise ValueError(f"chunk must be at least 1 shot, got {chunk}")
    engine.check(start)  # refused here, by name, rather than on every worker
    if len(shots) == 0:
        return []
    with _connected(address, client) as client:
        if chunk is None:
            chunk = default_chunk(len(shots), len(client.scheduler_info()["workers"]))
        chunk = int(chunk)
        # The engine (pickled as its table, models and coefficients) and the start state are small:
        # each task carries its own copy rather than depending on scattered data, which a dying
        # worker could take with it.
        futures = [client.submit(_map_chunk, fn, engine, start, shots[i:i + chunk], noise, seed + i,
                                 threads_per_chunk, pure=False) for i in range(0, len(shots), chunk)]
        bar = _Progress(len(futures), len(shots), progress)
        for _ in as_completed(futures):
            bar.step()
        return client.gather(futures)


def _whole(outcome: Batch) -> Batch:
    return outcome


def batch(engine: Engine, start: State, shots, noise: bool = False, seed: int = 0, chunk: Optional[int] = None,
          address: Optional[str] = None, client=None, threads_per_chunk: int = 1, progress: bool = True) -> Batch:
    """cue_sim.batch() spread over a Dask cluster, `chunk` shots a task; the same Batch, in order.

    address: a scheduler's address ("tcp://host:8786"); None with no client starts a LocalCluster
    of this machine's cores (one single-threaded worker process each) for this call.
    client: a dask.distributed.Client to use instead (left open).
    chunk: shots a task; None: default_chunk() for the cluster's workers.
    threads_per_chunk: the engine's threads within one task (1 suits one worker process a core).
    progress: a progress bar on stderr.
    """
    parts = map_batch(_whole, engine, start, shots, noise, seed, chunk, address, client, threads_per_chunk, progress)
    return _join(parts) if parts else local_batch(engine, start, np.zeros((0, 6)), noise=noise, seed=seed)


def _rollout_chunk(policy, engine: Engine, task: str, options: dict, first: int, tables: int, seed: int,
                   steps: int) -> dict:
    """`steps` vector steps of tables first .. first + tables - 1 (seeded seed + first + i), on one
    worker: every observation, action, reward and end."""
    from cue_sim.envs import TableVectorEnv
    envs = TableVectorEnv(tables, task=task, engine=engine, threads=1, **options)
    obs, _ = envs.reset(seed=seed + first)
    out = {"observations": [], "actions": [], "rewards": [], "terminated": [], "truncated": [], "autoreset": []}
    for _ in range(steps):
        actions = np.asarray(policy(obs), dtype=np.float64)
        out["observations"].append(obs)
        out["actions"].append(actions)
        obs, rewards, terminated, truncated, info = envs.step(actions)
        out["rewards"].append(rewards)
        out["terminated"].append(terminated)
        out["truncated"].append(truncated)
        out["autoreset"].append(info["autoreset"])
    return {key: _stack(values) for key, values in out.items()}


def _stack(values):
    if values and isinstance(values[0], dict):
        return {key: np.stack([v[key] for v in values]) for key in values[0]}
    return np.stack(values)


def _concatenate(parts, axis):
    if isinstance(parts[0], dict):
        return {key: np.concatenate([p[key] for p in parts], axis=axis) for key in parts[0]}
    return np.concatenate(parts, axis=axis)


def rollouts(policy: Callable[[Any], np.ndarray], tables: int, steps: int, task: str = "pot",
             engine: Optional[Engine] = None, seed: int = 0, chunk: Optional[int] = None, address: Optional[str] = None,
             client=None, progress: bool = True, **options) -> dict:
    """Learning rollouts on a Dask cluster: `tables` tables of `task` (cue_sim.envs.TableVectorEnv
    and its options), each stepped `steps` times with policy(observations) -> actions, `chunk`
    tables a task. Returns arrays of shape (steps, tables, ...): "observations" (what each action
    was chosen from), "actions", "rewards", "terminated", "truncated" and "autoreset".

    Table i is seeded seed + i wherever it runs, so that for a deterministic policy the result is
    one machine's TableVectorEnv(tables) stepped the same way, whatever the chunking. policy must
    be picklable, as map_batch's fn. address, client and progress as for batch().
    """
    from dask.distributed import as_completed

    if tables < 1 or steps < 1:
        raise ValueError(f"tables and steps must be at least 1, got {tables} and {steps}")
    engine = engine if engine is not None else Engine("7ft")
    with _connected(address, client) as client:
        workers = len(client.scheduler_info()["workers"])
        chunk = int(chunk) if chunk is not None else max(1, -(-tables // (CHUNKS_PER_WORKER * max(workers, 1))))
        if chunk < 1:
            raise ValueError(f"chunk must be at least 1 table, got {chunk}")
        futures = [client.submit(_rollout_chunk, policy, engine, task, options, first, min(chunk, tables - first),
                                 seed, steps, pure=False) for first in range(0, tables, chunk)]
        bar = _Progress(len(futures), tables * steps, progress)
        for _ in as_completed(futures):
            bar.step()
        parts = client.gather(futures)
        return {key: _concatenate([p[key] for p in parts], axis=1) for key in parts[0]}
