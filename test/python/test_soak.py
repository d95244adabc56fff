"""cue_sim.soak on a real dask.distributed LocalCluster: the same shots, events and tallies whatever
the sharding, equal to one process running them all; refusals name the field."""
import pytest

from cue_sim import _core

distributed = pytest.importorskip("dask.distributed")
import cue_sim.soak as soak  # noqa: E402


@pytest.fixture(scope="module")
def client():
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    with distributed.Client(cluster) as c:
        yield c
    cluster.close()


def comparable(summary):
    """What does not depend on the machine's speed or the order shards finish in."""
    keep = ("shots", "events", "scanned", "at_rest", "endless", "by_table", "by_models", "by_balls", "regime_shots",
            "violations", "reports")
    return {k: summary[k] for k in keep}


def test_the_shards_cover_the_range_once():
    assert soak.shards(5, 12, 5) == [(5, 5), (10, 5), (15, 2)]
    assert soak.shards(0, 3, 10) == [(0, 3)]
    covered = [k for first, n in soak.shards(17, 1001, 64) for k in range(first, first + n)]
    assert covered == list(range(17, 1018))


@pytest.mark.parametrize("airborne", [False, True])
def test_any_sharding_gives_one_process_campaign(client, tmp_path, airborne):
    whole = _core.soak(3, 40, 60, airborne, 1, 4, str(tmp_path))
    assert whole["shots"] == 60 and whole["events"] > 0
    assert sum(whole["regime_shots"].values()) == 60
    for shard in (60, 7, 1):
        merged = soak.run(seed=3, first=40, shots=60, airborne=airborne, shard=shard, out=str(tmp_path),
                          client=client, progress=False)
        assert merged["shards"] == len(soak.shards(40, 60, shard))
        assert comparable(merged) == comparable(whole), shard


def test_refusals_name_the_field(client):
    with pytest.raises(ValueError, match="shots"):
        soak.shards(0, 0, 10)
    with pytest.raises(ValueError, match="shard"):
        soak.run(shots=10, shard=0, client=client, progress=False)
    with pytest.raises(ValueError, match="full_scan_every"):
        soak.run(shots=10, full_scan_every=0, client=client, progress=False)
    with pytest.raises(ValueError, match="first"):
        _core.soak(1, -1, 10)


def test_the_report_prints_every_regime_rate(tmp_path):
    summary = soak.merge(soak.empty_summary(), _core.soak(9, 0, 20, False, 1, 4, str(tmp_path)))
    summary["seconds"] = 1.0
    text = soak.report(summary, 9, 0, 20)
    for regime in summary["regime_shots"]:
        assert regime in text
    assert "cannot end by physics" in text
