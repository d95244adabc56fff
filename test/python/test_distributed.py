"""cue_sim.distributed on a real dask.distributed LocalCluster: the local batch's results, in
order, whatever the chunking, and none lost when a worker is killed mid-batch."""
import os
import re
import signal
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import cue_sim

distributed = pytest.importorskip("dask.distributed")
import cue_sim.distributed as spread  # noqa: E402


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()


def breaks(n):
    return np.column_stack([np.zeros(n), np.full(n, 8.0), np.linspace(-0.02, 0.02, n), np.zeros((n, 3))])


def same(a, b):
    return all(np.array_equal(getattr(a, f), getattr(b, f)) for f in
               ("executed", "positions", "pocket", "motion", "events", "time_to_rest", "at_rest")) and a.error == b.error


def test_any_chunking_gives_the_local_batch_in_order(client):
    engine = cue_sim.Engine("7ft")
    start = engine.rack("nine", gap=1e-4, jitter=5e-5, seed=3)
    shots = breaks(101)
    local = cue_sim.batch(engine, start, shots, noise=True, seed=11)
    for chunk in (1000, 10, 7):
        assert same(spread.batch(engine, start, shots, noise=True, seed=11, chunk=chunk, client=client,
                                 progress=False), local), chunk


def chunk_states(client):
    """The scheduler's state of every chunk task of the running batch ("memory" once done)."""
    return client.run_on_scheduler(lambda dask_scheduler: [
        ts.state for key, ts in dask_scheduler.tasks.items() if str(key).startswith("_map_chunk")])


def test_a_worker_killed_mid_batch_loses_no_shot(client):
    engine = cue_sim.Engine("7ft")
    start = engine.rack("eight", gap=1e-4, jitter=5e-5, seed=1)
    shots = breaks(48000)
    local = cue_sim.batch(engine, start, shots)
    result = {}
    runner = threading.Thread(target=lambda: result.update(
        out=spread.batch(engine, start, shots, chunk=200, client=client, progress=False)))
    runner.start()
    deadline = time.monotonic() + 60
    while True:  # some chunks done, many still to do
        states = chunk_states(client)
        if states.count("memory") >= 4 and len(states) - states.count("memory") >= 40:
            break
        assert time.monotonic() < deadline and runner.is_alive(), states
        time.sleep(0.005)
    busy = [worker for worker, keys in client.processing().items() if keys]
    assert busy
    pids = client.run(os.getpid)
    os.kill(pids[busy[0]], signal.SIGKILL)  # in the middle of a chunk
    assert runner.is_alive()
    runner.join(timeout=300)
    assert not runner.is_alive()
    assert same(result["out"], local)
    assert client.run(os.getpid)  # the nanny brought a worker back


def test_the_break_search_example_runs_small():
    script = os.path.join(os.path.dirname(__file__), "..", "..", "scripts", "search_breaks.py")
    out = subprocess.run([sys.executable, script, "--shots", "3000"], capture_output=True, text=True, timeout=300)
    assert out.returncode == 0, out.stderr[-3000:]
    assert re.search(r"best of 3000 breaks: shot \d+ pots [1-9]\d* object balls", out.stdout), out.stdout
    assert re.search(r"dask \(\d+ workers, chunks of \d+\): [\d,]+ shots/s", out.stdout), out.stdout
    assert "(same scores)" in out.stdout  # the cluster's scores are the local batch's
    assert "chunks" in out.stderr  # the progress bar


def ghost_ball_policy(obs):
    """A deterministic policy (the first ball, a pocket and a speed from the observation): picklable."""
    n = len(obs)
    pocket = (np.abs(obs[:, 0]) * 6).astype(int) % 6
    return np.column_stack([np.zeros(n), (pocket + 0.5) / 6, np.zeros(n), 1.0 + 2.0 * np.abs(obs[:, 1])])


def test_rollouts_are_one_machines_vector_environment(client):
    from cue_sim.envs import TableVectorEnv
    tables, steps = 9, 6
    local = TableVectorEnv(tables, task="pot", action="relative", max_shots=3, threads=1)
    obs, _ = local.reset(seed=21)
    rewards = []
    for _ in range(steps):
        obs, reward, terminated, truncated, info = local.step(ghost_ball_policy(obs))
        rewards.append(reward)
    for chunk in (4, 9):
        out = spread.rollouts(ghost_ball_policy, tables, steps, task="pot", seed=21, chunk=chunk, client=client,
                              progress=False, action="relative", max_shots=3)
        assert out["observations"].shape == (steps, tables, 48)
        assert out["actions"].shape == (steps, tables, 4)
        assert np.array_equal(out["rewards"], np.stack(rewards)), chunk
    assert (np.stack(rewards) != 0).any()  # the comparison saw shots that did something
