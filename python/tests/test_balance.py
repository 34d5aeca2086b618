"""Linkage.balance: the core's balance request from Python, to the bit the CLI's --json, the
balanced design written byte for byte as the CLI writes it; its refusals the core's sentences
spelled with the keyword."""

import json
import pathlib
import subprocess

import numpy
import pytest

import linkwright

# funsho-fourbar is the only built-in example with masses; its document is the second source.
DOCUMENTS = pathlib.Path(__file__).resolve().parents[2] / "tests" / "fuzz" / "corpus" / "documents"


def cli_balance(cli, path, *args):
    run = subprocess.run([cli, "balance", *args, "-o", str(path), "--json"], capture_output=True, check=True)
    return json.loads(run.stdout)


def figures(result):
    return {k: v for k, v in result.items() if k not in ("linkage", "angle_deg", "torque_before_Nm", "torque_after_Nm")}


@pytest.mark.parametrize(
    "example, keywords, options",
    [
        ("funsho-fourbar", {}, []),
        ("funsho-fourbar", {"radius": 0.5}, ["--radius", "0.5"]),
        (str(DOCUMENTS / "funsho-fourbar.linkwright"), {"radius": 2}, ["--radius", "2"]),
        ("funsho-fourbar", {"spring": ("rocker:C", "O2")}, ["--spring", "rocker:C,O2"]),
        ("funsho-fourbar", {"spring_search": "rocker"}, ["--spring-search", "rocker"]),
    ],
)
def test_balance_is_the_clis_json_and_file_to_the_bit(cli, tmp_path, example, keywords, options):
    source = [example] if example.endswith(".linkwright") else ["--example", example]
    expected = cli_balance(cli, tmp_path / "cli.linkwright", *source, *options)
    linkage = linkwright.load(example) if example.endswith(".linkwright") else linkwright.example(example)
    got = linkage.balance(str(tmp_path / "py.linkwright"), **keywords)
    expected["output"] = str(tmp_path / "py.linkwright")
    assert figures(got) == expected
    assert (tmp_path / "py.linkwright").read_bytes() == (tmp_path / "cli.linkwright").read_bytes()
    assert isinstance(got["linkage"], linkwright.Linkage)
    if "spring" in got:
        n = len(got["angle_deg"])
        assert n > 300 and got["torque_after_Nm"].shape == (n,)
        rms = numpy.sqrt(numpy.mean(got["torque_after_Nm"] ** 2))
        assert rms == pytest.approx(got["rms_torque_after_Nm"], rel=1e-2)


@pytest.mark.parametrize(
    "keywords, message, field",
    [
        ({"fraction": 2}, "fraction: ", "fraction"),
        ({"radius": 0}, "radius: the counterweight's", "radius"),
        ({"spring": ("rocker:C", "O2"), "radius": 1}, "radius sets the counterweights' distance", "radius"),
        ({"spring": ("rocker:C", "O2"), "spring_search": "rocker"}, "not both", "spring_search"),
        ({"spring": ("rocker:Z", "O2")}, "spring: ", "spring"),
    ],
)
def test_balance_refuses_with_the_cores_sentence_and_the_keyword(keywords, message, field):
    with pytest.raises(linkwright.Error, match=message) as refusal:
        linkwright.example("funsho-fourbar").balance(**keywords)
    assert refusal.value.field == field


def test_balance_refuses_a_linkage_without_masses_and_writes_nothing(tmp_path):
    with pytest.raises(linkwright.Error, match="there are no masses to balance"):
        linkwright.example("thesis-crank-rocker").balance(str(tmp_path / "x.linkwright"))
    assert list(tmp_path.iterdir()) == []
    with pytest.raises(OSError):
        linkwright.example("funsho-fourbar").balance(str(tmp_path / "missing" / "x.linkwright"))
