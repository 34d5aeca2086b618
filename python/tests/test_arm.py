"""linkwright.arm: the core's arm request (kinematics/design/arm_request.h), the columns of
linkwright-cli arm to the bit, its notes as SweepWarnings with the CLI's sentences, its refusals
spelled with the keyword; and the joints checked against the arm's geometry."""

import csv
import io
import math
import subprocess
import sys
import warnings

import numpy
import pytest

import linkwright

CASES = [
    ({"example": "seed-arm"}, ["--example", "seed-arm"]),
    ({"example": "seed-arm", "elbow": "up", "samples": 7}, ["--example", "seed-arm", "--elbow", "up", "--samples", "7"]),
    # The path leaves the workspace: joint cells empty, exit 3 with the exact times.
    (
        {"arm": (0.3, 0.2), "from_point": (0.45, 0.0), "to_point": (0.0, 0.6), "speed": 1.5, "step_time": 0.02},
        ["--arm", "0.3,0.2", "--from-point", "0.45,0", "--to-point", "0,0.6", "--speed", "1.5", "--step-time", "0.02"],
    ),
    # Through the stretched-out pose: the rates masked there, a note.
    (
        {"arm": (2.0, 1.0), "from_point": (2.0, 0.0), "to_point": (4.0, 0.0), "speed": 1.0, "samples": 5, "unit": "mm"},
        ["--arm", "2,1", "--from-point", "2,0", "--to-point", "4,0", "--speed", "1", "--samples", "5", "--unit", "mm"],
    ),
]


def cli_run(cli, options):
    return subprocess.run([cli, "arm", *options], capture_output=True, text=True)


def notes_of(stderr):
    """The CLI's stderr as the notes Python warns with: one per 'linkwright-cli: ' line, the
    indented lines after it included."""
    notes = []
    for line in stderr.splitlines():
        if line.startswith("linkwright-cli: "):
            notes.append(line[len("linkwright-cli: "):])
        else:
            notes[-1] += "\n" + line
    return notes


@pytest.mark.parametrize("keywords, options", CASES)
def test_arm_gives_the_clis_columns_to_the_bit_and_its_notes(cli, keywords, options):
    done = cli_run(cli, options)
    assert done.returncode in (0, 3), done.stderr
    rows = list(csv.reader(io.StringIO(done.stdout)))
    header, body = rows[0], rows[1:]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        table = linkwright.arm(**keywords)
    assert list(table) == header
    for c, name in enumerate(header):
        column = table[name]
        assert len(column) == len(body)
        mask = numpy.ma.getmaskarray(column)
        for j, row in enumerate(body):
            assert mask[j] == (row[c] == ""), (name, j)
            # The CLI prints round-trip digits; its time column the grid's times to 12 digits
            # (0.03, not 0.029999999999999999), which Python keeps exact.
            if row[c] and name == "time_s":
                assert float(f"{column[j]:.12g}") == float(row[c]), j
            elif row[c]:
                assert column[j] == float(row[c]), (name, j)
        assert numpy.isfinite(column.data).all()
    assert [str(w.message) for w in caught] == notes_of(done.stderr)
    assert all(issubclass(w.category, linkwright.SweepWarning) for w in caught)
    assert (done.returncode == 3) == any("leaves the arm's workspace" in str(w.message) for w in caught)


def test_arm_joints_close_the_arms_geometry():
    # Independent of the solver: the elbow is `upper` from the shoulder and `forearm` from the
    # tip, the link angles point from joint to joint, and the tip moves at the speed asked.
    upper, forearm, speed = 0.3, 0.2, 2.0
    t = linkwright.arm(example="seed-arm", samples=401)
    ex, ey = t["elbow_x_m"], t["elbow_y_m"]
    tx, ty = t["tip_x_m"], t["tip_y_m"]
    assert numpy.ma.getmaskarray(ex).sum() == 0
    assert numpy.allclose(numpy.hypot(ex, ey), upper, rtol=0, atol=1e-14)
    assert numpy.allclose(numpy.hypot(tx - ex, ty - ey), forearm, rtol=0, atol=1e-14)
    for j in range(len(ex)):
        a1 = math.degrees(math.atan2(ey[j], ex[j]))
        a2 = math.degrees(math.atan2(ty[j] - ey[j], tx[j] - ex[j]))
        assert math.remainder(t["upper_angle_deg"][j] - a1, 360) == pytest.approx(0, abs=1e-11)
        assert math.remainder(t["forearm_angle_deg"][j] - a2, 360) == pytest.approx(0, abs=1e-11)
    # The line (0.3, 0) to (0, 0.3) at 2 m/s: 401 times from 0 to its length / 2.
    assert numpy.allclose(t["time_s"], numpy.linspace(0, math.hypot(0.3, 0.3) / speed, 401), rtol=0, atol=1e-15)
    # ω by a central difference of the angle: its error, h²/6 times θ's third derivative, is
    # 1.5e-3 rad/s at 41 samples (h = 5.3 ms, measured), so about 1.5e-5 at h = 0.53 ms.
    h = t["time_s"][1] - t["time_s"][0]
    finite = numpy.radians(numpy.asarray(t["upper_angle_deg"][2:]) - numpy.asarray(t["upper_angle_deg"][:-2])) / (2 * h)
    assert numpy.allclose(finite, t["upper_omega_rad_s"][1:-1], rtol=0, atol=1e-4)


def test_arm_writes_the_clis_file(cli, tmp_path):
    subprocess.run([cli, "arm", "--example", "seed-arm", "--format", "table", "-o", str(tmp_path / "cli.txt")],
                   check=True, capture_output=True)
    linkwright.arm(example="seed-arm", output=str(tmp_path / "py.txt"), table=True)
    assert (tmp_path / "py.txt").read_bytes() == (tmp_path / "cli.txt").read_bytes()
    subprocess.run([cli, "arm", "--example", "seed-arm", "-o", str(tmp_path / "cli.csv")], check=True,
                   capture_output=True)
    linkwright.arm(example="seed-arm", output=str(tmp_path / "py.csv"))
    assert (tmp_path / "py.csv").read_bytes() == (tmp_path / "cli.csv").read_bytes()


# The peak memory a call adds, in a fresh interpreter (KB of ru_maxrss): what is measured is the
# call's, not the test session's.
GROWTH = """
import resource, sys, linkwright
linkwright.arm(example="seed-arm", samples=3)  # numpy.ma and the module loaded
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
columns = linkwright.arm(example="seed-arm", samples=int(sys.argv[1]), output=sys.argv[2])
print(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss - before, len(columns["time_s"]))
"""


def test_arm_holds_its_rows_once_and_streams_its_file(tmp_path):
    rows = 1_000_000
    done = subprocess.run([sys.executable, "-c", GROWTH, str(rows), str(tmp_path / "big.csv")], check=True,
                          capture_output=True, text=True)
    grown_kb, returned = map(int, done.stdout.split())
    assert returned == rows
    # 11 columns of a float64 and a mask byte: 99 MB. Keeping the rows, or the file's text, as
    # well (as before) takes over 300 MB more.
    arrays_kb = 11 * 9 * rows / 1024
    assert grown_kb < 1.25 * arrays_kb
    with open(tmp_path / "big.csv", newline="") as f:
        assert sum(1 for _ in f) == rows + 1


def test_arm_says_when_its_file_cannot_be_written():
    with pytest.raises(OSError, match="cannot write /dev/full: No space left on device"):
        linkwright.arm(example="seed-arm", samples=100_000, output="/dev/full")


@pytest.mark.parametrize(
    "keywords, options, field, python_says, cli_says",
    [
        ({"example": "nosuch"}, ["--example", "nosuch"], "example",
         "example: no arm example named 'nosuch' (arm has one: seed-arm)",
         "--example: no arm example named 'nosuch' (arm has one: seed-arm)"),
        ({"example": "seed-arm", "unit": "mm"}, ["--example", "seed-arm", "--unit", "mm"], "unit",
         "unit: the seed-arm example is in metres; give arm, from_point, to_point and speed without example to "
         "work in mm",
         "--unit: the seed-arm example is in metres; give --arm, --from-point, --to-point and --speed without "
         "--example to work in mm"),
        ({"example": "seed-arm", "samples": 10**7 + 1}, ["--example", "seed-arm", "--samples", "10000001"], "samples",
         "samples must be between 2 and 10000000 (got 10000001)",
         "--samples must be between 2 and 10000000 (got 10000001)"),
        ({"example": "seed-arm", "step_time": 1e-12}, ["--example", "seed-arm", "--step-time", "1e-12"], "step_time",
         "step_time is too small: it would give 2.12132e+11 rows (at most 10000000)",
         "--step-time is too small: it would give 2.12132e+11 rows (at most 10000000)"),
        ({"example": "seed-arm", "to_point": (0.3, 0.0)}, ["--example", "seed-arm", "--to-point", "0.3,0"],
         "to_point", "to_point must differ from from_point (both are (0.3, 0))",
         "--to-point must differ from --from-point (both are (0.3, 0))"),
        ({"example": "seed-arm", "speed": 1e-300}, ["--example", "seed-arm", "--speed", "1e-300"], "speed",
         "speed is too slow: the path of 0.424264 m would take 4.24264e+299 s, beyond 1e+06 s (the speed must be at "
         "least 4.24264e-07 m/s)",
         "--speed is too slow: the path of 0.424264 m would take 4.24264e+299 s, beyond 1e+06 s (the speed must be "
         "at least 4.24264e-07 m/s)"),
        ({"example": "seed-arm", "unit": "m2"}, None, "unit",
         "unit must be a unit name made of letters, e.g. mm, m, in (got 'm2')", None),
        ({"example": "seed-arm", "samples": 1}, None, "samples", "samples must be between 2 and 10000000 (got 1)", None),
    ],
)
def test_arm_refuses_as_the_cli_does_naming_the_keyword(cli, tmp_path, keywords, options, field, python_says,
                                                        cli_says):
    with pytest.raises(linkwright.Error) as refusal:
        linkwright.arm(output=str(tmp_path / "x.csv"), **keywords)
    assert refusal.value.field == field
    assert str(refusal.value) == python_says
    assert list(tmp_path.iterdir()) == []
    if options is not None:
        done = cli_run(cli, options)
        assert done.returncode == 2
        assert done.stderr == "linkwright-cli: " + cli_says + "\n"


def test_arm_refuses_an_elbow_it_does_not_know():
    with pytest.raises(linkwright.Error, match="elbow must be 'up' or 'down'") as refusal:
        linkwright.arm(example="seed-arm", elbow="sideways")
    assert refusal.value.field == "elbow"
