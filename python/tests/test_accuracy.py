"""linkwright.accuracy: the core's accuracy study (kinematics/design/accuracy_study.h), the rows of
linkwright-cli accuracy (its errors at full precision where the CLI prints 3 digits), and what
the study is for: refined peaks exact at any grid, peaks read off samples wrong by O(1/N²)."""

import csv
import io
import subprocess

import numpy
import pytest

import linkwright


@pytest.mark.parametrize("example", ["ls3-engine", "watt-ii"])
def test_accuracy_gives_the_clis_rows(cli, tmp_path, example):
    done = subprocess.run([cli, "accuracy", "--example", example], capture_output=True, text=True, check=True)
    rows = list(csv.reader(io.StringIO(done.stdout)))
    study = linkwright.accuracy(example=example, output=str(tmp_path / "py.csv"))
    assert list(study) == rows[0]
    body = rows[1:]
    assert len(study["method"]) == len(body)
    for j, row in enumerate(body):
        assert [study["example"][j], study["method"][j], str(study["samples_per_rev"][j])] == row[:3]
        assert study["reference"][j] == row[9]
        for c, name in enumerate(rows[0][4:9], start=4):
            assert float(f"{study[name][j]:.3g}") == float(row[c]), (name, j)
    # The file is the CLI's CSV but for the times, which are measured again.
    written = list(csv.reader(io.StringIO((tmp_path / "py.csv").read_text())))
    assert [r[:3] + r[4:] for r in written] == [r[:3] + r[4:] for r in rows]
    assert all(numpy.isfinite(study[name]).all() for name in rows[0][3:9])


def test_accuracy_measures_what_the_docs_say():
    study = linkwright.accuracy(example="miranda-fourbar")
    method, n = numpy.array(study["method"]), study["samples_per_rev"]
    worst = numpy.maximum.reduce([study[k] for k in ("omega_rel_error", "alpha_rel_error", "speed_rel_error",
                                                     "acceleration_rel_error")])
    refined = method == "refined"
    # Refined between samples, the peaks are the reference's to round-off on every grid.
    assert (worst[refined] < 1e-9).all()
    # Read off samples, a smooth peak is missed by O(h²): ten times the samples, about a
    # hundredth of the error (between 30 and 300 here, with the peak's position on the grid).
    sampled = {int(k): e for k, e in zip(n[method == "samples"], worst[method == "samples"])}
    assert 30 < sampled[360] / sampled[3600] < 300
    # Newton at tolerance 1e-14 agrees with the closed form far below the 1e-4 one.
    newton = {m: e for m, e in zip(method, worst) if m.startswith("newton-")}
    assert newton["newton-1e-14"] < 1e-9 < newton["newton-0.0001"]


def test_accuracy_refuses_an_unknown_example(tmp_path):
    with pytest.raises(linkwright.Error) as refusal:
        linkwright.accuracy(example="nosuch", output=str(tmp_path / "x.csv"))
    assert str(refusal.value) == "example: no example named 'nosuch' (see linkwright.examples())"
    assert refusal.value.field == "example"
    assert list(tmp_path.iterdir()) == []
