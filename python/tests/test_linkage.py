"""Building linkages, reading documents and classifying them."""

import glob
import os
import subprocess

import pytest

import linkwright


def test_four_bar_has_the_thesis_names():
    linkage = linkwright.four_bar(60, 25, 70, 45)
    assert linkage.points == ["O2", "O4", "B", "C"]
    assert linkage.links == ["crank", "coupler", "rocker"]
    assert linkage.length_unit == "mm"
    with_p = linkwright.four_bar(60, 25, 70, 45, unit="in", coupler_point=(35, 20))
    assert "P" in with_p.points
    assert with_p.length_unit == "in"
    assert "P_x_in" in with_p.sweep(samples=2, start_deg=0, stop_deg=10)


DOCUMENTS = sorted(glob.glob(os.path.join(os.path.dirname(__file__), "..", "..", "tests", "fuzz", "corpus",
                                           "documents", "*.linkwright")))


def test_there_are_documents():
    assert len(DOCUMENTS) >= 10


@pytest.mark.parametrize("path", DOCUMENTS, ids=os.path.basename)
def test_a_document_sweeps_as_the_cli_sweeps_it(cli, path):
    # Every document the repository keeps (a crank's grid, a motion law in time, a table law,
    # the version 1 four-bar form, linear drivers): the module's CSV is the CLI's.
    run = subprocess.run([cli, "analyze", path], capture_output=True, check=False)
    assert run.returncode in (0, 3), run.stderr.decode()
    assert linkwright.load(path).sweep_csv() == run.stdout.decode("utf-8")


def test_classify_a_crank_rocker():
    c = linkwright.example("thesis-crank-rocker").classify()
    assert c["mobility"] == 1
    assert c["grashof"]["class"] == "crank-rocker"
    assert c["grashof"]["s_plus_l"] == 95.0
    assert c["grashof"]["p_plus_q"] == 105.0
    assert c["input_fully_rotates"] is True
    assert 0 < c["transmission"]["minimum_deg"] < c["transmission"]["maximum_deg"] < 180
    assert c["quick_return"] is None


def test_classify_a_quick_return():
    c = linkwright.example("shaper").classify()
    assert c["grashof"] is None
    assert c["quick_return"]["time_ratio"] > 1


def test_every_example_classifies():
    for name in linkwright.examples():
        c = linkwright.example(name).classify()
        assert c["mobility"] >= 1, name
