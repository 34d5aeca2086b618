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
    >>> client = Client()                      # a local cluster; Client("tcp://host:8786") a real one
    >>> search = linkwright.PathSearch(points, starts=100_000)
    >>> best = linkwright.batch.path_synthesis(search, client)["candidates"][0]
"""

import numpy

__all__ = ["atlas", "path_synthesis", "tolerance_study"]


def _client(client):
    if client is not None:
        return client
    from dask.distributed import get_client  # the Client the caller made, if any

    return get_client()


def _atlas_page(grid, first, count, filter):
    return grid.page(first, count, filter)


def atlas(grid, client=None, *, cells_per_task=100, filter=None):
    """Atlas.page()'s cells for the whole grid (filtered as page() filters), computed
    cells_per_task cells a Dask task on `client`, in cell order."""
    if cells_per_task < 1:
        raise ValueError(f"cells_per_task must be at least 1 (got {cells_per_task})")
    client = _client(client)
    firsts = list(range(0, grid.cells, cells_per_task))
    counts = [min(cells_per_task, grid.cells - first) for first in firsts]
    [scattered] = client.scatter([grid], broadcast=True)
    n = len(firsts)
    futures = client.map(_atlas_page, [scattered] * n, firsts, counts, [filter] * n, pure=True)
    return [cell for page in client.gather(futures) for cell in page]


def _run_blocks(search, blocks):
    return [search.run_block(b) for b in blocks]


def path_synthesis(search, client=None, *, blocks_per_task=1):
    """PathSearch.run()'s answer, its blocks run as Dask tasks on `client`
    (default: the current dask.distributed Client); blocks_per_task blocks of
    PATH_STARTS_PER_BLOCK starts each make a task."""
    if blocks_per_task < 1:
        raise ValueError(f"blocks_per_task must be at least 1 (got {blocks_per_task})")
    client = _client(client)
    shards = [list(range(first, min(first + blocks_per_task, search.blocks)))
              for first in range(0, search.blocks, blocks_per_task)]
    [scattered] = client.scatter([search], broadcast=True)
    futures = client.map(_run_blocks, [scattered] * len(shards), shards, pure=True)
    blocks = [block for shard in client.gather(futures) for block in shard]
    return search.merge(blocks)


def _study_shard(linkage, tolerance, first, count, seed, grid):
    return linkage.tolerance_study(tolerance, mc_samples=count, seed=seed, first_sample=first, **grid)


def _combine(studies):
    """Shards of one study, in sample order, as the one study: each band the shards'
    lowest and highest values, the worst deviation the largest (the earliest on a
    tie, as the serial run keeps its first), the counts summed."""
    whole = dict(studies[0])
    whole["mc_samples"] = sum(s["mc_samples"] for s in studies)
    for count in ("used", "not_assembled", "singular"):
        whole[count] = sum(s[count] for s in studies)
    columns = {}
    for name, first in studies[0]["columns"].items():
        bands = [s["columns"][name] for s in studies]
        worst = None
        for band in bands:
            if band["worst_deviation"] is not None and (worst is None or band["worst_deviation"] > worst["worst_deviation"]):
                worst = band
        columns[name] = {
            "nominal": first["nominal"],
            "low": numpy.ma.min(numpy.ma.stack([b["low"] for b in bands]), axis=0),
            "high": numpy.ma.max(numpy.ma.stack([b["high"] for b in bands]), axis=0),
            "worst_deviation": None if worst is None else worst["worst_deviation"],
            "worst_at": None if worst is None else worst["worst_at"],
        }
    whole["columns"] = columns
    return whole


def tolerance_study(linkage, tolerance, client=None, *, mc_samples, seed=46, shard_samples=10_000, **grid):
    """Linkage.tolerance_study(tolerance, mc_samples=..., seed=...)'s answer for any
    number of samples (one call takes at most 100 000), shard_samples samples a
    Dask task; grid keywords as Linkage.sweep's."""
    if mc_samples < 1:
        raise ValueError(f"mc_samples must be at least 1 (got {mc_samples})")
    if not 1 <= shard_samples <= 100_000:
        raise ValueError(f"shard_samples must be between 1 and 100000 (got {shard_samples})")
    client = _client(client)
    firsts = list(range(0, mc_samples, shard_samples))
    counts = [min(shard_samples, mc_samples - first) for first in firsts]
    [scattered] = client.scatter([linkage], broadcast=True)
    n = len(firsts)
    futures = client.map(_study_shard, [scattered] * n, [tolerance] * n, firsts, counts, [seed] * n, [grid] * n,
                         pure=True)
    return _combine(client.gather(futures))
