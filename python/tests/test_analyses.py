"""Forces, extremes and the tolerance study from Python, against the CLI and against the sweep."""

import json
import subprocess

import numpy
import pytest

import linkwright

def examples_with_masses():
    names = []
    for name in linkwright.examples():
        try:
            linkwright.example(name).sweep(samples=2, forces=True)
        except linkwright.Error as refusal:
            assert refusal.field == "forces"
            continue
        names.append(name)
    return names


def test_forces_csv_is_analyze_forces_byte_for_byte(cli):
    names = examples_with_masses()
    assert "funsho-fourbar" in names
    for name in names:
        run = subprocess.run([cli, "analyze", "--example", name, "--forces"], capture_output=True, check=False)
        assert run.returncode in (0, 3), run.stderr.decode()
        assert linkwright.example(name).sweep_csv(forces=True) == run.stdout.decode("utf-8"), name


def test_force_columns_follow_the_kinematic_ones_and_hold_the_clis_numbers(cli):
    funsho = linkwright.example("funsho-fourbar")
    table = funsho.sweep(forces=True, start_deg=0, stop_deg=360, samples=13)
    names = list(table)
    kinematic = list(funsho.sweep(start_deg=0, stop_deg=360, samples=13))
    assert names[:len(kinematic)] == kinematic
    assert {"F_O2_N", "T_drive_Nm", "T_drive_virtual_work_Nm", "shaking_N"} <= set(names[len(kinematic):])
    # Newton-Euler and virtual work agree to round-off at every row: two methods.
    difference = table["T_drive_Nm"] - table["T_drive_virtual_work_Nm"]
    assert numpy.ma.max(abs(difference)) < 1e-9 * numpy.ma.max(abs(table["T_drive_Nm"]))
    assert numpy.ma.max(abs(table["T_drive_Nm"])) > 0.1


def test_forces_without_masses_are_refused_naming_the_field():
    with pytest.raises(linkwright.Error) as refused:
        linkwright.example("thesis-crank-rocker").sweep(forces=True)
    assert refused.value.field == "forces"
    assert "needs masses and loads, and the example thesis-crank-rocker has none" in str(refused.value)


def test_extremes_lie_on_the_solved_curve_and_beat_the_samples():
    thesis = linkwright.example("thesis-crank-rocker")
    found = thesis.extremes(start_deg=0, stop_deg=360, samples=73)  # every 5 degrees
    fine = thesis.sweep(start_deg=0, stop_deg=360, samples=7201)    # every 0.05 degrees
    coarse = thesis.sweep(start_deg=0, stop_deg=360, samples=73)
    for column in ("rocker_omega_rad_s", "rocker_alpha_rad_s2", "coupler_angle_deg"):
        e = found[column]
        # At least as far out as every sample it refines between, and as the fine grid's.
        assert e["max"] >= coarse[column].max() and e["min"] <= coarse[column].min()
        assert e["max"] >= fine[column].max() - 1e-9 and e["min"] <= fine[column].min() + 1e-9
        # Within the fine grid's own error, (Δθ)²·|f''|/8 at most: far below the coarse grid's.
        assert e["max"] - fine[column].max() < 1e-4 * (abs(e["max"]) + 1)
        # The value at the reported angle is the solver's there (a sweep of one sample).
        at = thesis.sweep(start_deg=e["max_at_deg"], stop_deg=e["max_at_deg"], samples=1)[column][0]
        assert at == pytest.approx(e["max"], rel=1e-12, abs=1e-12)


def test_tolerance_study_is_the_clis(cli):
    thesis = linkwright.example("thesis-crank-rocker")
    ours = thesis.tolerance_study(0.05, mc_samples=50, seed=7)
    run = subprocess.run([cli, "tolerance", "--example", "thesis-crank-rocker", "--tolerance", "0.05",
                          "--mc-samples", "50", "--seed", "7", "--json"], capture_output=True, check=True)
    theirs = json.loads(run.stdout)
    assert ours["used"] == theirs["samples_in_band"] == 50
    assert ours["dimensions"] == theirs["dimensions"] or len(ours["dimensions"]) == len(theirs["dimensions"])
    for column in theirs["columns"]:
        mine = ours["columns"][column["name"]]
        assert mine["worst_deviation"] == pytest.approx(column["worst_deviation"], rel=1e-9, abs=1e-12)
        assert numpy.all(mine["low"] <= mine["nominal"] + 1e-12)
        assert numpy.all(mine["high"] >= mine["nominal"] - 1e-12)


def test_a_tolerance_study_in_shards_is_the_one_run():
    linkage = linkwright.four_bar(60, 25, 70, 45, coupler_point=(35, 20))
    whole = linkage.tolerance_study(4.0, mc_samples=90, seed=5, samples=37)
    first = linkage.tolerance_study(4.0, mc_samples=50, seed=5, first_sample=0, samples=37)
    second = linkage.tolerance_study(4.0, mc_samples=40, seed=5, first_sample=50, samples=37)
    assert whole["not_assembled"] > 0  # some samples fail at ± 4 mm: the counts are checked too
    assert first["used"] + second["used"] == whole["used"]
    assert first["not_assembled"] + second["not_assembled"] == whole["not_assembled"]
    for name, band in whole["columns"].items():
        low = numpy.ma.min(numpy.ma.stack([first["columns"][name]["low"], second["columns"][name]["low"]]), axis=0)
        high = numpy.ma.max(numpy.ma.stack([first["columns"][name]["high"], second["columns"][name]["high"]]), axis=0)
        assert numpy.array_equal(numpy.ma.getdata(low), numpy.ma.getdata(band["low"])), name
        assert numpy.array_equal(numpy.ma.getdata(high), numpy.ma.getdata(band["high"])), name


@pytest.mark.parametrize("keywords, field, message", [
    ({"mc_samples": 0}, "mc_samples", "mc_samples must be between 1 and 100000 (got 0)"),
    ({"mc_samples": -5}, "mc_samples", "mc_samples must be between 1 and 100000 (got -5)"),
    ({"first_sample": -1}, "first_sample", "first_sample must be between 0 and 9007199254740992 (got -1)"),
    ({"first_sample": 2**53 + 1}, "first_sample",
     "first_sample must be between 0 and 9007199254740992 (got 9007199254740993)"),
])
def test_a_bad_study_is_refused_naming_the_keyword(keywords, field, message):
    with pytest.raises(linkwright.Error) as refused:
        linkwright.example("thesis-crank-rocker").tolerance_study(0.05, **keywords)
    assert refused.value.field == field
    assert str(refused.value) == message


@pytest.mark.parametrize("deg", [0.0, 37.0, 135.0, 250.0])
def test_the_couplers_instant_centre_is_where_its_velocity_field_vanishes(deg):
    # A second method: I13 = B + perp(v_B)/ω3, from the sweep's velocities; and the velocity
    # ratio is ω4/ω2 from the same row.
    thesis = linkwright.example("thesis-crank-rocker")
    found = thesis.instant_centres(deg)
    assert found["bodies"][0] == "frame" and len(found["bodies"]) == 4
    row = thesis.sweep(start_deg=deg, stop_deg=deg, samples=1)
    v = numpy.array([row["B_vx_mm_s"][0], row["B_vy_mm_s"][0]])
    b = numpy.array([row["B_x_mm"][0], row["B_y_mm"][0]])
    omega3 = row["coupler_omega_rad_s"][0]
    expected = b + numpy.array([-v[1], v[0]]) / omega3
    bodies = found["bodies"]
    coupler = bodies.index("coupler") + 1
    i13 = found["centres"][f"I1{coupler}"]
    assert i13["kind"] == "finite" and i13["found_by"].startswith("Kennedy")
    assert (i13["x"], i13["y"]) == pytest.approx(tuple(expected), abs=1e-9 * 100)
    assert found["centres"]["I12"]["found_by"] == "pin O2"
    assert found["velocity_ratio"] == pytest.approx(row["rocker_omega_rad_s"][0] / row["crank_omega_rad_s"][0],
                                                    rel=1e-9)
    assert found["mechanical_advantage"] == pytest.approx(1 / found["velocity_ratio"], rel=1e-12)


def test_instant_centres_refuse_a_bad_input():
    with pytest.raises(linkwright.Error) as refused:
        linkwright.example("thesis-crank-rocker").instant_centres(float("nan"))
    assert refused.value.field == "at"
    assert "(got undefined)" in str(refused.value)


def test_a_dimensions_own_tolerance_is_the_clis(cli):
    thesis = linkwright.example("thesis-crank-rocker")
    own = {"crank length": 0.0, "coupler length": 0.5}
    ours = thesis.tolerance_study(0.05, mc_samples=50, seed=7, per_dimension=own)
    assert ours["per_dimension"] == own
    run = subprocess.run([cli, "tolerance", "--example", "thesis-crank-rocker", "--tolerance", "0.05",
                          "--tolerance-of", "crank length=0,coupler length=0.5", "--mc-samples", "50", "--seed", "7",
                          "--json"], capture_output=True, check=True)
    theirs = json.loads(run.stdout)
    for column in theirs["columns"]:
        assert ours["columns"][column["name"]]["worst_deviation"] == pytest.approx(column["worst_deviation"],
                                                                                   rel=1e-12, abs=1e-15)
    with pytest.raises(linkwright.Error) as refused:
        thesis.tolerance_study(0.05, per_dimension={"crank": 0.1})
    assert refused.value.field == "per_dimension[0]"
    assert "no dimension is named 'crank'" in str(refused.value)
