"""linkwright.Atlas: the coupler-curve atlas from Python, against the CLI and the solver."""

import json
import math
import pickle
import subprocess

import numpy
import pytest

import linkwright

SMALL = dict(coupler=[2.5, 3.0], rocker=[2.5], frame=[2.0, 3.0], along=[0.0, 2.0], across=[0.0, 1.0], samples=120)


def same_cell(a, b):
    assert a.keys() == b.keys()
    for key, value in a.items():
        if isinstance(value, numpy.ndarray):
            assert numpy.array_equal(value, b[key]), key
        else:
            assert value == b[key], key


def test_the_cells_are_the_clis(cli):
    grid = linkwright.Atlas(**SMALL)
    assert grid.cells == 16
    ours = grid.page()
    run = subprocess.run([cli, "atlas", "--coupler", "2.5,3", "--rocker", "2.5", "--frame", "2,3", "--along", "0,2",
                          "--across", "0,1", "--samples", "120", "--json"], capture_output=True, check=True)
    theirs = json.loads(run.stdout)["atlas"]
    assert len(ours) == len(theirs) == 16
    for mine, cell in zip(ours, theirs):
        for key in ("cell", "coupler", "rocker", "frame", "along", "across", "branch", "class", "crank"):
            assert mine[key] == cell[key], key
        assert mine["size"] == pytest.approx(cell["size"], rel=1e-12)
        assert len(mine["cusps"]) == len(cell["cusps"]) and len(mine["crunodes"]) == len(cell["crunodes"])
        assert (mine["straight"] is None) == (cell["straight"] is None)


def test_a_cells_curve_is_its_linkages_coupler_path():
    grid = linkwright.Atlas(**SMALL)
    for cell in grid.page(0, 4):
        if cell["crank"] != "full turn":
            continue
        linkage = grid.linkage(cell["cell"])  # crank 1 mm: the curve's own units
        for k in (0, 17, 63):
            deg = float(cell["crank_deg"][k])
            row = linkage.sweep(start_deg=deg, stop_deg=deg, samples=1)
            assert math.hypot(row["P_x_mm"][0] - cell["x"][k], row["P_y_mm"][0] - cell["y"][k]) < 1e-9


def test_hoekens_linkage_is_found_by_the_straight_filter():
    grid = linkwright.Atlas(coupler=[2.5], rocker=[2.5], frame=[2.0], along=[2.0], across=[0.0])
    [cell] = grid.page(filter="straight")
    assert cell["straight"]["length"] > 3 and "straight" in cell["features"]
    assert linkwright.Atlas(coupler=[2.5], rocker=[2.5], frame=[2.0], along=[0.0], across=[0.0]).page(
        filter="straight") == []


def test_an_atlas_pickles_as_the_same_grid():
    grid = linkwright.Atlas(**SMALL)
    again = pickle.loads(pickle.dumps(grid))
    for a, b in zip(grid.page(3, 2), again.page(3, 2)):
        same_cell(a, b)


@pytest.mark.parametrize("call, field", [
    (lambda: linkwright.Atlas(coupler=[]), "coupler"),
    (lambda: linkwright.Atlas(rocker=[-1.0]), "rocker"),
    (lambda: linkwright.Atlas(samples=10), "samples"),
    (lambda: linkwright.Atlas(samples=-1), "samples"),
    (lambda: linkwright.Atlas(branch="twisted"), "branch"),
    (lambda: linkwright.Atlas(**SMALL).page(16), "first"),
    (lambda: linkwright.Atlas(**SMALL).page(0, -2), "count"),
    (lambda: linkwright.Atlas(**SMALL).page(filter="wiggly"), "filter"),
    (lambda: linkwright.Atlas(**SMALL).linkage(99), "cell"),
])
def test_a_bad_atlas_request_is_refused_naming_the_keyword(call, field):
    with pytest.raises(linkwright.Error) as refused:
        call()
    assert refused.value.field == field
