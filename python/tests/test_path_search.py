"""linkwright.PathSearch: path synthesis whole and in blocks, which merge to the same answer."""

import math
import pickle

import pytest

import linkwright

# The thesis four-bar's coupler point (35, 20) at crank angles 10, 60, ..., 260 degrees.
THESIS = linkwright.four_bar(60, 25, 70, 45, coupler_point=(35, 20))


def thesis_points(degrees):
    points = []
    for deg in degrees:
        row = THESIS.sweep(start_deg=deg, stop_deg=deg, samples=1)
        points.append((float(row["P_x_mm"][0]), float(row["P_y_mm"][0])))
    return points


POINTS = thesis_points([10, 60, 110, 160, 210, 260])


def comparable(result):
    """A result without its Linkage objects (compared through their sweeps instead)."""
    return [{k: v for k, v in c.items() if k != "linkage"} for c in result["candidates"]]


def test_the_search_finds_the_curve_and_its_distances_are_the_solvers():
    found = linkwright.PathSearch(POINTS, starts=200).run()
    assert found["starts_run"] == 200
    best = found["candidates"][0]
    assert best["worst_distance"] < 1e-6 * found["scale"]
    # Each distance is the pose solver's: sweep the returned linkage at its crank angle.
    for (x, y), deg, distance in zip(POINTS, best["crank_angles_deg"], best["distances"]):
        row = best["linkage"].sweep(start_deg=deg, stop_deg=deg, samples=1)
        assert math.hypot(row["P_x_mm"][0] - x, row["P_y_mm"][0] - y) == pytest.approx(distance, abs=1e-9)


def test_blocks_merged_in_any_order_are_the_whole_search_to_the_bit():
    search = linkwright.PathSearch(POINTS, starts=2 * linkwright.PATH_STARTS_PER_BLOCK + 30, keep=5, seed=11)
    assert search.blocks == 3
    whole = search.run()
    blocks = [pickle.loads(pickle.dumps(search.run_block(b))) for b in (2, 0, 1)]
    merged = search.merge(blocks)
    assert comparable(merged) == comparable(whole)
    assert merged["starts_run"] == whole["starts_run"]
    partial = search.merge(blocks[:2])
    assert partial["cancelled"] and not whole["cancelled"]


def test_a_search_pickles_as_the_same_search():
    search = linkwright.PathSearch(POINTS, timing_deg=[0, 50, 100, 150, 200, 250], starts=100, seed=4)
    again = pickle.loads(pickle.dumps(search))
    assert comparable(again.run()) == comparable(search.run())


@pytest.mark.parametrize("keywords, field, message", [
    ({"starts": 0}, "starts", "starts must be between 1 and 100000 (got 0)"),
    ({"keep": 0}, "keep", "keep must be between 1 and 1000 (got 0)"),
    ({"max_evaluations": 5}, "max_evaluations", "max_evaluations must be between 10 and 100000 (got 5)"),
    ({"timing_from": "crank"}, "timing_from", 'timing_from must be "start" or "frame" (got "crank")'),
    ({"timing_deg": [0, 10]}, "timing_deg", "timing must give one crank angle per point, 6 (got 2)"),
])
def test_a_bad_search_is_refused_naming_the_keyword(keywords, field, message):
    with pytest.raises(linkwright.Error) as refused:
        linkwright.PathSearch(POINTS, **keywords)
    assert refused.value.field == field
    assert str(refused.value) == message


def test_a_block_outside_the_search_is_refused():
    with pytest.raises(linkwright.Error) as refused:
        linkwright.PathSearch(POINTS, starts=100).run_block(1)
    assert refused.value.field == "block"
    assert str(refused.value) == "block must be between 0 and 0 (got 1)"
