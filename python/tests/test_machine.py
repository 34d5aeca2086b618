"""Linkage.machine: the core's machine request from Python, to the bit the CLI's --json, its
keywords the request's fields (the docstring and the stub list every one), its refusals the
core's sentences spelled with the keyword."""

import ast
import json
import pathlib
import re
import subprocess

import numpy
import pytest

import linkwright

FIELDS = ["rpm", "omega", "samples", "tolerance", "cs", "gear_ratio", "efficiency", "rated_torque", "rated_speed"]


def cli_json(cli, *args):
    run = subprocess.run([cli, "machine", *args, "--json"], capture_output=True, check=True)
    return json.loads(run.stdout)


def figures(result):
    """The dict without the curves: what --json holds."""
    return {k: v for k, v in result.items() if k not in ("angle_deg", "torque_Nm", "energy_J", "flywheel_run")}


@pytest.mark.parametrize(
    "keywords, options",
    [
        ({}, []),
        ({"cs": 0.05, "gear_ratio": 10, "efficiency": 0.9}, ["--cs", "0.05", "--gear-ratio", "10", "--efficiency", "0.9"]),
        ({"rpm": 600, "rated_torque": 0.5, "rated_speed": 3000}, ["--rpm", "600", "--rated-torque", "0.5", "--rated-speed", "3000"]),
        ({"samples": 181, "tolerance": 1e-12}, ["--samples", "181", "--tolerance", "1e-12"]),
    ],
)
def test_machine_is_the_clis_json_to_the_bit(cli, keywords, options):
    result = linkwright.example("funsho-fourbar").machine(**keywords)
    assert figures(result) == cli_json(cli, "--example", "funsho-fourbar", *options)


def test_machine_gives_the_turns_curves_as_arrays():
    result = linkwright.example("funsho-fourbar").machine(cs=0.02)
    assert result["converged"] is True
    n = result["samples"]
    for key in ("angle_deg", "torque_Nm", "energy_J"):
        assert isinstance(result[key], numpy.ndarray) and result[key].shape == (n,)
    assert result["angle_deg"][-1] - result["angle_deg"][0] == pytest.approx(360.0)
    # The energy curve spans the energy fluctuation (its extremes are refined between samples).
    span = result["energy_J"].max() - result["energy_J"].min()
    assert span <= result["energy_fluctuation_J"] and span == pytest.approx(result["energy_fluctuation_J"], rel=1e-3)
    run = result["flywheel_run"]
    speed = run["speed_rad_s"]
    assert (speed.max() - speed.min()) / (0.5 * (speed.max() + speed.min())) == pytest.approx(0.02, rel=0.02)


@pytest.mark.parametrize(
    "keywords, message",
    [
        ({"efficiency": 5e-324}, "efficiency must be from 0.01 to 1 (got 5e-324)"),
        ({"samples": 3}, "samples must be a whole number from 4 to 100000 (got 3)"),
        ({"rpm": 10, "omega": 1}, "rpm and omega are one speed: give one of them"),
        ({"cs": 1}, "cs must be from 1e-5 to 0.9 (got 1)"),
    ],
)
def test_machine_refuses_with_the_cores_sentence_and_the_keyword(keywords, message):
    with pytest.raises(linkwright.Error) as refusal:
        linkwright.example("funsho-fourbar").machine(**keywords)
    assert str(refusal.value) == message
    assert refusal.value.field == next(iter(keywords))


def test_machine_refuses_keywords_and_types_it_does_not_take():
    funsho = linkwright.example("funsho-fourbar")
    with pytest.raises(TypeError, match="unexpected keyword argument 'radius'"):
        funsho.machine(radius=3)
    with pytest.raises(TypeError, match="cs must be a number"):
        funsho.machine(cs="0.05")
    with pytest.raises(TypeError, match="cs must be a number"):
        funsho.machine(cs=True)
    with pytest.raises(linkwright.Error, match="machine needs masses and loads"):
        linkwright.example("thesis-crank-rocker").machine()
    with pytest.raises(linkwright.Error, match="need a crank"):
        linkwright.example("seed-arm").machine()


def test_the_docstring_and_the_stub_list_every_field_of_the_request():
    doc = linkwright.Linkage.machine.__doc__
    listed = re.findall(r"^    ([a-z_]+): ", doc, re.MULTILINE)
    assert listed == FIELDS
    stub = ast.parse((pathlib.Path(linkwright.__file__).parent / "__init__.pyi").read_text())
    linkage = next(n for n in stub.body if isinstance(n, ast.ClassDef) and n.name == "Linkage")
    machine = next(n for n in linkage.body if isinstance(n, ast.FunctionDef) and n.name == "machine")
    assert [a.arg for a in machine.args.kwonlyargs] == FIELDS
