"""The closed-form synthesis problems: each result, swept, does what was asked."""

import pytest

import linkwright


def test_the_crank_rocker_swings_as_asked_with_its_time_ratio():
    found = linkwright.synthesize_crank_rocker(50, time_ratio=1.2, length=40)
    assert found["grashof"] == "crank-rocker" and not found["defects"]
    assert found["rocker"] == pytest.approx(40, rel=1e-12)
    e = found["linkage"].extremes(start_deg=0, stop_deg=360, samples=721)["rocker_angle_deg"]
    assert e["max"] - e["min"] == pytest.approx(50, abs=1e-7)
    # The slow stroke (min to max, or max to min) over the quick one is the time ratio.
    arc = (e["max_at_deg"] - e["min_at_deg"]) % 360
    assert max(arc, 360 - arc) / min(arc, 360 - arc) == pytest.approx(1.2, abs=1e-7)


def test_the_slider_crank_strokes_as_asked():
    found = linkwright.synthesize_slider_crank(100, time_ratio=1.3, rod=150)
    slider = [name for name in found["linkage"].sweep(samples=2) if name.endswith("_x_mm")]
    e = found["linkage"].extremes(start_deg=0, stop_deg=360, samples=721)
    strokes = [e[name]["max"] - e[name]["min"] for name in slider]
    assert any(s == pytest.approx(100, abs=1e-7) for s in strokes)
    assert found["far_end"] - found["near_end"] == pytest.approx(100, abs=1e-9)


def test_the_function_generator_meets_log10_at_its_precision_points():
    import math
    found = linkwright.synthesize_function("log10", x0=1, x1=10, input_start_deg=30, input_span_deg=90,
                                           output_start_deg=60, output_span_deg=90, frame=100)
    assert len(found["points"]) == 3 and found["max_error_deg"] > 0
    offsets = []
    for x in found["points"]:
        crank = 30 + 90 * (x - 1) / 9
        wanted = 60 + 90 * math.log10(x)
        row = found["linkage"].sweep(start_deg=crank, stop_deg=crank, samples=1)
        # Exact at each precision point, up to the half turn a reversed rocker adds.
        offsets.append((row["rocker_angle_deg"][0] - wanted + 90) % 180 - 90)
    assert max(abs(o) for o in offsets) < 1e-7


@pytest.mark.parametrize("call, field", [
    (lambda: linkwright.synthesize_crank_rocker(200), "swing_deg"),
    (lambda: linkwright.synthesize_crank_rocker(50, time_ratio=0.5), "time_ratio"),
    (lambda: linkwright.synthesize_crank_rocker(50, scale="coupler"), "scale"),
    (lambda: linkwright.synthesize_slider_crank(100), "rod"),
    (lambda: linkwright.synthesize_slider_crank(100, rod=150, offset=5), "rod"),
    (lambda: linkwright.synthesize_function("log10", x0=1, x1=10, input_start_deg=0, input_span_deg=90,
                                            output_start_deg=0, output_span_deg=90, count=-1), "count"),
])
def test_a_bad_problem_is_refused_naming_the_keyword(call, field):
    with pytest.raises(linkwright.Error) as refused:
        call()
    assert refused.value.field == field


def test_the_motion_generator_carries_its_coupler_through_three_poses():
    import math
    poses = [(0.0, 0.0, 0.0), (40.0, 10.0, 20.0), (70.0, 35.0, 45.0)]
    found = linkwright.synthesize_motion(poses, circle_a=(-20.0, -30.0), circle_b=(30.0, -25.0))
    assert found["error"] == 0
    linkage = found["linkage"]
    # P at each pose's crank angle is the pose's point (the pose solver's, a second method).
    for (x, y, _), deg in zip(poses, found["crank_angles_deg"]):
        row = linkage.sweep(start_deg=deg, stop_deg=deg, samples=1)
        assert math.hypot(row["P_x_mm"][0] - x, row["P_y_mm"][0] - y) < 1e-9
    with pytest.raises(linkwright.Error) as refused:
        linkwright.synthesize_motion(poses[:1], circle_a=(0, 0), circle_b=(1, 1))
    assert refused.value.field == "poses"
    with pytest.raises(linkwright.Error) as refused:
        linkwright.synthesize_motion(poses, circle_a=(0, 0), circle_b=(1, 1), centre_a=3)
    assert refused.value.field == "centre_a"
