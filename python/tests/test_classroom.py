"""Linkage.polygons and Linkage.inversions: the core's answers from Python, to the bit the CLI's
--json (kinematics/io/polygon_json.h, inversions_json.h), their refusals the core's sentences
spelled with the keyword."""

import json
import subprocess

import pytest

import linkwright


def cli_json(cli, *args):
    run = subprocess.run([cli, *args, "--json"], capture_output=True, check=True)
    return json.loads(run.stdout)


@pytest.mark.parametrize(
    "example, at, keywords, options",
    [
        ("thesis-crank-rocker", [30.0], {}, []),
        ("shaper", [60.0, 200.0], {"alpha": 4}, ["--alpha", "4"]),
        ("funsho-fourbar", [0.0, 135.5], {"rpm": 120}, ["--rpm", "120"]),
        ("ls3-engine", [45.0], {"omega": 3.5, "alpha": -1}, ["--omega", "3.5", "--alpha", "-1"]),
    ],
)
def test_polygons_are_the_clis_json_to_the_bit(cli, example, at, keywords, options):
    got = linkwright.example(example).polygons(at, **keywords)
    expected = cli_json(cli, "polygon", "--example", example, "--at", ",".join(repr(a) for a in at), *options)
    assert got == expected
    # One angle alone gives its dict.
    assert linkwright.example(example).polygons(at[0], **keywords) == expected[0]


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda l: l.polygons(2e6), "at must be"),
        (lambda l: l.polygons(10, omega=2e6), "omega must be"),
        (lambda l: l.polygons(10, alpha=float("nan")), "alpha must be"),
        (lambda l: l.polygons(10, rpm=10, omega=1), "rpm and omega cannot be used together"),
    ],
)
def test_polygons_refuse_with_the_cores_sentence_and_the_keyword(call, message):
    with pytest.raises(linkwright.Error, match=message) as refusal:
        call(linkwright.example("thesis-crank-rocker"))
    assert isinstance(refusal.value, ValueError)


def test_polygons_refuse_a_linkage_without_a_crank():
    with pytest.raises(linkwright.Error, match=r"polygon needs a crank-driven linkage \(the example excavator-boom"):
        linkwright.example("excavator-boom").polygons(10)


@pytest.mark.parametrize("example", ["thesis-crank-rocker", "ls3-engine", "funsho-fourbar"])
def test_inversions_are_the_clis_json_to_the_bit(cli, example):
    assert linkwright.example(example).inversions() == cli_json(cli, "inversions", "--example", example)


def test_inversions_of_a_four_bar_given_by_its_lengths(cli):
    got = linkwright.four_bar(60, 25, 70, 45, unit="cm").inversions()
    assert got == cli_json(cli, "inversions", "--fourbar", "60,25,70,45", "--unit", "cm")
    assert [i["grounded"] for i in got["inversions"]] == ["frame", "crank", "coupler", "rocker"]


def test_inversions_refuse_another_linkage_with_the_cores_sentence(cli):
    with pytest.raises(linkwright.Error) as refusal:
        linkwright.example("shaper").inversions()
    run = subprocess.run([cli, "inversions", "--example", "shaper"], capture_output=True, text=True)
    assert run.returncode == 2
    assert run.stderr == "linkwright-cli: " + str(refusal.value) + "\n"


@pytest.mark.parametrize(
    "call",
    [
        lambda l: l.polygons(10),
        lambda l: l.inversions(),
        lambda l: l.cognates(),
        lambda l: l.balance(),
        lambda l: l.dxf("never-written.dxf"),
    ],
)
def test_a_linkage_made_without_init_is_refused_not_used(call):
    with pytest.raises(TypeError, match="linkwright.Linkage is not initialised"):
        call(linkwright.Linkage.__new__(linkwright.Linkage))
