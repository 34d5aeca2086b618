"""Sweeps on a motion law in time (sweep(law=...)), byte for byte analyze --law's."""

import subprocess

import pytest

import linkwright


def analyze(cli, *args):
    run = subprocess.run([cli, "analyze", *args], capture_output=True, check=False)
    assert run.returncode in (0, 3), run.stderr.decode()
    return run.stdout.decode("utf-8")


CASES = [
    ("thesis-crank-rocker", {"law": "constant", "omega": 2.0},
     ["--law", "constant", "--omega", "2"]),
    ("thesis-crank-rocker", {"law": "ramp", "ramp_time_s": 0.5, "omega": 3.0, "samples": 50},
     ["--law", "ramp", "--ramp-time", "0.5", "--omega", "3", "--samples", "50"]),
    ("thesis-crank-rocker", {"law": "cycloidal", "rise_deg": 90, "duration_s": 2, "start_deg": 30},
     ["--law", "cycloidal", "--rise", "90", "--duration", "2", "--from", "30"]),
    ("ls3-engine", {"law": "345", "rise_deg": 120, "duration_s": 0.1, "step_time_s": 0.002},
     ["--law", "345", "--rise", "120", "--duration", "0.1", "--step-time", "0.002"]),
    ("thesis-crank-rocker", {"law": "ramp", "ramp_time_s": 1, "from_time_s": 0.25, "to_time_s": 1.5, "samples": 7},
     ["--law", "ramp", "--ramp-time", "1", "--from-time", "0.25", "--to-time", "1.5", "--samples", "7"]),
]


@pytest.mark.parametrize("name, keywords, options", CASES)
def test_a_law_sweep_is_analyze_law_byte_for_byte(cli, name, keywords, options):
    ours = linkwright.example(name).sweep_csv(**keywords)
    assert ours.startswith("time_s,")
    assert ours == analyze(cli, "--example", name, *options)


def test_a_measured_table_drives_the_cylinder(cli, tmp_path):
    table = tmp_path / "cylinder.csv"
    table.write_text("time_s,actuator_length_m\n0,1.2\n1,1.3\n2,1.5\n3,1.6\n")
    boom = linkwright.example("excavator-boom")
    columns = boom.sweep(law="table", law_table=str(table), samples=4)
    assert list(columns["actuator_length_m"]) == [1.2, 1.3, 1.5, 1.6]
    assert list(columns["time_s"]) == [0.0, 1.0, 2.0, 3.0]
    assert boom.sweep_csv(law="table", law_table=str(table), samples=4) == analyze(
        cli, "--example", "excavator-boom", "--law", "table", "--law-table", str(table), "--samples", "4")


def test_the_cycloidal_rise_is_the_closed_form():
    # θ(t) = θ0 + h (t/T − sin(2πt/T)/2π): a second method for the law's own column.
    import math
    rows = linkwright.example("thesis-crank-rocker").sweep(law="cycloidal", rise_deg=90, duration_s=2, samples=21)
    for t, angle in zip(rows["time_s"], rows["crank_angle_deg"]):
        expected = 90 * (t / 2 - math.sin(2 * math.pi * t / 2) / (2 * math.pi))
        assert angle == pytest.approx(expected, abs=1e-9)


@pytest.mark.parametrize("keywords, field, message", [
    ({"law": "ramp"}, "ramp_time_s", "ramp_time_s is needed: law ramp takes it"),
    ({"law": "cycloidal", "rise_deg": 90}, "duration_s", "duration_s is needed: law cycloidal takes it"),
    ({"law": "spiral"}, "law", 'law must be one of constant, ramp, cycloidal, 345, table (got "spiral")'),
    ({"law": "constant", "rise_deg": 9}, "rise_deg", "rise_deg does not apply to law constant"),
    ({"law": "constant", "stop_deg": 90}, "stop_deg",
     "stop_deg sets the angle grid; with law the driver follows the law in time (give from_time_s, to_time_s and "
     "samples instead)"),
    ({"law": "constant", "samples": 5, "step_time_s": 0.1}, "samples", "samples and step_time_s cannot be given together"),
    ({"law": "constant", "step_time_s": -1}, "step_time_s", "step_time_s must be positive and finite (got -1)"),
    ({"law": "constant", "omega": 0}, "to_time_s",
     "to_time_s is needed: the crank does not turn, so no default end time follows"),
    ({"law": "table"}, "law_table", "law_table is needed: law table takes it"),
    ({"law": "table", "law_table": "/nonexistent/q.csv"}, "law_table", None),
])
def test_a_bad_law_is_refused_naming_the_keyword(keywords, field, message):
    with pytest.raises(linkwright.Error) as refused:
        linkwright.example("thesis-crank-rocker").sweep(**keywords)
    assert refused.value.field == field
    if message is not None:
        assert str(refused.value) == message
    else:
        assert "/nonexistent/q.csv" in str(refused.value)
