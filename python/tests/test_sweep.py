"""The module's sweep against linkwright-cli analyze: the same bytes, the same numbers."""

import csv
import io
import subprocess
import warnings

import numpy
import pytest

import linkwright

EXAMPLES = linkwright.examples()


def analyze(cli, *args):
    # analyze exits 3 when some rows cannot be assembled, having written the others: the
    # table is compared whatever the exit status, which must be 0 or 3.
    run = subprocess.run([cli, "analyze", *args], capture_output=True, check=False)
    assert run.returncode in (0, 3), run.stderr.decode()
    return run.stdout.decode("utf-8")


def test_there_are_examples():
    assert len(EXAMPLES) >= 10
    assert "thesis-crank-rocker" in EXAMPLES


@pytest.mark.parametrize("name", EXAMPLES)
def test_sweep_csv_is_the_clis_byte_for_byte(cli, name):
    ours = linkwright.example(name).sweep_csv()
    assert ours.count("\r\n") >= 2
    assert ours == analyze(cli, "--example", name)


def test_sweep_csv_with_a_grid_and_speed_is_the_clis(cli):
    linkage = linkwright.four_bar(60, 25, 70, 45)
    ours = linkage.sweep_csv(start_deg=10, stop_deg=50, samples=9, omega=2.5, alpha=-1)
    theirs = analyze(cli, "--fourbar", "60,25,70,45", "--from", "10", "--to", "50", "--samples", "9",
                     "--omega", "2.5", "--alpha", "-1")
    assert ours == theirs
    assert linkage.sweep_csv() == analyze(cli, "--fourbar", "60,25,70,45")


def parse(text):
    rows = list(csv.reader(io.StringIO(text, newline="")))
    return rows[0], rows[1:]


@pytest.mark.parametrize("name", EXAMPLES)
def test_columns_are_the_csv_parsed_back(name):
    linkage = linkwright.example(name)
    header, rows = parse(linkage.sweep_csv())
    table = linkage.sweep()
    assert list(table) == header
    for c, column in enumerate(header):
        values = table[column]
        assert isinstance(values, numpy.ma.MaskedArray)
        assert values.dtype == numpy.float64
        assert len(values) == len(rows)
        mask = numpy.ma.getmaskarray(values)
        for j, row in enumerate(rows):
            if row[c] == "":
                assert mask[j], (column, j)
            else:
                assert not mask[j], (column, j)
                assert values.data[j] == float(row[c]), (column, j, row[c])


@pytest.mark.parametrize("name", EXAMPLES)
def test_no_nan_or_infinity_is_returned(name):
    for column, values in linkwright.example(name).sweep().items():
        assert numpy.isfinite(values.data).all(), column


def test_a_toggle_masks_the_rates_not_the_positions():
    # A change-point four-bar (S + L = P + Q) passes a toggle at 0°: its rates are undefined
    # there, its positions are not.
    with pytest.warns(linkwright.SweepWarning):
        table = linkwright.four_bar(40, 20, 40, 20).sweep(start_deg=0, stop_deg=90, samples=4)
    assert numpy.ma.getmaskarray(table["rocker_omega_rad_s"])[0]
    assert not numpy.ma.getmaskarray(table["C_x_mm"]).any()
    assert numpy.isfinite(table["rocker_omega_rad_s"].data).all()


def test_the_grid_columns_hold_the_grid_as_asked():
    table = linkwright.example("thesis-crank-rocker").sweep(start_deg=0, stop_deg=90, samples=4)
    assert table["crank_angle_deg"].tolist() == [0.0, 30.0, 60.0, 90.0]
    assert not numpy.ma.getmaskarray(table["crank_angle_deg"]).any()


def test_rows_that_cannot_be_assembled_are_left_out_with_a_warning():
    # A crank longer than frame + rocker − coupler allows: only part of the turn assembles.
    linkage = linkwright.four_bar(60, 40, 30, 45)
    with pytest.warns(linkwright.SweepWarning, match=r"cannot be assembled at \d+ of 360 requested crank angles"):
        table = linkage.sweep(start_deg=0, stop_deg=359, samples=360)
    angles = table["crank_angle_deg"]
    assert 0 < len(angles) < 360
    with pytest.warns(linkwright.SweepWarning, match="those rows are left out"):
        header, rows = parse(linkage.sweep_csv(start_deg=0, stop_deg=359, samples=360))
    assert len(rows) == len(angles)


def test_a_toggle_is_a_warning_too():
    with pytest.warns(linkwright.SweepWarning, match="toggle position at crank angle 0°"):
        linkwright.four_bar(40, 20, 40, 20).sweep(start_deg=0, stop_deg=90, samples=4)


def cli_notes(stderr):
    # analyze's notes on stderr as the module's warnings: "linkwright-cli: " (and "note: ")
    # before each, its further sentences indented on the lines beneath.
    notes = []
    for line in stderr.splitlines():
        if line.startswith("  "):
            notes[-1] += " " + line.strip()
            continue
        assert line.startswith("linkwright-cli: "), line
        text = line[len("linkwright-cli: "):]
        notes.append(text[len("note: "):] if text.startswith("note: ") else text)
    return notes


@pytest.mark.parametrize("lengths,start,stop,samples", [
    ((60, 40, 30, 45), 0, 359, 360),  # rows left out
    ((40, 20, 40, 20), 0, 90, 4),  # a toggle at 0°
    ((40, 20, 40, 20), 0, 359, 360),  # two toggles
])
def test_warnings_are_the_clis_notes_word_for_word(cli, lengths, start, stop, samples):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        linkwright.four_bar(*lengths).sweep(start_deg=start, stop_deg=stop, samples=samples)
    ours = [str(w.message) for w in caught if issubclass(w.category, linkwright.SweepWarning)]
    run = subprocess.run([cli, "analyze", "--fourbar", ",".join(str(x) for x in lengths), "--from", str(start),
                          "--to", str(stop), "--samples", str(samples)], capture_output=True, check=False)
    assert run.returncode in (0, 3), run.stderr.decode()
    assert ours
    assert ours == cli_notes(run.stderr.decode("utf-8"))


def test_rows_left_out_name_a_four_bars_exact_range():
    with pytest.warns(linkwright.SweepWarning,
                      match=r"those rows are left out\. .*It can be assembled for crank angles .* \(exact\)\.$"):
        linkwright.four_bar(60, 40, 30, 45).sweep(start_deg=0, stop_deg=359, samples=360)


def test_warnings_can_be_errors():
    with warnings.catch_warnings():
        warnings.simplefilter("error", linkwright.SweepWarning)
        with pytest.raises(linkwright.SweepWarning):
            linkwright.four_bar(40, 20, 40, 20).sweep(start_deg=0, stop_deg=90, samples=4)


def test_a_clean_sweep_warns_nothing():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        linkwright.example("thesis-crank-rocker").sweep()
