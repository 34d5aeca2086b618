"""Big jobs over Linkwright's core as Dask tasks (docs/scale.md).

Each function splits a job into shards, maps the module over them with a
dask.distributed Client and gathers the shards' results into the answer the one
serial call gives, to the last bit: an atlas's pages of cells (Atlas.page), a path
search's blocks (PathSearch.run_block) merged by PathSearch.merge, a tolerance
study's shards of samples
(Linkage.tolerance_study(first_sample=...)) combined by their lowest and highest
values. Dask schedules, retries a task whose worker died and moves the data;
nothing here does.

    >>> from dask.distributed import Client
    >>> import linkwright, linkwright.batch
    >>> client = Client()                      # a local cluster; "tcp://host:8786" for a real one
    >>> search = linkwright.PathSearch(points, starts=100_000)
    >>> best = linkwright.batch.path_synthesis(search, client)["candidates"][0]
"""

import contextlib
import itertools

import numpy

from ._linkwright import Error

__all__ = ["atlas", "path_synthesis", "tolerance_study", "MAX_TOLERANCE_SAMPLES"]


def _refuse(field, message):
    """A refusal as the module's own: linkwright.Error naming the keyword."""
    error = Error(message)
    error.field = field
    error.code = "invalid-value"
    raise error


@contextlib.contextmanager
def _client(client):
    """The Client to run on: the one given; a scheduler's address ("tcp://host:8786"),
    connected to for this call only; or None for the Client already made in this process,
    else a new local cluster (dask.distributed.Client(), a worker process per core), kept
    for the calls that follow."""
    from dask.distributed import Client, get_client  # only when a batch job runs

    if isinstance(client, str):
        with Client(client) as connected:
            yield connected
        return
    if client is None:
        try:
            client = get_client()
        except ValueError:  # no Client yet
            client = Client()
    elif not isinstance(client, Client):
        raise TypeError("client must be a dask.distributed.Client, a scheduler's address "
                        f"(\"tcp://host:8786\") or None (got {type(client).__name__} {client!r})")
    yield client


def _atlas_page(grid, first, count, filter):
    return grid.page(first, count, filter)


def atlas(grid, client=None, *, cells_per_task=100, filter=None):
    """Atlas.page()'s cells for the whole grid (filtered as page() filters), computed
    cells_per_task cells a Dask task on `client`, in cell order."""
    if cells_per_task < 1:
        _refuse("cells_per_task", f"cells_per_task must be at least 1 (got {cells_per_task})")
    with _client(client) as client:
        firsts = list(range(0, grid.cells, cells_per_task))
        counts = [min(cells_per_task, grid.cells - first) for first in firsts]
        [scattered] = client.scatter([grid], broadcast=True, hash=False)
        n = len(firsts)
        futures = client.map(_atlas_page, [scattered] * n, firsts, counts, [filter] * n, pure=True)
        return [cell for page in client.gather(futures) for cell in page]


def _run_blocks(search, blocks):
    return [search.run_block(b) for b in blocks]


def path_synthesis(search, client=None, *, blocks_per_task=1):
    """PathSearch.run()'s answer, its blocks run as Dask tasks on `client` (a Client,
    a scheduler's address, or None: see _client); blocks_per_task blocks of
    PATH_STARTS_PER_BLOCK starts each make a task."""
    if blocks_per_task < 1:
        _refuse("blocks_per_task", f"blocks_per_task must be at least 1 (got {blocks_per_task})")
    with _client(client) as client:
        shards = [list(range(first, min(first + blocks_per_task, search.blocks)))
                  for first in range(0, search.blocks, blocks_per_task)]
        [scattered] = client.scatter([search], broadcast=True, hash=False)
        futures = client.map(_run_blocks, [scattered] * len(shards), shards, pure=True)
        blocks = [block for shard in client.gather(futures) for block in shard]
        return search.merge(blocks)


def _study_shard(linkage, tolerance, first, count, seed, grid):
    return linkage.tolerance_study(tolerance, mc_samples=count, seed=seed, first_sample=first, **grid)


# The core's largest first sample (kMaxToleranceFirstSample, 2**53: exact as a double): the
# most samples a study in shards can have.
MAX_TOLERANCE_SAMPLES = 2 ** 53


def _shards(mc_samples, shard_samples):
    """(first, count) of each shard in sample order, made as they are sent, never all at once."""
    for first in range(0, mc_samples, shard_samples):
        yield first, min(shard_samples, mc_samples - first)


def _fold(whole, study):
    """The study so far and its next shard, in sample order, as one study: each band the
    lowest and highest values, the worst deviation that of the linkage whose worst on the grid
    is the largest (the earlier on a tie, as the serial run keeps its first), refined as its
    shard refined it, the counts summed."""
    if whole is None:
        return dict(study)
    whole = dict(whole)
    whole["mc_samples"] += study["mc_samples"]
    for count in ("used", "not_assembled", "singular"):
        whole[count] += study[count]
    columns = {}
    for name, mine in whole["columns"].items():
        band = study["columns"][name]
        deviation = band["worst_on_grid"]
        worst = band if deviation is not None and (mine["worst_on_grid"] is None or
                                                   deviation > mine["worst_on_grid"]) else mine
        columns[name] = {
            "nominal": mine["nominal"],
            "low": numpy.ma.min(numpy.ma.stack([mine["low"], band["low"]]), axis=0),
            "high": numpy.ma.max(numpy.ma.stack([mine["high"], band["high"]]), axis=0),
            "worst_deviation": worst["worst_deviation"],
            "worst_at": worst["worst_at"],
            "worst_input": worst["worst_input"],
            "worst_on_grid": worst["worst_on_grid"],
        }
    whole["columns"] = columns
    return whole


def tolerance_study(linkage, tolerance, client=None, *, mc_samples, seed=46, shard_samples=10_000, **grid):
    """Linkage.tolerance_study(tolerance, mc_samples=..., seed=...)'s answer for any
    number of samples up to MAX_TOLERANCE_SAMPLES (one call takes at most 100 000),
    shard_samples samples a Dask task; grid keywords as Linkage.sweep's. The shards are
    made and sent as the cluster works (twice as many in flight as it has threads) and
    folded in as they come back, so memory does not grow with mc_samples."""
    if not isinstance(mc_samples, int) or isinstance(mc_samples, bool) or \
            not 1 <= mc_samples <= MAX_TOLERANCE_SAMPLES:
        _refuse("mc_samples", f"mc_samples must be a whole number between 1 and {MAX_TOLERANCE_SAMPLES} "
                              f"(got {mc_samples!r})")
    if not 1 <= shard_samples <= 100_000:
        _refuse("shard_samples", f"shard_samples must be between 1 and 100000 (got {shard_samples})")
    from dask.distributed import as_completed  # only when a batch job runs

    with _client(client) as client:
        [scattered] = client.scatter([linkage], broadcast=True, hash=False)
        shards = enumerate(_shards(mc_samples, shard_samples))
        in_flight = 2 * max(sum(client.nthreads().values()), 1)

        index_of = {}

        def send(index_shard):
            index, (first, count) = index_shard
            future = client.submit(_study_shard, scattered, tolerance, first, count, seed, grid, pure=True)
            index_of[future.key] = index
            return future

        running = as_completed([send(s) for s in itertools.islice(shards, in_flight)])
        arrived, whole, folded = {}, None, 0
        for future in running:
            arrived[index_of.pop(future.key)] = future.result()
            future.release()
            for shard in itertools.islice(shards, 1):
                running.add(send(shard))
            while folded in arrived:  # in sample order, whatever order they arrive in
                whole = _fold(whole, arrived.pop(folded))
                folded += 1
        return whole
