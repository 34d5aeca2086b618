"""linkwright.batch on a real Dask cluster (a LocalCluster of 2 worker processes):
sharded jobs give exactly the serial answers, also when a worker is killed mid-run."""

import concurrent.futures
import os
import pickle
import signal
import time

import distributed  # python3-distributed: install-deps.sh installs it, so its absence fails here
import numpy
import pytest

import linkwright
import linkwright.batch

from test_atlas import SMALL, same_cell
from test_path_search import POINTS, comparable


@pytest.fixture(scope="module")
def client():
    # Worker processes, as on a real cluster: every task's arguments and results are pickled.
    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None)
    with distributed.Client(cluster) as client:
        yield client
    cluster.close()


def test_a_linkage_pickles_as_the_same_linkage():
    for name in linkwright.examples():
        linkage = linkwright.example(name)
        again = pickle.loads(pickle.dumps(linkage))
        assert again.sweep_csv() == linkage.sweep_csv(), name
        assert again.source == linkage.source and again.kind == linkage.kind
    mine = linkwright.four_bar(60, 25, 70, 45, branch="crossed", coupler_point=(35, 20), unit="in")
    assert pickle.loads(pickle.dumps(mine)).sweep_csv(omega=2) == mine.sweep_csv(omega=2)


def test_a_sharded_atlas_is_the_serial_one(client):
    grid = linkwright.Atlas(**SMALL)
    serial = grid.page()
    for per_task in (1, 5):
        sharded = linkwright.batch.atlas(grid, client, cells_per_task=per_task)
        assert len(sharded) == len(serial) == grid.cells
        for a, b in zip(sharded, serial):
            same_cell(a, b)
    # No client: the one this process made; an address: a Client of its own to that scheduler.
    for where in (None, client.scheduler_info()["address"]):
        for a, b in zip(linkwright.batch.atlas(grid, where, cells_per_task=4), serial):
            same_cell(a, b)
    filtered = linkwright.batch.atlas(grid, client, cells_per_task=3, filter="crunode")
    assert filtered
    assert [c["cell"] for c in filtered] == [c["cell"] for c in grid.page(filter="crunode")]


def test_a_sharded_path_search_is_the_serial_one(client):
    search = linkwright.PathSearch(POINTS, starts=5 * linkwright.PATH_STARTS_PER_BLOCK, keep=6, seed=8)
    serial = search.run()
    for per_task in (1, 2):
        sharded = linkwright.batch.path_synthesis(search, client, blocks_per_task=per_task)
        assert comparable(sharded) == comparable(serial)
        assert sharded["starts_run"] == serial["starts_run"] and not sharded["cancelled"]


def test_a_sharded_tolerance_study_is_the_serial_one(client):
    linkage = linkwright.four_bar(60, 25, 70, 45, coupler_point=(35, 20))
    serial = linkage.tolerance_study(4.0, mc_samples=300, seed=5, samples=37)
    sharded = linkwright.batch.tolerance_study(linkage, 4.0, client, mc_samples=300, seed=5, shard_samples=70,
                                               samples=37)
    assert serial["not_assembled"] > 0
    for count in ("used", "not_assembled", "singular", "mc_samples"):
        assert sharded[count] == serial[count]
    for name, band in serial["columns"].items():
        mine = sharded["columns"][name]
        for part in ("low", "high", "nominal"):
            assert numpy.array_equal(numpy.ma.getdata(mine[part]), numpy.ma.getdata(band[part])), (name, part)
            assert numpy.array_equal(numpy.ma.getmaskarray(mine[part]), numpy.ma.getmaskarray(band[part]))
        worst = ("worst_deviation", "worst_at", "worst_input", "worst_on_grid")
        assert [mine[key] for key in worst] == [band[key] for key in worst]


def test_a_tolerance_study_in_many_small_shards_is_the_serial_one_and_its_shards_are_made_lazily(client):
    linkage = linkwright.four_bar(60, 25, 70, 45, coupler_point=(35, 20))
    serial = linkage.tolerance_study(4.0, mc_samples=300, seed=5, samples=13)
    # 43 shards, more than are ever in flight: sent as others come back, folded in order.
    sharded = linkwright.batch.tolerance_study(linkage, 4.0, client, mc_samples=300, seed=5, shard_samples=7,
                                               samples=13)
    for count in ("used", "not_assembled", "singular", "mc_samples"):
        assert sharded[count] == serial[count]
    for name, band in serial["columns"].items():
        mine = sharded["columns"][name]
        for part in ("low", "high"):
            assert numpy.array_equal(numpy.ma.getdata(mine[part]), numpy.ma.getdata(band[part])), (name, part)
        worst = ("worst_deviation", "worst_at", "worst_input", "worst_on_grid")
        assert [mine[key] for key in worst] == [band[key] for key in worst]
    # 10**12 samples: the shards are a generator, not 10**8 argument lists made up front.
    shards = linkwright.batch._shards(10 ** 12, 10_000)
    assert next(shards) == (0, 10_000) and next(shards) == (10_000, 10_000)
    assert not isinstance(shards, (list, tuple))


@pytest.mark.parametrize("mc_samples", [2 ** 53 + 1, 10 ** 20, 2.5, True])
def test_a_tolerance_study_beyond_the_cores_samples_is_refused_naming_mc_samples(client, mc_samples):
    with pytest.raises(linkwright.Error) as refused:
        linkwright.batch.tolerance_study(linkwright.example("thesis-crank-rocker"), 0.1, client,
                                         mc_samples=mc_samples)
    assert refused.value.field == "mc_samples"
    assert str(refused.value) == (f"mc_samples must be a whole number between 1 and 9007199254740992 "
                                  f"(got {mc_samples!r})")
    assert linkwright.batch.MAX_TOLERANCE_SAMPLES == 2 ** 53


def test_a_worker_killed_mid_run_still_gives_the_serial_answer(client):
    search = linkwright.PathSearch(POINTS, starts=20 * linkwright.PATH_STARTS_PER_BLOCK, keep=6, seed=9)
    serial = search.run()
    pids = client.run(os.getpid)  # worker address -> its process
    with concurrent.futures.ThreadPoolExecutor(1) as pool:
        running = pool.submit(linkwright.batch.path_synthesis, search, client)
        # Wait until both workers are busy, then kill one as a machine dies: no goodbye.
        deadline = time.monotonic() + 60
        while not all(client.processing().get(address) for address in pids):
            assert time.monotonic() < deadline, "the workers never both got a task"
            time.sleep(0.05)
        victim = sorted(pids)[0]
        os.kill(pids[victim], signal.SIGKILL)
        assert not running.done()
        sharded = running.result(timeout=300)
    assert comparable(sharded) == comparable(serial)
    assert sharded["starts_run"] == serial["starts_run"]
    # The nanny started a fresh worker process in its place.
    assert pids[victim] not in client.run(os.getpid).values()


@pytest.mark.parametrize("call, field", [
    (lambda c: linkwright.batch.atlas(linkwright.Atlas(**SMALL), c, cells_per_task=0), "cells_per_task"),
    (lambda c: linkwright.batch.path_synthesis(linkwright.PathSearch(POINTS), c, blocks_per_task=0),
     "blocks_per_task"),
    (lambda c: linkwright.batch.tolerance_study(linkwright.example("thesis-crank-rocker"), 0.1, c, mc_samples=0),
     "mc_samples"),
    (lambda c: linkwright.batch.tolerance_study(linkwright.example("thesis-crank-rocker"), 0.1, c, mc_samples=10,
                                                shard_samples=200_000), "shard_samples"),
])
def test_a_bad_batch_request_is_refused_naming_the_keyword(client, call, field):
    with pytest.raises(linkwright.Error) as refused:
        call(client)
    assert refused.value.field == field


@pytest.mark.parametrize("call", [
    lambda c: linkwright.batch.atlas(linkwright.Atlas(**SMALL), c),
    lambda c: linkwright.batch.path_synthesis(linkwright.PathSearch(POINTS), c),
    lambda c: linkwright.batch.tolerance_study(linkwright.example("thesis-crank-rocker"), 0.1, c, mc_samples=10),
])
@pytest.mark.parametrize("not_a_client", [42, object(), ["tcp://host:8786"]])
def test_a_client_that_is_not_one_is_refused_naming_the_argument(call, not_a_client):
    with pytest.raises(TypeError, match=r"^client must be a dask\.distributed\.Client, a scheduler's address "
                                        r"\(\"tcp://host:8786\"\) or None \(got "):
        call(not_a_client)
