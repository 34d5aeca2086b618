"""Refusals: linkwright.Error (a ValueError) with the core's sentence, never a crash or a NaN."""

import math
import os

import pytest

import linkwright


def test_error_is_a_value_error():
    assert issubclass(linkwright.Error, ValueError)


@pytest.mark.parametrize("field,lengths", [
    ("frame", (0, 25, 70, 45)),
    ("crank", (60, -25, 70, 45)),
    ("coupler", (60, 25, -70, 45)),
    ("rocker", (60, 25, 70, math.nan)),
    ("rocker", (60, 25, 70, math.inf)),
])
def test_bad_lengths_name_the_field_and_the_value(field, lengths):
    with pytest.raises(linkwright.Error) as caught:
        linkwright.four_bar(*lengths)
    message = str(caught.value)
    assert message.startswith(field)
    assert caught.value.field == field
    assert caught.value.code == "invalid-value"
    bad = [v for v in lengths if not (v > 0 and math.isfinite(v))][0]
    shown = "undefined" if math.isnan(bad) else "inf" if math.isinf(bad) else "%g" % bad
    assert "(got " in message
    if shown != "inf":  # the core writes infinity its own way; the field is what matters
        assert "(got %s)" % shown in message
    assert "nan" not in message.lower()


def test_unknown_example_lists_the_names():
    with pytest.raises(linkwright.Error) as caught:
        linkwright.example("no-such-linkage")
    message = str(caught.value)
    assert "no example named 'no-such-linkage'" in message
    assert "thesis-crank-rocker" in message


@pytest.mark.parametrize("unit", ["", "m m", "mm,", "µm"])
def test_a_unit_is_letters(unit):
    with pytest.raises(linkwright.Error) as caught:
        linkwright.four_bar(60, 25, 70, 45, unit=unit)
    assert caught.value.field == "unit"
    assert str(caught.value) == "unit must be a unit name made of letters, e.g. mm, m, in (got '%s')" % unit


def test_unknown_branch():
    with pytest.raises(linkwright.Error, match=r'branch must be "open" or "crossed" \(got "sideways"\)'):
        linkwright.four_bar(60, 25, 70, 45, branch="sideways")


@pytest.mark.parametrize("kwargs,field", [
    ({"start_deg": math.nan}, "start_deg"),
    ({"stop_deg": 2e6}, "stop_deg"),
    ({"omega": math.inf}, "omega"),
    ({"alpha": 1e300}, "alpha"),
    ({"samples": 0}, "samples"),
    ({"start_deg": 90, "stop_deg": 10}, "stop_deg"),
    ({"start_deg": 10, "stop_deg": 10, "samples": 5}, "samples"),
])
def test_bad_sweep_options_name_the_keyword(kwargs, field):
    linkage = linkwright.example("thesis-crank-rocker")
    with pytest.raises(linkwright.Error) as caught:
        linkage.sweep(**kwargs)
    assert caught.value.field == field
    assert str(caught.value).startswith(field)
    with pytest.raises(linkwright.Error):
        linkage.sweep_csv(**kwargs)


def test_a_missing_document_names_the_file(tmp_path):
    path = os.path.join(str(tmp_path), "missing.linkwright")
    with pytest.raises(linkwright.Error) as caught:
        linkwright.load(path)
    assert path in str(caught.value)


def test_a_bad_document_names_the_member(tmp_path):
    good = os.path.join(os.path.dirname(__file__), "..", "..", "tests", "fuzz", "corpus", "documents",
                        "fourbar_v1.linkwright")
    with open(good, encoding="utf-8") as f:
        text = f.read()
    assert '"coupler": 70' in text
    path = tmp_path / "bad.linkwright"
    path.write_text(text.replace('"coupler": 70', '"coupler": -70'))
    with pytest.raises(linkwright.Error) as caught:
        linkwright.load(str(path))
    message = str(caught.value)
    assert message.startswith(str(path) + ": ")
    assert "mechanism.lengths.coupler" in message
    assert "(got -70)" in message


@pytest.mark.parametrize("method", ["sweep", "sweep_csv"])
def test_a_table_too_big_to_hold_is_refused_before_it_is_built(method):
    # 10⁷ rows of the thesis crank-rocker took 7.8 GB as CSV text; the refusal comes from the
    # first window, not after the memory is gone, and says how to write any size.
    crank_rocker = linkwright.example("thesis-crank-rocker")
    with pytest.raises(linkwright.Error) as refusal:
        getattr(crank_rocker, method)(samples=10**7)
    assert refusal.value.field == "samples"
    assert "a table held whole in Python may take at most 2 GB" in str(refusal.value)
    assert "(got 10000000); linkwright-cli analyze -o FILE writes any number of samples, streamed" in str(refusal.value)
    # A size that fits is swept.
    assert len(getattr(crank_rocker, method)(samples=100001)) > 0
