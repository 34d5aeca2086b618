"""Linkages a second per Dask worker, for docs/scale.md: each job run serially in this
process, then as linkwright.batch runs it on a LocalCluster of 1 and of 2 worker processes
(one thread each). Run from a build:  PYTHONPATH=build/python python3 python/bench/throughput.py

An atlas cell is one linkage swept at 360 samples and its curve classified; a
path-synthesis start is one linkage fitted by Levenberg-Marquardt (hundreds of solves); a
tolerance sample is one linkage swept over the grid (361 poses here)."""

import os
import time

import distributed

import linkwright
import linkwright.batch

THESIS = linkwright.four_bar(60, 25, 70, 45, coupler_point=(35, 20))


def points():
    out = []
    for deg in (10, 60, 110, 160, 210, 260):
        row = THESIS.sweep(start_deg=deg, stop_deg=deg, samples=1)
        out.append((float(row["P_x_mm"][0]), float(row["P_y_mm"][0])))
    return out


def timed(run):
    began = time.perf_counter()
    run()
    return time.perf_counter() - began


def main():
    search = linkwright.PathSearch(points(), starts=20 * linkwright.PATH_STARTS_PER_BLOCK, seed=3)
    samples = 20_000
    grid = linkwright.Atlas(coupler=[1.5, 2.0, 2.5, 3.0, 3.5], rocker=[1.5, 2.0, 2.5, 3.0], frame=[2.0, 2.5, 3.0],
                            along=[0.0, 0.5, 1.0, 1.5, 2.0], across=[0.0, 0.5, 1.0])  # 900 cells, 360 samples
    jobs = {
        "atlas (cells of 360 samples, classified)": (grid.cells, grid.page,
                                                      lambda client: linkwright.batch.atlas(grid, client)),
        "path synthesis (starts)": (search.blocks * linkwright.PATH_STARTS_PER_BLOCK, search.run,
                                    lambda client: linkwright.batch.path_synthesis(search, client)),
        "tolerance study (linkages x 361 poses)": (
            samples, lambda: THESIS.tolerance_study(0.05, mc_samples=samples, samples=361),
            lambda client: linkwright.batch.tolerance_study(THESIS, 0.05, client, mc_samples=samples,
                                                            shard_samples=2000, samples=361)),
    }
    print(f"load average before: {os.getloadavg()[0]:.2f} on {os.cpu_count()} cores")
    for name, (count, serial, _) in jobs.items():
        print(f"{name}: serial {count / timed(serial):,.0f} a second")
    for workers in (1, 2):
        with distributed.LocalCluster(n_workers=workers, threads_per_worker=1, processes=True,
                                      dashboard_address=None) as cluster, distributed.Client(cluster) as client:
            for name, (count, _, batch) in jobs.items():
                batch(client)  # warm: workers import the module once
                seconds = timed(lambda: batch(client))
                print(f"{name}: {workers} worker(s) {count / seconds:,.0f} a second, "
                      f"{count / seconds / workers:,.0f} per worker")
    print(f"load average after: {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
