"""Linkage.dxf: the drawing written through the CLI's writer, the same bytes as linkwright-cli
dxf; its refusals the core's sentences spelled with the keyword."""

import subprocess

import pytest

import linkwright


@pytest.mark.parametrize(
    "example, keywords, options",
    [
        ("thesis-crank-rocker", {}, []),
        ("shaper", {"at": 75}, ["--at", "75"]),
        ("funsho-fourbar", {"at": 10, "hole": 2, "width": 9}, ["--at", "10", "--hole", "2", "--width", "9"]),
        ("excavator-boom", {}, []),
    ],
)
def test_dxf_writes_the_clis_file(cli, tmp_path, example, keywords, options):
    subprocess.run([cli, "dxf", "--example", example, *options, "-o", str(tmp_path / "cli.dxf")], check=True,
                   capture_output=True)
    got = linkwright.example(example).dxf(str(tmp_path / "py.dxf"), **keywords)
    assert (tmp_path / "py.dxf").read_bytes() == (tmp_path / "cli.dxf").read_bytes()
    assert got["output"] == str(tmp_path / "py.dxf") and "GROUND" in got["layers"]


@pytest.mark.parametrize(
    "keywords, message, field",
    [
        ({"at": 2e6}, "at must be", "at"),
        ({"hole": -1}, "hole: ", "hole"),
        ({"hole": 2, "width": 1}, "width: ", "width"),
    ],
)
def test_dxf_refuses_with_the_cores_sentence_and_writes_nothing(tmp_path, keywords, message, field):
    with pytest.raises(linkwright.Error, match=message) as refusal:
        linkwright.example("thesis-crank-rocker").dxf(str(tmp_path / "x.dxf"), **keywords)
    assert refusal.value.field == field
    assert list(tmp_path.iterdir()) == []


def test_dxf_keeps_the_old_file_when_it_cannot_write(tmp_path):
    with pytest.raises(OSError):
        linkwright.example("thesis-crank-rocker").dxf(str(tmp_path / "missing" / "x.dxf"))
