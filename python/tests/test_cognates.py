"""Linkage.cognates: the core's cognates from Python, to the bit the CLI's --json, the documents
written byte for byte as the CLI writes them, each cognate also a Linkage."""

import json
import pathlib
import subprocess

import pytest

import linkwright

# The only built-in example with a coupler point is miranda-fourbar; a document and four_bar() make
# the second and third sources.
DOCUMENTS = pathlib.Path(__file__).resolve().parents[2] / "tests" / "fuzz" / "corpus" / "documents"


def cli_cognates(cli, prefix, *args):
    run = subprocess.run([cli, "cognates", *args, "-o", str(prefix), "--json"], capture_output=True, check=True)
    return json.loads(run.stdout)


def without_linkages(result):
    out = dict(result)
    out["linkages"] = [{k: v for k, v in l.items() if k != "linkage"} for l in result["linkages"]]
    return out


@pytest.mark.parametrize(
    "make, options",
    [
        (lambda: linkwright.example("miranda-fourbar"), ["--example", "miranda-fourbar"]),
        (lambda: linkwright.load(str(DOCUMENTS / "miranda-fourbar.linkwright")),
         [str(DOCUMENTS / "miranda-fourbar.linkwright")]),
        (lambda: linkwright.four_bar(60, 25, 70, 45, coupler_point=(0.5, 0.3)),
         ["--fourbar", "60,25,70,45", "--coupler-point", "0.5,0.3"]),
    ],
)
def test_cognates_are_the_clis_json_and_files_to_the_bit(cli, tmp_path, make, options):
    expected = cli_cognates(cli, tmp_path / "cli", *options)
    got = make().cognates(str(tmp_path / "py"))
    for linkage in expected["linkages"]:
        if linkage["file"]:
            linkage["file"] = linkage["file"].replace(str(tmp_path / "cli"), str(tmp_path / "py"))
    assert without_linkages(got) == expected
    for n in (1, 2):
        assert (tmp_path / f"py-{n}.linkwright").read_bytes() == (tmp_path / f"cli-{n}.linkwright").read_bytes()
    # Each cognate is a Linkage: its coupler point traces the original's curve.
    original, _, second = (l["linkage"] for l in got["linkages"])
    assert isinstance(second, linkwright.Linkage)
    assert second.kind == "four-bar"


def test_cognates_without_output_write_nothing(tmp_path):
    got = linkwright.example("miranda-fourbar").cognates()
    assert [l["file"] for l in got["linkages"]] == [None, None, None]
    assert list(tmp_path.iterdir()) == []


def test_cognates_refuse_with_the_cores_sentence():
    with pytest.raises(linkwright.Error, match="coupler_point: "):
        linkwright.example("miranda-fourbar").cognates(coupler_point="nowhere")
    with pytest.raises(linkwright.Error, match="no point fixed on its coupler"):
        linkwright.example("thesis-crank-rocker").cognates()
    with pytest.raises(linkwright.Error):
        linkwright.example("shaper").cognates()


def test_cognates_keep_the_old_files_when_they_cannot_write(tmp_path):
    with pytest.raises(OSError):
        linkwright.example("miranda-fourbar").cognates(str(tmp_path / "missing" / "x"))
